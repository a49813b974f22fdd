// General gear-train kinematics, efficiency, statics and reduced inertia.
//
// A train is a set of members (gears, carriers, shafts), meshes between two gears whose axes are
// both fixed on a frame member (a carrier, or the housing for fixed-axis gears), rigid
// connections, fixed members and input speeds. Every mesh gives one Willis equation
//     z_a·(ω_a − ω_c) + z_b·(ω_b − ω_c) = 0        (signed z: internal gears negative),
// connections ω_a = ω_b, fixed members ω = 0, inputs ω = ω_in. The solver assembles them as one
// linear system and returns every member's speed; a train whose equations leave a member
// undetermined, or contradict each other, is rejected with the reason. Nothing in here knows a
// particular train: the bi-planetary train, planetary sets, split-path and cycloidal drives are
// all data (see builtin_trains below).
//
// Statics use the torque method (Kudryavtsev; Müller, "Epicyclic drive trains"): a mesh puts
// torques T_a, T_b = k·T_a and −(T_a + T_b) on its two gears and its frame, each about the
// member's own axis, with k = (z_b/z_a)·η^(±1): η when gear a drives in the frame's rotating
// reference, 1/η when it is driven. Every non-fixed rigid body is in torque equilibrium. The
// directions of relative power flow are found by iteration from the loss-free solution.
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace gearstiff::kinematics
{
// The housing: always present, never rotates, frame of all fixed-axis meshes.
inline const std::string housing_name = "housing";

struct TrainMember
{
  std::string name;
  int teeth = 0;                 // -, 0 for a carrier or shaft; negative: internal gear (ring)
  double module = 0.;            // m, transverse module of the toothing; 0 = not given (no forces)
  std::string carrier;           // member on which this member's axis rides; "" = the housing
  unsigned int copies = 1;       // -, identical copies equally spaced (planets)
  double moment_of_inertia = 0.; // kg·m², one copy about its own axis
  double mass = 0.;              // kg, one copy (counts when its axis moves)
  double profile_shift = 0.;     // -, x (ISO 21771; internal: the ring's own x, signed as there)
};

struct TrainMesh
{
  std::string gear_a;
  std::string gear_b;
  std::string frame = housing_name; // member holding both axes (carrier) or the housing
};

struct GearTrainSpec
{
  std::vector<TrainMember> members;
  std::vector<TrainMesh> meshes;
  std::vector<std::pair<std::string, std::string>> connections; // rigidly joined members
  std::vector<std::string> fixed;                               // members held still
  std::vector<std::pair<std::string, double>> inputs;           // member, speed in rad/s
  std::string output;                                           // member for ratio/statics
  // rad, α_n of every toothing: with profile shifts it sets the working centre distances
  // (working_centre_distance); the dynamics command's Train/pressure angle, else 20°.
  double pressure_angle = 20. * M_PI / 180.;
};

// m, the zero-backlash working centre distance of meshing gears a and b (ISO 21771: inv α_w =
// inv α + 2·tan α·(x_a + x_b)/(z_a + z_b), signed z serving internal pairs; a_w = a·cos α/cos
// α_w): exactly the reference distance m·|z_a + z_b|/2 when the shifts sum to zero. A planet's
// orbit radius and an FE table's pair (dynamics) are checked against it. InputError naming
// "Train/profile shifts" when the shifts leave no working pressure angle.
double working_centre_distance(const TrainMember& a, const TrainMember& b, double pressure_angle);

struct TrainSolution
{
  std::vector<std::string> names;   // members in spec order, then the housing
  std::vector<double> speeds;       // rad/s, absolute
  std::vector<double> orbit_radius; // m, distance of the axis from its carrier's axis (0: none)
  std::vector<unsigned int> mesh_copies; // -, per mesh: copies of its planet (1: fixed axes)
  unsigned int degrees_of_freedom = 0;   // -, of the train without its inputs
  double ratio = 0.;                     // -, ω_input / ω_output (first input)

  double speed(const std::string& member) const; // rad/s
  std::size_t index(const std::string& member) const;
};

// Checks the description (InputError naming "Train/<parameter>") and solves for all speeds.
// Cost: one dense LU of size (members + 1), microseconds.
TrainSolution solve_train_kinematics(const GearTrainSpec& spec);

// Pair efficiency relative to the frame (docs/references.md §2, Drewniak et al. 2016):
// η = 1 − 2.3·μ_z·(u ± 1)/(u·z_1) for the pinion z_1, external (+) or internal (−), which with
// signed tooth counts is the one expression 1 − 2.3·μ_z·|1/z_a + 1/z_b|.
double pair_efficiency(int teeth_a, int teeth_b, double tooth_friction);

// Efficiency of an epicyclic train from its base (carrier-fixed) ratio and efficiency when the
// sun drives and power flows sun → ring in the carrier frame: η = (1 − i_b·η_b)/(1 − i_b).
double epicyclic_efficiency(double base_ratio, double base_efficiency);

struct MeshTorques
{
  double on_a = 0.;             // N·m, torque of the mesh on gear a (all copies)
  double on_b = 0.;             // N·m, on gear b
  double on_frame = 0.;         // N·m, on the frame member
  double efficiency = 1.;       // -, pair efficiency used
  bool a_drives = true;         // gear a drives in the frame's reference
  double tangential_force = 0.; // N, per copy, at the pitch circle (0: no module given)
};

struct TrainStatics
{
  std::vector<MeshTorques> meshes;    // in spec order
  std::vector<double> applied_torque; // N·m per member: input, output load, reactions
  double input_torque = 0.;           // N·m, on the first input
  double output_torque = 0.;          // N·m, applied by the load on the output (sign!)
  double efficiency = 1.;             // -, −P_out / P_in
  unsigned int power_flow_iterations = 0;
  // Torque delivered to the output's rigid body, one entry per mesh touching it.
  std::vector<std::pair<std::size_t, double>> output_paths; // (mesh index, N·m)
  // Force on the axis of each planet body per copy (vector sum of its tooth forces, mates
  // central); (member name, N). Only where modules are given.
  std::vector<std::pair<std::string, double>> planet_axis_forces;
};

// Statics for input torque `input_torque` (N·m) on the first input and the load on the
// output, with pair efficiencies from `tooth_friction` μ_z (0: loss-free). Needs a train with
// one degree of freedom. Throws SolverFailure when the power-flow directions do not settle
// (a self-locking train).
TrainStatics solve_train_statics(const GearTrainSpec& spec, const TrainSolution& solution,
                                 double input_torque, double tooth_friction);

// The paper's route to the train efficiency: hold the output carrier, let the single fixed
// member turn as output, and take i_b and η_b of that base train; η = (1 − i_b·η_b)/(1 − i_b).
struct CarrierMethodEfficiency
{
  double base_ratio = 0.;      // -, i_b = (ω_in − ω_c)/(ω_fixed − ω_c)
  double base_efficiency = 0.; // -, η_b of the base train (torque method)
  double efficiency = 0.;      // -, η of the train
};
CarrierMethodEfficiency carrier_method_efficiency(const GearTrainSpec& spec, double tooth_friction);

// One body's share of the kinetic energy: J·(ω/ω_ref)² + m·(v/ω_ref)² per copy.
struct InertiaTerm
{
  std::string member;
  double moment_of_inertia = 0.; // kg·m²
  double mass = 0.;              // kg
  double speed_ratio = 0.;       // -, ω/ω_ref
  double velocity_ratio = 0.;    // m, v/ω_ref of its centre (root mean square over a turn)
  unsigned int copies = 1;
};
double reduced_moment_of_inertia(const std::vector<InertiaTerm>& terms); // kg·m²

// The terms of a solved train, reduced to `member`'s speed. Planet centre speeds add the
// carrier chain in quadrature, exact for ≥ 2 equally spaced copies per carrier (their cross
// terms cancel) and the mean over a revolution otherwise.
std::vector<InertiaTerm> inertia_terms(const GearTrainSpec& spec, const TrainSolution& solution,
                                       const std::string& member);

// The planetary J* of Milev et al. 2025 (docs/references.md §3) as printed, in units of ρ·π·h
// (radii normalised by the ring radius R_b = R_a + 2·R_c = 1): sun R_a, N planets R_c, carrier
// disc of thickness h/k. Term by term it is Σ J·(ω/ω_a)² + m·(v/ω_a)² with planet spin
// R_a/R_c, planet centre speed R_a·(R_a + R_c)/(2·R_c) and carrier (ω_h/ω_a)² = R_a²/(2·R_c²)
// — ratios that no single fixed member gives (see tests/kinematics/test_gear_train.cc).
double milev_planetary_inertia(double sun_radius, double planet_radius, unsigned int planets,
                               double carrier_thickness_ratio);

// Raw text of a train as written in a parameter file (subsection "Train"). Each string is a
// comma-separated list; see app/kinematics/kinematics_command.cc for the syntax shown to users.
struct GearTrainText
{
  std::string gears;          // "1: 21, 5: -69"              name: teeth (negative: internal)
  std::string modules;        // "1: 2, 5: 2"                 name: module in mm
  std::string carriers;       // "h, H"                       toothless members
  std::string planets;        // "2: h*3, 4: H*9"             name: carrier*copies
  std::string meshes;         // "1-2/h, 3-4/H, 10-11"        a-b/frame (default housing)
  std::string connections;    // "3=2, 5=h"
  std::string fixed;          // "7"
  std::string inputs;         // "1: 1470"                    name: speed in rpm
  std::string output;         // "h"
  std::string inertias;       // "1: 0.01"                    name: J in kg·m² (one copy)
  std::string masses;         // "2: 1.5"                     name: mass in kg (one copy)
  std::string profile_shifts; // "1: 0.2, 2: -0.2"          name: x (optional, default 0)
};
// Parses and checks the syntax (InputError naming "Train/<key>"); the structure is checked by
// solve_train_kinematics.
GearTrainSpec parse_gear_train(const GearTrainText& text);

// Built-in trains in the same text form: "bi-planetary" (docs/references.md §2, modules 2/2/4 mm
// inferred from the published forces and coaxiality), "planetary" (sun 20, 3 planets 10,
// ring 40, m 2 mm), "split-path" (§1), "cycloidal" (§4: z_s 19, z_k 20, eccentric input).
GearTrainText builtin_train(const std::string& name);
std::vector<std::string> builtin_train_names();
} // namespace gearstiff::kinematics
