#include "app/stiffness/stiffness_report.h"

#include "app/core/parameter_patterns.h"
#include "app/core/units.h"
#include "app/kinematics/kinematics_parameters.h"
#include "app/scenes/fe_contact_parameters.h"
#include "app/scenes/geometry_parameters.h"
#include "dynamics/mesh_stiffness.h"
#include "dynamics/train_model.h"
#include "errors/errors.h"
#include "errors/format.h"
#include "errors/limits.h"
#include "geometry/tooth_fault.h"
#include "kinematics/gear_pair.h"
#include "stiffness/transmission_error.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <sstream>
#include <unistd.h>

namespace gearstiff::app
{
void refuse_load_lists(const StiffnessParameters& p, const std::string& command)
{
  if (!p.settings.torques.empty())
    throw InputError("Stiffness/torques",
                     "`" + command +
                         "` runs at one load, Gear pair scene/pinion torque (the list is for "
                         "`stiffness` in mode sweep)");
  if (!p.variants.empty())
    throw InputError("Stiffness/variants", "`" + command +
                                               "` runs the modifications of Gear pair/Pinion "
                                               "and Wheel alone (the list is for `stiffness` "
                                               "in mode sweep)");
}

std::string pair_chart_case(const StiffnessParameters& p)
{
  const kinematics::GearPairSpec& pair = p.settings.scene.pair;
  const auto both = [](double a, double b, double scale, int digits)
  { return format_number(a * scale, digits) + "/" + format_number(b * scale, digits); };
  std::string text = "z " + std::to_string(pair.pinion.teeth) + "/" +
                     (pair.wheel.internal ? "-" : "") + std::to_string(pair.wheel.teeth) +
                     ", m_n " + format_number(pair.pinion.normal_module * 1e3, 4) + " mm, b " +
                     both(pair.pinion.face_width, pair.wheel.face_width, 1e3, 4) + " mm, x " +
                     both(pair.pinion.profile_shift, pair.wheel.profile_shift, 1., 4);
  if (pair.pinion.helix_angle != 0.)
    text += ", β " + format_number(pair.pinion.helix_angle / degree, 4) + "°";
  std::string torques;
  for (const double t : p.settings.torques)
    torques += (torques.empty() ? "" : ", ") + format_number(t, 4);
  return text +
         ", T1 = " + (torques.empty() ? format_number(p.settings.pinion_torque, 4) : torques) +
         " N·m";
}

void report_pinion_torque(Report& report, const StiffnessParameters& p)
{
  report.add_value("pinion_torque", p.settings.pinion_torque, "N·m",
                   "T1 on the pinion (Gear pair scene/pinion torque), the load of every solve");
}

void report_stiffness_position(Report& report, const stiffness::GearMeshStiffnessResult& r,
                               const std::string& prefix, const std::string& label)
{
  report.add_value(prefix + "pinion_roll_angle", r.pinion_roll_angle / degree, "deg",
                   label + ": pinion roll angle ℓ/r_b1 of the reference pair");
  report.add_value(prefix + "mesh_position", r.mesh_position, "-",
                   label + ": reference pair's roll position from A (base pitches)");
  report.add_value(
      prefix + "loaded_pairs", r.loaded_pairs, "-",
      label + ": tooth pairs carrying load (kinematic: " + std::to_string(r.kinematic_pairs) + ")");
  report.add_value(prefix + "pinion_rotation", r.pinion_rotation * 1e6, "µrad",
                   label + ": pinion rotation Δφ under T1");
  report.add_value(prefix + "transmission_error", r.transmission_error * 1e6, "µm",
                   label + ": loaded transmission error r_b1·Δφ");
  report.add_value(prefix + "torque_ratio", r.torque_ratio, "-",
                   label + ": |T_wheel/T1| (r_b2/r_b1 = " +
                       format_number(r.wheel_base_radius / r.pinion_base_radius, 6) +
                       " without friction)");
  for (const auto& pair : r.pairs)
    report.add_value(
        prefix + "load_share_pair_" +
            (pair.pair < 0 ? "m" + std::to_string(-pair.pair) : std::to_string(pair.pair)),
        pair.load_share, "-",
        label + ": load share of tooth pair " + std::to_string(pair.pair) + " (at " +
            format_number(pair.position * 1e3, 5) + " mm from T1)");
  report.add_value(prefix + "max_contact_pressure", r.max_contact_pressure / 1e6, "MPa",
                   label + ": largest nodal contact pressure (Q2: an estimate, docs/accuracy.md)");
  if (const stiffness::ToothPairLoad* peak = peak_pressure_pair(r))
  {
    report.add_value(prefix + "max_pressure_roll", peak->max_pressure_roll * 1e3, "mm",
                     label + ": where it acts: roll length √(r² − r_b1²) of its pinion node, "
                             "from T1 as the path of contact A–E");
    report.add_value(prefix + "max_pressure_face", peak->max_pressure_face * 1e3, "mm",
                     label + ": where it acts across the face, from the middle (2D: 0)");
    report.add_value(prefix + "max_pressure_wheel_roll", peak->max_pressure_wheel_roll * 1e3, "mm",
                     label + ": the same point on the wheel, on the path's scale: where the "
                             "wheel's involute through it meets the line of action, from T1 "
                             "(A: the wheel tip)");
  }
  if (!r.pairs.empty())
  {
    // The most loaded pair's closed zone: its width across the profile is 2a of Hertz's line
    // contact to within one contact cell (the edge lies between a closed and an open node).
    const auto loaded =
        std::max_element(r.pairs.begin(), r.pairs.end(),
                         [](auto& a, auto& b) { return a.normal_force < b.normal_force; });
    report.add_value(prefix + "contact_width", loaded->contact_length * 1e3, "mm",
                     label + ": extent of the closed nodes of the most loaded pair");
    report.add_value(prefix + "contact_normal_force", loaded->normal_force, "N",
                     label + ": normal force of the most loaded pair");
  }
  report.add_value(prefix + "pinion_root_stress", r.pinion_root_stress / 1e6, "MPa",
                   label + ": largest first principal stress on the pinion fillets");
  report.add_value(prefix + "wheel_root_stress", r.wheel_root_stress / 1e6, "MPa",
                   label + ": largest first principal stress on the wheel fillets");
  report.add_value(prefix + "cells", r.n_cells, "-", label + ": cells");
  report.add_value(prefix + "dofs", r.n_dofs, "-", label + ": degrees of freedom");
  report.add_value(prefix + "contact_size", r.contact_size * 1e3, "mm",
                   label + ": h_c, cell size at the contacts");
  report.add_value(prefix + "active_set_iterations", r.active_set_iterations, "-",
                   label + ": contact active-set iterations (linear solves)");
  report.add_value(prefix + "time_scene", r.scene_time, "s", label + ": scene and meshing");
  report.add_value(prefix + "time_setup", r.setup_time, "s",
                   label + ": DoFs, stiffness matrix, mortar coupling");
  report.add_value(prefix + "time_solve", r.solve_time, "s",
                   label + ": contact iterations (assembly + solves)");
  report.add_value(prefix + "time_total", r.total_time, "s", label + ": wall time");
}

void add_pair_identity(Report& report, const kinematics::GearPairGeometry& pair)
{
  const double wheel_sign = pair.spec.wheel.internal ? -1. : 1.;
  report.add_value("pinion_teeth", pair.spec.pinion.teeth, "-", "z1 of the pair (drives)");
  report.add_value("wheel_teeth", wheel_sign * pair.spec.wheel.teeth, "-",
                   "z2 of the pair (negative: internal)");
  report.add_value("transverse_module", pair.transverse_module / mm, "mm", "m_t of the pair");
  report.add_value("centre_distance", pair.centre_distance / mm, "mm", "a_w of the pair");
  report.add_value("contact_ratio", pair.transverse_contact_ratio, "-", "ε_α of the pair");
  // Where the pitch point lies on the path (the train model's mesh phasing needs it).
  report.add_value("approach_ratio",
                   (pair.pitch_point - pair.contact_start) / pair.transverse_base_pitch, "-",
                   "ε_f = AC/p_bt, start of contact to the pitch point (pinion drives)");
}

const stiffness::ToothPairLoad* peak_pressure_pair(const stiffness::GearMeshStiffnessResult& r)
{
  const stiffness::ToothPairLoad* peak = nullptr;
  for (const auto& load : r.pairs)
    if (load.normal_force > 0. && load.closed_nodes > 0 &&
        (peak == nullptr || load.max_pressure > peak->max_pressure))
      peak = &load;
  return peak;
}

bool tip_edge_contact(const stiffness::GearMeshStiffnessResult& r,
                      const kinematics::GearPairGeometry& pair)
{
  // The position's largest pressure acts within one contact cell of a tip edge: the pinion's
  // (its node's roll at E or beyond) or the wheel's (the same point's roll on the wheel at A or
  // beyond). There the pressure is an edge singularity, not a Hertz pressure, and grows with
  // refinement. Each gear's own roll decides: a wheel tip corner pressing the pinion off the line
  // of action (near a helical face end) lies inside A by the pinion's roll but at A by the
  // wheel's. The peak's own node decides, not the closed zone's extent: a helical contact line
  // meets A or E in some section at most positions while its largest pressure may lie mid-face.
  const stiffness::ToothPairLoad* peak = peak_pressure_pair(r);
  const double tolerance = r.contact_size;
  return peak != nullptr && (peak->max_pressure_wheel_roll <= pair.contact_start + tolerance ||
                             peak->max_pressure_roll >= pair.contact_end - tolerance);
}

void report_input_sizes(Report& report, const StiffnessParameters& p)
{
  if (!p.derived_sizes.empty())
    report.add_text("derived sizes", kinematics::derived_sizes_text(p.derived_sizes));
  std::string notes;
  for (const std::string& note : p.input_notes)
    notes += (notes.empty() ? "" : "; ") + note;
  if (!notes.empty())
    report.add_text("input notes", notes);
}

namespace
{
// What the sweep's columns max_pressure_roll, max_pressure_wheel_roll and tip_edge_contact
// are read against: A, E and h_c.
void add_path_ends(Report& report, const stiffness::StiffnessSweepResult& sweep,
                   const kinematics::GearPairGeometry& pair)
{
  report.add_value("contact_start", pair.contact_start * 1e3, "mm",
                   "A, start of the path of contact, roll length from T1 (the wheel tip)");
  report.add_value("contact_end", pair.contact_end * 1e3, "mm",
                   "E, end of the path of contact, roll length from T1 (the pinion tip)");
  if (!sweep.positions.empty() && sweep.positions.front().contact_size > 0.) // FE contact
    report.add_value("contact_size", sweep.positions.front().contact_size * 1e3, "mm",
                     "h_c, cell size at the contacts (tip_edge_contact: a peak within h_c of A by "
                     "its wheel roll or of E by its pinion roll)");
}
} // namespace

void add_stiffness_sweep_table(Report& report, const stiffness::StiffnessSweepResult& sweep,
                               const std::string& name, const kinematics::GearPairGeometry& pair)
{
  ReportTable& table =
      report.add_table(name,
                       {"position",
                        "roll_angle",
                        "mesh_position",
                        "loaded_pairs",
                        "stiffness",
                        "transmission_error",
                        "unloaded_transmission_error",
                        "share_pair_m1",
                        "share_pair_0",
                        "share_pair_p1",
                        "max_pressure",
                        "max_pressure_roll",
                        "max_pressure_face",
                        "max_pressure_wheel_roll",
                        "tip_edge_contact",
                        "pinion_root_stress",
                        "wheel_root_stress",
                        "torque_ratio",
                        "iterations",
                        "dofs",
                        "time",
                        "rank"},
                       {"-",  "deg", "-",  "-", "N/um", "um",  "um", "-", "-", "-", "MPa",
                        "mm", "mm",  "mm", "-", "MPa",  "MPa", "-",  "-", "-", "s", "-"});
  add_path_ends(report, sweep, pair);
  std::string edges;
  for (unsigned int i = 0; i < sweep.positions.size(); ++i)
  {
    const stiffness::GearMeshStiffnessResult& r = sweep.positions[i];
    double share[3] = {0., 0., 0.};
    for (const auto& load : r.pairs)
      if (load.pair >= -1 && load.pair <= 1)
        share[load.pair + 1] = load.load_share;
    const bool edge = tip_edge_contact(r, pair);
    const stiffness::ToothPairLoad* peak = peak_pressure_pair(r);
    if (edge)
      edges += (edges.empty() ? "" : ", ") + std::to_string(i + 1);
    table.add_row({double(i + 1),
                   r.pinion_roll_angle / degree,
                   r.mesh_position,
                   double(r.loaded_pairs),
                   r.mesh_stiffness / 1e6,
                   r.transmission_error * 1e6,
                   r.unloaded_transmission_error * 1e6,
                   share[0],
                   share[1],
                   share[2],
                   r.max_contact_pressure / 1e6,
                   peak ? peak->max_pressure_roll * 1e3 : 0.,
                   peak ? peak->max_pressure_face * 1e3 : 0.,
                   peak ? peak->max_pressure_wheel_roll * 1e3 : 0.,
                   edge ? 1. : 0.,
                   r.pinion_root_stress / 1e6,
                   r.wheel_root_stress / 1e6,
                   r.torque_ratio,
                   double(r.active_set_iterations),
                   double(r.n_dofs),
                   r.total_time,
                   double(sweep.rank_of_position[i])});
  }
  if (edges.empty())
    return;
  // A rounded tip ends its involute at d_Fa in a smooth arc: a peak there is the arc's contact,
  // resolved only when the radius spans several contact cells, not a corner's singularity.
  const bool rounded =
      pair.spec.pinion.tip_rounding_radius > 0. || pair.spec.wheel.tip_rounding_radius > 0.;
  report.add_text(
      name + " tip edge contact",
      "positions " + edges +
          ": the largest pressure acts at the end of an involute (within one contact cell of the "
          "wheel's A by column max_pressure_wheel_roll or of the pinion's E by max_pressure_roll; "
          "across the face: max_pressure_face): " +
          (rounded ? "at a sharp tip a corner, whose edge pressure grows with refinement; at a "
                     "rounded tip the rounding's contact, resolved only if its radius spans "
                     "several contact cells (column tip_edge_contact)"
                   : "a tip corner; there max_pressure is an edge pressure that grows with "
                     "refinement, not a Hertz pressure (column tip_edge_contact)"));
}

void add_torque_tables(Report& report, const stiffness::StiffnessSweepResult& sweep,
                       const std::string& name, const std::string& map_name)
{
  ReportTable& table = report.add_table(
      name,
      {"torque", "position", "roll_angle", "mesh_position", "transmission_error",
       "unloaded_transmission_error", "stiffness", "share_pair_m1", "share_pair_0", "share_pair_p1",
       "max_pressure", "pinion_root_stress", "wheel_root_stress", "iterations", "time"},
      {"N*m", "-", "deg", "-", "um", "um", "N/um", "-", "-", "-", "MPa", "MPa", "MPa", "-", "s"});
  ReportTable& map =
      report.add_table(map_name,
                       {"torque", "te_peak_to_peak", "te_mean", "te_harmonic_1", "te_harmonic_2",
                        "te_harmonic_3", "stiffness_mean", "max_pressure"},
                       {"N*m", "um", "um", "um", "um", "um", "N/um", "MPa"});
  for (unsigned int t = 0; t < sweep.by_torque.size(); ++t)
  {
    for (unsigned int i = 0; i < sweep.by_torque[t].size(); ++i)
    {
      const stiffness::GearMeshStiffnessResult& r = sweep.by_torque[t][i];
      double share[3] = {0., 0., 0.};
      for (const auto& pair : r.pairs)
        if (pair.pair >= -1 && pair.pair <= 1)
          share[pair.pair + 1] = pair.load_share;
      table.add_row({sweep.torques[t], double(i + 1), r.pinion_roll_angle / degree, r.mesh_position,
                     r.transmission_error * 1e6, r.unloaded_transmission_error * 1e6,
                     r.mesh_stiffness / 1e6, share[0], share[1], share[2],
                     r.max_contact_pressure / 1e6, r.pinion_root_stress / 1e6,
                     r.wheel_root_stress / 1e6, double(r.active_set_iterations), r.total_time});
    }
    const stiffness::TransmissionErrorSummary s =
        stiffness::summarize_transmission_error(sweep.by_torque[t]);
    map.add_row({sweep.torques[t], s.peak_to_peak * 1e6, s.mean * 1e6, s.harmonics[0] * 1e6,
                 s.harmonics[1] * 1e6, s.harmonics[2] * 1e6, s.stiffness_mean / 1e6,
                 s.max_pressure / 1e6});
  }
}

std::string dynamics_stiffness_table(const stiffness::StiffnessSweepResult& sweep)
{
  std::vector<std::pair<double, double>> samples; // x [base pitches], k [N/mm]
  for (const auto& r : sweep.positions)
    samples.emplace_back(r.mesh_position - std::floor(r.mesh_position), r.mesh_stiffness / 1e3);
  std::sort(samples.begin(), samples.end());
  std::ostringstream text;
  text.precision(10);
  double last = -1.;
  for (const auto& [x, k] : samples)
  {
    if (x - last < 1e-9)
      continue;
    text << (last < 0. ? "" : ", ") << x << ":" << k;
    last = x;
  }
  return text.str();
}

double solved_torque(const StiffnessParameters& p, const stiffness::StiffnessSweepResult& sweep)
{
  return sweep.torques.empty() ? p.settings.pinion_torque : sweep.torques.front();
}

std::string dynamics_table_input(const stiffness::StiffnessSweepResult& sweep)
{
  const std::string table = dynamics_stiffness_table(sweep);
  std::string text;
  for (const std::string mesh : {"Mesh 1", "Mesh 2"})
    text += "subsection " + mesh + "\n  set stiffness source = table\n" +
            "  set stiffness table = " + table + "\nend\n";
  return text;
}

namespace
{
// The moment of inertia [kg·m²] of a steel blank of the gear's face width between bore and
// reference circle (a ring between its reference circle and its outer diameter): the inertia a
// user would start from. `name` is the gear's section in "Gear pair" ("Pinion", "Wheel").
double steel_blank_inertia(const kinematics::GearSpec& gear, const std::string& name,
                           const kinematics::GearPairGeometry& pair)
{
  constexpr double steel_density = 7850.; // kg/m³
  kinematics::TrainMember member;
  member.name = name;
  member.teeth = gear.internal ? -static_cast<int>(gear.teeth) : static_cast<int>(gear.teeth);
  member.module = pair.transverse_module;
  return dynamics::blank_inertia(member, {name, gear.face_width, gear.bore_diameter}, steel_density,
                                 "Gear pair/" + name + "/bore diameter")
      .moment_of_inertia;
}
} // namespace

void check_own_pair_dynamics_input(const StiffnessParameters& p,
                                   const kinematics::GearPairGeometry& pair)
{
  steel_blank_inertia(p.settings.scene.pair.pinion, "Pinion", pair);
  steel_blank_inertia(p.settings.scene.pair.wheel, "Wheel", pair);
}

namespace
{
// A whole `gearstiff dynamics` file for the own pair: two gears, one mesh, its stiffness given by
// `stiffness_lines` (a k(x) table or a Cai curve) whose mean is `mean_stiffness` [N/m], at the
// pinion torque `torque` [N·m]; `source` says where the stiffness came from (the header's lines).
std::string own_pair_train_input(const StiffnessParameters& p,
                                 const kinematics::GearPairGeometry& pair, double torque,
                                 double mean_stiffness, const std::string& source,
                                 const std::string& stiffness_lines)
{
  const kinematics::GearPairSpec& spec = p.settings.scene.pair;
  const double j1 = steel_blank_inertia(spec.pinion, "Pinion", pair);
  const double j2 = steel_blank_inertia(spec.wheel, "Wheel", pair);
  const double r_b1 = 0.5 * pair.pinion.base_diameter, r_b2 = 0.5 * pair.wheel.base_diameter;
  // The mesh's equivalent mass along the line of action and its resonance speed n_E1 (ISO
  // 6336-1 §6.3: the mesh frequency z1·n1/60 at the torsional mode's frequency √(k/m_e)/2π).
  const double equivalent_mass = j1 * j2 / (j1 * r_b2 * r_b2 + j2 * r_b1 * r_b1);
  const double natural = std::sqrt(mean_stiffness / equivalent_mass); // rad/s
  const unsigned int z1 = spec.pinion.teeth;
  const double resonance_rpm = 30. * natural / (M_PI * z1);
  // Subcritical (ISO 6336-1: N ≤ 0.85) and below the second harmonic's resonance at N = 0.5.
  constexpr double speed_ratio = 0.3;
  constexpr double damping_ratio = 0.05; // the Train meshes' default ζ
  const double damping = 2. * damping_ratio * std::sqrt(mean_stiffness * equivalent_mass);
  // The friction force reverses at the pitch point; its arm about each centre there is the
  // roll length r_b·tan α_wt.
  const double arm_1 = r_b1 * std::tan(pair.working_pressure_angle);
  const double arm_2 = r_b2 * std::tan(pair.working_pressure_angle);
  std::ostringstream out;
  out << "# This pair: z " << z1 << "/" << (spec.wheel.internal ? "-" : "") << spec.wheel.teeth
      << ", m_t " << format_number(pair.transverse_module / mm, 6) << " mm, a_w "
      << format_number(pair.centre_distance / mm, 6) << " mm, x "
      << format_number(spec.pinion.profile_shift, 4) << "/"
      << format_number(spec.wheel.profile_shift, 4) << ", eps_alpha "
      << format_number(pair.transverse_contact_ratio, 6) << ", T1 " << format_number(torque, 6)
      << " N·m: two gears, one mesh.\n"
      << source
      << "# Inertias: steel blanks (7850 kg/m³) between bore and reference circle; damping: "
         "zeta = 0.05 of the mean k; friction: the FE's mu, arms r_b·tan(alpha_wt).\n"
      << "# Input speed: " << speed_ratio
      << " x the resonance speed n_E1 = " << format_number(resonance_rpm, 6)
      << " rpm of this pair (ISO 6336-1, subcritical); set your running speed.\n"
      << "subsection Train\n  set number of gears = 2\n  set input speed = "
      << format_number(speed_ratio * resonance_rpm, 8)
      << "\n  set published reference = false\nend\n"
      << "subsection Gear 1\n  set inertia = " << format_number(j1, 8)
      << "\n  set torque = " << format_number(torque, 10) << "\nend\n"
      << "subsection Gear 2\n  set inertia = " << format_number(j2, 8)
      << "\n  set torque = balance\nend\n"
      << "subsection Mesh 1\n  set driver gear = 1\n  set driven gear = 2\n"
      << "  set driver teeth = " << z1
      << "\n  set driver base radius = " << format_number(r_b1 / mm, 10)
      << "\n  set driven base radius = " << format_number(r_b2 / mm, 10)
      << "\n  set contact ratio = " << format_number(pair.transverse_contact_ratio, 10)
      << "\n  set approach ratio = "
      << format_number((pair.pitch_point - pair.contact_start) / pair.transverse_base_pitch, 10)
      << "\n  set damping = " << format_number(damping, 8) << "\n  set friction coefficient = "
      << format_number(p.settings.contact.friction_coefficient, 8)
      << "\n  set driver friction arm = " << format_number(arm_1 / mm, 8)
      << "\n  set driven friction arm = " << format_number(arm_2 / mm, 8) << "\n"
      << stiffness_lines << "end\n";
  return out.str();
}
} // namespace

std::string own_pair_dynamics_input(const StiffnessParameters& p,
                                    const kinematics::GearPairGeometry& pair,
                                    const stiffness::StiffnessSweepResult& sweep)
{
  const kinematics::GearPairSpec& spec = p.settings.scene.pair;
  // The train runs at the torque its k(x) was solved at (a tip relief's k(x) depends on the
  // load: the dynamics must see the k of the torque it applies).
  const double torque = solved_torque(p, sweep);
  double sum = 0.;
  for (const auto& r : sweep.positions)
    sum += r.mesh_stiffness;
  const double mean_stiffness = sum / sweep.positions.size(); // N/m
  const std::string source =
      (spec.pinion.helix_angle != 0.
           ? "# Helical, beta " + format_number(std::abs(spec.pinion.helix_angle) / degree, 6) +
                 " deg (beta_b " + format_number(pair.base_helix_angle / degree, 6) +
                 " deg): k(x) acts along the transverse line of action (normal to the flank: "
                 "k/cos^2 beta_b); the axial force and the tilting moment are not in the "
                 "torsional model (dynamics/README.md, Helical meshes).\n"
           : "") +
      std::string(sweep.torques.size() > 1
                      ? "# k(x) and T1 are the first torque's of Stiffness/torques (te_sweep.csv "
                        "holds every torque's k per position).\n"
                      : "");
  return own_pair_train_input(p, pair, torque, mean_stiffness, source,
                              "  set stiffness source = table\n  set stiffness table = " +
                                  dynamics_stiffness_table(sweep) + "\n");
}

std::string own_pair_cai_input(const StiffnessParameters& p,
                               const kinematics::GearPairGeometry& pair,
                               const dynamics::CaiParameters& cai)
{
  const double mean_stiffness =
      dynamics::MeshStiffness::cai(cai, "cai").mean_stiffness(pair.transverse_contact_ratio);
  return own_pair_train_input(
      p, pair, p.settings.pinion_torque, mean_stiffness,
      "# Mesh stiffness: the Cai curve calibrated to this pair's FE pair stiffnesses (gearstiff "
      "cai).\n",
      "  set stiffness source = cai\n  set stiffness = " + format_number(cai.scale / 1e3, 10) +
          "\n  set cai shape = " + format_number(cai.shape[0], 10) + ", " +
          format_number(cai.shape[1], 10) + ", " + format_number(cai.shape[2], 10) + "\n");
}

std::string dynamics_cai_input(const dynamics::CaiParameters& cai)
{
  std::string text;
  for (const std::string mesh : {"Mesh 1", "Mesh 2"})
    text += "subsection " + mesh + "\n  set stiffness source = cai\n" +
            "  set stiffness = " + format_number(cai.scale / 1e3, 10) + "\n" +
            "  set cai shape = " + format_number(cai.shape[0], 10) + ", " +
            format_number(cai.shape[1], 10) + ", " + format_number(cai.shape[2], 10) + "\nend\n";
  return text;
}

std::vector<std::pair<double, double>>
pair_stiffness_samples(const stiffness::StiffnessSweepResult& sweep, double contact_ratio)
{
  std::vector<std::pair<double, double>> samples;
  for (const auto& r : sweep.positions)
    for (const auto& pair : r.pairs)
    {
      const double position = r.mesh_position + pair.pair;
      if (pair.load_share > 1e-6 && position >= 0. && position < contact_ratio)
        samples.emplace_back(position, pair.load_share * r.mesh_stiffness);
    }
  std::sort(samples.begin(), samples.end());
  return samples;
}
} // namespace gearstiff::app
