#include "geometry/tooth_fault.h"

#include "errors/errors.h"
#include "errors/format.h"
#include "geometry/fields.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>

namespace gearstiff::geometry
{
namespace
{
// Distance (roll length, m) a spall keeps from the form circle and the tip corner: its walls
// need points of their own, and the limits of the scene's smallest feature (errors/limits.h).
constexpr double flank_margin = 20e-6;

bool is_involute(ProfileSegment segment)
{
  return segment == ProfileSegment::root_relief || segment == ProfileSegment::flank ||
         segment == ProfileSegment::relief;
}

double roll_of(const Eigen::Vector2d& p, double base_radius)
{
  return std::sqrt(std::max(0., p.squaredNorm() - base_radius * base_radius));
}

// Involute arc length from the base circle to roll length ρ: s = ρ²/(2 r_b).
double involute_arc(double roll, double base_radius)
{
  return 0.5 * roll * roll / base_radius;
}

// Roll length (m) of a spall's centre: its roll angle times r_b, or (0) the reference circle's.
double spall_centre(const ToothModification& spall, const ToothProfile& tooth)
{
  const double rb = tooth.base_radius;
  return spall.position > 0.
             ? spall.position * rb
             : std::sqrt(std::max(0., tooth.reference_radius * tooth.reference_radius - rb * rb));
}

// The roll lengths of a spall's ends (m): the arc lengths s_c ± L/2 about its centre.
std::pair<double, double> spall_rolls(const ToothModification& spall, const ToothProfile& tooth)
{
  const double base_radius = tooth.base_radius;
  const double centre = involute_arc(spall_centre(spall, tooth), base_radius);
  const double low = centre - 0.5 * spall.length, high = centre + 0.5 * spall.length;
  return {low > 0. ? std::sqrt(2. * base_radius * low) : -1., std::sqrt(2. * base_radius * high)};
}

std::string entry(const std::string& gear, const std::string& name)
{
  return field::gear_entry(gear, name);
}

ProfilePoint lerp(const ProfilePoint& a, const ProfilePoint& b, double w)
{
  ProfilePoint p = a;
  p.position = a.position + w * (b.position - a.position);
  p.normal = (a.normal + w * (b.normal - a.normal)).normalized();
  p.arc_length = a.arc_length + w * (b.arc_length - a.arc_length);
  return p;
}

// The point of the loaded flank (side s) at roll length `roll`, interpolated between the
// outline's points (160 per flank: the chord's sagitta is far below a micrometre).
std::optional<ProfilePoint> flank_point(const ToothProfile& tooth, int side, double roll)
{
  const double rb = tooth.base_radius;
  for (std::size_t i = 0; i + 1 < tooth.points.size(); ++i)
  {
    const ProfilePoint &a = tooth.points[i], &b = tooth.points[i + 1];
    if (a.side != side || b.side != side || !is_involute(a.segment) || !is_involute(b.segment))
      continue;
    const double ra = roll_of(a.position, rb), rb_ = roll_of(b.position, rb);
    if ((roll - ra) * (roll - rb_) <= 0. && ra != rb_)
      return lerp(a, b, (roll - ra) / (rb_ - ra));
  }
  return std::nullopt;
}

// Half chordal thickness (m) of the nominal tooth at the radius of a flank point.
double half_thickness_at(const ProfilePoint& p)
{
  const double r = p.position.norm();
  return r * std::sin(std::abs(std::atan2(p.position.y(), p.position.x())));
}

// Where the line origin + t·direction crosses the line a + s·(b − a): (t, s); none if parallel.
std::optional<Eigen::Vector2d> crossing(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                        const Eigen::Vector2d& origin,
                                        const Eigen::Vector2d& direction)
{
  Eigen::Matrix2d m;
  m << direction, a - b;
  if (std::abs(m.determinant()) < 1e-300)
    return std::nullopt;
  return Eigen::Vector2d(m.inverse() * (a - origin));
}

// Where the ray start + t·direction (t > `skip`) leaves the outline first (t, m), if it does.
std::optional<double> ray_exit(const ToothProfile& tooth, const Eigen::Vector2d& start,
                               const Eigen::Vector2d& direction, double skip)
{
  std::optional<double> best;
  for (std::size_t i = 0; i + 1 < tooth.points.size(); ++i)
  {
    const Eigen::Vector2d a = tooth.points[i].position, b = tooth.points[i + 1].position;
    Eigen::Matrix2d m;
    m << direction, a - b;
    if (std::abs(m.determinant()) < 1e-300)
      continue;
    const Eigen::Vector2d ts = m.inverse() * (a - start);
    if (ts(0) > skip && ts(1) >= 0. && ts(1) <= 1. && (!best || ts(0) < *best))
      best = ts(0);
  }
  return best;
}

// Where the line origin + t·direction crosses the outline nearest t = 0: the segment index
// and the weight along it.
std::pair<std::size_t, double> line_crossing(const std::vector<ProfilePoint>& points,
                                             const Eigen::Vector2d& origin,
                                             const Eigen::Vector2d& direction, int side)
{
  std::pair<std::size_t, double> best{points.size(), 0.};
  double best_t = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
  {
    if (points[i].side != side && points[i + 1].side != side)
      continue;
    const auto ts = crossing(points[i].position, points[i + 1].position, origin, direction);
    if (ts && (*ts)(1) >= 0. && (*ts)(1) < 1. && std::abs((*ts)(0)) < best_t)
    {
      best_t = std::abs((*ts)(0));
      best = {i, (*ts)(1)};
    }
  }
  return best;
}

void check_chipping(const ToothModification& m, const ToothProfile& nominal,
                    const std::string& parameter)
{
  const std::string name = entry(parameter, "tip chipping");
  const double height = nominal.tip_radius - nominal.root_radius;
  if (!(m.amount > 0.) || !std::isfinite(m.amount))
    throw InputError(name, "must be a positive height [mm] (0: none)");
  if (m.amount >= height)
    throw InputError(name, format_mm(m.amount) + " is taller than the tooth (" + format_mm(height) +
                               " from root to tip)");
  if (nominal.tip_radius - m.amount <= nominal.form_radius + flank_margin)
    throw InputError(name, format_mm(m.amount) +
                               " reaches below the involute (the form circle lies " +
                               format_mm(nominal.tip_radius - nominal.form_radius) +
                               " below the tip): a deeper loss is a broken tooth");
}

void check_spall(const ToothModification& m, const ToothProfile& nominal,
                 const FlankRollRange& range, int loaded_side, const std::string& parameter)
{
  if (!(m.length > 0.) || !std::isfinite(m.length))
    throw InputError(entry(parameter, "spall length"), "must be positive [mm]");
  const auto [low, high] = spall_rolls(m, nominal);
  const double centre_roll = spall_centre(m, nominal);
  const double form = std::min(range.form, range.tip), tip = std::max(range.form, range.tip);
  if (!(centre_roll > form && centre_roll < tip))
    throw InputError(entry(parameter, "spall position"),
                     "the centre (roll length " + format_mm(centre_roll) +
                         ") lies outside the flank (" + format_mm(form) + " to " + format_mm(tip) +
                         " from the base circle)");
  if (low < form + flank_margin || high > tip - flank_margin)
    throw InputError(entry(parameter, "spall length"),
                     format_mm(m.length) + " at roll length " + format_mm(centre_roll) +
                         " reaches beyond the flank (roll lengths " + format_mm(form) + " to " +
                         format_mm(tip) + ")");
  const auto centre = flank_point(nominal, loaded_side, centre_roll);
  // A pit deeper than a quarter of the tooth's chordal thickness is no longer a surface fault
  // (spalls are tens to a few hundred µm deep, Chaari et al. 2008).
  const double limit = centre ? 0.5 * half_thickness_at(*centre) : 0.;
  if (!(m.amount > 0.) || m.amount >= limit)
    throw InputError(entry(parameter, "spall depth"),
                     format_mm(m.amount) +
                         " must be positive and less than a quarter of the tooth's thickness at "
                         "the spall (" +
                         format_mm(limit) + ")");
}

void check_crack(const ToothModification& m, const ToothProfile& nominal, int loaded_side,
                 const std::string& parameter)
{
  if (!(m.angle > 0. && m.angle <= 0.5 * M_PI))
    throw InputError(entry(parameter, "crack angle"),
                     "must lie in (0, 90] degrees to the tooth centre line");
  if (!(m.amount > 0.) || !std::isfinite(m.amount))
    throw InputError(entry(parameter, "crack depth"), "must be a positive depth [mm] (0: none)");
  const CrackPath path = crack_path(m, nominal, loaded_side);
  if (!(path.across > 0.))
    throw InputError(entry(parameter, "crack angle"),
                     "the crack path leaves the tooth into the rim: use a larger angle");
  // The tip must keep a ligament of a few slit widths to the opposite outline.
  if (m.amount >= path.across - 4. * crack_opening)
    throw InputError(entry(parameter, "crack depth"),
                     format_mm(m.amount) +
                         " is deeper than the tooth: the crack path crosses it in " +
                         format_mm(path.across) + " at this angle");
}

// The radius-r point of the outline of side `side` within the fillet (the crack's given start).
std::optional<ProfilePoint> fillet_point_at_radius(const ToothProfile& tooth, int side, double r)
{
  for (std::size_t i = 0; i + 1 < tooth.points.size(); ++i)
  {
    const ProfilePoint &a = tooth.points[i], &b = tooth.points[i + 1];
    if (a.side != side || edge_between(a, b).segment != ProfileSegment::fillet)
      continue;
    const double ra = a.position.norm(), rb = b.position.norm();
    if ((r - ra) * (r - rb) <= 0. && ra != rb)
      return lerp(a, b, (r - ra) / (rb - ra));
  }
  return std::nullopt;
}

// 2D outline of a broken tooth: the root arc between the two gap middles.
std::vector<ProfilePoint> broken_outline(const ToothProfile& tooth)
{
  const ProfilePoint first = tooth.points.front(), last = tooth.points.back();
  const double radius = first.position.norm();
  const double from = std::atan2(first.position.y(), first.position.x());
  const double to = std::atan2(last.position.y(), last.position.x());
  const unsigned int n = 9;
  std::vector<ProfilePoint> points;
  for (unsigned int k = 0; k < n; ++k)
  {
    ProfilePoint p;
    const double angle = from + (to - from) * k / (n - 1);
    p.position = radius * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    p.normal = p.position.normalized();
    p.arc_length = first.arc_length + radius * (angle - from);
    p.segment = ProfileSegment::root;
    p.side = angle < 0. ? -1 : 1;
    points.push_back(p);
  }
  points.front() = first;
  points.back() = last;
  points.front().segment = points.back().segment = ProfileSegment::root;
  return points;
}

// The outline cut by the circle r_cut: points beyond it removed, a tip arc at r_cut between
// the two flank crossings.
std::vector<ProfilePoint> chipped_outline(const std::vector<ProfilePoint>& points, double r_cut,
                                          unsigned int arc_points)
{
  std::vector<ProfilePoint> result;
  std::vector<ProfilePoint> crossings;
  std::size_t insert_at = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const double r = points[i].position.norm();
    if (r <= r_cut)
      result.push_back(points[i]);
    if (i + 1 == points.size())
      break;
    const double r_next = points[i + 1].position.norm();
    if ((r - r_cut) * (r_next - r_cut) < 0.)
    {
      ProfilePoint c = lerp(points[i], points[i + 1], (r_cut - r) / (r_next - r));
      c.position *= r_cut / c.position.norm();
      c.segment = ProfileSegment::tip; // the new tip corner is a tip point (tooth_profile.h)
      c.side = 0;
      c.normal = c.position.normalized();
      crossings.push_back(c);
      if (crossings.size() == 1)
      {
        result.push_back(c);
        insert_at = result.size();
      }
      else
        result.push_back(c);
    }
  }
  if (crossings.size() != 2)
    throw SolverFailure("tooth fault outline", "the chipping circle does not cut both flanks");
  const double from = std::atan2(crossings[0].position.y(), crossings[0].position.x());
  const double to = std::atan2(crossings[1].position.y(), crossings[1].position.x());
  std::vector<ProfilePoint> arc;
  for (unsigned int k = 1; k + 1 < arc_points; ++k)
  {
    ProfilePoint p = crossings[0];
    const double angle = from + (to - from) * k / (arc_points - 1);
    p.position = r_cut * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    p.normal = p.position.normalized();
    arc.push_back(p);
  }
  result.insert(result.begin() + insert_at, arc.begin(), arc.end());
  return result;
}

// The loaded flank between the spall's ends moved inwards by its depth, with walls.
std::vector<ProfilePoint> spalled_outline(const std::vector<ProfilePoint>& points,
                                          const ToothModification& spall, const ToothProfile& tooth,
                                          int loaded_side)
{
  const double base_radius = tooth.base_radius;
  const auto [low, high] = spall_rolls(spall, tooth);
  const auto inside = [&](double roll) { return roll > low && roll < high; };
  std::vector<ProfilePoint> result;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    ProfilePoint p = points[i];
    const bool on_flank = p.side == loaded_side && is_involute(p.segment);
    const double roll = roll_of(p.position, base_radius);
    if (on_flank && inside(roll))
    {
      p.position -= spall.amount * p.normal;
      p.segment = ProfileSegment::root; // the pit is a free surface (no flank, no contact id)
    }
    result.push_back(p);
    if (i + 1 == points.size())
      break;
    const ProfilePoint& q = points[i + 1];
    if (!(on_flank && q.side == loaded_side && is_involute(q.segment)))
      continue;
    const double roll_next = roll_of(q.position, base_radius);
    // The ends met between the two points, in the order of the outline (a spall shorter than
    // the point spacing has both there); each toggles inside/outside.
    std::vector<double> ends;
    for (const double end : {low, high})
      if ((end - roll) * (end - roll_next) < 0.)
        ends.push_back(end);
    std::sort(ends.begin(), ends.end(),
              [roll](double a, double b) { return std::abs(a - roll) < std::abs(b - roll); });
    bool in = inside(roll);
    for (const double end : ends)
    {
      ProfilePoint wall = lerp(points[i], q, (end - roll) / (roll_next - roll));
      ProfilePoint floor = wall;
      floor.position -= spall.amount * wall.normal;
      floor.segment = ProfileSegment::root;
      wall.corner = floor.corner = true;
      // Entering the pit: the flank point first; leaving it: the floor first.
      if (in)
        std::swap(wall, floor);
      result.push_back(wall);
      result.push_back(floor);
      in = !in;
    }
  }
  return result;
}

