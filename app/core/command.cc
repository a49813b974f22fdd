#include "app/core/command.h"

#include "app/core/tools_directory.h"
#include "errors/errors.h"
#include "errors/file_names.h"

#include <algorithm>
#include <array>
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <pthread.h>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

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

namespace
{
namespace fs = std::filesystem;
const std::string staging_prefix = ".gearstiff-staging-";

// The staging folder the signal thread removes (empty: none); guarded by the mutex.
std::mutex staging_mutex;
std::string staging_to_remove;
// The scratch folder (scratch_directory()), removed at exit and by the signal thread.
std::string scratch_to_remove;
const std::string scratch_prefix = "gearstiff-scratch-";

struct ScratchRemoval
{
  ~ScratchRemoval()
  {
    const std::lock_guard<std::mutex> lock(staging_mutex);
    std::error_code error;
    if (!scratch_to_remove.empty())
      fs::remove_all(scratch_to_remove, error);
    scratch_to_remove.clear();
  }
};

void set_staging_to_remove(const std::string& path)
{
  const std::lock_guard<std::mutex> lock(staging_mutex);
  staging_to_remove = path;
}

// The nearest folder at or above `path` that exists (the current folder at the end).
fs::path existing_ancestor(const fs::path& path)
{
  fs::path candidate = fs::absolute(path).lexically_normal();
  while (!candidate.empty() && !fs::exists(candidate))
    candidate = candidate.parent_path();
  return candidate.empty() ? fs::current_path() : candidate;
}

// Staging (or scratch) folders in `folder` of processes that no longer run (killed by SIGKILL, or
// a crash): nothing will ever move or remove them.
void remove_stale_staging(const fs::path& folder, const std::string& prefix = staging_prefix)
{
  std::error_code error;
  if (!fs::is_directory(folder, error))
    return;
  for (const auto& entry : fs::directory_iterator(folder, error))
  {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0)
      continue;
    const std::string digits = name.substr(prefix.size());
    if (digits.empty() || digits.size() > 9 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
      continue;
    const long pid = std::stol(digits);
    if (pid > 0 && kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
      fs::remove_all(entry.path(), error);
  }
}

void wait_for_signals(sigset_t signals)
{
  int signal_number = 0;
  if (sigwait(&signals, &signal_number) != 0)
    return;
  {
    const std::lock_guard<std::mutex> lock(staging_mutex);
    std::error_code error;
    // Twice: the main thread may still be creating a file while the first pass runs.
    for (int pass = 0; pass < 2 && !staging_to_remove.empty(); ++pass)
      fs::remove_all(staging_to_remove, error);
    for (int pass = 0; pass < 2 && !scratch_to_remove.empty(); ++pass)
      fs::remove_all(scratch_to_remove, error);
    // An MPI job ends by SIGTERM to every rank when one rank was killed (SIGKILL): that rank's
    // scratch folder is stale by now (mpirun has reaped it), and the next run would remove it.
    if (!scratch_to_remove.empty())
      remove_stale_staging(fs::path(scratch_to_remove).parent_path(), scratch_prefix);
  }
  std::signal(signal_number, SIG_DFL);
  pthread_sigmask(SIG_UNBLOCK, &signals, nullptr);
  raise(signal_number);
  _exit(128 + signal_number); // not reached: the default action ends the process
}
} // namespace

void install_signal_cleanup()
{
  sigset_t signals;
  sigemptyset(&signals);
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP})
  {
    // A signal the caller ignores (nohup, a background job) stays ignored.
    struct sigaction current
    {
    };
    if (sigaction(signal_number, nullptr, &current) == 0 && current.sa_handler != SIG_IGN)
      sigaddset(&signals, signal_number);
  }
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  std::thread(wait_for_signals, signals).detach();
  // Without this, `ulimit -f` killed the process in the middle of the scene mesh (exit 153) and
  // left its staging folder; ignored, the write fails with EFBIG and is checked like any other.
  // Child processes (the plot scripts) inherit it: Python then raises OSError [Errno 27].
  std::signal(SIGXFSZ, SIG_IGN);
}

