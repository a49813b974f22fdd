#include "dynamics/iso6336_dynamic_factor.h"

#include "dynamics/fields.h"
#include "errors/errors.h"

#include <cmath>

namespace gearstiff::dynamics
{
std::string iso_speed_range_name(IsoSpeedRange range)
{
  switch (range)
  {
  case IsoSpeedRange::subcritical:
    return "subcritical";
  case IsoSpeedRange::main_resonance:
    return "main resonance";
  case IsoSpeedRange::intermediate:
    return "intermediate";
  case IsoSpeedRange::supercritical:
    return "supercritical";
  }
  return "?";
}

double reduced_mass(double pinion_inertia, double pinion_base_radius, double wheel_inertia,
                    double wheel_base_radius)
{
  const double m1 = pinion_inertia / (pinion_base_radius * pinion_base_radius);
  const double m2 = wheel_inertia / (wheel_base_radius * wheel_base_radius);
  return m1 * m2 / (m1 + m2);
}

namespace
{
// ISO 6336-1 method B: the C_v factors as functions of the total contact ratio.
std::array<double, 7> c_v_factors(double eps)
{
  std::array<double, 7> c{};
  const bool small = eps <= 2.;
  c[0] = 0.32;
  c[1] = small ? 0.34 : 0.57 / (eps - 0.3);
  c[2] = small ? 0.23 : 0.096 / (eps - 1.56);
  c[3] = small ? 0.90 : (0.57 - 0.05 * eps) / (eps - 1.44);
  c[4] = 0.47;
  c[5] = small ? 0.47 : 0.12 / (eps - 1.74);
  c[6] = eps <= 1.5 ? 0.75 : (eps <= 2.5 ? 0.125 * std::sin(M_PI * (eps - 2.)) + 0.875 : 1.);
  return c;
}
} // namespace

IsoDynamicFactor iso6336_dynamic_factor(const IsoDynamicFactorInput& in)
{
  auto positive = [](double value, const std::string& name)
  {
    if (!(value > 0.) || !std::isfinite(value))
      throw InputError(name,
                       "must be positive for ISO 6336-1 method B, got " + std::to_string(value));
  };
  if (in.pinion_teeth == 0)
    throw InputError(field::iso6336("pinion_teeth"), "must be positive");
  positive(in.pinion_speed, field::iso6336("pinion_speed"));
  positive(in.mesh_stiffness, field::iso6336("mesh_stiffness"));
  positive(in.single_stiffness, field::iso6336("single_stiffness"));
  positive(in.face_width, field::iso6336("face_width"));
  positive(in.reduced_mass, field::iso6336("reduced_mass"));
  positive(in.tangential_force, field::iso6336("tangential_force"));
  positive(in.application_factor, field::iso6336("application_factor"));
  if (!(in.total_contact_ratio >= 1.))
    throw InputError(field::iso6336("contact_ratio"), "must be at least 1");
  if (in.pitch_deviation < 0. || in.profile_deviation < 0. || in.tip_relief < 0.)
    throw InputError(field::iso6336("deviations"),
                     "f_pb,eff, f_f,eff and C_a must not be negative");

  IsoDynamicFactor out;
  // Resonance speed n_E1 = 30000/(π·z1)·sqrt(c_γα/m_red) [rpm] with per-face-width quantities in
  // N/(mm·µm) and kg/mm; in SI and whole-face-width terms ω_E = sqrt(c_γα·b/m_red), n_E1 = ω_E/z1.
  out.resonance_speed =
      std::sqrt(in.mesh_stiffness * in.face_width / in.reduced_mass) / in.pinion_teeth;
  out.resonance_ratio = in.pinion_speed / out.resonance_speed;

  // N_S from the specific load F_t·K_A/b, compared in N/mm.
  const double specific_load = in.tangential_force * in.application_factor / in.face_width;
  const double specific_load_n_per_mm = specific_load * 1e-3;
  out.subcritical_limit =
      specific_load_n_per_mm >= 100. ? 0.85 : 0.5 + 0.35 * std::sqrt(specific_load_n_per_mm / 100.);

  // Dimensionless deviation and relief terms.
  out.b_p = in.single_stiffness * in.pitch_deviation / specific_load;
  out.b_f = in.single_stiffness * in.profile_deviation / specific_load;
  out.b_k = std::abs(1. - in.single_stiffness * in.tip_relief / specific_load);
  out.c_v = c_v_factors(in.total_contact_ratio);
  const auto& c = out.c_v;

  const double main_resonance = c[0] * out.b_p + c[1] * out.b_f + c[3] * out.b_k + 1.;
  const double supercritical = c[4] * out.b_p + c[5] * out.b_f + c[6];
  const double N = out.resonance_ratio;
  if (N <= out.subcritical_limit)
  {
    out.range = IsoSpeedRange::subcritical; // K_v = N·K + 1
    out.kv = N * (c[0] * out.b_p + c[1] * out.b_f + c[2] * out.b_k) + 1.;
  }
  else if (N <= 1.15)
  {
    out.range = IsoSpeedRange::main_resonance;
    out.kv = main_resonance;
  }
  else if (N < 1.5)
  {
    out.range = IsoSpeedRange::intermediate; // linear between N = 1.15 and 1.5
    out.kv = supercritical + (main_resonance - supercritical) / 0.35 * (1.5 - N);
  }
  else
  {
    out.range = IsoSpeedRange::supercritical;
    out.kv = supercritical;
  }
  return out;
}
} // namespace gearstiff::dynamics