// Where the slit's faces meet the outline: the segments and weights, first the one met first.
struct SlitMouths
{
  std::size_t i1 = 0, i2 = 0;
  double w1 = 0., w2 = 0.;
  double offset1 = 0.; // m, the first mouth's offset across the path
};

SlitMouths slit_mouths(const std::vector<ProfilePoint>& points, const CrackPath& path,
                       int loaded_side)
{
  const Eigen::Vector2d across(-path.direction.y(), path.direction.x());
  const double half = 0.5 * crack_opening;
  const auto [i_a, w_a] =
      line_crossing(points, path.start + half * across, path.direction, loaded_side);
  const auto [i_b, w_b] =
      line_crossing(points, path.start - half * across, path.direction, loaded_side);
  if (i_a >= points.size() || i_b >= points.size())
    throw SolverFailure("tooth fault outline", "the crack's faces miss the fillet");
  const bool a_first = i_a + w_a < i_b + w_b;
  return {a_first ? i_a : i_b, a_first ? i_b : i_a, a_first ? w_a : w_b, a_first ? w_b : w_a,
          a_first ? half : -half};
}

// The outline with the crack's slit: mouth, one face, tip, the other face, mouth.
std::vector<ProfilePoint> cracked_outline(const std::vector<ProfilePoint>& points,
                                          const CrackPath& path, int loaded_side)
{
  const Eigen::Vector2d across(-path.direction.y(), path.direction.x());
  const double half = 0.5 * crack_opening;
  const auto [i1, i2, w1, w2, offset1] = slit_mouths(points, path, loaded_side);
  ProfilePoint mouth1 = lerp(points[i1], points[i1 + 1], w1);
  ProfilePoint mouth2 = lerp(points[i2], points[i2 + 1], w2);
  const double face = path.depth - half;
  ProfilePoint end1 = mouth1, tip = mouth1, end2 = mouth2;
  end1.position = path.start + offset1 * across + face * path.direction;
  end1.normal = -std::copysign(1., offset1) * across;
  end2.position = path.start - offset1 * across + face * path.direction;
  end2.normal = std::copysign(1., offset1) * across;
  tip.position = path.start + path.depth * path.direction;
  tip.normal = -path.direction;
  std::vector<ProfilePoint> result(points.begin(), points.begin() + i1 + 1);
  for (ProfilePoint p : {mouth1, end1, tip, end2, mouth2})
  {
    p.corner = true;
    p.segment = mouth1.segment;
    p.side = loaded_side;
    result.push_back(p);
  }
  result.insert(result.end(), points.begin() + i2 + 1, points.end());
  return result;
}