IoError located(const IoError& error, const std::string& staging_directory,
                const std::string& output_directory)
{
  if (!error.place().empty())
    return error;
  const fs::path path(error.path());
  if (!staging_directory.empty() && error.path().rfind(staging_directory + "/", 0) == 0)
    return IoError(path.lexically_relative(staging_directory).string(), error.reason(),
                   "-o " + output_directory);
  std::error_code ignored;
  const fs::path temporary = fs::temp_directory_path(ignored);
  if (!temporary.empty() && error.path().rfind((temporary / scratch_prefix).string(), 0) == 0)
    return IoError(path.lexically_relative(temporary).string(), error.reason(),
                   "TMPDIR (" + temporary.string() + ")");
  return error;
}

StagedOutput::StagedOutput(const std::string& directory_, MPI_Comm communicator)
    : directory(directory_), communicator(communicator)
{
  check_file_name(directory, "-o"); // every rank holds the same name: all throw alike
  int rank = 0;
  MPI_Comm_rank(communicator, &rank);
  root = rank == 0;
  // All ranks must agree on the name: rank 0's process id. Rank 0 checks and creates.
  long id = static_cast<long>(getpid());
  MPI_Bcast(&id, 1, MPI_LONG, 0, communicator);
  int ok = 1;
  std::string problem;
  fs::path parent;
  if (root)
  {
    std::error_code error;
    parent = existing_ancestor(directory);
    if (fs::exists(directory, error) && !fs::is_directory(directory, error))
      problem = "'" + directory + "' exists and is not a folder";
    else if (!fs::is_directory(parent, error))
      problem = "'" + parent.string() + "' is not a folder";
    else if (access(parent.c_str(), W_OK | X_OK) != 0)
      problem = "cannot write into '" + parent.string() + "'";
    if (problem.empty())
    {
      remove_stale_staging(parent);
      remove_stale_staging(directory); // where earlier versions staged
      staging = (parent / (staging_prefix + std::to_string(id))).string();
      set_staging_to_remove(staging);
      fs::create_directory(staging, error);
      if (error)
        problem = "cannot create '" + staging + "': " + error.message();
    }
    ok = problem.empty();
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, communicator);
  if (!ok)
  {
    if (root)
      set_staging_to_remove("");
    throw InputError("-o", problem);
  }
  // The other ranks learn the path (they write their own VTU pieces into it). They remove it on
  // a signal too: when rank 0 was killed (SIGKILL), mpirun ends them by SIGTERM.
  int length = static_cast<int>(staging.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, communicator);
  staging.resize(length);
  MPI_Bcast(staging.data(), length, MPI_CHAR, 0, communicator);
  if (!root)
    set_staging_to_remove(staging);
}

namespace
{
// The command and the files that a run's summary.json names (empty if the folder has none, or
// one gearstiff did not write).
struct RunFiles
{
  std::string command;
  std::vector<std::string> files;
};

RunFiles run_files(const fs::path& summary)
{
  RunFiles run;
  std::error_code error;
  if (!fs::is_regular_file(summary, error))
    return run;
  try
  {
    boost::property_tree::ptree tree;
    boost::property_tree::read_json(summary.string(), tree);
    run.command = tree.get<std::string>("command", "");
    if (const auto files = tree.get_child_optional("files"))
      for (const auto& entry : *files)
        run.files.push_back(entry.second.data());
  }
  catch (const std::exception&)
  {
    return {};
  }
  return run;
}

// Into an existing folder that holds an earlier run's results: that run's files which this one
// does not write are removed when it was the same command (they would sit beside these as if
// this run had written them: a sweep's stiffness_table.prm and te_map.csv beside a later
// single position's summary, found 2026-12-07); another command's results are kept, and a note
// says whose they are. Files the summary does not name (the user's own) are never touched.
void settle_earlier_results(const fs::path& folder, const fs::path& staging)
{
  const RunFiles earlier = run_files(folder / "summary.json");
  if (earlier.command.empty())
    return;
  const RunFiles now = run_files(staging / "summary.json");
  const std::string where = "-o " + folder.string();
  if (earlier.command != now.command)
  {
    std::cerr << "gearstiff: note: " << where << " held the results of `gearstiff "
              << earlier.command << "`; files of the same names are replaced, its others kept\n";
    return;
  }
  std::vector<std::string> removed;
  for (const std::string& file : earlier.files)
  {
    std::error_code error;
    const fs::path name(file);
    if (file.empty() || name.has_parent_path() || fs::exists(staging / name, error) ||
        !fs::is_regular_file(folder / name, error))
      continue;
    if (fs::remove(folder / name, error))
      removed.push_back(file);
  }
  if (removed.empty())
    return;
  std::string listed;
  for (std::size_t i = 0; i < removed.size() && i < 4; ++i)
    listed += (i == 0 ? "" : ", ") + removed[i];
  std::cerr << "gearstiff: note: " << where << ": removed " << removed.size()
            << " file(s) of the earlier `gearstiff " << earlier.command
            << "` run there that this run does not write (" << listed
            << (removed.size() > 4 ? ", ..." : "") << ")\n";
}
} // namespace

