#include "dynamics/simulation.h"

#include "dynamics/fields.h"
#include "errors/errors.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <limits>
#include <unsupported/Eigen/FFT>

namespace gearstiff::dynamics
{
std::string start_state_name(StartState start)
{
  return start == StartState::rest ? "rest" : "static deflection";
}

std::string sweep_direction_name(SweepDirection direction)
{
  return direction == SweepDirection::up     ? "up"
         : direction == SweepDirection::down ? "down"
                                             : "both";
}

std::string sweep_status_name(SweepStatus status)
{
  switch (status)
  {
  case SweepStatus::valid:
    return "valid";
  case SweepStatus::diverged:
    return "diverged (linear model unstable)";
  case SweepStatus::contact_loss:
    return "contact loss (mesh force < 0, outside the linear model)";
  case SweepStatus::not_steady:
    return "not steady (window halves differ)";
  }
  return "?";
}

namespace
{
// Single-sided amplitude spectrum of samples (t_i, f_i) over [start, end). The window spans
// a whole number of mesh periods, so the mesh harmonics fall on FFT bins; the series is
// resampled by linear interpolation onto 2^k points so the FFT never meets a large prime
// factor (the step oversamples the mesh frequency ~100-fold, so interpolation is harmless).
//
// `on_steps`: when the samples are the steps of a window of whole steps (a whole-revolution
// table's run, whose step divides the revolution), the FFT takes them as they are: no
// interpolation error, which would otherwise leak about 1e-3 of the mesh lines between them.
void amplitude_spectrum(const std::vector<double>& time, const std::vector<double>& force,
                        std::size_t first, double start, double end, double max_frequency,
                        std::vector<double>& frequencies, std::vector<double>& amplitudes,
                        bool on_steps = false)
{
  const std::size_t available = time.size() - first;
  const double steps = available > 1 ? (end - start) / (time[first + 1] - time[first]) : 0.;
  const bool take_steps = on_steps && available > 1 && std::abs(steps - std::round(steps)) < 1e-6 &&
                          std::size_t(std::llround(steps)) + 1 == available;
  std::size_t n = 1;
  while (n < available && n < (std::size_t(1) << 20))
    n *= 2;
  if (take_steps)
    n = available - 1; // [start, end): the end point is the next period's start
  std::vector<double> resampled(n);
  const double dt = (end - start) / n;
  std::size_t j = first;
  for (std::size_t i = 0; i < n && take_steps; ++i)
    resampled[i] = force[first + i];
  for (std::size_t i = 0; i < n && !take_steps; ++i)
  {
    const double t = start + i * dt;
    while (j + 1 < time.size() && time[j + 1] < t)
      ++j;
    const std::size_t j1 = std::min(j + 1, time.size() - 1);
    const double w = (j1 == j) ? 0. : std::clamp((t - time[j]) / (time[j1] - time[j]), 0., 1.);
    resampled[i] = (1. - w) * force[j] + w * force[j1];
  }
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, resampled);
  const double resolution = 1. / (end - start);
  for (std::size_t k = 0; k <= n / 2; ++k)
  {
    const double frequency = k * resolution;
    if (frequency > max_frequency)
      break;
    frequencies.push_back(frequency);
    amplitudes.push_back((k == 0 ? 1. : 2.) * std::abs(spectrum[k]) / n);
  }
}
} // namespace

