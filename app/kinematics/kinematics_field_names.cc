// The kinematics library's fields (kinematics/fields.h) as the parameters the user writes: one
// table for the gear pair ("Gear pair/...", every command that reads a pair) and one for the
// train ("Train/...", `kinematics` and `dynamics`). app/core/field_names.h says why.
#include "app/core/field_names.h"
#include "kinematics/fields.h"

#include <string>

namespace gearstiff::app
{
namespace
{
ParameterNames gear_pair_field_names()
{
  namespace field = kinematics::field;
  ParameterNames names = {{field::centre_distance, "Gear pair/centre distance"},
                          {field::ring_tip_margin, "Gear pair/ring tip margin"}};
  for (const bool wheel : {false, true})
    names.merge(field_family(wheel ? "Gear pair/Wheel" : "Gear pair/Pinion", field::gear_members(),
                             [wheel](const std::string& member)
                             { return field::gear(wheel, member); },
                             {{"normal_module", "module"}}));
  return names;
}

ParameterNames train_field_names()
{
  namespace field = kinematics::field;
  ParameterNames names = field_family("Train", field::train_fields(), field::train);
  names[field::train_members] = "Train";
  return names;
}

const FieldNamesRegistration gear_pair("gear pair", gear_pair_field_names);
const FieldNamesRegistration train("train", train_field_names);
} // namespace
} // namespace gearstiff::app
