// `gearstiff dynamics` with `Train/model = lateral` (issue 30): modes with their classes and
// multiplicities, modal energies, static planet load sharing with pin errors, bearing forces and,
// with Train/gyroscopic, the Campbell chart over carrier speed. See dynamics/lateral_model.h.
#pragma once

#include "app/core/command.h"

#include <deal.II/base/parameter_handler.h>

namespace gearstiff::app
{
void run_lateral_dynamics(dealii::ParameterHandler& prm, CommandContext& context);
} // namespace gearstiff::app
