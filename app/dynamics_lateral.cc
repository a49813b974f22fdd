#include "app/dynamics_lateral.h"

#include "app/lateral_parameters.h"
#include "app/units.h"
#include "dynamics/lateral_model.h"
#include "dynamics/lateral_response.h"
#include "errors/errors.h"
#include "errors/format.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace gearstiff::app
{
namespace
{
using namespace gearstiff::dynamics;

double class_code(LateralModeClass type)
{
  return static_cast<double>(static_cast<int>(type));
}

void report_modes(const LateralModel& model, const LateralModes& modes, Report& report)
{
  const unsigned int n = model.n_planets();
  auto& table =
      report.add_table("lateral_modes", {"mode", "frequency", "class", "multiplicity", "group"},
                       {"-", "Hz", "-", "-", "-"});
  unsigned int counts[4] = {0, 0, 0, 0};
  for (std::size_t g = 0; g < modes.groups.size(); ++g)
  {
    const LateralModeGroup& group = modes.groups[g];
    ++counts[static_cast<int>(group.type)];
    for (const unsigned int k : group.modes)
      table.add_row({double(k + 1), modes.frequencies[k], class_code(group.type),
                     double(group.modes.size()), double(g + 1)});
  }
  report.add_text("mode classes",
                  "0 = rotational (central members only rotate), 1 = translational (central "
                  "members only translate), 2 = planet (central members still), 3 = mixed; "
                  "Lin & Parker 1999 for " +
                      std::to_string(n) +
                      " equally spaced planets: 6 rotational (x1), 6 "
                      "translational (x2), " +
                      std::to_string(n >= 4 ? 3 : 0) + " planet (x" +
                      std::to_string(n >= 3 ? n - 3 : 0) + ")");
  report.add_value("rotational_groups", counts[0], "-", "rotational frequencies");
  report.add_value("translational_groups", counts[1], "-", "translational frequencies");
  report.add_value("planet_groups", counts[2], "-", "planet-mode frequencies");
  report.add_value("mixed_groups", counts[3], "-", "frequencies of mixed modes");

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
                                 {"-", "deg", "µm", "µm", "N", "N", "-", "-", "N", "N"});
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
  const char* names[3] = {"carrier", "ring", "sun"};
  for (unsigned int j = 0; j < 3; ++j)
    report.add_value(std::string("bearing_force_") + names[j],
                     std::hypot(s.bearing_force(j, 0), s.bearing_force(j, 1)), "N",
                     std::string("static bearing force on the ") + names[j] + " (x " +
                         format_number(s.bearing_force(j, 0), 6) + " N, y " +
                         format_number(s.bearing_force(j, 1), 6) + " N)");
}

void report_campbell(const LateralParameters& p, const LateralModel& model, Report& report)
{
  // From standstill to twice the nominal carrier speed (or 1000 rpm when the carrier is held).
  const double top = std::abs(p.carrier_speed) > 0. ? 2. * std::abs(p.carrier_speed) : 1000. * rpm;
  const unsigned int points = 41;
  std::vector<std::string> columns{"carrier_speed"}, units{"rpm"};
  const unsigned int n_modes = model.free_dofs().size();
  for (unsigned int k = 0; k < n_modes; ++k)
  {
    columns.push_back("f" + std::to_string(k + 1));
    units.push_back("Hz");
  }
  auto& table = report.add_table("lateral_campbell", columns, units);
  for (unsigned int i = 0; i < points; ++i)
  {
    const double speed = top * i / (points - 1);
    std::vector<double> row{speed / rpm};
    for (const double f : model.gyroscopic_frequencies(speed))
      row.push_back(f);
    table.add_row(row);
  }
  const std::vector<double> nominal = model.gyroscopic_frequencies(p.carrier_speed);
  report.add_value("carrier_speed", p.carrier_speed / rpm, "rpm", "nominal carrier speed");
  report.add_value("lowest_frequency_running", nominal.size() > 1 ? nominal[1] : 0., "Hz",
                   "second-lowest natural frequency at the nominal carrier speed, gyroscopic "
                   "and centripetal terms included (the lowest is the rigid rotation)");
}
// RK4 on the lateral stage: orbits and bearing forces of the central members.
void report_response(const LateralParameters& p, const LateralModel& model, Report& report)
{
  const LateralResponse r = integrate_lateral(model, p.load, p.excitation, p.run);
  auto& orbit = report.add_table(
      "lateral_orbit", {"time", "carrier_x", "carrier_y", "ring_x", "ring_y", "sun_x", "sun_y"},
      {"s", "µm", "µm", "µm", "µm", "µm", "µm"});
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
}
} // namespace

void run_lateral_dynamics(dealii::ParameterHandler& prm, CommandContext& context)
{
  const LateralParameters p = parse_lateral_parameters(prm);
  const LateralModel model(p.stage);
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
  report_response(p, model, report);

  if (context.writes_files())
  {
    {
      const TemporaryCsv csv(report, "lateral_load_sharing");
      context.plot("plot_lateral.py", {"sharing", csv.path()}, "lateral_load_sharing.png",
                   "planet load sharing factors");
    }
    {
      const TemporaryCsv csv(report, "lateral_orbit");
      context.plot("plot_lateral.py", {"orbit", csv.path()}, "lateral_orbit.png",
                   "orbits of sun, ring and carrier (x, y)");
    }
    if (p.gyroscopic)
    {
      const TemporaryCsv csv(report, "lateral_campbell");
      context.plot("plot_lateral.py", {"campbell", csv.path()}, "lateral_campbell.png",
                   "natural frequencies over carrier speed (gyroscopic)");
    }
  }
}
} // namespace gearstiff::app
