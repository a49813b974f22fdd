#include "dynamics/integrators.h"

#include "dynamics/fields.h"
#include "errors/errors.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <sstream>

namespace gearstiff::dynamics
{
std::string integrator_name(IntegratorType type)
{
  switch (type)
  {
  case IntegratorType::rk4:
    return "RK4";
  case IntegratorType::adaptive_rk:
    return "Dormand-Prince 5(4)";
  case IntegratorType::hht_alpha:
    return "HHT-alpha";
  }
  return "?";
}

namespace
{
// Energy growth beyond this factor is taken as divergence. A physical linear response stays
// far below it: even a resonance with 0.5 % damping amplifies the static deflection about
// 100-fold (energy 10⁴), and an unstable RK4 mode grows by |R| ≥ 1.01 per step, so it crosses
// 10⁶ within a few hundred steps.
constexpr double divergence_energy_factor = 1e6;
constexpr unsigned int check_interval = 16; // steps between energy checks

std::string format_number(double value)
{
  std::ostringstream s;
  s.precision(3);
  s << value;
  return s.str();
}

// Stores the output points and watches for divergence; shared by all three methods.
class Recorder
{
public:
  Recorder(const TorsionalModel& model, Trajectory& trajectory, const IntegratorSettings& settings,
           const double* angle, const double* velocity)
      : model(model), trajectory(trajectory), settings(settings), n(model.n_dofs())
  {
    const StaticState statics = model.static_state(false);
    double strain = 0.;
    for (unsigned int m = 0; m < model.n_meshes(); ++m)
      strain += 0.5 * statics.mesh_force[m] * statics.deflection[m];
    reference_energy = std::max(
        {model.vibration_energy(0., angle, velocity), strain, std::numeric_limits<double>::min()});
    // Sized once: growing vectors inside the step loop would cost more than the steps.
    const std::size_t expected =
        static_cast<std::size_t>(settings.end_time / settings.time_step / settings.record_stride) +
        2;
    trajectory.time.resize(expected);
    trajectory.angle.resize(expected * n);
    trajectory.velocity.resize(expected * n);
  }

  void output(unsigned long index, double time, const double* angle, const double* velocity)
  {
    if (settings.observer)
      settings.observer(time, angle, velocity);
    if (index % settings.record_stride != 0)
      return;
    if (stored == trajectory.time.size())
    {
      trajectory.time.resize(2 * stored);
      trajectory.angle.resize(2 * stored * n);
      trajectory.velocity.resize(2 * stored * n);
    }
    trajectory.time[stored] = time;
    std::copy(angle, angle + n, trajectory.angle.begin() + stored * n);
    std::copy(velocity, velocity + n, trajectory.velocity.begin() + stored * n);
    ++stored;
  }

  // Drops the unused tail of the preallocated arrays.
  void finish()
  {
    trajectory.time.resize(stored);
    trajectory.angle.resize(stored * n);
    trajectory.velocity.resize(stored * n);
  }