StagedOutput::~StagedOutput()
{
  if (committed)
    return;
  if (root)
  {
    std::error_code error;
    fs::remove_all(staging, error);
  }
  set_staging_to_remove("");
}

void StagedOutput::commit()
{
  // Every rank has written its files (VTU pieces) before rank 0 moves them.
  MPI_Barrier(communicator);
  if (!root)
  {
    set_staging_to_remove("");
    committed = true;
    return;
  }
  std::error_code error;
  if (!fs::exists(directory, error))
  {
    // A new folder appears complete, in one rename; to the normalised path, whose parents were
    // created ("a/../out" with no folder a failed in the rename, exit 1: cli.fuzz, issue 42).
    const fs::path target = fs::absolute(directory).lexically_normal();
    fs::create_directories(target.parent_path(), error);
    fs::rename(staging, target);
  }
  else
  {
    // An existing folder: its files of the same names are replaced; an earlier run's other
    // results go when they were the same command's, others are kept.
    settle_earlier_results(directory, staging);
    for (const auto& entry : fs::directory_iterator(staging))
    {
      const fs::path target = fs::path(directory) / entry.path().filename();
      fs::remove_all(target);
      fs::rename(entry.path(), target);
    }
    fs::remove_all(staging);
  }
  committed = true;
  set_staging_to_remove("");
}

std::string scratch_directory()
{
  static ScratchRemoval removal; // constructed before the path is set: destroyed after use
  const std::lock_guard<std::mutex> lock(staging_mutex);
  if (scratch_to_remove.empty())
  {
    std::error_code error;
    const fs::path temporary = fs::temp_directory_path(error);
    remove_stale_staging(temporary, scratch_prefix);
    const fs::path folder = temporary / (scratch_prefix + std::to_string(getpid()));
    fs::create_directories(folder, error);
    if (error)
      throw InputError("TMPDIR", "cannot create the scratch folder '" + folder.string() +
                                     "': " + error.message());
    scratch_to_remove = folder.string();
  }
  return scratch_to_remove;
}

std::string shared_scratch_directory(MPI_Comm communicator)
{
  std::string folder = scratch_directory();
  int length = static_cast<int>(folder.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, communicator);
  folder.resize(length);
  MPI_Bcast(folder.data(), length, MPI_CHAR, 0, communicator);
  return folder;
}

CommandContext::CommandContext(MPI_Comm communicator, dealii::ConditionalOStream& pcout,
                               const std::string& staging_directory, bool quiet, bool show_progress)
    : mpi_communicator(communicator), pcout(pcout), staging_directory(staging_directory),
      quiet(quiet), show_progress(show_progress)
{
}

void CommandContext::progress(const std::string& stage, const std::string& text) const
{
  if (!show_progress)
    return;
  int rank = 0, ranks = 1;
  MPI_Comm_rank(mpi_communicator, &rank);
  MPI_Comm_size(mpi_communicator, &ranks);
  std::ostringstream line;
  line << stage << ": " << text;
  if (ranks > 1)
    line << " [rank " << rank << "]";
  line << '\n';
  // One write per line, so that the lines of several ranks do not interleave within a line.
  std::cerr << line.str() << std::flush;
}

std::function<void(const std::string&)> CommandContext::progress_counter(const std::string& stage,
                                                                         double share) const
{
  const auto start = std::chrono::steady_clock::now();
  auto done = std::make_shared<unsigned int>(0);
  return [this, stage, share, start, done](const std::string& text)
  {
    ++*done;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // `share` is an even split; ranks that take the next free item (fem::distribute_items) can
    // solve more than it: then the count itself is the best estimate of the total here.
    const double expected = std::max(share, double(*done));
    const double left = (expected - *done) * elapsed / *done;
    std::ostringstream line;
    line.precision(3);
    line << text << " (" << *done << " done here of ~" << std::lround(expected) << ", " << elapsed
         << " s elapsed, ~" << left << " s left)";
    progress(stage, line.str());
  };
}

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
  std::error_code error;
  std::filesystem::create_directories(path.parent_path(), error);
  if (error)
    record_write_failure(path.parent_path().string(),
                         write_failure_reason(path.string(), error.value()));
  report.add_output_file(name, description);
  return path.string();
}

