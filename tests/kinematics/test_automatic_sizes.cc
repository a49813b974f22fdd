// The `auto` sizes of kinematics/automatic_sizes.h (issue 25): the built-in case of
// docs/references.md §1 keeps its published tips and its bores, any other pair gets the
// standard tips (ISO 21771: d_a = d ± 2·m_n·(h_aP* + x)) and the stated bore rules, and the
// published FE values belong to the built-in pair alone (decided by the geometry).
#include "errors/errors.h"
#include "kinematics/automatic_sizes.h"

#include <gtest/gtest.h>

using namespace gearstiff::kinematics;

namespace
{
constexpr double mm = 1e-3;
const AutomaticSizes all{true, true, true, true};
constexpr double margin =
    0.05e-3; // m, the ring tip margin default (app/kinematics/kinematics_parameters.cc)

// The own pair of issue 25: z 30/45, m = 3 mm, face width 20 mm, the rest the built-in defaults
// (x ±0.29, 20°, ISO 53 A rack).
GearPairSpec own_pair()
{
  GearPairSpec spec = split_path_pair();
  spec.pinion.teeth = 30;
  spec.wheel.teeth = 45;
  for (GearSpec* gear : {&spec.pinion, &spec.wheel})
  {
    gear->normal_module = 3e-3;
    gear->face_width = 20e-3;
    gear->tip_diameter = 0.;
    gear->bore_diameter = 0.;
  }
  return spec;
}
} // namespace

// The built-in pair: the same tips (to round-off: they are the values themselves) and bores as
// split_path_pair(), and it is recognised as the published case.
TEST(AutomaticSizes, BuiltInPairKeepsItsPublishedSizes)
{
  const GearPairSpec builtin = split_path_pair();
  GearPairSpec spec = builtin;
  spec.pinion.tip_diameter = spec.wheel.tip_diameter = 0.;
  spec.pinion.bore_diameter = spec.wheel.bore_diameter = 0.;
  std::vector<DerivedSize> derived;
  resolve_automatic_sizes(spec, all, margin, derived);
  EXPECT_NEAR(spec.pinion.tip_diameter, builtin.pinion.tip_diameter, 1e-12);
  EXPECT_NEAR(spec.wheel.tip_diameter, builtin.wheel.tip_diameter, 1e-12);
  EXPECT_DOUBLE_EQ(spec.pinion.bore_diameter, 20e-3);
  EXPECT_DOUBLE_EQ(spec.wheel.bore_diameter, 40e-3);
  EXPECT_EQ(derived.size(), 4u);
  EXPECT_TRUE(is_split_path_pair(spec));
  EXPECT_TRUE(is_split_path_pair(builtin));
}

// z 30/45, m 3, x ±0.29: d_a1 = 90 + 2·3·(1 + 0.29) = 97.74 mm, d_a2 = 135 + 2·3·(1 − 0.29) =
// 139.26 mm (standard tips, hand derivation of ISO 21771); root d_f = d − 2·m·(1.25 − x):
// 84.24 / 125.76 mm, bores half of them: 42.12 / 62.88 mm. Tolerance 1 nm: closed forms.
TEST(AutomaticSizes, OwnPairGetsStandardTipsAndHalfRootBores)
{
  GearPairSpec spec = own_pair();
  std::vector<DerivedSize> derived;
  resolve_automatic_sizes(spec, all, margin, derived);
  EXPECT_NEAR(spec.pinion.tip_diameter, 97.74 * mm, 1e-9);
  EXPECT_NEAR(spec.wheel.tip_diameter, 139.26 * mm, 1e-9);
  EXPECT_NEAR(spec.pinion.bore_diameter, 42.12 * mm, 1e-9);
  EXPECT_NEAR(spec.wheel.bore_diameter, 62.88 * mm, 1e-9);
  ASSERT_EQ(derived.size(), 4u);
  EXPECT_EQ(derived[0].parameter, "pinion.tip_diameter");
  EXPECT_NE(derived_sizes_text(derived).find("half the root diameter"), std::string::npos);
  EXPECT_FALSE(is_split_path_pair(spec));
  EXPECT_FALSE(has_split_path_teeth(spec));
}

// A given size is kept and not listed; only the `auto` ones are derived.
TEST(AutomaticSizes, GivenSizesStay)
{
  GearPairSpec spec = own_pair();
  spec.pinion.bore_diameter = 30e-3;
  std::vector<DerivedSize> derived;
  resolve_automatic_sizes(spec, {true, true, false, true}, margin, derived);
  EXPECT_DOUBLE_EQ(spec.pinion.bore_diameter, 30e-3);
  EXPECT_EQ(derived.size(), 3u);
}

// The built-in teeth with another face width are not the published case (k scales with b);
// changing a tip by 0.1 mm neither.
TEST(AutomaticSizes, PublishedCaseNeedsTheWholeGeometry)
{
  GearPairSpec spec = split_path_pair();
  spec.wheel.face_width = 20e-3;
  EXPECT_TRUE(has_split_path_teeth(spec));
  EXPECT_FALSE(is_split_path_pair(spec));
  spec = split_path_pair();
  spec.pinion.tip_diameter += 0.1e-3;
  EXPECT_FALSE(is_split_path_pair(spec));
}

// Planet 24 in ring 69 (m 2.5, x 0): the ring's tip is the clearing tip (the standard ring tip
// interferes, tests/kinematics/test_gear_pair.cc InternalPair), its outer diameter the root
// diameter + 8·m_n: d_f2 = 69·2.5 + 2·2.5·1.25 = 178.75 mm → 198.75 mm.
TEST(AutomaticSizes, RingGetsClearingTipAndFourModuleRim)
{
  GearPairSpec spec = split_path_pair();
  spec.pinion.teeth = 24;
  spec.wheel.teeth = 69;
  spec.wheel.internal = true;
  spec.pinion.profile_shift = spec.wheel.profile_shift = 0.;
  std::vector<DerivedSize> derived;
  resolve_automatic_sizes(spec, all, margin, derived);
  GearPairSpec clearing = spec;
  clearing.pinion.bore_diameter = clearing.wheel.bore_diameter = 0.;
  clearing.pinion.tip_diameter = 0.;
  EXPECT_NEAR(spec.wheel.tip_diameter, clearing_ring_tip_diameter(clearing, margin), 1e-12);
  EXPECT_NEAR(spec.wheel.bore_diameter, 198.75 * mm, 1e-9);
  EXPECT_NO_THROW(compute_gear_pair(spec));
}
