// The fields the dynamics library names a torsional train's gears and meshes by (the gear's or
// mesh's number: "gear2.inertia", "mesh1.damping", dynamics/fields.h) as the parameter sections
// they came from. Those sections are known only once the train is parsed ("Gear n"/"Mesh n",
// or the Train description's "Train mesh n"), so the dynamics command maps them at its calls
// (with_parameter_names, app/core/field_names.h) rather than through a registered table.
#pragma once

#include "app/core/field_names.h"
#include "dynamics/torsional_model.h"

#include <string>

namespace gearstiff::app
{
// The fields of mesh `m` (from 0) under `section`: "mesh1.driver_base_radius" ->
// "Mesh 1/driver base radius".
ParameterNames gear_mesh_parameter_names(unsigned int m, const std::string& section);

// Every gear's and mesh's fields under its name (the section it was parsed from), "Gear n" and
// "Mesh n" for one without a name; a nonlinear mesh's harmonics under its own section.
ParameterNames train_parameter_names(const dynamics::GearTrain& train);
} // namespace gearstiff::app
