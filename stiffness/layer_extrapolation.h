// Richardson extrapolation of a 3D analysis in the layer height (Mesh/layer extrapolation,
// docs/helical.md "Layer extrapolation"). A helical face is meshed in layers of height Δz; the
// contact between them carries an error that falls as Δz² (the chords between the layers' helices
// sag inside the helicoids by r·Δφ²/8; the dual mortar's weighted gap where a contact line crosses
// a face diagonally: bench/helical_layers_2026-12-03.txt). Solved on L and on 2L layers with
// everything else equal, the O(Δz²) term cancels:
//
//     x∞ = x(2L) + (x(2L) − x(L)) / 3
//
// for every value the layers' error enters linearly: the pinion rotation Δφ (and so k = T1/(r_b1²·
// Δφ∞) and TE = r_b1·Δφ∞ + the unloaded TE), each pair's normal force, load share and resultant,
// the forces and moments of the mesh on the gears. What is local to the mesh (pressures, line
// loads and K_Hβ, root stresses, closed zones) is the 2L solve's: a field is not extrapolated from
// two meshes' nodes. On the built-in pair (β ±15°, 13/26 layers, ten positions) the limits from the
// two flank geometries, whose errors have opposite signs, agree to 0.07 % at every position.
#pragma once

#include "stiffness/mesh_stiffness.h"
#include "stiffness/mesh_stiffness_sweep.h"

namespace gearstiff::stiffness
{
// -, the largest Richardson correction |Δφ∞ − Δφ(2L)|/Δφ∞ that is returned. The L solve is then
// 4 × 5 % = 20 % from its limit, where the terms beyond Δz² (of the order of its square, 4 %)
// are no longer small against the 1 % the extrapolation is for: the two levels are not in the
// asymptotic range, and the extrapolation fails (SolverFailure) instead of returning a number.
// Measured: 0.8 % on the built-in pair at 13/26 layers (bench/helical_layers_2026-12-03.txt).
inline constexpr double max_layer_correction = 0.05;

// The extrapolated result of one position from its solves on `coarse_layers` (L) and 2L layers.
// SolverFailure when the two model different tooth pairs or positions (not one analysis on two
// meshes) or the correction exceeds max_layer_correction.
GearMeshStiffnessResult extrapolate_layers(const GearMeshStiffnessResult& coarse,
                                           const GearMeshStiffnessResult& fine,
                                           unsigned int coarse_layers);
// Every position (and every torque of a torque list) of two sweeps of the same positions; the
// costs are summed, everything else is the 2L sweep's.
StiffnessSweepResult extrapolate_layers(const StiffnessSweepResult& coarse,
                                        const StiffnessSweepResult& fine,
                                        unsigned int coarse_layers);
} // namespace gearstiff::stiffness
