#include "app/core/invoke.h"

#include "app/core/build_info.h"
#include "app/core/field_names.h"
#include "app/core/parameter_file_check.h"
#include "app/core/parameter_names.h"
#include "app/core/renamed_parameters.h"
#include "app/core/units.h"
#include "errors/errors.h"
#include "errors/file_names.h"
#include "errors/io.h"
#include "fem/parallel.h"

#include <cstdlib>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>
#include <unistd.h>

namespace gearstiff::app
{
namespace
{
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

// The parameters used and the report's tables and summary, into the staging folder (rank 0).
void write_results(CommandContext& context, const dealii::ParameterHandler& prm,
                   const std::string& command_name)
{
  // A comment first (a .prm allows it; JSON has none: summary.json carries the same): which
  // gearstiff wrote these parameters.
  context.write_output("parameters.prm", "parameters actually used",
                       [&](std::ostream& out)
                       {
                         out << "# The parameters `gearstiff " << command_name << "` used; "
                             << version_line() << ".\n";
                         prm.print_parameters(out, dealii::ParameterHandler::ShortPRM);
                       });
  context.write_output("parameters.json", "the same, as JSON",
                       [&](std::ostream& out)
                       { prm.print_parameters(out, dealii::ParameterHandler::ShortJSON); });
  for (const auto& table : context.report.tables())
    context.write_output(table.name + ".csv", "table " + table.name,
                         [&](std::ostream& out) { context.report.write_table_csv(table, out); });
  context.write_output("summary.json", "all results as JSON",
                       [&](std::ostream& out) { context.report.print_json(out, command_name); });
}

// "section/sub/key" as its sections and its key.
std::pair<std::vector<std::string>, std::string> split_parameter_path(const std::string& path)
{
  std::vector<std::string> sections;
  std::size_t start = 0;
  for (std::size_t slash; (slash = path.find('/', start)) != std::string::npos; start = slash + 1)
    sections.push_back(path.substr(start, slash - start));
  return {sections, path.substr(start)};
}
} // namespace

const Command& find_command(const std::string& name)
{
  const auto found = command_registry().find(name);
  if (found == command_registry().end())
    throw InputError(name, "unknown command (see gearstiff --help)");
  return found->second;
}

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

std::vector<std::string> read_parameter_file(dealii::ParameterHandler& prm, const std::string& file,
                                             const std::string& command)
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
  // JSON values deal.II would misread (arrays where a value is due) first, then misspelt names:
  // the section and the nearest declared names, not deal.II's message.
  check_json_parameter_file(file);
  OtherCommandNames others;
  std::vector<std::pair<std::string, DeclaredSection>> by_command;
  for (const auto& [other_name, other] : command_registry())
  {
    dealii::ParameterHandler other_prm;
    other.declare_parameters(other_prm);
    by_command.emplace_back(other_name, declared_parameters(other_prm));
    merge_declared(others.declared, by_command.back().second);
  }
  // Renamed parameters read under their new names (one note each, rank 0).
  std::ifstream in(file);
  const std::string original{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const bool json = file.size() > 5 && file.substr(file.size() - 5) == ".json";
  std::vector<std::string> renamed;
  const std::string text = with_current_names(original, json, renamed);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    for (const std::string& old_path : renamed)
      std::cerr << renamed_note(name, old_path) << "\n";
  check_parameter_file(declared_parameters(prm), file, &others, renamed.empty() ? nullptr : &text);
  // A file that gives this command nothing is another command's input (a sweep's
  // stiffness_table.prm, a `dynamics` input, given to `cai`): run on under a note, it gave the
  // built-in pair's result (found 2026-12-06).
  if (!command.empty() && others.own == 0 && !others.ignored.empty())
  {
    std::string listed, readers;
    std::size_t reader_count = 0;
    for (std::size_t i = 0; i < others.ignored.size() && i < 3; ++i)
      listed += (i == 0 ? "" : ", ") + others.ignored[i];
    for (const auto& [other_name, other_declared] : by_command)
    {
      bool reads_all = other_name != command;
      for (std::size_t i = 0; reads_all && i < others.ignored.size(); ++i)
      {
        const auto [sections, key] = split_parameter_path(others.ignored[i]);
        try
        {
          check_parameter_name(other_declared, sections, key, others.ignored[i]);
        }
        catch (const InputError&)
        {
          reads_all = false;
        }
      }
      if (reads_all)
      {
        readers += (readers.empty() ? "" : ", ") + ("`gearstiff " + other_name + "`");
        ++reader_count;
      }
    }
    const std::size_t count = others.ignored.size();
    throw InputError(name,
                     "holds no parameter `" + command + "` takes: " +
                         (count == 1 ? "its one is another command's ("
                                     : "its " + std::to_string(count) + " are other commands' (") +
                         listed + (count > 3 ? ", ..." : "") + ")" +
                         (readers.empty()
                              ? ""
                              : "; " + readers + (reader_count == 1 ? " reads" : " read") + " it"));
  }
  try
  {
    // Names only other commands declare were listed above; deal.II skips them.
    std::istringstream renamed_text(json ? json_names_for_deal_ii(text) : text);
    if (json)
      prm.parse_input_from_json(renamed_text, !others.ignored.empty());
    else if (renamed.empty())
      prm.parse_input(file, "", !others.ignored.empty(), true);
    else
      prm.parse_input(renamed_text, file, "", !others.ignored.empty());
  }
  catch (const dealii::ExceptionBase& e)
  {
    // deal.II's text ("does not match the given pattern: [Selection ...]") named neither the
    // parameter nor the nearest value: a refused selection value is told as --set tells it.
    check_selection_values(prm, file);
    throw InputError(name, one_line(deal_ii_message(e)));
  }
  return others.ignored;
}

void apply_override(dealii::ParameterHandler& prm, const std::string& typed_path,
                    const std::string& value)
{
  // A renamed parameter is set under its new name, with a note (rank 0).
  const std::string path = current_parameter_path(typed_path);
  if (path != typed_path && dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cerr << renamed_note("--set", typed_path) << "\n";
  const auto [parts, key] = split_parameter_path(path);
  check_parameter_name(declared_parameters(prm), parts, key, path);
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
    const std::string refused = pattern_mismatch(prm, parts, key, value);
    throw InputError(
        path, "cannot set to '" + shortened(value) +
                  "': " + (refused.empty() ? shortened_in(deal_ii_message(e), value) : refused));
  }
  for (; entered > 0; --entered)
    prm.leave_subsection();
}

void load_parameters(const Command& command, const Invocation& invocation,
                     dealii::ParameterHandler& prm)
{
  command.declare_parameters(prm);
  if (!invocation.parameter_file.empty())
  {
    const std::vector<std::string> ignored =
        read_parameter_file(prm, invocation.parameter_file, command.name);
    // One note for a pair file shared with other commands (rank 0; stderr, never the JSON).
    if (!ignored.empty() && dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      std::string listed;
      for (std::size_t i = 0; i < ignored.size() && i < 3; ++i)
        listed += (i == 0 ? "" : ", ") + ignored[i];
      std::cerr << "gearstiff: note: " << shortened(invocation.parameter_file) << ": "
                << ignored.size() << " parameter(s) that other commands use ignored by `"
                << command.name << "` (" << listed << (ignored.size() > 3 ? ", ..." : "") << ")\n";
    }
  }
  for (const auto& [path, value] : invocation.overrides)
    apply_override(prm, path, value);
}

void check_temporary_folder()
{
  const char* value = std::getenv("TMPDIR");
  if (value == nullptr || *value == '\0')
    return;
  check_file_name(value, "TMPDIR");
  std::error_code error;
  if (!std::filesystem::is_directory(value, error))
    throw InputError("TMPDIR", "'" + shortened(value) +
                                   "' is not a folder (the temporary folder of Open MPI and of "
                                   "gearstiff's scratch)");
  if (access(value, W_OK | X_OK) != 0)
    throw InputError("TMPDIR", "cannot write into '" + shortened(value) + "'");
}

Report run_loaded_command(const Command& command, dealii::ParameterHandler& prm,
                          const std::string& output_directory, MPI_Comm communicator,
                          std::ostream& progress, bool show_progress, bool quiet)
{
  const bool root = dealii::Utilities::MPI::this_mpi_process(communicator) == 0;
  // The Python module reaches here without main's check (and TMPDIR may change in-process).
  check_temporary_folder();
  // Output folder (checked before any work; created only on success).
  std::unique_ptr<StagedOutput> output;
  if (!output_directory.empty())
    output = std::make_unique<StagedOutput>(output_directory, communicator);
  const std::string staging = output ? output->staging_directory() : "";
  try
  {
    dealii::ConditionalOStream pcout(progress, root && show_progress);
    CommandContext context(communicator, pcout, staging, quiet, show_progress);
    // Library errors name library fields; the user reads the parameter they wrote.
    with_registered_field_names([&] { command.run(prm, context); });
    if (output)
    {
      // A result or chart that rank 0 could not write whole fails the run on every rank, and
      // the staging folder goes with `output`: DIR gets all the results or none.
      const fem::Failure failure = fem::catch_failure(
          [&]()
          {
            if (root)
              write_results(context, prm, command.name);
            context.throw_write_failure();
          });
      fem::first_failure(communicator, failure).rethrow();
      output->commit();
    }
    return std::move(context.report);
  }
  catch (const IoError& error)
  {
    throw located(error, staging, output_directory);
  }
}
} // namespace gearstiff::app