// The fill of a partial crack: the slit's material, closed by the chord across its mouth (the
// fillet's sagitta over the 40 µm mouth is far below a micrometre).
FaultFill crack_fill(const ToothProfile& tooth, const ToothModification& crack, int loaded_side,
                     double face_width)
{
  const CrackPath path = crack_path(crack, tooth, loaded_side);
  const auto [i1, i2, w1, w2, offset1] = slit_mouths(tooth.points, path, loaded_side);
  FaultFill fill;
  fill.closing = {lerp(tooth.points[i1], tooth.points[i1 + 1], w1),
                  lerp(tooth.points[i2], tooth.points[i2 + 1], w2)};
  for (ProfilePoint& p : fill.closing)
  {
    p.segment = ProfileSegment::fillet;
    p.side = loaded_side;
  }
  fill.from = fill.closing.front().position;
  fill.to = fill.closing.back().position;
  const double extent = crack.width_fraction * face_width;
  const bool parabolic = crack.parabolic_front;
  fill.removed = [path, extent, parabolic](const Eigen::Vector2d& p, double z)
  {
    if (z >= extent)
      return false;
    const double depth = parabolic ? path.depth * std::sqrt(1. - z / extent) : path.depth;
    return (p - path.start).dot(path.direction) < depth;
  };
  return fill;
}
// The fill of a spall narrower than the face (centred on the face's middle): the pit's
// material, closed by the flank between the pit's walls.
FaultFill spall_fill(const ToothProfile& tooth, const ToothModification& spall, int loaded_side,
                     double face_width)
{
  const auto [low, high] = spall_rolls(spall, tooth);
  const auto from = flank_point(tooth, loaded_side, low);
  const auto to = flank_point(tooth, loaded_side, high);
  if (!from || !to)
    throw SolverFailure("tooth fault outline", "the spall's ends are not on the flank");
  FaultFill fill;
  fill.closing.push_back(*from);
  std::vector<ProfilePoint> between;
  for (const ProfilePoint& p : tooth.points)
  {
    const double roll = roll_of(p.position, tooth.base_radius);
    if (p.side == loaded_side && is_involute(p.segment) && roll > low && roll < high)
      between.push_back(p);
  }
  const double base_radius = tooth.base_radius;
  std::sort(between.begin(), between.end(),
            [base_radius](const ProfilePoint& a, const ProfilePoint& b)
            { return roll_of(a.position, base_radius) < roll_of(b.position, base_radius); });
  fill.closing.insert(fill.closing.end(), between.begin(), between.end());
  fill.closing.push_back(*to);
  for (ProfilePoint& p : fill.closing)
    p.corner = false;
  fill.from = from->position;
  fill.to = to->position;
  const double middle = 0.5 * face_width, half = 0.5 * spall.width;
  fill.removed = [middle, half](const Eigen::Vector2d&, double z)
  { return std::abs(z - middle) < half; };
  return fill;
}

