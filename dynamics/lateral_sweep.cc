#include "dynamics/lateral_sweep.h"

#include "dynamics/fields.h"
#include "errors/errors.h"
#include "errors/format.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace gearstiff::dynamics
{
double planet_ring_mesh_offset(int planet_teeth, double sun_approach_ratio,
                               double ring_approach_ratio)
{
  const double x = ring_approach_ratio - sun_approach_ratio + 0.5 * (std::abs(planet_teeth) + 1);
  return x - std::floor(x);
}

namespace
{
// Status of a finished speed (simulation.h's rules): a linear mesh whose force turns negative
// has left the model; window halves apart by more than steady_state_tolerance: not steady.
SweepStatus point_status(const LateralWindowSummary& s, bool nonlinear)
{
  if (!nonlinear && s.mesh_force_min < 0.)
    return SweepStatus::contact_loss;
  if (std::abs(s.kv_max_first_half - s.kv_max_second_half) > steady_state_tolerance * s.kv_max)
    return SweepStatus::not_steady;
  return SweepStatus::valid;
}

LateralSweepPoint diverged_point(const SolverFailure& failure)
{
  LateralSweepPoint point;
  point.status = SweepStatus::diverged;
  point.failure = failure.what();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  LateralWindowSummary& s = point.summary;
  s.sun_mesh_force_max = s.ring_mesh_force_max = s.mesh_force_min = nan;
  s.kv_max = s.kv_max_first_half = s.kv_max_second_half = nan;
  s.bearing_force_max.setConstant(nan);
  s.orbit_amplitude.setConstant(nan);
  return point;
}
// The slowest mode has no damping: named by what would damp it. With mesh damping given the
// undamped mode moves bearings only (issue 44: the message blamed the damped meshes).
[[noreturn]] void throw_undamped(const LateralModel& model)
{
  const LateralModes modes = model.modes();
  double frequency = 0.;
  for (Eigen::Index k = 0; k < modes.frequencies.size(); ++k)
    if (modes.frequencies[k] > 0. &&
        !(modes.shapes.col(k).dot(model.damping() * modes.shapes.col(k)) > 0.))
    {
      frequency = modes.frequencies[k];
      break;
    }
  const std::string mode = "the " + format_number(frequency, 5) +
                           " Hz mode has no damping, so "
                           "the start-up transient never decays";
  const LateralStage& stage = model.stage();
  if (stage.sun_mesh_damping > 0. && stage.ring_mesh_damping > 0.)
    throw InputError(field::train("bearing_damping"),
                     mode + " (the meshes' damping does not reach it: it moves the bearings); "
                            "give bearing damping 'name: c, ...' (N·s/m) for sun, ring and "
                            "carrier, or Simulation/steady state start");
  throw InputError(field::train_mesh(0, "damping"),
                   mode + ": give the meshes' damping (Train mesh 1 and 2) or Simulation/steady "
                          "state start");
}
} // namespace

LateralSweepWork lateral_sweep_work(const LateralModel& model,
                                    const LateralMeshExcitation& excitation,
                                    const LateralRunSettings& run,
                                    const LateralSweepSettings& sweep)
{
  if (!(sweep.nominal_input_speed != 0.) || !(excitation.mesh_frequency > 0.))
    throw InputError(field::speed_sweep("points"),
                     "the stage's input and meshes must turn for a sweep");
  LateralSweepWork work;
  work.settle_time = sweep.settle_time >= 0. ? sweep.settle_time : lateral_decay_time(model);
  if (!std::isfinite(work.settle_time))
    throw_undamped(model);
  const double directions = sweep.direction == SweepDirection::both ? 2. : 1.;
  for (const double w : sweep.input_speeds)
  {
    const double f = excitation.mesh_frequency * std::abs(w / sweep.nominal_input_speed);
    const double h = std::min(run.time_step, 1. / (f * sweep.steps_per_mesh_period));
    work.steps += directions * (work.settle_time + sweep.window_periods / f) / h;
  }
  if (work.steps > 2e8)
    throw InputError(field::simulation("steady_state_start"),
                     "the sweep would need " + format_number(work.steps, 3) +
                         " steps (limit 2e8): the slowest mode decays in " +
                         format_number(work.settle_time, 3) +
                         " s; give more damping or a shorter steady state start");
  return work;
}

LateralSweepResult lateral_speed_sweep(const LateralModel& model, const LateralStaticLoad& load,
                                       const LateralMeshExcitation& excitation,
                                       const LateralRunSettings& run,
                                       const LateralSweepSettings& sweep,
                                       const std::function<void(const std::string&)>& progress)
{
  LateralSweepResult result;
  result.settle_time = lateral_sweep_work(model, excitation, run, sweep).settle_time;
  std::vector<std::pair<double, bool>> order; // speed, descending
  if (sweep.direction != SweepDirection::down)
    for (const double w : sweep.input_speeds)
      order.push_back({w, false});
  if (sweep.direction != SweepDirection::up)
    for (auto w = sweep.input_speeds.rbegin(); w != sweep.input_speeds.rend(); ++w)
      order.push_back({*w, true});

  const bool nonlinear = excitation.sun_nonlinear || excitation.ring_nonlinear;
  const auto start = std::chrono::steady_clock::now();
  LateralResponse previous;
  for (const auto& [speed, descending] : order)
  {
    const double scale = std::abs(speed / sweep.nominal_input_speed);
    LateralMeshExcitation at_speed = excitation;
    at_speed.mesh_frequency = excitation.mesh_frequency * scale;
    LateralRunSettings settings = run;
    settings.time_step =
        std::min(run.time_step, 1. / (at_speed.mesh_frequency * sweep.steps_per_mesh_period));
    settings.window_start = result.settle_time;
    settings.end_time = result.settle_time + sweep.window_periods / at_speed.mesh_frequency;
    settings.record = false;
    settings.record_stride = 1000;
    if (sweep.continuation && !previous.final_position.empty())
    {
      settings.initial_position = previous.final_position;
      settings.initial_velocity = previous.final_velocity;
      settings.mesh_position = previous.final_mesh_position;
    }
    LateralSweepPoint point;
    try
    {
      previous = integrate_lateral(model, load, at_speed, settings);
      point.summary = previous.summary;
      point.status = point_status(point.summary, nonlinear);
      point.steps = previous.steps;
    }
    catch (const SolverFailure& failure)
    {
      point = diverged_point(failure);
      previous = LateralResponse();
    }
    point.input_speed = speed;
    point.carrier_speed = sweep.nominal_carrier_speed * speed / sweep.nominal_input_speed;
    point.mesh_frequency = at_speed.mesh_frequency;
    point.time_step = settings.time_step;
    point.descending = descending;
    result.points.push_back(point);
    if (progress)
      progress(format_number(speed * 30. / M_PI, 5) + " rpm " + (descending ? "down" : "up") +
               ": K_v " + format_number(point.summary.kv_max, 4) + " (" +
               sweep_status_name(point.status) + ")");
  }
  result.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}
} // namespace gearstiff::dynamics
