// gearstiff — mesh stiffness, frictional contact and torsional dynamics of gear drives.
//
//   gearstiff <command> [file.prm|file.json] [--set section/key=value ...] [--json] [-o DIR]
//   gearstiff --help            lists the commands
//   gearstiff --version         the version, source revision and libraries
//   gearstiff <command> --help  describes one; --print-parameters lists its parameters
//
// Exit codes: 0 success, 2 bad input (names the parameter), 3 a numerical method failed
// (names the method and why), 1 anything else (an I/O error names the file and why: "no space
// left on device"). Errors go to stderr as one line.
#include "app/core/build_info.h"
#include "app/core/command.h"
#include "app/core/invoke.h"
#include "app/core/scratch.h"
#include "app/core/units.h"
#include "errors/errors.h"
#include "errors/file_names.h"
#include "errors/io.h"
#include "fem/blas_start.h"
#include "fem/mpi_start.h"

#include <cstdlib>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <iostream>
#include <unistd.h>

namespace
{
using namespace gearstiff;
using namespace gearstiff::app;

struct CommandLine
{
  std::string command;
  std::string parameter_file;
  std::vector<std::pair<std::string, std::string>> overrides; // "section/sub/key", value
  bool json = false;
  bool quiet = false;
  bool help = false;
  bool print_parameters = false;
  bool version = false;
  std::string output_directory;
};

void print_usage(std::ostream& out)
{
  out << "gearstiff — FE mesh stiffness, frictional contact and dynamics of gear drives\n\n"
         "usage: gearstiff <command> [file.prm|file.json] [--set section/key=value ...]\n"
         "                 [--json] [--quiet] [-o DIR] [--help] [--print-parameters]\n"
         "       gearstiff --version\n\n"
         "commands:\n";
  for (const auto& [name, command] : command_registry())
  {
    out << "  " << name;
    for (std::size_t i = name.size(); i < 14; ++i)
      out << ' ';
    out << command.summary << '\n';
  }
  out << "\noptions:\n"
         "  --set S/K=V         override parameter K of subsection S (nested: S/T/K)\n"
         "  --json              print the results as one JSON object on stdout\n"
         "  --quiet, -q         no progress lines and diagnostics (stderr; errors still print)\n"
         "  -o DIR              write result files (CSV, JSON, VTU, PNG) and the parameters\n"
         "                      used into DIR; nothing is written if the command fails\n"
         "  --print-parameters  list the command's parameters, defaults, units and ranges\n"
         "  --help              this text, or a command's description\n"
         "  --version           the version, source revision and libraries of this build\n\n"
         "Units: parameter files use the unit stated in each parameter's documentation\n"
         "(mm, degrees, rpm, N·m where gear engineers use them); everything inside is SI.\n";
}

CommandLine parse_command_line(int argc, char** argv)
{
  CommandLine line;
  std::vector<std::string> args(argv + 1, argv + argc);
  std::size_t i = 0;
  if (!args.empty() && args[0].rfind("-", 0) != 0)
    line.command = args[i++];
  for (; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    auto next_value = [&](const std::string& option)
    {
      if (i + 1 >= args.size())
        throw InputError(option, "expects a value");
      return args[++i];
    };
    if (a == "--help" || a == "-h")
      line.help = true;
    else if (a == "--version")
      line.version = true;
    else if (a == "--print-parameters")
      line.print_parameters = true;
    else if (a == "--json")
      line.json = true;
    else if (a == "--quiet" || a == "-q")
      line.quiet = true;
    else if (a == "-o" || a == "--output" || a.rfind("--output=", 0) == 0)
    {
      // An empty name wrote nothing and exited 0; a name too long for the file system ended in
      // std::filesystem's text.
      line.output_directory = a.rfind("--output=", 0) == 0 ? a.substr(9) : next_value(a);
      check_file_name(line.output_directory, "-o");
    }
    else if (a == "--set" || a.rfind("--set=", 0) == 0)
    {
      const std::string assignment = (a == "--set") ? next_value(a) : a.substr(6);
      const auto eq = assignment.find('=');
      if (eq == std::string::npos || eq == 0)
        throw InputError("--set", "expects section/key=value, got '" + shortened(assignment) + "'");
      line.overrides.emplace_back(assignment.substr(0, eq), assignment.substr(eq + 1));
    }
    else if (a.rfind("-", 0) == 0)
      throw InputError(shortened(a), "unknown option (see gearstiff --help)");
    else if (line.parameter_file.empty())
      line.parameter_file = a;
    else
      throw InputError(shortened(a), "a second parameter file was given (only one is read)");
  }
  return line;
}

// TMPDIR holds Open MPI's session files and gearstiff's scratch: one that is no writable folder
// failed inside MPI_Init with Open MPI's own text (exit 1). Checked before MPI starts; the
// problem as an error line, or empty.
//
// MUMPS writes out-of-core factors (fem/stiffness_factorization.cc: from 500k DoFs, 1.9 GB a
// file) to $MUMPS_OOC_TMPDIR, else /tmp, and removes them only when it ends normally: a run
// stopped by a signal or killed left them in /tmp (11 GB of them after one day's killed runs,
// 2026-12-05). In the process's scratch folder they go with it (at exit, by the signal thread,
// after a SIGKILL by the next run); so it is made here, before MPI. A folder the user chose is
// kept.
std::string temporary_folder_problem()
{
  try
  {
    check_temporary_folder();
    if (std::getenv("MUMPS_OOC_TMPDIR") == nullptr)
      setenv("MUMPS_OOC_TMPDIR", gearstiff::app::scratch_directory().c_str(), 0);
  }
  catch (const InputError& e)
  {
    return e.what();
  }
  return "";
}

// `gearstiff --version`: what a bug report needs — the version, the source revision, the
// libraries compiled against and the MPI library this process runs with.
void print_version(std::ostream& out)
{
  out << version_line() << "\nbuilt against " << library_line();
  char mpi[MPI_MAX_LIBRARY_VERSION_STRING];
  int length = 0;
  MPI_Get_library_version(mpi, &length);
  std::string mpi_library(mpi, static_cast<std::size_t>(length));
  mpi_library = mpi_library.substr(0, mpi_library.find_first_of(",\n"));
  out << "\nMPI: " << mpi_library << '\n';
}

int run(int argc, char** argv, MPI_Comm comm)
{
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  const CommandLine line = parse_command_line(argc, argv);

  if (line.version)
  {
    if (root)
      print_version(std::cout);
    return 0;
  }

  if (line.command.empty())
  {
    if (!line.help)
      throw InputError("command", "none given; usage: gearstiff <command> [file.prm] ... "
                                  "(see gearstiff --help)");
    if (root)
      print_usage(std::cout);
    return 0;
  }
  const Command& command = find_command(line.command);

  if (line.help)
  {
    if (root)
      std::cout << "gearstiff " << command.name << " — " << command.summary << "\n\n"
                << command.description << "\n\nusage: gearstiff " << command.name
                << " [file.prm|file.json] [--set section/key=value ...] [--json] [-o DIR]\n"
                << "       gearstiff " << command.name
                << " --print-parameters   (all parameters, defaults, units, ranges)\n";
    return 0;
  }

  dealii::ParameterHandler prm;
  load_parameters(command, Invocation{line.parameter_file, line.overrides, line.output_directory},
                  prm);

  if (line.print_parameters)
  {
    if (root)
      prm.print_parameters(std::cout, line.json ? dealii::ParameterHandler::JSON
                                                : dealii::ParameterHandler::PRM);
    return 0;
  }

  // Progress and diagnostics on stderr (with or without --json), so that stdout holds the report
  // alone; --quiet: nowhere.
  const Report report = run_loaded_command(command, prm, line.output_directory, comm, std::cerr,
                                           !line.quiet, line.json || line.quiet);
  if (root)
  {
    if (line.json)
      report.print_json(std::cout, command.name);
    else
      report.print_text(std::cout);
  }
  return 0;
}
} // namespace

