// What the influence-coefficient model refuses (docs/ltca.md, limits), before and after its
// solve: check_influence_settings (stiffness/influence_sweep.h) for the settings, these two for
// what only the run knows. Each throws InputError naming the parameter, never returns a number
// outside what the model is verified on. Internal to stiffness/.
#pragma once

#include "stiffness/influence_geometry.h"
#include "stiffness/mesh_stiffness.h"

#include <string>
#include <vector>

namespace gearstiff::stiffness::influence
{
// The grid step (m) must follow the gap's kinks and the near field's depth (m).
void check_grid_step(double step, double depth, const PairSeparation& separation);

// An uncrowned 3D face's node planes, Δz = stations.layer apart, must not be closer than the end
// faces' layer is verified on, in matching depths `depth` (m) (exit 2 naming Mesh/layers).
void check_end_plane_spacing(const GearMeshStiffnessSettings& settings,
                             const FaceStations& stations, double depth);

// A crowned or sloped lead's contact ending inside the face must load enough node planes
// (influence_checks.cc) of `layers` layers at every position and torque of `by_torque` (exit 2
// naming Mesh/layers); `contact` names it in the message ("crowned contact", …).
void check_crowned_contact_planes(
    const std::vector<std::vector<GearMeshStiffnessResult>>& by_torque,
    const FaceStations& stations, unsigned int layers, const std::string& contact);
} // namespace gearstiff::stiffness::influence
