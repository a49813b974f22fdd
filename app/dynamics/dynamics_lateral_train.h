// `gearstiff dynamics` with `Train/model = lateral` on a train of several stages (issue 30):
// the general form of dynamics/lateral_train.h — modes with their classes, static mesh and
// bearing forces, the response at the nominal speed (K_v per Train mesh, orbits and bearing
// forces of the central members, their orbit chart) and the speed sweep.
#pragma once

#include "app/core/command.h"

#include <deal.II/base/parameter_handler.h>

namespace gearstiff::app
{
void run_lateral_train_dynamics(dealii::ParameterHandler& prm, CommandContext& context);
} // namespace gearstiff::app
