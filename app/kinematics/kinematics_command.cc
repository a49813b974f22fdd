// `gearstiff kinematics [train.prm]`: speeds of every member of a gear train from its Willis
// equations, efficiency and statics by the torque method, forces on planet axes, reduced
// inertia. Default: the bi-planetary train of docs/references.md §2, reported beside the published
// values.
//
//   gearstiff kinematics
//   gearstiff kinematics --set "Train/input torque=0"      (speeds only)
//   gearstiff kinematics tests/kinematics/cli/planetary.prm (a simple planetary set)
//   gearstiff kinematics train.prm --json -o results/
#include "app/core/command.h"
#include "app/core/units.h"
#include "app/kinematics/kinematics_parameters.h"
#include "errors/errors.h"
#include "kinematics/gear_train.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace gearstiff::app
{
namespace
{
const std::string source = "docs/references.md §2 (Drewniak, Garlicka, Kolber 2016)";

bool same_text(const kinematics::GearTrainText& a, const kinematics::GearTrainText& b)
{
  return a.gears == b.gears && a.modules == b.modules && a.carriers == b.carriers &&
         a.planets == b.planets && a.meshes == b.meshes && a.connections == b.connections &&
         a.fixed == b.fixed && a.inputs == b.inputs && a.output == b.output;
}

// The report of one train: values compared with the published ones only for the published case.
struct TrainReport
{
  const TrainParameters& parameters;
  const kinematics::GearTrainSpec& spec;
  const kinematics::TrainSolution& solution;
  Report& report;
  bool published = false;

  void value(const std::string& key, double v, double reference, const std::string& unit,
             const std::string& description, const std::string& note = "") const
  {
    if (published && !std::isnan(reference))
      report.add_compared_value(key, v, reference, unit, description, source + note);
    else
      report.add_value(key, v, unit, description);
  }
};

const double none = std::nan("");

// Checked before any work: an unknown member here was silently ignored (issue 11).
void check_reduce_to(const TrainParameters& parameters, const kinematics::GearTrainSpec& spec)
{
  if (!parameters.reduce_to.empty() && std::none_of(spec.members.begin(), spec.members.end(),
                                                    [&](const kinematics::TrainMember& member) {
                                                      return member.name == parameters.reduce_to;
                                                    }))
    throw InputError("Train/reduce inertia to", "unknown member '" + parameters.reduce_to +
                                                    "' (declare it in gears or carriers)");
}

void report_speeds(const TrainReport& r)
{
  r.report.add_value("degrees_of_freedom", r.solution.degrees_of_freedom, "-",
                     "degrees of freedom of the train without its inputs");
  if (!r.spec.output.empty())
  {
    r.value("ratio", r.solution.ratio, 57.676, "-", "ratio ω_input/ω_output");
    r.value("output_speed", r.solution.speed(r.spec.output) / rpm, 25.487, "rpm",
            "speed of the output " + r.spec.output);
  }
  for (std::size_t i = 0; i + 1 < r.solution.names.size(); ++i)
    r.report.add_value("speed_" + r.solution.names[i], r.solution.speeds[i] / rpm, "rpm",
                       "speed of member " + r.solution.names[i]);
}

void report_meshes(const TrainReport& r)
{
  ReportTable& meshes = r.report.add_table(
      "meshes", {"mesh", "teeth_a", "teeth_b", "copies", "relative_speed_a", "pair_efficiency"},
      {"-", "-", "-", "-", "rpm", "-"});
  for (std::size_t m = 0; m < r.spec.meshes.size(); ++m)
  {
    const auto& mesh = r.spec.meshes[m];
    const int za = r.spec.members[r.solution.index(mesh.gear_a)].teeth;
    const int zb = r.spec.members[r.solution.index(mesh.gear_b)].teeth;
    meshes.add_row({double(m + 1), double(za), double(zb), double(r.solution.mesh_copies[m]),
                    (r.solution.speed(mesh.gear_a) - r.solution.speed(mesh.frame)) / rpm,
                    kinematics::pair_efficiency(za, zb, r.parameters.tooth_friction)});
    r.report.add_text("mesh_" + std::to_string(m + 1),
                      mesh.gear_a + "-" + mesh.gear_b + " on " + mesh.frame);
  }
  if (r.published)
  {
    // Pair efficiencies as printed; η_45 is printed 0.994, the formula gives 0.995.
    const double mu = r.parameters.tooth_friction;
    r.value("efficiency_12", kinematics::pair_efficiency(21, 81, mu), 0.989, "-", "pair η_12");
    r.value("efficiency_34", kinematics::pair_efficiency(21, 24, mu), 0.984, "-", "pair η_34");
    r.value("efficiency_45", kinematics::pair_efficiency(24, -69, mu), 0.994, "-", "pair η_45",
            "; printed 0.994 is a misprint, the formula gives 0.995");
    r.value("efficiency_67", kinematics::pair_efficiency(21, -72, mu), 0.994, "-", "pair η_67");
  }
}

// Loss-free first: the paper's torques and forces are loss-free values.
void report_lossless_statics(const TrainReport& r)
{
  const kinematics::TrainStatics ideal =
      kinematics::solve_train_statics(r.spec, r.solution, r.parameters.input_torque, 0.);
  r.value("output_torque_lossless", -ideal.output_torque, 6932.70, "N·m",
          "torque delivered to the output, loss-free (T1·i)");
  const double path_references[] = {583.83, 1523.35, 4825.52};
  for (std::size_t k = 0; k < ideal.output_paths.size(); ++k)
  {
    const auto& [m, torque] = ideal.output_paths[k];
    r.value("output_path_mesh_" + std::to_string(m + 1), torque, k < 3 ? path_references[k] : none,
            "N·m", "loss-free torque reaching the output through mesh " + std::to_string(m + 1));
  }
  ReportTable& loads = r.report.add_table(
      "mesh_loads", {"mesh", "torque_a", "torque_b", "torque_frame", "tangential_force_per_copy"},
      {"-", "N*m", "N*m", "N*m", "N"});
  for (std::size_t m = 0; m < ideal.meshes.size(); ++m)
    loads.add_row({double(m + 1), ideal.meshes[m].on_a, ideal.meshes[m].on_b,
                   ideal.meshes[m].on_frame, ideal.meshes[m].tangential_force});
  for (const auto& [name, force] : ideal.planet_axis_forces)
    r.value("planet_axis_force_" + name, force, name == "2" ? 1907.94 : none, "N",
            "loss-free force on the axis of planet " + name + " (per copy)",
            name == "6" ? "; the paper's printed formula for planet 6 does not give its "
                          "printed value"
                        : "");
  if (r.published)
  {
    r.report.add_text("planet_6_force",
                      "docs/references.md §2: the paper's printed formula for the "
                      "force on planet 6 does not give its printed value; the "
                      "value above follows from the torque balance (m_67 = 4 mm)");
    r.value("tooth_force_45", ideal.meshes[2].tangential_force, 2453.06, "N",
            "loss-free tooth force on gear 5 per planet 4");
  }
}

void report_lossy_statics(const TrainReport& r)
{
  const kinematics::TrainStatics lossy = kinematics::solve_train_statics(
      r.spec, r.solution, r.parameters.input_torque, r.parameters.tooth_friction);
  r.value("efficiency", lossy.efficiency, 0.967, "-", "train efficiency (torque method)");
  r.value("output_torque", -lossy.output_torque, 6703.92, "N·m",
          "torque delivered to the output with mesh losses",
          "; printed value is T1·i·0.967 with η rounded to 3 digits");
  r.report.add_value("power_flow_passes", lossy.power_flow_iterations, "-",
                     "passes until the directions of relative power flow settled");
  for (std::size_t i = 0; i + 1 < r.solution.names.size(); ++i)
    if (lossy.applied_torque[i] != 0.)
      r.report.add_value("applied_torque_" + r.solution.names[i], lossy.applied_torque[i], "N·m",
                         "external torque on " + r.solution.names[i] +
                             " (input, load or reaction) with losses");
}

// The carrier method needs one fixed member and an output carrier that frames a mesh.
void report_carrier_method(const TrainReport& r)
{
  if (r.spec.fixed.size() != 1 ||
      std::none_of(r.spec.meshes.begin(), r.spec.meshes.end(),
                   [&](const kinematics::TrainMesh& mesh) { return mesh.frame == r.spec.output; }))
    return;
  const kinematics::CarrierMethodEfficiency carrier =
      kinematics::carrier_method_efficiency(r.spec, r.parameters.tooth_friction);
  r.value("base_ratio", carrier.base_ratio, -56.676, "-", "base ratio i_b (output carrier held)");
  r.value("base_efficiency", carrier.base_efficiency, 0.966, "-", "base efficiency η_b",
          "; printed 0.966 follows from the η_45 misprint");
  r.value("efficiency_carrier_method", carrier.efficiency, 0.967, "-",
          "η = (1 − i_b·η_b)/(1 − i_b)");
}

void report_reduced_inertia(const TrainReport& r)
{
  if (r.parameters.text.inertias.empty() && r.parameters.text.masses.empty())
    return;
  const std::string member =
      r.parameters.reduce_to.empty() ? r.spec.inputs.front().first : r.parameters.reduce_to;
  const double inertia =
      kinematics::reduced_moment_of_inertia(kinematics::inertia_terms(r.spec, r.solution, member));
  r.report.add_value("reduced_inertia", inertia, "kg·m²",
                     "mass moment of inertia reduced to member " + member);
}

void run(dealii::ParameterHandler& prm, CommandContext& context)
{
  const TrainParameters parameters = parse_train_parameters(prm);
  const auto start = std::chrono::steady_clock::now();
  const kinematics::GearTrainSpec spec = kinematics::parse_gear_train(parameters.text);
  const kinematics::TrainSolution solution = kinematics::solve_train_kinematics(spec);
  check_reduce_to(parameters, spec);
  TrainReport report{parameters, spec, solution, context.report};
  report.published = same_text(parameters.text, kinematics::builtin_train("bi-planetary")) &&
                     parameters.input_torque == 120.2 && parameters.tooth_friction == 0.08;

  report_speeds(report);
  report_meshes(report);
  if (parameters.input_torque != 0. && spec.inputs.size() == 1 && !spec.output.empty())
  {
    report_lossless_statics(report);
    report_lossy_statics(report);
    report_carrier_method(report);
  }
  else
    context.report.add_text("statics",
                            "skipped: needs one input, an output and a non-zero input torque");
  report_reduced_inertia(report);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  context.report.add_value("cost", elapsed * 1e6, "µs",
                           "wall time: dense LU of the Willis system, torque-method passes");
}

const CommandRegistration registration(Command{
    "kinematics", "gear-train speeds, efficiency, torques, planet forces, reduced inertia",
    "Any gear train described by its members, meshes (a-b/frame), rigid connections, fixed\n"
    "members and input speeds: the Willis equations are solved as one linear system for every\n"
    "member's speed (under- or over-constrained trains are rejected with the reason). With one\n"
    "input and an output: statics by the torque method with pair efficiencies from μ_z, train\n"
    "efficiency, tooth forces and forces on planet axes; reduced inertia when inertias/masses\n"
    "are given. Default: the bi-planetary train of docs/references.md §2 (Drewniak et al. 2016),\n"
    "compared with the published values.",
    declare_train_parameters, run});
} // namespace
} // namespace gearstiff::app
