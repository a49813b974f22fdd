// Scratch scene files of the stiffness tests: <build>/tests/stiffness/work/<name>-<pid> (a stem),
// with rank 0's process id on every rank (a distributed solve reads the file rank 0 writes).
#pragma once

#include "tests/test_paths.h"

#include <deal.II/base/mpi.h>
#include <filesystem>
#include <string>
#include <unistd.h>

inline std::string stiffness_work_stem(const std::string& name)
{
  const auto folder = gearstiff::test_support::build_work_folder("tests/stiffness/work");
  const int pid = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, static_cast<int>(getpid()), 0);
  return (folder / (name + "-" + std::to_string(pid))).string();
}
