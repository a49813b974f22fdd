#include "dynamics/lateral_response.h"

#include "errors/errors.h"
#include "errors/format.h"

#include <Eigen/Eigenvalues>
#include <chrono>
#include <cmath>
#include <sstream>

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
  double damping = 0.;
};

// The message numbers of errors/format.h, 4 significant digits.
std::string format(double value)
{
  return format_number(value, 4);
}
} // namespace

LateralResponse integrate_lateral(const LateralModel& model, const LateralStaticLoad& load,
                                  const LateralMeshExcitation& excitation,
                                  const LateralRunSettings& settings)
{
  const std::vector<unsigned int>& free = model.free_dofs();
  const unsigned int nf = free.size(), n = model.n_dofs(), planets = model.n_planets();
  std::vector<int> free_index(n, -1);
  for (unsigned int i = 0; i < nf; ++i)
    free_index[free[i]] = static_cast<int>(i);
  const LateralStage& stage = model.stage();

  // The constant part (bearings, supports, pins) and the meshes apart.
  Eigen::MatrixXd k_fixed(nf, nf), c_fixed(nf, nf);
  for (unsigned int i = 0; i < nf; ++i)
    for (unsigned int j = 0; j < nf; ++j)
    {
      k_fixed(i, j) = model.stiffness()(free[i], free[j]);
      c_fixed(i, j) = model.damping()(free[i], free[j]);
    }
  std::vector<MeshSpring> meshes;
  for (const LateralModel::Spring& s : model.springs())
  {
    if (s.group < 3)
      continue;
    MeshSpring m{s.planet, s.group == 3, {}, s.damping};
    for (const auto& [i, v] : s.terms)
      if (free_index[i] >= 0)
        m.terms.push_back({static_cast<unsigned int>(free_index[i]), v});
    for (const auto& [i, vi] : m.terms)
      for (const auto& [j, vj] : m.terms)
      {
        k_fixed(i, j) -= s.stiffness * vi * vj;
        c_fixed(i, j) -= s.damping * vi * vj;
      }
    meshes.push_back(m);
  }
  auto phase = [&](const std::vector<double>& list, unsigned int p)
  { return list.empty() ? 0. : list[p]; };
  auto mesh_stiffness = [&](const MeshSpring& m, double t)
  {
    if (!excitation.varying)
      return m.sun ? stage.sun_mesh_stiffness : stage.ring_mesh_stiffness;
    const double x = excitation.mesh_frequency * t +
                     phase(m.sun ? excitation.sun_phase : excitation.ring_phase, m.planet);
    return m.sun ? excitation.sun_mesh.stiffness(x, excitation.sun_contact_ratio)
                 : excitation.ring_mesh.stiffness(x, excitation.ring_contact_ratio);
  };

  // RK4 stability: |h·ω| ≤ 2√2 for the highest mode at the largest mesh stiffness (undamped).
  LateralResponse response;
  {
    Eigen::MatrixXd k_max = k_fixed;
    for (const MeshSpring& m : meshes)
    {
      const double k = !excitation.varying
                           ? (m.sun ? stage.sun_mesh_stiffness : stage.ring_mesh_stiffness)
                       : m.sun ? excitation.sun_mesh.max_stiffness(excitation.sun_contact_ratio)
                               : excitation.ring_mesh.max_stiffness(excitation.ring_contact_ratio);
      for (const auto& [i, vi] : m.terms)
        for (const auto& [j, vj] : m.terms)
          k_max(i, j) += k * vi * vj;
    }
    Eigen::VectorXd scale(nf);
    for (unsigned int i = 0; i < nf; ++i)
      scale[i] = 1. / std::sqrt(model.mass()[free[i]]);
    const Eigen::MatrixXd a = scale.asDiagonal() * k_max * scale.asDiagonal();
    const double omega =
        std::sqrt(std::max(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a, Eigen::EigenvaluesOnly)
                               .eigenvalues()
                               .maxCoeff(),
                           0.));
    response.rk4_step_limit = omega > 0. ? 2. * std::sqrt(2.) / omega : INFINITY;
  }
  if (!(settings.time_step > 0.) || !(settings.end_time > 0.))
    throw InputError("Simulation/time step", "time step and simulated time must be positive");
  if (settings.time_step > response.rk4_step_limit && !settings.allow_unstable_step)
    throw InputError("Simulation/time step",
                     format(settings.time_step * 1e6) +
                         " µs exceeds the RK4 stability limit of the lateral model, " +
                         format(response.rk4_step_limit * 1e6) + " µs");

  // Loads and the start.
  const LateralStaticState statics = model.static_state(load);
  Eigen::VectorXd force = Eigen::VectorXd::Zero(nf);
  for (unsigned int i = 0; i < nf; ++i)
    force[i] = model.pin_error_force()[free[i]];
  const double r_in = (load.input == LateralMember::sun    ? stage.sun
                       : load.input == LateralMember::ring ? stage.ring
                                                           : stage.carrier)
                          .radius;
  const double r_out = (load.output == LateralMember::sun    ? stage.sun
                        : load.output == LateralMember::ring ? stage.ring
                                                             : stage.carrier)
                           .radius;
  force[free_index[LateralModel::central_dof(load.input, 2)]] += load.input_torque / r_in;
  force[free_index[LateralModel::central_dof(load.output, 2)]] += statics.output_torque / r_out;
  Eigen::VectorXd inverse_mass(nf);
  for (unsigned int i = 0; i < nf; ++i)
    inverse_mass[i] = 1. / model.mass()[free[i]];

  Eigen::VectorXd q = Eigen::VectorXd::Zero(nf), v = Eigen::VectorXd::Zero(nf);
  if (settings.start_static)
    for (unsigned int i = 0; i < nf; ++i)
      q[i] = statics.displacement[free[i]];

  auto acceleration =
      [&](double t, const Eigen::VectorXd& x, const Eigen::VectorXd& xd, Eigen::VectorXd& out)
  {
    out.noalias() = force - k_fixed * x;
    out.noalias() -= c_fixed * xd;
    for (const MeshSpring& m : meshes)
    {
      double d = 0., dd = 0.;
      for (const auto& [i, c] : m.terms)
      {
        d += c * x[i];
        dd += c * xd[i];
      }
      const double f = mesh_stiffness(m, t) * d + m.damping * dd;
      for (const auto& [i, c] : m.terms)
        out[i] -= c * f;
    }
    out.array() *= inverse_mass.array();
  };
  auto record = [&](double t)
  {
    response.time.push_back(t);
    Eigen::Matrix<double, 3, 2> position, bearing;
    for (unsigned int j = 0; j < 3; ++j)
    {
      const double k = (j == 0 ? stage.carrier : j == 1 ? stage.ring : stage.sun).bearing_stiffness;
      for (unsigned int c = 0; c < 2; ++c)
      {
        position(j, c) = q[free_index[3 * j + c]];
        bearing(j, c) = -k * position(j, c);
      }
    }
    response.position.push_back(position);
    response.bearing_force.push_back(bearing);
    std::vector<double> sun(planets), ring(planets);
    for (const MeshSpring& m : meshes)
    {
      double d = 0.;
      for (const auto& [i, c] : m.terms)
        d += c * q[i];
      (m.sun ? sun : ring)[m.planet] = mesh_stiffness(m, t) * d;
    }
    response.sun_mesh_force.push_back(sun);
    response.ring_mesh_force.push_back(ring);
  };

  const auto start = std::chrono::steady_clock::now();
  const double h = settings.time_step;
  const unsigned long steps = static_cast<unsigned long>(std::ceil(settings.end_time / h - 1e-9));
  Eigen::VectorXd k1(nf), k2(nf), k3(nf), k4(nf), qt(nf), vt(nf);
  record(0.);
  for (unsigned long s = 0; s < steps; ++s)
  {
    const double t = s * h;
    // q' = v, v' = a(q, v): classical RK4 on the first-order form.
    acceleration(t, q, v, k1);
    qt = q + 0.5 * h * v;
    vt = v + 0.5 * h * k1;
    acceleration(t + 0.5 * h, qt, vt, k2);
    const Eigen::VectorXd v2 = vt;
    qt = q + 0.5 * h * v2;
    vt = v + 0.5 * h * k2;
    acceleration(t + 0.5 * h, qt, vt, k3);
    const Eigen::VectorXd v3 = vt;
    qt = q + h * v3;
    vt = v + h * k3;
    acceleration(t + h, qt, vt, k4);
    q += h / 6. * (v + 2. * v2 + 2. * v3 + vt);
    v += h / 6. * (k1 + 2. * k2 + 2. * k3 + k4);
    if ((s + 1) % settings.record_stride == 0 || s + 1 == steps)
    {
      if (!q.allFinite() || !v.allFinite())
        throw SolverFailure("RK4", "the lateral model diverged at t = " + format(t) + " s (step " +
                                       format(h * 1e6) + " µs, stability limit " +
                                       format(response.rk4_step_limit * 1e6) + " µs)");
      record((s + 1) * h);
    }
  }
  response.steps = steps;
  response.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return response;
}
} // namespace gearstiff::dynamics
