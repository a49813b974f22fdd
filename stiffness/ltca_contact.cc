#include "stiffness/ltca_contact.h"

#include "errors/errors.h"
#include "errors/format.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

namespace gearstiff::stiffness
{
double hertz_layer_compression(double peak_pressure, double half_width, const LayerBody& body)
{
  // On the axis (Johnson 1985 §2.6): σ_z = −p0·a/√(a²+z²), σ_x = −(p0/a)·((a²+2z²)/√(a²+z²) − 2z);
  // plane strain ε_z = [(1−ν²)σ_z − ν(1+ν)σ_x]/E. The integrals over 0..h are closed forms:
  // ∫σ_z = −p0·a·asinh(h/a), ∫σ_x = −(p0/a)·(h·√(a²+h²) − h²).
  const double a = half_width, h = body.matching_depth, nu = body.poisson_ratio;
  const double sigma_z = peak_pressure * a * std::asinh(h / a);
  const double sigma_x = peak_pressure / a * (h * std::sqrt(a * a + h * h) - h * h);
  return ((1. - nu * nu) * sigma_z - nu * (1. + nu) * sigma_x) / body.young_modulus;
}

namespace
{
// Half-width and peak pressure of the Hertz line contact (Johnson 1985 §4.3).
std::pair<double, double> hertz_zone(double force, double face_width, double relative_radius,
                                     const LayerBody& first, const LayerBody& second)
{
  const double e_star =
      1. / ((1. - first.poisson_ratio * first.poisson_ratio) / first.young_modulus +
            (1. - second.poisson_ratio * second.poisson_ratio) / second.young_modulus);
  const double line_load = force / face_width;
  const double a = std::sqrt(4. * line_load * relative_radius / (M_PI * e_star));
  return {a, 2. * line_load / (M_PI * a)};
}

double layer_approach(double force, double face_width, double relative_radius,
                      const LayerBody& first, const LayerBody& second)
{
  const auto [a, p0] = hertz_zone(force, face_width, relative_radius, first, second);
  return hertz_layer_compression(p0, a, first) + hertz_layer_compression(p0, a, second);
}
} // namespace

LineContact hertz_line_contact(double force, double face_width, double relative_radius,
                               const LayerBody& first, const LayerBody& second)
{
  LineContact contact;
  if (!(force > 0.))
    return contact;
  std::tie(contact.half_width, contact.peak_pressure) =
      hertz_zone(force, face_width, relative_radius, first, second);
  contact.approach = layer_approach(force, face_width, relative_radius, first, second);
  // δ ≈ c·F·(ln(K/F)): smooth for F > 0; a central difference of relative step 1e-6 is exact
  // to ~1e-10 of dδ/dF, far below what the Newton iteration needs.
  const double step = 1e-6 * force;
  contact.compliance = (layer_approach(force + step, face_width, relative_radius, first, second) -
                        layer_approach(force - step, face_width, relative_radius, first, second)) /
                       (2. * step);
  return contact;
}

namespace
{
// Newton on the active pairs for F (≥ 0) and e: Σ_k C_jk F_k + δ(F_j) + s_j − e = 0 on the
// active set, Σ F = W. Steps are damped to keep every force positive (δ is defined for F > 0);
// a force driven below 1e-12·W leaves the active set (returned false with it cleared).
bool newton_on_active(const MeshContactProblem& problem, const std::vector<int>& active,
                      std::vector<double>& force, double& approach, unsigned int& steps)
{
  const int n = active.size();
  for (unsigned int iteration = 0; iteration < 100; ++iteration, ++steps)
  {
    Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(n + 1, n + 1);
    Eigen::VectorXd residual(n + 1);
    double sum = 0.;
    for (int a = 0; a < n; ++a)
    {
      const int j = active[a];
      const LineContact near = hertz_line_contact(
          force[j], problem.face_width, problem.relative_radius[j], problem.pinion, problem.wheel);
      residual[a] = near.approach + problem.separation[j] - approach;
      for (int b = 0; b < n; ++b)
      {
        residual[a] += problem.compliance[j][active[b]] * force[active[b]];
        jacobian(a, b) = problem.compliance[j][active[b]];
      }
      jacobian(a, a) += near.compliance;
      jacobian(a, n) = -1.;
      jacobian(n, a) = 1.;
      sum += force[j];
    }
    residual[n] = sum - problem.total_force;
    const Eigen::VectorXd delta = jacobian.partialPivLu().solve(-residual);
    double damping = 1.;
    for (int a = 0; a < n; ++a)
      if (delta[a] < 0.)
        damping = std::min(damping, 0.5 * force[active[a]] / -delta[a]);
    for (int a = 0; a < n; ++a)
      force[active[a]] += damping * delta[a];
    approach += damping * delta[n];
    for (int a = 0; a < n; ++a)
      if (force[active[a]] < 1e-12 * problem.total_force)
      {
        force[active[a]] = 0.;
        return false;
      }
    // 1e-12 of the load and 1e-16 m (1e-10 of a µm-sized approach): round-off level.
    const double largest = delta.head(n).cwiseAbs().maxCoeff();
    if (damping == 1. && largest < 1e-12 * problem.total_force && std::abs(delta[n]) < 1e-16)
      return true;
  }
  throw SolverFailure("influence-coefficient contact",
                      "Newton's method on the loaded pairs did not converge in 100 steps");
}

// The gap g_j = e − s_j − Σ_k C_jk F_k of an unloaded pair (> 0: it would penetrate).
double penetration(const MeshContactProblem& problem, const std::vector<double>& force,
                   double approach, int j)
{
  double g = approach - problem.separation[j];
  for (std::size_t k = 0; k < force.size(); ++k)
    g -= problem.compliance[j][k] * force[k];
  return g;
}
} // namespace

MeshContactSolution solve_mesh_contact(const MeshContactProblem& problem,
                                       const std::vector<double>& start)
{
  const int n = problem.separation.size();
  if (n == 0)
    throw SolverFailure("influence-coefficient contact", "no tooth pair in contact");
  MeshContactSolution solution;
  std::vector<double>& force = solution.force;
  // Warm start: the neighbour's forces when it had as many pairs, else the smallest gaps loaded.
  force.assign(n, 0.);
  const double smallest = *std::min_element(problem.separation.begin(), problem.separation.end());
  for (int j = 0; j < n; ++j)
    force[j] = static_cast<int>(start.size()) == n        ? start[j]
               : problem.separation[j] <= smallest + 1e-9 ? problem.total_force
                                                          : 0.;
  double total = std::accumulate(force.begin(), force.end(), 0.);
  if (!(total > 0.))
  {
    force.assign(n, problem.total_force / n);
    total = problem.total_force;
  }
  for (double& f : force)
    f *= problem.total_force / total;
  double& approach = solution.approach;
  approach = 0.;
  for (int pass = 0; pass < 4 * n + 8; ++pass)
  {
    ++solution.active_set_passes;
    std::vector<int> active;
    for (int j = 0; j < n; ++j)
      if (force[j] > 0.)
        active.push_back(j);
    if (active.empty())
      throw SolverFailure("influence-coefficient contact", "every pair left the active set");
    if (!newton_on_active(problem, active, force, approach, solution.newton_steps))
      continue; // a pair unloaded itself: solve again without it
    // An unloaded pair that would penetrate enters with a small force (1e-3 of the load).
    int entering = -1;
    double deepest = 1e-15; // m: round-off of µm-sized gaps
    for (int j = 0; j < n; ++j)
    {
      const double depth = force[j] == 0. ? penetration(problem, force, approach, j) : 0.;
      if (depth > deepest)
      {
        deepest = depth;
        entering = j;
      }
    }
    if (entering < 0)
    {
      solution.contact.resize(n);
      for (int j = 0; j < n; ++j)
        solution.contact[j] =
            hertz_line_contact(force[j], problem.face_width, problem.relative_radius[j],
                               problem.pinion, problem.wheel);
      return solution;
    }
    force[entering] = 1e-3 * problem.total_force;
  }
  throw SolverFailure("influence-coefficient contact",
                      "the active set of the tooth pairs did not settle in " +
                          std::to_string(4 * n + 8) + " passes");
}
} // namespace gearstiff::stiffness
