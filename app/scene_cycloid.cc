// Scene type "cycloid" of `gearstiff mesh`: a cycloid disc with its rollers and, for a deck, its
// output pins (geometry/scene_cycloid.h). Subsections Cycloid disc, Cycloid scene.
#include "geometry/scene_cycloid.h"

#include "app/cycloid_scene_parameters.h"
#include "app/geometry_parameters.h"
#include "app/parameter_patterns.h"
#include "app/scene.h"
#include "app/units.h"

namespace
{
using namespace gearstiff;
using namespace gearstiff::app;

void declare_parameters(ParameterHandler& prm)
{
  // The common entries, then this command's own: the disc's position and the Hertz estimate.
  declare_cycloid_scene_parameters(prm, geometry::CycloidSceneSpec());
  prm.enter_subsection("Cycloid scene");
  prm.declare_entry("disc rotation", "0", Double(-360., 360.),
                    "disc rotation ψ about its own centre (degrees); the disc centre follows "
                    "the eccentric with the ring fixed");
  prm.declare_entry("roller force", "1711", Double(0.),
                    "roller force for the Hertz estimate of h_c (N; docs/references.md §4 P_max)");
  declare_elastic_constants(prm, "the disc and the rollers");
  prm.leave_subsection();
}

class CycloidMeshScene : public Scene
{
public:
  explicit CycloidMeshScene(const geometry::CycloidSceneSpec& spec) : spec(spec) {}

  // The cycloid deck ties the output pins to the output member: mesh them in their holes.
  void prepare_for_deck() override { spec.output_pin_bodies = true; }

  geometry::SceneInfo write_mesh(const std::string& path) override
  {
    return geometry::write_cycloid_scene(spec, path);
  }

  geometry::AbaqusDeckSpec deck_spec(const geometry::SceneInfo& info,
                                     const DeckOptions& options) const override
  {
    return geometry::cycloid_deck_spec(spec, info, options.output_torque, options.penalty_factor);
  }

private:
  geometry::CycloidSceneSpec spec;
};

std::unique_ptr<Scene> parse(ParameterHandler& prm)
{
  geometry::CycloidSceneSpec spec;
  parse_cycloid_scene_parameters(prm, spec);
  prm.enter_subsection("Cycloid scene");
  spec.disc_rotation = prm.get_double("disc rotation") * degree;
  spec.roller_force = prm.get_double("roller force");
  parse_elastic_constants(prm, spec.young_modulus, spec.poisson_ratio);
  prm.leave_subsection();
  spec.mesh = parse_scene_mesh_parameters(prm);
  return std::make_unique<CycloidMeshScene>(spec);
}

const SceneRegistration
    registration({"cycloid", "a cycloid disc with its rollers (Cycloid disc, Cycloid scene)",
                  declare_parameters, parse});
} // namespace
