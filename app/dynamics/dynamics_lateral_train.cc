#include "app/dynamics/dynamics_lateral_train.h"

#include "app/core/units.h"
#include "app/dynamics/dynamics_parameters.h"
#include "app/dynamics/lateral_mode_report.h"
#include "app/dynamics/lateral_parameters.h"
#include "app/dynamics/sweep_categories.h"
#include "dynamics/lateral_train_response.h"
#include "errors/errors.h"
#include "errors/format.h"

#include <chrono>
#include <cmath>

namespace gearstiff::app
{
namespace
{
using namespace gearstiff::dynamics;

// The rotational model of the same description: Train/model = train's parameters (mesh k(x)
// from Train mesh n, damping as derived there), its general-form train with that damping.
TrainModel rotational_model(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Train");
  prm.set("model", "train");
  prm.leave_subsection();
  DynamicsParameters d;
  try
  {
    d = parse_dynamics_parameters(prm);
  }
  catch (...)
  {
    prm.enter_subsection("Train");
    prm.set("model", "lateral");
    prm.leave_subsection();
    throw;
  }
  prm.enter_subsection("Train");
  prm.set("model", "lateral");
  prm.leave_subsection();
  TrainModel model = d.train_model;
  model.train = d.train;
  return model;
}

std::vector<unsigned int> central_bodies(const LateralTrain& train)
{
  std::vector<unsigned int> bodies;
  for (unsigned int b = 0; b < train.bodies.size(); ++b)
    if (train.bodies[b].central)
      bodies.push_back(b);
  return bodies;
}

void report_modes(const LateralTrainModel& model, Report& report)
{
  const auto start = std::chrono::steady_clock::now();
  const LateralTrainModes modes = model.modes();
  report.add_value("modes_time",
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() *
                       1e3,
                   "ms", "wall time of the modes and their classification");
  report_mode_classes(modes, "lateral_train_modes", "", report);
}

void report_statics(const LateralTrainSetup& setup, const LateralTrainModel& model, Report& report)
{
  const LateralTrainStatics s =
      model.static_state(setup.input_body, setup.output_body, setup.input_torque);
  auto& meshes =
      report.add_table("lateral_train_mesh_forces",
                       {"line", "train_mesh", "copy", "force", "share"}, {"-", "-", "-", "N", "-"});
  const TrainModel& r = setup.rotational;
  for (std::size_t i = 0; i < s.mesh_force.size(); ++i)
  {
    // Share of this copy in its Train mesh's copies on the same body set: F·N/ΣF.
    double sum = 0.;
    unsigned int n = 0;
    for (std::size_t j = 0; j < s.mesh_force.size(); ++j)
      if (r.spec_mesh[j] == r.spec_mesh[i])
        sum += s.mesh_force[j], ++n;
    meshes.add_row({double(i + 1), double(r.spec_mesh[i] + 1), double(r.mesh_copy[i] + 1),
                    s.mesh_force[i], s.mesh_force[i] * n / sum});
  }
  auto& bearings = report.add_table("lateral_train_bearing_forces", {"body", "fx", "fy", "force"},
                                    {"-", "N", "N", "N"});
  for (const unsigned int b : central_bodies(setup.train))
    bearings.add_row({double(b + 1), s.bearing_force(b, 0), s.bearing_force(b, 1),
                      s.bearing_force.row(b).norm()});
  report.add_value("output_torque", std::abs(s.output_torque), "N·m",
                   "static load on the output (balances the input torque)");
}

// The run at one speed: settle (given, else the decay of the slowest mode to 1/1000), then
// `window_periods` periods of the slowest mesh at `steps_per_mesh_period` steps of the fastest.
LateralTrainRun run_at(const LateralTrainParameters& p, double speed, double settle)
{
  double slowest = 1e300, fastest = 0.;
  for (const Mesh& mesh : p.setup.rotational.train.meshes)
  {
    slowest = std::min(slowest, mesh.position_ratio * speed);
    fastest = std::max(fastest, mesh.position_ratio * speed);
  }
  LateralTrainRun run;
  run.input_speed = speed;
  run.time_step =
      std::min(1. / (fastest * p.steps_per_mesh_period), 0.9 * lateral_train_step_limit(p.setup));
  run.settle_time = settle;
  run.window = p.window_periods / slowest;
  return run;
}

void report_response(const LateralTrainParameters& p, double settle, Report& report)
{
  LateralTrainRun run = run_at(p, p.input_speed, settle);
  run.recorded_bodies = central_bodies(p.setup.train);
  run.record_stride = std::max(1u, static_cast<unsigned int>(run.window / run.time_step / 4000.));
  const LateralTrainResponse r = integrate_lateral_train(p.setup, run);
  std::vector<std::string> columns{"time"}, units{"s"};
  for (const unsigned int b : run.recorded_bodies)
    for (const char* axis : {"_x", "_y"})
    {
      columns.push_back(p.setup.train.bodies[b].name + axis);
      units.push_back("um");
    }
  auto& orbit = report.add_table("lateral_train_orbit", columns, units);
  for (std::size_t i = 0; i < r.time.size(); ++i)
  {
    std::vector<double> row{r.time[i]};
    for (Eigen::Index j = 0; j < r.position[i].size(); ++j)
      row.push_back(r.position[i][j] * 1e6);
    orbit.add_row(row);
  }
  for (std::size_t m = 0; m < r.summary.kv_max.size(); ++m)
    report.add_value("kv_max_train_mesh" + std::to_string(m + 1), r.summary.kv_max[m], "-",
                     "largest F/F_static over the copies of Train mesh " + std::to_string(m + 1));
  for (const unsigned int b : run.recorded_bodies)
  {
    const std::string& name = p.setup.train.bodies[b].name;
    report.add_value("orbit_" + name, r.summary.orbit_amplitude[b] * 1e6, "µm",
                     "orbit amplitude of " + name + " at the nominal speed");
    report.add_value("bearing_force_max_" + name, r.summary.bearing_force_max[b], "N",
                     "largest bearing force on " + name + " at the nominal speed");
  }
  report.add_value("settle_time", settle * 1e3, "ms", "time before the window");
  report.add_value("time_step", run.time_step * 1e6, "µs", "RK4 time step");
  report.add_value("rk4_step_limit", r.rk4_step_limit * 1e6, "µs", "RK4 stability limit");
  report.add_value("steps", double(r.steps), "-", "integration steps");
  report.add_value("integration_time", r.wall_time * 1e3, "ms", "wall time of the run");
}

void report_sweep(const LateralTrainParameters& p, double settle, Report& report)
{
  const auto start = std::chrono::steady_clock::now();
  const std::vector<LateralTrainSweepPoint> points = lateral_train_sweep(
      p.setup, p.sweep_speeds, settle, p.window_periods, p.steps_per_mesh_period);
  std::vector<std::string> columns{"input_speed", "status", "time_step"}, units{"rpm", "-", "us"};
  const std::size_t n_meshes = p.setup.rotational.spec_mesh_contact_ratio.size();
  for (std::size_t m = 0; m < n_meshes; ++m)
  {
    columns.push_back("kv_mesh" + std::to_string(m + 1));
    units.push_back("-");
  }
  const std::vector<unsigned int> central = central_bodies(p.setup.train);
  for (const char* what : {"orbit_", "bearing_force_"})
    for (const unsigned int b : central)
    {
      columns.push_back(what + p.setup.train.bodies[b].name);
      units.push_back(what[0] == 'o' ? "um" : "N");
    }
  auto& table = report.add_table("lateral_train_speed_sweep", columns, units);
  table.set_categories("status", sweep_status_categories());
  for (const LateralTrainSweepPoint& point : points)
  {
    std::vector<double> row{point.input_speed / rpm, double(static_cast<int>(point.status)),
                            point.time_step * 1e6};
    for (std::size_t m = 0; m < n_meshes; ++m)
      row.push_back(point.summary.kv_max.empty() ? 0. : point.summary.kv_max[m]);
    for (const unsigned int b : central)
      row.push_back(point.summary.kv_max.empty() ? 0. : point.summary.orbit_amplitude[b] * 1e6);
    for (const unsigned int b : central)
      row.push_back(point.summary.kv_max.empty() ? 0. : point.summary.bearing_force_max[b]);
    table.add_row(row);
  }
  report.add_text("lateral train sweep", "status: " + sweep_status_meanings());
  report.add_value("lateral_sweep_time",
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                   "s", "wall time of the sweep");
}
} // namespace

void run_lateral_train_dynamics(dealii::ParameterHandler& prm, CommandContext& context)
{
  const TrainModel rotational = rotational_model(prm);
  const LateralTrainParameters p = parse_lateral_train_parameters(prm, rotational);
  const LateralTrainModel model(p.setup.train);
  Report& report = context.report;
  report.add_text("model", "planar lateral-torsional train (Lin & Parker 1999 generalised to "
                           "several stages): " +
                               std::to_string(model.n_bodies()) + " bodies, " +
                               std::to_string(model.free_dofs().size()) + " DOF");
  std::string bodies;
  for (unsigned int b = 0; b < model.n_bodies(); ++b)
    bodies += (b ? ", " : "") + std::to_string(b + 1) + " " + p.setup.train.bodies[b].name;
  report.add_text("bodies", bodies);
  report_modes(model, report);
  report_statics(p.setup, model, report);
  const double settle = p.settle_time > 0. ? p.settle_time : lateral_train_decay_time(model);
  if (!std::isfinite(settle) || settle * p.input_speed > 1e6)
    throw InputError("Simulation/steady state start",
                     "the slowest mode barely decays (undamped?): give the settling time");
  report_response(p, settle, report);
  if (!p.sweep_speeds.empty())
    report_sweep(p, settle, report);
  if (context.writes_files())
  {
    const TemporaryCsv csv(report, "lateral_train_orbit");
    context.plot("plot_lateral.py", {"orbit", csv.path()}, "lateral_train_orbit.png",
                 "orbits of the central members (x, y)");
  }
}
} // namespace gearstiff::app
