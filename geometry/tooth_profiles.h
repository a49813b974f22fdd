// The profile provider of one gear: the nominal outline with its profile modifications
// (geometry/tooth_modification.h) and then its faults (geometry/tooth_fault.h) applied, each
// tooth built once when first asked for. Its own component, above both, so that the
// modifications and the faults need not include each other.
#pragma once

#include "geometry/tooth_modification.h"
#include "geometry/tooth_profile.h"

#include <map>
#include <string>
#include <vector>

namespace gearstiff::geometry
{
// `parameter` is the gear whose fields an InputError names (geometry::field::modified_gear).
class ToothProfiles
{
public:
  ToothProfiles() = default;
  ToothProfiles(ToothProfile nominal, GearModifications modifications, FlankRollRange range,
                int loaded_side, std::string parameter);
  const ToothProfile& nominal() const { return nominal_tooth; }
  // Tooth `index` (CCW from tooth 0 in the gear's frame), in the frame of tooth 0 (the caller
  // rotates it by index·angular_pitch).
  const ToothProfile& tooth(int index) const;
  // Tooth `index` with its profile modifications and without its faults: the outline the faults
  // cut (tooth() = apply_faults of it), from which a 3D partial fault's fill is closed.
  ToothProfile unfaulted_tooth(int index) const;
  // δ (m) removed from the loaded flank of tooth `index` at roll length `roll`.
  double loaded_flank_removal(int index, double roll) const;
  const std::vector<ToothModification>& modifications_of(int index) const;
  // The roll lengths of the loaded flank (FlankRollRange).
  const FlankRollRange& roll_range() const { return range; }

private:
  ToothProfile nominal_tooth;
  GearModifications modifications;
  FlankRollRange range;
  int loaded_side = 1;
  std::string parameter;
  mutable std::map<int, ToothProfile> built;
  mutable std::map<int, std::vector<ToothModification>> joined; // all_teeth + by_tooth
};
} // namespace gearstiff::geometry