// The fill of a chipped corner (from the end face z = 0 over the chipping width): the tooth
// above the cut circle, closed by the healthy outline over the tip.
FaultFill chip_fill(const ToothProfile& tooth, const ToothModification& chip)
{
  const double r_cut = tooth.tip_radius - chip.amount;
  FaultFill fill;
  const auto& points = tooth.points;
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
  {
    const double r = points[i].position.norm(), r_next = points[i + 1].position.norm();
    if (r > r_cut)
      fill.closing.push_back(points[i]);
    if ((r - r_cut) * (r_next - r_cut) < 0.)
    {
      ProfilePoint c = lerp(points[i], points[i + 1], (r_cut - r) / (r_next - r));
      c.position *= r_cut / c.position.norm();
      fill.closing.push_back(c);
    }
  }
  if (fill.closing.size() < 3)
    throw SolverFailure("tooth fault outline", "the chipping circle does not cut both flanks");
  for (ProfilePoint& p : fill.closing)
    p.corner = false;
  fill.from = fill.closing.front().position;
  fill.to = fill.closing.back().position;
  const double width = chip.width;
  fill.removed = [width](const Eigen::Vector2d&, double z) { return z < width; };
  return fill;
}

// The first crossing of the ray origin + t·direction (t > 0) with the outline: segment index,
// weight along it and t (m); none if the ray misses it.
std::optional<std::tuple<std::size_t, double, double>>
ray_crossing(const std::vector<ProfilePoint>& points, const Eigen::Vector2d& origin,
             const Eigen::Vector2d& direction)
{
  std::optional<std::tuple<std::size_t, double, double>> best;
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
  {
    const auto ts = crossing(points[i].position, points[i + 1].position, origin, direction);
    if (ts && (*ts)(0) > 0. && (*ts)(1) >= 0. && (*ts)(1) < 1. &&
        (!best || (*ts)(0) < std::get<2>(*best)))
      best = std::make_tuple(i, (*ts)(1), (*ts)(0));
  }
  return best;
}