// Refuses a run that cannot finish (issue 11) before anything is allocated, naming what made
// it long: a tiny step, a long simulated time, or a window that waits for a decay that takes
// too long (light damping).
void check_simulation_work(const TorsionalModel& model, const SimulationSettings& settings,
                           const IntegratorSettings& integrator, const SimulationResult& result,
                           double mesh_period)
{
  // Per step the observer keeps the window's time and forces (time series only), and the
  // stored trajectory is expanded into three series per mesh afterwards.
  const double per_step = settings.keep_time_series ? (1. + model.n_meshes()) * sizeof(double) +
                                                          3. * model.n_meshes() * sizeof(double) /
                                                              integrator.record_stride
                                                    : 0.;
  const WorkEstimate work = estimate_work(model, integrator, per_step);
  // A sensible step (the smaller of the RK4 limit and 1/20 mesh period) tells whether the span
  // or the step is to blame.
  const double sensible_step = std::min(model.rk4_step_limit(), mesh_period / 20.);
  const bool span_too_long = integrator.end_time / sensible_step > max_integration_steps;
  if (!span_too_long)
    check_work(work, field::simulation("time_step"),
               "the step " + std::to_string(integrator.time_step) +
                   " s is far below what the model needs (RK4 limit " +
                   std::to_string(model.rk4_step_limit()) + " s): enlarge it");
  else if (settings.end_time > 0.)
    check_work(work, field::simulation("simulated_time"), "shorten it");
  else if (!result.window_automatic)
    check_work(work, field::simulation("steady_state_start"), "start the window earlier");
  else
    check_work(work, field::simulation("steady_state_start"),
               "the automatic window waits " + std::to_string(result.decay_time) +
                   " s for the slowest mode to decay to 1/1000 (mesh damping too light): give "
                   "the window start or more damping");
}

// An excitation harmonic the step cannot follow (fewer than 8 steps per period) is refused,
// naming the harmonics of the mesh that carries it.
void check_excitation_resolution(const TorsionalModel& model, double step)
{
  constexpr double steps_per_harmonic = 8.;
  for (unsigned int m = 0; m < model.n_meshes(); ++m)
  {
    const Mesh& mesh = model.train().meshes[m];
    if (!mesh.nonlinear)
      continue;
    const double order = mesh.nonlinear->transmission_error.highest_order();
    const double frequency = order * model.mesh_position_rate(m);
    if (frequency * step * steps_per_harmonic > 1.)
    {
      throw InputError(field::gear_mesh(m, "transmission_error_harmonics"),
                       "order " + std::to_string(order) + " at " + std::to_string(frequency) +
                           " Hz is above what the time step " + std::to_string(step * 1e6) +
                           " µs resolves (8 steps per period: at most " +
                           std::to_string(1. / (steps_per_harmonic * step)) +
                           " Hz); lower the order or the step");
    }
  }
}

double excitation_period(const TorsionalModel& model)
{
  double period = 1. / model.mesh_position_rate(0);
  for (unsigned int m = 0; m < model.n_meshes(); ++m)
  {
    const unsigned int pitches = model.train().meshes[m].stiffness.period();
    if (pitches > 1)
      period = std::max(period, pitches / model.mesh_position_rate(m));
  }
  return period;
}

