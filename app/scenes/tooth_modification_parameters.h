// Parameter-file form of the tooth micro-geometry (geometry/tooth_modification.h), in
// "Gear pair/Pinion" and "Gear pair/Wheel" (ISO 21771 terms; amounts in µm, lengths in mm), and
// the variants of `Stiffness/variants` (one modification set each). Declared by the commands
// that build a gear-pair scene (mesh, stiffness, cai, run); kept apart from the gear's own
// entries (app/kinematics/kinematics_parameters.cc), which the gear-pair and kinematics commands
// share.
#pragma once

#include "app/scenes/modification_text.h"
#include "geometry/tooth_modification.h"

#include <deal.II/base/parameter_handler.h>
#include <map>
#include <string>
#include <vector>

namespace gearstiff::app
{
// The entries in Gear pair/Pinion and Gear pair/Wheel (all 0: unmodified).
void declare_tooth_modification_parameters(dealii::ParameterHandler& prm);

PairModificationText read_tooth_modification_text(dealii::ParameterHandler& prm);

// The modification list of one gear (`wheel` names the parameters "Gear pair/Wheel/...");
// InputError for a malformed or negative value and for lead modifications when `dimension` is 2
// (in 3D they go to GearModifications::lead).
geometry::GearModifications parse_gear_modifications(const ModificationText& text, bool wheel,
                                                     unsigned int dimension);

// `Stiffness/variants`: "" (none) or variants separated by ';', each a comma-separated list of
// `name = value` with name a modification entry ("tip relief", both gears) or "Pinion/<entry>",
// "Wheel/<entry>"; e.g. "tip relief = 0; tip relief = 10; Pinion/tip relief = 10". Returns the
// variants' texts built on `base` and their labels (InputError naming `parameter`).
struct ModificationVariant
{
  std::string label; // the variant as written, e.g. "tip relief = 10"
  PairModificationText text;
};
std::vector<ModificationVariant> parse_modification_variants(const std::string& text,
                                                             const PairModificationText& base,
                                                             const std::string& parameter);

// The parameter path of the first non-zero amount ("Gear pair/Pinion/tip relief"), "" when
// every amount is 0 (a scene type without involute teeth refuses modifications).
std::string first_modified_entry(const PairModificationText& text);
} // namespace gearstiff::app