  void check(double time, const double* angle, const double* velocity)
  {
    bool finite = true;
    for (unsigned int i = 0; i < n; ++i)
      finite = finite && std::isfinite(angle[i]) && std::isfinite(velocity[i]);
    const double energy = finite ? model.vibration_energy(time, angle, velocity) : 0.;
    if (finite && energy <= divergence_energy_factor * reference_energy)
      return;
    std::ostringstream reason;
    reason.precision(4);
    reason << "diverged at t = " << time << " s ("
           << (finite
                   ? "vibration energy grew by a factor " + format_number(energy / reference_energy)
                   : std::string("non-finite state"))
           << ") with step " << settings.time_step << " s; estimated RK4 stability limit "
           << trajectory.rk4_step_limit << " s (highest natural frequency "
           << trajectory.highest_frequency / (2. * M_PI) << " Hz)";
    // Below the RK4 limit, or with a stable method, the growth is the model's own: a parametric
    // resonance of the time-varying mesh stiffness. Real teeth would separate and bound it, which
    // this linear model does not represent, so no K_v exists there.
    const bool numerical =
        settings.type == IntegratorType::rk4 && settings.time_step > trajectory.rk4_step_limit;
    if (!numerical)
      reason << "; the step is stable, so the linear model itself is unstable here "
                "(parametric resonance of the mesh stiffness; tooth separation not modelled)";
    throw SolverFailure(numerical ? trajectory.method
                                  : "torsional model (" + trajectory.method + ")",
                        reason.str());
  }

private:
  const TorsionalModel& model;
  Trajectory& trajectory;
  const IntegratorSettings& settings;
  const unsigned int n;
  double reference_energy = 0.;
  std::size_t stored = 0;
};

unsigned long fixed_step_count(const IntegratorSettings& settings)
{
  return static_cast<unsigned long>(std::ceil(settings.end_time / settings.time_step - 1e-9));
}

// One classical RK4 step of length h from (angle, velocity) at t into (angle_out, velocity_out);
// `work` holds 9·n doubles.
void rk4_step(const TorsionalModel& model, double t, double h, const double* angle,
              const double* velocity, double* angle_out, double* velocity_out, double* work)
{
  const unsigned int n = model.n_dofs();
  double *a1 = work, *a2 = work + n, *a3 = work + 2 * n, *a4 = work + 3 * n, *phi = work + 4 * n,
         *omega2 = work + 5 * n, *omega3 = work + 6 * n, *omega4 = work + 7 * n;
  model.acceleration(t, angle, velocity, a1);
  for (unsigned int i = 0; i < n; ++i)
  {
    phi[i] = angle[i] + 0.5 * h * velocity[i];
    omega2[i] = velocity[i] + 0.5 * h * a1[i];
  }
  model.acceleration(t + 0.5 * h, phi, omega2, a2);
  for (unsigned int i = 0; i < n; ++i)
  {
    phi[i] = angle[i] + 0.5 * h * omega2[i];
    omega3[i] = velocity[i] + 0.5 * h * a2[i];
  }
  model.acceleration(t + 0.5 * h, phi, omega3, a3);
  for (unsigned int i = 0; i < n; ++i)
  {
    phi[i] = angle[i] + h * omega3[i];
    omega4[i] = velocity[i] + h * a3[i];
  }
  model.acceleration(t + h, phi, omega4, a4);
  for (unsigned int i = 0; i < n; ++i)
  {
    angle_out[i] = angle[i] + h / 6. * (velocity[i] + 2. * omega2[i] + 2. * omega3[i] + omega4[i]);
    velocity_out[i] = velocity[i] + h / 6. * (a1[i] + 2. * a2[i] + 2. * a3[i] + a4[i]);
  }
}

// Event location for nonlinear meshes (integrate()'s comment): the contact regime of every
// nonlinear mesh, and the first switch inside a trial step.
class SwitchLocator
{
public:
  SwitchLocator(const TorsionalModel& model, const IntegratorSettings& settings, double t,
                const double* angle, const double* velocity)
      : model(model), settings(settings), m(model.n_meshes()), z0(m), r0(m), z1(m), r1(m),
        regime(m, ContactRegime::drive)
  {
    model.flank_approach(t, angle, velocity, z0.data(), r0.data());
    for (unsigned int k = 0; k < m; ++k)
      if (model.is_nonlinear(k))
        regime[k] = contact_regime(z0[k], model.free_play(k));
  }

  // The start of the next trial step (after an accepted step or a switch).
  void restart(double t, const double* angle, const double* velocity)
  {
    model.flank_approach(t, angle, velocity, z0.data(), r0.data());
  }