// A crack whose faces meet (ToothModification::crack_contact) cuts the tooth along mouth → tip
// → end, `end` where the ray from the tip parallel to the centre line towards the tooth tip
// leaves the outline. `marked`: the outline with the mouth and the end as corners (the tooth's
// outline: its flanks stay whole); `outline`: the body's meshed outline, mouth, tip, end
// (corners; the cut's edges are root segments, so they carry no flank id) in place of the
// outline between the mouth and the end; `closing`: that outline, from the mouth to the end,
// which closes the fill beyond the cut (geometry/mesh_planar.h PlanarFill).
struct CrackCut
{
  std::vector<ProfilePoint> marked, outline, closing;
};

CrackCut crack_cut(const std::vector<ProfilePoint>& points, const CrackPath& path, int loaded_side)
{
  const auto [i, w] = line_crossing(points, path.start, path.direction, loaded_side);
  const Eigen::Vector2d tip_position = path.start + path.depth * path.direction;
  const auto exit = ray_crossing(points, tip_position, Eigen::Vector2d::UnitX());
  if (i >= points.size() || !exit)
    throw SolverFailure("tooth fault outline", "the crack's cut misses the outline");
  const auto [j, v, t] = *exit;
  ProfilePoint mouth = lerp(points[i], points[i + 1], w), end = lerp(points[j], points[j + 1], v);
  ProfilePoint tip = mouth;
  mouth.position = path.start;
  tip.position = tip_position;
  tip.normal = -path.direction;
  tip.segment = ProfileSegment::root;
  tip.side = loaded_side;
  const bool forward = i + w < j + v; // the mouth comes first along the outline
  CrackCut cut;
  cut.closing.push_back(mouth);
  if (forward)
    cut.closing.insert(cut.closing.end(), points.begin() + i + 1, points.begin() + j + 1);
  else
    cut.closing.insert(cut.closing.end(), points.rend() - i - 1, points.rend() - j - 1);
  cut.closing.push_back(end);
  for (ProfilePoint& p : cut.closing)
    p.corner = false;
  mouth.corner = tip.corner = end.corner = true;
  const std::size_t before = forward ? i : j, after = forward ? j : i;
  const ProfilePoint first = forward ? mouth : end, last = forward ? end : mouth;
  cut.outline.assign(points.begin(), points.begin() + before + 1);
  cut.marked = cut.outline;
  for (const ProfilePoint& p : {first, tip, last})
    cut.outline.push_back(p);
  cut.marked.push_back(first);
  cut.marked.insert(cut.marked.end(), points.begin() + before + 1, points.begin() + after + 1);
  cut.marked.push_back(last);
  for (std::vector<ProfilePoint>* list : {&cut.outline, &cut.marked})
    list->insert(list->end(), points.begin() + after + 1, points.end());
  return cut;
}