namespace
{
// Modes, decay time and the steady-state window of a run (result.modes, decay_time, window_*);
// returns the end of the integration [s].
double plan_window(const TorsionalModel& model, const SimulationSettings& settings,
                   SimulationResult& result)
{
  result.start = settings.start;
  result.modes = model.modal_properties();
  const double slowest_decay =
      result.modes.decay_rates.empty() ? 0. : result.modes.decay_rates.front();
  result.decay_time = slowest_decay > 0. ? std::log(1000.) / slowest_decay
                                         : std::numeric_limits<double>::infinity();

  const double mesh_period = 1. / model.mesh_position_rate(0);
  // The window spans whole periods of the excitation: mesh 1's mesh period, or, with a
  // whole-revolution table (docs/faults.md), the longest table period, so that the once-per-
  // revolution sidebands fall on FFT bins and every revolution counts alike.
  const double period = excitation_period(model);
  const double h = settings.integrator.time_step; // output interval of every method
  result.window_automatic = settings.steady_state_start < 0.;
  double requested_start = settings.steady_state_start;
  if (result.window_automatic)
    // Without damping nothing decays: skip a fixed 20 mesh periods and say so via decay_time.
    requested_start = std::isfinite(result.decay_time) ? result.decay_time : 20. * mesh_period;
  double window = settings.window_periods * mesh_period;
  double window_origin = requested_start;
  if (period > mesh_period) // whole revolutions, at least the periods asked for, from the step
  {
    window = std::ceil(window / period - 1e-9) * period;
    window_origin = std::ceil(requested_start / h - 1e-9) * h;
  }
  const double end_time = settings.end_time > 0. ? settings.end_time : window_origin + window;
  if (!(end_time > requested_start + h))
    throw InputError(field::simulation("steady_state_start"),
                     "the steady-state window [" + std::to_string(requested_start) + ", " +
                         std::to_string(end_time) + "] s is empty; lengthen the simulated time");

  // The window opens at the first output time after the requested start and spans whole periods
  // of mesh 1, so the mean is a period mean and the mesh harmonics fall on FFT bins.
  result.window_start = std::ceil(requested_start / h - 1e-9) * h;
  const double whole_periods = std::floor((end_time - result.window_start) / period + 1e-9);
  result.window_end = whole_periods >= 1. ? result.window_start + whole_periods * period : end_time;
  return end_time;
}

// The state the run starts from: the given one (a sweep's continuation), the static deflection
// or rest [rad], [rad/s] per DOF.
void start_state(const TorsionalModel& model, const SimulationSettings& settings,
                 std::vector<double>& angle, std::vector<double>& velocity)
{
  const unsigned int n = model.n_dofs();
  angle.assign(n, 0.);
  velocity.assign(n, 0.);
  if (!settings.initial_angle.empty())
  {
    if (settings.initial_angle.size() != n || settings.initial_velocity.size() != n)
      throw InputError("initial state", "needs one angle and one speed per degree of freedom");
    angle = settings.initial_angle;
    velocity = settings.initial_velocity;
  }
  else if (settings.start == StartState::static_deflection)
    angle = model.static_state(true).angle;
}

// What a run gathers at every step in the window (the integrator's observers): K_v extremes per
// mesh and window half, mean force and DTE, separated steps, contact changes, and the window's
// samples for the spectra; finish() turns them into the MeshResults.
class WindowStatistics
{
public:
  WindowStatistics(const TorsionalModel& model, const SimulationSettings& settings,
                   SimulationResult& result)
      : model(model), settings(settings), result(result), h(settings.integrator.time_step),
        middle(0.5 * (result.window_start + result.window_end)), tolerance(1e-9 * h),
        keep_deflection(settings.keep_time_series || settings.dte_spectrum_orders > 0.),
        n_meshes(model.n_meshes()), window_force(n_meshes), window_deflection(n_meshes),
        deflection_sum(n_meshes, 0.), deflection_square(n_meshes, 0.), separated_steps(n_meshes, 0),
        scale(n_meshes), force_sum(n_meshes, 0.),
        revolution_table(excitation_period(model) * model.mesh_position_rate(0) > 1.5)
  {
    result.meshes.resize(n_meshes);
    for (unsigned int m = 0; m < n_meshes; ++m)
    {
      MeshResult& mesh = result.meshes[m];
      const Mesh& description = model.train().meshes[m];
      mesh.name = description.name.empty() ? "Mesh " + std::to_string(m + 1) : description.name;
      mesh.nominal_force = model.nominal_force(m);
      mesh.mesh_frequency = model.mesh_position_rate(m);
      mesh.initial_position = description.initial_position;
      // K_v is relative to the nominal force; a mesh without load has no K_v.
      const double nominal = std::abs(mesh.nominal_force);
      scale[m] = nominal > 0. ? 1. / nominal : std::numeric_limits<double>::quiet_NaN();
      mesh.kv_max = mesh.kv_max_first_half = mesh.kv_max_second_half =
          -std::numeric_limits<double>::infinity();
      mesh.kv_min = std::numeric_limits<double>::infinity();
      mesh.nonlinear = model.is_nonlinear(m);
    }
  }

