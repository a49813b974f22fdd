// The dynamic factor K_v by ISO 6336-1 method B (internal dynamic factor), for comparison with the
// simulated one. Stated assumptions (the standard leaves them to the user; the command reports
// them):
//  - c_γα (mean mesh stiffness) and c' (single stiffness) per unit face width are inputs; the
//    command takes them from the dynamic model's own stiffness source by default;
//  - the effective deviations f_pb,eff = f_pb − y_p and f_f,eff = f_fα − y_f (running-in
//    allowances already subtracted) and the tip relief C_a are inputs;
//  - m_red is the reduced mass of the pair from the moments of inertia (ISO 6336-1 method B:
//    m_red = m1*·m2*/(m1* + m2*), m* = J/r_b²). For a pinion shared by several meshes the
//    command gives each mesh its share J1/n_meshes, which makes n_E1 the frequency of the
//    in-phase mode in which the pinion vibrates against all wheels at once.
#pragma once

#include <array>
#include <string>

namespace gearstiff::dynamics
{
struct IsoDynamicFactorInput
{
  unsigned int pinion_teeth = 0;
  double pinion_speed = 0.;        // [rad/s] n1
  double mesh_stiffness = 0.;      // [N/m²] c_γα per unit face width (1 N/(mm·µm) = 1e9 N/m²)
  double single_stiffness = 0.;    // [N/m²] c' per unit face width
  double face_width = 0.;          // [m] b
  double reduced_mass = 0.;        // [kg] m_red of the whole face width
  double tangential_force = 0.;    // [N] F_t (nominal, at the reference circle)
  double application_factor = 1.;  // [-] K_A
  double total_contact_ratio = 0.; // [-] ε_γ (= ε_α for spur gears)
  double pitch_deviation = 0.;     // [m] f_pb,eff
  double profile_deviation = 0.;   // [m] f_f,eff
  double tip_relief = 0.;          // [m] C_a
};

enum class IsoSpeedRange
{
  subcritical,
  main_resonance,
  intermediate,
  supercritical
};

std::string iso_speed_range_name(IsoSpeedRange range);

struct IsoDynamicFactor
{
  double resonance_speed = 0.;   // [rad/s] n_E1 = sqrt(c_γα·b/m_red)/z1
  double resonance_ratio = 0.;   // [-] N = n1/n_E1
  double subcritical_limit = 0.; // [-] N_S
  IsoSpeedRange range = IsoSpeedRange::subcritical;
  double b_p = 0., b_f = 0., b_k = 0.; // [-] B_p, B_f, B_k
  std::array<double, 7> c_v{};         // [-] C_v1 .. C_v7
  double kv = 0.;                      // [-] K_v
};

// Throws InputError for non-positive stiffness, mass, speed, force or width.
IsoDynamicFactor iso6336_dynamic_factor(const IsoDynamicFactorInput& input);

// m_red [kg] of a pair from J [kg·m²] and base radii [m] (ISO 6336-1 method B).
double reduced_mass(double pinion_inertia, double pinion_base_radius, double wheel_inertia,
                    double wheel_base_radius);
} // namespace gearstiff::dynamics