// The modifications but the cracks whose faces meet (they cut the outline last).
std::vector<ToothModification> without_meeting_cracks(const std::vector<ToothModification>& list)
{
  std::vector<ToothModification> others;
  for (const ToothModification& m : list)
    if (m.kind != ModificationKind::root_crack || !m.crack_contact)
      others.push_back(m);
  return others;
}
} // namespace

double crack_tip_cell_size(const ToothModification& crack)
{
  return crack.crack_tip_size > 0. ? crack.crack_tip_size : crack_tip_size;
}

bool flanks_whole(const GearModifications& modifications)
{
  for (const auto& [index, list] : modifications.by_tooth)
    for (const ToothModification& m : list)
      if (is_fault(m.kind) && m.kind != ModificationKind::root_crack)
        return false;
  return true;
}

Eigen::Vector2d critical_section_point(const ToothProfile& nominal, int side)
{
  // The tangent's inclination to the centre line falls along the fillet from near 90° at the
  // root to the flank's near the form circle; 30° lies between two points.
  const double target = M_PI / 6.;
  std::optional<Eigen::Vector2d> previous;
  double previous_angle = 0.;
  for (const ProfilePoint& p : nominal.points)
  {
    if (p.side != side || p.segment != ProfileSegment::fillet)
      continue;
    const double angle = std::atan2(std::abs(p.normal.x()), std::abs(p.normal.y()));
    if (previous && (previous_angle - target) * (angle - target) <= 0. && angle != previous_angle)
      return *previous +
             (target - previous_angle) / (angle - previous_angle) * (p.position - *previous);
    previous = p.position;
    previous_angle = angle;
  }
  throw SolverFailure("tooth fault outline", "no fillet point with a 30° tangent");
}