std::string CommandContext::write_output(const std::string& name, const std::string& description,
                                         const std::function<void(std::ostream&)>& write)
{
  const std::string path = output_file(name, description);
  if (!write_failure.first.empty())
    return path; // the run fails already; no need to fill the disk further
  try
  {
    write_file(path, write);
  }
  catch (const IoError& e)
  {
    record_write_failure(e.path(), e.reason());
  }
  return path;
}

void CommandContext::record_write_failure(const std::string& path, const std::string& reason)
{
  if (write_failure.first.empty())
    write_failure = {path, reason};
}

void CommandContext::throw_write_failure() const
{
  if (!write_failure.first.empty())
    throw IoError(write_failure.first, write_failure.second);
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

// A finished script: its exit status (as pclose gives it) and everything it printed.
struct ScriptRun
{
  int status = -1;
  std::string output; // stdout and stderr
};

// Runs a shell command with its output captured: a plot script's traceback is never passed on.
ScriptRun run_captured(const std::string& command)
{
  ScriptRun run;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr)
    return run;
  std::array<char, 4096> buffer{};
  for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;)
    run.output.append(buffer.data(), n);
  run.status = pclose(pipe);
  return run;
}

// No python3 (the shell's 127) or no matplotlib/numpy: a chart the machine cannot draw.
bool python_missing(const ScriptRun& run)
{
  return (WIFEXITED(run.status) && WEXITSTATUS(run.status) == 127) ||
         run.output.find("ModuleNotFoundError") != std::string::npos ||
         run.output.find("ImportError") != std::string::npos;
}

// Why a plot script did not write `png`: the errno of its OSError ("OSError: [Errno 28] No space
// left on device: '...'") in errors/io.h's words, else its last line.
std::string script_failure_reason(const std::string& script, const std::string& png,
                                  const ScriptRun& run)
{
  std::string line;
  std::istringstream lines(run.output);
  for (std::string next; std::getline(lines, next);)
    if (next.find_first_not_of(" \t\r") != std::string::npos)
      line = next;
  const std::size_t at = line.find("[Errno ");
  if (at != std::string::npos)
    return write_failure_reason(png, std::atoi(line.c_str() + at + 7));
  if (line.empty())
    line = run.status == 0 ? "no chart written" : "exit status " + std::to_string(run.status);
  return script + " failed: " + line;
}
} // namespace

bool CommandContext::plot(const std::string& script, const std::vector<std::string>& arguments,
                          const std::string& png_name, const std::string& description)
{
  if (!writes_files() || !is_root() || !write_failure.first.empty())
    return false;
  const std::string python =
      std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string script_path = tools_directory() + "/" + script;
  if (!std::filesystem::exists(script_path))
  {
    pcout << "note: plot script " << script_path << " not found; " << png_name << " not drawn\n";
    return false;
  }
  // A table the script would read, cut short by a full scratch disk, is this chart's failure.
  for (const auto& a : arguments)
    if (const std::string reason = temporary_write_failure(a); !reason.empty())
    {
      record_write_failure(a, reason);
      return false;
    }
  const std::string png = (std::filesystem::path(staging_directory) / png_name).string();
  std::ostringstream command;
  if (!chart_case.empty())
    command << "GEARSTIFF_CHART_CASE=" << shell_quote(chart_case) << " ";
  command << python << " " << shell_quote(script_path);
  for (const auto& a : arguments)
    command << " " << shell_quote(a);
  command << " " << shell_quote(png);
  const ScriptRun run = run_captured(command.str());
  if (run.status == 0 && std::filesystem::exists(png))
  {
    if (!quiet)
      std::cerr << run.output << std::flush;
    report.add_output_file(png_name, description);
    return true;
  }
  if (python_missing(run))
  {
    pcout << "note: could not draw " << png_name
          << " (python3 with matplotlib is needed: apt-get install python3-matplotlib)\n";
    return false;
  }
  record_write_failure(png, script_failure_reason(script, png, run));
  return false;
}
} // namespace gearstiff::app
