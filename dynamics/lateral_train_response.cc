#include "dynamics/lateral_train_response.h"

#include "dynamics/fields.h"
#include "errors/errors.h"
#include "errors/format.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace gearstiff::dynamics
{
namespace
{
// The right-hand side: constant springs and the mesh lines' k(x) at time t.
struct Rhs
{
  const LateralTrainModel& model;
  const LateralTrainSetup& setup;
  double speed = 0.;              // [rad/s]
  Eigen::VectorXd force;          // [N] external: input torque, output load (full coordinates)
  Eigen::VectorXd inverse_mass;   // [1/kg] 0 on held coordinates
  std::vector<double> mesh_force; // [N] per line, of the last evaluation

  double mesh_stiffness(unsigned int line, double t) const
  {
    const Mesh& mesh = setup.rotational.train.meshes[line];
    const double x = mesh.initial_position + mesh.position_ratio * speed * t;
    return mesh.stiffness.stiffness(x, mesh.contact_ratio);
  }
  void operator()(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, Eigen::VectorXd& a)
  {
    a = force;
    for (const LateralTrainModel::Spring& s : model.springs())
    {
      double d = s.preload, rate = 0.;
      for (const auto& [i, c] : s.terms)
        d += c * q[i], rate += c * v[i];
      const double k = s.group == 3 ? mesh_stiffness(s.planet, t) : s.stiffness;
      const double f = k * d + s.damping * rate;
      if (s.group == 3)
        mesh_force[s.planet] = f;
      for (const auto& [i, c] : s.terms)
        a[i] -= c * f;
    }
    a = a.cwiseProduct(inverse_mass);
  }
};

Rhs make_rhs(const LateralTrainModel& model, const LateralTrainSetup& setup,
             const LateralTrainStatics& statics, double speed)
{
  Rhs rhs{model,
          setup,
          speed,
          Eigen::VectorXd::Zero(model.n_dofs()),
          Eigen::VectorXd::Zero(model.n_dofs()),
          std::vector<double>(setup.train.meshes.size())};
  const LateralTrain& train = setup.train;
  rhs.force[LateralTrainModel::dof(setup.input_body, 2)] +=
      setup.input_torque / train.bodies[setup.input_body].radius;
  rhs.force[LateralTrainModel::dof(setup.output_body, 2)] +=
      statics.output_torque / train.bodies[setup.output_body].radius;
  for (const unsigned int i : model.free_dofs())
    rhs.inverse_mass[i] = 1. / model.mass()[i];
  return rhs;
}

// Window statistics of one accepted state.
struct Tracker
{
  const LateralTrainModel& model;
  const LateralTrainSetup& setup;
  const std::vector<double>& static_force;
  double half_time = 0.;
  LateralTrainSummary summary;
  Eigen::MatrixXd low, high; // per body: global x, y extremes

  void add(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
           const std::vector<double>& mesh_force)
  {
    for (std::size_t i = 0; i < mesh_force.size(); ++i)
    {
      const double kv = mesh_force[i] / static_force[i];
      double& largest = summary.kv_max[setup.train.meshes[i].spec_mesh];
      largest = std::max(largest, kv);
      double& half = t < half_time ? summary.kv_first_half : summary.kv_second_half;
      half = std::max(half, kv);
      summary.mesh_force_min = std::min(summary.mesh_force_min, mesh_force[i]);
    }
    for (unsigned int b = 0; b < model.n_bodies(); ++b)
    {
      const LateralBody& body = setup.train.bodies[b];
      const double c = std::cos(body.frame_angle), s = std::sin(body.frame_angle);
      const unsigned int i = LateralTrainModel::dof(b, 0);
      const Eigen::Vector2d r(c * q[i] - s * q[i + 1], s * q[i] + c * q[i + 1]);
      const Eigen::Vector2d rate(c * v[i] - s * v[i + 1], s * v[i] + c * v[i + 1]);
      low.row(b) = low.row(b).cwiseMin(r.transpose());
      high.row(b) = high.row(b).cwiseMax(r.transpose());
      summary.bearing_force_max[b] =
          std::max(summary.bearing_force_max[b],
                   (body.bearing_stiffness * r + body.bearing_damping * rate).norm());
    }
  }
};

Tracker make_tracker(const LateralTrainModel& model, const LateralTrainSetup& setup,
                     const std::vector<double>& static_force, double half_time)
{
  const unsigned int n = model.n_bodies();
  Tracker tracker{model, setup, static_force, half_time, {}, {}, {}};
  tracker.summary.kv_max.assign(setup.rotational.spec_mesh_contact_ratio.size(), 0.);
  tracker.summary.mesh_force_min = std::numeric_limits<double>::infinity();
  tracker.summary.orbit_amplitude = Eigen::VectorXd::Zero(n);
  tracker.summary.bearing_force_max = Eigen::VectorXd::Zero(n);
  tracker.low = Eigen::MatrixXd::Constant(n, 2, std::numeric_limits<double>::infinity());
  tracker.high = -tracker.low;
  return tracker;
}
} // namespace

double lateral_train_step_limit(const LateralTrainSetup& setup)
{
  LateralTrain stiffest = setup.train;
  for (std::size_t i = 0; i < stiffest.meshes.size(); ++i)
  {
    const Mesh& mesh = setup.rotational.train.meshes[i];
    stiffest.meshes[i].stiffness = mesh.stiffness.max_stiffness(mesh.contact_ratio);
  }
  const double f = LateralTrainModel(stiffest).modes().frequencies.maxCoeff();
  return 2. * std::sqrt(2.) / (2. * M_PI * f);
}

double lateral_train_decay_time(const LateralTrainModel& model)
{
  const LateralTrainModes modes = model.modes();
  double slowest = std::numeric_limits<double>::infinity();
  for (Eigen::Index k = 0; k < modes.frequencies.size(); ++k)
    if (modes.frequencies[k] > 0.)
    {
      const Eigen::VectorXd phi = modes.shapes.col(k);
      slowest = std::min(slowest, 0.5 * phi.dot(model.damping() * phi));
    }
  return slowest > 0. ? std::log(1000.) / slowest : std::numeric_limits<double>::infinity();
}

LateralTrainResponse integrate_lateral_train(const LateralTrainSetup& setup,
                                             const LateralTrainRun& run)
{
  const auto start = std::chrono::steady_clock::now();
  const LateralTrainModel model(setup.train);
  LateralTrainResponse response;
  response.rk4_step_limit = lateral_train_step_limit(setup);
  if (!(run.time_step > 0.) ||
      (run.time_step > response.rk4_step_limit && !run.allow_unstable_step))
    throw InputError(field::simulation("time_step"),
                     format_number(run.time_step * 1e6, 4) + " µs is above the RK4 limit " +
                         format_number(response.rk4_step_limit * 1e6, 4) +
                         " µs of the lateral model (highest mode at the largest mesh stiffness)");
  const LateralTrainStatics statics =
      model.static_state(setup.input_body, setup.output_body, setup.input_torque);
  Rhs rhs = make_rhs(model, setup, statics, run.input_speed);
  const double h = run.time_step, end = run.settle_time + run.window;
  Tracker tracker =
      make_tracker(model, setup, statics.mesh_force, run.settle_time + 0.5 * run.window);
  Eigen::VectorXd q = statics.displacement, v = Eigen::VectorXd::Zero(model.n_dofs());
  Eigen::VectorXd a1, a2, a3, a4;
  const unsigned long steps = static_cast<unsigned long>(std::ceil(end / h));
  for (unsigned long n = 0; n < steps; ++n)
  {
    const double t = n * h;
    rhs(t, q, v, a1);
    if (t >= run.settle_time)
    {
      tracker.add(t, q, v, rhs.mesh_force);
      const unsigned long window_step = n - static_cast<unsigned long>(run.settle_time / h);
      if (run.record_stride > 0 && window_step % run.record_stride == 0)
      {
        Eigen::VectorXd xy(2 * run.recorded_bodies.size());
        for (std::size_t j = 0; j < run.recorded_bodies.size(); ++j)
          xy.segment<2>(2 * j) = q.segment<2>(LateralTrainModel::dof(run.recorded_bodies[j], 0));
        response.time.push_back(t);
        response.position.push_back(xy);
      }
    }
    rhs(t + 0.5 * h, q + 0.5 * h * v, v + 0.5 * h * a1, a2);
    rhs(t + 0.5 * h, q + 0.5 * h * (v + 0.5 * h * a1), v + 0.5 * h * a2, a3);
    rhs(t + h, q + h * (v + 0.5 * h * a2), v + h * a3, a4);
    q += h * v + h * h / 6. * (a1 + a2 + a3);
    v += h / 6. * (a1 + 2. * a2 + 2. * a3 + a4);
    if (!q.allFinite())
      throw SolverFailure(
          "RK4", "the lateral state turned non-finite at t = " + format_number(t, 4) + " s");
  }
  for (unsigned int b = 0; b < model.n_bodies(); ++b)
    tracker.summary.orbit_amplitude[b] =
        0.5 * (tracker.high.row(b) - tracker.low.row(b)).maxCoeff();
  response.summary = tracker.summary;
  response.steps = steps;
  response.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return response;
}

std::vector<LateralTrainSweepPoint>
lateral_train_sweep(const LateralTrainSetup& setup, const std::vector<double>& speeds,
                    double settle_time, unsigned int window_periods, unsigned int steps_per_period)
{
  const double limit = lateral_train_step_limit(setup);
  std::vector<LateralTrainSweepPoint> points;
  for (const double speed : speeds)
  {
    double slowest = std::numeric_limits<double>::infinity(), fastest = 0.;
    for (const Mesh& mesh : setup.rotational.train.meshes)
    {
      slowest = std::min(slowest, mesh.position_ratio * speed);
      fastest = std::max(fastest, mesh.position_ratio * speed);
    }
    LateralTrainRun run;
    run.input_speed = speed;
    run.time_step = std::min(1. / (fastest * steps_per_period), 0.9 * limit);
    run.settle_time = settle_time;
    run.window = window_periods / slowest;
    LateralTrainSweepPoint point;
    point.input_speed = speed;
    point.time_step = run.time_step;
    try
    {
      const LateralTrainResponse r = integrate_lateral_train(setup, run);
      point.summary = r.summary;
      point.steps = r.steps;
      const double kv = std::max(r.summary.kv_first_half, r.summary.kv_second_half);
      point.status = r.summary.mesh_force_min < 0. ? LateralTrainStatus::contact_loss
                     : std::abs(r.summary.kv_first_half - r.summary.kv_second_half) > 0.05 * kv
                         ? LateralTrainStatus::not_steady
                         : LateralTrainStatus::valid;
    }
    catch (const SolverFailure&)
    {
      point.status = LateralTrainStatus::diverged;
    }
    points.push_back(point);
  }
  return points;
}
} // namespace gearstiff::dynamics
