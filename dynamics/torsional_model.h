// Lumped-parameter torsional model of a gear train: one rotational degree of freedom per gear,
// gears coupled by meshes with time-varying stiffness, damping and tooth friction.
//
// Implementation of the 3-DOF equations of Reszuta & Drewniak 2015 (docs/references.md §1),
// generalised to any tree-shaped train. Every gear's angle φ_i is measured in its own running
// direction and relative to the nominal rigid rotation (φ_i = 0, φ̇_i = 0 is "turning at the
// nominal speed, teeth unloaded"); the parametric excitation runs on nominal time, as in the
// paper's K(t). For a mesh m from driver a to driven gear b:
//
//   deflection along the line of action   δ_m = r_a·φ_a − r_b·φ_b             (paper: δ_1i)
//   mesh force                             F_m = k_m(t)·δ_m + c_m·δ̇_m          (paper: F_1i)
//   friction direction                     σ_m(t) ∈ [−1, 1] (mesh_stiffness.h): −1 while the
//                                          pair is before the pitch point, +1 after it
//   torque on the driver                   −(r_a + μ·σ_m·r_fa)·F_m
//   torque on the driven gear              +(r_b + μ·σ_m·r_fb)·F_m
//
// so   J_i·φ̈_i = T_i − Σ_m g_mi·F_m   with g_m = (r_a + μσ r_fa)·e_a − (r_b + μσ r_fb)·e_b.
// For the split path (pinion 1, wheels 2, 3) this is the paper's
//   J1·φ̈1 = T1 − r_b1·(F_12 + F_13) ∓ μ·r_f1·(F_12 + F_13),  Ji·φ̈i = −Ti + r_bi·F_1i ± μ·r_fi·F_1i
// with the upper signs after the pitch point (recess): there the driving pinion's flank slides
// faster than the wheel's, so friction brakes the pinion and drags the wheel; before the pitch
// point (approach) both signs flip. The paper writes one sign per mesh; here each pair in
// contact carries its own sign, weighted by its share of the mesh force, so in double contact
// the two pairs' friction partly cancels. With one pair in contact both readings coincide.
// Load torques are negative external torques (T_i here = −T_i of the paper for i = 2, 3).
#pragma once

#include "dynamics/mesh_stiffness.h"
#include "dynamics/nonlinear_mesh.h"

