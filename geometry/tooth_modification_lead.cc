#include "geometry/tooth_modification_lead.h"

#include "errors/errors.h"
#include "errors/format.h"
#include "geometry/fields.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gearstiff::geometry
{
namespace
{
std::string um(double length)
{
  return format_number(length * 1e6, 4) + " µm";
}

// inv(α_r) = tan α_r − α_r with cos α_r = r_b/r; 0 inside the base circle (the involute starts
// there), which keeps the weights continuous.
double involute_function(double base_radius, double radius)
{
  if (radius <= base_radius)
    return 0.;
  const double alpha = std::acos(base_radius / radius);
  return std::tan(alpha) - alpha;
}
// The field of the first non-zero entry of `gear`'s lead modifications ("pinion.lead_crowning",
// "pinion.lead_slope" or "pinion.end_relief", geometry/fields.h).
std::string first_entry(const LeadModification& lead, const std::string& gear)
{
  return field::gear_entry(gear, lead.crowning != 0. ? "lead crowning"
                                 : lead.slope != 0.  ? "lead slope"
                                                     : "end relief");
}
} // namespace

double lead_removed_depth(const LeadModification& lead, double z, double face_width, bool loaded)
{
  if (!loaded && lead.flanks == ModifiedFlanks::loaded)
    return 0.;
  const double u = std::clamp(z / face_width, 0., 1.);
  const double middle = 2. * u - 1.;
  double depth = lead.crowning * middle * middle;
  depth += lead.slope > 0. ? lead.slope * u : -lead.slope * (1. - u);
  const double from_end = std::min(u, 1. - u) * face_width;
  if (lead.end_relief > 0. && lead.end_relief_length > 0. && from_end < lead.end_relief_length)
    depth += lead.end_relief * (1. - from_end / lead.end_relief_length);
  return depth;
}

double smallest_lead_separation(const LeadModification& first, const LeadModification& second,
                                double face_width)
{
  constexpr int samples = 2000;
  double smallest = std::numeric_limits<double>::max();
  for (int i = 0; i <= samples; ++i)
  {
    const double z = face_width * i / samples;
    smallest = std::min(smallest, lead_removed_depth(first, z, face_width, true) +
                                      lead_removed_depth(second, z, face_width, true));
  }
  return smallest;
}

void check_lead_modification(const LeadModification& lead, const ToothProfile& nominal,
                             double face_width, const std::string& parameter)
{
  if (lead.empty())
    return;
  for (const auto& [amount, name] :
       {std::pair{lead.crowning, "lead crowning"}, std::pair{lead.slope, "lead slope"},
        std::pair{lead.end_relief, "end relief"}})
  {
    if (!std::isfinite(amount))
      throw InputError(field::gear_entry(parameter, name), "must be a finite amount (µm)");
    if (amount < 0. && std::string(name) != "lead slope")
      throw InputError(field::gear_entry(parameter, name),
                       "must be 0 or positive (material removed, µm)");
  }
  if (lead.end_relief > 0. &&
      !(lead.end_relief_length > 0. && lead.end_relief_length <= 0.5 * face_width))
    throw InputError(field::gear_entry(parameter, "end relief length"),
                     "must lie in (0, half the face width] (mm) for a non-zero end relief");
  const double worst = std::max(lead_removed_depth(lead, 0., face_width, true),
                                lead_removed_depth(lead, face_width, face_width, true)) *
                       (lead.flanks == ModifiedFlanks::both ? 2. : 1.);
  if (worst >= nominal.tip_thickness)
    throw InputError(first_entry(lead, parameter),
                     "the lead modifications remove " + um(worst) +
                         " across the tooth at an end of the face, beyond its tip thickness " +
                         um(nominal.tip_thickness));
}

LeadModifier::LeadModifier(const ToothProfile& nominal, const LeadModification& lead,
                           int loaded_side, double face_width, const Eigen::Vector2d& centre,
                           double rotation, const std::string& parameter)
    : lead(lead), loaded_side(loaded_side), face_width(face_width), centre(centre),
      rotation(rotation), pitch(nominal.angular_pitch), base_radius(nominal.base_radius),
      sigma(nominal.internal ? 1. : -1.), root_radius(nominal.root_radius),
      form_radius(nominal.form_radius)
{
  check_lead_modification(lead, nominal, face_width, parameter);
  // c from one nominal flank point of side +1 (the flank is an exact involute there).
  for (const ProfilePoint& p : nominal.points)
    if (p.segment == ProfileSegment::flank && p.side == 1)
    {
      flank_constant = std::atan2(p.position.y(), p.position.x()) -
                       sigma * involute_function(base_radius, p.position.norm());
      return;
    }
  throw SolverFailure("lead modification", "the tooth outline has no involute flank");
}

double LeadModifier::flank_angle(double radius) const
{
  return flank_constant + sigma * involute_function(base_radius, radius);
}

double LeadModifier::local_angle(const Eigen::Vector2d& point) const
{
  const Eigen::Vector2d d = point - centre;
  double theta = std::atan2(d.y(), d.x()) - rotation;
  theta -= pitch * std::round(theta / pitch);
  return theta;
}

double LeadModifier::depth_below_flank(const Eigen::Vector2d& point, int side) const
{
  const double radius = (point - centre).norm();
  return base_radius * (flank_angle(radius) - side * local_angle(point));
}

Eigen::Vector2d LeadModifier::offset(const Eigen::Vector3d& point) const
{
  const Eigen::Vector2d p = point.head<2>();
  const double radius = (p - centre).norm();
  const double radial = std::clamp((radius - root_radius) / (form_radius - root_radius), 0., 1.);
  if (radial == 0.)
    return Eigen::Vector2d::Zero();
  const double upper = depth_below_flank(p, +1), lower = depth_below_flank(p, -1);
  const double thickness = upper + lower; // > 0 inside the tooth
  if (!(thickness > 0.))
    return Eigen::Vector2d::Zero();
  const double w_upper = std::clamp(lower / thickness, 0., 1.);
  const double w_lower = std::clamp(upper / thickness, 0., 1.);
  const double z = point.z();
  const double turn = radial *
                      (-w_upper * lead_removed_depth(lead, z, face_width, loaded_side == +1) +
                       w_lower * lead_removed_depth(lead, z, face_width, loaded_side == -1)) /
                      base_radius;
  const Eigen::Vector2d d = p - centre;
  // A rotation by `turn` about the centre (exact, not its linearisation: r·turn²/2 ~ 1e-12 m).
  const Eigen::Vector2d turned(std::cos(turn) * d.x() - std::sin(turn) * d.y(),
                               std::sin(turn) * d.x() + std::cos(turn) * d.y());
  return turned - d;
}

std::function<Eigen::Vector2d(int, const Eigen::Vector3d&)>
lead_node_offset(unsigned int dimension, const std::vector<std::pair<int, LeadModifier>>& bodies,
                 const std::vector<std::string>& parameters)
{
  bool any = false;
  for (std::size_t b = 0; b < bodies.size(); ++b)
  {
    if (bodies[b].second.empty())
      continue;
    if (dimension != 3)
      throw InputError(first_entry(bodies[b].second.modification(), parameters.at(b)),
                       "a lead modification needs the 3D model (Mesh/dimension = 3): a 2D model "
                       "has no face width to vary over");
    any = true;
  }
  if (!any)
    return {};
  return [bodies](int material_id, const Eigen::Vector3d& point) -> Eigen::Vector2d
  {
    for (const auto& [id, modifier] : bodies)
      if (id == material_id)
        return modifier.offset(point);
    return Eigen::Vector2d::Zero();
  };
}
} // namespace gearstiff::geometry
