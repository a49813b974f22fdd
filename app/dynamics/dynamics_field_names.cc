// The dynamics library's fields (dynamics/fields.h) as the parameters the user writes: the
// train members only the dynamics reads ("Train/..."), "Simulation/...", "ISO 6336/...",
// "Speed sweep/..." and the lateral stage's "Train mesh 1|2/...". app/core/field_names.h says
// why.
#include "app/core/field_names.h"
#include "dynamics/fields.h"

#include <string>

namespace gearstiff::app
{
namespace
{
ParameterNames dynamics_train_field_names()
{
  return field_family("Train", dynamics::field::train_fields(), dynamics::field::train);
}

ParameterNames simulation_field_names()
{
  return field_family("Simulation", dynamics::field::simulation_fields(),
                      dynamics::field::simulation, {{"hht_alpha", "HHT alpha"}});
}

ParameterNames iso6336_field_names()
{
  return field_family("ISO 6336", dynamics::field::iso6336_fields(), dynamics::field::iso6336,
                      {{"mesh_stiffness", "mesh stiffness c_gamma_alpha"},
                       {"single_stiffness", "single stiffness c'"}});
}

ParameterNames speed_sweep_field_names()
{
  return field_family("Speed sweep", dynamics::field::speed_sweep_fields(),
                      dynamics::field::speed_sweep);
}

ParameterNames lateral_stage_mesh_field_names()
{
  ParameterNames names;
  for (unsigned int m = 0; m < dynamics::field::lateral_stage_meshes; ++m)
    for (const std::string& member : dynamics::field::train_mesh_fields())
      names[dynamics::field::train_mesh(m, member)] =
          "Train mesh " + std::to_string(m + 1) + "/" + member;
  return names;
}

const FieldNamesRegistration train("dynamics train", dynamics_train_field_names);
const FieldNamesRegistration simulation("simulation", simulation_field_names);
const FieldNamesRegistration iso6336("ISO 6336", iso6336_field_names);
const FieldNamesRegistration speed_sweep("speed sweep", speed_sweep_field_names);
const FieldNamesRegistration lateral_meshes("lateral stage meshes", lateral_stage_mesh_field_names);
} // namespace
} // namespace gearstiff::app
