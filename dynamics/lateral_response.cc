#include "dynamics/lateral_response.h"

#include "dynamics/fields.h"
#include "errors/errors.h"
#include "errors/format.h"

#include <Eigen/Eigenvalues>
#include <chrono>
#include <cmath>

namespace gearstiff::dynamics
{
namespace
{
// A mesh spring in the free coordinates: δ = Σ v_i·q[dof_i].
struct MeshSpring
{
  unsigned int planet = 0;
  bool sun = true;
  std::vector<std::pair<unsigned int, double>> terms; // (free index, coefficient)
  double damping = 0.;                                // [N·s/m]
  double static_force = 0.;                           // [N] under the static load, mean stiffness
};

// The message numbers of errors/format.h, 4 significant digits.
std::string format(double value)
{
  return format_number(value, 4);
}

// The equations of motion in the free coordinates: constant part (bearings, supports, pins),
// the meshes apart, loads.
struct LateralSystem
{
  std::vector<int> free_index; // full → free coordinate (−1: held)
  Eigen::MatrixXd k_fixed, c_fixed;
  std::vector<MeshSpring> meshes;
  Eigen::VectorXd force, inverse_mass;
};

LateralSystem build_system(const LateralModel& model, const LateralStaticLoad& load,
                           const LateralStaticState& statics)
{
  const std::vector<unsigned int>& free = model.free_dofs();
  const unsigned int nf = free.size();
  LateralSystem s;
  s.free_index.assign(model.n_dofs(), -1);
  for (unsigned int i = 0; i < nf; ++i)
    s.free_index[free[i]] = static_cast<int>(i);
  s.k_fixed.resize(nf, nf);
  s.c_fixed.resize(nf, nf);
  for (unsigned int i = 0; i < nf; ++i)
    for (unsigned int j = 0; j < nf; ++j)
    {
      s.k_fixed(i, j) = model.stiffness()(free[i], free[j]);
      s.c_fixed(i, j) = model.damping()(free[i], free[j]);
    }
  for (const LateralModel::Spring& spring : model.springs())
  {
    if (spring.group < 3)
      continue;
    const bool sun = spring.group == 3;
    MeshSpring m{spring.planet,
                 sun,
                 {},
                 spring.damping,
                 (sun ? statics.sun_mesh_force : statics.ring_mesh_force)[spring.planet]};
    for (const auto& [i, v] : spring.terms)
      if (s.free_index[i] >= 0)
        m.terms.push_back({static_cast<unsigned int>(s.free_index[i]), v});
    for (const auto& [i, vi] : m.terms)
      for (const auto& [j, vj] : m.terms)
      {
        s.k_fixed(i, j) -= spring.stiffness * vi * vj;
        s.c_fixed(i, j) -= spring.damping * vi * vj;
      }
    s.meshes.push_back(m);
  }
  s.force = Eigen::VectorXd::Zero(nf);
  for (unsigned int i = 0; i < nf; ++i)
    s.force[i] = model.pin_error_force()[free[i]];
  const LateralStage& stage = model.stage();
  auto radius = [&](LateralMember j)
  {
    return (j == LateralMember::sun    ? stage.sun
            : j == LateralMember::ring ? stage.ring
                                       : stage.carrier)
        .radius;
  };
  s.force[s.free_index[LateralModel::central_dof(load.input, 2)]] +=
      load.input_torque / radius(load.input);
  s.force[s.free_index[LateralModel::central_dof(load.output, 2)]] +=
      statics.output_torque / radius(load.output);
  s.inverse_mass.resize(nf);
  for (unsigned int i = 0; i < nf; ++i)
    s.inverse_mass[i] = 1. / model.mass()[free[i]];
  return s;
}

// RK4 stability: |h·ω| ≤ 2√2 for the highest mode at the largest mesh stiffness (undamped).
double rk4_step_limit(const LateralModel& model, const LateralSystem& s,
                      const LateralMeshExcitation& excitation)
{
  const LateralStage& stage = model.stage();
  Eigen::MatrixXd k_max = s.k_fixed;
  for (const MeshSpring& m : s.meshes)
  {
    const double k = !excitation.varying
                         ? (m.sun ? stage.sun_mesh_stiffness : stage.ring_mesh_stiffness)
                     : m.sun ? excitation.sun_mesh.max_stiffness(excitation.sun_contact_ratio)
                             : excitation.ring_mesh.max_stiffness(excitation.ring_contact_ratio);
    for (const auto& [i, vi] : m.terms)
      for (const auto& [j, vj] : m.terms)
        k_max(i, j) += k * vi * vj;
  }
  const std::vector<unsigned int>& free = model.free_dofs();
  Eigen::VectorXd scale(free.size()); // M^(-1/2)
  for (std::size_t i = 0; i < free.size(); ++i)
    scale[i] = 1. / std::sqrt(model.mass()[free[i]]);
  const Eigen::MatrixXd a = scale.asDiagonal() * k_max * scale.asDiagonal();
  const double omega =
      std::sqrt(std::max(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a, Eigen::EigenvaluesOnly)
                             .eigenvalues()
                             .maxCoeff(),
                         0.));
  return omega > 0. ? 2. * std::sqrt(2.) / omega : INFINITY;
}

// The mesh law of every mesh at time t: stiffness, position and (nonlinear) TE and free play.
class MeshLaw
{
public:
  MeshLaw(const LateralStage& stage, const LateralMeshExcitation& excitation, double offset)
      : stage(stage), excitation(excitation), offset(offset)
  {
  }
  double position(const MeshSpring& m, double t) const
  {
    const std::vector<double>& list = m.sun ? excitation.sun_phase : excitation.ring_phase;
    return excitation.mesh_frequency * t + ((list.empty() ? 0. : list[m.planet]) + offset);
  }
  double stiffness(const MeshSpring& m, double t) const
  {
    if (!excitation.varying)
      return m.sun ? stage.sun_mesh_stiffness : stage.ring_mesh_stiffness;
    const double x = position(m, t);
    return m.sun ? excitation.sun_mesh.stiffness(x, excitation.sun_contact_ratio)
                 : excitation.ring_mesh.stiffness(x, excitation.ring_contact_ratio);
  }
  const NonlinearMesh* nonlinear(const MeshSpring& m) const
  {
    const auto& law = m.sun ? excitation.sun_nonlinear : excitation.ring_nonlinear;
    return law ? &*law : nullptr;
  }
  // Elastic force [N] for deflection d [m]: k·δ, or k·h(δ − e) with the contact regime.
  double elastic_force(const MeshSpring& m, double t, double d, ContactRegime& regime) const
  {
    const NonlinearMesh* law = nonlinear(m);
    regime = ContactRegime::drive;
    if (!law)
      return stiffness(m, t) * d;
    const double x = position(m, t);
    const double z = d - law->transmission_error.value(x);
    regime = contact_regime(z, law->backlash);
    if (regime == ContactRegime::separated)
      return 0.;
    const double k = regime == ContactRegime::back && law->back_stiffness
                         ? law->back_stiffness->stiffness(x, m.sun ? excitation.sun_contact_ratio
                                                                   : excitation.ring_contact_ratio)
                         : stiffness(m, t);
    return k * backlash_function(z, law->backlash);
  }
  // Whole force [N] for deflection d [m] and rate dd [m/s].
  double force(const MeshSpring& m, double t, double d, double dd, ContactRegime& regime) const
  {
    const NonlinearMesh* law = nonlinear(m);
    if (!law)
    {
      regime = ContactRegime::drive;
      return stiffness(m, t) * d + m.damping * dd;
    }
    const double elastic = elastic_force(m, t, d, regime);
    if (regime == ContactRegime::separated)
      return 0.;
    const double x = position(m, t);
    return elastic +
           m.damping * (dd - law->transmission_error.slope(x) * excitation.mesh_frequency);
  }

private:
  const LateralStage& stage;
  const LateralMeshExcitation& excitation;
  double offset; // [base pitches]
};

double deflection(const MeshSpring& m, const Eigen::VectorXd& q)
{
  double d = 0.;
  for (const auto& [i, c] : m.terms)
    d += c * q[i];
  return d;
}

// The window's extremes, step by step (LateralWindowSummary).
class WindowTracker
{
public:
  WindowTracker(const LateralStage& stage, const LateralRunSettings& settings, std::size_t n_meshes)
      : stage(stage), start(settings.window_start),
        middle(0.5 * (settings.window_start + settings.end_time)), last(n_meshes, 0)
  {
    summary.mesh_force_min = INFINITY;
    low.setConstant(INFINITY);
    high.setConstant(-INFINITY);
  }
  void add(double t, const LateralSystem& s, const MeshLaw& law, const Eigen::VectorXd& q,
           const Eigen::VectorXd& v)
  {
    if (t < start)
      return;
    for (std::size_t k = 0; k < s.meshes.size(); ++k)
    {
      const MeshSpring& m = s.meshes[k];
      ContactRegime regime;
      const double f = law.force(m, t, deflection(m, q), deflection(m, v), regime);
      double& largest = m.sun ? summary.sun_mesh_force_max : summary.ring_mesh_force_max;
      largest = std::max(largest, f);
      summary.mesh_force_min = std::min(summary.mesh_force_min, f);
      const double kv = f / m.static_force;
      (t < middle ? summary.kv_max_first_half : summary.kv_max_second_half) =
          std::max(t < middle ? summary.kv_max_first_half : summary.kv_max_second_half, kv);
      separated += regime != ContactRegime::drive;
      summary.back_impacts += regime == ContactRegime::back && last[k] != 2;
      last[k] = static_cast<int>(regime);
    }
    mesh_steps += s.meshes.size();
    for (unsigned int j = 0; j < 3; ++j)
    {
      const double k = (j == 0 ? stage.carrier : j == 1 ? stage.ring : stage.sun).bearing_stiffness;
      const double x = q[s.free_index[3 * j]], y = q[s.free_index[3 * j + 1]];
      summary.bearing_force_max[j] = std::max(summary.bearing_force_max[j], k * std::hypot(x, y));
      low.row(j) = low.row(j).cwiseMin(Eigen::RowVector2d(x, y));
      high.row(j) = high.row(j).cwiseMax(Eigen::RowVector2d(x, y));
    }
  }
  LateralWindowSummary result() const
  {
    LateralWindowSummary r = summary;
    r.kv_max = std::max(r.kv_max_first_half, r.kv_max_second_half);
    r.separation_fraction = mesh_steps ? double(separated) / mesh_steps : 0.;
    if (mesh_steps)
      for (unsigned int j = 0; j < 3; ++j)
        r.orbit_amplitude[j] = 0.5 * (high.row(j) - low.row(j)).maxCoeff();
    else
      r.mesh_force_min = 0.;
    return r;
  }

private:
  const LateralStage& stage;
  double start, middle; // [s]
  std::vector<int> last;
  LateralWindowSummary summary;
  Eigen::Matrix<double, 3, 2> low, high;
  unsigned long separated = 0, mesh_steps = 0;
};

void record(double t, const LateralStage& stage, const LateralSystem& s, const MeshLaw& law,
            const Eigen::VectorXd& q, unsigned int planets, LateralResponse& response)
{
  response.time.push_back(t);
  Eigen::Matrix<double, 3, 2> position, bearing;
  for (unsigned int j = 0; j < 3; ++j)
  {
    const double k = (j == 0 ? stage.carrier : j == 1 ? stage.ring : stage.sun).bearing_stiffness;
    for (unsigned int c = 0; c < 2; ++c)
    {
      position(j, c) = q[s.free_index[3 * j + c]];
      bearing(j, c) = -k * position(j, c);
    }
  }
  response.position.push_back(position);
  response.bearing_force.push_back(bearing);
  std::vector<double> sun(planets), ring(planets);
  for (const MeshSpring& m : s.meshes)
  {
    ContactRegime regime;
    (m.sun ? sun : ring)[m.planet] = law.elastic_force(m, t, deflection(m, q), regime);
  }
  response.sun_mesh_force.push_back(sun);
  response.ring_mesh_force.push_back(ring);
}

// The start: a given state, the static deflection or rest.
void initial_state(const LateralModel& model, const LateralRunSettings& settings,
                   const LateralStaticState& statics, Eigen::VectorXd& q, Eigen::VectorXd& v)
{
  const std::vector<unsigned int>& free = model.free_dofs();
  const unsigned int nf = free.size();
  q = Eigen::VectorXd::Zero(nf);
  v = Eigen::VectorXd::Zero(nf);
  if (!settings.initial_position.empty())
  {
    if (settings.initial_position.size() != nf || settings.initial_velocity.size() != nf)
      throw InputError(field::speed_sweep("direction"),
                       "the continued state does not fit the model");
    q = Eigen::Map<const Eigen::VectorXd>(settings.initial_position.data(), nf);
    v = Eigen::Map<const Eigen::VectorXd>(settings.initial_velocity.data(), nf);
  }
  else if (settings.start_static)
    for (unsigned int i = 0; i < nf; ++i)
      q[i] = statics.displacement[free[i]];
}
// M⁻¹·(f − K·x − C·ẋ − mesh forces) [m/s²] in the free coordinates.
void acceleration(const LateralSystem& system, const MeshLaw& law, double t,
                  const Eigen::VectorXd& x, const Eigen::VectorXd& xd, Eigen::VectorXd& out)
{
  out.noalias() = system.force - system.k_fixed * x;
  out.noalias() -= system.c_fixed * xd;
  for (const MeshSpring& m : system.meshes)
  {
    double d = 0., dd = 0.;
    for (const auto& [i, c] : m.terms)
    {
      d += c * x[i];
      dd += c * xd[i];
    }
    ContactRegime regime;
    const double f = law.force(m, t, d, dd, regime);
    for (const auto& [i, c] : m.terms)
      out[i] -= c * f;
  }
  out.array() *= system.inverse_mass.array();
}

struct Rk4Scratch
{
  explicit Rk4Scratch(Eigen::Index n) : k1(n), k2(n), k3(n), k4(n), qt(n), vt(n) {}
  Eigen::VectorXd k1, k2, k3, k4, qt, vt;
};

// q' = v, v' = a(q, v): one classical RK4 step on the first-order form.
void rk4_step(const LateralSystem& system, const MeshLaw& law, double t, double h,
              Eigen::VectorXd& q, Eigen::VectorXd& v, Rk4Scratch& w)
{
  acceleration(system, law, t, q, v, w.k1);
  w.qt = q + 0.5 * h * v;
  w.vt = v + 0.5 * h * w.k1;
  acceleration(system, law, t + 0.5 * h, w.qt, w.vt, w.k2);
  const Eigen::VectorXd v2 = w.vt;
  w.qt = q + 0.5 * h * v2;
  w.vt = v + 0.5 * h * w.k2;
  acceleration(system, law, t + 0.5 * h, w.qt, w.vt, w.k3);
  const Eigen::VectorXd v3 = w.vt;
  w.qt = q + h * v3;
  w.vt = v + h * w.k3;
  acceleration(system, law, t + h, w.qt, w.vt, w.k4);
  q += h / 6. * (v + 2. * v2 + 2. * v3 + w.vt);
  v += h / 6. * (w.k1 + 2. * w.k2 + 2. * w.k3 + w.k4);
}
} // namespace

