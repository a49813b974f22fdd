#include "stiffness/cycloid_sweep.h"

#include "errors/errors.h"
#include "fem/parallel.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <map>

namespace gearstiff::stiffness
{
using namespace dealii;

namespace
{
// Results cross ranks as fixed-length rows of doubles (zero on the ranks that did not solve a
// case, so one sum gathers them all).
constexpr unsigned int scalar_fields = 28;
constexpr unsigned int contact_fields = 9;

std::vector<double> pack(const CycloidLoadResult& r, unsigned int length)
{
  std::vector<double> row{1., // marks the row as filled
                          r.crank_angle,
                          r.disc_rotation,
                          r.output_torque,
                          r.max_roller_force,
                          r.max_pin_force,
                          double(r.loaded_rollers),
                          double(r.loaded_pins),
                          r.bearing_force,
                          r.bearing_angle,
                          r.bearing_force_direction,
                          r.input_torque,
                          r.input_torque_ratio,
                          r.disc_force_balance,
                          r.disc_moment_balance,
                          r.output_moment_balance,
                          r.output_rotation,
                          r.disc_rotation_load,
                          r.max_contact_pressure,
                          r.disc_von_mises,
                          double(r.n_cells),
                          double(r.n_dofs),
                          double(r.active_set_iterations),
                          r.contact_size,
                          r.scene_time,
                          r.setup_time,
                          r.solve_time,
                          r.total_time};
  const auto add = [&row](const std::vector<CycloidContactLoad>& loads)
  {
    for (const auto& l : loads)
      row.insert(row.end(), {double(l.index), l.angle, l.initial_gap, l.force, l.force_x, l.force_y,
                             l.max_pressure, l.analytic_force, double(l.candidate)});
  };
  add(r.rollers);
  add(r.pins);
  row.push_back(r.analytic.max_roller_force);
  row.push_back(r.analytic.max_pin_force);
  row.push_back(r.analytic.bearing_force.norm());
  row.push_back(r.analytic.output_rotation);
  if (row.size() != length)
    throw SolverFailure("cycloid cases", "result row of unexpected length");
  return row;
}

CycloidLoadResult unpack(const double* row, unsigned int rollers, unsigned int pins)
{
  CycloidLoadResult r;
  unsigned int i = 1;
  r.crank_angle = row[i++];
  r.disc_rotation = row[i++];
  r.output_torque = row[i++];
  r.max_roller_force = row[i++];
  r.max_pin_force = row[i++];
  r.loaded_rollers = std::lround(row[i++]);
  r.loaded_pins = std::lround(row[i++]);
  r.bearing_force = row[i++];
  r.bearing_angle = row[i++];
  r.bearing_force_direction = row[i++];
  r.input_torque = row[i++];
  r.input_torque_ratio = row[i++];
  r.disc_force_balance = row[i++];
  r.disc_moment_balance = row[i++];
  r.output_moment_balance = row[i++];
  r.output_rotation = row[i++];
  r.disc_rotation_load = row[i++];
  r.max_contact_pressure = row[i++];
  r.disc_von_mises = row[i++];
  r.n_cells = std::lround(row[i++]);
  r.n_dofs = std::lround(row[i++]);
  r.active_set_iterations = std::lround(row[i++]);
  r.contact_size = row[i++];
  r.scene_time = row[i++];
  r.setup_time = row[i++];
  r.solve_time = row[i++];
  r.total_time = row[i++];
  const auto take =
      [&](std::vector<CycloidContactLoad>& loads, unsigned int n, std::vector<double>& analytic)
  {
    for (unsigned int k = 0; k < n; ++k, i += contact_fields)
    {
      CycloidContactLoad l;
      l.index = std::lround(row[i]);
      l.angle = row[i + 1];
      l.initial_gap = row[i + 2];
      l.force = row[i + 3];
      l.force_x = row[i + 4];
      l.force_y = row[i + 5];
      l.max_pressure = row[i + 6];
      l.analytic_force = row[i + 7];
      l.candidate = row[i + 8] > 0.5;
      loads.push_back(l);
      analytic.push_back(l.analytic_force);
    }
  };
  take(r.rollers, rollers, r.analytic.roller_forces);
  take(r.pins, pins, r.analytic.pin_forces);
  r.analytic.max_roller_force = row[i++];
  r.analytic.max_pin_force = row[i++];
  r.analytic.bearing_force = Eigen::Vector2d(row[i++], 0.);
  r.analytic.output_rotation = row[i++];
  return r;
}

// The settings of the mirror image about the x axis (see the header).
CycloidLoadSettings mirrored(const CycloidLoadSettings& s)
{
  CycloidLoadSettings m = s;
  m.crank_angle = -s.crank_angle;
  m.output_torque = -s.output_torque;
  if (m.scene.disc.rollers != 0)
    m.scene.disc.rotation = -s.scene.disc.rotation;
  // Pin centres at ψ + phase + 2πj/n must map to −(ψ + phase) − 2πj/n.
  const double psi = geometry::disc_rotation_at_crank_angle(s.scene.ring, s.crank_angle);
  const double psi_mirror = geometry::disc_rotation_at_crank_angle(s.scene.ring, -s.crank_angle);
  m.scene.output_pin_phase = -psi - s.scene.output_pin_phase - psi_mirror;
  return m;
}

// Result of the mirrored case mapped back: index k ↔ (n − k) mod n, y and rotations negated.
void mirror_back(CycloidLoadResult& r, const CycloidLoadSettings& original)
{
  const auto flip = [](std::vector<CycloidContactLoad>& loads)
  {
    const unsigned int n = loads.size();
    std::vector<CycloidContactLoad> flipped(n);
    for (unsigned int k = 0; k < n; ++k)
    {
      CycloidContactLoad l = loads[(n - k) % n];
      l.index = k;
      l.angle = -l.angle;
      l.force_y = -l.force_y;
      flipped[k] = l;
    }
    loads = flipped;
  };
  flip(r.rollers);
  flip(r.pins);
  r.crank_angle = original.crank_angle;
  r.disc_rotation =
      geometry::disc_rotation_at_crank_angle(original.scene.ring, original.crank_angle);
  r.output_torque = original.output_torque;
  r.bearing_force_direction = -r.bearing_force_direction;
  r.output_rotation = -r.output_rotation;
  r.disc_rotation_load = -r.disc_rotation_load;
  r.analytic.output_rotation = -r.analytic.output_rotation;
  r.analytic.disc_rotation = -r.analytic.disc_rotation;
  for (unsigned int i = 0; i < r.rollers.size(); ++i)
    r.analytic.roller_forces[i] = r.rollers[i].analytic_force;
  r.analytic.pin_forces.clear();
  for (const auto& l : r.pins)
    r.analytic.pin_forces.push_back(l.analytic_force);
}
} // namespace

CycloidLoadResult solve_cycloid_case(const CycloidLoadSettings& settings)
{
  check_cycloid_load_settings(settings);
  if (settings.output_torque > 0.)
    return CycloidLoads<2>(settings).run();
  CycloidLoadResult r = CycloidLoads<2>(mirrored(settings)).run();
  mirror_back(r, settings);
  return r;
}

std::vector<CycloidLoadResult>
solve_cycloid_cases(MPI_Comm communicator, const std::vector<CycloidLoadSettings>& cases,
                    const std::string& scene_file_stem,
                    const std::function<void(const std::string&)>& progress)
{
  const unsigned int rank = Utilities::MPI::this_mpi_process(communicator);
  if (cases.empty())
    return {};
  const unsigned int rollers = cases[0].scene.ring.rollers, pins = cases[0].scene.output_pins;
  const unsigned int length = scalar_fields + contact_fields * (rollers + pins) + 4;
  for (const auto& c : cases)
    if (c.scene.ring.rollers != rollers || c.scene.output_pins != pins)
      throw InputError("Cycloid disc/rollers", "every case of a sweep needs the same drive");
  std::vector<double> rows(length * cases.size(), 0.);
  // A failure stops every rank soon (fem::distribute_items); the first failing case's error
  // is thrown on every rank.
  fem::distribute_items(
      communicator, cases.size(),
      [&](const unsigned int k)
      {
        CycloidLoadSettings settings = cases[k];
        settings.scene_file = scene_file_stem + "_" + std::to_string(k) + ".msh";
        CycloidLoadResult r;
        const fem::Failure failure =
            fem::catch_failure([&]() { r = solve_cycloid_case(settings); });
        std::filesystem::remove(settings.scene_file);
        failure.rethrow();
        const std::vector<double> row = pack(r, length);
        std::copy(row.begin(), row.end(), rows.begin() + k * length);
        if (progress && rank == 0)
          progress("case " + std::to_string(k + 1) + "/" + std::to_string(cases.size()) +
                   ": P_max = " + std::to_string(r.max_roller_force) + " N, " +
                   std::to_string(r.n_dofs) + " DoFs, " + std::to_string(r.total_time) +
                   " s (scene " + std::to_string(r.scene_time) + " s, setup " +
                   std::to_string(r.setup_time) + " s, solve " + std::to_string(r.solve_time) +
                   " s)");
      });
  Utilities::MPI::sum(rows, communicator, rows);
  std::vector<CycloidLoadResult> results;
  for (unsigned int k = 0; k < cases.size(); ++k)
    results.push_back(unpack(&rows[k * length], rollers, pins));
  return results;
}

std::vector<double> crank_angles(double start, double span, unsigned int positions)
{
  std::vector<double> angles;
  for (unsigned int k = 0; k < positions; ++k)
    angles.push_back(start + span * k / positions);
  return angles;
}

std::vector<double> torsional_levels(double rated_torque, unsigned int steps)
{
  std::vector<double> levels;
  const double m = std::abs(rated_torque);
  for (const double f : {0.03, 0.5, 1.})
  {
    levels.push_back(f * m);
    levels.push_back(-f * m);
  }
  for (unsigned int k = 0; k <= steps; ++k)
    levels.push_back(-m + 2. * m * k / std::max(steps, 1u));
  std::sort(levels.begin(), levels.end());
  std::vector<double> unique;
  for (const double t : levels)
    if (std::abs(t) > 1e-9 * m && (unique.empty() || std::abs(t - unique.back()) > 1e-9 * m))
      unique.push_back(t);
  return unique;
}

TorsionalCurve torsional_curve(double rated_torque, const std::vector<CycloidLoadResult>& results)
{
  TorsionalCurve curve;
  std::map<double, double> rotation; // torque -> θ
  for (const auto& r : results)
    rotation[r.output_torque] = r.output_rotation;
  for (const auto& [t, theta] : rotation)
  {
    curve.torques.push_back(t);
    curve.rotations.push_back(theta);
  }
  const double m = std::abs(rated_torque);
  const auto at = [&rotation, m](double fraction)
  {
    for (const auto& [t, theta] : rotation)
      if (std::abs(t - fraction * m) < 1e-9 * m)
        return theta;
    throw SolverFailure("torsional curve", "no solve at " + std::to_string(fraction * m) + " N·m");
  };
  const double positive = 0.5 * m / (at(1.) - at(0.5));
  const double negative = 0.5 * m / (at(-0.5) - at(-1.));
  curve.stiffness = 0.5 * (positive + negative);
  curve.lost_motion = at(0.03) - at(-0.03);
  curve.hysteresis = 0.; // frictionless: the unloading branch is the loading one
  return curve;
}
} // namespace gearstiff::stiffness
