#include "app/dynamics/dynamics_lateral.h"

#include "app/core/units.h"
#include "app/dynamics/lateral_mode_report.h"
#include "app/dynamics/lateral_parameters.h"
#include "app/dynamics/sweep_categories.h"
#include "dynamics/lateral_model.h"
#include "dynamics/lateral_response.h"
#include "dynamics/lateral_sweep.h"
#include "errors/errors.h"
#include "errors/format.h"
#include "errors/limits.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

namespace gearstiff::app
{
namespace
{
using namespace gearstiff::dynamics;

void report_modes(const LateralModel& model, const LateralModes& modes, Report& report)
{
  const unsigned int n = model.n_planets();
  report_mode_classes(modes, "lateral_modes",
                      "; Lin & Parker 1999 for " + std::to_string(n) +
                          " equally spaced planets: 6 rotational (x1), 6 translational (x2), " +
                          std::to_string(n >= 4 ? 3 : 0) + " planet (x" +
                          std::to_string(n >= 3 ? n - 3 : 0) + ")",
                      report);

  std::vector<std::string> columns{"mode", "frequency"}, units{"-", "Hz"};
  std::vector<std::string> bodies{"carrier", "ring", "sun"};
  for (unsigned int p = 0; p < n; ++p)
    bodies.push_back("planet" + std::to_string(p + 1));
  for (const std::string& b : bodies)
    for (const char* type : {"_translation", "_rotation"})
    {
      columns.push_back("kinetic_" + b + type);
      units.push_back("-");
    }
  for (const char* group : {"bearings", "supports", "pins", "sun_meshes", "ring_meshes"})
  {
    columns.push_back(std::string("strain_") + group);
    units.push_back("-");
  }
  auto& energy = report.add_table("lateral_modal_energy", columns, units);
  for (Eigen::Index k = 0; k < modes.frequencies.size(); ++k)
  {
    std::vector<double> row{double(k + 1), modes.frequencies[k]};
    for (Eigen::Index c = 0; c < modes.kinetic_energy_share.cols(); ++c)
      row.push_back(modes.kinetic_energy_share(k, c));
    for (Eigen::Index c = 0; c < modes.strain_energy_share.cols(); ++c)
      row.push_back(modes.strain_energy_share(k, c));
    energy.add_row(row);
  }
}

void report_statics(const LateralParameters& p, const LateralModel& model, Report& report)
{
  const LateralStaticState s = model.static_state(p.load);
  const unsigned int n = model.n_planets();
  // A linear model cannot let a mesh open: a pin error that unloads a mesh is outside it.
  double mean = 0.;
  for (const double f : s.sun_mesh_force)
    mean += f / n;
  for (unsigned int k = 0; k < n; ++k)
    if (s.sun_mesh_force[k] * mean <= 0. || s.ring_mesh_force[k] * mean <= 0.)
      throw InputError("Train/planet pin errors",
                       "planet " + std::to_string(k + 1) +
                           " would lose contact (its mesh force changes sign): the pin error "
                           "exceeds what the load closes; the linear model does not apply");
  auto& table = report.add_table("lateral_load_sharing",
                                 {"planet", "angle", "pin_error_tangential", "pin_error_radial",
                                  "sun_mesh_force", "ring_mesh_force", "lsf_sun", "lsf_ring",
                                  "pin_force_radial", "pin_force_tangential"},
                                 {"-", "deg", "um", "um", "N", "N", "-", "-", "N", "N"});
  const LateralStage& stage = p.stage;
  double largest = 0.;
  for (unsigned int k = 0; k < n; ++k)
  {
    table.add_row({double(k + 1), stage.planet_angles[k] / degree,
                   stage.pin_error_tangential.empty() ? 0. : stage.pin_error_tangential[k] * 1e6,
                   stage.pin_error_radial.empty() ? 0. : stage.pin_error_radial[k] * 1e6,
                   s.sun_mesh_force[k], s.ring_mesh_force[k], s.sun_load_sharing[k],
                   s.ring_load_sharing[k], s.pin_radial_force[k], s.pin_tangential_force[k]});
    largest = std::max(largest, s.sun_load_sharing[k]);
  }
  report.add_value("lsf_max", largest, "-",
                   "largest planet load sharing factor N·F_sn/ΣF_s (1 = equal shares)");
  report.add_value("output_torque", s.output_torque, "N·m",
                   "load on the output balancing the input torque");
  // A bearing force below 1e-9 of the largest mesh force is the round-off of a member the
  // planets balance (equal, equally spaced planets): reported as 0, not as a 1e-13 N value.
  double scale = 0.; // N
  for (std::size_t k = 0; k < s.sun_mesh_force.size(); ++k)
    scale = std::max({scale, std::abs(s.sun_mesh_force[k]), std::abs(s.ring_mesh_force[k])});
  const auto force = [&](unsigned int j, unsigned int axis)
  { return std::abs(s.bearing_force(j, axis)) < 1e-9 * scale ? 0. : s.bearing_force(j, axis); };
  const char* names[3] = {"carrier", "ring", "sun"};
  for (unsigned int j = 0; j < 3; ++j)
    report.add_value(std::string("bearing_force_") + names[j], std::hypot(force(j, 0), force(j, 1)),
                     "N",
                     std::string("static bearing force on the ") + names[j] + " (x " +
                         format_number(force(j, 0), 6) + " N, y " + format_number(force(j, 1), 6) +
                         " N; below 1e-9 of the largest mesh force: 0, balanced)");
}

// Mesh orders drawn on the Campbell chart and searched for crossings.
constexpr unsigned int campbell_mesh_orders = 3;

// Where natural frequency `mode` (index among the ascending frequencies) meets the k-th mesh
// order k·ρ·Ω, ρ = f_mesh/|Ω_c| [Hz per rad/s], between carrier speeds low and high [rad/s]
// where the difference changes sign: bisection to 1e-10 of the bracket.
double crossing_speed(const LateralModel& model, unsigned int mode, double order_slope, double low,
                      double high)
{
  auto difference = [&](double speed)
  { return model.gyroscopic_frequencies(speed)[mode] - order_slope * speed; };
  double f_low = difference(low);
  for (int i = 0; i < 40 && high - low > 1e-10 * high; ++i)
  {
    const double middle = 0.5 * (low + high);
    const double f_middle = difference(middle);
    if ((f_middle > 0.) == (f_low > 0.))
    {
      low = middle;
      f_low = f_middle;
    }
    else
      high = middle;
  }
  return 0.5 * (low + high);
}

// Crossings of the mesh-order lines with the natural frequencies (Campbell chart): a table of
// order, mode, carrier and input speed, frequency.
void report_crossings(const LateralParameters& p, const LateralModel& model,
                      const std::vector<double>& speeds,
                      const std::vector<std::vector<double>>& frequencies, Report& report)
{
  const double slope = p.excitation.mesh_frequency / std::abs(p.carrier_speed); // Hz per rad/s
  auto& table = report.add_table("lateral_campbell_crossings",
                                 {"order", "mode", "carrier_speed", "input_speed", "frequency"},
                                 {"-", "-", "rpm", "rpm", "Hz"});
  unsigned int count = 0;
  for (unsigned int k = 1; k <= campbell_mesh_orders; ++k)
    for (std::size_t mode = 0; mode < frequencies.front().size(); ++mode)
      for (std::size_t i = 1; i < speeds.size(); ++i)
      {
        const double before = frequencies[i - 1][mode] - k * slope * speeds[i - 1];
        const double after = frequencies[i][mode] - k * slope * speeds[i];
        // Rigid modes (0 Hz) meet the lines at standstill only; a crossing lies inside a step.
        if (frequencies[i][mode] <= 0. || !((before > 0.) && (after <= 0.)))
          continue;
        const double speed = crossing_speed(model, mode, k * slope, speeds[i - 1], speeds[i]);
        table.add_row({double(k), double(mode + 1), speed / rpm,
                       speed * p.input_speed / p.carrier_speed / rpm, k * slope * speed});
        ++count;
      }
  report.add_value("campbell_crossings", count, "-",
                   "crossings of the mesh orders 1.." + std::to_string(campbell_mesh_orders) +
                       " with the natural frequencies on the Campbell chart");
  report.add_value("mesh_frequency_per_carrier_rpm", slope * rpm, "Hz/rpm",
                   "mesh frequency per carrier speed (order 1 line)");
}

// The Campbell table's unstable speeds (`first_unstable` [rad/s], −1: none) in words.
void report_instability(unsigned int unstable, double first_unstable, unsigned int points,
                        Report& report)
{
  report.add_value("campbell_unstable_speeds", unstable, "-",
                   "carrier speeds of the Campbell table (of " + std::to_string(points) +
                       ") where the undamped stage is unstable (divergence or flutter)");
  if (unstable > 0)
    report.add_text("campbell stability",
                    "unstable from a carrier speed of " + format_number(first_unstable / rpm, 6) +
                        " rpm: the frequencies there are |Im λ| of growing roots, not "
                        "vibration frequencies (column stability, growth_rate)");
}

void report_campbell(const LateralParameters& p, const LateralModel& model, Report& report)
{
  // From standstill to twice the nominal carrier speed (or 1000 rpm when the carrier is held).
  const double top = std::abs(p.carrier_speed) > 0. ? 2. * std::abs(p.carrier_speed) : 1000. * rpm;
  const unsigned int points = 41;
  const bool orders = std::abs(p.carrier_speed) > 0. && p.excitation.mesh_frequency > 0.;
  std::vector<std::string> columns{"carrier_speed"}, units{"rpm"};
  const unsigned int n_modes = model.free_dofs().size();
  for (unsigned int k = 0; k < n_modes; ++k)
  {
    columns.push_back("f" + std::to_string(k + 1));
    units.push_back("Hz");
  }
  for (unsigned int k = 1; orders && k <= campbell_mesh_orders; ++k)
  {
    columns.push_back("mesh_order_" + std::to_string(k));
    units.push_back("Hz");
  }
  // |Im λ| alone reads a divergent or fluttering mode as a frequency: each speed says whether
  // the undamped stage is stable there.
  columns.insert(columns.end(), {"stability", "growth_rate"});
  units.insert(units.end(), {"-", "1/s"});
  auto& table = report.add_table("lateral_campbell", columns, units);
  table.set_categories("stability", {{0, "stable"}, {1, "divergence"}, {2, "flutter"}});
  std::vector<double> speeds;
  std::vector<std::vector<double>> frequencies;
  double first_unstable = -1.;
  unsigned int unstable = 0;
  for (unsigned int i = 0; i < points; ++i)
  {
    speeds.push_back(top * i / (points - 1));
    frequencies.push_back(model.gyroscopic_frequencies(speeds.back()));
    const dynamics::GyroscopicStability stability = model.gyroscopic_stability(speeds.back());
    std::vector<double> row{speeds.back() / rpm};
    row.insert(row.end(), frequencies.back().begin(), frequencies.back().end());
    for (unsigned int k = 1; orders && k <= campbell_mesh_orders; ++k)
      row.push_back(k * p.excitation.mesh_frequency * speeds.back() / std::abs(p.carrier_speed));
    row.push_back(stability.stable ? 0. : stability.oscillating ? 2. : 1.);
    row.push_back(stability.growth_rate);
    table.add_row(row);
    if (!stability.stable && unstable++ == 0)
      first_unstable = speeds.back();
  }
  report_instability(unstable, first_unstable, points, report);
  if (orders)
    report_crossings(p, model, speeds, frequencies, report);
  const std::vector<double> nominal = model.gyroscopic_frequencies(p.carrier_speed);
  report.add_value("carrier_speed", p.carrier_speed / rpm, "rpm", "nominal carrier speed");
  report.add_value("lowest_frequency_running", nominal.size() > 1 ? nominal[1] : 0., "Hz",
                   "second-lowest natural frequency at the nominal carrier speed, gyroscopic "
                   "and centripetal terms included (the lowest is the rigid rotation)");
}

// Speed sweep: K_v, bearing forces and orbit amplitudes against the input speed.
// `seconds_per_step` [s]: measured on this model by the response run, so the estimate stated
// (and checked) before the first speed holds for this stage's size and mesh law.
void report_sweep(const LateralParameters& p, const LateralModel& model, double seconds_per_step,
                  CommandContext& context)
{
  Report& report = context.report;
  const unsigned int runs =
      p.sweep_points * (p.sweep.direction == dynamics::SweepDirection::both ? 2 : 1);
  const double estimate =
      lateral_sweep_work(model, p.excitation, p.run, p.sweep).steps * seconds_per_step;
  const std::string work = std::to_string(runs) + " runs, ~" + format_number(estimate, 3) + " s" +
                           " (" + format_number(seconds_per_step * 1e6, 3) +
                           " µs an RK4 step, measured on the response run)";
  if (estimate > limits::max_run_seconds)
    throw InputError("Speed sweep/points",
                     "the sweep would take " + work + ", over the limit of " +
                         format_number(limits::max_run_seconds, 4) +
                         " s (docs/limits.md): fewer points, a shorter Simulation/steady "
                         "state start or more damping");
  context.progress("dynamics lateral sweep", "estimate: " + work);
  const auto progress = context.progress_counter("dynamics lateral sweep", runs);
  const LateralSweepResult sweep =
      lateral_speed_sweep(model, p.load, p.excitation, p.run, p.sweep, progress);
  auto& table = report.add_table(
      "lateral_speed_sweep",
      {"input_speed", "carrier_speed", "mesh_frequency", "direction", "status", "kv_max",
       "sun_mesh_force_max", "ring_mesh_force_max", "bearing_force_carrier", "bearing_force_ring",
       "bearing_force_sun", "orbit_carrier", "orbit_ring", "orbit_sun", "separation_fraction",
       "time_step"},
      {"rpm", "rpm", "Hz", "-", "-", "-", "N", "N", "N", "N", "N", "um", "um", "um", "-", "us"});
  table.set_categories("direction", sweep_direction_categories());
  table.set_categories("status", sweep_status_categories());
  unsigned int counts[4] = {0, 0, 0, 0};
  unsigned long steps = 0;
  for (const LateralSweepPoint& point : sweep.points)
  {
    const LateralWindowSummary& s = point.summary;
    table.add_row({std::abs(point.input_speed) / rpm, std::abs(point.carrier_speed) / rpm,
                   point.mesh_frequency, point.descending ? 1. : 0.,
                   double(static_cast<int>(point.status)), s.kv_max, s.sun_mesh_force_max,
                   s.ring_mesh_force_max, s.bearing_force_max[0], s.bearing_force_max[1],
                   s.bearing_force_max[2], s.orbit_amplitude[0] * 1e6, s.orbit_amplitude[1] * 1e6,
                   s.orbit_amplitude[2] * 1e6, s.separation_fraction, point.time_step * 1e6});
    ++counts[static_cast<int>(point.status)];
    steps += point.steps;
  }
  report.add_text(
      "lateral sweep",
      sweep_direction_name(p.sweep.direction) +
          (p.sweep.continuation ? ", each speed continuing from the previous one's state" : "") +
          "; window " + std::to_string(p.sweep.window_periods) + " mesh periods after " +
          format_number(sweep.settle_time * 1e3, 4) +
          " ms (decay of the slowest mode to 1/1000 unless Simulation/steady state "
          "start); status: " +
          sweep_status_meanings());
  report.add_value("lateral_sweep_points", sweep.points.size(), "-", "runs of the lateral sweep");
  report.add_value("lateral_sweep_diverged", counts[1], "-", "runs where RK4 diverged");
  report.add_value("lateral_sweep_contact_loss", counts[2], "-",
                   "runs where a linear mesh force turned negative");
  report.add_value("lateral_sweep_not_steady", counts[3], "-", "runs not periodic in the window");
  report.add_value("lateral_sweep_steps", double(steps), "-", "RK4 steps of the sweep");
  report.add_value("lateral_sweep_time", sweep.wall_time, "s", "wall time of the lateral sweep");
}

// RK4 on the lateral stage: orbits and bearing forces of the central members.
// Returns the measured wall time of one RK4 step [s].
double report_response(const LateralParameters& p, const LateralModel& model, Report& report)
{
  const LateralResponse r = integrate_lateral(model, p.load, p.excitation, p.run);
  auto& orbit = report.add_table(
      "lateral_orbit", {"time", "carrier_x", "carrier_y", "ring_x", "ring_y", "sun_x", "sun_y"},
      {"s", "um", "um", "um", "um", "um", "um"});
  auto& forces = report.add_table(
      "lateral_bearing_forces",
      {"time", "carrier_fx", "carrier_fy", "ring_fx", "ring_fy", "sun_fx", "sun_fy"},
      {"s", "N", "N", "N", "N", "N", "N"});
  Eigen::Vector3d largest = Eigen::Vector3d::Zero();
  const std::size_t second_half = r.time.size() / 2;
  for (std::size_t i = 0; i < r.time.size(); ++i)
  {
    std::vector<double> row{r.time[i]}, force_row{r.time[i]};
    for (unsigned int j = 0; j < 3; ++j)
      for (unsigned int c = 0; c < 2; ++c)
      {
        row.push_back(r.position[i](j, c) * 1e6);
        force_row.push_back(r.bearing_force[i](j, c));
      }
    orbit.add_row(row);
    forces.add_row(force_row);
    if (i >= second_half)
      for (unsigned int j = 0; j < 3; ++j)
        largest[j] = std::max(largest[j], r.bearing_force[i].row(j).norm());
  }
  const char* names[3] = {"carrier", "ring", "sun"};
  for (unsigned int j = 0; j < 3; ++j)
    report.add_value(std::string("bearing_force_max_") + names[j], largest[j], "N",
                     std::string("largest dynamic bearing force on the ") + names[j] +
                         " (second half of the run)");
  report.add_value("time_step", p.run.time_step * 1e6, "µs", "RK4 time step");
  report.add_value("rk4_step_limit", r.rk4_step_limit * 1e6, "µs",
                   "RK4 stability limit of the lateral model (largest mesh stiffness)");
  report.add_value("steps", double(r.steps), "-", "integration steps");
  report.add_value("integration_time", r.wall_time * 1e3, "ms", "wall time of the integration");
  return r.steps > 0 ? r.wall_time / double(r.steps) : 0.;
}
} // namespace

void run_lateral_dynamics(dealii::ParameterHandler& prm, CommandContext& context)
{
  const LateralParameters p = parse_lateral_parameters(prm);
  const LateralModel model(p.stage);
  context.chart_case = "lateral stage, " + std::to_string(model.n_planets()) + " planets, input " +
                       format_number(std::abs(p.input_speed) / rpm, 5) + " rpm, " +
                       format_number(std::abs(p.load.input_torque), 5) + " N·m on the " +
                       (p.load.input == dynamics::LateralMember::sun       ? "sun"
                        : p.load.input == dynamics::LateralMember::carrier ? "carrier"
                                                                           : "ring");
  Report& report = context.report;
  report.add_text(
      "model",
      "planar lateral-torsional stage (Lin & Parker 1999): " + std::to_string(model.n_planets()) +
          " planets, " + std::to_string(model.free_dofs().size()) +
          " DOF (x, y, u = r·theta per member; planets radial, tangential, u)");
  report.add_text("members", "sun " + p.sun + ", ring " + p.ring + ", carrier " + p.carrier +
                                 ", planet " + p.planet);
  for (std::size_t i = 0; i < p.notes.size(); ++i)
    report.add_text("lateral note " + std::to_string(i + 1), p.notes[i]);

  const auto start = std::chrono::steady_clock::now();
  const LateralModes modes = model.modes();
  report.add_value("modes_time",
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() *
                       1e3,
                   "ms", "wall time of the modes and their classification");
  report_modes(model, modes, report);
  report_statics(p, model, report);
  if (p.gyroscopic)
    report_campbell(p, model, report);
  const double seconds_per_step = report_response(p, model, report);
  report.add_value("ring_mesh_offset", p.ring_mesh_offset, "base pitches",
                   "each planet's ring mesh after its sun mesh (Parker & Lin 2004 phasing)");
  if (p.sweep_points > 0)
    report_sweep(p, model, seconds_per_step, context);

  if (context.writes_files())
  {
    {
      const TemporaryCsv csv(report, "lateral_load_sharing");
      context.plot("plot_lateral.py", {"sharing", csv.path()}, "lateral_load_sharing.png",
                   "planet load sharing factors");
    }
    {
      const TemporaryCsv csv(report, "lateral_orbit");
      // An orbit below 1e-9 of the sun's base radius is round-off: said, not drawn.
      context.plot("plot_lateral.py",
                   {"orbit", csv.path(), format_number(1e-9 * p.stage.sun.radius * 1e6, 3)},
                   "lateral_orbit.png", "orbits of sun, ring and carrier (x, y)");
    }
    if (p.sweep_points > 0)
    {
      const TemporaryCsv csv(report, "lateral_speed_sweep");
      context.plot("plot_lateral.py", {"sweep", csv.path()}, "lateral_speed_sweep.png",
                   "K_v, bearing forces and orbit amplitudes against input speed");
    }
    if (p.gyroscopic)
    {
      const TemporaryCsv csv(report, "lateral_campbell");
      std::vector<std::string> arguments{"campbell", csv.path()};
      std::optional<TemporaryCsv> crossings;
      const auto& tables = report.tables();
      if (std::any_of(tables.begin(), tables.end(),
                      [](const ReportTable& t) { return t.name == "lateral_campbell_crossings"; }))
        arguments.push_back(crossings.emplace(report, "lateral_campbell_crossings").path());
      context.plot("plot_lateral.py", arguments, "lateral_campbell.png",
                   "natural frequencies over carrier speed (gyroscopic), crossings circled, "
                   "unstable speeds shaded");
    }
  }
}
} // namespace gearstiff::app
