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
// case, so one sum gathers them all): a 1 marking the row as filled, the scalar fields, each
// roller's and pin's fields, the analytic summary. One list of members serves both directions.
using Result = CycloidLoadResult;
using Load = CycloidContactLoad;
const std::vector<double Result::*> result_reals = {&Result::crank_angle,
                                                    &Result::disc_rotation,
                                                    &Result::output_torque,
                                                    &Result::max_roller_force,
                                                    &Result::max_pin_force,
                                                    &Result::bearing_force,
                                                    &Result::bearing_angle,
                                                    &Result::bearing_force_direction,
                                                    &Result::input_torque,
                                                    &Result::input_torque_ratio,
                                                    &Result::disc_force_balance,
                                                    &Result::disc_moment_balance,
                                                    &Result::output_moment_balance,
                                                    &Result::closing_rotation,
                                                    &Result::output_rotation,
                                                    &Result::disc_rotation_load,
                                                    &Result::max_contact_pressure,
                                                    &Result::disc_von_mises,
                                                    &Result::contact_size,
                                                    &Result::scene_time,
                                                    &Result::setup_time,
                                                    &Result::solve_time,
                                                    &Result::total_time,
                                                    &Result::meshing_time,
                                                    &Result::read_time,
                                                    &Result::factorization_time,
                                                    &Result::iteration_time,
                                                    &Result::evaluate_time};
const std::vector<unsigned int Result::*> result_counts = {
    &Result::loaded_rollers, &Result::loaded_pins,           &Result::n_cells,
    &Result::n_dofs,         &Result::active_set_iterations, &Result::meshing_attempts};
const std::vector<double Load::*> load_reals = {
    &Load::angle,   &Load::initial_gap,  &Load::force,          &Load::force_x,
    &Load::force_y, &Load::max_pressure, &Load::contact_length, &Load::analytic_force};
const std::vector<double CycloidAnalyticResult::*> analytic_reals = {
    &CycloidAnalyticResult::max_roller_force, &CycloidAnalyticResult::max_pin_force,
    &CycloidAnalyticResult::disc_rotation, &CycloidAnalyticResult::output_rotation,
    &CycloidAnalyticResult::input_torque};
const unsigned int load_fields = load_reals.size() + 2; // + index, candidate

unsigned int row_length(unsigned int rollers, unsigned int pins)
{
  return 1 + result_reals.size() + result_counts.size() + load_fields * (rollers + pins) +
         analytic_reals.size() + 2; // + the bearing force's components
}

std::vector<double> pack(const Result& r, unsigned int length)
{
  std::vector<double> row{1.};
  for (const auto m : result_reals)
    row.push_back(r.*m);
  for (const auto m : result_counts)
    row.push_back(r.*m);
  for (const auto* loads : {&r.rollers, &r.pins})
    for (const Load& l : *loads)
    {
      row.push_back(l.index);
      for (const auto m : load_reals)
        row.push_back(l.*m);
      row.push_back(l.candidate);
    }
  for (const auto m : analytic_reals)
    row.push_back(r.analytic.*m);
  row.push_back(r.analytic.bearing_force.x());
  row.push_back(r.analytic.bearing_force.y());
  if (row.size() != length)
    throw SolverFailure("cycloid cases", "result row of unexpected length");
  return row;
}

Result unpack(const double* row, unsigned int rollers, unsigned int pins)
{
  Result r;
  const double* x = row + 1;
  for (const auto m : result_reals)
    r.*m = *x++;
  for (const auto m : result_counts)
    r.*m = std::lround(*x++);
  for (auto [loads, n] : {std::pair(&r.rollers, rollers), std::pair(&r.pins, pins)})
    for (unsigned int k = 0; k < n; ++k)
    {
      Load l;
      l.index = std::lround(*x++);
      for (const auto m : load_reals)
        l.*m = *x++;
      l.candidate = *x++ > 0.5;
      loads->push_back(l);
    }
  for (const auto m : analytic_reals)
    r.analytic.*m = *x++;
  r.analytic.bearing_force.x() = *x++;
  r.analytic.bearing_force.y() = *x++;
  for (const Load& l : r.rollers)
    r.analytic.roller_forces.push_back(l.analytic_force);
  for (const Load& l : r.pins)
    r.analytic.pin_forces.push_back(l.analytic_force);
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
  r.closing_rotation = -r.closing_rotation;
  r.disc_rotation_load = -r.disc_rotation_load;
  r.analytic.output_rotation = -r.analytic.output_rotation;
  r.analytic.disc_rotation = -r.analytic.disc_rotation;
  r.analytic.bearing_force.y() = -r.analytic.bearing_force.y();
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
  if (cases.empty())
    return {};
  const unsigned int rollers = cases[0].scene.ring.rollers, pins = cases[0].scene.output_pins;
  const unsigned int length = row_length(rollers, pins);
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
        if (progress) // on the rank that solved the case
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
  const auto solved_at = [&results, m](double fraction) -> const CycloidLoadResult&
  {
    for (const auto& r : results)
      if (std::abs(r.output_torque - fraction * m) < 1e-9 * m)
        return r;
    throw SolverFailure("torsional curve", "no solve at " + std::to_string(fraction * m) + " N·m");
  };
  const auto at = [&solved_at](double fraction) { return solved_at(fraction).output_rotation; };
  const double positive = 0.5 * m / (at(1.) - at(0.5));
  const double negative = 0.5 * m / (at(-0.5) - at(-1.));
  curve.stiffness = 0.5 * (positive + negative);
  curve.lost_motion = at(0.03) - at(-0.03);
  curve.backlash = solved_at(0.03).closing_rotation - solved_at(-0.03).closing_rotation;
  curve.hysteresis = 0.; // frictionless: the unloading branch is the loading one
  return curve;
}
} // namespace gearstiff::stiffness
