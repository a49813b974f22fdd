// The influence-coefficient model's geometry (stiffness/influence_geometry.h).
#include "stiffness/influence_geometry.h"

#include "geometry/involute_tooth.h"
#include "geometry/scene_gear_pair.h"
#include "stiffness/face_load.h"

#include <Eigen/Dense>
#include <algorithm>
#include <limits>

namespace gearstiff::stiffness::influence
{
FaceStations face_stations(int dim, unsigned int layers, double face_width)
{
  FaceStations stations;
  if (dim == 2)
  {
    stations.z = {0.};
    stations.width = {face_width};
    return stations;
  }
  stations.layer = face_width / layers;
  // The exact path's Q1 node planes, with their widths (stiffness/face_load.h): the line loads
  // of both paths are forces over the same widths.
  const FacePlanes planes{face_width, layers, 1};
  for (unsigned int i = 0; i <= layers; ++i)
  {
    stations.z.push_back(i * stations.layer);
    stations.width.push_back(planes.width(stations.z.back()));
  }
  return stations;
}

double on_path_width(const FaceStations& stations, const Helix& helix,
                     const kinematics::GearPairGeometry& pair, std::size_t s, double at)
{
  if (helix.rate == 0. || stations.layer == 0.)
    return stations.width[s];
  const double z_s = stations.z[s];
  double low = std::max(0., z_s - 0.5 * stations.layer);
  double high = std::min(stations.z.back(), z_s + 0.5 * stations.layer);
  const double z_a = z_s + (pair.contact_start - at) / helix.rate;
  const double z_e = z_s + (pair.contact_end - at) / helix.rate;
  low = std::max(low, std::min(z_a, z_e));
  high = std::min(high, std::max(z_a, z_e));
  return std::max(0., high - low);
}

double tip_corner_gap(const PairFrame& frame, double beyond, bool at_start, double rounding)
{
  const kinematics::GearPairGeometry& pair = frame.pair;
  const Eigen::Vector2d o1(0., 0.), o2(frame.wheel_centre[0], frame.wheel_centre[1]);
  const Eigen::Vector2d u(frame.u[0], frame.u[1]);
  const auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b)
  { return a.x() * b.y() - a.y() * b.x(); };
  const auto turn = [](const Eigen::Vector2d& p, const Eigen::Vector2d& c, double angle)
  {
    const Eigen::Vector2d d = p - c;
    return Eigen::Vector2d(c.x() + std::cos(angle) * d.x() - std::sin(angle) * d.y(),
                           c.y() + std::sin(angle) * d.x() + std::cos(angle) * d.y());
  };
  const double r_b1 = frame.pinion_base_radius(), r_b2 = frame.wheel_base_radius();
  // A counter-clockwise turn φ moves the pinion's contact by +s₁·r_b1·φ along ℓ, the wheel's by
  // −s₂·r_b2·φ (checked: the curves so generated cross the line of action at right angles).
  const double s1 = cross(geometry::line_of_action_point(pair, 0.) - o1, u) > 0. ? 1. : -1.;
  const double s2 = cross(geometry::line_of_action_point(pair, frame.t2) - o2, -u) > 0. ? 1. : -1.;
  const auto angle_to =
      [&](const Eigen::Vector2d& from, const Eigen::Vector2d& to, const Eigen::Vector2d& c)
  { return std::atan2(cross(from - c, to - c), (from - c).dot(to - c)); };
  // A rounded tip: its arc's centre, r inside the tooth along the form point's normal (the line
  // of action there: towards T1 into the pinion, away from the pinion into a wheel's or a ring's
  // tooth), stands in for the corner, and the arc lies r nearer than it (the mate's involutes are
  // parallel curves, so the distance from a point to the flank is the same |Δℓ|).
  if (!at_start)
  {
    const double at = pair.contact_end + beyond;
    const Eigen::Vector2d corner = turn(
        geometry::line_of_action_point(pair, pair.contact_end - rounding), o1, beyond * s1 / r_b1);
    const double rho = std::sqrt(std::max(0., (corner - o2).squaredNorm() - r_b2 * r_b2));
    // The point of the line of action as far from O₂: on T₂'s side towards T₁ for an external
    // wheel (t₂ > ℓ), beyond T₂ away from it for a ring (t₂ < 0 < ℓ, ρ₂ = ℓ − t₂).
    const double l_r = pair.spec.wheel.internal ? frame.t2 + rho : frame.t2 - rho;
    const double alpha = angle_to(corner, geometry::line_of_action_point(pair, l_r), o2);
    return std::max(0., std::abs(l_r + alpha * s2 * r_b2 - at) - rounding);
  }
  const double at = pair.contact_start - beyond;
  const Eigen::Vector2d corner = turn(
      geometry::line_of_action_point(pair, pair.contact_start + rounding), o2, beyond * s2 / r_b2);
  const double l_r = std::sqrt(std::max(0., corner.squaredNorm() - r_b1 * r_b1));
  const double alpha = angle_to(corner, geometry::line_of_action_point(pair, l_r), o1);
  return std::max(0., std::abs(l_r - alpha * s1 * r_b1 - at) - rounding);
}

