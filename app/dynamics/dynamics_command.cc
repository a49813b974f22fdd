// `gearstiff dynamics`: torsional vibration of a gear train with time-varying mesh stiffness,
// the dynamic factor K_v (simulated, and ISO 6336-1 method B beside it), the mesh-force spectrum
// and the K_v resonance chart over input speed.
//
//   gearstiff dynamics                 the built-in split-path gearbox of docs/references.md §1
//                                      (Reszuta & Drewniak 2015): T1 = 49.4 N·m at 1450 rpm
//   gearstiff dynamics case.prm        any tree-shaped train (Train, Gear n, Mesh n sections)
//   gearstiff dynamics --set "Simulation/integrator=HHT-alpha" --set "Speed sweep/points=0"
//   gearstiff dynamics -o out          also writes time series, spectrum, tables and PNG charts
//
// How the paper's 3-DOF equations are implemented (sign of friction, phase, start) is described
// in dynamics/torsional_model.h; every K_v is reported with the window, phase and start used.
#include "app/core/command.h"
#include "app/core/units.h"
#include "app/dynamics/dynamics_fault_report.h"
#include "app/dynamics/dynamics_field_names.h"
#include "app/dynamics/dynamics_lateral.h"
#include "app/dynamics/dynamics_lateral_train.h"
#include "app/dynamics/dynamics_parameters.h"
#include "app/dynamics/lateral_parameters.h"
#include "app/dynamics/sweep_categories.h"
#include "dynamics/iso6336_dynamic_factor.h"
#include "dynamics/simulation.h"
#include "dynamics/train_model.h"
#include "errors/errors.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>

