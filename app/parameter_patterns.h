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
} // namespace gearstiff::app