double rounded_tip_removal(double base_radius, double form_roll, double radius, double roll,
                           bool internal)
{
  if (!(radius > 0.) || !(internal ? roll < form_roll : roll > form_roll))
    return 0.;
  // The involute in its gear's frame, its normal's angle θ = ρ/r_b: P(θ) = r_b(−sin θ, cos θ) +
  // ρ·n(θ), n = (cos θ, sin θ) outward; the arc's centre lies r under the form point.
  const auto point = [base_radius](double rho)
  {
    const double theta = rho / base_radius;
    return Eigen::Vector2d(-base_radius * std::sin(theta) + rho * std::cos(theta),
                           base_radius * std::cos(theta) + rho * std::sin(theta));
  };
  const auto normal = [base_radius](double rho)
  { return Eigen::Vector2d(std::cos(rho / base_radius), std::sin(rho / base_radius)); };
  // Into the material: −n on an external gear's tooth, +n on a ring's (its material lies on the
  // other side of the same involute).
  const double inward = internal ? 1. : -1.;
  const Eigen::Vector2d centre = point(form_roll) + inward * radius * normal(form_roll);
  // |P + t·inward·n − C| = r for the nearer t ≥ 0.
  const Eigen::Vector2d d = point(roll) - centre;
  const double along = -inward * d.dot(normal(roll));
  const double discriminant = along * along - d.squaredNorm() + radius * radius;
  return discriminant >= 0. ? along - std::sqrt(discriminant) : along;
}

PairSeparation::PairSeparation(const GearMeshStiffnessSettings& settings, const PairFrame& frame)
    : pinion(settings.scene.pinion_modifications.all_teeth),
      wheel(settings.scene.wheel_modifications.all_teeth),
      pinion_lead(settings.scene.pinion_modifications.lead),
      wheel_lead(settings.scene.wheel_modifications.lead), face_width(frame.pair.common_face_width),
      t2(frame.t2), pinion_base(frame.pinion_base_radius()), wheel_base(frame.wheel_base_radius()),
      pinion_rounding(settings.scene.pair.pinion.tip_rounding_radius),
      wheel_rounding(settings.scene.pair.wheel.tip_rounding_radius)
{
  for (const bool is_wheel : {false, true})
  {
    const kinematics::GearSpec& gear =
        is_wheel ? settings.scene.pair.wheel : settings.scene.pair.pinion;
    const kinematics::GearGeometry& derived = is_wheel ? frame.pair.wheel : frame.pair.pinion;
    geometry::InvoluteToothSpec spec = geometry::involute_tooth_spec(gear, derived.tip_diameter);
    spec.required_form_diameter = derived.active_profile_start;
    const geometry::ToothProfile tooth =
        geometry::generate_gear_tooth(spec, settings.scene.resolution, is_wheel);
    (is_wheel ? wheel_range : pinion_range) =
        geometry::flank_roll_range(frame.pair, tooth, is_wheel);
    const double r_a = 0.5 * derived.tip_diameter,
                 r_b = is_wheel ? frame.wheel_base_radius() : frame.pinion_base_radius();
    (is_wheel ? wheel_apex : pinion_apex) = std::sqrt(std::max(0., r_a * r_a - r_b * r_b));
  }
  // By value: a copied PairSeparation keeps working.
  flanks.pinion_removal =
      [list = pinion, range = pinion_range, r_b = pinion_base, r = pinion_rounding](double roll)
  { return flank_removal(list, range, r_b, r, roll); };
  flanks.wheel_removal = [list = wheel, range = wheel_range, r_b = wheel_base, r = wheel_rounding,
                          internal = frame.pair.spec.wheel.internal](double roll)
  { return flank_removal(list, range, r_b, r, roll, internal); };
  flanks.pinion_range = pinion_range;
  flanks.wheel_range = wheel_range;
  flanks.pinion_base_radius = frame.pinion_base_radius();
  flanks.wheel_base_radius = frame.wheel_base_radius();
  flanks.t2 = t2;
  flanks.internal = frame.pair.spec.wheel.internal;
}
} // namespace gearstiff::stiffness::influence
