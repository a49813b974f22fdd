// Scene type "gear pair" of `gearstiff mesh`: a spur pair at one position, the teeth around the
// predicted contacts (geometry/scene_gear_pair.h). Subsections Gear pair, Gear pair scene.
#include "geometry/scene_gear_pair.h"

#include "app/geometry_parameters.h"
#include "app/kinematics_parameters.h"
#include "app/parameter_patterns.h"
#include "app/scene.h"
#include "app/units.h"

namespace
{
using namespace gearstiff;
using namespace gearstiff::app;

const std::string split_path_source = "docs/references.md §1 (Reszuta & Drewniak 2015)";

void declare_parameters(ParameterHandler& prm)
{
  declare_gear_pair_parameters(prm);
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
    if (info.contacts.size() == 2)
      report.add_compared_value(
          "contact_spacing", (info.contacts[1].point - info.contacts[0].point).norm() / mm, 7.380,
          "mm", "distance between the two contacts (transverse base pitch p_et)",
          split_path_source);
  }

private:
  geometry::GearPairSceneSpec spec;
  geometry::GearPairScene scene; // set by write_mesh
};

std::unique_ptr<Scene> parse(ParameterHandler& prm)
{
  geometry::GearPairSceneSpec spec;
  spec.pair = parse_gear_pair_parameters(prm);
  parse_gear_scene_parameters(prm, spec);
  spec.mesh = parse_scene_mesh_parameters(prm);
  prm.enter_subsection("Gear pair scene");
  spec.position = geometry::parse_pair_position(prm.get("position"), "Gear pair scene/position");
  spec.pinion_roll_angle = prm.get_double("pinion roll angle") * degree;
  spec.both_flanks = prm.get_bool("both flanks");
  spec.pinion_torque = prm.get_double("pinion torque");
  parse_elastic_constants(prm, spec.young_modulus, spec.poisson_ratio);
  prm.leave_subsection();
  return std::make_unique<GearPairMeshScene>(spec);
}

const SceneRegistration registration(
    {"gear pair", "a spur gear pair at one position (subsections Gear pair, Gear pair scene)",
     declare_parameters, parse});
} // namespace
