#include "stiffness/cycloid_analytic.h"

#include "errors/errors.h"
#include "kinematics/hertz.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>

namespace gearstiff::stiffness
{
namespace
{
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  return a.x() * b.y() - a.y() * b.x();
}

// One contact of the rigid-body model: it closes by angle·lever − gap and answers with the
// force of its compliance law.
struct Spring
{
  double lever = 0.;                      // m
  double gap = 0.;                        // m
  std::function<double(double)> approach; // m, δ(P)
};

// P from δ(P) = closure by bisection on a bracket grown from 1 N (δ is increasing in P).
double force_for_closure(const std::function<double(double)>& approach, double closure)
{
  if (!(closure > 0.))
    return 0.;
  double low = 0., high = 1.;
  while (approach(high) < closure)
  {
    low = high;
    high *= 2.;
    if (high > 1e12)
      throw SolverFailure("cycloid analytic model", "no contact force matches the closure");
  }
  for (int it = 0; it < 100 && high - low > 1e-12 * high; ++it)
  {
    const double mid = 0.5 * (low + high);
    (approach(mid) < closure ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

// The rotation at which Σ P_k(angle·l_k − g_k)·l_k = torque (either sign), and the forces.
std::vector<double> balance(const std::vector<Spring>& springs, double torque, double& angle,
                            const std::string& what)
{
  const auto forces_at = [&](double a)
  {
    std::vector<double> forces;
    for (const Spring& s : springs)
      forces.push_back(force_for_closure(s.approach, a * s.lever - s.gap));
    return forces;
  };
  const auto moment = [&](double a)
  {
    const std::vector<double> forces = forces_at(a);
    double sum = 0.;
    for (unsigned int k = 0; k < springs.size(); ++k)
      sum += forces[k] * springs[k].lever;
    return sum;
  };
  const double sign = torque > 0. ? 1. : -1.;
  double low = 0., high = sign * 1e-6;
  while (std::abs(moment(high)) < std::abs(torque))
  {
    low = high;
    high *= 2.;
    if (std::abs(high) > 1.)
      throw SolverFailure("cycloid analytic model", "no " + what + " rotation carries the torque");
  }
  for (int it = 0; it < 200 && std::abs(high - low) > 1e-14 * std::abs(high); ++it)
  {
    const double mid = 0.5 * (low + high);
    (std::abs(moment(mid)) < std::abs(torque) ? low : high) = mid;
  }
  angle = 0.5 * (low + high);
  return forces_at(angle);
}
} // namespace

double line_contact_approach(double force, double length, double r1, double r2, double e1,
                             double nu1, double e2, double nu2)
{
  if (!(force > 0.))
    return 0.;
  const double c1 = (1. - nu1 * nu1) / e1, c2 = (1. - nu2 * nu2) / e2;
  const double a =
      kinematics::hertz_line_contact(force / length, r1, r2, 1. / (c1 + c2)).half_width;
  return force / (M_PI * length) *
         (c1 * (2. * std::log(4. * std::abs(r1) / a) - 1.) +
          c2 * (2. * std::log(4. * std::abs(r2) / a) - 1.));
}

namespace
{
Eigen::Vector2d disc_centre(const geometry::CycloidSceneSpec& scene)
{
  const double angle = -double(scene.ring.rollers - 1) * scene.disc_rotation;
  return -scene.ring.eccentricity * Eigen::Vector2d(std::cos(angle), std::sin(angle));
}
} // namespace

double closing_rotation(const geometry::CycloidSceneSpec& scene, double torque_sign, double overlap)
{
  // The smallest clearance in the torque's sense, −overlap, after turning the disc profile by
  // β·torque_sign: each roller's clearance is linear in β only while its closest point stays
  // put, which it does not over a backlash of several arcminutes (the closest point slides
  // along the flank). Newton on the exact clearances, the slope being the lever of the roller
  // that closes first, from the linear estimate.
  const geometry::CycloidDiscSpec disc = scene.disc.rollers == 0 ? scene.ring : scene.disc;
  const Eigen::Vector2d centre = disc_centre(scene);
  const auto first_to_close = [&](double beta, double& lever)
  {
    geometry::CycloidDiscSpec turned = disc;
    turned.rotation += torque_sign * beta;
    double smallest = std::numeric_limits<double>::infinity();
    for (const auto& c : geometry::roller_contacts(scene.ring, turned, scene.disc_rotation))
    {
      const double l = torque_sign * cross(c.point - centre, c.normal);
      if (l > 0. && (c.clearance + overlap) / l < smallest)
        smallest = (c.clearance + overlap) / l, lever = l;
    }
    if (!std::isfinite(smallest))
      throw SolverFailure("cycloid closing rotation", "no roller closes in that sense");
    return smallest; // rad, the further rotation that closes the first roller (linearised)
  };
  double lever = 0., beta = 0.;
  for (int it = 0; it < 50; ++it)
  {
    const double step = first_to_close(beta, lever);
    beta += step;
    if (std::abs(step * lever) < 1e-12)
      return std::max(beta, 0.);
  }
  throw SolverFailure("cycloid closing rotation", "no convergence in 50 Newton steps");
}

namespace
{
// The turn (rad, ≥ 0) of the output pins alone about the ring centre, in the sense `sign`, at
// which the first of `pins` reaches `reach` from its hole's centre. Pin j turned by θ sits at
// rot(θ)·c_j; its hole's centre is c_j + C (C the disc centre): the centres' distance is
// |(rot(θ) − 1)·c_j − C|, e at θ = 0. The play is a few degrees of turn at most, over which the
// distance is not linear in θ (a pin whose path meets the offset at γ_j gains (R_w·θ·sin γ_j)²/(2e)
// across it): the first θ is bracketed on a fine scan and bisected. −1 when none does within a
// pin pitch.
double first_pin_closure(const geometry::CycloidSceneSpec& scene, double sign, double reach,
                         const std::vector<unsigned int>& pins)
{
  const Eigen::Vector2d centre = disc_centre(scene);
  const auto farthest = [&](double theta)
  {
    const Eigen::Rotation2Dd turn(sign * theta);
    double largest = 0.;
    for (const unsigned int j : pins)
    {
      const Eigen::Vector2d c = geometry::output_pin_centre(scene, j);
      largest = std::max(largest, (turn * c - c - centre).norm());
    }
    return largest;
  };
  const double play = reach - scene.ring.eccentricity;
  const double limit = 2. * M_PI / scene.output_pins;
  // At most a million steps whatever the play (the bisection refines the bracket).
  const double step = std::max(0.02 * play / scene.output_pin_circle_radius, 1e-6 * limit);
  double below = 0.;
  for (double above = step; above <= limit; below = above, above += step)
    if (farthest(above) >= reach)
    {
      for (int it = 0; it < 60; ++it)
      {
        const double middle = 0.5 * (below + above);
        (farthest(middle) >= reach ? above : below) = middle;
      }
      return above;
    }
  return -1.;
}
} // namespace

double pin_closing_rotation(const geometry::CycloidSceneSpec& scene, double torque_sign,
                            double overlap)
{
  // Without play every pin touches its hole at the nominal placement already.
  if (!geometry::has_output_pin_play(scene) || scene.output_pins == 0)
    return 0.;
  const double reach = scene.output_pin_hole_radius - scene.output_pin_radius + overlap;
  std::vector<unsigned int> pins(scene.output_pins);
  std::iota(pins.begin(), pins.end(), 0u);
  const double turn = first_pin_closure(scene, torque_sign, reach, pins);
  if (turn < 0.)
    throw SolverFailure("cycloid pin closing rotation", "no output pin closes its play");
  return turn;
}

CycloidAnalyticResult analytic_cycloid_loads(const geometry::CycloidSceneSpec& scene,
                                             double output_torque, double roller_young_modulus)
{
  const geometry::CycloidDiscSpec& ring = scene.ring;
  const geometry::CycloidDiscSpec disc = scene.disc.rollers == 0 ? ring : scene.disc;
  const double e_disc = scene.young_modulus, nu = scene.poisson_ratio;
  const double e_roller = roller_young_modulus > 0. ? roller_young_modulus : e_disc;
  const double width = scene.disc_width;
  const std::vector<geometry::RollerContact> contacts =
      geometry::roller_contacts(ring, disc, scene.disc_rotation);
  const Eigen::Vector2d centre =
      -ring.eccentricity *
      Eigen::Vector2d(std::cos(-double(ring.rollers - 1) * scene.disc_rotation),
                      std::sin(-double(ring.rollers - 1) * scene.disc_rotation));
  CycloidAnalyticResult result;

  // Rollers: levers about the disc centre, clearances, line contact disc outline / roller.
  std::vector<Spring> rollers;
  for (const geometry::RollerContact& c : contacts)
  {
    Spring s;
    s.lever = cross(c.point - centre, c.normal);
    s.gap = c.clearance;
    const double r_disc = geometry::cycloid_curvature_radius(disc, c.generating_angle);
    s.approach = [=, q = ring.roller_radius](double p)
    { return line_contact_approach(p, width, r_disc, q, e_disc, nu, e_roller, nu); };
    rollers.push_back(s);
    result.roller_levers.push_back(s.lever);
  }
  result.roller_forces = balance(rollers, output_torque, result.disc_rotation, "disc");

  // Output pins: all pushed along u, levers w_j about the ring centre (equal about C).
  const Eigen::Vector2d u = -centre.normalized();
  const double play = scene.output_pin_hole_radius - scene.output_pin_radius - ring.eccentricity;
  std::vector<Spring> pins;
  for (unsigned int j = 0; j < scene.output_pins; ++j)
  {
    Spring s;
    s.lever = cross(geometry::output_pin_centre(scene, j), u);
    // With play, each pin's exact closing turn as the gap the lever must turn through (the part
    // of its path across the offset closes it sooner than the lever alone says); the spring stays
    // linear beyond it. On an own drive (R_w 45 mm, e 2.5 mm, 6 pins, 0.5 mm play, 250 N·m) the
    // rotation fell from 41.21 to 40.80 arcmin, below the FE's 41.00 again (a rigid model's lower
    // bound).
    const double closes =
        geometry::has_output_pin_play(scene)
            ? first_pin_closure(scene, s.lever > 0. ? 1. : -1.,
                                scene.output_pin_hole_radius - scene.output_pin_radius, {j})
            : 0.;
    s.gap = closes >= 0. ? std::abs(s.lever) * closes : play;
    s.approach = [=, rp = scene.output_pin_radius, rh = scene.output_pin_hole_radius](double p)
    { return line_contact_approach(p, width, -rh, rp, e_disc, nu, e_disc, nu); };
    pins.push_back(s);
    result.pin_levers.push_back(s.lever);
  }
  double relative = 0.;
  result.pin_forces = balance(pins, output_torque, relative, "output");
  result.output_rotation = result.disc_rotation + relative;

  const double small = 1e-6; // of the largest force: loaded, as the FE counts
  result.max_roller_force =
      *std::max_element(result.roller_forces.begin(), result.roller_forces.end());
  result.max_pin_force = *std::max_element(result.pin_forces.begin(), result.pin_forces.end());
  for (unsigned int i = 0; i < contacts.size(); ++i)
  {
    result.bearing_force += result.roller_forces[i] * contacts[i].normal;
    result.loaded_rollers += result.roller_forces[i] > small * result.max_roller_force;
  }
  for (const double q : result.pin_forces)
  {
    result.bearing_force -= q * u;
    result.loaded_pins += q > small * result.max_pin_force;
  }
  result.input_torque = std::abs(cross(centre, result.bearing_force));
  return result;
}
} // namespace gearstiff::stiffness
