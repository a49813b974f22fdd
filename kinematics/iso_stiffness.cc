#include "kinematics/iso_stiffness.h"

#include <algorithm>
#include <cmath>

namespace gearstiff::kinematics
{
namespace
{
constexpr double pi = 3.14159265358979323846;
constexpr double degree = pi / 180.;

// C_R of one gear (ISO 6336-1 eq. for webbed blanks); solid blanks have C_R = 1. The web
// ratio is clamped to the tested range 0.2…1.2 as ISO prescribes.
double blank_factor(const GearSpec& gear, double face_width)
{
  if (gear.web_thickness <= 0.)
    return 1.;
  const double web_ratio = std::clamp(gear.web_thickness / face_width, 0.2, 1.2);
  return 1. + std::log(web_ratio) / (5. * std::exp(gear.rim_thickness / (5. * gear.normal_module)));
}

// C_B of one gear: the q' fit holds for h_fP = 1.2·m_n and α_Pn = 20°.
double basic_rack_factor(const GearSpec& gear)
{
  return (1. + 0.5 * (1.2 - gear.dedendum_coefficient)) *
         (1. - 0.02 * (20. - gear.pressure_angle / degree));
}
} // namespace

bool IsoStiffness::valid() const
{
  return std::all_of(validity.begin(), validity.end(),
                     [](const ValidityCheck& check) { return check.satisfied; });
}

IsoStiffness iso_mesh_stiffness(const GearPairGeometry& pair, const IsoStiffnessOptions& options)
{
  const GearSpec& g1 = pair.spec.pinion;
  const GearSpec& g2 = pair.spec.wheel;
  const double beta = std::abs(g1.helix_angle);
  const double beta_b = pair.base_helix_angle;
  // Virtual numbers of teeth z_n = z/(cos²β_b·cos β); an internal wheel counts as a rack
  // (z_n2 = ∞, ISO 6336-1 9.3.2).
  const double virtual_factor = 1. / (std::cos(beta_b) * std::cos(beta_b) * std::cos(beta));
  const double zn1 = g1.teeth * virtual_factor;
  const double inverse_zn2 = g2.internal ? 0. : 1. / (g2.teeth * virtual_factor);
  const double x1 = g1.profile_shift;
  const double x2 = g2.profile_shift;

  // ISO 6336-1 eq. (B.?) / docs/references.md §5: q' in mm·µm/N.
  const double q = 0.04723 + 0.15551 / zn1 + 0.25791 * inverse_zn2 - 0.00635 * x1 -
                   0.11654 * x1 / zn1 - 0.00193 * x2 - 0.24188 * x2 * inverse_zn2 +
                   0.00529 * x1 * x1 + 0.00182 * x2 * x2;

  IsoStiffness result;
  result.flexibility = q * 1e-9; // mm·µm/N = 1e-3 m · 1e-6 m / N
  result.theoretical_single = 1. / result.flexibility;
  result.face_width = pair.common_face_width;
  result.blank_factor =
      0.5 * (blank_factor(g1, result.face_width) + blank_factor(g2, result.face_width));
  result.basic_rack_factor = 0.5 * (basic_rack_factor(g1) + basic_rack_factor(g2));
  result.theoretical_correction = options.theoretical_correction;
  result.single = result.theoretical_single * result.theoretical_correction * result.blank_factor *
                  result.basic_rack_factor * std::cos(beta);

  // Below 100 N/mm the teeth do not bed in fully and c' falls (ISO 6336-1 9.3.1).
  constexpr double reference_load = 100e3; // N/m = 100 N/mm
  if (options.specific_load > 0. && options.specific_load < reference_load)
    result.load_factor = std::pow(options.specific_load / reference_load, 0.25);
  result.single_loaded = result.single * result.load_factor;
  const double eps_alpha = pair.transverse_contact_ratio;
  result.mesh_alpha = result.single_loaded * (0.75 * eps_alpha + 0.25);
  result.mesh_beta = 0.85 * result.mesh_alpha;
  result.single_per_width = result.single * result.face_width;
  result.mesh_alpha_per_width = result.mesh_alpha * result.face_width;

  auto check = [&](const std::string& condition, double value, bool satisfied) {
    result.validity.push_back({condition, value, satisfied});
  };
  check("x1 + x2 in [-0.5, 2.0]", x1 + x2, x1 + x2 >= -0.5 && x1 + x2 <= 2.0);
  check("x1 >= x2", x1 - x2, x1 >= x2);
  check("helix angle <= 30 deg", beta / degree, beta <= 30. * degree + 1e-12);
  check("eps_alpha >= 1.2 for c_gamma_alpha", eps_alpha, eps_alpha >= 1.2);
  for (const GearSpec* gear : {&g1, &g2})
    if (gear->web_thickness > 0.)
    {
      const std::string which = gear == &g1 ? "pinion" : "wheel";
      const double ratio = gear->web_thickness / result.face_width;
      check(which + " web b_s/b in [0.2, 1.2]", ratio, ratio >= 0.2 && ratio <= 1.2);
      const double rim = gear->rim_thickness / gear->normal_module;
      check(which + " rim s_R/m_n >= 1", rim, rim >= 1.);
    }
  if (options.specific_load > 0.)
    check("F_t*K_A/b >= 100 N/mm (else load factor)", options.specific_load * 1e-3,
          options.specific_load >= reference_load);
  check("steel/steel (assumed, not checked)", 1., true);
  return result;
}
} // namespace gearstiff::kinematics
