// The k(θ) sweep of the influence-coefficient contact model (Stiffness/contact model =
// influence coefficients, docs/ltca.md): one FE model of both gears whose flank cells are sized
// for bending, not for the Hertz zone, factored once; the influence coefficients of a grid on
// every flank that meshes in the sweep, read at a matching depth under the flank; the analytic
// plane-strain Hertz layer above that depth (stiffness/ltca_contact.h); at each position and
// torque a complementarity problem of a few unknowns. Same results as the exact sweep
// (stiffness/mesh_stiffness_sweep.h); the root stresses from the FE body's fillets under the
// solved loads in 2D, NaN in 3D (docs/ltca.md "Root stress").
//
//   settings.contact_model = ContactModel::influence_coefficients;
//   StiffnessSweepResult r = influence_sweep<2>(MPI_COMM_WORLD, settings, spec, "/tmp/scene");
#pragma once

#include "stiffness/mesh_stiffness_sweep.h"

#include <functional>
#include <mpi.h>
#include <string>

namespace gearstiff::stiffness
{
// Rank 0 computes, every rank receives every position. InputError (naming the field of
// stiffness_parameter or geometry::scene_field) for what the model cannot carry: a helical pair
// or a crowned internal pair in 3D, tooth faults, a grid too coarse for the path or a
// modification, a position off the grid; SolverFailure when the FE or a contact problem fails.
// `scene_file_stem` gets "_influence.msh" appended (removed afterwards).
template <int dim>
StiffnessSweepResult
influence_sweep(MPI_Comm mpi_communicator, const GearMeshStiffnessSettings& settings,
                const StiffnessSweepSpec& spec, const std::string& scene_file_stem,
                const std::function<void(const std::string&)>& progress = {});

// The checks influence_sweep makes before anything is meshed (InputError naming the field).
void check_influence_settings(const GearMeshStiffnessSettings& settings);

// -, the fewest layers check_influence_settings accepts for this scene's face (a helical face's
// node planes at most 0.74·m_n apart; 16 with lead crowning on either gear), 1 where it asks for
// none. `Mesh/layers = auto` takes at least this many with this model.
unsigned int influence_least_layers(const GearMeshStiffnessSettings& settings);
} // namespace gearstiff::stiffness
