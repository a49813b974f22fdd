#include "geometry/scene_gear_pair.h"

#include "errors/errors.h"
#include "errors/format.h"
#include "errors/limits.h"
#include "geometry/fields.h"
#include "geometry/gear_pair_internal.h"
#include "geometry/involute_tooth.h"
#include "geometry/tooth_fault.h"
#include "geometry/tooth_modification_lead.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

namespace gearstiff::geometry
{
using namespace detail;

namespace
{
// Lead modifications (3D, geometry/tooth_modification_lead.h): the extruded nodes of each gear
// turned about its axis by their removal; empty without lead modifications.
std::function<Eigen::Vector2d(int, const Eigen::Vector3d&)>
lead_offsets(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair,
             const PlacedGears& gears)
{
  return lead_node_offset(
      spec.mesh.dimension,
      {{scene_ids::pinion_body,
        LeadModifier(gears.pinion, spec.pinion_modifications.lead, loaded_side(gears.pinion),
                     pair.common_face_width, gears.pinion_centre, gears.pinion_rotation,
                     field::modified_gear(false))},
       {scene_ids::wheel_body,
        LeadModifier(gears.wheel, spec.wheel_modifications.lead, loaded_side(gears.wheel),
                     pair.common_face_width, gears.wheel_centre, gears.wheel_rotation,
                     field::modified_gear(true))}},
      {field::modified_gear(false), field::modified_gear(true)});
}

// Meshes the model. The rims only carry the tooth loads to the bore: their cells may grow with
// depth below the root circle, which keeps a thin-rimmed wheel sector from dominating the cell
// count.
void mesh_gear_pair(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair,
                    const PlacedGears& gears, const ModelWindows& w, const PlanarModel& model,
                    const std::vector<SceneContact>& contacts, const std::string& file,
                    GearPairScene& scene)
{
  scene.pinion_root_radius = outline_root_radius(gears.pinion);
  scene.wheel_root_radius = outline_root_radius(gears.wheel);
  const auto depth_below_root = [&](const Eigen::Vector2d& x)
  {
    return std::max(scene.pinion_root_radius - (x - gears.pinion_centre).norm(),
                    involute_sign(gears.wheel) *
                        (scene.wheel_root_radius - (x - gears.wheel_centre).norm()));
  };
  // spec.rim_coarse_beyond_teeth: the arc length (at the point's radius) by which a point of a
  // gear's body lies outside the angular span of its modelled teeth (0 inside it; a sector rim
  // spans exactly its teeth).
  const auto beyond_teeth = [&](const Eigen::Vector2d& x, const ToothProfile& tooth,
                                const Eigen::Vector2d& centre, double rotation, int first, int last)
  {
    const Eigen::Vector2d d = x - centre;
    if (!(involute_sign(tooth) * (tooth.tip_radius - d.norm()) > 0.))
      return 0.; // not this gear's body
    const double middle = rotation + 0.5 * (first + last) * tooth.angular_pitch;
    const double half_span = 0.5 * (last - first + 1) * tooth.angular_pitch;
    const double off = std::abs(std::remainder(std::atan2(d.y(), d.x()) - middle, 2. * M_PI));
    return d.norm() * std::max(0., off - half_span);
  };
  const auto rim_depth = [&](const Eigen::Vector2d& x)
  {
    if (!spec.rim_coarse_beyond_teeth)
      return depth_below_root(x);
    return std::max({depth_below_root(x),
                     beyond_teeth(x, gears.pinion, gears.pinion_centre, gears.pinion_rotation,
                                  w.pinion_first, w.pinion_last),
                     beyond_teeth(x, gears.wheel, gears.wheel_centre, gears.wheel_rotation,
                                  w.wheel_first, w.wheel_last)});
  };
  std::vector<SizeFocus> foci =
      placed_fault_foci(gears.pinion_teeth, gears.pinion_centre, gears.pinion_rotation,
                        w.pinion_first, w.pinion_last);
  const std::vector<SizeFocus> wheel_foci = placed_fault_foci(
      gears.wheel_teeth, gears.wheel_centre, gears.wheel_rotation, w.wheel_first, w.wheel_last);
  foci.insert(foci.end(), wheel_foci.begin(), wheel_foci.end());
  // A rolling sweep's band of foci along every flank (add_swept_contacts): gmsh's longest edges
  // at the foci reached 1.0798 times the size at the usual first scale of 0.6 (default pair,
  // 128 positions), so the band was meshed twice, the second time at 0.6·0.95/1.0798. The band
  // starts at that scale: the same mesh, generated once (a band whose edges still overshoot is
  // generated again finer, as before). 2D only: the 3D band's accuracy was measured on the
  // meshes from the first scale of 0.6 (test_sweep_once.ThreeDQ1).
  SceneMeshSettings mesh = spec.mesh;
  if (is_helical_pair(pair)) // fewer layers than the twist needs are refused (gear_pair_helix.cc)
    mesh.least_layers = layers_for_twist(pair);
  if (!spec.swept_positions.empty() && spec.mesh.dimension == 2)
    mesh.initial_contact_scale = 0.6 * (0.95 / 1.0798158575774983);
  scene.info = mesh_scene(model, contacts, mesh, pair.common_face_width, file, rim_depth, foci);
}

// The predicted contact of every pair in contact, and the foci along the flanks that a rolling
// sweep or a helical pair's sections across the face need. The normal force behind the Hertz
// estimate is shared by the pairs in contact in the model section (a helical pair's mid-face
// section: on average ε_α pairs carry, as the contact lines' total length ε_α·b/cos β_b says),
// so that β → 0 gives the spur scene.
std::vector<SceneContact> predicted_contacts(const GearPairSceneSpec& spec,
                                             const kinematics::GearPairGeometry& pair,
                                             const LineOfAction& line, const PlacedGears& gears,
                                             const GearPairScene& scene)
{
  const bool helical = is_helical_pair(pair);
  const std::size_t sharing = helical ? pairs_in_contact(pair, scene.reference_position).size()
                                      : scene.contact_pairs.size();
  const double normal_force = spec.pinion_torque / (0.5 * pair.pinion.base_diameter) / sharing;
  std::vector<SceneContact> contacts;
  for (const int j : scene.contact_pairs)
    contacts.push_back(
        predicted_contact(spec, pair, line, gears, scene.reference_position, j, normal_force,
                          helical ? nearest_roll(pair, scene.reference_position, j) : 0.));
  std::vector<double> reached = spec.swept_positions; // the positions the contacts reach
  if (helical)
  {
    // The sections of the face are the model rolled; a rolling sweep rolls the whole face to
    // each swept position, so its band spans every one's sections too.
    GearPairSceneSpec across = spec;
    across.swept_positions = face_positions(pair, scene.reference_position);
    for (const double position : spec.swept_positions)
    {
      const std::vector<double> sections = face_positions(pair, position);
      across.swept_positions.push_back(sections.front());
      across.swept_positions.push_back(sections.back());
    }
    add_swept_contacts(across, pair, line, gears, scene.reference_position, contacts);
    reached = across.swept_positions;
  }
  else if (!spec.swept_positions.empty())
    add_swept_contacts(spec, pair, line, gears, scene.reference_position, contacts);
  reached.push_back(scene.reference_position);
  const auto [first, last] = std::minmax_element(reached.begin(), reached.end());
  add_tip_round_contacts(spec, pair, gears, *first, *last, contacts);
  return contacts;
}

// The scene's own numbers in SceneInfo (centres, rotations, line of action, quantities).
void describe_scene(const GearPairSceneSpec& spec, const kinematics::GearPairGeometry& pair,
                    const LineOfAction& line, const PlacedGears& gears, GearPairScene& scene)
{
  SceneInfo& info = scene.info;
  info.kind = "gear pair";
  info.first_centre = gears.pinion_centre;
  info.second_centre = gears.wheel_centre;
  info.first_rotation = gears.pinion_rotation;
  info.second_rotation = gears.wheel_rotation;
  info.reference_line = {line.at(std::min(0., line.t2)),
                         line.at(std::max(line.t2, pair.contact_end))};
  scene.pinion_roll_angle = scene.reference_position / (0.5 * pair.pinion.base_diameter);
  scene.pinion_tip_radius = gears.pinion.tip_radius;
  scene.wheel_tip_radius = gears.wheel.tip_radius;
  scene.pinion_sector_angle = spec.rim == RimModel::sector
                                  ? spec.pinion_teeth_modelled * gears.pinion.angular_pitch
                                  : 2. * M_PI;
  scene.wheel_sector_angle = spec.rim == RimModel::sector
                                 ? spec.wheel_teeth_modelled * gears.wheel.angular_pitch
                                 : 2. * M_PI;
  info.quantities = scene_quantities(scene);
  info.quantities.insert(info.quantities.begin(),
                         {{"centre_distance", pair.centre_distance, "m", "centre distance a_w"},
                          {"working_pressure_angle", pair.working_pressure_angle, "rad",
                           "working pressure angle α_wt"},
                          {"pinion_teeth_modelled", double(spec.pinion_teeth_modelled), "-",
                           "pinion teeth in the scene"},
                          {"wheel_teeth_modelled", double(spec.wheel_teeth_modelled), "-",
                           "wheel teeth in the scene"}});
  if (!spec.pinion_modifications.empty() || !spec.wheel_modifications.empty())
    info.quantities.push_back({"unloaded_transmission_error", scene.unloaded_transmission_error,
                               "m", "the modifications' kinematic error at this position"});
}

} // namespace

GearPairScene write_gear_pair_scene(const GearPairSceneSpec& requested, const std::string& file)
{
  const auto start = std::chrono::steady_clock::now();
  // Everything is checked before gmsh runs: the pair itself (interference, backlash, contact
  // ratio, hands) by the kinematics, the scene's own extent here.
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(requested.pair);
  check_scene_spec(requested);
  check_helical_scene(requested, pair);
  const GearPairSceneSpec given = with_teeth_modelled(requested);
  const GearPairSceneSpec spec = transverse_section_spec(given);
  PlacedGears gears = generate_teeth(spec, pair);
  GearPairScene scene;
  set_rims(spec, gears, scene);

  const LineOfAction line = line_of_action(pair);
  locate_pairs(spec, pair, line, gears, scene);
  place_gears(pair, line, scene.reference_position, gears);
  const std::vector<SceneContact> contacts = predicted_contacts(spec, pair, line, gears, scene);
  set_unloaded_transmission_error(spec, pair, line, gears, scene);
  scene.contact_lines = contact_lines(pair, line, scene.reference_position, scene.contact_pairs);

  const ModelWindows windows = model_windows(spec, gears, scene);
  PlanarModel model = gear_pair_model(spec, gears, scene, windows, pair.common_face_width);
  model.node_offset = lead_offsets(spec, pair, gears);
  if (spec.mesh.dimension == 3)
    model.twist = gear_pair_twists(pair);
  mesh_gear_pair(spec, pair, gears, windows, model, contacts, file, scene);
  describe_scene(spec, pair, line, gears, scene);
  scene.info.time_total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return scene;
}

std::vector<SceneQuantity> scene_quantities(const GearPairScene& scene)
{
  return {
      {"reference_contact_position", scene.reference_position, "m",
       "reference contact, distance from T1"},
      {"pinion_roll_angle", scene.pinion_roll_angle, "rad", "pinion roll angle ℓ/r_b1"},
      {"pairs_in_contact", double(scene.contact_pairs.size()), "-", "tooth pairs in contact"},
      {"modelled_pairs", double(scene.modelled_pairs.size()), "-",
       "tooth pairs with both teeth in the scene"},
      {"pinion_bore_radius", scene.pinion_bore_radius, "m", "pinion bore radius"},
      {"wheel_bore_radius", scene.wheel_bore_radius, "m", "wheel bore radius"},
      {"pinion_root_radius", scene.pinion_root_radius, "m",
       "pinion root radius (rim outer radius)"},
      {"wheel_root_radius", scene.wheel_root_radius, "m", "wheel root radius (rim outer radius)"},
      {"pinion_tip_radius", scene.pinion_tip_radius, "m", "pinion tip radius"},
      {"wheel_tip_radius", scene.wheel_tip_radius, "m", "wheel tip radius"},
      {"pinion_sector_angle", scene.pinion_sector_angle, "rad", "angle spanned by the pinion body"},
      {"wheel_sector_angle", scene.wheel_sector_angle, "rad", "angle spanned by the wheel body"}};
}
} // namespace gearstiff::geometry