int main(int argc, char** argv)
{
  // Before anything computes: OpenBLAS's kernels for this processor (fem/blas_start.h).
  gearstiff::fem::select_blas_kernels();
  // First, before MPI or any library starts a thread: every thread inherits the blocked signals.
  gearstiff::app::install_signal_cleanup();
  if (const std::string problem = temporary_folder_problem(); !problem.empty())
  {
    // Before MPI: every process of a launch sees the same TMPDIR; the first rank reports.
    const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
    if (rank == nullptr || std::string(rank) == "0")
      std::cerr << "gearstiff: error: " << one_line(problem) << std::endl;
    return 2;
  }
  gearstiff::fem::prepare_mpi_start();
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  try
  {
    return run(argc, argv, comm);
  }
  catch (const gearstiff::InputError& e)
  {
    if (root)
      std::cerr << "gearstiff: error: " << one_line(e.what()) << std::endl;
    return 2;
  }
  catch (const gearstiff::SolverFailure& e)
  {
    if (root)
      std::cerr << "gearstiff: solver failure: " << one_line(e.what()) << std::endl;
    return 3;
  }
  catch (const gearstiff::IoError& e)
  {
    if (root)
      std::cerr << "gearstiff: I/O error: " << one_line(e.what()) << std::endl;
    return 1;
  }
  catch (const dealii::ExceptionBase& e)
  {
    if (root)
      std::cerr << "gearstiff: error: " << one_line(deal_ii_message(e)) << std::endl;
    return 1;
  }
  catch (const std::exception& e)
  {
    if (root)
      std::cerr << "gearstiff: error: " << one_line(e.what()) << std::endl;
    return 1;
  }
}