  void observe(double t, const double* phi, const double* omega)
  {
    if (t < result.window_start - tolerance || t > result.window_end + tolerance)
      return;
    const bool in_mean = t < result.window_end - 0.5 * h;
    if (keep_deflection)
      window_time.push_back(t);
    for (unsigned int m = 0; m < n_meshes; ++m)
    {
      MeshResult& mesh = result.meshes[m];
      const MeshResponse response = model.mesh_response(m, t, phi, omega);
      const double force = response.force;
      if (in_mean)
      {
        deflection_sum[m] += response.deflection;
        deflection_square[m] += response.deflection * response.deflection;
        separated_steps[m] += response.regime != ContactRegime::drive;
      }
      if (keep_deflection)
        window_deflection[m].push_back(response.deflection);
      const double kv = force * scale[m];
      if (kv > mesh.kv_max)
      {
        mesh.kv_max = kv;
        mesh.kv_max_time = t;
      }
      mesh.kv_min = std::min(mesh.kv_min, kv);
      double& half = t < middle ? mesh.kv_max_first_half : mesh.kv_max_second_half;
      half = std::max(half, kv);
      if (in_mean)
        force_sum[m] += force;
      if (settings.keep_time_series)
        window_force[m].push_back(force);
    }
    mean_count += in_mean;
    result.final_time = t;
    result.final_angle.assign(phi, phi + model.n_dofs());
    result.final_velocity.assign(omega, omega + model.n_dofs());
  }

  void contact_change(double t, unsigned int m, ContactRegime from, ContactRegime to)
  {
    if (t < result.window_start || t >= result.window_end)
      return;
    MeshResult& mesh = result.meshes[m];
    mesh.separations += from == ContactRegime::drive;
    mesh.back_impacts += to == ContactRegime::back;
  }

  // Means, rms, separation fraction and spectra of every mesh (after the integration).
  void finish()
  {
    double max_frequency = settings.max_spectrum_frequency;
    if (max_frequency <= 0.)
      max_frequency = 1.5 * result.trajectory.highest_frequency / (2. * M_PI);
    for (unsigned int m = 0; m < n_meshes; ++m)
    {
      MeshResult& mesh = result.meshes[m];
      const double count = std::max<std::size_t>(mean_count, 1);
      mesh.mean_force = force_sum[m] / count;
      mesh.mean_deflection = deflection_sum[m] / count;
      mesh.deflection_rms = std::sqrt(
          std::max(0., deflection_square[m] / count - mesh.mean_deflection * mesh.mean_deflection));
      mesh.separation_fraction = separated_steps[m] / count;
      result.kv_max = std::max(result.kv_max, mesh.kv_max);
      if (keep_deflection)
        amplitude_spectrum(
            window_time, window_deflection[m], 0, result.window_start, result.window_end,
            settings.keep_time_series ? max_frequency
                                      : settings.dte_spectrum_orders * mesh.mesh_frequency,
            mesh.dte_spectrum_frequency, mesh.dte_spectrum_amplitude, revolution_table);
      if (settings.keep_time_series)
        amplitude_spectrum(window_time, window_force[m], 0, result.window_start, result.window_end,
                           max_frequency, mesh.spectrum_frequency, mesh.spectrum_amplitude,
                           revolution_table);
    }
  }

private:
  const TorsionalModel& model;
  const SimulationSettings& settings;
  SimulationResult& result;
  const double h;         // [s] output interval
  const double middle;    // [s] between the window halves
  const double tolerance; // [s] on the window's ends
  const bool keep_deflection;
  const unsigned int n_meshes;
  std::vector<double> window_time; // [s]
  std::vector<std::vector<double>> window_force, window_deflection;
  std::vector<double> deflection_sum, deflection_square;
  std::vector<std::size_t> separated_steps;
  std::vector<double> scale, force_sum;
  std::size_t mean_count = 0;
  const bool revolution_table; // spectra on the steps (amplitude_spectrum)
};

// Force, stiffness and deflection of every mesh at the stored output times.
void mesh_time_series(const TorsionalModel& model, SimulationResult& result)
{
  const Trajectory& trajectory = result.trajectory;
  const std::vector<double>& time = trajectory.time;
  for (unsigned int m = 0; m < result.meshes.size(); ++m)
  {
    MeshResult& mesh = result.meshes[m];
    mesh.force.resize(time.size());
    mesh.stiffness.resize(time.size());
    mesh.deflection.resize(time.size());
    for (std::size_t i = 0; i < time.size(); ++i)
    {
      const MeshResponse response =
          model.mesh_response(m, time[i], trajectory.angle_at(i), trajectory.velocity_at(i));
      mesh.force[i] = response.force;
      mesh.stiffness[i] = response.stiffness;
      mesh.deflection[i] = response.deflection;
    }
  }
}
} // namespace

