// gearstiff — mesh stiffness, frictional contact and torsional dynamics of gear drives.
//
//   gearstiff <command> [file.prm|file.json] [--set section/key=value ...] [--json] [-o DIR]
//   gearstiff --help            lists the commands
//   gearstiff <command> --help  describes one; --print-parameters lists its parameters
//
// Exit codes: 0 success, 2 bad input (names the parameter), 3 a numerical method failed
// (names the method and why), 1 anything else. Errors go to stderr as one line.
#include "app/command.h"
#include "app/parameter_names.h"
#include "app/units.h"
#include "errors/errors.h"
#include "fem/mpi_start.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
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
  std::string output_directory;
};

void print_usage(std::ostream& out)
{
  out << "gearstiff — FE mesh stiffness, frictional contact and dynamics of gear drives\n\n"
         "usage: gearstiff <command> [file.prm|file.json] [--set section/key=value ...]\n"
         "                 [--json] [--quiet] [-o DIR] [--help] [--print-parameters]\n\n"
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
         "  --help              this text, or a command's description\n\n"
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
    else if (a == "--print-parameters")
      line.print_parameters = true;
    else if (a == "--json")
      line.json = true;
    else if (a == "--quiet" || a == "-q")
      line.quiet = true;
    else if (a == "-o" || a == "--output")
      line.output_directory = next_value(a);
    else if (a.rfind("--output=", 0) == 0)
      line.output_directory = a.substr(9);
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

// An error message as one line of reasonable length: newlines become spaces, and a message
// beyond a few hundred characters is cut.
std::string one_line(const std::string& text)
{
  // Words (runs without white space) are shortened one by one, so a huge value quoted inside
  // a parser's message does not push the rest of the message out; runs of spaces collapse.
  std::string line, word;
  const auto flush = [&]()
  {
    if (word.empty())
      return;
    line += (line.empty() ? "" : " ") + shortened(word, 2 * limits::echoed_value_length);
    word.clear();
  };
  for (const char c : text)
    if (c == ' ' || c == '\n' || c == '\r' || c == '\t')
      flush();
    else
      word += c;
  flush();
  return shortened(line, 600);
}

// deal.II's exceptions carry file/line context meant for developers; users get the message.
std::string deal_ii_message(const dealii::ExceptionBase& e)
{
  std::ostringstream s;
  e.print_info(s);
  std::string text = s.str();
  for (auto& c : text)
    if (c == '\n')
      c = ' ';
  while (!text.empty() && (text.back() == ' '))
    text.pop_back();
  while (!text.empty() && (text.front() == ' '))
    text.erase(text.begin());
  return text;
}

// `message` with every copy of the user's `value` in it shortened (deal.II repeats the
// offending value in its pattern messages).
std::string shortened_in(std::string message, const std::string& value)
{
  const std::string replacement = shortened(value);
  if (value.size() <= replacement.size())
    return message;
  for (std::size_t at = message.find(value); at != std::string::npos;
       at = message.find(value, at + replacement.size()))
    message.replace(at, value.size(), replacement);
  return message;
}

// Reads the parameter file; InputError naming the file for a missing file, a folder or a
// parse error.
void read_parameter_file(dealii::ParameterHandler& prm, const DeclaredSection& declared,
                         const std::string& file)
{
  const std::string name = shortened(file);
  std::error_code error;
  if (std::filesystem::is_directory(file, error))
    throw InputError(name, "is a folder, not a parameter file (.prm or .json)");
  if (!std::filesystem::exists(file, error))
    throw InputError(name, "parameter file does not exist");
  if (!std::filesystem::is_regular_file(file, error))
    throw InputError(name, "is not a regular file (a parameter file .prm or .json is expected)");
  if (access(file.c_str(), R_OK) != 0)
    throw InputError(name, "parameter file cannot be read (permissions)");
  // Misspelt names first: the section and the nearest declared names, not deal.II's message.
  check_parameter_file(declared, file);
  try
  {
    prm.parse_input(file, "", false, true);
  }
  catch (const dealii::ExceptionBase& e)
  {
    throw InputError(name, one_line(deal_ii_message(e)));
  }
}

void apply_override(dealii::ParameterHandler& prm, const DeclaredSection& declared,
                    const std::string& path, const std::string& value)
{
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t slash; (slash = path.find('/', start)) != std::string::npos; start = slash + 1)
    parts.push_back(path.substr(start, slash - start));
  const std::string key = path.substr(start);
  check_parameter_name(declared, parts, key, path);
  unsigned int entered = 0;
  try
  {
    for (const auto& section : parts)
    {
      prm.enter_subsection(section);
      ++entered;
    }
    // deal.II declares missing subsections on enter, so check the key explicitly.
    prm.get(key);
    prm.set(key, value);
  }
  catch (const dealii::ExceptionBase& e)
  {
    for (; entered > 0; --entered)
      prm.leave_subsection();
    throw InputError(path, "cannot set to '" + shortened(value) +
                               "': " + shortened_in(deal_ii_message(e), value));
  }
  for (; entered > 0; --entered)
    prm.leave_subsection();
}

