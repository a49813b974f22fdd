// The deal.II names every parameter declaration in app/ uses, so that a declaration reads
// `Double(0.)` or `Selection("a|b")` without each file repeating its own list of
// using-declarations.
#pragma once

#include <deal.II/base/parameter_handler.h>

namespace gearstiff::app
{
using dealii::ParameterHandler;
using dealii::Patterns::Anything;
using dealii::Patterns::Bool;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::List;
using dealii::Patterns::Selection;

// Every Coulomb friction coefficient of the parameter files (Contact/Friction coefficient, the
// CalculiX deck's, the dynamics meshes' and the train's pair efficiencies', all named `friction
// coefficient`, capitalised in the Contact section as its other entries) takes the same range: 0
// (frictionless) to 1 (dry steel on steel is about 0.6; lubricated gear teeth 0.01–0.1).
inline Double friction_coefficient_pattern()
{
  return Double(0., 1.);
}
} // namespace gearstiff::app
