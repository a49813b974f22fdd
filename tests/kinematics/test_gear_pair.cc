// Gear pair geometry against docs/references.md §1 (Reszuta & Drewniak, Mechanik 7/2015) and
// against closed-form ISO 21771 relations that the implementation does not use directly.
#include "errors/errors.h"
#include "kinematics/gear_pair.h"
#include "tests/kinematics/input_error_parameter.h"

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>

using namespace gearstiff;
using namespace gearstiff::kinematics;
using gearstiff::test_support::input_error_parameter;

namespace
{
constexpr double pi = 3.14159265358979323846;
constexpr double degree = pi / 180.;
constexpr double mm = 1e-3;

GearPairSpec standard_tips(GearPairSpec spec)
{
  spec.pinion.tip_diameter = 0.;
  spec.wheel.tip_diameter = 0.;
  return spec;
}

// An internal pair 24/69 with the tooling of the split-path pair, no profile shift and the
// standard tips (the ring's digs into the pinion fillet).
GearPairSpec internal_24_69_pair()
{
  GearPairSpec spec = standard_tips(split_path_pair());
  spec.pinion.teeth = 24;
  spec.wheel.teeth = 69;
  spec.wheel.internal = true;
  spec.pinion.profile_shift = 0.;
  spec.wheel.profile_shift = 0.;
  return spec;
}
} // namespace

TEST(GearPair, InverseInvoluteRoundTrips)
{
  for (double angle = 0.05; angle < 1.4; angle += 0.05)
    EXPECT_NEAR(inverse_involute(involute(angle)), angle, 1e-13);
}

// docs/references.md §1: r_b1 = 24.667 mm and p_et = 7.380 mm, printed to 1 µm: tolerance half a
// unit of the last printed digit.
TEST(GearPair, SplitPathBaseRadiusAndPitch)
{
  const GearPairGeometry pair = compute_gear_pair(split_path_pair());
  EXPECT_NEAR(0.5 * pair.pinion.base_diameter, 24.667 * mm, 0.0005 * mm);
  EXPECT_NEAR(pair.transverse_base_pitch, 7.380 * mm, 0.0005 * mm);
  // x1 + x2 = 0: working pressure angle and centre distance stay at 20° and 97.5 mm (§1 table).
  EXPECT_NEAR(pair.working_pressure_angle, 20. * degree, 1e-12);
  EXPECT_NEAR(pair.centre_distance, 97.5 * mm, 1e-12);
}

// docs/references.md §1 note: standard tip diameters d_a = d + 2m(1 + x) give ε_α ≈ 1.618 (3
// digits: tolerance 0.0005).
TEST(GearPair, SplitPathStandardTipsContactRatio)
{
  const GearPairGeometry pair = compute_gear_pair(standard_tips(split_path_pair()));
  EXPECT_NEAR(pair.pinion.tip_diameter, 58.95 * mm, 1e-12);
  EXPECT_NEAR(pair.wheel.tip_diameter, 146.05 * mm, 1e-12);
  EXPECT_NEAR(pair.transverse_contact_ratio, 1.618, 0.0005);
}

// The built-in case: both tip radii reduced equally so that ε_α = 1.500 (docs/references.md §1).
// The paper prints g_α = 11.068 mm, which is 1.4997·p_et: its own 1.5·p_et = 11.0705 mm. We keep
// ε_α = 1.500 exactly, so g_α differs from the print by 2.5 µm (0.02 %); tolerance 3 µm.
TEST(GearPair, SplitPathBuiltInContactRatio)
{
  const GearPairSpec spec = split_path_pair();
  const GearPairGeometry pair = compute_gear_pair(spec);
  // Input echo, not evidence: split_path_pair() bisects the tips until ε_α = 1.5, so this line
  // only states the construction. The results checked against the paper are the path of contact
  // (its print) and the tip reduction (its note), below.
  EXPECT_NEAR(pair.transverse_contact_ratio, 1.500, 1e-9);
  EXPECT_NEAR(pair.path_of_contact, 11.068 * mm, 0.003 * mm);
  // "both tip radii reduced by about 0.2 mm" (§1 note).
  const double reduction = 0.5 * (58.95 * mm - spec.pinion.tip_diameter);
  EXPECT_NEAR(reduction, 0.2 * mm, 0.01 * mm);
  EXPECT_NEAR(0.5 * (146.05 * mm - spec.wheel.tip_diameter), reduction, 1e-12);
}

