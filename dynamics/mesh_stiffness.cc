#include "dynamics/mesh_stiffness.h"

#include "errors/errors.h"
#include "errors/limits.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>

namespace gearstiff::dynamics
{
namespace
{
// Fine enough that the sampled maximum of a Cai curve is within 1e-6 of the true one.
constexpr unsigned int period_samples = 4096;
} // namespace

namespace
{
// "4.2e+08 N/m (420 N/µm)"
std::string format_stiffness(double k)
{
  std::ostringstream text;
  text.precision(3);
  text << k << " N/m (" << k * 1e-6 << " N/µm)";
  return text.str();
}

// A mesh stiffness in the range of real gears (errors/limits.h); outside it the value is a unit
// mistake. `what` names it in the message.
void check_plausible(double stiffness, const std::string& parameter, const std::string& what)
{
  if (!(stiffness > 0.) || !std::isfinite(stiffness))
    throw InputError(parameter,
                     what + " must be positive and finite, got " + format_stiffness(stiffness));
  if (stiffness < limits::min_mesh_stiffness || stiffness > limits::max_mesh_stiffness)
    throw InputError(parameter, what + " " + format_stiffness(stiffness) +
                                    " is outside the range of real gear meshes (" +
                                    format_stiffness(limits::min_mesh_stiffness) + " to " +
                                    format_stiffness(limits::max_mesh_stiffness) +
                                    ", docs/limits.md): check the value and its unit");
}
} // namespace

MeshStiffness MeshStiffness::constant(double stiffness, const std::string& parameter)
{
  check_plausible(stiffness, parameter, "mesh stiffness");
  MeshStiffness mesh;
  mesh.kind = StiffnessSource::constant;
  mesh.constant_value = stiffness;
  return mesh;
}

MeshStiffness MeshStiffness::cai(const CaiParameters& parameters, const std::string& parameter)
{
  check_plausible(parameters.scale, parameter, "Cai scale (single-pair peak stiffness)");
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
                                   const std::string& parameter, unsigned int period,
                                   const std::vector<bool>& lost_contact)
{
  if (positions.empty())
    throw InputError(parameter, "stiffness table is empty");
  if (positions.size() != stiffness.size())
    throw InputError(parameter, "positions and stiffness values differ in number");
  if (period < 1)
    throw InputError(parameter, "the table's period must be at least one base pitch");
  if (!lost_contact.empty() && lost_contact.size() != positions.size())
    throw InputError(parameter, "the lost-contact flags and the positions differ in number");
  const double span = period;
  MeshStiffness mesh;
  for (std::size_t i = 0; i < positions.size(); ++i)
  {
    if (!(positions[i] >= 0. && positions[i] < span))
      throw InputError(
          parameter, "position " + std::to_string(positions[i]) +
                         (period == 1 ? std::string(" outside one mesh period [0, 1) base pitches")
                                      : " outside the table's period [0, " +
                                            std::to_string(period) + ") base pitches"));
    if (i > 0 && !(positions[i] > positions[i - 1]))
      throw InputError(parameter, "positions must increase strictly (entry " +
                                      std::to_string(i + 1) + ": " + std::to_string(positions[i]) +
                                      " after " + std::to_string(positions[i - 1]) + ")");
    if (!lost_contact.empty() && lost_contact[i])
    {
      // No pair touches there: no stiffness exists, and none may be written (docs/faults.md).
      if (stiffness[i] != 0.)
        throw InputError(parameter, "row " + std::to_string(i + 1) +
                                        " is flagged as lost contact but carries a stiffness " +
                                        format_stiffness(stiffness[i]) + " (it must be 0)");
      ++mesh.lost_contact_rows;
      continue;
    }
    check_plausible(stiffness[i], parameter,
                    "stiffness at position " + std::to_string(positions[i]));
  }
  if (mesh.lost_contact_rows == positions.size())
    throw InputError(parameter, "no row of the table has contact: there is no mesh stiffness");
  mesh.kind = StiffnessSource::table;
  mesh.table_positions = positions;
  mesh.table_stiffness = stiffness;
  mesh.table_period = period;
  return mesh;
}

double MeshStiffness::first_lost_contact() const
{
  for (std::size_t i = 0; i < table_stiffness.size(); ++i)
    if (table_stiffness[i] == 0.)
      return table_positions[i];
  return std::numeric_limits<double>::quiet_NaN();
}

double MeshStiffness::table_value(double x) const
{
  const std::size_t n = table_positions.size();
  if (n == 1)
    return table_stiffness[0];
  // Periodic linear interpolation: the segment after the last node wraps to the first + period.
  const double span = table_period;
  const auto upper = std::upper_bound(table_positions.begin(), table_positions.end(), x);
  const std::size_t i1 = upper - table_positions.begin();
  const std::size_t i0 = (i1 == 0) ? n - 1 : i1 - 1;
  double x0 = table_positions[i0];
  double x1 = (i1 == n) ? table_positions[0] + span : table_positions[i1];
  if (i1 == 0)
    x0 -= span;
  const double w = (x - x0) / (x1 - x0);
  const double k0 = table_stiffness[i0], k1 = table_stiffness[i1 % n];
  // Between a row with contact and one without, the contact ends half-way (nearest row): a
  // stiffness between the two would be invented. The trapezoid mean is unchanged by this rule.
  if (lost_contact_rows > 0 && (k0 == 0.) != (k1 == 0.))
    return w < 0.5 ? k0 : k1;
  return (1. - w) * k0 + w * k1;
}

// x modulo the table's period (for P = 1 the same arithmetic as x − ⌊x⌋).
double MeshStiffness::table_position(double mesh_position) const
{
  const double span = table_period;
  return mesh_position - span * std::floor(mesh_position / span);
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
  state.stiffness = (kind == StiffnessSource::constant)
                        ? constant_value
                        : table_value(table_position(mesh_position));
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
    return table_value(table_position(mesh_position));
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
    // Exact mean of the periodic piecewise-linear function (trapezoids, wrap included; a
    // half-step to a row without contact has the trapezoid's area too).
    const std::size_t n = table_positions.size();
    const double span = table_period;
    double integral = 0.;
    for (std::size_t i = 0; i < n; ++i)
    {
      const double x0 = table_positions[i];
      const double x1 = (i + 1 < n) ? table_positions[i + 1] : table_positions[0] + span;
      integral += 0.5 * (x1 - x0) * (table_stiffness[i] + table_stiffness[(i + 1) % n]);
    }
    return integral / span;
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
      const double f = table_position(contact_ratio - table_positions[i]);
      // f = P by round-off is 0
      nodes.emplace_back(f < double(table_period) ? f : 0., table_stiffness[i]);
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
    if (table_period > 1)
      s << ", period " << table_period << " base pitches (one revolution of a " << table_period
        << "-tooth gear)";
    if (lost_contact_rows > 0)
      s << ", " << lost_contact_rows << " rows without contact (k = 0)";
    break;
  }
  return s.str();
}
} // namespace gearstiff::dynamics
