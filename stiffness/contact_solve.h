// The solve step every stiffness analysis shares: set up and solve its contact problem, then
// record the problem's size, active-set iterations and times in the analysis' result. With
// `warm_start` the iteration starts from the contact zones it holds (a neighbouring sweep
// position's, when not empty) and leaves this solve's converged zones in it. An analysis that
// must tell setup errors (e.g. an initial overlap) from solve errors calls setup_system() itself
// and then solve_set_up_contact_problem().
#pragma once

#include "contact/contact_problem.h"

#include <vector>

namespace gearstiff::stiffness
{
// `Result` has the members n_dofs, active_set_iterations, setup_time and solve_time (s, wall;
// the solve time counts the contact assembly and the linear solves).
template <int dim, typename Result>
void solve_set_up_contact_problem(contact::ContactProblem<dim>& problem, Result& result,
                                  std::vector<contact::ContactZone>* warm_start = nullptr)
{
  if (warm_start && !warm_start->empty())
    problem.start_from(*warm_start);
  const contact::ContactResults<dim>& contact = problem.solve();
  if (warm_start)
    *warm_start = problem.converged_zones();
  result.n_dofs = contact.n_dofs;
  result.active_set_iterations = contact.active_set_iterations;
  result.setup_time = contact.setup_time;
  result.solve_time = contact.assembly_time + contact.solve_time;
}

template <int dim, typename Result>
void solve_contact_problem(contact::ContactProblem<dim>& problem, Result& result,
                           std::vector<contact::ContactZone>* warm_start = nullptr)
{
  problem.setup_system();
  solve_set_up_contact_problem(problem, result, warm_start);
}
} // namespace gearstiff::stiffness