  // The first switch in the trial step [t, t + h] ending in (angle, velocity): its fraction
  // s ∈ (0, 1] of the step, the mesh and the regime it enters; s = 2 when none.
  double first_switch(double t, double h, const double* angle, const double* velocity,
                      unsigned int& mesh, ContactRegime& entered)
  {
    model.flank_approach(t + h, angle, velocity, z1.data(), r1.data());
    double first = 2.;
    for (unsigned int k = 0; k < m; ++k)
    {
      if (!model.is_nonlinear(k))
        continue;
      const double b = model.free_play(k);
      // Cubic Hermite interpolant of z over the step, s ∈ [0, 1].
      const double p0 = z0[k], p1 = z1[k], d0 = r0[k] * h, d1 = r1[k] * h;
      const auto z = [&](double s)
      {
        const double s2 = s * s, s3 = s2 * s;
        return (2. * s3 - 3. * s2 + 1.) * p0 + (s3 - 2. * s2 + s) * d0 + (-2. * s3 + 3. * s2) * p1 +
               (s3 - s2) * d1;
      };
      // Leaving the current regime: the signed distance to each of its boundaries (positive
      // inside); the start counts as inside (it may sit on the boundary after a switch).
      struct Boundary
      {
        double level, sign;
        ContactRegime next;
      };
      Boundary boundaries[2];
      unsigned int count = 0;
      if (regime[k] == ContactRegime::drive)
        boundaries[count++] = {0., 1., b > 0. ? ContactRegime::separated : ContactRegime::back};
      else if (regime[k] == ContactRegime::back)
        boundaries[count++] = {-b, -1., b > 0. ? ContactRegime::separated : ContactRegime::drive};
      else
      {
        boundaries[count++] = {0., -1., ContactRegime::drive};
        boundaries[count++] = {-b, 1., ContactRegime::back};
      }
      for (unsigned int j = 0; j < count; ++j)
      {
        const Boundary& boundary = boundaries[j];
        const auto inside = [&](double s) { return boundary.sign * (z(s) - boundary.level); };
        double previous = 0.;
        for (unsigned int i = 1; i <= samples && double(i - 1) / samples < first; ++i)
        {
          const double s = double(i) / samples;
          if (inside(s) >= 0.)
          {
            previous = s;
            continue;
          }
          double low = previous, high = s;
          for (int it = 0; it < 40; ++it)
          {
            const double middle = 0.5 * (low + high);
            (inside(middle) >= 0. ? low : high) = middle;
          }
          if (high < first)
          {
            first = high;
            mesh = k;
            entered = boundary.next;
          }
          break;
        }
      }
    }
    return first;
  }

