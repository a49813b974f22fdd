// Parameter-file form of the FE mesh-stiffness analysis (stiffness/mesh_stiffness.h), shared by the
// `stiffness`, `cai` and `run` commands: the gear pair (app/kinematics_parameters.h), the scene
// (subsections "Gear pair scene" and "Mesh" of app/geometry_parameters.h, mm and degrees), the FE
// model ("Finite elements", "Linear solver", "Contact" of app/fe_contact_parameters.h) and the
// load case and sweep ("Stiffness").
// Defaults: the split-path pair of docs/references.md §1 under its published load case (T1 = 49.4
// N·m, μ = 0.01, pinion bore free to rotate, wheel bore fixed) on the default scene chosen by the
// accuracy-versus-cost study (docs/accuracy.md).
#pragma once

#include "app/scenes/geometry_parameters.h"
#include "app/scenes/tooth_modification_parameters.h"
#include "dynamics/cai_stiffness.h"
#include "kinematics/automatic_sizes.h"
#include "stiffness/mesh_stiffness.h"
#include "stiffness/mesh_stiffness_sweep.h"

#include <deal.II/base/parameter_handler.h>
#include <string>

namespace gearstiff::app
{
// What "Stiffness/mode" asks for: one position of the scene, or a sweep.
enum class StiffnessMode
{
  single,
  double_pair,
  roll_angle,
  sweep
};
// The parameter-file spelling: "single", "double", "roll angle", "sweep".
std::string mode_name(StiffnessMode mode);

// One modification set of `Stiffness/variants` (the micro-geometry of both gears).
struct StiffnessVariant
{
  std::string label; // as written, e.g. "tip relief = 10"
  geometry::GearModifications pinion, wheel;
};

struct StiffnessParameters
{
  stiffness::GearMeshStiffnessSettings settings; // SI, scene_file left empty
  StiffnessMode mode = StiffnessMode::single;
  stiffness::StiffnessSweepSpec sweep;
  bool write_vtu = false;
  // Compare with docs/references.md §1: asked for and the pair is the split-path pair
  // (kinematics::is_split_path_pair).
  bool published_reference = true;
  std::vector<kinematics::DerivedSize> derived_sizes; // the `auto` sizes of the gear pair
  // Values that run but look like a unit slip (a relief typed in mm where µm are due), one
  // sentence each naming the parameter; the report prints them beside the result.
  std::vector<std::string> input_notes;
  // `Stiffness/variants`: further modification sets, each swept like the base one.
  std::vector<StiffnessVariant> variants;
  // s, mode sweep: the lower bound of the sweep's work on the ranks (checked against
  // limits::max_run_seconds, printed before the sweep starts)
  double estimated_seconds = 0.;
};

// Gear pair, scene, mesh, finite elements, linear solver, contact and "Stiffness".
void declare_stiffness_parameters(dealii::ParameterHandler& prm);
// The same with the defaults "Stiffness/mode = sweep" and "sweep positions = `positions`".
void declare_stiffness_sweep_parameters(dealii::ParameterHandler& prm, unsigned int positions);
// Parses and checks everything the analysis checks before it meshes (gear pair, scene
// extent, torque, sweep positions), so that bad input fails before any FE work.
StiffnessParameters parse_stiffness_parameters(dealii::ParameterHandler& prm);
// The stiffness and scene fields (stiffness::stiffness_parameter, geometry::scene_field) as the
// stiffness, cai and run commands declare them.
ParameterNames stiffness_parameter_names();
} // namespace gearstiff::app

// Steps shared by the stiffness, cai and run commands (they live here because app/ builds only
// *_command.cc and *_parameters.cc files).
#include "app/core/command.h"