CrackPath crack_path(const ToothModification& crack, const ToothProfile& nominal, int loaded_side)
{
  CrackPath path;
  if (crack.position > 0.)
  {
    const auto start = fillet_point_at_radius(nominal, loaded_side, crack.position);
    if (!start)
      throw InputError("crack start",
                       "radius " + format_mm(crack.position) + " is not on the fillet");
    path.start = start->position;
  }
  else
    path.start = critical_section_point(nominal, loaded_side);
  // Towards the root (−x on an external tooth) and across the centre line.
  path.direction = Eigen::Vector2d(-std::cos(crack.angle), -loaded_side * std::sin(crack.angle));
  path.depth = crack.amount;
  // The tooth ends where the path leaves it through the opposite flank or fillet, and at the
  // latest at the mirror image of its start across the centre line (a path that dives into the
  // rim: the crack then has crossed the tooth's whole thickness).
  const double sine = std::sin(crack.angle);
  path.across = sine > 0. ? 2. * std::abs(path.start.y()) / sine : 0.;
  const auto exit = ray_exit(nominal, path.start, path.direction, 1e-7);
  if (exit && (path.start + *exit * path.direction).y() * loaded_side < 0.)
    path.across = std::min(path.across, *exit);
  return path;
}

void check_faults(const std::vector<ToothModification>& modifications, const ToothProfile& nominal,
                  const FlankRollRange& range, int loaded_side, const std::string& parameter)
{
  if (!has_faults(modifications))
    return;
  if (nominal.internal)
    throw InputError(entry(parameter, "faulty tooth"),
                     "tooth faults are modelled on external gears only");
  for (const ToothModification& m : modifications)
    switch (m.kind)
    {
    case ModificationKind::tip_chipping:
      check_chipping(m, nominal, parameter);
      break;
    case ModificationKind::spall:
      check_spall(m, nominal, range, loaded_side, parameter);
      break;
    case ModificationKind::root_crack:
      try
      {
        check_crack(m, nominal, loaded_side, parameter);
      }
      catch (const InputError& e)
      {
        if (e.parameter() != "crack start")
          throw;
        throw InputError(entry(parameter, "crack start"), e.reason());
      }
      break;
    default:
      break;
    }
}

ToothProfile apply_faults(const ToothProfile& tooth,
                          const std::vector<ToothModification>& modifications, int loaded_side)
{
  ToothProfile faulty = tooth;
  // A broken tooth makes the others moot.
  for (const ToothModification& m : modifications)
    if (m.kind == ModificationKind::broken_tooth)
    {
      faulty.points = broken_outline(tooth);
      faulty.tip_radius = tooth.points.front().position.norm();
      return faulty;
    }
  for (const ToothModification& m : modifications)
    if (m.kind == ModificationKind::spall)
      faulty.points = spalled_outline(faulty.points, m, tooth, loaded_side);
  for (const ToothModification& m : modifications)
    if (m.kind == ModificationKind::root_crack && !m.crack_contact)
      faulty.points =
          cracked_outline(faulty.points, crack_path(m, tooth, loaded_side), loaded_side);
  for (const ToothModification& m : modifications)
    if (m.kind == ModificationKind::tip_chipping)
    {
      faulty.points = chipped_outline(faulty.points, tooth.tip_radius - m.amount, 8);
      faulty.tip_radius = tooth.tip_radius - m.amount;
    }
  for (const ToothModification& m : modifications) // the cut of a crack whose faces meet
    if (m.kind == ModificationKind::root_crack && m.crack_contact)
      faulty.points =
          crack_cut(faulty.points, crack_path(m, tooth, loaded_side), loaded_side).marked;
  return faulty;
}

