// The names the kinematics library gives its own fields in an InputError: "<struct>.<member>"
// of the struct its caller filled (the pinion's or wheel's GearSpec, GearPairSpec,
// GearTrainText). Library code names its fields, never the parameter paths users write
// ("Gear pair/Pinion/teeth"): the command that filled the struct maps every field to its
// parameter (app/kinematics/kinematics_field_names.cc), and tools/house_counts.py fails when
// kinematics/ spells a user parameter path.
#pragma once

#include <string>
#include <vector>

namespace gearstiff::kinematics::field
{
// A member of the pinion's (wheel = false) or wheel's GearSpec, "pinion.tip_diameter", or of
// the per-gear data beside it (the modifications' faulty_tooth, the generating rack's
// cutter_tip_radius named by geometry/involute_tooth.cc).
inline std::string gear(bool wheel, const std::string& member)
{
  return (wheel ? "wheel." : "pinion.") + member;
}
// Every member gear() is called with.
inline const std::vector<std::string>& gear_members()
{
  static const std::vector<std::string> members = {"teeth",
                                                   "normal_module",
                                                   "pressure_angle",
                                                   "helix_angle",
                                                   "profile_shift",
                                                   "face_width",
                                                   "tip_diameter",
                                                   "tip_rounding_radius",
                                                   "internal",
                                                   "addendum_coefficient",
                                                   "dedendum_coefficient",
                                                   "root_radius_coefficient",
                                                   "bore_diameter",
                                                   "web_thickness",
                                                   "rim_thickness",
                                                   "faulty_tooth",
                                                   "cutter_tip_radius"};
  return members;
}

inline const std::string centre_distance = "pair.centre_distance"; // GearPairSpec
inline const std::string ring_tip_margin = "pair.ring_tip_margin"; // clearing_ring_tip_diameter

// A member of GearTrainText, "train.profile_shifts", or of the train's other inputs
// (reduce_inertia_to: the member reduced_inertia reduces to; builtin: builtin_train's name).
inline std::string train(const std::string& member)
{
  return "train." + member;
}
// The train as a whole (a member name no list declares).
inline const std::string train_members = "train";
// Every member train() is called with in kinematics/.
inline const std::vector<std::string>& train_fields()
{
  static const std::vector<std::string> members = {
      "gears",  "modules", "carriers", "planets", "meshes",         "connections",       "fixed",
      "inputs", "output",  "inertias", "masses",  "profile_shifts", "reduce_inertia_to", "builtin"};
  return members;
}
} // namespace gearstiff::kinematics::field