  void switch_to(double time, unsigned int mesh, ContactRegime entered)
  {
    if (settings.contact_observer)
      settings.contact_observer(time, mesh, regime[mesh], entered);
    regime[mesh] = entered;
  }

private:
  static constexpr unsigned int samples = 16;
  const TorsionalModel& model;
  const IntegratorSettings& settings;
  const unsigned int m;
  std::vector<double> z0, r0, z1, r1;
  std::vector<ContactRegime> regime;
};

void run_rk4(const TorsionalModel& model, std::vector<double> angle, std::vector<double> velocity,
             const IntegratorSettings& settings, Trajectory& trajectory)
{
  const unsigned int n = model.n_dofs();
  const double h = settings.time_step;
  std::vector<double> work(9 * n), next_angle(n), next_velocity(n);
  Recorder recorder(model, trajectory, settings, angle.data(), velocity.data());
  recorder.output(0, 0., angle.data(), velocity.data());
  const unsigned long steps = fixed_step_count(settings);
  if (!model.has_nonlinear_meshes())
  {
    for (unsigned long step = 0; step < steps; ++step)
    {
      rk4_step(model, step * h, h, angle.data(), velocity.data(), angle.data(), velocity.data(),
               work.data());
      if ((step + 1) % check_interval == 0 || step + 1 == steps)
        recorder.check((step + 1) * h, angle.data(), velocity.data());
      recorder.output(step + 1, (step + 1) * h, angle.data(), velocity.data());
    }
    trajectory.cost.function_evaluations = 4 * steps;
  }
  else
  {
    SwitchLocator locator(model, settings, 0., angle.data(), velocity.data());
    unsigned long substeps = 0;
    for (unsigned long step = 0; step < steps; ++step)
    {
      const double t_end = (step + 1) * h;
      double t = step * h;
      for (unsigned int switches = 0;; ++switches)
      {
        if (switches > 1000)
          throw SolverFailure(trajectory.method + " event location",
                              "more than 1000 contact changes within one step at t = " +
                                  format_number(t) + " s (chattering contact)");
        const double span = t_end - t;
        rk4_step(model, t, span, angle.data(), velocity.data(), next_angle.data(),
                 next_velocity.data(), work.data());
        ++substeps;
        unsigned int mesh = 0;
        ContactRegime entered = ContactRegime::drive;
        const double s =
            locator.first_switch(t, span, next_angle.data(), next_velocity.data(), mesh, entered);
        if (s > 1.)
        {
          angle.swap(next_angle);
          velocity.swap(next_velocity);
          break;
        }
        // Step to the switch (a step too short to matter is not taken), then on from there.
        const double to_switch = s * span;
        if (to_switch > 1e-12 * h)
        {
          rk4_step(model, t, to_switch, angle.data(), velocity.data(), angle.data(),
                   velocity.data(), work.data());
          ++substeps;
          t += to_switch;
        }
        locator.switch_to(t, mesh, entered);
        ++trajectory.cost.located_switches;
        locator.restart(t, angle.data(), velocity.data());
      }
      locator.restart(t_end, angle.data(), velocity.data());
      if ((step + 1) % check_interval == 0 || step + 1 == steps)
        recorder.check(t_end, angle.data(), velocity.data());
      recorder.output(step + 1, t_end, angle.data(), velocity.data());
    }
    trajectory.cost.function_evaluations = 4 * substeps;
  }
  recorder.finish();
  trajectory.cost.steps = steps;
  trajectory.cost.smallest_step = trajectory.cost.largest_step = h;
}

void run_hht(const TorsionalModel& model, std::vector<double> angle, std::vector<double> velocity,
             const IntegratorSettings& settings, Trajectory& trajectory)
{
  const double alpha = settings.hht_alpha;
  if (!(alpha >= -1. / 3. && alpha <= 0.))
    throw InputError(field::simulation("hht_alpha"),
                     "must lie in [-1/3, 0] for unconditional stability, got " +
                         std::to_string(alpha));
  const double beta = 0.25 * (1. - alpha) * (1. - alpha);
  const double gamma = 0.5 - alpha;
  const unsigned int n = model.n_dofs();
  const double h = settings.time_step;
  const Eigen::VectorXd& torque = model.external_torques();
  const Eigen::MatrixXd mass = model.inertias().asDiagonal();

  Eigen::Map<Eigen::VectorXd> u(angle.data(), n), v(velocity.data(), n);
  Eigen::MatrixXd K, C;
  model.linearization(0., K, C);
  Eigen::VectorXd internal = K * u + C * v;
  Eigen::VectorXd a = model.inertias().cwiseInverse().cwiseProduct(torque - internal);
  Eigen::PartialPivLU<Eigen::MatrixXd> lu(n);

  Recorder recorder(model, trajectory, settings, angle.data(), velocity.data());
  recorder.output(0, 0., angle.data(), velocity.data());
  const unsigned long steps = fixed_step_count(settings);
  for (unsigned long step = 0; step < steps; ++step)
  {
    const double t1 = (step + 1) * h;
    model.linearization(t1, K, C);
    // Newmark predictors; HHT-α balances M·a₁ + (1+α)·f_int(t₁) − α·f_int(t₀) = T.
    const Eigen::VectorXd u_pred = u + h * v + h * h * (0.5 - beta) * a;
    const Eigen::VectorXd v_pred = v + h * (1. - gamma) * a;
    lu.compute(mass + (1. + alpha) * (beta * h * h * K + gamma * h * C));
    a = lu.solve(torque + alpha * internal - (1. + alpha) * (K * u_pred + C * v_pred));
    u = u_pred + beta * h * h * a;
    v = v_pred + gamma * h * a;
    internal = K * u + C * v;
    if ((step + 1) % check_interval == 0 || step + 1 == steps)
      recorder.check(t1, angle.data(), velocity.data());
    recorder.output(step + 1, t1, angle.data(), velocity.data());
  }
  recorder.finish();
  trajectory.cost.steps = steps;
  trajectory.cost.function_evaluations = steps + 1;
  trajectory.cost.linear_solves = steps;
  trajectory.cost.smallest_step = trajectory.cost.largest_step = h;
}

// Dormand & Prince (1980) 5(4) tableau, the 5th-order solution propagated (FSAL).
constexpr double dp_c[7] = {0., 1. / 5., 3. / 10., 4. / 5., 8. / 9., 1., 1.};
constexpr double dp_a[7][6] = {
    {},
    {1. / 5.},
    {3. / 40., 9. / 40.},
    {44. / 45., -56. / 15., 32. / 9.},
    {19372. / 6561., -25360. / 2187., 64448. / 6561., -212. / 729.},
    {9017. / 3168., -355. / 33., 46732. / 5247., 49. / 176., -5103. / 18656.},
    {35. / 384., 0., 500. / 1113., 125. / 192., -2187. / 6784., 11. / 84.}};
constexpr double dp_error[7] = {71. / 57600.,      0.,         -71. / 16695., 71. / 1920.,
                                -17253. / 339200., 22. / 525., -1. / 40.};

// Absolute tolerances of the adaptive method per state component (angles, then speeds): on the
// scale of the static deflection and of a vibration at the highest natural frequency with that
// amplitude, so the error test is unit-consistent.
std::vector<double> absolute_tolerances(const TorsionalModel& model,
                                        const std::vector<double>& angle,
                                        const std::vector<double>& velocity, double rtol,
                                        double highest_frequency)
{
  const unsigned int n = model.n_dofs();
  const StaticState statics = model.static_state(false);
  double angle_scale = 0.;
  for (unsigned int i = 0; i < n; ++i)
    angle_scale = std::max({angle_scale, std::abs(statics.angle[i]), std::abs(angle[i]),
                            std::abs(velocity[i]) / highest_frequency});
  if (angle_scale == 0.)
    angle_scale = 1e-12;
  std::vector<double> absolute(2 * n);
  for (unsigned int i = 0; i < n; ++i)
  {
    absolute[i] = rtol * angle_scale;
    absolute[n + i] = rtol * angle_scale * highest_frequency;
  }
  return absolute;
}

// One Dormand–Prince trial step of `step` from (t, y) with k[0] = f(t, y): stages k[1..6], the
// 5th-order solution in y_new (stage 7, FSAL); returns the scaled rms error estimate (1e10 when
// not finite).
template <typename Rhs>
double dormand_prince_trial(const Rhs& rhs, double t, double step, const std::vector<double>& y,
                            std::vector<std::vector<double>>& k, std::vector<double>& stage,
                            std::vector<double>& y_new, const std::vector<double>& absolute,
                            double rtol)
{
  const std::size_t size = y.size();
  for (unsigned int s = 1; s < 7; ++s)
  {
    for (unsigned int i = 0; i < size; ++i)
    {
      double sum = 0.;
      for (unsigned int j = 0; j < s; ++j)
        sum += dp_a[s][j] * k[j][i];
      stage[i] = y[i] + step * sum;
    }
    rhs(t + dp_c[s] * step, stage, k[s]);
  }
  y_new = stage; // stage 7 is the 5th-order solution
  double error = 0.;
  for (unsigned int i = 0; i < size; ++i)
  {
    double e = 0.;
    for (unsigned int j = 0; j < 7; ++j)
      e += dp_error[j] * k[j][i];
    const double scale = absolute[i] + rtol * std::max(std::abs(y[i]), std::abs(y_new[i]));
    error += (step * e / scale) * (step * e / scale);
  }
  error = std::sqrt(error / size);
  return std::isfinite(error) ? error : 1e10;
}

void run_adaptive(const TorsionalModel& model, const std::vector<double>& angle,
                  const std::vector<double>& velocity, const IntegratorSettings& settings,
                  Trajectory& trajectory)
{
  const double rtol = settings.relative_tolerance;
  if (!(rtol > 0. && rtol < 1e-1))
    throw InputError(field::simulation("relative_tolerance"), "must lie in (0, 0.1)");
  const unsigned int n = model.n_dofs();
  const unsigned int size = 2 * n;
  std::vector<double> y(size), y_new(size), stage(size);
  std::copy(angle.begin(), angle.end(), y.begin());
  std::copy(velocity.begin(), velocity.end(), y.begin() + n);
  std::vector<std::vector<double>> k(7, std::vector<double>(size));
  auto rhs = [&](double t, const std::vector<double>& state, std::vector<double>& out)
  {
    std::copy(state.begin() + n, state.end(), out.begin());
    model.acceleration(t, state.data(), state.data() + n, out.data() + n);
    ++trajectory.cost.function_evaluations;
  };
  const std::vector<double> absolute =
      absolute_tolerances(model, angle, velocity, rtol, trajectory.highest_frequency);

  Recorder recorder(model, trajectory, settings, y.data(), y.data() + n);
  recorder.output(0, 0., y.data(), y.data() + n);
  const unsigned long outputs = fixed_step_count(settings);
  double t = 0.;
  double h = std::min(settings.time_step, 0.1 / trajectory.highest_frequency);
  trajectory.cost.smallest_step = std::numeric_limits<double>::infinity();
  rhs(t, y, k[0]);
  for (unsigned long output = 1; output <= outputs; ++output)
  {
    const double t_output = output * settings.time_step;
    while (t < t_output * (1. - 1e-14))
    {
      const bool clipped = t + h > t_output;
      const double step = clipped ? t_output - t : h;
      const double error = dormand_prince_trial(rhs, t, step, y, k, stage, y_new, absolute, rtol);
      const double factor = std::min(5., std::max(0.2, 0.9 * std::pow(error, -0.2)));
      if (error <= 1.)
      {
        t = clipped ? t_output : t + step;
        y.swap(y_new);
        k[0].swap(k[6]);
        ++trajectory.cost.steps;
        trajectory.cost.smallest_step = std::min(trajectory.cost.smallest_step, step);
        trajectory.cost.largest_step = std::max(trajectory.cost.largest_step, step);
        if (trajectory.cost.steps % check_interval == 0)
          recorder.check(t, y.data(), y.data() + n);
        if (!clipped)
          h = std::min(step * factor, settings.time_step);
      }
      else
      {
        ++trajectory.cost.rejected_steps;
        h = step * factor;
      }
      if (h < 1e-12 * settings.end_time)
        throw SolverFailure(trajectory.method, "step size collapsed to " + std::to_string(h) +
                                                   " s at t = " + std::to_string(t) + " s");
    }
    recorder.check(t, y.data(), y.data() + n);
    recorder.output(output, t, y.data(), y.data() + n);
  }
  recorder.finish();
}
} // namespace

WorkEstimate estimate_work(const TorsionalModel& model, const IntegratorSettings& settings,
                           double bytes_per_step)
{
  WorkEstimate work;
  work.steps = std::ceil(settings.end_time / settings.time_step);
  const double stored = work.steps / std::max(1u, settings.record_stride) + 2.;
  work.memory = stored * (1. + 2. * model.n_dofs()) * sizeof(double) + work.steps * bytes_per_step;
  return work;
}

void check_work(const WorkEstimate& work, const std::string& parameter, const std::string& hint)
{
  if (std::isfinite(work.steps) && work.steps <= max_integration_steps &&
      work.memory <= max_integration_memory)
    return;
  std::ostringstream reason;
  reason.precision(3);
  reason << "the run would need " << work.steps << " steps and " << work.memory / 1e9
         << " GB of results (limits " << max_integration_steps << " steps, "
         << max_integration_memory / 1e9 << " GB); " << hint;
  throw InputError(parameter, reason.str());
}

Trajectory integrate(const TorsionalModel& model, const std::vector<double>& initial_angle,
                     const std::vector<double>& initial_velocity,
                     const IntegratorSettings& settings)
{
  if (initial_angle.size() != model.n_dofs() || initial_velocity.size() != model.n_dofs())
    throw InputError("initial state", "needs one angle and one speed per gear");
  if (!(settings.time_step > 0.) || !std::isfinite(settings.time_step))
    throw InputError(field::simulation("time_step"), "must be positive");
  if (!(settings.end_time >= settings.time_step))
    throw InputError(field::simulation("simulated_time"), "must be at least one time step");
  if (settings.record_stride == 0)
    throw InputError(field::simulation("output_stride"), "must be at least 1");
  check_work(estimate_work(model, settings), field::simulation("time_step"),
             "enlarge the time step or shorten the simulated time");

  Trajectory trajectory;
  trajectory.n_dofs = model.n_dofs();
  trajectory.method = integrator_name(settings.type);
  trajectory.rk4_step_limit = model.rk4_step_limit();
  trajectory.highest_frequency = model.highest_natural_frequency();

  if (settings.type == IntegratorType::rk4 && settings.time_step > trajectory.rk4_step_limit &&
      !settings.allow_unstable_step)
  {
    std::ostringstream reason;
    reason.precision(4);
    reason << settings.time_step << " s exceeds the estimated RK4 stability limit "
           << trajectory.rk4_step_limit << " s (highest natural frequency "
           << trajectory.highest_frequency / (2. * M_PI)
           << " Hz); use a smaller step, the implicit HHT-alpha method, or set "
              "'Simulation/allow unstable step = true' to run anyway";
    throw InputError(field::simulation("time_step"), reason.str());
  }

  if (model.has_nonlinear_meshes() && settings.type != IntegratorType::rk4)
    throw InputError(field::simulation("integrator"),
                     "the nonlinear mesh model needs RK4 (with located contact changes); " +
                         integrator_name(settings.type) + " would step over them");

  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  switch (settings.type)
  {
  case IntegratorType::rk4:
    run_rk4(model, initial_angle, initial_velocity, settings, trajectory);
    break;
  case IntegratorType::hht_alpha:
    run_hht(model, initial_angle, initial_velocity, settings, trajectory);
    break;
  case IntegratorType::adaptive_rk:
    run_adaptive(model, initial_angle, initial_velocity, settings, trajectory);
    break;
  }
  trajectory.cost.cpu_time = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  trajectory.cost.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return trajectory;
}
} // namespace gearstiff::dynamics
