// Two parallel cylinders in line contact: the Hertz verification scene of the contact module
// (Johnson, Contact Mechanics, 1985, §4.3). Cylinder 1 (first body) lies below the origin, centre
// (0, −R1); cylinder 2 (second body) above, centre (0, R2); they touch at the origin with the
// normal +y. Without a bore a cylinder is the half-disc on the contact side, its flat face
// through the centre (ids 5 and 6) carrying the support or the load; with a bore it is a full
// annulus (bore ids 1 and 2). Curved surfaces: candidate contact ids 3 and 4.
#pragma once

#include "geometry/scene_common.h"

#include <string>

namespace gearstiff::geometry
{
struct CylindersSceneSpec
{
  double radius_1 = 10e-3;       // m, R1
  double radius_2 = 10e-3;       // m, R2
  double bore_radius_1 = 0.;     // m; 0: half-disc with a flat face
  double bore_radius_2 = 0.;     // m; 0: half-disc with a flat face
  double force_per_length = 1e5; // N/m, line load for the Hertz estimate of h_c
  double length = 10e-3;         // m, cylinder length (3D extrusion)
  double young_modulus = 210e9;  // Pa, both cylinders
  double poisson_ratio = 0.3;    // -, both cylinders
  SceneMeshSettings mesh;
};

// Checks the spec (InputError naming "Cylinders/..." before gmsh runs), meshes, writes `file`.
SceneInfo write_cylinders_scene(const CylindersSceneSpec& spec, const std::string& file);
} // namespace gearstiff::geometry
