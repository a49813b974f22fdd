// The dynamics library's fields (dynamics/fields.h) as the parameters the user writes: the
// train members only the dynamics reads ("Train/..."), "Simulation/...", "ISO 6336/...",
// "Speed sweep/..." and the lateral stage's "Train mesh 1|2/...". app/core/field_names.h says
// why.
#include "app/dynamics/dynamics_field_names.h"

#include "app/core/field_names.h"
#include "dynamics/fields.h"

#include <algorithm>
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

// The words of `member` ("driver_base_radius" -> "driver base radius").
std::string words(std::string member)
{
  std::replace(member.begin(), member.end(), '_', ' ');
  return member;
}
} // namespace

ParameterNames gear_mesh_parameter_names(unsigned int m, const std::string& section)
{
  ParameterNames names;
  for (const std::string& member : dynamics::field::gear_mesh_fields())
    names[dynamics::field::gear_mesh(m, member)] = section + "/" + words(member);
  return names;
}

ParameterNames train_parameter_names(const dynamics::GearTrain& train)
{
  ParameterNames names;
  for (unsigned int i = 0; i < train.gears.size(); ++i)
  {
    const std::string& name = train.gears[i].name;
    const std::string section = name.empty() ? "Gear " + std::to_string(i + 1) : name;
    names[dynamics::field::train_gear(i)] = section;
    for (const std::string& member : dynamics::field::train_gear_fields())
      names[dynamics::field::train_gear(i, member)] = section + "/" + words(member);
  }
  for (unsigned int m = 0; m < train.meshes.size(); ++m)
  {
    const dynamics::Mesh& mesh = train.meshes[m];
    const std::string section = mesh.name.empty() ? "Mesh " + std::to_string(m + 1) : mesh.name;
    names.merge(gear_mesh_parameter_names(m, section));
    if (mesh.nonlinear && !mesh.nonlinear->section.empty())
      names[dynamics::field::gear_mesh(m, "transmission_error_harmonics")] =
          mesh.nonlinear->section + "/transmission error harmonics";
  }
  return names;
}
} // namespace gearstiff::app