#include <Eigen/Dense>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace gearstiff::dynamics
{
struct Gear
{
  std::string name;
  double inertia = 0.; // [kg·m²] mass moment of inertia about its axis
  double torque = 0.;  // [N·m] external torque, positive in the running direction (input),
                       //        negative for a load
};

// One rotation's share in a mesh of the general form (planetary meshes, see the note on
// GearTrain): it adds coefficient·φ to the deflection along the line of action, and the mesh
// puts −(coefficient + μ·σ·friction_arm)·F on this degree of freedom.
struct MeshTerm
{
  unsigned int dof = 0;
  double coefficient = 0.;  // [m] signed base radius (the carrier: minus the sum of the gears')
  double friction_arm = 0.; // [m] signed friction arm (the carrier: minus the gears' sum)
};

struct Mesh
{
  std::string name;
  unsigned int driver = 0;        // index of the driving gear
  unsigned int driven = 1;        // index of the driven gear
  double driver_base_radius = 0.; // [m]
  double driven_base_radius = 0.; // [m]
  // [-] teeth of the driver: the mesh position advances z pitches per driver revolution, so
  // the mesh frequency is z·n exactly, whatever rounding the base radii carry.
  unsigned int driver_teeth = 0;
  double contact_ratio = 0.;  // [-] transverse contact ratio ε_α
  double approach_ratio = 0.; // [-] ε_f: start of active contact to pitch point / p_et
  MeshStiffness stiffness;
  double damping = 0.;              // [N·s/m] along the line of action
  double friction_coefficient = 0.; // [-] tooth friction μ
  double driver_friction_arm = 0.;  // [m] r_f of the driver
  double driven_friction_arm = 0.;  // [m] r_f of the driven gear
  double initial_position = 0.;     // [base pitches] mesh position at t = 0 (holds the phase)
  // [N] the tooth force an FE table's k(x) was solved at (StiffnessFilePair::tooth_force); NaN
  // when the stiffness is not such a table. Only reported beside the nominal force.
  double table_force = std::numeric_limits<double>::quiet_NaN();
  // General form (planetary trains): when not empty these terms replace driver/driven, base
  // radii and friction arms, and the mesh position advances position_ratio·(input speed)
  // [base pitches per second per rad/s]: z_a·|ω_a − ω_frame|/(2π·ω_input).
  std::vector<MeshTerm> terms;
  double position_ratio = 0.;
  // Nonlinear mesh law (nonlinear_mesh.h: TE excitation, backlash, separation, back flank);
  // empty: the linear law F = k·δ + c·δ̇.
  std::optional<NonlinearMesh> nonlinear;
};

// A member that the kinematics holds still but that hangs on a torsional spring and damper to
// the housing (the bi-planetary paper's variant II: a flexibly suspended ring).
struct Suspension
{
  unsigned int dof = 0;
  double stiffness = 0.; // [N·m/rad]
  double damping = 0.;   // [N·m·s/rad]
};

// Two forms. Tree form (the split path): meshes join two gears each, angles φ_i in each gear's
// running direction, speeds follow from the base radii, n − 1 meshes for n gears. General form
// (any train from kinematics::GearTrainSpec, see train_model.h): `speed_ratios` is not empty,
// angles are absolute (one sense of rotation for all), meshes carry `terms` and may close
// loops; a static solution exists through the mesh stiffness (statically indeterminate).
struct GearTrain
{
  std::vector<Gear> gears;
  std::vector<Mesh> meshes;
  double input_speed = 0.; // [rad/s] nominal speed of gear 0
  // General form: nominal speed of each degree of freedom per unit input speed [-].
  std::vector<double> speed_ratios;
  std::vector<Suspension> suspensions;
};

// Phase of a mesh relative to another mesh of the same driver [base pitches, in [0, 1)], from
// where the driven wheel sits: θ [rad] is the angle between the two wheel centres seen from
// the driver's axis, measured against the driver's rotation, z the driver's tooth count.
// docs/references.md §1: phase = frac(z1·θ/2π); the built-in case θ = π, z1 = 21 gives 0.5.
double mesh_phase_from_placement(unsigned int driver_teeth, double placement_angle);

// What one mesh carries at one instant.
struct MeshResponse
{
  double position = 0.;           // [base pitches] mesh position (not reduced modulo 1)
  double stiffness = 0.;          // [N/m]
  double friction_direction = 0.; // [-]
  double deflection = 0.;         // [m] δ along the line of action
  double deflection_rate = 0.;    // [m/s]
  double force = 0.;              // [N] F = k·δ + c·δ̇ (nonlinear: nonlinear_mesh.h)
  double transmission_error = 0.; // [m] unloaded TE e (0 for a linear mesh)
  ContactRegime regime = ContactRegime::drive;
};

// The static state under mean mesh stiffness: the train turning at nominal speed, carrying its
// torques, no vibration.
struct StaticState
{
  std::vector<double> angle;      // [rad] per gear, rigid-mode component removed
  std::vector<double> mesh_force; // [N] per mesh
  std::vector<double> deflection; // [m] per mesh
  double rigid_acceleration = 0.; // [rad/s²] of gear 0 when the torques do not balance
};

struct ModalProperties
{
  std::vector<double> natural_frequencies; // [Hz] undamped, rigid mode excluded, ascending
  std::vector<double> decay_rates;         // [1/s] −Re λ of the damped modes, ascending
};

// Undamped modes at mean stiffness without friction (K symmetric): K·v = ω²·M·v, v mass
// normalised (vᵀ·M·v = 1), ascending, the rigid mode (ω ≈ 0) included when the train has one.
struct ModeShapes
{
  Eigen::VectorXd frequencies; // [Hz]
  Eigen::MatrixXd shapes;      // [rad/sqrt(kg·m²)] one column per mode
};

class TorsionalModel
{
public:
  // Validates the train (InputError naming its gears' and meshes' fields, "gear2.inertia",
  // "mesh1.damping": dynamics/fields.h).
  explicit TorsionalModel(const GearTrain& train);

  unsigned int n_dofs() const { return n_gears; }
  unsigned int n_meshes() const { return meshes.size(); }
  const GearTrain& train() const { return description; }

  // [rad/s] nominal speed of each gear (running direction positive).
  const std::vector<double>& nominal_speeds() const { return speeds; }
  // [base pitches / s] rate at which mesh m's position advances; [Hz] its mesh frequency.
  double mesh_position_rate(unsigned int m) const { return meshes[m].position_rate; }

  // The equations of motion: accelerations [rad/s²] from angles [rad] and speeds [rad/s].
  // The hot path of the explicit integrators: no allocation.
  void acceleration(double time, const double* angle, const double* velocity,
                    double* acceleration) const;
  MeshResponse mesh_response(unsigned int m, double time, const double* angle,
                             const double* velocity) const;

  // M·φ̈ + C(t)·φ̇ + K(t)·φ = f (the model is linear in the state at a given time), for the
  // implicit integrator and the modal analysis. K and C are not symmetric when μ > 0.
  void linearization(double time, Eigen::MatrixXd& stiffness, Eigen::MatrixXd& damping) const;
  const Eigen::VectorXd& external_torques() const { return torques; }
  const Eigen::VectorXd& inertias() const { return inertia; }

  // Nominal mesh force [N]: the static force from the torques alone, friction excluded
  // (docs/references.md §1: F_cn = 0.5·T1/(r1·cos α_t) = T1/(2·r_b1) for the split path).
  double nominal_force(unsigned int m) const { return nominal_forces[m]; }
  // Static deflection under mean stiffness (and mean friction direction).
  StaticState static_state(bool include_friction = true) const;

  // Undamped natural frequencies and decay rates with every mesh at its mean stiffness.
  ModalProperties modal_properties() const;
  ModeShapes mode_shapes() const;
  // Stiffness matrix at mean mesh stiffness without friction [N·m/rad].
  Eigen::MatrixXd mean_stiffness_matrix() const;
  bool general_form() const { return general; }
  // Highest undamped natural frequency [rad/s] with every mesh at its largest stiffness.
  double highest_natural_frequency() const;
  // Largest stable classical RK4 step [s]: the largest h for which h·λ stays inside the RK4
  // stability region |1 + z + z²/2 + z³/6 + z⁴/24| ≤ 1 for every eigenvalue λ of the
  // first-order system frozen at the largest mesh stiffness (friction direction +1).
  double rk4_step_limit() const;

  // Vibration energy [J]: kinetic energy of the motion relative to the rigid mode plus the
  // strain energy of the meshes. Non-negative; used to detect divergence.
  double vibration_energy(double time, const double* angle, const double* velocity) const;
  // Total mechanical energy minus the work potential of the (constant) external torques [J]:
  // conserved when there is no damping, no friction and constant stiffness.
  double total_energy(double time, const double* angle, const double* velocity) const;
  // Strain energy of the meshes and suspensions [J].
  double strain_energy(double time, const double* angle) const;
  // Rigid-mode vector: gear angles of a rigid rotation with gear 0 turning by 1 rad.
  const Eigen::VectorXd& rigid_mode() const { return rigid; }

  // Nonlinear meshes (nonlinear_mesh.h). Their switch functions: the flank approach z = δ − e
  // [m] and its rate [m/s] per mesh (linear meshes: untouched), and the free play 2b [m]; the
  // integrator locates where z crosses 0 and −2b.
  bool has_nonlinear_meshes() const { return any_nonlinear; }
  bool is_nonlinear(unsigned int m) const { return meshes[m].nonlinear; }
  double free_play(unsigned int m) const { return meshes[m].backlash; }
  void flank_approach(double time, const double* angle, const double* velocity, double* approach,
                      double* approach_rate) const;
  // [mesh orders] highest harmonic of the TE excitation over the meshes.
  double highest_excitation_order() const;

private:
  struct CompiledMesh
  {
    // δ = Σ c[i]·φ[dof[i]]; torque on dof[i]: −(c[i] + μσ·arm[i])·F. Two terms for a pair,
    // three with a moving frame (carrier).
    unsigned int n_terms = 0;
    unsigned int dof[3] = {0, 0, 0};
    double c[3] = {0., 0., 0.};
    double arm[3] = {0., 0., 0.};
    double damping, mu;
    double contact_ratio, approach_ratio;
    double position_rate, initial_position;
    MeshStiffness stiffness;
    bool nonlinear = false;
    double backlash = 0.; // [m] 2b
    TransmissionError transmission_error;
    MeshStiffness back_stiffness;
    double mean_transmission_error = 0.; // [m]
  };
  // e [m], ė [m/s] and k_back [N/m] of a nonlinear mesh at one instant.
  struct NonlinearState
  {
    double error = 0., error_rate = 0., back_stiffness = 0.;
  };
  void update_cache(double time) const;
  double largest_stiffness(const CompiledMesh& mesh) const;
  MeshStiffnessState mesh_state(const CompiledMesh& mesh, double time) const;
  void assemble(const std::vector<double>& k, const std::vector<double>& sigma, Eigen::MatrixXd& K,
                Eigen::MatrixXd& C) const;
  std::vector<double> solve_static(const std::vector<double>& sigma, double& rigid_acceleration,
                                   std::vector<double>& angle_out) const;
  double rk4_limit_for(const Eigen::MatrixXd& K, const Eigen::MatrixXd& C) const;
  // K and C with every mesh at its largest stiffness and in contact (the stiffest instant: the
  // highest frequency and the tightest explicit step).
  void assemble_at_largest_stiffness(Eigen::MatrixXd& K, Eigen::MatrixXd& C) const;
  // The first-order system matrix [[0, I], [−M⁻¹K, −M⁻¹C]] of the gears' angles and speeds.
  Eigen::MatrixXd state_matrix(const Eigen::MatrixXd& K, const Eigen::MatrixXd& C) const;
  double deflection(const CompiledMesh& mesh, const double* angle) const;
  std::vector<double> solve_static_general(const std::vector<double>& sigma,
                                           double& rigid_acceleration,
                                           std::vector<double>& angle_out) const;
  void compile_meshes(const GearTrain& train);
  void validate_mesh(const GearTrain& train, unsigned int m) const;

  GearTrain description;
  unsigned int n_gears = 0;
  std::vector<CompiledMesh> meshes;
  std::vector<double> speeds;
  std::vector<double> inverse_inertia;
  Eigen::VectorXd inertia;
  Eigen::VectorXd torques;
  Eigen::VectorXd rigid;
  std::vector<double> nominal_forces;
  std::vector<Suspension> suspensions;
  bool general = false;
  bool any_nonlinear = false;
  // Mesh states at cached_time (acceleration() only; a model is used by one thread at a time).
  mutable double cached_time = std::numeric_limits<double>::quiet_NaN();
  mutable std::vector<MeshStiffnessState> cached_states;
  mutable std::vector<NonlinearState> cached_nonlinear;
};
} // namespace gearstiff::dynamics
