#include "app/fe_contact_parameters.h"

namespace gearstiff::app
{
void declare_fe_contact_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Finite elements");
  fem::ElasticityParameters::declare_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("Linear solver");
  fem::LinearSolverParameters::declare_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("Contact");
  contact::ContactParameters::declare_parameters(prm);
  prm.leave_subsection();
}

void parse_fe_contact_parameters(dealii::ParameterHandler& prm,
                                 fem::ElasticityParameters& elasticity,
                                 fem::LinearSolverParameters& linear_solver,
                                 contact::ContactParameters& contact)
{
  prm.enter_subsection("Finite elements");
  elasticity.parse_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("Linear solver");
  linear_solver.parse_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("Contact");
  contact.parse_parameters(prm);
  prm.leave_subsection();
}
} // namespace gearstiff::app
