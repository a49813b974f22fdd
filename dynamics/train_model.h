// The purely rotational lumped model of any gear train described for the kinematics module
// (kinematics::GearTrainSpec: members, meshes a-b/frame, connections, fixed members, planets with
// copies, one input, an output), after Lin & Parker (1999) generalised to nested carriers; the
// derivation and the mesh phasing (Parker & Lin 2004) are in dynamics/README.md.
//
//   * one rotation per rigid body (members joined by connections) and per copy of it: a planet
//     with N copies is N degrees of freedom; bodies holding a fixed member are not degrees of
//     freedom unless suspended on a torsional spring and damper (Suspension);
//   * angles are absolute, one sense of rotation for all, relative to the nominal rotation;
//   * a mesh a-b on frame c (a carrier, or the housing) deflects along its line of action in
//     the frame's rotating reference: δ = r_a·(φ_a − φ_c) + r_b·(φ_b − φ_c), with signed base
//     radii r = m·z·cos α/2 (z < 0 for an internal gear) — the Willis relation
//     z_a(ω_a − ω_c) + z_b(ω_b − ω_c) = 0 of gear_train.h read for small rotations. Lin &
//     Parker's purely rotational sun–planet and ring–planet deflections are the special cases
//     (their carrier term (r_s + r_p)·θ_c = R_c·cos α·θ_c).
//   * by virtual work the mesh force F puts −(∂δ/∂φ_i)·F on each rotation (and the friction
//     terms of torsional_model.h on the two gears, its reaction on the frame);
//   * the mass m of a planet copy orbiting at radius R adds m·R² to its carrier (per level of
//     the carrier chain), as in Lin & Parker's purely rotational carrier equation; so the
//     kinetic energy of the nominal rotation is ½·J*·ω_in² with kinematics' reduced inertia J*.
#pragma once

