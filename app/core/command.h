// The `gearstiff` command line: one Command per sub-command, registered by a static
// CommandRegistration in its own app/<wing>/*_command.cc file, so adding a command touches no other
// file.
//
// Every command:
//  - declares its parameters (one subsection per parameter struct, units in each documentation
//    string) so `--print-parameters` lists them with defaults and allowed values;
//  - has a built-in default case: it runs with no parameter file;
//  - fills a Report; the driver prints it (text or --json) and, with -o DIR, writes it together
//    with the parameters actually used. Files are written into a staging folder and moved into
//    DIR only when the command succeeded, so a failed run leaves nothing that looks like a result
//    (StagedOutput: DIR itself is created only then, and SIGINT/SIGTERM remove the staging).
//    Every write is checked (errors/io.h): a file not written whole (a full disk, `ulimit -f`)
//    fails the command with one line naming it and why, exit 1, and nothing reaches DIR.
#pragma once

#include "app/core/report.h"
#include "app/core/scratch.h"
#include "errors/io.h"

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <map>
#include <mpi.h>
#include <string>
#include <utility>
#include <vector>

namespace gearstiff::app
{
// What a running command may use besides its parameters.
class CommandContext
{
public:
  // `quiet`: plot scripts print nothing (--json or --quiet); `show_progress`: progress lines
  // (off with --quiet).
  CommandContext(MPI_Comm communicator, dealii::ConditionalOStream& pcout,
                 const std::string& staging_directory, bool quiet, bool show_progress = true);

  MPI_Comm mpi_communicator;
  dealii::ConditionalOStream& pcout; // progress and diagnostics (stderr; nowhere with --quiet)
  Report report;

  // True when the user gave -o DIR; only then should files be written.
  bool writes_files() const { return !staging_directory.empty(); }
  // Path of a result file to write (inside the staging folder); registers it for the listing.
  // For a file another library writes (VTU, gmsh) and checks (errors/io.h).
  std::string output_file(const std::string& name, const std::string& description);
  // Writes result file `name` through `write`, checked (errors/io.h write_file). A failed write
  // does not stop the command here, on the one rank that writes: the run ends with that
  // IoError on every rank (run_loaded_command), and nothing reaches -o.
  // Returns the path (for a plot script that reads the file).
  std::string write_output(const std::string& name, const std::string& description,
                           const std::function<void(std::ostream&)>& write);
  // Runs tools/<script> with python3 (matplotlib) if available. A missing python3 or
  // matplotlib is reported on pcout and skipped: charts are a convenience. A script that fails
  // otherwise (a full disk, the file-size limit) fails the command as write_output does, with the
  // reason from its last line, never its traceback.
  bool plot(const std::string& script, const std::vector<std::string>& arguments,
            const std::string& png_name, const std::string& description);
  // The case every chart names in a footer line (tools/chart_case.py), e.g. "z 23/61, m_n 4 mm,
  // b 30 mm, x 0.2/-0.1, T1 = 300 N·m": a chart copied into a slide or a report still says what
  // it shows. Set by the command once its parameters are read; empty: no footer.
  std::string chart_case;
  // Throws the first failed write of this rank (write_output, plot), if any.
  void throw_write_failure() const;
  bool is_root() const;

  // One progress line on stderr from the calling rank — any rank, the one that did the work —
  // unless --quiet: "<stage>: <text> [rank r]" (the rank only when there are several). Never on
  // stdout, so a --json run's stdout stays one JSON object.
  void progress(const std::string& stage, const std::string& text) const;
  // A counter for `total` items of one stage on this rank: call it after each item with the
  // item's text; it prints "<stage>: <text> (<i>/<total> on this rank's share, <t> s elapsed,
  // ~<s> s left)" through progress(). `share`: the items this rank expects (total / ranks).
  std::function<void(const std::string&)> progress_counter(const std::string& stage,
                                                           double share) const;

private:
  std::string staging_directory;
  bool quiet;
  bool show_progress;
  // The first write that failed (an IoError's path and reason; path empty: none).
  std::pair<std::string, std::string> write_failure;
  void record_write_failure(const std::string& path, const std::string& reason);
};

struct Command
{
  std::string name;
  std::string summary;     // one line for `gearstiff --help`
  std::string description; // several lines for `gearstiff NAME --help`
  std::function<void(dealii::ParameterHandler&)> declare_parameters;
  std::function<void(dealii::ParameterHandler&, CommandContext&)> run;
};

std::map<std::string, Command>& command_registry();

struct CommandRegistration
{
  explicit CommandRegistration(Command command);
};

// The life of the -o folder DIR. Results go into a hidden staging folder
// `.gearstiff-staging-<pid>` in the nearest existing folder above DIR (same file system, so
// the final move is a rename). commit() moves them into DIR, creating it only then (one
// rename when DIR is new); otherwise the staging folder is removed by the destructor, by
// SIGINT/SIGTERM/SIGHUP (install_signal_cleanup; on every rank, so that a job whose rank 0 was
// killed still removes it) or, after a SIGKILL of every rank, by the next run, which removes
// staging folders of processes that no longer exist. Only rank 0 moves the files.
class StagedOutput
{
public:
  // Collective. InputError("-o") when DIR is a file or its folder is not writable.
  StagedOutput(const std::string& directory, MPI_Comm communicator);
  ~StagedOutput();
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  const std::string& staging_directory() const { return staging; }
  void commit(); // collective; rank 0 moves the results into DIR

private:
  std::string directory;
  MPI_Comm communicator;
  std::string staging;
  bool root = false;
  bool committed = false;
};

// Blocks SIGINT, SIGTERM and SIGHUP in the calling thread (call it first in main, before any
// other thread exists, so every thread inherits the mask) and starts a thread that waits for
// them, removes the current staging folder and ends the process by the same signal (exit
// status 128 + signal number, as a shell reports it). SIGXFSZ is ignored: a write beyond the
// file-size limit (ulimit -f) then fails with EFBIG and is reported as an I/O error, with the
// staging and scratch folders removed, instead of killing the process in the middle of a file.
void install_signal_cleanup();

// `error` as the user should read it: a path in the staging folder becomes the file of the -o
// folder `output_directory` ("-o out: cannot write 'summary.json': ..."), a scratch path is
// named under TMPDIR.
IoError located(const IoError& error, const std::string& staging_directory,
                const std::string& output_directory);
} // namespace gearstiff::app
