// Scene type "gear pair" of `gearstiff mesh`: a spur pair at one position, the teeth around the
// predicted contacts (geometry/scene_gear_pair.h). Subsections Gear pair, Gear pair scene.
#include "geometry/scene_gear_pair.h"

#include "app/core/parameter_patterns.h"
#include "app/core/units.h"
#include "app/kinematics/kinematics_parameters.h"
#include "app/scenes/geometry_parameters.h"
#include "app/scenes/scene.h"
#include "app/scenes/tooth_modification_parameters.h"
#include "errors/format.h"
#include "kinematics/automatic_sizes.h"
#include "stiffness/mesh_stiffness.h"

#include <vector>

namespace
{
using namespace gearstiff;
using namespace gearstiff::app;

const std::string split_path_source = "docs/references.md §1 (Reszuta & Drewniak 2015)";

void declare_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Scene");
  prm.declare_entry("gear pair defaults", "mesh", Selection("mesh|stiffness"),
                    "mesh: this command's gear-pair scene defaults (sector rims, sizes from the "
                    "Hertz half-width); stiffness: the scene `gearstiff stiffness` solves (full "
                    "rims, three teeth per gear, its mesh sizes) for every one of those entries "
                    "left at this command's default: with Mesh/format = inp, the CalculiX deck of "
                    "the stiffness scene (docs/calculix.md)");
  prm.leave_subsection();
  declare_gear_pair_parameters(prm);
  declare_tooth_modification_parameters(prm);
  const geometry::GearPairSceneSpec gear;
  prm.enter_subsection("Gear pair scene");
  prm.declare_entry("position", "single", Selection("single|double|roll angle"),
                    "single: pitch point if in the single-contact zone (else its middle); double: "
                    "middle of the first double-contact zone; roll angle: see below");
  prm.declare_entry("pinion roll angle", "20", Double(),
                    "pinion roll angle ℓ/r_b1 of the reference pair, ℓ from T1 along the line of "
                    "action [deg]; must lie on the path of contact (position = roll angle)");
  prm.leave_subsection();
  // The mesh only names the sector cut faces; the analysis that uses it chooses their support.
  declare_gear_scene_parameters(prm, gear, false);
  prm.enter_subsection("Gear pair scene");
  prm.declare_entry("both flanks", "false", Bool(),
                    "also mark the unloaded flanks as candidate contact surfaces");
  prm.declare_entry("pinion torque", "49.4", Double(0.),
                    "pinion torque T1 for the Hertz estimate of the contact size [N·m] "
                    "(docs/references.md §1: 7.5 kW at 1450 rpm)");
  declare_elastic_constants(prm, "both gears");
  prm.leave_subsection();
}

class GearPairMeshScene : public Scene
{
public:
  explicit GearPairMeshScene(const geometry::GearPairSceneSpec& spec) : spec(spec) {}

  geometry::SceneInfo write_mesh(const std::string& path) override
  {
    scene = with_parameter_names(gear_scene_parameter_names(),
                                 [&] { return geometry::write_gear_pair_scene(spec, path); });
    return scene.info;
  }

  geometry::AbaqusDeckSpec deck_spec(const geometry::SceneInfo& /*info*/,
                                     const DeckOptions& options) const override
  {
    return geometry::gear_pair_deck_spec(spec, scene, options.friction, options.penalty_factor);
  }

  void report(const geometry::SceneInfo& info, Report& report) const override
  {
    if (!derived.empty())
      report.add_text("derived sizes", kinematics::derived_sizes_text(derived));
    // What k = T1/(r_b1²·Δφ) needs from a solver's rotation of this scene's deck
    // (tools/calculix_stiffness.py).
    const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
    report.add_value("pinion_base_radius", 0.5 * pair.pinion.base_diameter / mm, "mm",
                     "r_b1, pinion base radius");
    report.add_value("pinion_torque", spec.pinion_torque, "N·m",
                     "T1, the torque on the pinion (the deck's load)");
    if (info.contacts.size() == 2)
      report.add_compared_value(
          "contact_spacing", (info.contacts[1].point - info.contacts[0].point).norm() / mm, 7.380,
          "mm", "distance between the two contacts (transverse base pitch p_et)",
          split_path_source);
  }

