// The classic analytic load distribution of a cycloid (Cyclo) drive at one crank angle, the
// estimate Chmurawa & Łokiec (docs/references.md §4) and the textbooks compare with: the disc is
// rigid and turns by a small angle β about its centre C (held by the eccentric bearing); each
// roller i is pressed along the disc normal n_i at its contact point x_i (the normal runs through
// the roller centre and, for the nominal profile, through the pitch point), so it closes by
//
//     δ_i = β·l_i − Δr_i,        l_i = ((x_i − C) × n_i)·z  (lever about C)
//
// with Δr_i the initial clearance of the (corrected) profile. The roller force P_i follows δ_i
// through the line-contact compliance of the disc–roller pair (below); Σ P_i·l_i = M_c fixes β.
// The output pins sit e off their holes' centres along u = −C/|C| (the W mechanism): with the
// output member turned by θ, pin j closes by δ_j = (θ − β)·w_j − s_j, w_j = (v_j × u)·z (v_j the
// pin centre from the ring centre, s_j the pin-hole play), and Σ Q_j·w_j = M_c fixes θ − β. The
// bearing force is what closes the disc's force balance: F = Σ P_i n_i − Σ Q_j u.
//
// Contact compliance (line contact of two elastic cylinders of length L under the force P,
// each body's approach of its centre to the contact; Johnson, Contact Mechanics, 1985, §5.6):
//
//     δ(P) = P/(π L) · Σ_k (1 − ν_k²)/E_k · (2·ln(4|R_k|/a) − 1),  a = √(4 P R /(π L E*))
//
// R_k the curvature radii at the contact (disc outline or hole, roller or pin), 1/R = Σ 1/R_k.
// Nothing else is elastic: the disc's body, the rollers' rings and the pins' bodies are rigid
// here, which is the main difference from the FE model (docs/cycloid.md).
#pragma once

#include "fem/fields.h"
#include "geometry/scene_cycloid.h"

#include <Eigen/Core>
#include <vector>

namespace gearstiff::stiffness
{
struct CycloidAnalyticResult
{
  std::vector<double> roller_forces; // N, P_i, roller i at polar angle 2πi/z_k
  std::vector<double> roller_levers; // m, l_i about the disc centre (> 0: closes for β > 0)
  std::vector<double> pin_forces;    // N, Q_j
  std::vector<double> pin_levers;    // m, w_j
  double disc_rotation = 0.;         // rad, β (counter-clockwise)
  double output_rotation = 0.;       // rad, θ of the output member
  double max_roller_force = 0.;      // N
  double max_pin_force = 0.;         // N
  Eigen::Vector2d bearing_force = Eigen::Vector2d::Zero(); // N, bearing on the disc
  double input_torque = 0.; // N·m, M_h = |C × F| holding the eccentric
  unsigned int loaded_rollers = 0, loaded_pins = 0;

  // Every member, once: serialisation (results cross MPI ranks, fem/parallel.h) and the
  // completeness check of tests/stiffness/test_result_fields.cc use this list.
  template <class Self, class Visit>
  static void for_each_field(Self& self, Visit&& visit)
  {
    visit("roller_forces", self.roller_forces);
    visit("roller_levers", self.roller_levers);
    visit("pin_forces", self.pin_forces);
    visit("pin_levers", self.pin_levers);
    visit("disc_rotation", self.disc_rotation);
    visit("output_rotation", self.output_rotation);
    visit("max_roller_force", self.max_roller_force);
    visit("max_pin_force", self.max_pin_force);
    visit("bearing_force", self.bearing_force);
    visit("input_torque", self.input_torque);
    visit("loaded_rollers", self.loaded_rollers);
    visit("loaded_pins", self.loaded_pins);
  }
  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    fem::serialize_fields(archive, *this);
  }
};

// Line-contact approach δ(P) (m) of two cylinders of length `length` (m), radii r1, r2 (m,
// concave < 0), moduli and Poisson ratios of both; P in N.
double line_contact_approach(double force, double length, double r1, double r2, double e1,
                             double nu1, double e2, double nu2);

// The smallest rigid rotation of the disc about its centre (rad, ≥ 0; in the sense of the
// torque's sign) that closes a roller's clearance: the backlash a corrected profile has to turn
// through before it carries load (0 for the nominal profile), plus `overlap` (m) of closure at
// that roller.
double closing_rotation(const geometry::CycloidSceneSpec& scene, double torque_sign,
                        double overlap = 0.);

// The smallest turn of the output pins alone about the ring centre (rad, ≥ 0; in the sense of
// the torque's sign), their holes held, that closes the first pin's play hole − pin − e, plus
// `overlap` (m) of closure at that pin: 0 without play. SolverFailure if no pin closes within a
// pin pitch.
double pin_closing_rotation(const geometry::CycloidSceneSpec& scene, double torque_sign,
                            double overlap = 0.);

// The analytic distribution for the scene's geometry (ring, disc profile, crank position, output
// pins) under the output torque `output_torque` (N·m, counter-clockwise on the output member;
// either sign). `roller_young_modulus` (Pa; ≤ 0: the scene's) lets the rollers be softer than
// the disc. SolverFailure when no roller or pin can carry the torque.
CycloidAnalyticResult analytic_cycloid_loads(const geometry::CycloidSceneSpec& scene,
                                             double output_torque,
                                             double roller_young_modulus = 0.);
} // namespace gearstiff::stiffness
