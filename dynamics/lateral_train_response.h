// Time response and speed sweep of the multi-stage lateral–torsional model (lateral_train.h):
// classical RK4 at a fixed step on M·q̈ + C·q̇ + K(t)·q = f, every mesh line following the k(x)
// of its rotational counterpart (train_model.h: constant, Cai, table or FE, reversed where the
// other gear drives) at that mesh's frequency and phase, bearings, pins and supports constant;
// the linear mesh law (negative forces allowed, flagged as contact loss). The train carries the
// input torque and the balancing output load and starts from its static deflection under mean
// stiffness. Outputs: per Train mesh the dynamic factor K_v = max F/F_static over its copies;
// per body the orbit amplitude ½·max(x range, y range) and the largest bearing force |k·r + c·ṙ|;
// the orbit of chosen bodies.
#pragma once

#include "dynamics/lateral_train.h"
#include "dynamics/lateral_train_build.h"

#include <vector>

namespace gearstiff::dynamics
{
struct LateralTrainRun
{
  double input_speed = 0.; // [rad/s] |ω_input|: mesh positions advance position_ratio·speed
  double time_step = 1e-5; // [s]
  double settle_time = 0.; // [s] before the window
  double window = 0.01;    // [s] the summary's span
  unsigned int record_stride = 0;            // record every n-th step of the window (0: none)
  std::vector<unsigned int> recorded_bodies; // bodies whose x, y are recorded
  bool allow_unstable_step = false;
};

struct LateralTrainSummary
{
  std::vector<double> kv_max; // [-] per Train mesh (largest over copies and window)
  double kv_first_half = 0., kv_second_half = 0.; // [-] largest over all meshes, window halves
  double mesh_force_min = 0.;        // [N] smallest over all mesh lines (< 0: contact loss)
  Eigen::VectorXd orbit_amplitude;   // [m] per body
  Eigen::VectorXd bearing_force_max; // [N] per body
};

struct LateralTrainResponse
{
  std::vector<double> time;              // [s] recorded instants
  std::vector<Eigen::VectorXd> position; // [m] x1, y1, x2, y2, ... of the recorded bodies
  LateralTrainSummary summary;
  double rk4_step_limit = 0.; // [s] 2√2/ω_max at the largest mesh stiffness
  unsigned long steps = 0;
  double wall_time = 0.; // [s]
};

// RK4 limit [s] of the model with every mesh at its largest stiffness.
double lateral_train_step_limit(const LateralTrainSetup& setup);
// [s] ln 1000/σ_min, σ = ½·φᵀCφ of the mass-normalised undamped modes (rigid ones skipped).
double lateral_train_decay_time(const LateralTrainModel& model);

// InputError("Simulation/time step") above the RK4 limit unless allowed; SolverFailure("RK4")
// for a non-finite state.
LateralTrainResponse integrate_lateral_train(const LateralTrainSetup& setup,
                                             const LateralTrainRun& run);

enum class LateralTrainStatus
{
  valid = 0,
  diverged = 1,
  contact_loss = 2,
  not_steady = 3
};

struct LateralTrainSweepPoint
{
  double input_speed = 0.; // [rad/s]
  double time_step = 0.;   // [s]
  LateralTrainStatus status = LateralTrainStatus::valid;
  LateralTrainSummary summary;
  unsigned long steps = 0;
};

// Speeds [rad/s]; each run settles for `settle_time` and spans `window_periods` periods of the
// slowest mesh, at `steps_per_period` steps of the fastest mesh period (capped at 0.9 of the RK4
// limit).
std::vector<LateralTrainSweepPoint>
lateral_train_sweep(const LateralTrainSetup& setup, const std::vector<double>& speeds,
                    double settle_time, unsigned int window_periods, unsigned int steps_per_period);
} // namespace gearstiff::dynamics
