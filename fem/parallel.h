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
//
// A loop of independent items spread over the ranks (sweep positions, crank angles) stops on
// every rank soon after the first failure, not when the others reach the next collective: the
// failing rank posts a notice to the others (StopSignal), and their long work looks for it at
// cheap points (interruption_point(): the contact iterations, mesh reading, between items).
//
//   fem::distribute_items(comm, n, [&](unsigned int i) { results[i] = solve(i); });
#pragma once

#include <climits>
#include <deal.II/base/mpi.h>
#include <functional>
#include <mpi.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace gearstiff::fem
{
// A caught exception in a form that can cross ranks: the type of gearstiff's error contract
// (errors/errors.h) and its two parts.
struct Failure
{
  enum Kind : int
  {
    none = 0,
    input = 1,   // InputError(parameter, reason)
    solver = 2,  // SolverFailure(method, reason)
    other = 3,   // any other std::exception (reason = what())
    stopped = 4, // Stopped: another rank failed; never a failure of its own, never sent
    io = 5       // IoError(path, reason, place) (errors/io.h): a file not written whole
  };
  int kind = none;
  std::string name;   // the parameter (input), the method (solver) or the path (io); else empty
  std::string reason; // why
  std::string place;  // io: where the path lives (IoError::place); empty otherwise

  // A failure of this rank's own work (not a stop for another rank's failure).
  bool failed() const { return kind != none && kind != stopped; }
  bool was_stopped() const { return kind == stopped; }
  // Throws the exception this Failure was made from (same type, same parts), with `context`
  // put in front of the reason; returns only when nothing failed or stopped.
  void rethrow(const std::string& context = "") const;

  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    archive& kind& name& reason& place;
  }
};

// Thrown at an interruption point when another rank has failed: this rank drops its work, and
// the other rank's failure is the one every rank reports.
class Stopped : public std::runtime_error
{
public:
  Stopped() : std::runtime_error("stopped because another MPI rank failed") {}
};

// Runs `work`, catching InputError, SolverFailure, IoError, Stopped and other std::exceptions
// into a Failure.
Failure catch_failure(const std::function<void()>& work);

// Collective over `communicator`: the failure with the smallest `order` over all ranks (ties:
// the lowest rank), identical on every rank; kind none when no rank failed. `order` lets a
// caller prefer e.g. the first position of a sweep; by default the lowest failing rank wins.
Failure first_failure(MPI_Comm communicator, const Failure& local, int order = 0);

// The failure notices of one distributed loop, on a duplicate of its communicator (a notice
// cannot be mistaken for any other message, nor one loop's notice for the next loop's).
// Protocol: a rank whose work failed calls notify() (non-blocking sends, one to every other
// rank); every rank polls should_stop() between cheap steps; finish() (collective) receives
// every notice still in flight, completes the sends and agrees on the first failure, so no
// message is left pending when the loop returns.
class StopSignal
{
public:
  explicit StopSignal(MPI_Comm communicator); // collective
  ~StopSignal();
  StopSignal(const StopSignal&) = delete;
  StopSignal& operator=(const StopSignal&) = delete;

  // This rank failed: tells every other rank, once.
  void notify();
  // Whether this rank failed or a notice of another rank has arrived (a non-blocking probe).
  bool should_stop();
  // Collective: drains the notices, then fem::first_failure(local, order).
  Failure finish(const Failure& local, int order);

private:
  MPI_Comm communicator;
  bool notified = false;         // this rank failed and told the others
  std::vector<MPI_Request> sent; // this rank's notices, one per other rank
  int received = 0;              // notices of other ranks received so far
};

// While an InterruptionScope lives (on this thread), interruption_point() throws Stopped once
// `signal` says stop. Scopes nest; the innermost one counts.
class InterruptionScope
{
public:
  explicit InterruptionScope(StopSignal& signal);
  ~InterruptionScope();
  InterruptionScope(const InterruptionScope&) = delete;
  InterruptionScope& operator=(const InterruptionScope&) = delete;

private:
  StopSignal* previous;
};

// A cheap point of a long computation where it may be abandoned: throws Stopped when the
// current InterruptionScope's signal says stop; does nothing outside a scope (serial runs).
// Only work on MPI_COMM_SELF may run inside a scope: ranks that share a computation could be
// stopped at different points and leave a collective call waiting.
void interruption_point();

// Collective: item(i) for i = 0 ... n − 1, each item on one rank: the ranks take items in
// increasing order from a shared counter as they become free (which rank solves which item
// varies from run to run; items that cost more than others do not leave a rank idle). When an item
// fails, every rank stops at its next interruption point or item, and every rank throws the failure
// of the lowest item index among those that failed (items stopped early do not count); returns only
// when every item succeeded. item(i) may throw any exception of the error contract; results cross
// ranks afterwards (all_gather).
void distribute_items(MPI_Comm communicator, unsigned int n,
                      const std::function<void(unsigned int)>& item);

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
  failure.rethrow(); // work stopped for another rank's failure (interruption_point): no value
  return dealii::Utilities::MPI::broadcast(communicator, value, 0);
}
} // namespace gearstiff::fem
