#include "fem/parallel.h"

#include "errors/errors.h"
#include "errors/io.h"

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
  case io:
    throw IoError(name, context + reason, place);
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
    failure = {Failure::input, e.parameter(), e.reason(), ""};
  }
  catch (const SolverFailure& e)
  {
    failure = {Failure::solver, e.method(), e.reason(), ""};
  }
  catch (const IoError& e)
  {
    failure = {Failure::io, e.path(), e.reason(), e.place()};
  }
  catch (const Stopped& e)
  {
    failure = {Failure::stopped, "", e.what(), ""};
  }
  catch (const std::exception& e)
  {
    failure = {Failure::other, "", e.what(), ""};
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

namespace
{
// The next item nobody has taken, shared by the ranks of one distributed loop: an integer in
// rank 0's memory that every rank increments atomically (MPI_Fetch_and_op in a passive-target
// epoch: rank 0 need not take part, and with all ranks on one node Open MPI's shared-memory
// window makes it a plain atomic add). A rank that finishes early takes the next item instead
// of idling at the end of a fixed share: a sweep position whose scene must be meshed twice
// costs 1.7 times its neighbours, and a fixed round-robin share left the other rank waiting
// (issue 12).
class ItemCounter
{
public:
  explicit ItemCounter(MPI_Comm communicator) // collective
  {
    int* base = nullptr;
    const bool root = dealii::Utilities::MPI::this_mpi_process(communicator) == 0;
    MPI_Win_allocate(root ? sizeof(int) : 0, sizeof(int), MPI_INFO_NULL, communicator, &base,
                     &window);
    MPI_Win_lock_all(0, window);
    if (root)
    {
      const int zero = 0;
      MPI_Accumulate(&zero, 1, MPI_INT, 0, 0, 1, MPI_INT, MPI_REPLACE, window);
      MPI_Win_flush(0, window);
    }
    MPI_Barrier(communicator); // nobody takes an item before the counter is zero
  }
  ~ItemCounter() // collective
  {
    MPI_Win_unlock_all(window);
    MPI_Win_free(&window);
  }
  ItemCounter(const ItemCounter&) = delete;
  ItemCounter& operator=(const ItemCounter&) = delete;

  unsigned int take()
  {
    const int one = 1;
    int taken = 0;
    MPI_Fetch_and_op(&one, &taken, MPI_INT, 0, 0, MPI_SUM, window);
    MPI_Win_flush(0, window);
    return static_cast<unsigned int>(taken);
  }

private:
  MPI_Win window = MPI_WIN_NULL;
};
} // namespace

void distribute_items(MPI_Comm communicator, const unsigned int n,
                      const std::function<void(unsigned int)>& item)
{
  StopSignal signal(communicator);
  ItemCounter counter(communicator);
  Failure failure;
  unsigned int failed_item = 0;
  {
    const InterruptionScope scope(signal);
    while (!signal.should_stop())
    {
      const unsigned int i = counter.take();
      if (i >= n)
        break;
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
