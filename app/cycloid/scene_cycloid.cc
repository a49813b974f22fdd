// Scene type "cycloid" of `gearstiff mesh`: a cycloid disc with its rollers and, for a deck, its
// output pins (geometry/scene_cycloid.h). Subsections Cycloid disc, Cycloid scene.
#include "geometry/scene_cycloid.h"

#include "app/core/parameter_patterns.h"
#include "app/core/units.h"
#include "app/cycloid/cycloid_scene_parameters.h"
#include "app/scenes/geometry_parameters.h"
#include "app/scenes/scene.h"
#include "errors/errors.h"
#include "geometry/abaqus_deck.h"
#include "stiffness/cycloid_analytic.h"

#include <cmath>
#include <cstdlib>

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
                    "disc rotation ψ about its own centre [deg]; the disc centre follows "
                    "the eccentric with the ring fixed");
  prm.declare_entry("roller force", "auto", Anything(),
                    "roller force for the Hertz estimate of automatic contact cells [N], or auto: "
                    "P_max and Q_max of the rigid-disc load model (stiffness/cycloid_analytic.h) "
                    "under Abaqus deck/output torque");
  declare_elastic_constants(prm, "the disc and the rollers");
  prm.leave_subsection();
}

geometry::AbaqusDeckSpec cycloid_deck(const geometry::CycloidSceneSpec& spec,
                                      const geometry::SceneInfo& info, const DeckOptions& options)
{
  return geometry::cycloid_deck_spec(spec, info, options.output_torque, options.penalty_factor);
}

class CycloidMeshScene : public SpecScene<geometry::CycloidSceneSpec>
{
public:
  explicit CycloidMeshScene(const geometry::CycloidSceneSpec& spec)
      : SpecScene(spec, geometry::write_cycloid_scene, cycloid_deck)
  {
  }

  // The cycloid deck ties the output pins to the output member: mesh them in their holes.
  void prepare_for_deck() override
  {
    spec.output_pin_bodies = true;
    geometry::check_cycloid_deck_play(spec); // before meshing, not after
  }
};

// The roller and pin forces the contact cells are sized for: given, or the case's own load as
// `cycloid-loads` sizes its cells (stiffness/cycloid_loads.cc), under the deck's output torque.
void set_sizing_forces(const std::string& roller_force, const double output_torque,
                       geometry::CycloidSceneSpec& spec)
{
  if (roller_force == "auto")
  {
    if (!(std::abs(output_torque) > 0.))
      throw InputError("Cycloid scene/roller force",
                       "auto estimates the forces under Abaqus deck/output torque, which is 0: "
                       "give a force (N) or a torque");
    stiffness::CycloidAnalyticResult estimate;
    try
    {
      estimate = stiffness::analytic_cycloid_loads(spec, output_torque);
    }
    catch (const SolverFailure&)
    {
      throw InputError("Cycloid scene/roller force",
                       "auto needs the rigid-disc load model, which cannot carry the torque with " +
                           std::to_string(spec.output_pins) +
                           " output pin(s): give the roller force (N)");
    }
    spec.roller_force = estimate.max_roller_force;
    spec.pin_force = estimate.max_pin_force;
    return;
  }
  char* end = nullptr;
  spec.roller_force = std::strtod(roller_force.c_str(), &end);
  if (end == roller_force.c_str() || *end != '\0' || !(spec.roller_force > 0.))
    throw InputError("Cycloid scene/roller force",
                     "'" + roller_force + "' is neither auto nor a positive force (N)");
}

std::unique_ptr<Scene> parse(ParameterHandler& prm)
{
  geometry::CycloidSceneSpec spec;
  parse_cycloid_scene_parameters(prm, spec);
  prm.enter_subsection("Cycloid scene");
  spec.disc_rotation = prm.get_double("disc rotation") * degree;
  const std::string roller_force = prm.get("roller force");
  parse_elastic_constants(prm, spec.young_modulus, spec.poisson_ratio);
  prm.leave_subsection();
  // `auto` sizes: the numbers the `mesh` command declares (a gear pair's at module 2.5 mm).
  spec.mesh = parse_scene_mesh_parameters(prm, geometry::GearPairSceneSpec().mesh);
  prm.enter_subsection("Abaqus deck");
  const double output_torque = prm.get_double("output torque");
  prm.leave_subsection();
  set_sizing_forces(roller_force, output_torque, spec);
  return std::make_unique<CycloidMeshScene>(spec);
}

const SceneRegistration
    registration({"cycloid", "a cycloid disc with its rollers (Cycloid disc, Cycloid scene)",
                  declare_parameters, parse});
} // namespace
