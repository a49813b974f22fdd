// Errors and results across MPI ranks. A rank that fails must not leave the others waiting in a
// collective call, and every rank must report the same error: a failure is caught where it
// happens (catch_failure), the first failure over all ranks is agreed on in one collective
// (first_failure) and rethrown with its type, parameter or method and reason on every rank
// (Failure::rethrow). Results travel with dealii::Utilities::MPI::broadcast / all_gather of
// structs with a boost-style `serialize` member (no hand-packed rows of doubles).
//
//   fem::Failure failure = fem::catch_failure([&] { result = solve(); });
//   fem::first_failure(comm, failure).rethrow(); // collective; throws on every rank or none
//
//   const Result r = fem::run_on_root(comm, [&] { return solve(); }); // rank 0 works
#pragma once

#include <climits>
#include <deal.II/base/mpi.h>
#include <functional>
#include <mpi.h>
#include <string>

namespace gearstiff::fem
{
// A caught exception in a form that can cross ranks: the type of gearstiff's error contract
// (errors/errors.h) and its two parts.
struct Failure
{
  enum Kind : int
  {
    none = 0,
    input = 1,  // InputError(parameter, reason)
    solver = 2, // SolverFailure(method, reason)
    other = 3   // any other std::exception (reason = what())
  };
  int kind = none;
  std::string name;   // the parameter (input) or the method (solver); empty otherwise
  std::string reason; // why

  bool failed() const { return kind != none; }
  // Throws the exception this Failure was made from (same type, same parts), with `context`
  // put in front of the reason; returns only when nothing failed.
  void rethrow(const std::string& context = "") const;

  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    archive& kind& name& reason;
  }
};

// Runs `work`, catching InputError, SolverFailure and other std::exceptions into a Failure.
Failure catch_failure(const std::function<void()>& work);

// Collective over `communicator`: the failure with the smallest `order` over all ranks (ties:
// the lowest rank), identical on every rank; kind none when no rank failed. `order` lets a
// caller prefer e.g. the first position of a sweep; by default the lowest failing rank wins.
Failure first_failure(MPI_Comm communicator, const Failure& local, int order = 0);

// Runs `work` on rank 0 of `communicator` only; every rank returns its result (broadcast) or
// throws its exception. T needs a default constructor and a boost `serialize`.
template <typename Work>
auto run_on_root(MPI_Comm communicator, Work work) -> decltype(work())
{
  decltype(work()) value{};
  Failure failure;
  if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
    failure = catch_failure([&]() { value = work(); });
  first_failure(communicator, failure).rethrow();
  return dealii::Utilities::MPI::broadcast(communicator, value, 0);
}
} // namespace gearstiff::fem
