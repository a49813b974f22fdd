#include "stiffness/cycloid_sweep.h"

#include "errors/errors.h"
#include "fem/parallel.h"
#include "geometry/fields.h"

#include <algorithm>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <map>

namespace gearstiff::stiffness
{
using namespace dealii;

namespace
{
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
  for (const auto& c : cases)
    if (c.scene.ring.rollers != rollers || c.scene.output_pins != pins)
      throw InputError(geometry::field::disc("rollers"),
                       "every case of a sweep needs the same drive");
  std::vector<std::pair<unsigned int, CycloidLoadResult>> mine; // (case, result) solved here
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
        mine.emplace_back(k, r);
        if (progress) // on the rank that solved the case
          progress("case " + std::to_string(k + 1) + "/" + std::to_string(cases.size()) +
                   ": P_max = " + std::to_string(r.max_roller_force) + " N, " +
                   std::to_string(r.n_dofs) + " DoFs, " + std::to_string(r.total_time) +
                   " s (scene " + std::to_string(r.scene_time) + " s, setup " +
                   std::to_string(r.setup_time) + " s, solve " + std::to_string(r.solve_time) +
                   " s)");
      });
  // Every rank receives every case's result, each member through its for_each_field list.
  std::vector<CycloidLoadResult> results(cases.size());
  for (const auto& solved : Utilities::MPI::all_gather(communicator, mine))
    for (const auto& [k, r] : solved)
      results[k] = r;
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
