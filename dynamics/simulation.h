// A dynamic run of a gear train and what it yields: mesh forces, the dynamic factor
// K_v(t) = F(t)/F_nominal (docs/references.md §1: K_v = F_c/F_cn), K_v max over a steady-state
// window, the mesh-force spectrum, and a speed sweep (K_v max against input speed).
//
// Results depend on the start (from rest or from the static deflection), on the mesh phase and
// on whether the start-up transient is included, so each result carries the window, phase and
// start it was computed with. The steady-state window starts, unless given, after the slowest
// vibration mode has decayed to 1/1000 (ln 1000 / smallest modal decay rate at mean stiffness)
// and is then trimmed to a whole number of periods of mesh 1 (of a revolution, for a
// whole-revolution stiffness table: excitation_period).
#pragma once

#include "dynamics/integrators.h"

#include <functional>
#include <string>
#include <vector>

namespace gearstiff::dynamics
{
enum class StartState
{
  rest,             // no deflection, no vibration: the torques are applied suddenly at t = 0
  static_deflection // static deflection under mean stiffness, no vibration
};

std::string start_state_name(StartState start);

struct SimulationSettings
{
  IntegratorSettings integrator; // its end_time is replaced when end_time below is automatic
  StartState start = StartState::static_deflection;
  double steady_state_start = -1.;    // [s] window start; negative: automatic (decay)
  double end_time = 0.;               // [s] 0: automatic, window start + window periods
  unsigned int window_periods = 40;   // [-] length of the automatic window in mesh periods
  double max_spectrum_frequency = 0.; // [Hz] spectrum up to here; 0: 1.5 × highest mode
  bool keep_time_series = true;       // false: only the summary (speed sweeps)
  // [s] spacing of the stored trajectory and time series; 0: every output point. K_v, the mean
  // force and the spectrum always use every step.
  double record_interval = 0.;
  // Start from this state instead of `start` (a sweep's continuation: the previous speed's
  // final state) [rad], [rad/s] per DOF; empty: `start`.
  std::vector<double> initial_angle, initial_velocity;
  // Nonlinear meshes: keep the DTE spectrum up to this many mesh orders even without time
  // series (a sweep's waterfall); 0: only with time series.
  double dte_spectrum_orders = 0.;
};

struct MeshResult
{
  std::string name;
  double nominal_force = 0.;    // [N]
  double mesh_frequency = 0.;   // [Hz]
  double initial_position = 0.; // [base pitches] the mesh phase at t = 0
  // Time series at the output times (empty when keep_time_series is false).
  std::vector<double> force;      // [N]
  std::vector<double> stiffness;  // [N/m]
  std::vector<double> deflection; // [m]
  // Over the steady-state window:
  double kv_max = 0.;             // [-] largest F/F_nominal
  double kv_max_time = 0.;        // [s] where it occurs
  double kv_min = 0.;             // [-] smallest F/F_nominal (negative: the teeth would separate,
                                  //     which this linear model does not represent)
  double mean_force = 0.;         // [N]
  double kv_max_first_half = 0.;  // [-] K_v max over each half of the window: their
  double kv_max_second_half = 0.; //     difference shows whether the response is periodic
  std::vector<double> spectrum_frequency; // [Hz]
  std::vector<double> spectrum_amplitude; // [N] single-sided amplitude of F
  // Dynamic transmission error δ (the deflection along the line of action) over the window:
  double mean_deflection = 0.; // [m]
  double deflection_rms = 0.;  // [m] about its mean
  // Nonlinear meshes (nonlinear_mesh.h), over the window:
  bool nonlinear = false;
  double separation_fraction = 0.; // [-] share of the output steps not in drive contact
  unsigned long separations = 0;   // [-] drive contact lost (located switches)
  unsigned long back_impacts = 0;  // [-] back flank struck
  // DTE spectrum (same frequencies as the force spectrum, or up to dte_spectrum_orders)
  std::vector<double> dte_spectrum_frequency; // [Hz]
  std::vector<double> dte_spectrum_amplitude; // [m]
};

struct SimulationResult
{
  Trajectory trajectory;
  std::vector<MeshResult> meshes;
  StartState start = StartState::static_deflection;
  // [s] the step used: the given one, or, with a whole-revolution table, shortened to divide
  // the mesh period of mesh 1 (and the revolution) into whole steps
  double time_step = 0.;
  double window_start = 0.; // [s]
  double window_end = 0.;   // [s]
  bool window_automatic = true;
  double decay_time = 0.; // [s] ln(1000)/slowest decay rate (inf without damping)
  ModalProperties modes;
  double kv_max = 0.;                // [-] largest over all meshes
  std::vector<double> initial_angle; // [rad]
  // The state at the end (a sweep continues from it): time [s], angles [rad], speeds [rad/s].
  double final_time = 0.;
  std::vector<double> final_angle, final_velocity;
};

SimulationResult simulate(const TorsionalModel& model, const SimulationSettings& settings);

// [s] the period the steady-state window is made of: mesh 1's mesh period, or, when a mesh runs
// a whole-revolution table (period P base pitches, docs/faults.md), the longest P/f_mesh over
// those meshes; the automatic window is then rounded up to whole such periods.
double excitation_period(const TorsionalModel& model);

// Whether a sweep point has a K_v at all. Only `valid` points carry one: a diverged run has
// none, a run whose mesh force turns negative (teeth would separate) is outside the linear
// model, and a run whose two window halves differ has not reached a steady state.
enum class SweepStatus
{
  valid,
  diverged,
  contact_loss,
  not_steady
};
std::string sweep_status_name(SweepStatus status);
// |K_v max(first half) − K_v max(second half)| above this fraction of K_v max: not steady.
constexpr double steady_state_tolerance = 0.05;

struct SweepPoint
{
  double input_speed = 0.;    // [rad/s]
  double mesh_frequency = 0.; // [Hz] of mesh 1
  double time_step = 0.;      // [s] used
  double kv_max = 0.;         // [-] largest over the meshes in the steady-state window
  double kv_min = 0.;         // [-]
  double periodicity = 0.;    // [-] |K_v max(first half) − K_v max(second half)|
  // The linear model diverged at this speed (parametric resonance): no K_v exists, the K_v
  // fields are NaN and `failure` holds the SolverFailure message.
  bool unstable = false;
  std::string failure;
  // The K_v fields keep the linear model's values for contact_loss and not_steady points (a
  // chart may show where the model stops holding); reports must print them as invalid.
  SweepStatus status = SweepStatus::valid;
  IntegrationCost cost;
  // Up/down sweeps with continuation (nonlinear meshes):
  bool descending = false;           // belongs to the down sweep
  double separation_fraction = 0.;   // [-] largest over the meshes
  unsigned long separations = 0;     // [-] all meshes, in the window
  unsigned long back_impacts = 0;    // [-] all meshes, in the window
  double mean_deflection = 0.;       // [m] mesh 1: mean DTE
  double deflection_rms = 0.;        // [m] mesh 1: DTE rms about its mean
  std::vector<double> dte_orders;    // [mesh orders] of mesh 1's DTE spectrum lines
  std::vector<double> dte_amplitude; // [m]
  // Every mesh's DTE spectrum (the waterfall of each mesh): per mesh, lines in its own mesh
  // orders [-] and amplitudes [m]; mesh 0's equal dte_orders and dte_amplitude.
  std::vector<std::vector<double>> mesh_dte_orders, mesh_dte_amplitude;
};

struct SweepResult
{
  std::vector<SweepPoint> points;
  double wall_time = 0.; // [s]
};

enum class SweepDirection
{
  up,
  down,
  both // up, then down from the top speed's state
};
std::string sweep_direction_name(SweepDirection direction);

// K_v against input speed. A speed at which the linear model diverges is recorded as unstable
// (not as a number) and the sweep goes on; bad input still throws. The step is
// settings.integrator.time_step, reduced where needed so every mesh period holds at least
// `steps_per_mesh_period` steps (the stiffness jumps must be resolved at high speed).
//
// `direction` orders the speeds (ascending, descending, or both one after the other);
// with `continuation` each speed starts from the previous speed's final state (angles, speeds
// relative to the nominal rotation, and mesh positions), so where the response is multi-valued
// (nonlinear meshes near resonance) the up and down sweeps follow different branches.
//
// `progress`, when given, is called after each speed with its point, the speeds done and the
// speeds in all (up and down counted separately).
using SweepProgress =
    std::function<void(const SweepPoint& point, std::size_t done, std::size_t total)>;
SweepResult speed_sweep(const GearTrain& train, const SimulationSettings& settings,
                        const std::vector<double>& input_speeds,
                        unsigned int steps_per_mesh_period = 40,
                        SweepDirection direction = SweepDirection::up, bool continuation = false,
                        const SweepProgress& progress = {});
} // namespace gearstiff::dynamics