// The parameters used and the report's tables and summary, into the staging folder (rank 0).
void write_results(CommandContext& context, const dealii::ParameterHandler& prm,
                   const std::string& command_name)
{
  {
    std::ofstream out(context.output_file("parameters.prm", "parameters actually used"));
    prm.print_parameters(out, dealii::ParameterHandler::ShortPRM);
  }
  {
    std::ofstream out(context.output_file("parameters.json", "the same, as JSON"));
    prm.print_parameters(out, dealii::ParameterHandler::ShortJSON);
  }
  for (const auto& table : context.report.tables())
  {
    std::ofstream out(context.output_file(table.name + ".csv", "table " + table.name));
    context.report.write_table_csv(table, out);
  }
  const std::string summary = context.output_file("summary.json", "all results as JSON");
  std::ofstream out(summary);
  context.report.print_json(out, command_name);
}

int run(int argc, char** argv, MPI_Comm comm)
{
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  const CommandLine line = parse_command_line(argc, argv);

  if (line.command.empty())
  {
    if (!line.help)
      throw InputError("command", "none given; usage: gearstiff <command> [file.prm] ... "
                                  "(see gearstiff --help)");
    if (root)
      print_usage(std::cout);
    return 0;
  }
  const auto found = command_registry().find(line.command);
  if (found == command_registry().end())
    throw InputError(line.command, "unknown command (see gearstiff --help)");
  const Command& command = found->second;

  dealii::ParameterHandler prm;
  command.declare_parameters(prm);

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

  const DeclaredSection declared = declared_parameters(prm);
  if (!line.parameter_file.empty())
    read_parameter_file(prm, declared, line.parameter_file);
  for (const auto& [path, value] : line.overrides)
    apply_override(prm, declared, path, value);

  if (line.print_parameters)
  {
    if (root)
      prm.print_parameters(std::cout, line.json ? dealii::ParameterHandler::JSON
                                                : dealii::ParameterHandler::PRM);
    return 0;
  }

  // Output folder (checked before any work; created only on success).
  std::unique_ptr<StagedOutput> output;
  if (!line.output_directory.empty())
    output = std::make_unique<StagedOutput>(line.output_directory, comm);

  // Progress and diagnostics go to stderr with --json (stdout holds the one JSON object) and
  // nowhere with --quiet.
  dealii::ConditionalOStream pcout(line.json ? std::cerr : std::cout, root && !line.quiet);
  CommandContext context(comm, pcout, output ? output->staging_directory() : "",
                         line.json || line.quiet, !line.quiet);
  command.run(prm, context);

  if (output)
  {
    if (root)
      write_results(context, prm, command.name);
    output->commit();
  }

  if (root)
  {
    if (line.json)
      context.report.print_json(std::cout, command.name);
    else
      context.report.print_text(std::cout);
  }
  return 0;
}
} // namespace

int main(int argc, char** argv)
{
  // First, before MPI or any library starts a thread: every thread inherits the blocked signals.
  gearstiff::app::install_signal_cleanup();
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
