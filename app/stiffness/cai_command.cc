// `gearstiff cai [case.prm]`: calibrates the Cai stiffness curve of one tooth pair
// (docs/references.md §1; dynamics/cai_stiffness.h) to FE contact results over the whole engagement
// A..E.
//
//   gearstiff cai -o out                                   scale only, published shape kept
//   gearstiff cai --set "Cai calibration/fit shape=true"    the shape coefficients too
//   mpirun -np 2 gearstiff cai -o out                       positions split over the ranks
//
// The FE samples of one pair come from a sweep over one base pitch: every pair in contact shares
// the one deflection r_b1·Δφ, so the mesh stiffness splits into pair stiffnesses k_j = share_j·k
// exactly as the load does, and the pairs at p and p + 1 cover the whole engagement 0 ≤ p < ε_α.
// Writes cai_calibrated.prm, which `gearstiff dynamics cai_calibrated.prm` reads (Mesh 1, Mesh 2:
// stiffness source cai, stiffness = fitted scale, cai shape = fitted shape).
#include "app/core/command.h"
#include "app/core/parameter_patterns.h"
#include "app/core/units.h"
#include "app/stiffness/stiffness_parameters.h"
#include "app/stiffness/stiffness_report.h"
#include "app/stiffness/stiffness_solve.h"
#include "dynamics/cai_stiffness.h"
#include "dynamics/mesh_stiffness.h"
#include "errors/errors.h"
#include "kinematics/automatic_sizes.h"

#include <cmath>

