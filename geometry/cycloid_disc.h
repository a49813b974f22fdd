// The disc of a cycloidal (Cyclo) planetary gear: equidistant of a shortened epicycloid,
// nominal and corrected (Chmurawa & Łokiec, "Distribution of loads in cycloidal planetary gear
// (CYCLO) including modification of equidistant"; docs/references.md §4).
//
//   x = r·cos α + e·cos(z_k·α) − q·cos(α + γ),   y = r·sin α + e·sin(z_k·α) − q·sin(α + γ)
//   γ = atan( sin(z_s·α) / (1/m + cos(z_s·α)) ),  m = e·z_k / r,  z_s = z_k − 1.
#pragma once

#include "geometry/tooth_profile.h"

#include <vector>

namespace gearstiff::geometry
{
struct CycloidDiscSpec
{
  unsigned int rollers = 20;        // -, z_k, rollers in the ring; the disc has z_k − 1 lobes
  double roller_circle_radius = 0.; // m, r, radius of the circle through the roller centres
  double eccentricity = 0.;         // m, e
  double roller_radius = 0.;        // m, q (the equidistant distance)
  double rotation = 0.;             // rad, δ, the disc profile turned counter-clockwise by δ
};

// m = e·z_k/r, the shortening coefficient of the epicycloid (< 1 for a valid disc).
double shortening_coefficient(const CycloidDiscSpec& spec);

// Point of the equidistant at generating angle α (rad), in m, disc frame, δ applied.
Eigen::Vector2d cycloid_point(const CycloidDiscSpec& spec, double generating_angle);

// Closed disc outline sampled per lobe, as a ToothProfile (teeth = z_k − 1 lobes; one lobe from
// the middle of a gap to the middle of the next, lobe tip on the +x axis when δ = 0; segment:
// flank everywhere, side by half-lobe). Rejects m ≥ 1 and q too large for the roller pitch
// (InputError naming the parameter).
ToothProfile generate_cycloid_disc(const CycloidDiscSpec& spec, unsigned int points_per_lobe = 120);

// The corrected equidistant (r_k, q_k, δ) for a contact arc |α2 − α1| = ε·α_pc, α_pc = 2π/z_s,
// with clearance to the nominal profile ≤ Δr over the arc and tangency at one point S.
struct CycloidCorrection
{
  double contact_arc_ratio = 0.;           // -, ε
  double clearance_limit = 0.;             // m, Δr
  double alpha_1 = 0., alpha_2 = 0.;       // rad, generating angles of the arc ends, nominal
  double alpha_ok_1 = 0., alpha_ok_2 = 0.; // rad, the same points on the corrected profile
  double alpha_s = 0.;                     // rad, tangency point S (nominal generating angle)
  double alpha_ok_s = 0.;                  // rad, S on the corrected profile
  double roller_circle_radius = 0.;        // m, r_k
  double roller_radius = 0.;               // m, q_k
  double rotation = 0.;                    // rad, δ
  double shortening = 0.;                  // -, m_k = e·z_k/r_k
  unsigned int iterations = 0;             // Levenberg–Marquardt iterations (cost)
  unsigned int function_evaluations = 0;   // residual evaluations (cost)
  double residual_norm = 0.;               // m, at the solution

  CycloidDiscSpec corrected_disc(const CycloidDiscSpec& nominal) const;
};

// Levenberg–Marquardt solution; SolverFailure if it does not converge.
CycloidCorrection solve_cycloid_correction(const CycloidDiscSpec& nominal, double contact_arc_ratio,
                                           double clearance_limit);

// Signed curvature radius of the disc outline at generating angle α (m; > 0 convex, i.e. the
// outline turns counter-clockwise there).
double cycloid_curvature_radius(const CycloidDiscSpec& disc, double generating_angle);

// The crank (eccentric) angle φ_h (rad) puts the disc centre at e·(cos φ_h, sin φ_h); with the
// ring fixed the disc has then turned by ψ = (π − φ_h)/z_s about its centre (the placement of
// roller_clearances: centre at −e·(cos z_sψ, −sin z_sψ)). i = −z_s: ψ falls as φ_h grows.
double disc_rotation_at_crank_angle(const CycloidDiscSpec& ring, double crank_angle);

// Clearance Δr_i (m) between the disc and each roller i = 0..z_k−1 (roller i at polar angle
// 2π·i/z_k on the roller circle of the nominal spec) when the disc is turned by
// disc_rotation (rad) about its own centre, with the disc centre displaced by e along the
// eccentric direction that matches that rotation; 0 where the roller touches.
std::vector<double> roller_clearances(const CycloidDiscSpec& nominal, const CycloidDiscSpec& disc,
                                      double disc_rotation);

// Where roller i meets the disc at the same placement (ring frame: ring centre at the origin).
struct RollerContact
{
  double clearance = 0.;                                   // m, Δr_i (as roller_clearances)
  Eigen::Vector2d roller_centre = Eigen::Vector2d::Zero(); // m, on the roller circle
  Eigen::Vector2d point = Eigen::Vector2d::Zero();         // m, closest point of the disc outline
  Eigen::Vector2d normal = Eigen::Vector2d::Zero(); // unit, outward disc normal there (its line
                                                    // runs through the roller centre)
  double generating_angle = 0.;                     // rad, α of that point on the disc profile
};
std::vector<RollerContact> roller_contacts(const CycloidDiscSpec& nominal,
                                           const CycloidDiscSpec& disc, double disc_rotation);
} // namespace gearstiff::geometry
