// Speed sweep of the planar lateral–torsional stage (issue 30): the time response of
// lateral_response.h at each input speed, its steady-state window summarised — dynamic factor
// K_v = F/F_static of the meshes, largest bearing forces and orbit amplitudes of sun, ring and
// carrier — up, down or both, with continuation (each speed starts from the previous speed's
// final state and mesh position) as the rotational sweep of simulation.h does; its status names
// and steadiness tolerance are simulation.h's.
#pragma once

#include "dynamics/lateral_response.h"
#include "dynamics/simulation.h"

#include <functional>
#include <string>
#include <vector>

namespace gearstiff::dynamics
{
// Rigid-body mesh frequency and carrier speed at an input speed, and the phase rule of one
// planet's ring mesh against its sun mesh (Parker & Lin 2004, dynamics/README.md): the ring mesh
// runs ε_f,r − ε_f,s + (z_p + 1)/2 base pitches (mod 1) after the sun mesh, ε_f the approach
// ratio of each mesh for the gear that drives in the carrier frame (docs/references.md §7).
// [base pitches] in [0, 1).
double planet_ring_mesh_offset(int planet_teeth, double sun_approach_ratio,
                               double ring_approach_ratio);

struct LateralSweepSettings
{
  // [rad/s] the input speed of the stage's description, whose mesh frequency and carrier speed
  // `excitation` and `carrier_speed` hold; every sweep speed scales them.
  double nominal_input_speed = 0.;
  double nominal_carrier_speed = 0.;       // [rad/s]
  std::vector<double> input_speeds;        // [rad/s] in the order of `direction` up
  unsigned int steps_per_mesh_period = 40; // [-] the step is reduced to keep at least these
  SweepDirection direction = SweepDirection::up;
  bool continuation = false;
  unsigned int window_periods = 40; // [-] mesh periods in the steady-state window
  double settle_time = -1.;         // [s] before the window; < 0: lateral_decay_time
};

struct LateralSweepPoint
{
  double input_speed = 0.;    // [rad/s]
  double carrier_speed = 0.;  // [rad/s]
  double mesh_frequency = 0.; // [Hz]
  double time_step = 0.;      // [s]
  bool descending = false;
  SweepStatus status = SweepStatus::valid;
  std::string failure; // diverged: the SolverFailure message; the numbers below are NaN
  LateralWindowSummary summary;
  unsigned long steps = 0;
};

struct LateralSweepResult
{
  std::vector<LateralSweepPoint> points;
  double wall_time = 0.;   // [s]
  double settle_time = 0.; // [s] used before each window
};

// What a sweep will integrate, known before it starts: RK4 steps of every run (each speed at its
// own step, both directions counted) and the settle time before each window [s]. Throws
// InputError when the slowest mode never decays or the steps exceed 2e8.
struct LateralSweepWork
{
  double steps = 0.;       // [-]
  double settle_time = 0.; // [s]
};
LateralSweepWork lateral_sweep_work(const LateralModel& model,
                                    const LateralMeshExcitation& excitation,
                                    const LateralRunSettings& run,
                                    const LateralSweepSettings& sweep);

// `progress` (may be empty) is called after each speed with a line of text. A diverged speed
// is recorded and the sweep goes on (continuation restarts from the static state); bad input
// throws.
LateralSweepResult lateral_speed_sweep(const LateralModel& model, const LateralStaticLoad& load,
                                       const LateralMeshExcitation& excitation,
                                       const LateralRunSettings& run,
                                       const LateralSweepSettings& sweep,
                                       const std::function<void(const std::string&)>& progress);
} // namespace gearstiff::dynamics
