// Report of the load across the face width of a 3D stiffness solve (issue 27,
// stiffness/face_load.h): K_Hβ and the peak line load with where it acts, the tables `face_load`
// (line load w(z) at every solved position) and `face_load_factor` (K_Hβ per position), and the
// contact-pattern chart (tools/plot_contact_pattern.py). Nothing in 2D.
#pragma once

#include "app/core/command.h"
#include "stiffness/mesh_stiffness.h"

#include <vector>

namespace gearstiff::app
{
void report_face_load(CommandContext& context,
                      const std::vector<stiffness::GearMeshStiffnessResult>& positions);
// The exact path's contact that ends inside the face on few node planes (a light load on crowned
// teeth): text `face resolution` with the fewest planes, where, and the layers that would give
// enough. Nothing when every loaded contact reaches an end of the face or spans enough planes.
void report_face_resolution(Report& report,
                            const std::vector<stiffness::GearMeshStiffnessResult>& positions,
                            unsigned int layers);
} // namespace gearstiff::app