SimulationResult simulate(const TorsionalModel& model, const SimulationSettings& given)
{
  // A whole-revolution table (docs/faults.md): the step is shortened to divide the mesh period
  // of mesh 1, and with it the revolution, into whole steps: every pitch is integrated at the
  // same phases of the step (else the pitches differ by the integration error, which shows as
  // false sidebands of about 1 % of the mesh line at 5 µs), the window holds whole steps, its
  // spectrum is taken on them and the response compared with itself a revolution earlier.
  SimulationSettings settings = given;
  // The stored series keeps every `stride`-th step; for a revolution table the stride too
  // divides the mesh period, so stored samples one revolution apart are the same phase.
  const double h0 = given.integrator.time_step;
  unsigned int stride =
      settings.keep_time_series
          ? std::max(1u, static_cast<unsigned int>(std::lround(std::min(
                             settings.record_interval / h0, double(max_integration_steps)))))
          : std::numeric_limits<unsigned int>::max();
  if (excitation_period(model) * model.mesh_position_rate(0) > 1.5)
  {
    const double mesh_period = 1. / model.mesh_position_rate(0);
    const double unit = settings.keep_time_series ? stride : 1.;
    settings.integrator.time_step =
        mesh_period / (unit * std::ceil(mesh_period / (unit * h0) - 1e-9));
  }
  SimulationResult result;
  result.time_step = settings.integrator.time_step;
  const double end_time = plan_window(model, settings, result);
  std::vector<double> angle, velocity;
  start_state(model, settings, angle, velocity);
  result.initial_angle = angle;
  const double h = settings.integrator.time_step;
  check_excitation_resolution(model, h);

  // K_v statistics at every step through the observer; only the window's forces are kept (for
  // the spectrum) and the trajectory itself every `record_interval`.
  WindowStatistics statistics(model, settings, result);
  IntegratorSettings integrator = settings.integrator;
  integrator.end_time = end_time;
  integrator.record_stride = stride;
  check_simulation_work(model, settings, integrator, result, 1. / model.mesh_position_rate(0));
  integrator.observer = [&](double t, const double* phi, const double* omega)
  { statistics.observe(t, phi, omega); };
  integrator.contact_observer = [&](double t, unsigned int m, ContactRegime from, ContactRegime to)
  { statistics.contact_change(t, m, from, to); };
  result.trajectory = integrate(model, angle, velocity, integrator);
  statistics.finish();
  if (settings.keep_time_series)
    mesh_time_series(model, result);
  else
  {
    result.trajectory.angle.clear();
    result.trajectory.velocity.clear();
    result.trajectory.time.clear();
  }
  return result;
}

