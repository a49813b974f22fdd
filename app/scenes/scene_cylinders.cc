// Scene type "cylinders" of `gearstiff mesh`: two cylinders in line contact, the Hertz
// verification case (geometry/scene_cylinders.h). Subsection Cylinders.
#include "geometry/scene_cylinders.h"

#include "app/core/parameter_patterns.h"
#include "app/core/units.h"
#include "app/scenes/geometry_parameters.h"
#include "app/scenes/scene.h"

namespace
{
using namespace gearstiff;
using namespace gearstiff::app;

void declare_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Cylinders");
  prm.declare_entry("radius 1", "10", Double(0.), "radius of the lower cylinder [mm]");
  prm.declare_entry("radius 2", "10", Double(0.), "radius of the upper cylinder [mm]");
  prm.declare_entry("bore radius 1", "0", Double(0.),
                    "bore of the lower cylinder [mm]; 0 = a half-disc whose flat face is the "
                    "support (boundary id 5)");
  prm.declare_entry("bore radius 2", "0", Double(0.),
                    "bore of the upper cylinder [mm]; 0 = half-disc");
  prm.declare_entry("force per length", "1e5", Double(0.),
                    "normal line load for the Hertz estimate [N/m]");
  prm.declare_entry("length", "10", Double(0.), "cylinder length (3D extrusion) [mm]");
  declare_elastic_constants(prm, "both cylinders");
  prm.leave_subsection();
}

geometry::AbaqusDeckSpec cylinders_deck(const geometry::CylindersSceneSpec& spec,
                                        const geometry::SceneInfo& info, const DeckOptions& options)
{
  return geometry::cylinders_deck_spec(spec, info, options.friction, options.penalty_factor);
}

std::unique_ptr<Scene> parse(ParameterHandler& prm)
{
  geometry::CylindersSceneSpec spec;
  prm.enter_subsection("Cylinders");
  spec.radius_1 = prm.get_double("radius 1") * mm;
  spec.radius_2 = prm.get_double("radius 2") * mm;
  spec.bore_radius_1 = prm.get_double("bore radius 1") * mm;
  spec.bore_radius_2 = prm.get_double("bore radius 2") * mm;
  spec.force_per_length = prm.get_double("force per length");
  spec.length = prm.get_double("length") * mm;
  parse_elastic_constants(prm, spec.young_modulus, spec.poisson_ratio);
  prm.leave_subsection();
  // `auto` sizes: the numbers the `mesh` command declares (a gear pair's at module 2.5 mm).
  spec.mesh = parse_scene_mesh_parameters(prm, geometry::GearPairSceneSpec().mesh);
  return std::make_unique<SpecScene<geometry::CylindersSceneSpec>>(
      spec, geometry::write_cylinders_scene, cylinders_deck);
}

const SceneRegistration registration({"cylinders", "two cylinders in line contact (Cylinders)",
                                      declare_parameters, parse});
} // namespace