// Zones along the line of action for 1 < ε_α < 2: double AB, single BD, double DE with
// AB = DE = (ε_α − 1)·p_bt and BD = (2 − ε_α)·p_bt (the definition of ε_α). Input echoes of the
// construction (ε_α = 1.5 by the tips, roll angle = ℓ/r_b1): what this test checks is that the
// zone bookkeeping (counts, order, B and D, the pitch point's zone) follows the definition.
TEST(GearPair, SplitPathContactZones)
{
  const GearPairGeometry pair = compute_gear_pair(split_path_pair());
  ASSERT_EQ(pair.contact_zones.size(), 3u);
  const double p = pair.transverse_base_pitch;
  EXPECT_EQ(pair.contact_zones[0].pairs, 2u);
  EXPECT_EQ(pair.contact_zones[1].pairs, 1u);
  EXPECT_EQ(pair.contact_zones[2].pairs, 2u);
  EXPECT_NEAR(pair.contact_zones[0].end - pair.contact_zones[0].start, 0.5 * p, 1e-12);
  EXPECT_NEAR(pair.contact_zones[1].end - pair.contact_zones[1].start, 0.5 * p, 1e-12);
  EXPECT_NEAR(pair.contact_zones[1].start, pair.single_contact_start(), 1e-12);
  EXPECT_NEAR(pair.contact_zones[1].end, pair.single_contact_end(), 1e-12);
  // Roll angles are positions over r_b1; the single zone spans 0.5·p_bt/r_b1 = π/z1.
  EXPECT_NEAR(pair.contact_zones[1].pinion_roll_end - pair.contact_zones[1].pinion_roll_start,
              pi / 21., 1e-12);
  // The pitch point lies inside the single-contact zone for this pair.
  EXPECT_EQ(pair.pairs_in_contact(pair.pitch_point), 1u);
}

// A helical variant: ε_β = b·sin β/(π·m_n) (ISO 21771); α_t from tan α_t = tan α_n / cos β.
TEST(GearPair, HelicalOverlapRatio)
{
  GearPairSpec spec = standard_tips(split_path_pair());
  spec.pinion.helix_angle = 15. * degree;
  spec.wheel.helix_angle = -15. * degree;
  const GearPairGeometry pair = compute_gear_pair(spec);
  EXPECT_NEAR(pair.overlap_ratio, 24. * std::sin(15. * degree) / (pi * 2.5), 1e-12);
  EXPECT_NEAR(std::tan(pair.transverse_pressure_angle),
              std::tan(20. * degree) / std::cos(15. * degree), 1e-12);
  // Zero-backlash centre distance, independent form: a = m_t·(z1+z2)/2·cos α_t / cos α_wt with
  // x1 + x2 = 0 → α_wt = α_t.
  EXPECT_NEAR(pair.centre_distance, 2.5 * mm / std::cos(15. * degree) * 39., 1e-12);
}

// Profile shifts with x1 + x2 > 0 spread the centre distance: a check against the textbook
// approximation a ≈ a_d + (x1 + x2 − Δ)·m is loose, so check inv α_wt exactly instead.
TEST(GearPair, ShiftedWorkingPressureAngle)
{
  GearPairSpec spec = standard_tips(split_path_pair());
  spec.pinion.profile_shift = 0.5;
  spec.wheel.profile_shift = 0.2;
  const GearPairGeometry pair = compute_gear_pair(spec);
  EXPECT_NEAR(involute(pair.working_pressure_angle),
              involute(20. * degree) + 2. * std::tan(20. * degree) * 0.7 / 78., 1e-14);
  EXPECT_GT(pair.centre_distance, 97.5 * mm);
  // With the same shifts but a given larger centre distance, there is backlash.
  spec.centre_distance = pair.centre_distance + 0.1 * mm;
  EXPECT_GT(compute_gear_pair(spec).backlash, 0.);
  spec.centre_distance = pair.centre_distance - 0.1 * mm;
  EXPECT_EQ(input_error_parameter([&] { compute_gear_pair(spec); }), "pair.centre_distance");
}

// An internal pair (24/69, m 2.5): with a standard ring tip the ring tip digs into the pinion
// fillet (rack form circle), a classic internal-gear interference; a larger ring tip diameter
// clears it.
TEST(GearPair, InternalPair)
{
  GearPairSpec spec = internal_24_69_pair();
  EXPECT_EQ(input_error_parameter([&] { compute_gear_pair(spec); }), "wheel.tip_diameter");
  spec.wheel.tip_diameter = (69. * 2.5 - 2. * 2.5 * 0.5) * mm; // addendum 0.5·m
  const GearPairGeometry pair = compute_gear_pair(spec);
  EXPECT_NEAR(pair.centre_distance, 0.5 * (69. - 24.) * 2.5 * mm, 1e-12);
  EXPECT_GT(pair.transverse_contact_ratio, 1.);
  // Internal pairs: the line of action T1T2 = a·sin α_w, T2 on the same side as T1.
  EXPECT_NEAR(pair.line_of_action_length, pair.centre_distance * std::sin(20. * degree), 1e-12);
}