  std::vector<kinematics::DerivedSize> derived; // sizes the parameters left `auto`

private:
  geometry::GearPairSceneSpec spec;
  geometry::GearPairScene scene; // set by write_mesh
};

// Scene/gear pair defaults = stiffness: the entries of the scene that still hold this command's
// defaults take those of stiffness::default_stiffness_scene().
void apply_stiffness_scene_defaults(ParameterHandler& prm)
{
  const geometry::GearPairSceneSpec mesh_scene;
  const geometry::GearPairSceneSpec stiffness_scene = stiffness::default_stiffness_scene();
  const auto replace = [&](const std::string& key, const std::string& from, const std::string& to)
  {
    if (prm.get(key) == from)
      prm.set(key, to);
  };
  const auto rim_name = [](geometry::RimModel rim)
  { return std::string(rim == geometry::RimModel::full ? "full" : "sector"); };
  prm.enter_subsection("Gear pair scene");
  replace("rim", rim_name(mesh_scene.rim), rim_name(stiffness_scene.rim));
  prm.leave_subsection();
  // The teeth counts left `auto` start from the stiffness scene's in parse().
  // The cell sizes left `auto` take the stiffness scene's numbers in parse().
  prm.enter_subsection("Mesh");
  replace("growth rate", format_number(mesh_scene.mesh.growth_rate, 10),
          format_number(stiffness_scene.mesh.growth_rate, 10));
  prm.leave_subsection();
}

std::unique_ptr<Scene> parse(ParameterHandler& prm)
{
  prm.enter_subsection("Scene");
  const bool stiffness_scene = prm.get("gear pair defaults") == "stiffness";
  prm.leave_subsection();
  if (stiffness_scene)
    apply_stiffness_scene_defaults(prm);
  geometry::GearPairSceneSpec spec;
  if (stiffness_scene)
  {
    spec.pinion_teeth_modelled = stiffness::default_stiffness_scene().pinion_teeth_modelled;
    spec.wheel_teeth_modelled = stiffness::default_stiffness_scene().wheel_teeth_modelled;
  }
  std::vector<kinematics::DerivedSize> derived;
  spec.pair = parse_gear_pair_parameters(prm, derived);
  parse_gear_scene_parameters(prm, spec);
  spec.mesh = parse_scene_mesh_parameters(
      prm,
      gear_pair_mesh_defaults(stiffness_scene ? stiffness::default_stiffness_scene().mesh
                                              : geometry::GearPairSceneSpec().mesh,
                              spec.pair),
      mesh_module_scale(spec.pair), &derived);
  prm.enter_subsection("Gear pair scene");
  spec.position = geometry::parse_pair_position(prm.get("position"), "Gear pair scene/position");
  spec.pinion_roll_angle = prm.get_double("pinion roll angle") * degree;
  spec.both_flanks = prm.get_bool("both flanks");
  spec.pinion_torque = prm.get_double("pinion torque");
  parse_elastic_constants(prm, spec.young_modulus, spec.poisson_ratio);
  prm.leave_subsection();
  // The micro-geometry, built into the outlines (and so into the CalculiX deck).
  const PairModificationText modifications = read_tooth_modification_text(prm);
  spec.pinion_modifications =
      parse_gear_modifications(modifications.pinion, false, spec.mesh.dimension);
  spec.wheel_modifications =
      parse_gear_modifications(modifications.wheel, true, spec.mesh.dimension);
  geometry::check_tooth_modifications(spec);
  auto scene = std::make_unique<GearPairMeshScene>(spec);
  scene->derived = derived;
  return scene;
}

const SceneRegistration registration(
    {"gear pair", "a spur gear pair at one position (subsections Gear pair, Gear pair scene)",
     declare_parameters, parse});
} // namespace
