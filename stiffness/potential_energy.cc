#include "stiffness/potential_energy.h"

#include "errors/errors.h"
#include "geometry/fields.h"
#include "geometry/involute_tooth.h"
#include "geometry/tooth_fault.h"
#include "kinematics/gear_pair.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace gearstiff::stiffness
{
namespace
{
using geometry::ModificationKind;
using geometry::ProfilePoint;
using geometry::ToothModification;
using geometry::ToothProfile;

// Loaded flank of an external gear's tooth in its own frame (geometry/scene_gear_pair.h).
constexpr int loaded = 1;

struct Elastic
{
  double plane_strain_modulus = 0.; // Pa, E' = E/(1 − ν²)
  double shear_modulus = 0.;        // Pa, G = E/(2(1 + ν))
  double hertz_modulus = 0.;        // Pa, E/(1 − ν²) of k_h = π·E·b/(4(1 − ν²))
  double face_width = 0.;           // m
};

// One gear: its nominal tooth, the per-tooth modifications (checked as the scene checks them),
// and each tooth's outline without its crack (the crack enters through the section rule).
class EnergyGear
{
public:
  EnergyGear(const kinematics::GearSpec& spec, const kinematics::GearGeometry& derived,
             const kinematics::GearPairGeometry& pair, const geometry::GearModifications& mods,
             double bore_radius, const geometry::ProfileResolution& resolution, bool wheel)
      : bore(bore_radius > 0. ? bore_radius : 0.5 * spec.bore_diameter)
  {
    // The section rule integrates a spur tooth's slices (the helical scene is FE only).
    if (spec.helix_angle != 0.)
      throw InputError(kinematics::gear_parameter_name(wheel, "helix angle"),
                       "the potential-energy method models spur gears only (helix angle 0)");
    geometry::InvoluteToothSpec tooth = geometry::involute_tooth_spec(spec, derived.tip_diameter);
    tooth.required_form_diameter = derived.active_profile_start;
    nominal = geometry::generate_gear_tooth(tooth, resolution, wheel);
    range = geometry::flank_roll_range(pair, nominal, wheel);
    parameter = geometry::field::modified_gear(wheel);
    teeth = geometry::ToothProfiles(nominal, mods, range, loaded, parameter);
  }
  const ToothProfile& outline(int index)
  {
    const auto found = outlines.find(index);
    if (found != outlines.end())
      return found->second;
    std::vector<ToothModification> list;
    for (const ToothModification& m : teeth.modifications_of(index))
      if (m.kind != ModificationKind::root_crack)
        list.push_back(m);
    return outlines
        .emplace(index, geometry::apply_faults(
                            geometry::modified_tooth(nominal, list, range, loaded, parameter), list,
                            loaded))
        .first->second;
  }
  ToothProfile nominal;
  geometry::ToothProfiles teeth;
  geometry::FlankRollRange range;
  std::string parameter;
  double bore = 0.; // m
  std::map<int, ToothProfile> outlines;
};

double roll_of(const Eigen::Vector2d& p, double base_radius)
{
  return std::sqrt(std::max(0., p.squaredNorm() - base_radius * base_radius));
}

// The loaded flank's point at roll length `roll` (position and normal, interpolated).
ProfilePoint load_point(const ToothProfile& tooth, double roll)
{
  for (std::size_t i = 0; i + 1 < tooth.points.size(); ++i)
  {
    const ProfilePoint &a = tooth.points[i], &b = tooth.points[i + 1];
    if (a.side != loaded || b.side != loaded || a.segment < geometry::ProfileSegment::root_relief ||
        b.segment < geometry::ProfileSegment::root_relief)
      continue;
    const double ra = roll_of(a.position, tooth.base_radius);
    const double rb = roll_of(b.position, tooth.base_radius);
    if ((roll - ra) * (roll - rb) <= 0. && ra != rb)
    {
      const double w = (roll - ra) / (rb - ra);
      ProfilePoint p = a;
      p.position = a.position + w * (b.position - a.position);
      p.normal = (a.normal + w * (b.normal - a.normal)).normalized();
      return p;
    }
  }
  throw SolverFailure("energy method",
                      "no flank point at roll length " + std::to_string(roll * 1e3) + " mm");
}

// Half height (m) of the outline's side `side` at x along the centre line: the smallest
// distance from the centre line of the outline's crossings of the section.
double half_height(const std::vector<ProfilePoint>& points, int side, double x)
{
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
  {
    const Eigen::Vector2d a = points[i].position, b = points[i + 1].position;
    if ((x - a.x()) * (x - b.x()) > 0. || a.x() == b.x())
      continue;
    const double y = a.y() + (x - a.x()) / (b.x() - a.x()) * (b.y() - a.y());
    if (y * side > 0.)
      best = std::min(best, y * side);
  }
  return best;
}

// Half angle θ_f (rad) of the tooth at the root circle: where the outline leaves the root arc
// (half the angular pitch when the fillets meet in the gap middle).
double root_half_angle(const ToothProfile& tooth)
{
  const double root = tooth.points.back().position.norm();
  double angle = 0.5 * tooth.angular_pitch;
  for (auto p = tooth.points.rbegin(); p != tooth.points.rend(); ++p)
  {
    if (std::abs(p->position.norm() - root) > 1e-9 * root)
      break;
    angle = std::atan2(p->position.y(), p->position.x());
  }
  return angle;
}

// The beam's compliances (bending, shear, axial) of the tooth outline `tooth` loaded at `load`,
// the loaded side ending at each crack tip's distance from the centre line above it (Tian 2004;
// Chaari et al. 2009).
ToothCompliance beam_compliance(const ToothProfile& tooth, const ProfilePoint& load,
                                const std::vector<Eigen::Vector2d>& tips, const Elastic& e,
                                unsigned int sections)
{
  const double x_c = load.position.x(), y_c = load.position.y();
  const double cos_a = load.normal.y(), sin_a = load.normal.x(); // α₁ to the centre line's normal
  const double r_f = tooth.points.front().position.norm();
  const double dx = (x_c - r_f) / sections;
  ToothCompliance c;
  for (unsigned int k = 0; k < sections; ++k)
  {
    const double x = r_f + (k + 0.5) * dx;
    double h_loaded = half_height(tooth.points, loaded, x);
    for (const Eigen::Vector2d& tip : tips)
      if (x >= tip.x())
        h_loaded = std::min(h_loaded, tip.y() * loaded);
    const double thickness = h_loaded + half_height(tooth.points, -loaded, x);
    if (!(thickness > 0.) || !std::isfinite(thickness))
      throw SolverFailure("energy method", "no tooth material at the section " +
                                               std::to_string(x * 1e3) + " mm from the centre");
    const double area = thickness * e.face_width;
    const double inertia = thickness * thickness * thickness * e.face_width / 12.;
    const double arm = cos_a * (x_c - x) - sin_a * y_c;
    c.bending += arm * arm / (e.plane_strain_modulus * inertia) * dx;
    c.shear += 1.2 * cos_a * cos_a / (e.shear_modulus * area) * dx;
    c.axial += sin_a * sin_a / (e.plane_strain_modulus * area) * dx;
  }
  return c;
}

// The crack depth (m) of `crack` at z (m from the end face z = 0) of a face of width b: a through
// the face; over part of it (3D) a for z < f·b (straight front) or a·√(1 − z/(f·b)) (parabolic
// front), 0 beyond (geometry/tooth_fault.h).
double crack_depth_at(const ToothModification& crack, double z, double face_width)
{
  if (!geometry::is_partial_width(crack))
    return crack.amount;
  const double extent = crack.width_fraction * face_width;
  if (z >= extent)
    return 0.;
  return crack.parabolic_front ? crack.amount * std::sqrt(1. - z / extent) : crack.amount;
}

// Bending, shear and axial compliance of tooth `index` at `load`. A crack through the face cuts
// every section the same way; a crack over part of the face (3D) is taken by slices along the
// face (Chen & Shao 2011, docs/references.md §17): each slice of width dz a beam with the crack
// depth of its z, the slices side by side (their stiffnesses add: the tooth's k is the mean over
// z of the full-width k at each slice's depth), no shear between them.
ToothCompliance cracked_beam_compliance(EnergyGear& gear, int index, const ProfilePoint& load,
                                        const Elastic& e, const EnergyMethodSettings& settings)
{
  std::vector<ToothModification> cracks;
  bool partial = false;
  for (const ToothModification& m : gear.teeth.modifications_of(index))
    if (m.kind == ModificationKind::root_crack)
    {
      cracks.push_back(m);
      partial = partial || geometry::is_partial_width(m);
    }
  const ToothProfile& tooth = gear.outline(index);
  const unsigned int slices = partial ? settings.face_slices : 1;
  ToothCompliance sum; // Σ over the slices of k_i²·c_i (each share c_i·k_i weighted by k_i)
  double stiffness = 0.;
  for (unsigned int i = 0; i < slices; ++i)
  {
    const double z = (i + 0.5) * e.face_width / slices;
    std::vector<Eigen::Vector2d> tips;
    for (const ToothModification& m : cracks)
    {
      const double depth = crack_depth_at(m, z, e.face_width);
      if (depth > 0.)
      {
        const geometry::CrackPath path = geometry::crack_path(m, gear.nominal, loaded);
        tips.push_back(path.start + depth * path.direction);
      }
    }
    const ToothCompliance c = beam_compliance(tooth, load, tips, e, settings.sections);
    const double k = 1. / c.total();
    stiffness += k / slices;
    sum.bending += k * k * c.bending;
    sum.shear += k * k * c.shear;
    sum.axial += k * k * c.axial;
  }
  // The mean stiffness k̄'s compliance 1/k̄, split as the slices' stiffness-weighted shares:
  // Σ_i (k_i/(n·k̄))·(c_i·k_i)/k̄ sums to 1/k̄.
  const double scale = 1. / (stiffness * stiffness * slices);
  return {sum.bending * scale, sum.shear * scale, sum.axial * scale, 0.};
}

ToothCompliance tooth_compliance(EnergyGear& gear, int index, double roll, const Elastic& e,
                                 const EnergyMethodSettings& settings)
{
  const ToothProfile& tooth = gear.outline(index);
  const ProfilePoint load = load_point(tooth, roll);
  const double x_c = load.position.x(), y_c = load.position.y();
  const double cos_a = load.normal.y(), sin_a = load.normal.x();
  const double r_f = tooth.points.front().position.norm();
  ToothCompliance c = cracked_beam_compliance(gear, index, load, e, settings);
  // Fillet foundation, Sainsot et al. 2004 (of the nominal tooth's root).
  const double theta_f = root_half_angle(gear.nominal);
  const double s_f = 2. * r_f * std::sin(theta_f);
  const double u_f = x_c - y_c * sin_a / cos_a - r_f;
  const double h_f = r_f / gear.bore;
  const double ratio = u_f / s_f, tan_a = sin_a / cos_a;
  c.foundation = cos_a * cos_a / (e.plane_strain_modulus * e.face_width) *
                 (sainsot_coefficient(0, h_f, theta_f) * ratio * ratio +
                  sainsot_coefficient(1, h_f, theta_f) * ratio +
                  sainsot_coefficient(2, h_f, theta_f) *
                      (1. + sainsot_coefficient(3, h_f, theta_f) * tan_a * tan_a));
  return c;
}

// Whether tooth `index` of the gear touches at roll `roll`: not broken or chipped away there,
// and not inside a through-face spall (the flank lies the pit's depth below its mate).
bool touches(EnergyGear& gear, int index, double roll)
{
  const auto& list = gear.teeth.modifications_of(index);
  return geometry::flank_carries(list, gear.nominal, roll) &&
         geometry::fault_flank_depth(list, gear.nominal, roll) == 0.;
}
} // namespace

double sainsot_coefficient(unsigned int row, double h_f, double theta_f)
{
  // Sainsot, Velex & Duverger 2004, Table 1: A, B, C, D, E, F of L*, M*, P*, Q*.
  static const double table[4][6] = {
      {-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045},
      {60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086},
      {-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236},
      {-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904}};
  const double* k = table[row];
  return k[0] / (theta_f * theta_f) + k[1] * h_f * h_f + k[2] * h_f / theta_f + k[3] / theta_f +
         k[4] * h_f + k[5];
}

std::vector<EnergyPosition> energy_mesh_stiffness(const geometry::GearPairSceneSpec& scene,
                                                  const std::vector<double>& positions,
                                                  const EnergyMethodSettings& settings)
{
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(scene.pair);
  if (scene.pair.wheel.internal)
    throw InputError(kinematics::gear_parameter_name(true, "internal"),
                     "the energy method models external pairs only");
  EnergyGear pinion(scene.pair.pinion, pair.pinion, pair, scene.pinion_modifications,
                    scene.pinion_bore_radius, scene.resolution, false);
  EnergyGear wheel(scene.pair.wheel, pair.wheel, pair, scene.wheel_modifications,
                   scene.wheel_bore_radius, scene.resolution, true);
  Elastic e;
  const double nu = scene.poisson_ratio;
  e.plane_strain_modulus = scene.young_modulus / (1. - nu * nu);
  e.shear_modulus = scene.young_modulus / (2. * (1. + nu));
  e.hertz_modulus = scene.young_modulus / (1. - nu * nu);
  e.face_width = pair.common_face_width;
  const double t2 = pair.line_of_action_length;
  std::vector<EnergyPosition> results;
  for (const double position : positions)
  {
    EnergyPosition result;
    result.position = position;
    result.mesh_position = (position - pair.contact_start) / pair.transverse_base_pitch;
    result.lost_contact = true;
    for (const int j : geometry::gear_pairs_in_contact(pair, position))
    {
      EnergyPair p;
      p.pair = j;
      p.position = position + j * pair.transverse_base_pitch;
      const double roll_wheel = t2 - p.position;
      p.carries = touches(pinion, j, p.position) && touches(wheel, -j, roll_wheel);
      p.hertz = M_PI * e.hertz_modulus * e.face_width / 4.; // Yang & Lin 1987
      if (p.carries)
      {
        p.pinion = tooth_compliance(pinion, j, p.position, e, settings);
        p.wheel = tooth_compliance(wheel, -j, roll_wheel, e, settings);
        p.stiffness = 1. / (1. / p.hertz + p.pinion.total() + p.wheel.total());
        result.mesh_stiffness += p.stiffness;
        result.lost_contact = false;
      }
      result.pairs.push_back(p);
    }
    results.push_back(result);
  }
  return results;
}
} // namespace gearstiff::stiffness
