#include "dynamics/mesh_stiffness.h"

#include "errors/errors.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

namespace gearstiff::dynamics
{
namespace
{
// Fine enough that the sampled maximum of a Cai curve is within 1e-6 of the true one.
constexpr unsigned int period_samples = 4096;
} // namespace

MeshStiffness MeshStiffness::constant(double stiffness, const std::string& parameter)
{
  if (!(stiffness > 0.) || !std::isfinite(stiffness))
    throw InputError(parameter, "mesh stiffness must be positive and finite, got " +
                                    std::to_string(stiffness) + " N/m");
  MeshStiffness mesh;
  mesh.kind = StiffnessSource::constant;
  mesh.constant_value = stiffness;
  return mesh;
}

MeshStiffness MeshStiffness::cai(const CaiParameters& parameters, const std::string& parameter)
{
  if (!(parameters.scale > 0.) || !std::isfinite(parameters.scale))
    throw InputError(parameter, "Cai scale (single-pair peak stiffness) must be positive, got " +
                                    std::to_string(parameters.scale) + " N/m");
  for (const double s : {0., 0.5, 1.})
    if (!(cai_pair_stiffness(parameters, s) > 0.))
      throw InputError(parameter, "Cai shape gives a non-positive pair stiffness at engagement "
                                  "fraction " +
                                      std::to_string(s));
  MeshStiffness mesh;
  mesh.kind = StiffnessSource::cai;
  mesh.cai_curve = parameters;
  return mesh;
}

MeshStiffness MeshStiffness::table(const std::vector<double>& positions,
                                   const std::vector<double>& stiffness,
                                   const std::string& parameter)
{
  if (positions.empty())
    throw InputError(parameter, "stiffness table is empty");
  if (positions.size() != stiffness.size())
    throw InputError(parameter, "positions and stiffness values differ in number");
  for (std::size_t i = 0; i < positions.size(); ++i)
  {
    if (!(positions[i] >= 0. && positions[i] < 1.))
      throw InputError(parameter, "position " + std::to_string(positions[i]) +
                                      " outside one mesh period [0, 1) base pitches");
    if (i > 0 && !(positions[i] > positions[i - 1]))
      throw InputError(parameter, "positions must increase strictly (entry " +
                                      std::to_string(i + 1) + ": " + std::to_string(positions[i]) +
                                      " after " + std::to_string(positions[i - 1]) + ")");
    if (!(stiffness[i] > 0.) || !std::isfinite(stiffness[i]))
      throw InputError(parameter, "stiffness must be positive, got " +
                                      std::to_string(stiffness[i]) + " N/m at position " +
                                      std::to_string(positions[i]));
  }
  MeshStiffness mesh;
  mesh.kind = StiffnessSource::table;
  mesh.table_positions = positions;
  mesh.table_stiffness = stiffness;
  return mesh;
}

double MeshStiffness::table_value(double x) const
{
  const std::size_t n = table_positions.size();
  if (n == 1)
    return table_stiffness[0];
  // Periodic linear interpolation: the segment after the last node wraps to the first + 1.
  const auto upper = std::upper_bound(table_positions.begin(), table_positions.end(), x);
  const std::size_t i1 = upper - table_positions.begin();
  const std::size_t i0 = (i1 == 0) ? n - 1 : i1 - 1;
  double x0 = table_positions[i0];
  double x1 = (i1 == n) ? table_positions[0] + 1. : table_positions[i1];
  if (i1 == 0)
    x0 -= 1.;
  const double w = (x - x0) / (x1 - x0);
  return (1. - w) * table_stiffness[i0] + w * table_stiffness[i1 % n];
}

MeshStiffnessState MeshStiffness::evaluate(double mesh_position, double contact_ratio,
                                           double approach_ratio) const
{
  const double x = mesh_position - std::floor(mesh_position);
  MeshStiffnessState state;
  if (kind == StiffnessSource::cai)
  {
    double weighted_direction = 0.;
    for (double p = x; p < contact_ratio; p += 1.)
    {
      const double k = cai_pair_stiffness(cai_curve, p / contact_ratio);
      state.stiffness += k;
      weighted_direction += (p < approach_ratio ? -k : k);
    }
    state.friction_direction = weighted_direction / state.stiffness;
    return state;
  }
  state.stiffness = (kind == StiffnessSource::constant) ? constant_value : table_value(x);
  int pairs = 0;
  int direction_sum = 0;
  for (double p = x; p < contact_ratio; p += 1., ++pairs)
    direction_sum += (p < approach_ratio ? -1 : 1);
  state.friction_direction = static_cast<double>(direction_sum) / pairs;
  return state;
}

double MeshStiffness::stiffness(double mesh_position, double contact_ratio) const
{
  const double x = mesh_position - std::floor(mesh_position);
  if (kind == StiffnessSource::constant)
    return constant_value;
  if (kind == StiffnessSource::table)
    return table_value(x);
  // Σ over the pairs of scale·(c0 + c1·s + c2·s²), s = p/ε_α ∈ [0, 1): cai_pair_stiffness's
  // arithmetic in its order, so the value is evaluate()'s to the last bit.
  const auto& c = cai_curve.shape;
  double sum = 0.;
  for (double p = x; p < contact_ratio; p += 1.)
  {
    const double s = p / contact_ratio;
    sum += cai_curve.scale * ((c[2] * s + c[1]) * s + c[0]);
  }
  return sum;
}

double MeshStiffness::mean_stiffness(double contact_ratio) const
{
  switch (kind)
  {
  case StiffnessSource::constant:
    return constant_value;
  case StiffnessSource::cai:
  {
    // Over one period every engagement fraction in [0, 1] is visited once per pair, spread
    // over ε_α base pitches: mean = ε_α · ∫₀¹ k_pair(s) ds.
    const auto& c = cai_curve.shape;
    return contact_ratio * cai_curve.scale * (c[0] + c[1] / 2. + c[2] / 3.);
  }
  case StiffnessSource::table:
  {
    // Exact mean of the periodic piecewise-linear function (trapezoids, wrap included).
    const std::size_t n = table_positions.size();
    double integral = 0.;
    for (std::size_t i = 0; i < n; ++i)
    {
      const double x0 = table_positions[i];
      const double x1 = (i + 1 < n) ? table_positions[i + 1] : table_positions[0] + 1.;
      integral += 0.5 * (x1 - x0) * (table_stiffness[i] + table_stiffness[(i + 1) % n]);
    }
    return integral;
  }
  }
  return 0.;
}

double MeshStiffness::max_stiffness(double contact_ratio) const
{
  double largest = 0.;
  for (unsigned int i = 0; i < period_samples; ++i)
    largest = std::max(largest, evaluate(double(i) / period_samples, contact_ratio, 0.).stiffness);
  for (const double k : table_stiffness)
    largest = std::max(largest, k);
  return largest;
}

double MeshStiffness::mean_friction_direction(double contact_ratio, double approach_ratio) const
{
  double sum = 0.;
  for (unsigned int i = 0; i < period_samples; ++i)
    sum += evaluate((i + 0.5) / period_samples, contact_ratio, approach_ratio).friction_direction;
  return sum / period_samples;
}

MeshStiffness MeshStiffness::reversed(double contact_ratio) const
{
  MeshStiffness mesh = *this;
  if (kind == StiffnessSource::cai)
  {
    // c2(1 − s)² + c1(1 − s) + c0 = c2·s² − (2c2 + c1)·s + (c2 + c1 + c0).
    const auto& c = cai_curve.shape;
    mesh.cai_curve.shape = {c[2] + c[1] + c[0], -2. * c[2] - c[1], c[2]};
  }
  else if (kind == StiffnessSource::table)
  {
    std::vector<std::pair<double, double>> nodes;
    for (std::size_t i = 0; i < table_positions.size(); ++i)
    {
      const double x = contact_ratio - table_positions[i];
      const double f = x - std::floor(x);
      nodes.emplace_back(f < 1. ? f : 0., table_stiffness[i]); // f = 1 by round-off is 0
    }
    std::sort(nodes.begin(), nodes.end());
    for (std::size_t i = 0; i < nodes.size(); ++i)
      std::tie(mesh.table_positions[i], mesh.table_stiffness[i]) = nodes[i];
  }
  return mesh;
}

std::string MeshStiffness::description() const
{
  std::ostringstream s;
  switch (kind)
  {
  case StiffnessSource::constant:
    // N/µm: the unit of every mesh stiffness the program prints.
    s << "constant " << constant_value / 1e6 << " N/µm";
    break;
  case StiffnessSource::cai:
    s << "Cai curve, single-pair peak " << cai_curve.scale / 1e6 << " N/µm, shape ("
      << cai_curve.shape[0] << ", " << cai_curve.shape[1] << ", " << cai_curve.shape[2] << ")";
    break;
  case StiffnessSource::table:
    s << "k(x) table, " << table_positions.size() << " points, periodic linear interpolation";
    break;
  }
  return s.str();
}
} // namespace gearstiff::dynamics
