// Time response of the planar lateral–torsional stage (lateral_model.h): classical RK4 at a
// fixed step on M·q̈ + C·q̇ + K(t)·q = f, with each planet's sun and ring meshes following their
// own k(x) (constant, Cai, table or FE: mesh_stiffness.h) at their own phase, the bearings,
// pins and supports constant. The stage carries the static load (input torque on the input,
// the balancing load on the output) and its pin errors; it starts from the static deflection
// under mean stiffness (or at rest, or a given state) so that what follows is the mesh-stiffness
// excitation. With the nonlinear mesh law (nonlinear_mesh.h: unloaded TE e(x), free play,
// separation and back-flank contact) each mesh force is F = k(x)·h(δ − e) + c·(δ̇ − ė)·[contact];
// the switches are not located (the step resolves them: a sweep keeps ≥ 40 steps per mesh
// period). Outputs: the central members' orbits (x, y) and bearing forces, the mesh forces, and
// a summary over a window (largest forces, dynamic factor, orbit amplitudes, separations).
#pragma once

#include "dynamics/lateral_model.h"
#include "dynamics/mesh_stiffness.h"
#include "dynamics/nonlinear_mesh.h"

#include <optional>
#include <vector>

namespace gearstiff::dynamics
{
struct LateralMeshExcitation
{
  // k(x) of the sun–planet and ring–planet meshes [N/m]; false: constant at the stage's values.
  bool varying = false;
  MeshStiffness sun_mesh, ring_mesh;
  double sun_contact_ratio = 1.5, ring_contact_ratio = 1.5; // [-] ε_α
  double mesh_frequency = 0.; // [Hz] mesh positions advanced per second (carrier frame)
  // [base pitches] each planet's mesh position at t = 0 (empty: 0), sun and ring meshes.
  std::vector<double> sun_phase, ring_phase;
  // The nonlinear mesh law of the sun and ring meshes, the same for every planet (empty:
  // linear, F = k·δ + c·δ̇ with negative forces allowed).
  std::optional<NonlinearMesh> sun_nonlinear, ring_nonlinear;
};

struct LateralRunSettings
{
  double time_step = 1e-6;         // [s] RK4
  double end_time = 0.01;          // [s]
  unsigned int record_stride = 10; // keep every n-th step
  bool start_static = true;        // start from the static deflection (else at rest)
  bool allow_unstable_step = false;
  bool record = true;        // false: only the summary and the final state (speed sweeps)
  double window_start = -1.; // [s] the summary covers [window_start, end_time]; < 0: none
  double mesh_position = 0.; // [base pitches] added to every mesh's phase (a sweep's continuation)
  // Start from this state instead (a sweep's continuation) [m], [m/s] per free coordinate
  // (LateralModel::free_dofs()); empty: start_static.
  std::vector<double> initial_position, initial_velocity;
};

// Over the window (every step counted):
struct LateralWindowSummary
{
  double sun_mesh_force_max = 0.;  // [N] largest over the planets
  double ring_mesh_force_max = 0.; // [N]
  double mesh_force_min = 0.;      // [N] smallest over all meshes (< 0: teeth would separate)
  // Dynamic factor F/F_static (each mesh against its own static force), largest over all
  // meshes, over the whole window and over each half (their difference: not periodic yet).
  double kv_max = 0., kv_max_first_half = 0., kv_max_second_half = 0.; // [-]
  Eigen::Vector3d bearing_force_max = Eigen::Vector3d::Zero();         // [N] carrier, ring, sun
  // [m] orbit amplitude ½·max(x range, y range) of carrier, ring, sun (a circle's radius)
  Eigen::Vector3d orbit_amplitude = Eigen::Vector3d::Zero();
  double separation_fraction = 0.; // [-] nonlinear: share of mesh-steps out of drive contact
  unsigned long back_impacts = 0;  // [-] nonlinear: steps entering back-flank contact
};

struct LateralResponse
{
  std::vector<double> time;                               // [s] recorded instants
  std::vector<Eigen::Matrix<double, 3, 2>> position;      // [m] x, y of carrier, ring, sun
  std::vector<Eigen::Matrix<double, 3, 2>> bearing_force; // [N] on carrier, ring, sun
  std::vector<std::vector<double>> sun_mesh_force, ring_mesh_force; // [N] per planet
  double rk4_step_limit = 0.; // [s] 2√2/ω_max at the largest mesh stiffness
  unsigned long steps = 0;
  double wall_time = 0.; // [s]
  LateralWindowSummary summary;
  // The state at the end (free coordinates) and the mesh position reached [base pitches].
  std::vector<double> final_position, final_velocity;
  double final_mesh_position = 0.;
};

// InputError("Simulation/time step") above the RK4 stability limit unless allowed;
// SolverFailure("RK4") when the state turns non-finite.
LateralResponse integrate_lateral(const LateralModel& model, const LateralStaticLoad& load,
                                  const LateralMeshExcitation& excitation,
                                  const LateralRunSettings& settings);

// [s] time for the slowest damped mode to decay to 1/1000 (ln 1000/σ_min, σ = ½·φᵀCφ of the
// mass-normalised undamped modes at mean stiffness; infinite without damping).
double lateral_decay_time(const LateralModel& model);
} // namespace gearstiff::dynamics