bool flank_carries(const std::vector<ToothModification>& modifications, const ToothProfile& nominal,
                   double roll)
{
  for (const ToothModification& m : modifications)
  {
    if (m.kind == ModificationKind::broken_tooth)
      return false;
    // A chipped corner (3D) leaves the rest of the face's width to carry.
    if (m.kind == ModificationKind::tip_chipping && !is_partial_width(m) &&
        roll > roll_of(Eigen::Vector2d(nominal.tip_radius - m.amount, 0.), nominal.base_radius))
      return false;
  }
  return fault_flank_depth(modifications, nominal, roll) == 0.; // not over a spall's pit
}

double fault_flank_depth(const std::vector<ToothModification>& modifications,
                         const ToothProfile& nominal, double roll)
{
  double depth = 0.;
  for (const ToothModification& m : modifications)
    if (m.kind == ModificationKind::spall && !is_partial_width(m)) // (3D: the rest of the face
    {                                                              // width touches there)
      const auto [low, high] = spall_rolls(m, nominal);
      if (roll > low && roll < high)
        depth += m.amount;
    }
  return depth;
}

bool is_partial_width(const ToothModification& fault)
{
  switch (fault.kind)
  {
  case ModificationKind::root_crack:
    return fault.width_fraction < 1. || fault.parabolic_front;
  case ModificationKind::spall:
  case ModificationKind::tip_chipping:
    return fault.width > 0.;
  default:
    break;
  }
  return false;
}

std::vector<FaultFill> fault_fills(const ToothProfile& tooth,
                                   const std::vector<ToothModification>& modifications,
                                   int loaded_side, double face_width, const std::string& parameter)
{
  std::vector<FaultFill> fills;
  for (const ToothModification& m : modifications)
    if (m.kind == ModificationKind::broken_tooth)
      return fills;
  for (const ToothModification& m : modifications)
    if (m.kind == ModificationKind::root_crack && m.crack_contact)
    {
      const ToothProfile before =
          apply_faults(tooth, without_meeting_cracks(modifications), loaded_side);
      const CrackCut cut = crack_cut(before.points, crack_path(m, tooth, loaded_side), loaded_side);
      FaultFill fill;
      fill.closing = cut.closing;
      fill.outline = cut.outline;
      fill.from = cut.closing.front().position;
      fill.to = cut.closing.back().position;
      fill.crack = true;
      fill.removed = [](const Eigen::Vector2d&, double) { return false; };
      fills.push_back(fill);
    }
  for (const ToothModification& m : modifications)
  {
    if (!is_partial_width(m) || !(face_width > 0.))
      continue;
    if (m.kind != ModificationKind::root_crack && !(m.width < face_width))
      throw InputError(entry(parameter, m.kind == ModificationKind::spall ? "spall width"
                                                                          : "tip chipping width"),
                       format_mm(m.width) + " is not narrower than the face (" +
                           format_mm(face_width) + "): 0 = through the face");
    if (m.kind == ModificationKind::root_crack)
      fills.push_back(crack_fill(tooth, m, loaded_side, face_width));
    else if (m.kind == ModificationKind::spall)
      fills.push_back(spall_fill(tooth, m, loaded_side, face_width));
    else
      fills.push_back(chip_fill(tooth, m));
  }
  return fills;
}

std::vector<SizeFocus> fault_foci(const std::vector<ToothModification>& modifications,
                                  const ToothProfile& nominal, int loaded_side)
{
  std::vector<SizeFocus> foci;
  for (const ToothModification& m : modifications)
    if (m.kind == ModificationKind::root_crack)
    {
      const CrackPath path = crack_path(m, nominal, loaded_side);
      // Faces that meet: refined self-similarly with the tip size (faces 2 h_tip, tip radius
      // 10 h_tip: the defaults give the slit's 20 µm and 0.1 mm).
      const double tip = crack_tip_cell_size(m);
      const double face = m.crack_contact ? 2. * tip : crack_face_size;
      const double spacing = m.crack_contact ? 2. * face : crack_opening;
      const unsigned int n = static_cast<unsigned int>(std::ceil(path.depth / spacing));
      for (unsigned int k = 0; k < n; ++k)
        foci.push_back({path.start + (path.depth * k / n) * path.direction, face, spacing});
      foci.push_back({path.start + path.depth * path.direction, tip,
                      m.crack_contact ? 10. * tip : crack_tip_radius});
    }
  return foci;
}
} // namespace gearstiff::geometry
