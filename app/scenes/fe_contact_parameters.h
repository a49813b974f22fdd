// Parameter-file form of the FE contact model, shared by the `contact` command and the
// stiffness analyses (app/stiffness/stiffness_parameters.h): subsections "Finite elements"
// (fem::ElasticityParameters), "Linear solver" (fem::LinearSolverParameters) and "Contact"
// (contact::ContactParameters), each declared and parsed by its own struct. A command may set
// other defaults or declare further entries in these subsections after declaring them.
#pragma once

#include "contact/contact_problem.h"
#include "fem/parameters.h"

#include <deal.II/base/parameter_handler.h>

namespace gearstiff::app
{
void declare_fe_contact_parameters(dealii::ParameterHandler& prm);
void parse_fe_contact_parameters(dealii::ParameterHandler& prm,
                                 fem::ElasticityParameters& elasticity,
                                 fem::LinearSolverParameters& linear_solver,
                                 contact::ContactParameters& contact);
} // namespace gearstiff::app
