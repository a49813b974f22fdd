#include "fem/parallel.h"

#include "errors/errors.h"

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
} // namespace gearstiff::fem
