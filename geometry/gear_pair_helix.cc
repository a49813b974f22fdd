// The helical part of the gear-pair scene (ISO 21771:2007, docs/references.md; docs/helical.md).
// The transverse model at the middle of the face (z₀ = b/2) is the spur scene of the transverse
// section; the face-width stage (geometry/face_width.cc) turns every section of each gear about
// its axis by its lead, φ(z) = σ·(z − z₀)·tan β_b / r_b (σ = +1 for a right-hand pinion; the
// wheel turns the other way on an external pair, the same way on an internal one). A turned
// section is the transverse model rolled by φ: its pair j touches the line of action at
// ℓ_j(z) = ℓ_j + σ·(z − z₀)·tan β_b, so the contact lines lie in the plane of action, inclined at
// β_b to the axis, and every section meets the pairs the rolled transverse model meets.
#include "errors/errors.h"
#include "errors/format.h"
#include "geometry/fields.h"
#include "geometry/gear_pair_internal.h"
#include "geometry/scene_gear_pair.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace gearstiff::geometry
{
namespace
{
// -, layers per unit of overlap ratio: a contact line then moves by at most p_bt/8 along the
// line of action from one layer to the next, and each pair's line crosses at least 8·ε_α layers
// (the load along it is resolved like the spur scene's 8 layers across the face).
constexpr double layers_per_overlap = 8.;

// -, the default layers per unit of ε_β of a helical scene: twice the twist rule's, for the
// contact lines. Within a layer the mortar gap of a flank node near a line crossing it at β_b
// comes out negative by an error that grows as the layer height squared (docs/helical.md "Layers
// and the contact lines"); at 16 per unit it stays within half the 1 µm overlap tolerance on
// every pair measured (2026-12-02: the built-in pair at β 15°, 13 layers, ≈ −0.32 µm scaled from
// −0.538 µm at 10; case 24 of the invariants, 8 layers, −0.461 µm; the face-width study's pair at
// β 20°, 16 per unit at every ε_β), where the twist rule's 8 per unit are refused (−1.71 and
// −2.13 µm) or 2 % stiff (the built-in pair's 7 layers against 14, "Mesh convergence").
constexpr double default_layers_per_overlap = 16.;
// -, the default body size of a helical scene over the spur default: the cells of a twisted
// scene scale with its layers, and the built-in pair at 0.7 mm exceeds the cell limit at 8
// layers already; its ladder (7–14 layers) is measured at twice the spur size.
constexpr double default_body_size_factor = 2.;

// -, sin β_b = sin β·cos α_n (ISO 21771), from the pinion's signed β.
double cos_base_helix(const kinematics::GearPairSpec& pair)
{
  const double sin_b = std::sin(pair.pinion.helix_angle) * std::cos(pair.pinion.pressure_angle);
  return std::sqrt(1. - sin_b * sin_b);
}

void scale_amounts(GearModifications& modifications, double factor)
{
  for (ToothModification& m : modifications.all_teeth)
    m.amount *= factor;
  for (auto& [index, list] : modifications.by_tooth)
    for (ToothModification& m : list)
      m.amount *= factor;
  modifications.lead.crowning *= factor;
  modifications.lead.slope *= factor;
  modifications.lead.end_relief *= factor;
}
} // namespace

bool is_helical(const GearPairSceneSpec& spec)
{
  return spec.pair.pinion.helix_angle != 0.;
}

GearPairSceneSpec transverse_section_spec(const GearPairSceneSpec& spec)
{
  if (!is_helical(spec))
    return spec;
  GearPairSceneSpec section = spec;
  const double factor = 1. / cos_base_helix(spec.pair); // δ_t = δ_n / cos β_b
  scale_amounts(section.pinion_modifications, factor);
  scale_amounts(section.wheel_modifications, factor);
  return section;
}

unsigned int layers_for_twist(const kinematics::GearPairGeometry& pair)
{
  return static_cast<unsigned int>(std::ceil(layers_per_overlap * pair.overlap_ratio - 1e-9));
}

SceneMeshSettings helical_mesh_defaults(const SceneMeshSettings& spur,
                                        const kinematics::GearPairGeometry& pair)
{
  if (!detail::is_helical_pair(pair))
    return spur;
  SceneMeshSettings helical = spur;
  helical.layers = std::max(
      spur.layers,
      static_cast<unsigned int>(std::ceil(default_layers_per_overlap * pair.overlap_ratio - 1e-9)));
  helical.body_size = default_body_size_factor * spur.body_size;
  return helical;
}

std::map<int, BodyTwist> gear_pair_twists(const kinematics::GearPairGeometry& pair)
{
  if (!detail::is_helical_pair(pair))
    return {};
  const double rate = detail::contact_shift_rate(pair);
  const double r_b1 = 0.5 * std::abs(pair.pinion.base_diameter);
  const double r_b2 = 0.5 * std::abs(pair.wheel.base_diameter);
  const double wheel_sense = pair.spec.wheel.internal ? 1. : -1.;
  const double z0 = detail::model_section(pair);
  // About the axes of the scene's placement (gear_pair_placement.cc: the pinion at the origin).
  return {{scene_ids::pinion_body, {Eigen::Vector2d::Zero(), rate / r_b1, z0}},
          {scene_ids::wheel_body, {detail::wheel_centre(pair), wheel_sense * rate / r_b2, z0}}};
}

namespace detail
{
void check_helical_scene(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair)
{
  if (!is_helical(spec))
    return;
  const double beta = std::abs(spec.pair.pinion.helix_angle);
  if (!(beta < M_PI / 4.))
    throw InputError(kinematics::gear_parameter_name(false, "helix angle"),
                     "must lie below 45° in magnitude for the FE scene (its hexahedra follow the "
                     "twist; " +
                         format_number(beta * 180. / M_PI, 6) + "° given)");
  if (spec.mesh.dimension != 3)
    throw InputError(field::mesh("dimension"), "must be 3 for a helical pair (helix angle " +
                                                   format_number(beta * 180. / M_PI, 6) +
                                                   "°): its teeth twist along the face width");
  const unsigned int needed = layers_for_twist(pair);
  if (spec.mesh.layers < needed)
    throw InputError(field::mesh("layers"),
                     "must be at least " + std::to_string(needed) +
                         " to follow the twist of this helical pair (8 per unit "
                         "of overlap ratio ε_β = " +
                         format_number(pair.overlap_ratio, 4) + "), got " +
                         std::to_string(spec.mesh.layers));
  // A root crack leaves the flanks whole, so the pairs carry as on the healthy scene; a spall, a
  // chipped or a broken tooth decide which pairs carry by where a pair touches (docs/faults.md
  // "Which pairs carry"), one point per pair, while a helical pair touches along a line that
  // crosses the fault in some sections only.
  for (const GearModifications* m : {&spec.pinion_modifications, &spec.wheel_modifications})
    for (const auto& [index, list] : m->by_tooth)
      for (const ToothModification& fault : list)
        if (is_fault(fault.kind) && fault.kind != ModificationKind::root_crack)
          throw InputError(
              kinematics::gear_parameter_name(m == &spec.wheel_modifications,
                                              fault_name(fault.kind)),
              "a helical pair carries root cracks only: a spall, a chipped or a broken tooth "
              "changes which pairs carry along each contact line (spur pairs only)");
}

double contact_shift_rate(const kinematics::GearPairGeometry& pair)
{
  const double sigma = pair.spec.pinion.helix_angle > 0. ? 1. : -1.;
  return is_helical_pair(pair) ? sigma * std::tan(pair.base_helix_angle) : 0.;
}

bool is_helical_pair(const kinematics::GearPairGeometry& pair)
{
  return pair.spec.pinion.helix_angle != 0.;
}

double model_section(const kinematics::GearPairGeometry& pair)
{
  return 0.5 * pair.common_face_width;
}

std::vector<double> face_positions(const kinematics::GearPairGeometry& pair, double reference)
{
  // Every section across the face, also those whose model-section pair (j = 0) lies off the path
  // of contact: there the pairs j = ±2 can touch (ε_β > 2 − ε_α), and their contact lines need
  // the same refinement as the others' (add_swept_contacts keeps each pair's points on the path).
  // A quarter base pitch apart, so that no pair's interval of sections ((ε_α − 1)·p_bt long at
  // least) falls between two samples.
  const double half = 0.5 * pair.common_face_width * std::abs(contact_shift_rate(pair));
  const double step = 0.25 * pair.transverse_base_pitch;
  const unsigned int n = static_cast<unsigned int>(std::ceil(2. * half / step)) + 1;
  std::vector<double> positions;
  for (unsigned int k = 0; k < n; ++k)
    positions.push_back(n == 1 ? reference : reference - half + 2. * half * k / (n - 1));
  return positions;
}

std::vector<int> pairs_across_face(const kinematics::GearPairGeometry& pair, double reference)
{
  std::vector<int> pairs;
  for (const double section : face_positions(pair, reference))
    for (const int j : pairs_in_contact(pair, section))
      pairs.push_back(j);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

double nearest_roll(const kinematics::GearPairGeometry& pair, double reference, int j)
{
  // Kept a hundredth of a base pitch inside the path: the line of action meets both flanks.
  const double margin = 0.01 * pair.transverse_base_pitch;
  const double at = reference + j * pair.transverse_base_pitch;
  const double inside = std::clamp(at, pair.contact_start + margin, pair.contact_end - margin);
  return inside - at;
}

std::vector<ContactLine> contact_lines(const kinematics::GearPairGeometry& pair,
                                       const LineOfAction& line, double reference,
                                       const std::vector<int>& pairs)
{
  const double rate = contact_shift_rate(pair), b = pair.common_face_width;
  const double z0 = model_section(pair);
  std::vector<ContactLine> lines;
  for (const int j : pairs)
  {
    const double at = reference + j * pair.transverse_base_pitch;
    double z_from = 0., z_to = b;
    if (rate != 0.)
    {
      const double za = z0 + (pair.contact_start - at) / rate;
      const double ze = z0 + (pair.contact_end - at) / rate;
      z_from = std::max(0., std::min(za, ze));
      z_to = std::min(b, std::max(za, ze));
    }
    if (!(z_to > z_from))
      continue;
    ContactLine l;
    l.pair = j;
    l.start_position = at + rate * (z_from - z0);
    l.end_position = at + rate * (z_to - z0);
    const Eigen::Vector2d p = line.at(l.start_position), q = line.at(l.end_position);
    l.start = Eigen::Vector3d(p.x(), p.y(), z_from);
    l.end = Eigen::Vector3d(q.x(), q.y(), z_to);
    lines.push_back(l);
  }
  return lines;
}
} // namespace detail
} // namespace gearstiff::geometry
