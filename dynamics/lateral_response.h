// Time response of the planar lateral–torsional stage (lateral_model.h): classical RK4 at a
// fixed step on M·q̈ + C·q̇ + K(t)·q = f, with each planet's sun and ring meshes following their
// own k(x) (constant, Cai, table or FE: mesh_stiffness.h) at their own phase, the bearings,
// pins and supports constant. The stage carries the static load (input torque on the input,
// the balancing load on the output) and its pin errors; it starts from the static deflection
// under mean stiffness (or at rest) so that what follows is the mesh-stiffness excitation.
// Outputs: the central members' orbits (x, y) and bearing forces, the mesh forces.
#pragma once

#include "dynamics/lateral_model.h"
#include "dynamics/mesh_stiffness.h"

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
};

struct LateralRunSettings
{
  double time_step = 1e-6;         // [s] RK4
  double end_time = 0.01;          // [s]
  unsigned int record_stride = 10; // keep every n-th step
  bool start_static = true;        // start from the static deflection (else at rest)
  bool allow_unstable_step = false;
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
};

// InputError("Simulation/time step") above the RK4 stability limit unless allowed;
// SolverFailure("RK4") when the state turns non-finite.
LateralResponse integrate_lateral(const LateralModel& model, const LateralStaticLoad& load,
                                  const LateralMeshExcitation& excitation,
                                  const LateralRunSettings& settings);
} // namespace gearstiff::dynamics