// The automatic ring tip of the same pair: the longest ring teeth that still meet the pinion on
// its involute with the stated margin. Exact by construction: the pair is valid at that tip,
// a tip 1 µm smaller (longer teeth) is not (or breaks the margin), and the hand-chosen
// 170 mm tip above (addendum 0.5·m) is valid, so the automatic one is no larger.
TEST(GearPair, ClearingRingTip)
{
  GearPairSpec spec = internal_24_69_pair();
  const double margin = 0.05 * mm;
  const double tip = clearing_ring_tip_diameter(spec, margin);
  EXPECT_LE(tip, 170. * mm);
  spec.wheel.tip_diameter = tip;
  const GearPairGeometry pair = compute_gear_pair(spec);
  const double rb1 = 0.5 * pair.pinion.base_diameter;
  const double form_roll =
      std::sqrt(0.25 * pair.pinion.form_diameter * pair.pinion.form_diameter - rb1 * rb1);
  EXPECT_NEAR(pair.contact_start - form_roll, margin, 1e-9); // bisection to 1e-12 m in d_a2
  EXPECT_GT(pair.transverse_contact_ratio, 1.);
  std::cout << "24/69 ring tip auto: d_a2 = " << tip / mm
            << " mm, eps_alpha = " << pair.transverse_contact_ratio << "\n";
  spec.wheel.internal = false;
  EXPECT_EQ(input_error_parameter([&] { clearing_ring_tip_diameter(spec, margin); }),
            "wheel.tip_diameter");
}

// Issue 11: the parameter to fix is named. A given centre distance beyond the zero-backlash
// one shortens the path of contact; a bore outside the root circle leaves no body.
TEST(GearPair, NamesTheParameterToFix)
{
  GearPairSpec spec = split_path_pair();
  spec.centre_distance = 99. * mm; // zero-backlash 97.5 mm (docs/references.md §1)
  EXPECT_EQ(input_error_parameter([&] { compute_gear_pair(spec); }), "pair.centre_distance");
  spec = split_path_pair();
  spec.pinion.bore_diameter = 100. * mm;
  EXPECT_EQ(input_error_parameter([&] { compute_gear_pair(spec); }), "pinion.bore_diameter");
  spec = split_path_pair();
  spec.pinion.normal_module = spec.wheel.normal_module = 1.; // 1 m with the 58.55 mm tip
  EXPECT_EQ(input_error_parameter([&] { compute_gear_pair(spec); }), "pinion.normal_module");
}

TEST(GearPair, RejectsBadInput)
{
  const GearPairSpec base = split_path_pair();
  GearPairSpec spec = base;
  spec.pinion.teeth = 0;
  EXPECT_EQ(input_error_parameter([&] { compute_gear_pair(spec); }), "pinion.teeth");
  // Undercut: x_min = 1.25 − 0.38·(1 − sin 20°) − z·sin²α/2 = −0.228 for z = 21.
  spec = standard_tips(base);
  spec.pinion.profile_shift = -0.3;
  spec.wheel.profile_shift = 0.3;
  EXPECT_EQ(input_error_parameter([&] { compute_gear_pair(spec); }), "pinion.profile_shift");
  EXPECT_NEAR(compute_gear_pair(standard_tips(base)).pinion.minimum_profile_shift,
              1.25 - 0.38 * (1. - std::sin(20. * degree)) -
                  21. * std::pow(std::sin(20. * degree), 2) / 2.,
              1e-12);
  // Pointed tooth: x = 1.3 on z = 21 with a standard tip (s_at < 0 by ISO 21771 by hand).
  spec = standard_tips(base);
  spec.pinion.profile_shift = 1.3;
  spec.wheel.profile_shift = -1.3;
  EXPECT_EQ(input_error_parameter([&] { compute_gear_pair(spec); }), "pinion.profile_shift");
  // Internal wheel with fewer teeth than the pinion.
  spec = standard_tips(base);
  spec.wheel.internal = true;
  spec.wheel.teeth = 20;
  EXPECT_EQ(input_error_parameter([&] { compute_gear_pair(spec); }), "wheel.teeth");
  // ε_α < 1: tips cut down to 1 mm above the reference circle.
  spec = base;
  spec.pinion.tip_diameter = 54.5 * mm;
  spec.wheel.tip_diameter = 144.5 * mm;
  EXPECT_EQ(input_error_parameter([&] { compute_gear_pair(spec); }), "pinion.tip_diameter");
}