LateralResponse integrate_lateral(const LateralModel& model, const LateralStaticLoad& load,
                                  const LateralMeshExcitation& excitation,
                                  const LateralRunSettings& settings)
{
  const LateralStaticState statics = model.static_state(load);
  const LateralSystem system = build_system(model, load, statics);
  const LateralStage& stage = model.stage();
  const MeshLaw law(stage, excitation, settings.mesh_position);
  LateralResponse response;
  response.rk4_step_limit = rk4_step_limit(model, system, excitation);
  if (!(settings.time_step > 0.) || !(settings.end_time > 0.))
    throw InputError(field::simulation("time_step"),
                     "time step and simulated time must be positive");
  if (settings.time_step > response.rk4_step_limit && !settings.allow_unstable_step)
    throw InputError(field::simulation("time_step"),
                     format(settings.time_step * 1e6) +
                         " µs exceeds the RK4 stability limit of the lateral model, " +
                         format(response.rk4_step_limit * 1e6) + " µs");
  Eigen::VectorXd q, v;
  initial_state(model, settings, statics, q, v);

  const auto start = std::chrono::steady_clock::now();
  const double h = settings.time_step;
  const unsigned long steps = static_cast<unsigned long>(std::ceil(settings.end_time / h - 1e-9));
  const unsigned int nf = q.size();
  Rk4Scratch scratch(nf);
  WindowTracker window(stage, settings, system.meshes.size());
  if (settings.record)
    record(0., stage, system, law, q, model.n_planets(), response);
  for (unsigned long s = 0; s < steps; ++s)
  {
    const double t = s * h;
    rk4_step(system, law, t, h, q, v, scratch);
    if (settings.window_start >= 0.)
      window.add((s + 1) * h, system, law, q, v);
    if ((s + 1) % settings.record_stride == 0 || s + 1 == steps)
    {
      if (!q.allFinite() || !v.allFinite())
        throw SolverFailure("RK4", "the lateral model diverged at t = " + format(t) + " s (step " +
                                       format(h * 1e6) + " µs, stability limit " +
                                       format(response.rk4_step_limit * 1e6) + " µs)");
      if (settings.record)
        record((s + 1) * h, stage, system, law, q, model.n_planets(), response);
    }
  }
  response.steps = steps;
  response.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (settings.window_start >= 0.)
    response.summary = window.result();
  response.final_position.assign(q.data(), q.data() + nf);
  response.final_velocity.assign(v.data(), v.data() + nf);
  response.final_mesh_position = settings.mesh_position + excitation.mesh_frequency * steps * h;
  return response;
}

double lateral_decay_time(const LateralModel& model)
{
  const LateralModes modes = model.modes();
  double slowest = INFINITY;
  for (Eigen::Index k = 0; k < modes.frequencies.size(); ++k)
    if (modes.frequencies[k] > 0.)
    {
      const Eigen::VectorXd phi = modes.shapes.col(k);
      slowest = std::min(slowest, 0.5 * phi.dot(model.damping() * phi));
    }
  return slowest > 0. ? std::log(1000.) / slowest : INFINITY;
}
} // namespace gearstiff::dynamics
