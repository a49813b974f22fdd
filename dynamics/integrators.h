// Time integration of a TorsionalModel: classical RK4 at a fixed step (the published method,
// Reszuta & Drewniak 2015: 5 µs), an adaptive embedded Runge–Kutta (Dormand–Prince 5(4)) with
// error control, and the implicit HHT-α method for stiff meshes.
//
// Every run reports its cost (steps, function evaluations, linear solves, wall time) and watches
// for divergence: a non-finite state or vibration energy grown beyond 10⁶ times its reference
// (the larger of the initial vibration energy and the static strain energy) stops it with a
// SolverFailure that gives the step used and the estimated RK4 stability limit. RK4 refuses a
// step above that limit with an InputError unless the override is set.
#pragma once

#include "dynamics/torsional_model.h"

#include <functional>
#include <string>
#include <vector>

namespace gearstiff::dynamics
{
enum class IntegratorType
{
  rk4,
  adaptive_rk,
  hht_alpha
};

std::string integrator_name(IntegratorType type);

struct IntegratorSettings
{
  IntegratorType type = IntegratorType::rk4;
  // [s] fixed step of RK4 and HHT-α; the output interval (and largest step) of the adaptive
  // method, whose own steps follow from the error control.
  double time_step = 5e-6;
  double end_time = 0.1;            // [s]
  double relative_tolerance = 1e-7; // [-] adaptive method: per-step error relative to state
  double hht_alpha = -0.05;         // [-] HHT-α parameter in [−1/3, 0]; 0 = trapezoidal rule
  bool allow_unstable_step = false; // run RK4 above the estimated stability limit anyway
  unsigned int record_stride = 1;   // keep every n-th output point in the Trajectory
  // Called at every output point (before the stride), so results that need every step can be
  // accumulated without storing the whole trajectory (its memory traffic would cost more than
  // the integration). Empty: not called.
  std::function<void(double time, const double* angle, const double* velocity)> observer;
  // Nonlinear meshes: called at every located contact change of mesh `mesh` (RK4 only: the
  // step is cut at the switch, see integrate()). Empty: not called.
  std::function<void(double time, unsigned int mesh, ContactRegime from, ContactRegime to)>
      contact_observer;
};

struct IntegrationCost
{
  unsigned long steps = 0;
  unsigned long rejected_steps = 0;       // adaptive only
  unsigned long function_evaluations = 0; // calls of the equations of motion
  unsigned long linear_solves = 0;        // HHT-α only
  double smallest_step = 0.;              // [s]
  double largest_step = 0.;               // [s]
  unsigned long located_switches = 0;     // contact changes of nonlinear meshes (RK4)
  double wall_time = 0.;                  // [s]
  // [s] processor time of this process during the run: on a shared machine the honest cost
  double cpu_time = 0.;
};

struct Trajectory
{
  unsigned int n_dofs = 0;
  std::vector<double> time;     // [s] output times, uniform spacing
  std::vector<double> angle;    // [rad] n_dofs per output time, row after row
  std::vector<double> velocity; // [rad/s] likewise
  IntegrationCost cost;
  std::string method;
  double rk4_step_limit = 0.;    // [s] estimated largest stable RK4 step
  double highest_frequency = 0.; // [rad/s] at the largest mesh stiffness

  std::size_t size() const { return time.size(); }
  const double* angle_at(std::size_t i) const { return angle.data() + i * n_dofs; }
  const double* velocity_at(std::size_t i) const { return velocity.data() + i * n_dofs; }
};

// What a run will cost before it starts (issue 11: absurd spans or steps must be refused, not
// run out of memory or time). Steps are exact for the fixed-step methods and a lower bound for
// the adaptive one (its output points); memory counts the stored trajectory plus
// `bytes_per_step` more per step (the caller's own per-step storage).
struct WorkEstimate
{
  double steps = 0.;  // [-]
  double memory = 0.; // [bytes]
};
WorkEstimate estimate_work(const TorsionalModel& model, const IntegratorSettings& settings,
                           double bytes_per_step = 0.);
// The limits every run is held to: 2e8 steps (minutes of processor time for a small train)
// and 2 GiB of stored results.
constexpr double max_integration_steps = 2e8;
constexpr double max_integration_memory = 2. * 1024. * 1024. * 1024.;
// Throws InputError naming `parameter` with the estimate when it exceeds a limit; `hint` says
// what to change.
void check_work(const WorkEstimate& work, const std::string& parameter, const std::string& hint);

// Integrates from the initial angles [rad] and speeds [rad/s] (relative to the nominal
// rotation, see torsional_model.h) from t = 0 to settings.end_time.
//
// Nonlinear meshes (nonlinear_mesh.h) switch between drive contact, separation and back-flank
// contact where the flank approach z = δ − e crosses 0 or −2b, a kink in the force. RK4 does not
// step over such a switch: after each trial step the cubic Hermite interpolant of z (values and
// rates at both ends) is searched for the first crossing (sampled at h/16, then bisection); the
// step is cut there, the switch counted, and the rest of the step taken from the switch, so
// every RK4 step sees a smooth right-hand side. HHT-α (linearised) and the adaptive method
// refuse nonlinear meshes (InputError naming Simulation/integrator).
Trajectory integrate(const TorsionalModel& model, const std::vector<double>& initial_angle,
                     const std::vector<double>& initial_velocity,
                     const IntegratorSettings& settings);
} // namespace gearstiff::dynamics
