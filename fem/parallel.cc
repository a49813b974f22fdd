#include "fem/parallel.h"

#include "errors/errors.h"

#include <algorithm>
#include <boost/serialization/string.hpp>
#include <stdexcept>

namespace gearstiff::fem
{
void Failure::rethrow(const std::string& context) const
{
  switch (kind)
  {
  case none:
    return;
  case input:
    throw InputError(name, context + reason);
  case solver:
    throw SolverFailure(name, context + reason);
  case stopped:
    throw Stopped();
  default:
    throw std::runtime_error(context + reason);
  }
}

Failure catch_failure(const std::function<void()>& work)
{
  Failure failure;
  try
  {
    work();
  }
  catch (const InputError& e)
  {
    failure = {Failure::input, e.parameter(), e.reason()};
  }
  catch (const SolverFailure& e)
  {
    failure = {Failure::solver, e.method(), e.reason()};
  }
  catch (const Stopped& e)
  {
    failure = {Failure::stopped, "", e.what()};
  }
  catch (const std::exception& e)
  {
    failure = {Failure::other, "", e.what()};
  }
  return failure;
}

Failure first_failure(MPI_Comm communicator, const Failure& local, const int order)
{
  int rank = 0;
  MPI_Comm_rank(communicator, &rank);
  // MINLOC over (order, rank): ranks without a failure offer INT_MAX and never win.
  struct
  {
    int order;
    int rank;
  } mine{local.failed() ? std::min(order, INT_MAX - 1) : INT_MAX, rank}, first{};
  MPI_Allreduce(&mine, &first, 1, MPI_2INT, MPI_MINLOC, communicator);
  if (first.order == INT_MAX)
    return Failure();
  return dealii::Utilities::MPI::broadcast(communicator, local, first.rank);
}

namespace
{
// The tag of a failure notice (a zero-length message on the duplicated communicator).
constexpr int notice_tag = 1;

// The signal interruption_point() checks on this thread (InterruptionScope).
thread_local StopSignal* current_signal = nullptr;
} // namespace

StopSignal::StopSignal(MPI_Comm communicator_)
{
  MPI_Comm_dup(communicator_, &communicator);
}

StopSignal::~StopSignal()
{
  MPI_Comm_free(&communicator);
}

void StopSignal::notify()
{
  if (notified)
    return;
  notified = true;
  int rank = 0, ranks = 1;
  MPI_Comm_rank(communicator, &rank);
  MPI_Comm_size(communicator, &ranks);
  sent.reserve(ranks);
  for (int other = 0; other < ranks; ++other)
    if (other != rank)
    {
      sent.emplace_back();
      MPI_Isend(nullptr, 0, MPI_INT, other, notice_tag, communicator, &sent.back());
    }
}

bool StopSignal::should_stop()
{
  if (notified || received > 0)
    return true;
  int arrived = 0;
  MPI_Status status;
  MPI_Iprobe(MPI_ANY_SOURCE, notice_tag, communicator, &arrived, &status);
  if (arrived)
  {
    MPI_Recv(nullptr, 0, MPI_INT, status.MPI_SOURCE, notice_tag, communicator, MPI_STATUS_IGNORE);
    ++received;
  }
  return received > 0;
}

Failure StopSignal::finish(const Failure& local, const int order)
{
  // Every rank that notified sent one notice to each other rank: receive the rest of ours.
  const int mine = notified ? 1 : 0;
  int notifying = 0;
  MPI_Allreduce(&mine, &notifying, 1, MPI_INT, MPI_SUM, communicator);
  for (; received < notifying - mine; ++received)
    MPI_Recv(nullptr, 0, MPI_INT, MPI_ANY_SOURCE, notice_tag, communicator, MPI_STATUS_IGNORE);
  MPI_Waitall(static_cast<int>(sent.size()), sent.data(), MPI_STATUSES_IGNORE);
  sent.clear();
  notified = false;
  received = 0;
  return first_failure(communicator, local, order);
}

InterruptionScope::InterruptionScope(StopSignal& signal) : previous(current_signal)
{
  current_signal = &signal;
}

InterruptionScope::~InterruptionScope()
{
  current_signal = previous;
}

void interruption_point()
{
  if (current_signal != nullptr && current_signal->should_stop())
    throw Stopped();
}

void distribute_items(MPI_Comm communicator, const unsigned int n,
                      const std::function<void(unsigned int)>& item)
{
  const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(communicator);
  const unsigned int ranks = dealii::Utilities::MPI::n_mpi_processes(communicator);
  StopSignal signal(communicator);
  Failure failure;
  unsigned int failed_item = 0;
  {
    const InterruptionScope scope(signal);
    for (unsigned int i = rank; i < n && !signal.should_stop(); i += ranks)
    {
      const Failure outcome = catch_failure([&]() { item(i); });
      if (outcome.failed())
      {
        failure = outcome;
        failed_item = i;
        signal.notify();
      }
    }
  }
  signal.finish(failure, static_cast<int>(std::min<unsigned int>(failed_item, INT_MAX - 1)))
      .rethrow();
}
} // namespace gearstiff::fem