namespace
{
using namespace gearstiff;
using namespace gearstiff::app;
using namespace gearstiff::dynamics;

// docs/references.md §1: nominal force per mesh F_cn = 0.5·T1/(r1·cos α_t) = 1001.27 N.
constexpr double published_nominal_force = 1001.27; // [N]
const std::string published_source = "docs/references.md §1 (Reszuta & Drewniak 2015)";

// ISO 6336-1 method B for mesh m of `model` (the split path: at the driver's speed, its inertia
// shared equally among the meshes it drives, see iso6336_dynamic_factor.h; a train: the pair in
// its frame's rotating reference, train_model.h TrainIsoPair).
IsoDynamicFactor iso_factor(const TorsionalModel& model, const DynamicsParameters& p,
                            unsigned int m)
{
  const Mesh& mesh = p.train.meshes[m];
  IsoDynamicFactorInput in;
  if (p.train_description)
  {
    const TrainIsoPair& pair = p.train_model.spec_mesh_iso[p.train_model.spec_mesh[m]];
    in.pinion_teeth = pair.pinion_teeth;
    in.pinion_speed = pair.pinion_speed_ratio * std::abs(model.nominal_speeds()[0]);
    in.reduced_mass = pair.reduced_mass;
  }
  else
  {
    unsigned int shares = 0;
    for (const Mesh& other : p.train.meshes)
      shares += other.driver == mesh.driver;
    in.pinion_teeth = mesh.driver_teeth;
    in.pinion_speed = model.nominal_speeds()[mesh.driver];
    in.reduced_mass =
        reduced_mass(p.train.gears[mesh.driver].inertia / shares, mesh.driver_base_radius,
                     p.train.gears[mesh.driven].inertia, mesh.driven_base_radius);
  }
  in.face_width = p.iso.face_width;
  in.mesh_stiffness = p.iso.mesh_stiffness > 0.
                          ? p.iso.mesh_stiffness
                          : mesh.stiffness.mean_stiffness(mesh.contact_ratio) / p.iso.face_width;
  in.single_stiffness = p.iso.single_stiffness > 0.
                            ? p.iso.single_stiffness
                            : in.mesh_stiffness / (0.75 * mesh.contact_ratio + 0.25);
  in.tangential_force = std::abs(model.nominal_force(m)) * std::cos(p.iso.pressure_angle);
  in.application_factor = p.iso.application_factor;
  in.total_contact_ratio = mesh.contact_ratio;
  in.pitch_deviation = p.iso.pitch_deviation;
  in.profile_deviation = p.iso.profile_deviation;
  in.tip_relief = p.iso.tip_relief;
  return iso6336_dynamic_factor(in);
}

// Amplitude of the spectrum line nearest to `frequency` [Hz].
double line_amplitude(const MeshResult& mesh, double frequency)
{
  if (mesh.spectrum_frequency.size() < 2)
    return std::numeric_limits<double>::quiet_NaN();
  const double resolution = mesh.spectrum_frequency[1] - mesh.spectrum_frequency[0];
  const std::size_t index = static_cast<std::size_t>(std::llround(frequency / resolution));
  return index < mesh.spectrum_amplitude.size() ? mesh.spectrum_amplitude[index]
                                                : std::numeric_limits<double>::quiet_NaN();
}

void write_time_series(std::ostream& out, const TorsionalModel& model,
                       const SimulationResult& result, double interval)
{
  out << "time [s]";
  for (unsigned int i = 0; i < model.n_dofs(); ++i)
    out << ",phi_" << i + 1 << " [urad]";
  for (const auto& mesh : result.meshes)
  {
    const std::string m = mesh.name.substr(mesh.name.find(' ') + 1);
    out << ",force_" << m << " [N],kv_" << m << " [-],stiffness_" << m << " [N/um],dte_" << m
        << " [um],te_" << m << " [um]";
  }
  out << '\n' << std::setprecision(10);
  const Trajectory& trajectory = result.trajectory;
  const std::size_t stride = std::max<std::size_t>(
      1, static_cast<std::size_t>(std::llround(
             interval /
             (trajectory.time.size() > 1 ? trajectory.time[1] - trajectory.time[0] : interval))));
  for (std::size_t i = 0; i < trajectory.size(); i += stride)
  {
    out << trajectory.time[i];
    for (unsigned int d = 0; d < model.n_dofs(); ++d)
      out << ',' << trajectory.angle_at(i)[d] * 1e6;
    for (unsigned int m = 0; m < result.meshes.size(); ++m)
    {
      const MeshResult& mesh = result.meshes[m];
      // DTE = δ along the line of action; e the unloaded TE (nonlinear meshes, else 0)
      const double te = model
                            .mesh_response(m, trajectory.time[i], trajectory.angle_at(i),
                                           trajectory.velocity_at(i))
                            .transmission_error;
      out << ',' << mesh.force[i] << ',' << mesh.force[i] / std::abs(mesh.nominal_force) << ','
          << mesh.stiffness[i] * 1e-6 << ',' << mesh.deflection[i] * 1e6 << ',' << te * 1e6;
    }
    out << '\n';
  }
}

void write_spectrum(std::ostream& out, const SimulationResult& result)
{
  out << "frequency [Hz]";
  for (const auto& mesh : result.meshes)
    out << ",amplitude_" << mesh.name.substr(mesh.name.find(' ') + 1) << " [N]";
  out << '\n' << std::setprecision(10);
  const std::size_t n = result.meshes.front().spectrum_frequency.size();
  for (std::size_t k = 0; k < n; ++k)
  {
    out << result.meshes.front().spectrum_frequency[k];
    for (const auto& mesh : result.meshes)
      out << ',' << mesh.spectrum_amplitude[k];
    out << '\n';
  }
}

void report_iso(Report& report, const std::string& key, const std::string& name,
                const IsoDynamicFactor& iso)
{
  report.add_value(key + "kv_iso", iso.kv, "-", name + " K_v ISO 6336-1 method B");
  report.add_value(key + "iso_resonance_speed", iso.resonance_speed / rpm, "rpm",
                   name + " ISO resonance speed n_E1");
  report.add_value(key + "iso_resonance_ratio", iso.resonance_ratio, "-",
                   name + " ISO resonance ratio N");
  report.add_text(name + " ISO range", iso_speed_range_name(iso.range) +
                                           " (N_S = " + format_number(iso.subcritical_limit, 4) +
                                           ", B_p = " + format_number(iso.b_p, 4) +
                                           ", B_f = " + format_number(iso.b_f, 4) +
                                           ", B_k = " + format_number(iso.b_k, 4) + ")");
}

// Train model: degrees of freedom, notes (planet spacing, blank inertias), J* and the modal
// energy per body.
void report_train_model(const DynamicsParameters& p, const TorsionalModel& model, Report& report)
{
  const TrainModel& train = p.train_model;
  std::string dofs;
  for (const std::string& name : train.dof_names)
    dofs += (dofs.empty() ? "" : ", ") + name;
  report.add_text("degrees of freedom", dofs + " (member#copy; rigid bodies by connections)");
  for (std::size_t i = 0; i < train.notes.size(); ++i)
    report.add_text("train note " + std::to_string(i + 1), train.notes[i]);
  report.add_value("reduced_inertia", train.reduced_inertia, "kg·m²",
                   "kinematics' J* reduced to the input (the rigid mode's inertia)");
  const Eigen::VectorXd& r = model.rigid_mode();
  report.add_value("rigid_mode_inertia", r.cwiseProduct(model.inertias()).dot(r), "kg·m²",
                   "inertia of the model's nominal rotation (equals J*)");

  // Modal energy distribution per body (all copies together).
  std::vector<std::string> bodies;
  std::vector<unsigned int> group;
  for (const std::string& body : train.dof_body)
  {
    const auto found = std::find(bodies.begin(), bodies.end(), body);
    group.push_back(found - bodies.begin());
    if (found == bodies.end())
      bodies.push_back(body);
  }
  const Eigen::MatrixXd share = modal_energy_distribution(model, group, bodies.size());
  const ModeShapes modes = model.mode_shapes();
  std::vector<std::string> columns{"mode", "frequency"};
  std::vector<std::string> units{"-", "Hz"};
  for (const std::string& body : bodies)
  {
    columns.push_back("energy_" + body);
    units.push_back("-");
  }
  // Mesh frequency per input rpm of each Train mesh (its first copy): the Campbell chart's
  // order lines.
  auto& campbell =
      report.add_table("dynamics_campbell", {"mesh", "mesh_frequency_per_rpm"}, {"-", "Hz/rpm"});
  for (unsigned int m = 0; m < model.n_meshes(); ++m)
    if (train.mesh_copy[m] == 0)
      campbell.add_row({double(train.spec_mesh[m] + 1),
                        model.mesh_position_rate(m) / (p.train.input_speed / rpm)});
  auto& table = report.add_table("dynamics_modal_energy", columns, units);
  for (Eigen::Index k = 0; k < share.rows(); ++k)
  {
    std::vector<double> row{double(k + 1), modes.frequencies[k]};
    for (Eigen::Index g = 0; g < share.cols(); ++g)
      row.push_back(share(k, g));
    table.add_row(row);
  }
}

// ---- issue 29: the nonlinear mesh model's results ----
// Per mesh: DF, separation, impacts, the dynamic TE; the law used.
void report_nonlinear_meshes(const DynamicsParameters& p, const SimulationResult& result,
                             Report& report)
{
  report.add_text(
      "mesh model",
      mesh_model_name(p.mesh_model) +
          (p.mesh_model == MeshModel::nonlinear
               ? ": F = k·h(δ − e) + c·(δ̇ − ė)·[in contact]; drive flank for δ − e > 0, "
                 "separated in the free play, back flank (drive table mirrored) below "
                 "−2b; switches located by RK4 (dynamics/README.md)"
               : ": F = k·δ + c·δ̇"));
  if (p.mesh_model == MeshModel::nonlinear)
    report.add_value("located_switches", result.trajectory.cost.located_switches, "-",
                     "contact changes located by RK4 (all meshes, whole run)");
  for (unsigned int m = 0; m < result.meshes.size(); ++m)
  {
    const MeshResult& mesh = result.meshes[m];
    const std::string key = "mesh" + std::to_string(m + 1) + "_";
    report.add_value(key + "mean_dte", mesh.mean_deflection * 1e6, "µm",
                     mesh.name + " mean dynamic transmission error in the window");
    report.add_value(key + "dte_rms", mesh.deflection_rms * 1e6, "µm",
                     mesh.name + " DTE rms about its mean");
    if (!mesh.nonlinear)
      continue;
    const NonlinearMesh& law = *p.train.meshes[m].nonlinear;
    report.add_text(mesh.name + " nonlinear law",
                    "backlash 2b = " + format_number(law.backlash * 1e6, 5) + " µm, unloaded TE " +
                        law.transmission_error.description());
    report.add_value(key + "dynamic_factor", mesh.kv_max, "-",
                     mesh.name + " DF = max dynamic / static mesh force");
    report.add_value(key + "separation_fraction", mesh.separation_fraction, "-",
                     mesh.name + " share of the window without drive-flank contact");
    report.add_value(key + "separations", mesh.separations, "-",
                     mesh.name + " drive-flank separations in the window");
    report.add_value(key + "back_impacts", mesh.back_impacts, "-",
                     mesh.name + " back-flank impacts in the window");
  }
}

// The sweep's nonlinear columns and the DTE waterfall (each mesh's spectrum per speed).
void report_nonlinear_sweep(const DynamicsParameters& p, const SweepResult& sweep, Report& report)
{
  auto& table = report.add_table("dynamics_nonlinear_sweep",
                                 {"input_speed", "mesh_frequency", "direction", "dynamic_factor",
                                  "kv_min", "separation_fraction", "separations", "back_impacts",
                                  "mean_dte", "dte_rms", "status"},
                                 {"rpm", "Hz", "-", "-", "-", "-", "-", "-", "um", "um", "-"});
  table.set_categories("direction", sweep_direction_categories());
  table.set_categories("status", sweep_status_categories());
  // Every mesh's DTE spectrum; a train's copies of a Train mesh are one pair: its first copy.
  auto& waterfall = report.add_table("dynamics_dte_waterfall",
                                     {"input_speed", "direction", "mesh", "order", "amplitude"},
                                     {"rpm", "-", "-", "-", "um"});
  waterfall.set_categories("direction", sweep_direction_categories());
  unsigned int impacts = 0, separated = 0;
  for (const SweepPoint& point : sweep.points)
  {
    table.add_row({point.input_speed / rpm, point.mesh_frequency, point.descending ? 1. : 0.,
                   point.kv_max, point.kv_min, point.separation_fraction, double(point.separations),
                   double(point.back_impacts), point.mean_deflection * 1e6,
                   point.deflection_rms * 1e6, double(static_cast<int>(point.status))});
    for (std::size_t m = 0; m < point.mesh_dte_orders.size(); ++m)
      if (!p.train_description || p.train_model.mesh_copy[m] == 0)
        for (std::size_t k = 1; k < point.mesh_dte_orders[m].size(); ++k)
          waterfall.add_row({point.input_speed / rpm, point.descending ? 1. : 0., double(m + 1),
                             point.mesh_dte_orders[m][k], point.mesh_dte_amplitude[m][k] * 1e6});
    separated += point.separation_fraction > 0.;
    impacts += point.back_impacts > 0;
  }
  report.add_text("sweep direction",
                  sweep_direction_name(p.sweep_direction) +
                      (p.mesh_model == MeshModel::nonlinear
                           ? ", each speed from the previous speed's final state (continuation)"
                           : ""));
  report.add_value("sweep_separating_speeds", separated, "-",
                   "sweep speeds where a mesh separates (direction counted separately)");
  report.add_value("sweep_back_impact_speeds", impacts, "-",
                   "sweep speeds with back-flank impacts");
}
void plot_nonlinear(CommandContext& context, Report& report, const std::string& series,
                    const std::string& window, bool with_sweep)
{
  context.plot("plot_nonlinear_dynamics.py", {"dte", series, window}, "dynamics_dte.png",
               "dynamic and unloaded transmission error DTE(t), e(t)");
  if (!with_sweep)
    return;
  const TemporaryCsv sweep_csv(report, "dynamics_nonlinear_sweep");
  context.plot("plot_nonlinear_dynamics.py", {"sweep", sweep_csv.path()},
               "dynamics_dynamic_factor.png", "DF against speed, up and down sweeps");
  const TemporaryCsv waterfall_csv(report, "dynamics_dte_waterfall");
  context.plot("plot_nonlinear_dynamics.py", {"waterfall", waterfall_csv.path()},
               "dynamics_dte_waterfall.png",
               "DTE spectrum against speed (mesh orders), one row per mesh");
}
// ---- end of issue 29 results ----

// The case and its assumptions first: every K_v below depends on them.
void report_case(const DynamicsParameters& p, const TorsionalModel& model, Report& report)
{
  report.add_text("model", std::to_string(model.n_dofs()) + "-DOF torsional train, " +
                               std::to_string(model.n_meshes()) +
                               " meshes; angles relative to the nominal rotation");
  if (p.train_description)
    report_train_model(p, model, report);
  if (!p.derived_sizes.empty())
  {
    std::string text;
    for (const std::string& size : p.derived_sizes)
      text += (text.empty() ? "" : "; ") + size;
    report.add_text("derived values", text);
  }
  for (unsigned int m = 0; m < model.n_meshes(); ++m)
  {
    const Mesh& mesh = p.train.meshes[m];
    report.add_text(mesh.name + " stiffness", p.stiffness_description[m]);
    if (p.train_description)
      report.add_text(mesh.name + " phase",
                      "initial mesh position " + format_number(mesh.initial_position, 6) +
                          " base pitches (planet spacing and sun/ring phasing), ε_α = " +
                          format_number(mesh.contact_ratio, 5) +
                          ", ε_f = " + format_number(mesh.approach_ratio, 5));
    else
      report.add_text(mesh.name + " phase",
                      "initial mesh position " + format_number(mesh.initial_position, 6) +
                          " base pitches (placement angle " +
                          format_number(p.placement_angle[m] * 180. / M_PI, 4) +
                          "°, z = " + std::to_string(mesh.driver_teeth) + ")");
  }
  report.add_text("friction", "per pair in contact, sign reverses at the pitch point "
                              "(approach ratio), pairs weighted by their force share");
  report.add_text("start", start_state_name(p.simulation.start));
  report.add_text("integrator", integrator_name(p.simulation.integrator.type));
}

// The run's window, speeds, step, stability limit and modes.
void report_run(const DynamicsParameters& p, const TorsionalModel& model,
                const SimulationResult& result, Report& report)
{
  const Trajectory& trajectory = result.trajectory;
  report.add_text("steady-state window",
                  "[" + format_number(result.window_start, 6) + ", " +
                      format_number(result.window_end, 6) + "] s, " +
                      (result.window_automatic
                           ? (std::isfinite(result.decay_time)
                                  ? "automatic: starts when the slowest mode has decayed to 1/1000"
                                  : "automatic: no damping, so 20 mesh periods skipped")
                           : "as given") +
                      (excitation_period(model) * model.mesh_position_rate(0) > 1.5
                           ? ", whole revolutions of the faulty gear (revolution table)"
                           : ", whole periods of mesh 1"));

  report.add_value("input_speed", p.train.input_speed / rpm, "rpm", "input speed n1");
  report.add_value("input_torque", p.train.gears[0].torque, "N·m", "torque on gear 1");
  report.add_value("mesh_frequency", model.mesh_position_rate(0), "Hz", "mesh frequency (mesh 1)");
  report.add_value("time_step", result.time_step * 1e6, "µs",
                   "time step (output interval for adaptive RK)");
  report.add_value("rk4_step_limit", trajectory.rk4_step_limit * 1e6, "µs",
                   "estimated RK4 stability limit");
  report.add_value("highest_natural_frequency", trajectory.highest_frequency / (2. * M_PI), "Hz",
                   "highest natural frequency (largest stiffness)");
  report.add_value("decay_time", result.decay_time, "s", "decay of the slowest mode to 1/1000");
  report.add_value("window_start", result.window_start, "s", "K_v window start");
  report.add_value("window_end", result.window_end, "s", "K_v window end");

  auto& modes =
      report.add_table("dynamics_modes", {"mode", "frequency", "decay_rate"}, {"-", "Hz", "1/s"});
  for (std::size_t i = 0; i < result.modes.natural_frequencies.size(); ++i)
    modes.add_row({double(i + 1), result.modes.natural_frequencies[i],
                   i < result.modes.decay_rates.size() ? result.modes.decay_rates[i]
                                                       : std::numeric_limits<double>::quiet_NaN()});
}

// Per mesh: nominal and mean force, simulated and ISO K_v, mean stiffness, the Cai fit.
// A mesh whose k(x) came from an FE summary: the tooth force it was solved at beside the
// train's nominal force, and a warning when they differ by more than 10 % (a modified pair's k
// and TE depend on the load: tip relief made the own pair of issue 43 12 % softer at a third of
// the load). Once per Train mesh (its copies carry the same file).
void report_table_load(const DynamicsParameters& p, unsigned int m, const MeshResult& mesh,
                       Report& report)
{
  const Mesh& data = p.train.meshes[m];
  if (!std::isfinite(data.table_force) || (p.train_description && p.train_model.mesh_copy[m] != 0))
    return;
  const std::string key = "mesh" + std::to_string(m + 1) + "_";
  report.add_value(key + "table_force", data.table_force, "N",
                   data.name + " tooth force the stiffness file's k(x) was solved at");
  const double ratio = std::abs(mesh.nominal_force) / data.table_force;
  if (ratio > 1.1 || ratio < 1. / 1.1)
    report.add_text(data.name + " load warning",
                    "the stiffness file's k(x) was solved at a tooth force of " +
                        format_number(data.table_force, 5) + " N; this train loads the mesh with " +
                        format_number(std::abs(mesh.nominal_force), 5) + " N (" +
                        format_number(ratio, 3) +
                        "×). k(x) depends on the load (strongly with profile modifications): "
                        "sweep the pair at this load (Stiffness/torques) for its table");
}

void report_meshes(const DynamicsParameters& p, const TorsionalModel& model,
                   const SimulationResult& result, Report& report)
{
  auto& meshes = report.add_table("dynamics_meshes",
                                  {"mesh", "nominal_force", "mean_force", "kv_max", "kv_max_time",
                                   "kv_min", "kv_iso", "resonance_ratio"},
                                  {"-", "N", "N", "-", "s", "-", "-", "-"});
  for (unsigned int m = 0; m < model.n_meshes(); ++m)
  {
    const MeshResult& mesh = result.meshes[m];
    const std::string key = "mesh" + std::to_string(m + 1) + "_";
    if (p.published_reference)
      report.add_compared_value(key + "nominal_force", mesh.nominal_force, published_nominal_force,
                                "N", mesh.name + " nominal force F_cn (r_b1 rounded to 24.7 mm)",
                                published_source);
    else
      report.add_value(key + "nominal_force", mesh.nominal_force, "N",
                       mesh.name + " nominal force");
    report_table_load(p, m, mesh, report);
    report.add_value(key + "mean_force", mesh.mean_force, "N",
                     mesh.name + " mean force in the window");
    report.add_value(key + "kv_max", mesh.kv_max, "-", mesh.name + " K_v max (simulated)");
    report.add_value(key + "kv_min", mesh.kv_min, "-", mesh.name + " K_v min (simulated)");
    report.add_value(key + "kv_periodicity",
                     std::abs(mesh.kv_max_first_half - mesh.kv_max_second_half), "-",
                     mesh.name + " |K_v max 1st half - 2nd half|");
    const IsoDynamicFactor iso = iso_factor(model, p, m);
    // A train: once per Train mesh (its copies are the same pair).
    if (!p.train_description || p.train_model.mesh_copy[m] == 0)
    {
      report_iso(report, key, mesh.name, iso);
      const Mesh& data = p.train.meshes[m];
      report.add_value(key + "mean_stiffness",
                       data.stiffness.mean_stiffness(data.contact_ratio) * 1e-6, "N/µm",
                       mesh.name + " mean mesh stiffness over a mesh cycle");
    }
    meshes.add_row({double(m + 1), mesh.nominal_force, mesh.mean_force, mesh.kv_max,
                    mesh.kv_max_time, mesh.kv_min, iso.kv, iso.resonance_ratio});
    if (mesh.kv_min < 0. && !mesh.nonlinear)
      report.add_text(mesh.name + " warning",
                      "the mesh force turns negative (K_v min < 0): real teeth would separate, "
                      "which this linear model does not represent");
    if (p.cai_fit[m])
    {
      report.add_value(key + "cai_fit_scale", p.cai_fit[m]->parameters.scale / 1e6, "N/µm",
                       mesh.name + " fitted Cai scale (single-pair peak)");
      report.add_value(key + "cai_fit_rms", p.cai_fit[m]->rms_residual / 1e6, "N/µm",
                       mesh.name + " Cai fit rms residual");
    }
  }
  report.add_value("kv_max", result.kv_max, "-", "K_v max over all meshes (simulated)");
}

void report_iso_assumptions(const DynamicsParameters& p, Report& report)
{
  report.add_text("ISO assumptions",
                  "c_gamma_alpha = mean model stiffness / b unless given, c' = c_gamma_alpha/"
                  "(0.75 eps + 0.25) unless given; f_pb,eff = " +
                      format_number(p.iso.pitch_deviation * 1e6, 4) +
                      " µm, f_f,eff = " + format_number(p.iso.profile_deviation * 1e6, 4) +
                      " µm, C_a = " + format_number(p.iso.tip_relief * 1e6, 4) + " µm; " +
                      (p.train_description
                           ? "each Train mesh as an isolated pair in its frame (n1 relative to "
                             "the frame), m_red by ISO 6336-1 6.5.9's planetary rule (a gear's "
                             "m* = J/r_b² shared among the mesh copies it carries, a fixed gear "
                             "infinitely heavy); method B ignores the coupling of the meshes "
                             "and the carriers' motion, which the simulated K_v includes"
                           : "m_red with the driver inertia shared among its meshes"));
}

// Mesh 1's force harmonics and what the integration cost.
void report_harmonics_and_cost(const DynamicsParameters& p, const TorsionalModel& model,
                               const SimulationResult& result, Report& report)
{
  auto& harmonics = report.add_table(
      "dynamics_harmonics", {"harmonic", "frequency", "amplitude_mesh1"}, {"-", "Hz", "N"});
  for (unsigned int k = 0; k <= 10; ++k)
  {
    const double frequency = k * model.mesh_position_rate(0);
    const double amplitude = line_amplitude(result.meshes[0], frequency);
    if (std::isfinite(amplitude))
      harmonics.add_row({double(k), frequency, amplitude});
  }

  const IntegrationCost& cost = result.trajectory.cost;
  report.add_value("steps", cost.steps, "-", "integration steps");
  report.add_value("function_evaluations", cost.function_evaluations, "-",
                   "equation-of-motion evaluations");
  if (p.simulation.integrator.type == IntegratorType::adaptive_rk)
    report.add_value("rejected_steps", cost.rejected_steps, "-", "rejected steps");
  if (p.simulation.integrator.type == IntegratorType::hht_alpha)
    report.add_value("linear_solves", cost.linear_solves, "-", "linear solves");
  report.add_value("integration_time", cost.wall_time * 1e3, "ms", "wall time of the integration");
  report.add_value("integration_cpu_time", cost.cpu_time * 1e3, "ms",
                   "processor time of the integration");
}

// The K_v chart's table: one row per speed (K_v only where valid) and the status counts.
void report_speed_sweep(const DynamicsParameters& p, const SweepResult& sweep, Report& report)
{
  auto& table = report.add_table("dynamics_speed_sweep",
                                 {"input_speed", "mesh_frequency", "resonance_ratio", "kv_max",
                                  "kv_min", "kv_iso", "status", "time_step", "kv_max_linear"},
                                 {"rpm", "Hz", "-", "-", "-", "-", "-", "us", "-"});
  table.set_categories("status", sweep_status_categories());
  unsigned int unstable = 0, separated = 0, not_steady = 0;
  unsigned long steps = 0;
  for (const SweepPoint& point : sweep.points)
  {
    GearTrain train = p.train;
    train.input_speed = point.input_speed;
    const TorsionalModel point_model(train);
    const IsoDynamicFactor iso = iso_factor(point_model, p, 0);
    // Only valid points show a K_v (issue 11: diverged or contact-loss rows printed as
    // ordinary numbers); the linear model's value stays in its own column for the chart.
    const bool valid = point.status == SweepStatus::valid;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    table.add_row({point.input_speed / rpm, point.mesh_frequency, iso.resonance_ratio,
                   valid ? point.kv_max : nan, valid ? point.kv_min : nan, iso.kv,
                   double(static_cast<int>(point.status)), point.time_step * 1e6, point.kv_max});
    unstable += point.status == SweepStatus::diverged;
    separated += point.status == SweepStatus::contact_loss;
    not_steady += point.status == SweepStatus::not_steady;
    steps += point.cost.steps;
  }
  report.add_value("sweep_points", sweep.points.size(), "-", "speeds in the sweep");
  report.add_value("sweep_unstable", unstable, "-",
                   "speeds where the linear model diverges (no K_v)");
  report.add_value("sweep_contact_loss", separated, "-",
                   "speeds with negative mesh force (teeth would separate)");
  report.add_value("sweep_not_steady", not_steady, "-",
                   "speeds whose K_v window is not periodic (no K_v)");
  report.add_text("sweep status", sweep_status_meanings() + "; K_v only for valid points");
  report.add_value("sweep_steps", steps, "-", "integration steps of the sweep");
  if (p.mesh_model == MeshModel::nonlinear || p.sweep_direction != SweepDirection::up)
    report_nonlinear_sweep(p, sweep, report);
  report.add_value("sweep_time", sweep.wall_time, "s", "wall time of the sweep");
}

// The K_v speed sweep (issue 25: one progress line per speed on stderr, from rank 0, none with
// --quiet) and its report.
SweepResult run_speed_sweep(const DynamicsParameters& p, CommandContext& context)
{
  std::vector<double> speeds;
  for (unsigned int i = 0; i < p.sweep.points; ++i)
    speeds.push_back(p.sweep.points == 1
                         ? p.sweep.minimum_speed
                         : p.sweep.minimum_speed + (p.sweep.maximum_speed - p.sweep.minimum_speed) *
                                                       i / (p.sweep.points - 1));
  context.pcout << "dynamics: speed sweep over " << p.sweep.points << " speeds" << std::endl;
  SimulationSettings sweep_settings = p.simulation;
  const bool nonlinear = p.mesh_model == MeshModel::nonlinear;
  if (nonlinear)
    sweep_settings.dte_spectrum_orders = 4.; // the waterfall: mesh orders up to 4
  const unsigned int runs = p.sweep.points * (p.sweep_direction == SweepDirection::both ? 2 : 1);
  const bool root = context.is_root(); // every rank runs the same sweep
  const auto counter = context.progress_counter("dynamics", runs);
  const SweepProgress progress = [&](const SweepPoint& point, std::size_t done, std::size_t total)
  {
    if (root)
      counter("speed sweep " + std::to_string(done) + "/" + std::to_string(total) + ", " +
              format_number(point.input_speed / rpm, 6) + " rpm" +
              (point.descending ? " (down)" : "") + ", " +
              (point.status == SweepStatus::valid ? "K_v max " + format_number(point.kv_max, 4)
                                                  : sweep_status_name(point.status)));
  };
  const SweepResult sweep =
      speed_sweep(p.train, sweep_settings, speeds, p.sweep.steps_per_mesh_period, p.sweep_direction,
                  nonlinear, progress);
  report_speed_sweep(p, sweep, context.report);
  return sweep;
}

// Campbell chart over the sweep range (or, without a sweep, from 0 up to where the fastest
// mesh's first order meets the highest mode).
void plot_campbell(const DynamicsParameters& p, const TorsionalModel& model,
                   const SimulationResult& result, CommandContext& context)
{
  const double low = p.sweep.points > 0 ? p.sweep.minimum_speed : 0.;
  double fastest = 0.;
  for (unsigned int m = 0; m < model.n_meshes(); ++m)
    fastest = std::max(fastest, model.mesh_position_rate(m) / p.train.input_speed);
  const double high = p.sweep.points > 0
                          ? p.sweep.maximum_speed
                          : 1.1 * result.trajectory.highest_frequency / (2. * M_PI) / fastest;
  const TemporaryCsv campbell(context.report, "dynamics_campbell");
  const TemporaryCsv modes(context.report, "dynamics_modes");
  context.plot("plot_dynamics.py",
               {"campbell", campbell.path(), modes.path(),
                format_number(low / rpm, 8) + "," + format_number(high / rpm, 8)},
               "dynamics_campbell.png", "Campbell chart: mesh orders against natural frequencies");
}

// -o DIR: time series, spectrum and the charts.
void write_files(const DynamicsParameters& p, const TorsionalModel& model,
                 const SimulationResult& result, const SweepResult& sweep, CommandContext& context)
{
  Report& report = context.report;
  const std::string series = context.write_output(
      "dynamics_time_series.csv", "phi_i(t), mesh forces, K_v(t), mesh stiffness",
      [&](std::ostream& out) { write_time_series(out, model, result, p.output_interval); });
  context.write_output("dynamics_spectrum.csv", "mesh-force spectrum",
                       [&](std::ostream& out) { write_spectrum(out, result); });
  const std::string window =
      format_number(result.window_start, 8) + "," + format_number(result.window_end, 8);
  context.plot("plot_dynamics.py", {"vibration", series, window}, "dynamics_vibration.png",
               "torsional vibration phi_i(t)");
  // A few mesh periods and the envelope per mesh period: the whole run is a solid band.
  context.plot(
      "plot_dynamics.py",
      {"kv", series, window + "," + format_number(1. / result.meshes[0].mesh_frequency, 8)},
      "dynamics_kv.png", "K_v(t): envelope per mesh period and the last periods");
  context.plot("plot_dynamics.py", {"stiffness", series, window}, "dynamics_stiffness.png",
               "mesh stiffness k(t)");
  if (p.train_description)
    plot_campbell(p, model, result, context);
  if (!sweep.points.empty())
  {
    const TemporaryCsv csv(report, "dynamics_speed_sweep");
    context.plot("plot_dynamics.py", {"resonance", csv.path()}, "dynamics_resonance.png",
                 "K_v against input speed (resonance chart)");
  }
  if (p.mesh_model == MeshModel::nonlinear)
    plot_nonlinear(context, report, series, window, !sweep.points.empty());
}

// The torsional model of the train: its case, simulation, speed sweep and files.
void run_torsional(const DynamicsParameters& p, CommandContext& context)
{
  const TorsionalModel model(p.train);
  context.chart_case = "torsional model, " + std::to_string(model.n_dofs()) + " DOF, " +
                       std::to_string(p.train.meshes.size()) + " meshes, input " +
                       format_number(p.train.input_speed / rpm, 5) + " rpm, " +
                       format_number(std::abs(p.train.gears.front().torque), 5) + " N·m";
  Report& report = context.report;
  report_case(p, model, report);

  context.pcout << "dynamics: simulating " << model.n_dofs() << " DOF with "
                << integrator_name(p.simulation.integrator.type) << std::endl;
  const SimulationResult result = simulate(model, p.simulation);
  report_run(p, model, result, report);
  report_meshes(p, model, result, report);
  report_nonlinear_meshes(p, result, report);
  report_iso_assumptions(p, report);
  report_harmonics_and_cost(p, model, result, report);
  report_fault_signature(model, result, report); // issue 31: revolution tables only

  SweepResult sweep;
  if (p.sweep.points > 0)
    sweep = run_speed_sweep(p, context);
  if (context.writes_files())
    write_files(p, model, result, sweep, context);
}

void run(dealii::ParameterHandler& prm, CommandContext& context)
{
  if (lateral_train_selected(prm)) // issue 30, several stages: dynamics_lateral_train.cc
  {
    run_lateral_train_dynamics(prm, context);
    return;
  }
  if (lateral_model_selected(prm)) // issue 30: dynamics_lateral.cc
  {
    run_lateral_dynamics(prm, context);
    return;
  }
  const DynamicsParameters p = parse_dynamics_parameters(prm);
  // The library names the train's gears and meshes by number ("gear2.inertia"): the sections
  // they came from are known here.
  with_parameter_names(train_parameter_names(p.train), [&] { run_torsional(p, context); });
}

const CommandRegistration registration(Command{
    "dynamics",
    "torsional gear-train dynamics: K_v(t), K_v max, spectrum, resonance chart, ISO K_v",
    "Lumped torsional model of a gear train (one DOF per gear) with time-varying mesh stiffness\n"
    "(Cai curve, constant, k(x) table or a Cai curve fitted to a table), mesh damping and tooth\n"
    "friction whose sign reverses at the pitch point. Integrators: RK4 (fixed step, the published\n"
    "method), adaptive Dormand-Prince 5(4), implicit HHT-alpha. Reports K_v = F/F_nominal over a\n"
    "steady-state window (with the window, phase and start), the mesh-force spectrum, a K_v\n"
    "speed sweep, and ISO 6336-1 method B K_v beside it. Built-in case: the split-path gearbox\n"
    "of Reszuta & Drewniak 2015 (docs/references.md §1), T1 = 49.4 N·m at 1450 rpm, wheels 180° "
    "apart.",
    [](dealii::ParameterHandler& prm)
    {
      declare_dynamics_parameters(prm);
      declare_lateral_parameters(prm);
    },
    run});
} // namespace