#include "dynamics/mesh_stiffness.h"
#include "dynamics/torsional_model.h"
#include "kinematics/gear_train.h"

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace gearstiff::dynamics
{
// What a mesh of the Train description needs beyond its tooth counts (one per Train mesh, in
// the order of Train/meshes; every copy of it gets the same values).
struct TrainMeshDynamics
{
  MeshStiffness stiffness;
  double damping = 0.;              // [N·s/m]
  double friction_coefficient = 0.; // [-]
  double driver_friction_arm = 0.;  // [m] of the gear that drives in the frame's reference
  double driven_friction_arm = 0.;  // [m]
  // Which gear drove when `stiffness` was computed (an FE result: 0 gear a, 1 gear b; empty:
  // none, e.g. a constant). Where the other gear drives in the train, the model uses
  // stiffness.reversed(ε_α): contact then runs along the path the other way.
  std::optional<unsigned int> stiffness_driver;
  // Path of contact of the FE pair (with its tips, e.g. a shortened ring tip) when the
  // stiffness came from a file: ε_α and ε_f (its pinion, `stiffness_driver`, driving). The
  // model then uses them instead of the standard-tooth values for the mesh cycle, the table's
  // reversal, friction and the sun/ring phasing, so k(x) and the phase share one origin (A).
  std::optional<double> contact_ratio;  // [-]
  std::optional<double> approach_ratio; // [-]
  // Nonlinear mesh law (nonlinear_mesh.h), the same for every copy; its TE and back-flank
  // stiffness are reversed with `stiffness` where the other gear drives.
  std::optional<NonlinearMesh> nonlinear;
  // [N] the tooth force the file's k(x) was solved at (Mesh::table_force); NaN: not a file
  double table_force = std::numeric_limits<double>::quiet_NaN();
};

struct TrainSuspension
{
  std::string member;    // a fixed member
  double stiffness = 0.; // [N·m/rad]
  double damping = 0.;   // [N·m·s/rad]
};

// A gear blank for its inertia when Train/inertias (masses) do not give it: a steel annulus
// of the face width between the bore and the reference diameter m·|z| (external gears), or
// between the reference diameter and the outer diameter (internal gears: `bore_diameter` is the
// rim's outside diameter then, and must be given).
struct GearBlank
{
  std::string member;
  double face_width = 0.;    // [m] b
  double bore_diameter = 0.; // [m] d_i (external; 0: solid), d_o (internal)
};

struct BlankInertia
{
  double moment_of_inertia = 0.; // [kg·m²] ρ·π·b·(d_o⁴ − d_i⁴)/32
  double mass = 0.;              // [kg] ρ·π·b·(d_o² − d_i²)/4
};
// InputError naming `parameter` for an internal gear without outer diameter, or a bore not
// inside the reference circle.
BlankInertia blank_inertia(const kinematics::TrainMember& gear, const GearBlank& blank,
                           double density, const std::string& parameter);

struct TrainDynamicsInput
{
  kinematics::GearTrainSpec spec; // inertias and masses per member copy inside
  double input_torque = 0.;       // [N·m] on the (single) input; the output takes the load
  double pressure_angle = 20. * M_PI / 180.; // [rad] standard teeth (x = 0, h_a* = 1)
  std::vector<TrainMeshDynamics> meshes;     // one per spec mesh
  std::vector<TrainSuspension> suspensions;
  // Members whose J (and mass) Train/inertias (masses) leave at 0 take them from their blank.
  std::vector<GearBlank> blanks;
  double density = 7850.;       // [kg/m³] of the blanks (steel)
  double initial_position = 0.; // [base pitches] added to every mesh phase
  // Names for error messages: the list parameters of the parameter file.
  std::string mesh_section = "Train mesh"; // + " n" for mesh n
};

// One Train mesh as the gear pair of ISO 6336-1:2006 method B (6.5): the pair vibrating alone
// in its frame's rotating reference. The reduced mass follows 6.5.9's rule for planetary
// gears, generalised: each gear contributes m* = J/r_b² of its rotation (the DOF's inertia:
// members rigid with it and planets' orbiting masses included) divided by the number of copies
// of the mesh it carries (a sun with p planets: m_S/p, so m_red = m_S·m_P/(m_S + p·m_P)); a
// gear that does not turn (a fixed ring) counts as infinitely heavy (m_red = m_P). The speed is
// gear a's relative to the frame (ISO's n1 in the carrier frame); the split path's rule — the
// driver's J shared among its meshes — is the same rule for a train on fixed axes.
struct TrainIsoPair
{
  unsigned int pinion_teeth = 0;  // [-] |z_a|
  double pinion_speed_ratio = 0.; // [-] |ω_a − ω_c|/ω_input
  double reduced_mass = 0.;       // [kg] m_red
  double pinion_base_radius = 0.; // [m] |r_b,a|
};

struct TrainModel
{
  GearTrain train;                              // general form, DOF 0 = the input
  std::vector<std::string> dof_names;           // "1", "2#3" (member, copy), ...
  std::vector<std::string> dof_body;            // representative member of each DOF's body
  std::vector<unsigned int> spec_mesh;          // per model mesh: index of its Train mesh
  std::vector<unsigned int> mesh_copy;          // per model mesh: copy number (0-based)
  std::vector<std::string> notes;               // assembly spacing, assumptions
  std::vector<double> spec_mesh_contact_ratio;  // [-] per Train mesh
  std::vector<double> spec_mesh_approach_ratio; // [-] per Train mesh (driver's side)
  double reduced_inertia = 0.;                  // [kg·m²] kinematics' J* reduced to the input
  std::vector<TrainIsoPair> spec_mesh_iso;      // per Train mesh
};

// Builds the model; InputError naming the Train parameter (or "<mesh_section> n/...") for
// trains the kinematics rejects, missing modules, zero inertia, copies that do not divide.
TrainModel build_train_model(const TrainDynamicsInput& input);

// Transverse contact ratio and approach ratio ε_f (start of active contact to the pitch point,
// in base pitches) of gears a and b (signed tooth counts, negative: internal; module; profile
// shifts x) with standard addenda (h_a* = 1, tips d + 2m(1 + x), signed d) at their
// zero-backlash working centre distance (kinematics::working_centre_distance); `driver` is 0
// for a, 1 for b. With x = 0 the standard pair at its reference centre distance.
struct StandardMesh
{
  double contact_ratio = 0.;
  double approach_ratio = 0.;
};
StandardMesh standard_mesh(const kinematics::TrainMember& a, const kinematics::TrainMember& b,
                           double pressure_angle, unsigned int driver);

// Share of each group's kinetic energy in every mode [-]: rows = modes of model.mode_shapes(),
// columns = groups; group_of_dof[i] is the group of DOF i.
Eigen::MatrixXd modal_energy_distribution(const TorsionalModel& model,
                                          const std::vector<unsigned int>& group_of_dof,
                                          unsigned int n_groups);
} // namespace gearstiff::dynamics
