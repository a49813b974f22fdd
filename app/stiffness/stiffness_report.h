// The report steps shared by the stiffness, faults, cai and run commands: load, position values,
// pair identity, sweep and torque tables, and the `gearstiff dynamics` input a sweep writes.
#pragma once

#include "app/core/report.h"
#include "app/stiffness/stiffness_parameters.h"

namespace gearstiff::app
{
// `command` (faults, cai, run) solves at the one load Gear pair scene/pinion torque and the base
// modifications: InputError naming Stiffness/torques or Stiffness/variants when either is set
// (they were dropped silently).
void refuse_load_lists(const StiffnessParameters& p, const std::string& command);
// The case a chart names (CommandContext::chart_case): "z 23/61, m_n 4 mm, b 30 mm,
// x 0.2/-0.1, T1 = 300 N·m" (an internal wheel's teeth negative, β where helical, every torque
// of a torque list).
std::string pair_chart_case(const StiffnessParameters& p);
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
// The loaded pair with the position's largest pressure (nullptr: nothing closed).
const stiffness::ToothPairLoad* peak_pressure_pair(const stiffness::GearMeshStiffnessResult& r);
// Whether the position's largest pressure acts at a tip corner (its node within one contact cell
// of A or E of `pair`).
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
// The pinion torque [N·m] the sweep's positions were solved at: a torque list's first (its
// positions are the first torque's), else `Gear pair scene/pinion torque`.
double solved_torque(const StiffnessParameters& p, const stiffness::StiffnessSweepResult& sweep);
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
// The same file as own_pair_dynamics_input with the calibrated Cai curve on its mesh (`gearstiff
// cai` of an own pair), at Gear pair scene/pinion torque.
std::string own_pair_cai_input(const StiffnessParameters& p,
                               const kinematics::GearPairGeometry& pair,
                               const dynamics::CaiParameters& cai);
// Before a sweep of an own pair: the steel-blank inertias own_pair_dynamics_input will need
// (InputError naming Gear pair/Pinion|Wheel/bore diameter), so that bad input is refused before
// any work, not after the sweep while its files are written.
void check_own_pair_dynamics_input(const StiffnessParameters& p,
                                   const kinematics::GearPairGeometry& pair);
// Single-pair stiffness samples for the Cai fit: at each position each loaded pair j carries
// k_j = share_j·k at roll position p_ref + j [base pitches] (all pairs share one deflection,
// so the mesh stiffness splits as the load does).
std::vector<std::pair<double, double>>
pair_stiffness_samples(const stiffness::StiffnessSweepResult& sweep, double contact_ratio);
} // namespace gearstiff::app
