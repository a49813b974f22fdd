// Planar lateral–torsional model of one planetary stage (Lin & Parker 1999, docs/references.md
// §7): sun, ring and carrier with two translations and a rotation each on their bearings, N
// planets on carrier pins with radial and tangential motion and a rotation, meshes along their
// lines of action. Optionally the rotating carrier frame's gyroscopic and centripetal terms
// (Cooley & Parker 2012/2014, §7).
//
// Coordinates, in the carrier-fixed frame (Lin & Parker's):
//   central member j ∈ {carrier, ring, sun}: x_j, y_j [m] and u_j = r_j·θ_j [m], r_j the base
//     radius for sun and ring, the pin-circle radius for the carrier;
//   planet n at angle ψ_n on the carrier: radial ζ_n, tangential η_n [m] and u_n = r_p·θ_n [m].
// Mass matrix diag(m, m, J/r²) per body. Deflections (compression positive), α_s, α_r the
// pressure angles, ψ_sn = ψ_n − α_s, ψ_rn = ψ_n + α_r:
//   sun–planet mesh   δ_sn = −x_s sin ψ_sn + y_s cos ψ_sn + u_s − ζ_n sin α_s − η_n cos α_s + u_n
//   ring–planet mesh  δ_rn = −x_r sin ψ_rn + y_r cos ψ_rn + u_r + ζ_n sin α_r − η_n cos α_r − u_n
//   pin, radial       x_c cos ψ_n + y_c sin ψ_n − ζ_n
//   pin, tangential   −x_c sin ψ_n + y_c cos ψ_n + u_c − η_n (+ the pin's position error)
//   bearings          x_j, y_j (stiffness k_j), torsional support u_j (k_θ/r_j²).
// Potential energy ½Σk·δ², so K = Σ k·v·vᵀ with v the coefficient vector of each δ; damping
// likewise with the same v. A member held in rotation (a fixed ring without torsional support)
// loses its u DOF. Equally spaced planets give Lin & Parker's three mode classes: rotational
// (multiplicity 1, central members only rotate), translational (2, central members only
// translate), planet (N − 3, central members still).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace gearstiff::dynamics
{
enum class LateralMember
{
  carrier = 0,
  ring = 1,
  sun = 2
};
std::string lateral_member_name(LateralMember member);

struct LateralCentralMember
{
  double mass = 0.;                // [kg]
  double moment_of_inertia = 0.;   // [kg·m²]
  double radius = 0.;              // [m] base radius (sun, ring), pin-circle radius (carrier)
  double bearing_stiffness = 0.;   // [N/m] in x and in y
  double bearing_damping = 0.;     // [N·s/m] in x and in y
  bool held = false;               // rotation held (no u DOF), e.g. a fixed ring
  double torsional_stiffness = 0.; // [N·m/rad] support to the housing when not held
  double torsional_damping = 0.;   // [N·m·s/rad]
};

struct LateralStage
{
  LateralCentralMember carrier, ring, sun;
  double planet_mass = 0.;              // [kg] one planet
  double planet_moment_of_inertia = 0.; // [kg·m²] one planet about its axis
  double planet_base_radius = 0.;       // [m]
  double pin_stiffness = 0.;            // [N/m] radial and tangential, each planet
  double pin_damping = 0.;              // [N·s/m]
  // [m] radius of the planet's tip circle, for the collision check of the planet angles (0:
  // the pitch radius r_p/cos α_s stands in)
  double planet_tip_radius = 0.;
  std::vector<double> planet_angles; // [rad] ψ_n, one per planet, counter-clockwise
  double sun_mesh_stiffness = 0.;    // [N/m] k_sp along the line of action (mean)
  double ring_mesh_stiffness = 0.;   // [N/m] k_rp
  double sun_mesh_damping = 0.;      // [N·s/m]
  double ring_mesh_damping = 0.;     // [N·s/m]
  double sun_pressure_angle = 0.;    // [rad] α_s
  double ring_pressure_angle = 0.;   // [rad] α_r
  // Carrier pin position errors [m] per planet (empty: none): tangential (in the sense of ψ)
  // and radial (outwards); a pin displaced by e pre-loads its spring by ±k·e.
  std::vector<double> pin_error_tangential, pin_error_radial;
};

// What each coordinate is.
enum class LateralDofType
{
  translation = 0, // x, y, ζ, η
  rotation = 1     // u
};

enum class LateralModeClass
{
  rotational,
  translational,
  planet,
  mixed // neither: unequal spacing or unequal planets couple the classes
};
std::string lateral_mode_class_name(LateralModeClass type);

struct LateralModeGroup
{
  LateralModeClass type = LateralModeClass::mixed;
  double frequency = 0.;           // [Hz] mean of the group
  std::vector<unsigned int> modes; // indices into LateralModes::frequencies
};

struct LateralModes
{
  Eigen::VectorXd frequencies;          // [Hz] ascending, zero for rigid-body modes
  Eigen::MatrixXd shapes;               // full coordinates (held DOFs zero), mass normalised
  std::vector<LateralModeGroup> groups; // modes of equal frequency, classified
  // Kinetic energy share per mode (rows) and body × DOF type (columns: body b's translation at
  // 2b, rotation at 2b + 1; bodies carrier, ring, sun, planet 1..N); rows sum to 1.
  Eigen::MatrixXd kinetic_energy_share;
  // Strain energy share per mode (rows) and spring group (columns: bearings, torsional
  // supports, pins, sun meshes, ring meshes); rows sum to 1 (0 for rigid modes).
  Eigen::MatrixXd strain_energy_share;
};

// Static solution under the stage's pin errors and the torques: input torque on `input`, the
// balancing load on `output` (when the stage has a rigid rotation; otherwise the supports take
// it), all forces in the carrier frame.
struct LateralStaticLoad
{
  LateralMember input = LateralMember::sun;
  LateralMember output = LateralMember::carrier;
  double input_torque = 0.; // [N·m] on the input, positive counter-clockwise
};

struct LateralStaticState
{
  Eigen::VectorXd displacement;             // [m] full coordinates
  std::vector<double> sun_mesh_force;       // [N] per planet (compression positive)
  std::vector<double> ring_mesh_force;      // [N] per planet
  std::vector<double> pin_radial_force;     // [N] per planet, on the planet (outwards)
  std::vector<double> pin_tangential_force; // [N] per planet, on the planet
  // Bearing force on each central member [N] (carrier, ring, sun; x, y), the housing's
  // reaction on the member.
  Eigen::Matrix<double, 3, 2> bearing_force;
  double output_torque = 0.; // [N·m] the load applied on the output
  // Load sharing factor per planet [-]: N·F_sn/ΣF_s (sun meshes) and N·F_rn/ΣF_r.
  std::vector<double> sun_load_sharing, ring_load_sharing;
};

// Stability of the undamped stage with the gyroscopic and centripetal terms at one carrier
// speed. Unstable when a real part of the eigenvalues λ of the first-order form exceeds 1e-5 of
// the largest |λ| at standstill (round-off: the rigid rotation's double zero root scatters by
// √round-off, 1e-3 Hz, tests/dynamics/test_lateral_model.cc); the roots of the rigid rotation
// itself are set aside (a drift of the free stage, not an instability).
struct GyroscopicStability
{
  bool stable = true;
  double growth_rate = 0.;  // largest Re λ [1/s] (0 when stable)
  bool oscillating = false; // that root is complex (flutter); else real (divergence)
};

class LateralModel
{
public:
  // InputError naming `parameter_prefix`-based Train parameters for bad data (masses,
  // stiffnesses, colliding planets, pin errors per planet).
  explicit LateralModel(const LateralStage& stage);

  unsigned int n_planets() const { return n_planet; }
  unsigned int n_dofs() const { return 9 + 3 * n_planet; } // full coordinates
  // Index of a central member's coordinate (0 x, 1 y, 2 u), of planet n's (0 ζ, 1 η, 2 u).
  static unsigned int central_dof(LateralMember member, unsigned int component)
  {
    return 3 * static_cast<unsigned int>(member) + component;
  }
  static unsigned int planet_dof(unsigned int planet, unsigned int component)
  {
    return 9 + 3 * planet + component;
  }
  std::string dof_name(unsigned int dof) const;
  // DOFs that move (held rotations removed), ascending.
  const std::vector<unsigned int>& free_dofs() const { return free; }

  // Full-coordinate matrices: M diagonal [kg], K [N/m], C [N·s/m]; G and K_Ω of the rotating
  // carrier frame per unit carrier speed: M q̈ + (C + Ω G) q̇ + (K − Ω² K_Ω) q = f
  // (Cooley & Parker 2012).
  const Eigen::VectorXd& mass() const { return mass_diagonal; }
  const Eigen::MatrixXd& stiffness() const { return stiffness_matrix; }
  const Eigen::MatrixXd& damping() const { return damping_matrix; }
  Eigen::MatrixXd gyroscopic() const;
  Eigen::MatrixXd centripetal() const;
  // Forces from the pin errors (−Σ k_p·e·v) [N], full coordinates.
  const Eigen::VectorXd& pin_error_force() const { return error_force; }

  // Undamped modes at Ω = 0 with classification. Degenerate frequencies are those within
  // `relative_tolerance` of each other (in ω²).
  LateralModes modes(double relative_tolerance = 1e-7) const;
  // Natural frequencies [Hz] with the gyroscopic and centripetal terms at carrier speed
  // `carrier_speed` [rad/s] (undamped, ascending, each complex pair once); a zero or imaginary
  // frequency (divergence) is returned as 0.
  std::vector<double> gyroscopic_frequencies(double carrier_speed) const;
  // Whether the undamped stage at carrier speed `carrier_speed` [rad/s] is stable: |Im λ| alone
  // reads a divergent or fluttering mode as a frequency (issue 42).
  GyroscopicStability gyroscopic_stability(double carrier_speed) const;

  // Static solution; SolverFailure when the stage moves freely (a free translation).
  LateralStaticState static_state(const LateralStaticLoad& load) const;

  // Deflections of planet n's sun mesh, ring mesh, radial and tangential pin [m] (pin errors
  // included) for full coordinates q.
  double sun_mesh_deflection(unsigned int planet, const double* q) const;
  double ring_mesh_deflection(unsigned int planet, const double* q) const;

  const LateralStage& stage() const { return data; }

  // The springs K = Σ k v vᵀ: coefficient vectors over full coordinates (sparse: ≤ 9 entries).
  struct Spring
  {
    unsigned int group = 0; // 0 bearing, 1 torsional support, 2 pin, 3 sun mesh, 4 ring mesh
    unsigned int planet = 0;
    double stiffness = 0.; // [N/m]
    double damping = 0.;   // [N·s/m]
    double preload = 0.;   // [m] added to the deflection (pin errors)
    std::vector<std::pair<unsigned int, double>> terms;
  };
  const std::vector<Spring>& springs() const { return spring_list; }
  static constexpr unsigned int n_spring_groups = 5;

private:
  double deflection(const Spring& spring, const double* q) const;
  void modal_energies(LateralModes& result) const;
  Eigen::VectorXd deflection_under(const Eigen::VectorXd& f,
                                   const std::vector<Eigen::VectorXd>& rigid) const;
  void static_forces(LateralStaticState& state) const;

  LateralStage data;
  unsigned int n_planet = 0;
  std::vector<unsigned int> free;
  std::vector<Spring> spring_list;
  Eigen::VectorXd mass_diagonal;
  Eigen::MatrixXd stiffness_matrix, damping_matrix;
  Eigen::VectorXd error_force;
  std::vector<unsigned int> sun_mesh_spring, ring_mesh_spring; // per planet: spring index
};

// K = Σ k·v·vᵀ and C = Σ c·v·vᵀ [N/m], [N·s/m] of `springs` over n coordinates, and the forces of
// their preloads −Σ k·e·v [N] (pin errors).
void assemble_springs(const std::vector<LateralModel::Spring>& springs, unsigned int n,
                      Eigen::MatrixXd& stiffness, Eigen::MatrixXd& damping,
                      Eigen::VectorXd& preload_force);

// Undamped modes of M·q̈ + K·q = 0 over the coordinates `free` (M diagonal [kg], K [N/m]):
// ascending frequencies [Hz] (eigenvalues below 1e-11 of the largest count as rigid: 0) and
// mass-normalised shapes in full coordinates; returns the largest eigenvalue of M^(-1/2)·K·M^(-1/2)
// [1/s²]. SolverFailure when the eigensolver fails.
double undamped_modes(const Eigen::VectorXd& mass, const Eigen::MatrixXd& stiffness,
                      const std::vector<unsigned int>& free, Eigen::VectorXd& frequencies,
                      Eigen::MatrixXd& shapes);

// Static deflection K·q = f over the coordinates `free` [m, N], orthogonal in M to the rigid
// motion `rigid` (full coordinates) when it is not null: [K M·v0; v0ᵀ·M 0]·[q; a] = [f; 0]. Full
// coordinates out. SolverFailure when the system is singular.
Eigen::VectorXd constrained_deflection(const Eigen::VectorXd& mass,
                                       const Eigen::MatrixXd& stiffness,
                                       const std::vector<unsigned int>& free,
                                       const Eigen::VectorXd& f, const Eigen::VectorXd* rigid);

// Groups of equal frequency (within `relative_tolerance` in ω²) and their class, judged on the
// whole group (a degenerate pair's basis is arbitrary, its subspace is not) by the kinetic
// energy of the `central` bodies (translation in column 2b, rotation in 2b + 1). `largest`: the
// largest eigenvalue of M^(-1/2)·K·M^(-1/2) [1/s²].
std::vector<LateralModeGroup> classify_mode_groups(const Eigen::VectorXd& frequencies,
                                                   const Eigen::MatrixXd& kinetic_energy_share,
                                                   const std::vector<unsigned int>& central,
                                                   double relative_tolerance, double largest);

// Equally spaced angles 2πn/N [rad].
std::vector<double> equally_spaced_angles(unsigned int planets);
} // namespace gearstiff::dynamics