// A rounded tip edge (GearSpec::tip_rounding_radius, transverse): the path of contact ends at the
// tip form circles d_Fa (ISO 21771; ISO 6336-1's active tip for a rounded tip, docs/references.md
// §20). Hand computation for the split-path pair with standard tips (d_a 58.95/146.05 mm, r_b =
// (z·m/2)·cos 20°, a_w 97.5 mm, α_wt 20°) and ρ_a = 0.5 mm on both (python, 2026-12-03):
// ρ_Fa = ρ_a + √((r_a − ρ_a)² − r_b²), d_Fa = 2·√(r_b² + ρ_Fa²) gives d_Fa1 58.480847 mm,
// d_Fa2 145.437315 mm, g_α = ρ_Fa1 + ρ_Fa2 − a_w·sin α_wt = 10.732339 mm, ε_α = g_α/(π·m·cos α)
// = 1.454182 (sharp: 1.617953, the test above). Tolerance 1e-6 mm: the 7 printed digits.
TEST(GearPair, TipRoundingShortensThePath)
{
  GearPairSpec spec = standard_tips(split_path_pair());
  spec.pinion.tip_rounding_radius = spec.wheel.tip_rounding_radius = 0.5 * mm;
  const GearPairGeometry pair = compute_gear_pair(spec);
  EXPECT_NEAR(pair.pinion.tip_form_diameter, 58.480847 * mm, 1e-6 * mm);
  EXPECT_NEAR(pair.wheel.tip_form_diameter, 145.437315 * mm, 1e-6 * mm);
  EXPECT_NEAR(pair.pinion.tip_diameter, 58.95 * mm, 1e-12); // d_a stays
  EXPECT_NEAR(pair.path_of_contact, 10.732339 * mm, 1e-6 * mm);
  EXPECT_NEAR(pair.transverse_contact_ratio, 1.454182, 1e-6);
  // E and A are where the tip form circles cross the line of action.
  const double rb1 = 0.5 * pair.pinion.base_diameter, rb2 = 0.5 * pair.wheel.base_diameter;
  const double rfa1 = 0.5 * pair.pinion.tip_form_diameter;
  const double rfa2 = 0.5 * pair.wheel.tip_form_diameter;
  EXPECT_NEAR(pair.contact_end, std::sqrt(rfa1 * rfa1 - rb1 * rb1), 1e-12);
  EXPECT_NEAR(pair.line_of_action_length - pair.contact_start, std::sqrt(rfa2 * rfa2 - rb2 * rb2),
              1e-12);
  // The mate's start of active profile follows: the wheel's d_Nf from E.
  const double t2_e = pair.line_of_action_length - pair.contact_end;
  EXPECT_NEAR(pair.wheel.active_profile_start, 2. * std::sqrt(rb2 * rb2 + t2_e * t2_e), 1e-12);
  // Sharp edges: d_Fa = d_a, every quantity as before.
  const GearPairGeometry sharp = compute_gear_pair(standard_tips(split_path_pair()));
  EXPECT_EQ(sharp.pinion.tip_form_diameter, sharp.pinion.tip_diameter);
  EXPECT_EQ(sharp.wheel.tip_form_diameter, sharp.wheel.tip_diameter);
  EXPECT_EQ(tip_form_diameter(60. * mm, 66. * mm, 0., false), 66. * mm);

  // Internal: the ring's tip circle is the inner one, its d_Fa lies outside it.
  GearPairSpec ring = internal_24_69_pair();
  ring.wheel.tip_diameter = (69. * 2.5 - 2. * 2.5 * 0.5) * mm; // as InternalPair above
  const GearPairGeometry ring_sharp = compute_gear_pair(ring);
  ring.wheel.tip_rounding_radius = 0.3 * mm;
  const GearPairGeometry ring_round = compute_gear_pair(ring);
  const double rb = 0.5 * ring_round.wheel.base_diameter, ra = 0.5 * ring_round.wheel.tip_diameter;
  const double roll = -0.3 * mm + std::sqrt((ra + 0.3 * mm) * (ra + 0.3 * mm) - rb * rb);
  EXPECT_NEAR(ring_round.wheel.tip_form_diameter, 2. * std::sqrt(rb * rb + roll * roll), 1e-12);
  EXPECT_GT(ring_round.wheel.tip_form_diameter, ring_round.wheel.tip_diameter);
  EXPECT_LT(ring_round.transverse_contact_ratio, ring_sharp.transverse_contact_ratio);
  EXPECT_NEAR(ring_round.contact_end, ring_sharp.contact_end, 1e-15); // the pinion's E stays

  // Radii that do not fit name the parameter: negative, consuming the whole top land, beyond
  // the tip's height above the base circle.
  for (const double bad : {-0.1, 3., 10.})
  {
    GearPairSpec s = standard_tips(split_path_pair());
    s.pinion.tip_rounding_radius = bad * mm;
    EXPECT_EQ(input_error_parameter([&] { compute_gear_pair(s); }), "pinion.tip_rounding_radius")
        << bad;
  }
}
