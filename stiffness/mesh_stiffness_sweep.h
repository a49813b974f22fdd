// Mesh stiffness over the mesh cycle: GearMeshStiffness at N pinion positions spread over one or
// more transverse base pitches, distributed over the MPI ranks (each rank solves its share of
// positions serially on MPI_COMM_SELF with its own scene file; every rank receives all results),
// and a discretization study by uniform scaling of the scene's mesh sizes with a Richardson
// estimate of the converged value.
#pragma once

#include "stiffness/mesh_stiffness.h"

#include <functional>
#include <mpi.h>
#include <string>
#include <utility>
#include <vector>

namespace gearstiff::stiffness
{
// How a sweep meshes its positions.
enum class SweepMesh
{
  per_position, // a new scene, mesh and factorization at every position (the reference)
  once          // one scene and factorization per rank, the bodies turned rigidly to each position
};

struct StiffnessSweepSpec
{
  // m, first position of the reference pair along the line of action (from T1); negative:
  // the start of active contact A.
  double start_position = -1.;
  double base_pitches = 1.;    // -, span of the sweep in transverse base pitches (> 0)
  unsigned int positions = 32; // -, N: positions at start + (i + 1/2)·span·p_bt/N, i < N
  SweepMesh mesh = SweepMesh::per_position;
};

// What the influence-coefficient model used and where its time went.
struct InfluenceModelInfo
{
  unsigned int grid_points = 0;   // -, G per flank over the path of contact
  unsigned int flanks = 0;        // -, flanks with a grid (both gears)
  double grid_step = 0.;          // m, along the line of action
  double flank_cell_size = 0.;    // m, h_f of the FE body at the flanks
  double matching_depth = 0.;     // m, h: FE below, analytic Hertz layer above
  unsigned int n_dofs = 0;        // -, of the FE body model
  double scene_time = 0.;         // s, wall: geometry and meshing
  double factorization_time = 0.; // s, wall: set-up of K and its factorization
  double coefficient_time = 0.;   // s, wall: the back-substitutions for the coefficients
  double contact_time = 0.;       // s, wall: every position's contact problem (all torques)
  unsigned int newton_steps = 0;  // -, summed over positions and torques

  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    archive& grid_points& flanks& grid_step& flank_cell_size& matching_depth& n_dofs& scene_time&
        factorization_time& coefficient_time& contact_time& newton_steps;
  }
};

struct StiffnessSweepResult
{
  std::vector<GearMeshStiffnessResult> positions; // in sweep order, complete on every rank
  // With settings.torques: [torque][position], positions = the first torque's (else empty).
  std::vector<double> torques; // N·m
  std::vector<std::vector<GearMeshStiffnessResult>> by_torque;
  std::vector<unsigned int> rank_of_position; // -, rank that solved each position
  unsigned int n_ranks = 1;
  double wall_time = 0.; // s, the whole sweep (slowest rank)
  SweepMesh mesh = SweepMesh::per_position;
  // s, wall, summed over the ranks (`once`: each rank meshes and factorizes once): what was
  // done once — meshing, set-up (DoFs, K) and the factorization —, and per position: turning,
  // pairing, contact solve, evaluation (per position: everything).
  double once_time = 0.;
  double per_position_time = 0.;
  // The contact model that ran and, for influence coefficients, its grid and FE body
  // (docs/ltca.md); zeros for the finite-element model.
  ContactModel contact_model = ContactModel::finite_element;
  InfluenceModelInfo influence;
};

// Whether a rolling sweep (SweepMesh::once) holds for `settings` and the further modification
// sets `variants` (each a pinion and a wheel set): where it has shown the accuracy of per position
// (2D) and can run — the Schur complement with the direct solver, and every flank whole: no tooth
// faults, or root cracks only (test_fault_stiffness CrackedSweepOnceMatchesPerPosition). A
// broken, chipped or spalled tooth changes which pairs carry from one position to the next: meshed
// per position. The rule of `Stiffness/sweep mesh = automatic`.
bool once_sweep_valid(
    const GearMeshStiffnessSettings& settings,
    const std::vector<std::pair<geometry::GearModifications, geometry::GearModifications>>&
        variants);

// Reference-pair positions (m from T1) of the sweep; InputError for zero positions, a
// non-positive span or a start outside the path of contact.
std::vector<double> sweep_positions(const kinematics::GearPairGeometry& pair,
                                    const StiffnessSweepSpec& spec);

// Solves every position (scene "roll angle"). `scene_file_stem` gets "_<position>.msh"
// appended (one file per position, removed after its solve). With settings.output_directory
// set, each position writes VTU as "<output_base>_<position>". `progress` (may be empty) is
// called on rank 0 after each of its positions with a one-line message. A position that fails
// stops the sweep on every rank with that position's exception (InputError or SolverFailure).
// The finite-element contact model only (InputError for influence coefficients: those run
// through stiffness/influence_sweep.h, the caller picks).
template <int dim>
StiffnessSweepResult
stiffness_sweep(MPI_Comm mpi_communicator, const GearMeshStiffnessSettings& settings,
                const StiffnessSweepSpec& spec, const std::string& scene_file_stem,
                const std::function<void(const std::string&)>& progress = {});

// One position solved serially on rank 0 of `mpi_communicator` (MPI_COMM_SELF), its result
// broadcast to every rank, its exception (InputError or SolverFailure) thrown on every rank.
// Used where a distributed solve of a 2D position would save little: one position of the
// default scene solves in seconds on one core.
template <int dim>
GearMeshStiffnessResult solve_on_first_rank(MPI_Comm mpi_communicator,
                                            const GearMeshStiffnessSettings& settings);

// The scene's size field multiplied by `factor` everywhere: contact, body and rim sizes and
// the growth rate scale, the fine radius (a region, not a size) stays. The contact size and
// rim size must be explicit (InputError otherwise): an automatic size would follow the load.
geometry::SceneMeshSettings scaled_mesh(const geometry::SceneMeshSettings& mesh, double factor);

// A refinement study: one value per level, each level's sizes halved.
struct RefinementLevel
{
  double size_factor = 1.; // -, sizes relative to the base mesh
  double stiffness = 0.;   // N/m
  unsigned int n_dofs = 0;
  double wall_time = 0.; // s
};

struct RichardsonEstimate
{
  double extrapolated = 0.;   // N/m, k at h → 0
  double observed_order = 0.; // -, p from the three finest levels
  double error_finest = 0.;   // -, |k_finest − k_extrapolated| / k_extrapolated
  bool monotone = false;      // the three differences have one sign (asymptotic range)
};

// From three or more levels with size ratio 2 (coarse to fine). The order comes from the
// three finest; SolverFailure when the differences change sign (not in the asymptotic
// range: no trustworthy extrapolation exists).
RichardsonEstimate richardson_estimate(const std::vector<RefinementLevel>& levels);
} // namespace gearstiff::stiffness
