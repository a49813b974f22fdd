// The "Cycloid disc" (the ring, app/scenes/geometry_parameters.h) and "Cycloid scene" subsections —
// bore, output pins and holes, roller pins, disc width, contact clearance, outline resolution (mm
// and counts in the file, SI in geometry::CycloidSceneSpec) — declared and parsed once for every
// command that builds a cycloid scene: `gearstiff mesh` (Scene/type = cycloid) and `gearstiff
// cycloid-loads`. A command adds its own entries to the same subsection after calling
// declare_cycloid_scene_parameters.
#pragma once

#include "geometry/scene_cycloid.h"

#include <deal.II/base/parameter_handler.h>

namespace gearstiff::app
{
// Entries with the defaults of `defaults` (SI; the ring's defaults are docs/references.md §4).
void declare_cycloid_scene_parameters(dealii::ParameterHandler& prm,
                                      const geometry::CycloidSceneSpec& defaults);
// Sets the ring and the declared members of `spec` (SI); leaves the others as they are.
void parse_cycloid_scene_parameters(dealii::ParameterHandler& prm,
                                    geometry::CycloidSceneSpec& spec);
} // namespace gearstiff::app
