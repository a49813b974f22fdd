// `gearstiff faults [case.prm]`: the mesh stiffness with one faulty tooth (issue 31) over the
// positions where it meshes, beside the healthy pitch and the potential-energy method, and the
// whole-revolution table of the faulty gear (stiffness/fault_sweep.h).
//
//   gearstiff faults -o out                                    built-in: 1 mm root crack, pinion
//   tooth 0 gearstiff faults --set "Gear pair/Pinion/crack depth=0" --set "Gear pair/Pinion/broken
//   tooth=true" gearstiff faults --set "Gear pair/Wheel/spall depth=0.05" --set "Gear
//   pair/Wheel/spall length=1"
//
// The fault entries are those of Gear pair/Pinion and Gear pair/Wheel
// (app/scenes/tooth_fault_parameters.h); Stiffness/sweep positions is N, the positions per base
// pitch.
#include "app/core/command.h"
#include "app/core/units.h"
#include "app/stiffness/stiffness_parameters.h"
#include "app/stiffness/stiffness_report.h"
#include "errors/errors.h"
#include "errors/format.h"
#include "geometry/tooth_fault.h"
#include "stiffness/fault_sweep.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace
{
using namespace gearstiff;
using namespace gearstiff::app;

void declare_parameters(dealii::ParameterHandler& prm)
{
  declare_stiffness_sweep_parameters(prm, 16);
  // The built-in case: a 1 mm crack from the pinion's critical section at 45°.
  prm.enter_subsection("Gear pair");
  prm.enter_subsection("Pinion");
  prm.set("crack depth", "1");
  prm.leave_subsection();
  prm.leave_subsection();
}

// The gear and the tooth that carry the fault (InputError when none does).
stiffness::FaultSweepSpec faulty_tooth(const StiffnessParameters& p)
{
  stiffness::FaultSweepSpec spec;
  spec.positions_per_pitch = p.sweep.positions;
  spec.mesh = p.sweep.mesh;
  for (const bool wheel : {false, true})
    for (const auto& [index, list] :
         (wheel ? p.settings.scene.wheel_modifications : p.settings.scene.pinion_modifications)
             .by_tooth)
      if (geometry::has_faults(list))
      {
        spec.wheel = wheel;
        spec.faulty_tooth = index;
        return spec;
      }
  throw InputError("Gear pair/Pinion/faulty tooth",
                   "no fault is set: give a crack depth, spall depth, tip chipping or broken "
                   "tooth (Gear pair/Pinion or Gear pair/Wheel)");
}

void report_rows(Report& report, const stiffness::FaultSweepResult& r)
{
  auto& table =
      report.add_table("fault_sweep",
                       {"mesh_position", "healthy_stiffness", "faulty_stiffness", "change",
                        "energy_healthy", "energy_faulty", "energy_change", "lost_contact",
                        "faulty_pairs", "healthy_share", "faulty_share"},
                       {"-", "N/um", "N/um", "%", "N/um", "N/um", "%", "-", "-", "-", "-"});
  for (const auto& row : r.rows)
  {
    const auto change = [](double faulty, double healthy)
    { return 100. * (faulty - healthy) / healthy; };
    table.add_row({row.mesh_position, row.healthy_stiffness * 1e-6, row.faulty_stiffness * 1e-6,
                   row.lost_contact ? -100. : change(row.faulty_stiffness, row.healthy_stiffness),
                   row.energy_healthy * 1e-6, row.energy_faulty * 1e-6,
                   change(row.energy_faulty, row.energy_healthy), double(row.lost_contact),
                   double(row.faulty_pairs), row.healthy_share, row.faulty_share});
  }
  if (r.crack_tip_factors) // a root crack whose faces meet: its tip's K at every position
  {
    auto& tip = report.add_table("crack_tip", {"mesh_position", "K_I", "K_II"},
                                 {"-", "MPa*m^0.5", "MPa*m^0.5"});
    for (const auto& row : r.rows)
      tip.add_row({row.mesh_position, row.mode_one * 1e-6, row.mode_two * 1e-6});
  }
  // `gearstiff dynamics` reads this table (dynamics/stiffness_file.h): its period column states
  // the base pitches of one revolution on every row, so the CSV describes itself.
  auto& revolution =
      report.add_table("revolution_stiffness",
                       {"mesh_position", "stiffness", "pinion_angle", "lost_contact", "period"},
                       {"-", "N/um", "deg", "-", "-"});
  for (std::size_t i = 0; i < r.revolution_position.size(); ++i)
    revolution.add_row({r.revolution_position[i], r.revolution_stiffness[i] * 1e-6,
                        r.revolution_pinion_angle[i] / degree, double(r.revolution_lost_contact[i]),
                        double(r.period_pitches)});
}

void report_summary(Report& report, const stiffness::FaultSweepResult& r, stiffness::SweepMesh mesh)
{
  double largest_drop = 0., fe_energy_spread = 0.;
  unsigned int lost = 0;
  for (const auto& row : r.rows)
  {
    lost += row.lost_contact;
    if (!row.lost_contact)
      largest_drop = std::max(largest_drop, 1. - row.faulty_stiffness / row.healthy_stiffness);
    fe_energy_spread =
        std::max(fe_energy_spread, std::abs(row.energy_healthy / row.healthy_stiffness - 1.));
  }
  report.add_value("faulty_positions", double(r.rows.size()), "-",
                   "positions where the faulty tooth meshes");
  report.add_value("lost_contact_positions", double(lost), "-",
                   "positions where no pair touches (no stiffness exists)");
  report.add_value("largest_reduction", 100. * largest_drop, "%",
                   "largest FE stiffness reduction where contact holds");
  // Without the energy method (its failure is stated) its columns hold 0: no spread to report.
  if (r.energy_failure.empty())
    report.add_value("energy_method_spread", 100. * fe_energy_spread, "%",
                     "largest |k_energy/k_FE − 1| of the healthy positions");
  report.add_value("revolution_period", double(r.period_pitches), "-",
                   "base pitches in the revolution table (teeth of the faulty gear)");
  report.add_value("wall_time", r.wall_time, "s", "healthy and faulty FE sweeps, energy method");
  const bool once = mesh == stiffness::SweepMesh::once;
  report.add_value("sweep_mesh", once ? 1. : 0., "-",
                   "Stiffness/sweep mesh: 1 once (each sweep meshed and factorized once per "
                   "rank and rolled), 0 per position (a scene, mesh and factorization each)");
  report.add_text("revolution table",
                  "revolution_stiffness: one revolution of the faulty gear, the healthy pitch "
                  "repeated and the faulty tooth's positions; rows with lost_contact = 1 carry "
                  "no stiffness (0 written: no pair touches). Its mesh positions run over the "
                  "whole revolution (period " +
                      std::to_string(r.period_pitches) +
                      " base pitches, column period); `gearstiff dynamics` reads it as a Train "
                      "mesh's stiffness file (docs/faults.md).");
}

// The fault in words, restated where its results are read (issue 44: the report named no
// fault, so an own case's table could not be told from the built-in crack's).
std::string fault_description(const StiffnessParameters& p, const stiffness::FaultSweepSpec& spec)
{
  const auto& by_tooth =
      (spec.wheel ? p.settings.scene.wheel_modifications : p.settings.scene.pinion_modifications)
          .by_tooth;
  std::string text = std::string(spec.wheel ? "wheel" : "pinion") + " tooth " +
                     std::to_string(spec.faulty_tooth) + ":";
  for (const auto& m : by_tooth.at(spec.faulty_tooth))
    switch (m.kind)
    {
    case geometry::ModificationKind::root_crack:
      text += " root crack " + format_number(m.amount / mm, 4) + " mm deep at " +
              format_number(m.angle / degree, 4) + "° to the centre line" +
              (m.position > 0. ? " from radius " + format_number(m.position / mm, 5) + " mm"
                               : " from the critical section");
      break;
    case geometry::ModificationKind::spall:
      text += " spall " + format_number(m.amount / mm, 4) + " mm deep, " +
              format_number(m.length / mm, 4) + " mm long";
      break;
    case geometry::ModificationKind::tip_chipping:
      text += " tip chipped " + format_number(m.amount / mm, 4) + " mm";
      break;
    case geometry::ModificationKind::broken_tooth:
      text += " broken off at the root circle";
      break;
    default:
      break;
    }
  return text;
}

// k of the faulty and the healthy pass against the mesh position; the crack tip's K_I, K_II.
void plot_fault(CommandContext& context, const std::string& fault)
{
  if (!context.writes_files())
    return;
  const TemporaryCsv sweep(context.report, "fault_sweep");
  const auto& tables = context.report.tables();
  std::optional<TemporaryCsv> tip;
  if (std::any_of(tables.begin(), tables.end(),
                  [](const ReportTable& t) { return t.name == "crack_tip"; }))
    tip.emplace(context.report, "crack_tip");
  std::vector<std::string> arguments{sweep.path(), fault};
  if (tip)
    arguments.push_back(tip->path());
  context.plot("plot_faults.py", arguments, "fault_stiffness.png",
               "mesh stiffness of the faulty and the healthy pass (and the crack tip's K_I, "
               "K_II)");
}

void run(dealii::ParameterHandler& prm, CommandContext& context)
{
  StiffnessParameters p = parse_stiffness_parameters(prm);
  refuse_load_lists(p, "faults");
  // The sweep's checks (its work among them) run in mode sweep alone: another mode was ignored.
  if (p.mode != StiffnessMode::sweep)
    throw InputError("Stiffness/mode", "`faults` sweeps the positions where the faulty tooth "
                                       "meshes: mode = sweep");
  const stiffness::FaultSweepSpec spec = faulty_tooth(p);
  report_input_sizes(context.report, p);
  context.chart_case = pair_chart_case(p);
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(p.settings.scene.pair);
  const auto progress = [&context](const std::string& text) { context.progress("faults", text); };
  const std::string stem = shared_scratch_directory(context.mpi_communicator) + "/fault_scene";
  const stiffness::FaultSweepResult r = with_parameter_names(
      stiffness_parameter_names(),
      [&]
      {
        return p.settings.scene.mesh.dimension == 3
                   ? stiffness::fault_sweep<3>(context.mpi_communicator, p.settings, spec, stem,
                                               progress)
                   : stiffness::fault_sweep<2>(context.mpi_communicator, p.settings, spec, stem,
                                               progress);
      });
  if (!r.energy_failure.empty())
    context.report.add_text("energy method",
                            "not available: " + r.energy_failure + " (its columns hold 0)");
  add_pair_identity(context.report, pair);
  report_pinion_torque(context.report, p);
  const std::string fault = fault_description(p, spec);
  context.report.add_text("fault", fault);
  report_summary(context.report, r, spec.mesh);
  report_rows(context.report, r);
  plot_fault(context, fault);
}

const CommandRegistration registration(
    {"faults", "mesh stiffness with a faulty tooth: FE and energy method, revolution table",
     "Sweeps the positions where the faulty tooth (Gear pair/Pinion or Wheel: crack depth,\n"
     "spall depth, tip chipping, broken tooth; faulty tooth = its index) meshes, with the\n"
     "healthy pitch at the same offsets and the potential-energy method beside both, and\n"
     "writes the whole-revolution table of the faulty gear. Built-in case: a 1 mm root crack\n"
     "from the pinion's critical section at 45° on the split-path pair.",
     declare_parameters, run});
} // namespace
