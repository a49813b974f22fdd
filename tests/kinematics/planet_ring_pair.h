// The planet–ring pair of the stiffness and geometry tests, planet z = 24 in ring z = 69 (the
// inner set of the bi-planetary train, docs/references.md §2): module 2.5 mm, 20°, no profile
// shift (the paper's modules and shifts of §2 are not in the reference data: stated defaults), the
// ring tip at an addendum of 0.5·m_n (d_a2 = 170 mm): a standard ring tip interferes with the
// planet's fillet (tests/kinematics/test_gear_pair.cc, InternalPair). The other entries (face
// widths, material, the pinion's bore) stay as `pair` has them; the ring's bore follows its rim.
#pragma once

#include "kinematics/gear_pair.h"

namespace gearstiff::test_support
{
inline void make_planet_ring(kinematics::GearPairSpec& pair)
{
  constexpr double mm = 1e-3;
  pair.pinion.teeth = 24;
  pair.wheel.teeth = 69;
  pair.wheel.internal = true;
  pair.pinion.profile_shift = 0.;
  pair.wheel.profile_shift = 0.;
  pair.pinion.tip_diameter = 0.;                               // standard
  pair.wheel.tip_diameter = (69. * 2.5 - 2. * 2.5 * 0.5) * mm; // addendum 0.5·m_n
  pair.wheel.bore_diameter = 0.;                               // the rim thickness sets it
}
} // namespace gearstiff::test_support
