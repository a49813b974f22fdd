// The process's scratch folder, apart from command.h so that the report writer (TemporaryCsv)
// needs it without including the command registry that includes the report (no include cycle).
// Defined in app/core/command.cc beside the signal thread that removes it.
#pragma once

#include <mpi.h>
#include <string>

namespace gearstiff::app
{
// The process's folder for scratch files (scene meshes, temporary CSV): a hidden
// `gearstiff-scratch-<pid>` in the temporary folder, created on first use. It is removed at exit,
// by SIGINT/SIGTERM/SIGHUP (install_signal_cleanup) and, after a SIGKILL, by the next run, so no
// scratch file outlives the process (a cycloid-loads run stopped by SIGTERM left 1.9 MB meshes).
std::string scratch_directory();
// scratch_directory() of rank 0 on every rank (a file rank 0 writes and every rank reads).
std::string shared_scratch_directory(MPI_Comm communicator);
} // namespace gearstiff::app
