// Running one command programmatically: the steps the command line takes between parsing its
// arguments and printing the report (find the command, read the parameter file, apply the
// `--set` overrides, stage the -o folder, run, write the results, commit). `gearstiff` (main.cc)
// and the Python module (python/gearstiff_module.cc) both go through these functions, so the two
// read the same parameters, raise the same errors with the same messages and fill the same Report.
#pragma once

#include "app/core/command.h"
#include "app/core/report.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <mpi.h>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace gearstiff::app
{
// The registered command `name` ("gear-pair"); InputError(name) when there is none.
const Command& find_command(const std::string& name);

// Reads a .prm or .json parameter file into `prm` (declared already); InputError naming the
// file for a missing file, a folder or a parse error, or a name no command declares. Returns the
// names only other commands declare ("section/key"), which are skipped: one pair file serves
// every command that reads a pair. With `command` (its name), a file whose every name is only
// other commands' is refused naming the file and the commands that read it.
std::vector<std::string> read_parameter_file(dealii::ParameterHandler& prm, const std::string& file,
                                             const std::string& command = {});

// Sets parameter `path` ("section/sub/key") to `value`; InputError(path) for an unknown
// parameter or a value its pattern rejects (the message repeats deal.II's reason).
void apply_override(dealii::ParameterHandler& prm, const std::string& path,
                    const std::string& value);

struct Invocation
{
  std::string parameter_file;                                 // .prm or .json; empty: defaults
  std::vector<std::pair<std::string, std::string>> overrides; // "section/sub/key", value
  std::string output_directory;                               // -o DIR; empty: no files
};

// Declares the command's parameters, then reads the file and applies the overrides.
void load_parameters(const Command& command, const Invocation& invocation,
                     dealii::ParameterHandler& prm);

// TMPDIR holds Open MPI's session files and gearstiff's scratch: unset, empty or a writable
// folder; else InputError("TMPDIR"). The command line checks it before MPI starts, and every run
// (the Python module's too) before its first file.
void check_temporary_folder();
// Runs `command` with the loaded parameters (collective over `communicator`): the -o folder is
// checked first and filled only on success. Progress goes to `progress` on rank 0 when
// `show_progress`; `quiet` silences the plot scripts (as --json does). Returns the report.
Report run_loaded_command(const Command& command, dealii::ParameterHandler& prm,
                          const std::string& output_directory, MPI_Comm communicator,
                          std::ostream& progress, bool show_progress, bool quiet);

// An error message as one line of reasonable length (newlines become spaces, long words and a
// long message are cut): what the command line prints after "gearstiff: error: ".
std::string one_line(const std::string& text);

// The user-facing message of a deal.II exception, without the developer's file/line context.
std::string deal_ii_message(const dealii::ExceptionBase& e);
} // namespace gearstiff::app