namespace
{
// The speeds in the order they run, each with whether it belongs to the down sweep.
std::vector<std::pair<double, bool>> sweep_order(const std::vector<double>& input_speeds,
                                                 SweepDirection direction, bool continuation)
{
  std::vector<double> ascending = input_speeds;
  std::vector<std::pair<double, bool>> order; // speed, descending
  if (direction != SweepDirection::up || continuation)
    std::sort(ascending.begin(), ascending.end());
  if (direction != SweepDirection::down)
    for (const double speed : ascending)
      order.emplace_back(speed, false);
  if (direction != SweepDirection::up)
    for (auto speed = ascending.rbegin(); speed != ascending.rend(); ++speed)
      order.emplace_back(*speed, true);
  return order;
}

// Where the next speed of a continued sweep starts: the previous speed's final state and mesh
// positions (empty: afresh).
struct SweepState
{
  std::vector<double> angle, velocity; // [rad], [rad/s]
  std::vector<double> positions;       // [base pitches] per mesh
};

// A finished run's summary over its meshes into `p`, and the state the next speed continues from.
void summarize_sweep_point(const TorsionalModel& model, const GearTrain& point_train,
                           const SimulationResult& result, SweepPoint& p, SweepState& state)
{
  p.kv_max = result.kv_max;
  p.kv_min = std::numeric_limits<double>::infinity();
  for (const auto& mesh : result.meshes)
  {
    p.kv_min = std::min(p.kv_min, mesh.kv_min);
    p.periodicity =
        std::max(p.periodicity, std::abs(mesh.kv_max_first_half - mesh.kv_max_second_half));
    p.separation_fraction = std::max(p.separation_fraction, mesh.separation_fraction);
    p.separations += mesh.separations;
    p.back_impacts += mesh.back_impacts;
  }
  const MeshResult& first = result.meshes.front();
  p.mean_deflection = first.mean_deflection;
  p.deflection_rms = first.deflection_rms;
  for (const MeshResult& mesh : result.meshes)
  {
    std::vector<double> orders;
    for (const double frequency : mesh.dte_spectrum_frequency)
      orders.push_back(frequency / mesh.mesh_frequency);
    p.mesh_dte_orders.push_back(orders);
    p.mesh_dte_amplitude.push_back(mesh.dte_spectrum_amplitude);
  }
  p.dte_orders = p.mesh_dte_orders.front();
  p.dte_amplitude = p.mesh_dte_amplitude.front();
  p.cost = result.trajectory.cost;
  // Nonlinear meshes represent separation: a negative force is back-flank contact.
  if (p.kv_min < 0. && !model.has_nonlinear_meshes())
    p.status = SweepStatus::contact_loss;
  else if (p.periodicity > steady_state_tolerance * p.kv_max)
    p.status = SweepStatus::not_steady;
  state.angle = result.final_angle;
  state.velocity = result.final_velocity;
  state.positions.clear();
  for (unsigned int m = 0; m < model.n_meshes(); ++m)
    state.positions.push_back(point_train.meshes[m].initial_position +
                              model.mesh_position_rate(m) * result.final_time);
}

// One speed of the sweep, started from `state` when continuing.
SweepPoint run_sweep_point(const GearTrain& train, const SimulationSettings& settings, double speed,
                           bool descending, unsigned int steps_per_mesh_period, bool continuation,
                           SweepState& state)
{
  GearTrain point_train = train;
  point_train.input_speed = speed;
  if (continuation && !state.positions.empty())
    for (std::size_t m = 0; m < state.positions.size(); ++m)
      point_train.meshes[m].initial_position = state.positions[m];
  const TorsionalModel model(point_train);
  SimulationSettings point = settings;
  point.keep_time_series = false;
  if (continuation && !state.angle.empty())
  {
    point.initial_angle = state.angle;
    point.initial_velocity = state.velocity;
  }
  double fastest_mesh = 0.;
  for (unsigned int m = 0; m < model.n_meshes(); ++m)
    fastest_mesh = std::max(fastest_mesh, model.mesh_position_rate(m));
  point.integrator.time_step =
      std::min(settings.integrator.time_step, 1. / (fastest_mesh * steps_per_mesh_period));
  SweepPoint p;
  p.input_speed = speed;
  p.descending = descending;
  p.mesh_frequency = model.mesh_position_rate(0);
  p.time_step = point.integrator.time_step;
  try
  {
    summarize_sweep_point(model, point_train, simulate(model, point), p, state);
  }
  catch (const SolverFailure& failure)
  {
    p.unstable = true;
    p.status = SweepStatus::diverged;
    p.failure = failure.what();
    p.kv_max = p.kv_min = p.periodicity = std::numeric_limits<double>::quiet_NaN();
    state.angle.clear(); // the next speed starts afresh
    state.positions.clear();
  }
  return p;
}
} // namespace

SweepResult speed_sweep(const GearTrain& train, const SimulationSettings& settings,
                        const std::vector<double>& input_speeds, unsigned int steps_per_mesh_period,
                        SweepDirection direction, bool continuation, const SweepProgress& progress)
{
  const auto start = std::chrono::steady_clock::now();
  SweepResult sweep;
  const std::vector<std::pair<double, bool>> order =
      sweep_order(input_speeds, direction, continuation);
  SweepState state;
  for (const auto& [speed, descending] : order)
  {
    sweep.points.push_back(run_sweep_point(train, settings, speed, descending,
                                           steps_per_mesh_period, continuation, state));
    if (progress)
      progress(sweep.points.back(), sweep.points.size(), order.size());
  }
  sweep.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return sweep;
}
} // namespace gearstiff::dynamics