namespace
{
namespace ansys = gearstiff::kinematics::split_path_published; // the published FE values
using namespace gearstiff;
using namespace gearstiff::app;

// docs/references.md §1: the paper scales the Cai curve so one pair's peak equals k'_j (ANSYS).
const std::string paper_source = "docs/references.md §1 (Reszuta & Drewniak 2015: Cai peak = k'_j)";

void declare_parameters(dealii::ParameterHandler& prm)
{
  // One base pitch from A holds every engagement position once (pairs at p and p + 1).
  declare_stiffness_sweep_parameters(prm, 16);
  prm.enter_subsection("Cai calibration");
  prm.declare_entry("fit shape", "false", Bool(),
                    "also fit the shape coefficients c0, c1, c2 (else only the scale, the "
                    "published shape 0.55, 1.8, -1.8 kept)");
  prm.leave_subsection();
}

bool parse_fit_shape(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Cai calibration");
  const bool fit_shape = prm.get_bool("fit shape");
  prm.leave_subsection();
  return fit_shape;
}

// Checked before the FE sweep: every position yields at least one pair sample, so the fit's
// unknowns (the scale, or the scale and three shape coefficients: dynamics/cai_stiffness.h)
// are determined only with at least that many positions.
void check_sweep_for_fit(const StiffnessParameters& p, bool fit_shape)
{
  if (p.mode != StiffnessMode::sweep)
    throw InputError("Stiffness/mode", "the Cai calibration needs mode = sweep");
  const unsigned int unknowns = fit_shape ? 3 : 1;
  if (p.sweep.positions < unknowns)
    throw InputError("Stiffness/sweep positions",
                     "must be at least " + std::to_string(unknowns) + " for the Cai fit" +
                         (fit_shape ? " of the shape (Cai calibration/fit shape = true)" : ""));
}

std::vector<dynamics::StiffnessSample> pair_samples(const stiffness::StiffnessSweepResult& sweep,
                                                    double contact_ratio)
{
  std::vector<dynamics::StiffnessSample> samples;
  for (const auto& [position, stiffness] : pair_stiffness_samples(sweep, contact_ratio))
    samples.push_back({position, stiffness});
  return samples;
}

void report_fit(Report& report, const StiffnessParameters& p,
                const kinematics::GearPairGeometry& pair, const dynamics::CaiFit& fit,
                bool fit_shape, std::size_t samples, std::size_t positions)
{
  report.add_text("samples", std::to_string(samples) +
                                 " single-pair FE samples k_j = share_j·k from " +
                                 std::to_string(positions) +
                                 " positions over one base pitch (engagement 0 ≤ p < ε_α = " +
                                 format_number(pair.transverse_contact_ratio, 5) + ")");
  report.add_text("fit", fit_shape ? "scale and shape (least squares, shape peak 1)"
                                   : "scale only (published Cai shape 0.55, 1.8, -1.8)");
  if (p.published_reference)
    report.add_compared_value("cai_scale", fit.parameters.scale / 1e6,
                              ansys::single_pair_stiffness / 1e6, "N/µm",
                              "calibrated Cai scale (one pair's peak stiffness)", paper_source);
  else
    report.add_value("cai_scale", fit.parameters.scale / 1e6, "N/µm",
                     "calibrated Cai scale (one pair's peak stiffness)");
  add_pair_identity(report, pair);
  report.add_value("cai_c0", fit.parameters.shape[0], "-", "shape c0");
  report.add_value("cai_c1", fit.parameters.shape[1], "-", "shape c1");
  report.add_value("cai_c2", fit.parameters.shape[2], "-", "shape c2");
  report.add_value("fit_rms_residual", fit.rms_residual / 1e6, "N/µm",
                   "rms of FE minus calibrated curve");
  report.add_value("fit_max_residual", fit.max_residual / 1e6, "N/µm",
                   "largest |FE − calibrated curve|");
  report.add_value("fit_relative_rms", fit.rms_residual / fit.parameters.scale, "-",
                   "rms residual / scale");
}

// The mean mesh stiffness of the FE sweep and of both Cai curves.
void report_means(Report& report, const stiffness::StiffnessSweepResult& sweep,
                  const dynamics::CaiParameters& calibrated, const dynamics::CaiParameters& paper,
                  double contact_ratio, bool fit_shape)
{
  double mean = 0.;
  for (const auto& r : sweep.positions)
    mean += r.mesh_stiffness / sweep.positions.size();
  report.add_value("fe_mean_mesh_stiffness", mean / 1e6, "N/µm", "FE mean mesh stiffness");
  const double calibrated_mean =
      dynamics::MeshStiffness::cai(calibrated, "cai").mean_stiffness(contact_ratio);
  report.add_value("cai_mean_mesh_stiffness", calibrated_mean / 1e6, "N/µm",
                   "mean mesh stiffness of the calibrated Cai curve");
  report.add_value("paper_cai_mean_mesh_stiffness",
                   dynamics::MeshStiffness::cai(paper, "cai").mean_stiffness(contact_ratio) / 1e6,
                   "N/µm", "mean mesh stiffness of the paper-scaled Cai curve");
  report.add_value("sweep_wall_time", sweep.wall_time, "s", "wall time of the FE sweep");
  // The scale-only fit keeps the published shape, which a modified pair's k(θ) need not follow:
  // own relieved pairs' curves came out 5–16 % above their FE mean (the invariants' cases 3, 7,
  // 11, 15 of seed 20261201; the built-in pair +0.2 %, an own unmodified 23/57 pair −1.1 %).
  // Fitting the shape met a relieved 23/40 pair's mean within 0.4 % (scale only +2.5 %) but
  // turned negative at the ends of case 7's pair (exit 3). Beyond 5 % the report says so.
  const double deviation = calibrated_mean / mean - 1.;
  if (std::abs(deviation) > 0.05)
    report.add_text(
        "fit check",
        std::string("the calibrated curve's mean mesh stiffness is ") +
            (deviation > 0. ? "+" : "") + format_number(100. * deviation, 3) +
            " % off the FE's: the Cai shape does not describe this pair's k(θ)" +
            (fit_shape ? ""
                       : "; Cai calibration/fit shape = true fits its shape too "
                         "(a quadratic, which a relieved pair's k(θ) need not "
                         "allow: exit 3 then)") +
            ", or drive `gearstiff dynamics` with the FE table, the stiffness_table.prm "
            "of `gearstiff stiffness`");
}

void add_cai_tables(Report& report, const std::vector<dynamics::StiffnessSample>& samples,
                    const dynamics::CaiParameters& calibrated, const dynamics::CaiParameters& paper,
                    double contact_ratio)
{
  ReportTable& points = report.add_table(
      "cai_samples", {"roll_position", "fe_pair_stiffness", "calibrated_cai", "paper_cai"},
      {"base pitches", "N/um", "N/um", "N/um"});
  for (const auto& s : samples)
    points.add_row({s.position, s.stiffness / 1e6,
                    dynamics::cai_pair_stiffness(calibrated, s.position / contact_ratio) / 1e6,
                    dynamics::cai_pair_stiffness(paper, s.position / contact_ratio) / 1e6});
  ReportTable& curve =
      report.add_table("cai_curves", {"roll_position", "calibrated_cai", "paper_cai"},
                       {"base pitches", "N/um", "N/um"});
  for (unsigned int i = 0; i <= 60; ++i)
  {
    const double s = i / 60.;
    curve.add_row({s * contact_ratio, dynamics::cai_pair_stiffness(calibrated, s) / 1e6,
                   dynamics::cai_pair_stiffness(paper, s) / 1e6});
  }
}

// cai_calibrated.prm for `gearstiff dynamics` and the calibration chart. The built-in pair's
// curve goes on both meshes of the published split-path gearbox; an own pair's drives a train of
// that pair alone, as its stiffness table does (issue 41), never the built-in gearbox.
void write_files(const StiffnessParameters& p, const kinematics::GearPairGeometry& pair,
                 CommandContext& context, const dynamics::CaiFit& fit, std::size_t samples)
{
  if (!(context.writes_files() && context.is_root()))
    return;
  const bool builtin = kinematics::is_split_path_pair(p.settings.scene.pair);
  context.write_output(
      "cai_calibrated.prm",
      builtin ? "calibrated Cai parameters for `gearstiff dynamics` (the split path's Mesh 1 and "
                "Mesh 2)"
              : "`gearstiff dynamics` input: this pair with its calibrated Cai curve",
      [&](std::ostream& out)
      {
        out << "# Cai curve calibrated to FE single-pair stiffness (gearstiff cai, " << samples
            << " samples, rms residual " << format_number(fit.rms_residual / 1e3, 6)
            << " N/mm).\n# Use: gearstiff dynamics cai_calibrated.prm\n"
            << (builtin ? dynamics_cai_input(fit.parameters)
                        : own_pair_cai_input(p, pair, fit.parameters));
      });
  const TemporaryCsv sample_csv(context.report, "cai_samples");
  const TemporaryCsv curve_csv(context.report, "cai_curves");
  context.plot("plot_cai.py", {sample_csv.path(), curve_csv.path()}, "cai_calibration.png",
               "FE pair stiffness, calibrated and paper-scaled Cai curves");
}

void run(dealii::ParameterHandler& prm, CommandContext& context)
{
  const StiffnessParameters p = parse_stiffness_parameters(prm);
  refuse_load_lists(p, "cai");
  const bool fit_shape = parse_fit_shape(prm);
  check_sweep_for_fit(p, fit_shape);
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(p.settings.scene.pair);
  const double contact_ratio = pair.transverse_contact_ratio;
  // The curve is one spur pair's over ε_α (docs/references.md §1): a helical pair's contact line
  // sweeps the face over ε_α + ε_β, its pairs' stiffnesses have another shape, and the samples
  // beyond ε_α would be dropped. Refused before the (3D) sweep, with the way that does work.
  if (p.settings.scene.pair.pinion.helix_angle != 0.)
    throw InputError("Gear pair/Pinion/helix angle",
                     "the Cai curve is a spur pair's stiffness over ε_α; a helical pair's pairs "
                     "engage over ε_α + ε_β = " +
                         format_number(pair.total_contact_ratio, 4) +
                         ": drive `gearstiff dynamics` with the stiffness_table.prm of `gearstiff "
                         "stiffness --set Stiffness/mode=sweep` instead");
  // An own pair's file carries its blanks' inertias: refused before the sweep, not after it.
  if (!kinematics::is_split_path_pair(p.settings.scene.pair))
    check_own_pair_dynamics_input(p, pair);
  Report& report = context.report;
  report_input_sizes(report, p);

  const stiffness::StiffnessSweepResult sweep = solve_stiffness_sweep(p, context, "cai");
  const std::vector<dynamics::StiffnessSample> samples = pair_samples(sweep, contact_ratio);
  const dynamics::CaiFit fit = dynamics::fit_cai_parameters(
      samples, contact_ratio, dynamics::StiffnessSampleKind::single_pair, fit_shape);
  const dynamics::CaiParameters paper =
      dynamics::cai_published_parameters(ansys::single_pair_stiffness);

  report_fit(report, p, pair, fit, fit_shape, samples.size(), sweep.positions.size());
  report_means(report, sweep, fit.parameters, paper, contact_ratio, fit_shape);
  add_cai_tables(report, samples, fit.parameters, paper, contact_ratio);
  write_files(p, pair, context, fit, samples.size());
}

const CommandRegistration registration(Command{
    "cai", "calibrate the Cai pair-stiffness curve to FE contact results (writes dynamics input)",
    "Runs an FE stiffness sweep over one base pitch (see `gearstiff stiffness`), splits the mesh\n"
    "stiffness into the pairs' stiffnesses by their load shares (one deflection, so k_j =\n"
    "share_j·k), and fits the Cai curve of docs/references.md §1 (scale, optionally its shape) by\n"
    "least squares (dynamics module). Writes cai_calibrated.prm for `gearstiff dynamics` and a\n"
    "chart of FE points, calibrated and paper-scaled Cai curves.",
    declare_parameters, run});
} // namespace
