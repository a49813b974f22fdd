// ISO 6336-1:2006 method B dynamic factor, hand-checked on the split-path pair.
#include "dynamics/iso6336_dynamic_factor.h"
#include "errors/errors.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace gearstiff;
using namespace gearstiff::dynamics;

namespace
{
// The split-path pair (docs/references.md §1 dynamic parameters, §5 stiffness): c' = 13.8
// N/(mm·µm), c_γα = c'·(0.75·ε_α + 0.25) = 18.975 N/(mm·µm), b = 24 mm, F_t = 1001.27 N,
// z1 = 21, 1450 rpm, m_red from J1/2 (the pinion is shared by two meshes) and J2:
// m1* = 7.35e-5/0.0247² = 0.12047 kg, m2* = 7.81e-3/0.067² = 1.73981 kg, m_red = 0.112672 kg.
// Assumed deviations: f_pb,eff = f_f,eff = 8 µm, no tip relief (C_a = 0).
IsoDynamicFactorInput split_path_input()
{
  IsoDynamicFactorInput in;
  in.pinion_teeth = 21;
  in.pinion_speed = 1450. * M_PI / 30.;
  in.single_stiffness = 13.8e9;
  in.mesh_stiffness = 13.8e9 * (0.75 * 1.5 + 0.25);
  in.face_width = 24e-3;
  in.reduced_mass = reduced_mass(1.47e-4 / 2., 24.7e-3, 7.81e-3, 67.0e-3);
  in.tangential_force = 1001.27;
  in.total_contact_ratio = 1.5;
  in.pitch_deviation = 8e-6;
  in.profile_deviation = 8e-6;
  in.tip_relief = 0.;
  return in;
}
} // namespace

TEST(Iso6336DynamicFactor, SplitPathPairHandCalculation)
{
  // By hand (values to 5 digits, so 1e-4 relative tolerances):
  //   n_E1 = 30000/(π·21)·sqrt(c_γα/m_red) with c_γα = 18.975 N/(mm·µm) and m_red per unit
  //   face width 0.112672/24 kg/mm → 28 909.5 rpm; N = 1450/28 909.5 = 0.050157;
  //   F_t/b = 41.72 N/mm < 100 → N_S = 0.5 + 0.35·sqrt(0.4172) = 0.72607;
  //   B_p = B_f = 13.8·8/41.72 = 2.64624, B_k = 1;
  //   subcritical: K_v = N·(0.32·B_p + 0.34·B_f + 0.23·B_k) + 1 = 1.09914.
  const IsoDynamicFactorInput in = split_path_input();
  EXPECT_NEAR(in.reduced_mass, 0.112672, 1e-6);
  const IsoDynamicFactor kv = iso6336_dynamic_factor(in);
  EXPECT_NEAR(kv.resonance_speed * 30. / M_PI, 28909.5, 3.);
  EXPECT_NEAR(kv.resonance_ratio, 0.050157, 5e-6);
  EXPECT_NEAR(kv.subcritical_limit, 0.72607, 1e-4);
  EXPECT_NEAR(kv.b_p, 2.64624, 3e-4);
  EXPECT_DOUBLE_EQ(kv.b_k, 1.);
  EXPECT_EQ(kv.range, IsoSpeedRange::subcritical);
  EXPECT_NEAR(kv.kv, 1.09914, 1e-4);
}

TEST(Iso6336DynamicFactor, RangesAndContinuity)
{
  // At N = 1 (main resonance): K_v = 0.32·B_p + 0.34·B_f + 0.90·B_k + 1 = 3.64652; at N = 2
  // (supercritical): 0.47·B_p + 0.47·B_f + 0.75 = 3.23746 (hand values, 1e-4 relative). The
  // intermediate range interpolates linearly, so it meets both at N = 1.15 and 1.5.
  IsoDynamicFactorInput in = split_path_input();
  const double n_e1 = iso6336_dynamic_factor(in).resonance_speed;
  auto at = [&](double ratio)
  {
    in.pinion_speed = ratio * n_e1;
    return iso6336_dynamic_factor(in);
  };
  EXPECT_EQ(at(1.0).range, IsoSpeedRange::main_resonance);
  EXPECT_NEAR(at(1.0).kv, 3.64652, 4e-4);
  EXPECT_EQ(at(2.0).range, IsoSpeedRange::supercritical);
  EXPECT_NEAR(at(2.0).kv, 3.23746, 4e-4);
  EXPECT_EQ(at(1.3).range, IsoSpeedRange::intermediate);
  EXPECT_NEAR(at(1.15 + 1e-9).kv, at(1.15).kv, 1e-6);
  EXPECT_NEAR(at(1.5 - 1e-9).kv, at(1.5).kv, 1e-6);
  // The C_v factors for ε_γ > 2 follow their own formulas;
  // check one value: ε_γ = 2.5 → C_v7 = 0.125·sin(0.5π) + 0.875 = 1.0.
  in.total_contact_ratio = 2.5;
  EXPECT_NEAR(iso6336_dynamic_factor(in).c_v[6], 1.0, 1e-12);
}

TEST(Iso6336DynamicFactor, RejectsNonPositiveInputs)
{
  IsoDynamicFactorInput in = split_path_input();
  in.reduced_mass = 0.;
  EXPECT_THROW(iso6336_dynamic_factor(in), InputError);
  in = split_path_input();
  in.mesh_stiffness = -1.;
  EXPECT_THROW(iso6336_dynamic_factor(in), InputError);
}
