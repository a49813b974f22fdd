#include "app/command.h"

#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace gearstiff::app
{
  std::map<std::string, Command>& command_registry()
  {
    // Function-local static: registrations from other translation units run before main() in
    // unspecified order, so the map must exist on first use.
    static std::map<std::string, Command> registry;
    return registry;
  }

  CommandRegistration::CommandRegistration(Command command)
  {
    const std::string name = command.name;
    command_registry().emplace(name, std::move(command));
  }

  std::string tools_directory()
  {
    if (const char* dir = std::getenv("GEARSTIFF_TOOLS_DIR"))
      return dir;
    return GEARSTIFF_TOOLS_DIR;
  }

  CommandContext::CommandContext(MPI_Comm communicator, dealii::ConditionalOStream& pcout,
                                 const std::string& staging_directory, bool quiet)
    : mpi_communicator(communicator)
    , pcout(pcout)
    , staging_directory(staging_directory)
    , quiet(quiet)
  {}

  bool CommandContext::is_root() const
  {
    int rank = 0;
    MPI_Comm_rank(mpi_communicator, &rank);
    return rank == 0;
  }

  std::string CommandContext::output_file(const std::string& name, const std::string& description)
  {
    if (staging_directory.empty())
      throw std::logic_error("output_file('" + name + "') called without -o DIR");
    const std::filesystem::path path = std::filesystem::path(staging_directory) / name;
    std::filesystem::create_directories(path.parent_path());
    report.add_output_file(name, description);
    return path.string();
  }

  namespace
  {
    std::string shell_quote(const std::string& s)
    {
      std::string quoted = "'";
      for (const char c : s)
        quoted += (c == '\'') ? std::string("'\\''") : std::string(1, c);
      return quoted + "'";
    }
  } // namespace

  bool CommandContext::plot(const std::string& script, const std::vector<std::string>& arguments,
                            const std::string& png_name, const std::string& description)
  {
    if (!writes_files() || !is_root())
      return false;
    const std::string python =
      std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
    const std::string script_path = tools_directory() + "/" + script;
    if (!std::filesystem::exists(script_path))
    {
      pcout << "note: plot script " << script_path << " not found; " << png_name
            << " not drawn\n";
      return false;
    }
    const std::string png = (std::filesystem::path(staging_directory) / png_name).string();
    std::ostringstream command;
    command << python << " " << shell_quote(script_path);
    for (const auto& a : arguments)
      command << " " << shell_quote(a);
    command << " " << shell_quote(png) << (quiet ? " >/dev/null 2>&1" : " 1>&2");
    const int status = std::system(command.str().c_str());
    if (status != 0 || !std::filesystem::exists(png))
    {
      pcout << "note: could not draw " << png_name
            << " (python3 with matplotlib is needed: apt-get install python3-matplotlib)\n";
      return false;
    }
    report.add_output_file(png_name, description);
    return true;
  }
} // namespace gearstiff::app