namespace gearstiff::app
{
// One position (modes single, double, roll angle), solved on all ranks of the context.
// `label` names the VTU files when p.write_vtu is set.
stiffness::GearMeshStiffnessResult solve_stiffness_position(const StiffnessParameters& p,
                                                            CommandContext& context,
                                                            const std::string& label);
// The sweep of p.sweep, positions distributed over the ranks, progress on context.pcout.
stiffness::StiffnessSweepResult solve_stiffness_sweep(const StiffnessParameters& p,
                                                      CommandContext& context,
                                                      const std::string& label);

// `command` (faults, cai, run) solves at the one load Gear pair scene/pinion torque and the base
// modifications: InputError naming Stiffness/torques or Stiffness/variants when either is set
// (they were dropped silently).
void refuse_load_lists(const StiffnessParameters& p, const std::string& command);
// The report value pinion_torque [N·m]: every report states its load.
void report_pinion_torque(Report& report, const StiffnessParameters& p);
// The position's values (prefix + key) in the report: stiffness, rotation, transmission
// error, torque ratio, pairs, pressures, root stresses and cost.
void report_stiffness_position(Report& report, const stiffness::GearMeshStiffnessResult& r,
                               const std::string& prefix, const std::string& label);
// The pair a stiffness result belongs to, as report values (pinion_teeth, wheel_teeth — negative
// for an internal wheel —, transverse_module and centre_distance in mm, contact_ratio): a
// `gearstiff dynamics` train reads them from the command's summary.json and rejects a table of
// another pair (app/dynamics_stiffness_file.h).
void add_pair_identity(Report& report, const kinematics::GearPairGeometry& pair);
// Whether a loaded pair of the position touches at a tip corner (closed nodes within one
// contact cell of A or E of `pair`).
bool tip_edge_contact(const stiffness::GearMeshStiffnessResult& r,
                      const kinematics::GearPairGeometry& pair);
// The sweep as a table (one row per position; column tip_edge_contact flags edge contact at a
// tip corner, and a report text lists those positions).
// The report's texts "derived sizes" (the `auto` sizes) and "input notes" (possible unit slips),
// when there are any: the first thing an own case's report shows.
void report_input_sizes(Report& report, const StiffnessParameters& p);
void add_stiffness_sweep_table(Report& report, const stiffness::StiffnessSweepResult& sweep,
                               const std::string& name, const kinematics::GearPairGeometry& pair);
// With a torque list: TE(θ), k(θ), load sharing and pressure per torque (table `name`, one row
// per torque and position) and the Harris-map table `map_name` (one row per torque: torque,
// te_peak_to_peak, te_mean, te_harmonic_1..3 [µm], stiffness_mean [N/µm], max_pressure [MPa]).
void add_torque_tables(Report& report, const stiffness::StiffnessSweepResult& sweep,
                       const std::string& name, const std::string& map_name);

// The sweep's mesh stiffness as the dynamics module's k(x) table "x:k, ..." (x in base
// pitches in [0, 1), the roll position of the pair that entered last; k in N/mm), positions
// sorted, duplicates modulo one pitch dropped.
std::string dynamics_stiffness_table(const stiffness::StiffnessSweepResult& sweep);
// Subsections "Mesh 1" and "Mesh 2" of a `gearstiff dynamics` parameter file that put on both
// meshes the sweep's k(x) table (dynamics_stiffness_table), or the Cai curve `cai` (scale
// written in N/mm).
std::string dynamics_table_input(const stiffness::StiffnessSweepResult& sweep);
// A whole `gearstiff dynamics` parameter file for the sweep's own pair (issue 41): two gears and
// one mesh with this pair's base radii, ε_α, approach ratio, steel-blank inertias, torque T1,
// friction arms and the sweep's k(x) table, at a subcritical input speed (0.3 of the pair's
// resonance speed), its header naming the pair.
std::string own_pair_dynamics_input(const StiffnessParameters& p,
                                    const kinematics::GearPairGeometry& pair,
                                    const stiffness::StiffnessSweepResult& sweep);
std::string dynamics_cai_input(const dynamics::CaiParameters& cai);
// Single-pair stiffness samples for the Cai fit: at each position each loaded pair j carries
// k_j = share_j·k at roll position p_ref + j [base pitches] (all pairs share one deflection,
// so the mesh stiffness splits as the load does).
std::vector<std::pair<double, double>>
pair_stiffness_samples(const stiffness::StiffnessSweepResult& sweep, double contact_ratio);
} // namespace gearstiff::app
