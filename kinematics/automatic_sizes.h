// The sizes a user may leave `auto` (tip diameters, bores, a ring's outer diameter) and the rules
// that derive them from the gear's own teeth, so that a changed pair never keeps the built-in
// case's sizes. The built-in case of docs/references.md §1 (kinematics::split_path_pair()) is
// recognised by its geometry, not by a flag: its published tips and its bores apply only to a
// pair with its teeth, and its published FE values only to a pair that is it.
#pragma once

#include "kinematics/gear_pair.h"

#include <string>
#include <vector>

namespace gearstiff::kinematics
{
// Whether `spec` has the teeth of split_path_pair(): tooth counts, modules, pressure and helix
// angles, profile shifts and basic rack of both gears (relative 1e-9), both external. Face
// widths, tips and bores are not looked at.
bool has_split_path_teeth(const GearPairSpec& spec);
// Whether `spec` is the pair the published ANSYS model of docs/references.md §1 solved: the teeth
// above, its face widths and its tip diameters (to 1 µm) and its zero-backlash centre distance.
// The bores are not published, so they are not compared.
bool is_split_path_pair(const GearPairSpec& spec);

// One size the program derived instead of reading it: the parameter, the value, the rule.
struct DerivedSize
{
  std::string parameter; // the field (kinematics/fields.h), e.g. "pinion.bore_diameter"
  double value = 0.;     // m
  std::string rule;      // the rule that gave it, in words
};

// Which sizes of a pair read `auto`.
struct AutomaticSizes
{
  bool pinion_tip = false;
  bool wheel_tip = false;
  bool pinion_bore = false;
  bool wheel_bore = false; // internal wheel: its outer diameter
};

// Rim under the root circle of an internal wheel whose outer diameter is `auto`, in modules:
// 4·m_n, thicker than the one module the FE scene requires and in the range where the rim
// study of docs/internal-gears.md shows the ring's support no longer dominating k.
constexpr double automatic_ring_rim_modules = 4.;

// Fills the `auto` sizes of `spec` and appends one DerivedSize for each:
//  - tip diameters: the published tips of split_path_pair() for a pair with its teeth; else the
//    standard d ± 2·m_n·(h_aP* + x) (ISO 21771), and for an internal wheel the longest ring
//    teeth that clear the pinion's involute by `ring_tip_margin` [m] (clearing_ring_tip_diameter);
//  - bores: 20/40 mm for a pair with the split-path teeth (split_path_pair()); else half the
//    root diameter d_f/2 for an external gear (a solid blank on a shaft of half its root
//    diameter: rim d_f/4 under the root) and d_f + 2·4·m_n for an internal wheel's outer
//    diameter (automatic_ring_rim_modules).
// InputError as compute_gear_pair / clearing_ring_tip_diameter for a pair they refuse.
void resolve_automatic_sizes(GearPairSpec& spec, const AutomaticSizes& automatic,
                             double ring_tip_margin, std::vector<DerivedSize>& derived);

// "Gear pair/Pinion/tip diameter = 96 mm (standard ...); ..." for a report, "" for none.
std::string derived_sizes_text(const std::vector<DerivedSize>& derived);
} // namespace gearstiff::kinematics
