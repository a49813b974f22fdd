// What the influence-coefficient model refuses (stiffness/influence_checks.h): every limit with
// the measurement behind it (docs/ltca.md).
#include "stiffness/influence_checks.h"

#include "errors/errors.h"
#include "errors/format.h"
#include "geometry/fields.h"
#include "geometry/tooth_modification.h"
#include "kinematics/fields.h"
#include "stiffness/influence_sweep.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace gearstiff::stiffness
{
namespace influence
{
namespace
{
// -, the fewest hexahedron layers (node planes b/layers apart) the 3D model accepts with lead
// crowning: the ladder in check_influence_settings.
constexpr unsigned int min_layers_with_lead = 16;
// -, the closest node planes of an uncrowned 3D face, in matching depths h, the end faces' layer
// (end_face_layer_excess) is verified on (check_end_plane_spacing): the default pair at 24 layers
// (Δz/h 1.39).
constexpr double min_uncrowned_spacing = 1.35;
// -, the fewest node planes a pair's crowned contact must load when it ends inside the face (and
// the pair carries ≥ min_resolved_share of the load): fewer planes sample the load along the face
// too coarsely for the per-plane Hertz layers. Measured 2026-12-04 (invariants case 29 of seed
// 20261201: z 25/85, m 2, b 14.4 mm, T1 16.0 N·m, C_β 13 µm on both gears, Q1, 2 positions,
// μ 0, 2 ranks, one run each; docs/ltca.md §3 "Lead modifications"): the model at 16, 24, 32
// layers loads 5, 7, 11 planes, k 137.78, 136.95, 136.72 and 135.15, 134.30, 134.28 N/µm, its
// own error against 32 layers +0.78/+0.64 % at 5 planes, +0.17/+0.01 % at 7. The default pair's
// C_β 20 µm at 16 layers loads 7 planes (+0.50 % against the exact path at 24 layers, accepted).
constexpr unsigned int min_loaded_planes = 7;
constexpr double min_resolved_share = 0.25;
// -, the widest node-plane spacing of a helical face, in normal modules, the model is verified on
// (check_influence_settings): the built-in pair's default 13 layers (b 24 mm, m_n 2.5 mm:
// 0.738·m_n) are within 0.8 % of the exact path's layer limit at five positions. Measured
// 2026-12-05 on invariants case 24 of seed 20261201 (z 22/31, m_n 1.5 mm, β 8.2°, b 16.4 mm, its
// exact position, Q1, μ 0, one run each): the model at 8, 16, 24, 32 layers (1.37, 0.68, 0.46,
// 0.34·m_n) k 253.18, 256.71, 256.89, 256.50 N/µm — 1.4 % low at 8 layers, within 0.2 % of its
// finer levels from 16; the exact path's limit there 256.3 … 257.5 N/µm (from its 24 and 32
// layers, as 1/L² … 1/L).
constexpr double max_helical_spacing_modules = 0.74;

// -, the fewest layers that put a helical face's node planes within max_helical_spacing_modules
// (1 on a spur pair).
unsigned int helical_least_layers(const GearMeshStiffnessSettings& settings)
{
  if (settings.scene.pair.pinion.helix_angle == 0.)
    return 1;
  const double face =
      std::min(settings.scene.pair.pinion.face_width, settings.scene.pair.wheel.face_width);
  return static_cast<unsigned int>(std::max(
      1.,
      std::ceil(face / (max_helical_spacing_modules * settings.scene.pair.pinion.normal_module) -
                1e-9)));
}

// Either gear's lead crowned.
bool lead_crowned(const GearMeshStiffnessSettings& settings)
{
  return settings.scene.pinion_modifications.lead.crowning != 0. ||
         settings.scene.wheel_modifications.lead.crowning != 0.;
}

// Either gear's lead sloped or end-relieved: the lead modifications that load a face without
// crowning's unloaded ends and need the layer kernel's 16 layers.
bool lead_sloped(const GearMeshStiffnessSettings& settings)
{
  for (const auto* gear :
       {&settings.scene.pinion_modifications, &settings.scene.wheel_modifications})
    if (gear->lead.slope != 0. || gear->lead.end_relief != 0.)
      return true;
  return false;
}
} // namespace

// The grid step must follow the gap's kinks and the near field's depth (docs/ltca.md, limits).
void check_grid_step(double step, double depth, const PairSeparation& separation)
{
  if (step > depth)
    throw InputError(stiffness_parameter::influence_grid_points,
                     "too coarse: the grid step " + format_number(step * 1e3, 4) +
                         " mm along the line of action exceeds the matching depth " +
                         format_number(depth * 1e3, 4) +
                         " mm (the same-flank coefficients "
                         "vary over that depth); use more points");
  const double relief = separation.shortest_relief();
  if (step > 0.5 * relief)
    throw InputError(stiffness_parameter::influence_grid_points,
                     "too coarse for the relief of length " + format_number(relief * 1e3, 4) +
                         " mm: the grid step " + format_number(step * 1e3, 4) +
                         " mm must be at most half of it; use more points");
}

// Uncrowned faces load their end planes, whose layer is the quarter-space's as far as the node
// planes resolve it (end_face_layer_excess). Against the exact path on the same layers (Q1, 4
// positions, μ 0, one run each, 2026-12-05; docs/ltca.md §3 "End faces"): default pair K_Hβ
// +0.49 … +0.55 % at 4 layers, +0.95 … +1.05 % at 8, +0.61 … +0.81 % at 16, +1.30 … +1.62 % at 24;
// planet–ring pair +0.50 … +0.56, +0.63 … +1.05, +0.72 … +0.88 % at 4, 8, 16 (before, with plane
// stress on the end planes: up to +3.5 % at 24, refused above 8 layers). With the layer kernel
// between spur planes (2026-12-07): default pair +0.4 … +0.5 % at 4, +0.7 … +0.8 % at 8, −0.24 …
// −0.13 % at 16, −0.11 … +0.09 % at 24; planet–ring +0.47 … +0.52, +0.50 … +0.95 % at 4, 8. Closer
// planes than the default pair's at 24 layers are not verified: refused, naming the layers that
// keep them apart.
void check_end_plane_spacing(const GearMeshStiffnessSettings& settings,
                             const FaceStations& stations, double depth)
{
  // Crowning unloads the ends (accepted from 16 layers, above).
  if (lead_crowned(settings) || stations.size() < 2 ||
      stations.layer >= min_uncrowned_spacing * depth)
    return;
  const double face = stations.z.back() - stations.z.front();
  const auto most = static_cast<unsigned int>(std::floor(face / (min_uncrowned_spacing * depth)));
  // A lead slope needs min_layers_with_lead layers as well: a face too narrow for both cannot
  // be run by this model at all, and naming a layer count that the other check refuses would
  // send the user round in a circle.
  if (lead_sloped(settings) && most < min_layers_with_lead)
    throw InputError(stiffness_parameter::contact_model,
                     "influence coefficients with a lead slope or end relief need " +
                         std::to_string(min_layers_with_lead) + " layers at least " +
                         format_number(min_uncrowned_spacing, 3) +
                         " matching depths apart (h = " + format_number(depth * 1e3, 3) +
                         " mm; docs/ltca.md §3 \"End faces\"), which this face of " +
                         format_number(face * 1e3, 4) + " mm does not hold: use finite element");
  throw InputError(
      geometry::field::mesh("layers"),
      "influence coefficients on an uncrowned face are verified with node planes at "
      "least " +
          format_number(min_uncrowned_spacing, 3) +
          " matching depths apart (h = " + format_number(depth * 1e3, 3) +
          " mm; docs/ltca.md §3 \"End faces\"), " + format_number(stations.layer * 1e3, 3) +
          " mm at " + std::to_string(stations.size() - 1) + " layers: use at most " +
          std::to_string(most) + " layers or Stiffness/contact model = finite element");
}

// A crowned pair's contact ends inside the face and, under a light load, spans few node planes:
// there the model samples the line load too coarsely (min_loaded_planes). A lead slope's contact
// does the same under a light enough load (the gap grows linearly from the loaded end). Such a
// run is refused with the layers that would resolve it, never returned (exit 2 naming
// Mesh/layers).
void check_crowned_contact_planes(
    const std::vector<std::vector<GearMeshStiffnessResult>>& by_torque,
    const FaceStations& stations, unsigned int layers, const std::string& contact)
{
  unsigned int fewest = std::numeric_limits<unsigned int>::max();
  double from = 0., to = 0.;      // m, the loaded z of the fewest
  double angle = 0., torque = 0.; // rad, N·m: where and under which torque (a Harris map's light
                                  // torques localize the contact most)
  for (const auto& results : by_torque)
    for (const GearMeshStiffnessResult& r : results)
      for (const ToothPairLoad& load : r.pairs)
      {
        if (load.load_share < min_resolved_share)
          continue;
        unsigned int loaded = 0;
        bool at_end = false;
        double lo = std::numeric_limits<double>::max(), hi = -lo;
        for (const FaceLoadPoint& point : r.face_load)
          if (point.pair == load.pair && point.line_load > 0.)
          {
            ++loaded;
            at_end |= point.z <= 0.5 * stations.layer ||
                      point.z >= stations.z.back() - 0.5 * stations.layer;
            lo = std::min(lo, point.z);
            hi = std::max(hi, point.z);
          }
        if (!at_end && loaded > 0 && loaded < fewest)
        {
          fewest = loaded;
          from = lo;
          to = hi;
          angle = r.pinion_roll_angle;
          torque = r.pinion_torque;
        }
      }
  if (fewest >= min_loaded_planes)
    return;
  const unsigned int needed = static_cast<unsigned int>(
      std::ceil(static_cast<double>(layers) * min_loaded_planes / fewest));
  throw InputError(
      geometry::field::mesh("layers"),
      "the " + contact + " is carried by only " + std::to_string(fewest) + " node planes (z " +
          format_number(from * 1e3, 3) + " … " + format_number(to * 1e3, 3) + " mm of the face " +
          format_number(stations.z.back() * 1e3, 3) + " mm at θ = " +
          format_number(angle * 180. / M_PI, 6) + "°, T1 = " + format_number(torque, 4) +
          " N·m): influence coefficients need " + std::to_string(min_loaded_planes) +
          " (at 5 planes k is 0.8 % off its layer limit; docs/ltca.md §3); use at "
          "least " +
          std::to_string(needed) + " layers or Stiffness/contact model = finite element");
}
} // namespace influence

using namespace influence;

unsigned int influence_least_layers(const GearMeshStiffnessSettings& settings)
{
  if (settings.scene.mesh.dimension != 3)
    return 1;
  return std::max(helical_least_layers(settings),
                  lead_crowned(settings) || lead_sloped(settings) ? min_layers_with_lead : 1u);
}

void check_influence_settings(const GearMeshStiffnessSettings& settings)
{
  if (settings.scene.mesh.dimension == 3)
  {
    // The 3D model is accepted for what it is verified on (docs/ltca.md §3): spur pairs,
    // external and, since 2026-12-03 (ltca47k), internal. The planet–ring pair (z 24/69, rim
    // 3·m_n; Q1, 4 positions, μ 0, one run each) against the exact path at h_c 0.06 mm on the
    // same layers: at 8 layers k +0.46 … +0.03 %, TE ≤ 0.015 µm, shares ≤ 0.0014, K_Hβ
    // +1.0 … +1.7 %; at 4 layers k within 0.4 %, K_Hβ within 0.7 %. With lead crowning (C_β
    // 10 µm on the planet, 16 layers, body 1 mm; session 29, one run each: exact 46 s, 2.6 GB,
    // the model 12.4 s, 1.6 GB): k +0.82, +0.33, +0.29, +0.37 %, TE −0.044 … −0.021 µm, K_Hβ
    // +0.58 … −0.14 %, shares 0.0018 (test_influence_3d_lead, InternalLeadCrowning).
    // Helical pairs, external and internal: accepted since 2026-12-05 for k, TE, load shares and
    // the forces (docs/ltca.md §3 "Helical pairs accepted"). Against the exact path's layer limit
    // (Q1, 4 positions, μ 0, one run each): the small pair (z 19/29, m_n 2 mm, b 8 mm, h_c
    // 0.075 mm; Richardson 10/20 layers) at β 5°, 10°, 15° k within 0.83 %, with 6 µm tip reliefs
    // 0.48 %, lead crowning 6 µm 0.39 %, both at β 15° 0.96 %, internal (z 19/57) 0.49 %; the
    // built-in pair at β 15° at its default 13 layers within 0.23 % of each position's
    // three-level limit (26/32/40 layers; 20/32/40 at 0.625), −0.76 % at its default position. K_Hβ
    // and the line loads are not: where a contact line ends inside the face the model's K_Hβ is up
    // to 7 % (14 % internal) off the exact path's, which itself moves by 5-6 % from 10 to 20 layers
    // there; the report leaves them out for helical pairs (app: report_face_load).
    if (settings.scene.pair.pinion.helix_angle != 0.)
    {
      // Rounded tips are accepted (session 41, docs/ltca.md §3 "Rounded tips on helical pairs"):
      // the small pair (z 19/29, m_n 2 mm, r 0.4 mm on both tips) against the exact path's layer
      // limit, 4 positions, μ 0: β 15° k within 0.95 %, TE 0.081 µm; with a ring (z 57, β 10°)
      // within 0.87 %, once a tip edge against a ring got its gap on the ring's side of the line
      // of action (tip_corner_gap; it was 3.9 % soft with the pinion's tip rounded).
      const double face =
          std::min(settings.scene.pair.pinion.face_width, settings.scene.pair.wheel.face_width);
      const double module = settings.scene.pair.pinion.normal_module;
      const unsigned int layers = settings.scene.mesh.layers;
      if (layers < helical_least_layers(settings))
        throw InputError(
            geometry::field::mesh("layers"),
            "influence coefficients on a helical pair are verified with node planes at most " +
                format_number(max_helical_spacing_modules, 3) + "·m_n apart (" +
                format_number(max_helical_spacing_modules * module * 1e3, 4) +
                " mm; docs/ltca.md §3 \"Helical pairs accepted\"), " +
                format_number(face / layers * 1e3, 4) + " mm at " + std::to_string(layers) +
                " layers: use at least " + std::to_string(helical_least_layers(settings)) +
                " layers");
    }
    // Lead crowning: each node plane's gap is geometry's lead removal there, so the planes must
    // resolve the crowned contact's line load along the face. Measured 2026-12-02 (ltca47h;
    // default pair, Q1, 4 positions, μ 0; docs/ltca.md §3 "Lead modifications"): C_β = 10 µm on
    // the pinion against the exact path at 16 layers, the fast model at 8 layers k +1.42 %, at 12
    // +0.74 %, at 16 +0.41 % (TE −0.03 µm, K_Hβ 0.76 %); C_β = 20 µm against the exact path at 24
    // layers, at 16 +0.50 % (TE −0.04 µm, K_Hβ 0.39 %). A light load's crowned contact may end
    // well inside the face: its node planes are counted after the solve
    // (check_crowned_contact_planes).
    // A lead slope f_Hβ loads one end of the face, where the hat between node planes left the
    // model's K_Hβ 7-9 % above the exact path's at 16 layers. Accepted on spur pairs since
    // 2026-12-07 with each plane's load on its own plane and the layer kernel between the planes
    // at each plane's own line load (layer_kernel_departure; docs/ltca.md §3 "End faces"), as is
    // an end relief. Against the exact path on the same 16 layers (Q1, 4 positions, μ 0, body
    // 1 mm; test_influence_3d_lead LeadSlope, EndRelief): f_Hβ 10 µm on the pinion of the default
    // pair K_Hβ +0.46 … +0.96 %, k ≤ 0.11 %, TE ≤ 0.014 µm, on the planet of the planet–ring pair
    // +0.75 … +1.12 %, k ≤ 0.40 %; C_I 10 µm over 4 mm on the default pair's pinion K_Hβ −0.63 …
    // −1.44 %, k ≤ 0.19 %. On helical pairs the kernel does not hold (K_Hβ 11 % off) and the hat's
    // end planes are 5-10 % too stiff: refused there.
    const bool helical = settings.scene.pair.pinion.helix_angle != 0.;
    for (const auto* gear :
         {&settings.scene.pinion_modifications, &settings.scene.wheel_modifications})
    {
      const bool sloped = gear->lead.slope != 0. || gear->lead.end_relief != 0.;
      if (sloped && helical)
        throw InputError(stiffness_parameter::contact_model,
                         "influence coefficients carry a lead slope or end relief on spur pairs "
                         "only (on a helical pair the end planes' K_Hβ is 5-10 % off the exact "
                         "path's; docs/ltca.md §3 \"End faces\"): use finite element");
      if (sloped && settings.scene.mesh.layers < min_layers_with_lead)
        throw InputError(geometry::field::mesh("layers"),
                         "influence coefficients with a lead slope or end relief need at least " +
                             std::to_string(min_layers_with_lead) +
                             " layers (verified against the exact path at 16 and 24; "
                             "docs/ltca.md §3 \"End faces\")");
      if (gear->lead.crowning != 0. && settings.scene.mesh.layers < min_layers_with_lead)
        throw InputError(geometry::field::mesh("layers"),
                         "influence coefficients with lead crowning need at least " +
                             std::to_string(min_layers_with_lead) +
                             " layers (node planes at most b/" +
                             std::to_string(min_layers_with_lead) +
                             " apart: at 8 layers k is 1.4 % off the exact path, at 16 within "
                             "0.5 %; docs/ltca.md §3)");
    }
  }
  // Profile modifications are carried (docs/ltca.md §5): each pair touches where its modified
  // flanks' gap is smallest, its FE coefficients read there, a kink in the zone by the strip.
  // Measured 2026-12-05 against the exact rolling sweep (μ 0; test_influence_coefficients): a
  // 10 µm long tip relief on both gears of the built-in pair worst |Δk| 0.43 %, |ΔTE| 0.031 µm;
  // 8 µm on the planet of the planet–ring pair 0.52 %, 0.024 µm, shares 0.0052 (before: 1.30 %
  // and 6.0 %, refused). Faults are not: by tooth, or listed for every tooth.
  for (const auto* gear :
       {&settings.scene.pinion_modifications, &settings.scene.wheel_modifications})
    if (!gear->by_tooth.empty() || geometry::has_faults(gear->all_teeth))
      throw InputError(stiffness_parameter::contact_model,
                       "influence coefficients cannot carry a tooth fault (the flank grid assumes "
                       "every tooth alike; a cracked tooth's compliance needs its cracked mesh): "
                       "use finite element");
  if (settings.influence_grid_points < 8)
    throw InputError(stiffness_parameter::influence_grid_points,
                     "must be at least 8 points over the path of contact");
  if (settings.scene.mesh.dimension == 2 &&
      settings.elasticity.model != fem::PlanarModel::plane_strain)
    throw InputError(stiffness_parameter::contact_model,
                     "the analytic near field of influence coefficients is plane strain; set "
                     "Finite elements/Planar model = plane strain or use finite element");
}
} // namespace gearstiff::stiffness
