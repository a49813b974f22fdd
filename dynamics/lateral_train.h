// Planar lateral–torsional model of any gear train (issue 30): Lin & Parker's (1999) planar
// stage (lateral_model.h, docs/references.md §7) generalised to several stages and nested
// carriers. Every body (members joined rigidly, one per copy) has two translations and a
// rotation; a body riding on a carrier sits on a pin (radial and tangential springs); meshes join
// any two bodies along their lines of action (external and internal); bodies on the main axis sit
// on bearings (x, y) and may have a torsional support. Written at one instant of the train's
// rotation (the frozen geometry of Lin & Parker's carrier-fixed frame at Ω = 0, no gyroscopic
// terms): a nested carrier's planets keep the angles they have at that instant.
//
// Coordinates of body b (centre O_b, frame angle β_b, radius r_b): translations q1, q2 along
// e(β_b) and e(β_b + 90°) [m] (β = 0 on the main axis: x, y; a planet: β = its position angle on
// its carrier, so q1, q2 are Lin & Parker's radial ζ and tangential η) and u = r_b·θ_b [m].
//   mesh a–b, unit line of action n (a pushes b), signed arms m = ((C − O)×n)_z of the line
//   about the bodies' axes (C any point of the line):
//       δ = n·(d_a − d_b) + (m_a/r_a)·u_a − (m_b/r_b)·u_b                (compression positive)
//   pin of planet p (orbit radius R on carrier c), radial and tangential:
//       e(β_p)·d_c − q1_p,      e(β_p + 90°)·d_c + (R/r_c)·u_c − q2_p     (+ pin errors)
//   bearing: the body's x and y (global); torsional support: u_b (k_θ/r_b²).
// With one stage this is lateral_model.h's stage to round-off (lateral_train_of_stage).
#pragma once

#include "dynamics/lateral_model.h"

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace gearstiff::dynamics
{
struct LateralBody
{
  std::string name;                                 // e.g. "2#1" (member, copy)
  double mass = 0.;                                 // [kg]
  double moment_of_inertia = 0.;                    // [kg·m²] about its own axis
  double radius = 0.;                               // [m] u = radius·θ
  Eigen::Vector2d centre = Eigen::Vector2d::Zero(); // [m] axis at the frozen instant
  double frame_angle = 0.;          // [rad] β: translations along e(β), e(β+90°)
  bool central = true;              // on the main axis (mode classes)
  double bearing_stiffness = 0.;    // [N/m] to the housing, x and y
  double bearing_damping = 0.;      // [N·s/m]
  bool held = false;                // rotation held (no u DOF)
  double torsional_stiffness = 0.;  // [N·m/rad] support when not held
  double torsional_damping = 0.;    // [N·m·s/rad]
  int carrier = -1;                 // body carrying it on a pin (-1: none)
  double orbit_radius = 0.;         // [m] R, pin to the carrier's axis
  double pin_stiffness = 0.;        // [N/m] radial and tangential
  double pin_damping = 0.;          // [N·s/m]
  double pin_error_tangential = 0.; // [m] in the sense of β + 90°
  double pin_error_radial = 0.;     // [m] outwards
};

struct LateralMeshLine
{
  std::string name;
  unsigned int body_a = 0, body_b = 0;
  double direction = 0.;      // [rad] angle of the unit line of action n (a pushes b)
  double arm_a = 0.;          // [m] ((C − O_a)×n)_z
  double arm_b = 0.;          // [m] ((C − O_b)×n)_z
  double stiffness = 0.;      // [N/m] (mean)
  double damping = 0.;        // [N·s/m]
  unsigned int spec_mesh = 0; // Train mesh it is a copy of
};

struct LateralTrain
{
  std::vector<LateralBody> bodies;
  std::vector<LateralMeshLine> meshes;
};

// One gear of a mesh: its body, its own centre (it may sit off the body's axis, e.g. a ring
// rigid with a carrier around a planet's pin), base radius, internal or external.
struct LateralGear
{
  unsigned int body = 0;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero(); // [m]
  double base_radius = 0.;                          // [m] > 0
  bool internal = false;
};

// The line of action of gears a and b for pressure angle α [rad] and flank `side` (+1: Lin &
// Parker's — the sun mesh at ψ − α, the ring mesh at ψ + α; −1 the other flank), with the arms
// about the bodies' axes. External: n = s·R(−sα)·t, arms (s·r_a, −s·r_b); internal gear a:
// n = s·R(sα)·t, arms (s·r_a, s·r_b); t ⊥ the centre line a → b. Mesh a–b and b–a are the same.
LateralMeshLine mesh_line(const LateralTrain& train, const LateralGear& a, const LateralGear& b,
                          double pressure_angle, int side);

// A one-stage train of lateral_model.h's form: bodies carrier, ring, sun, planets (that DOF
// order), meshes sun–planet then ring–planet of each planet.
LateralTrain lateral_train_of_stage(const LateralStage& stage);

struct LateralTrainModes
{
  Eigen::VectorXd frequencies;          // [Hz] ascending, zero for rigid-body modes
  Eigen::MatrixXd shapes;               // full coordinates (held zero), mass normalised
  std::vector<LateralModeGroup> groups; // equal frequencies, classified by the central bodies
  // Kinetic energy share per mode and body (2b translation, 2b + 1 rotation); rows sum to 1.
  Eigen::MatrixXd kinetic_energy_share;
};

struct LateralTrainStatics
{
  Eigen::VectorXd displacement;   // [m] full coordinates
  std::vector<double> mesh_force; // [N] per mesh line (compression positive)
  Eigen::MatrixXd bearing_force;  // [N] per body (rows) x, y: the housing's force on it
  std::vector<double> pin_force;  // [N] per spring of group 2 (on the planet)
  double output_torque = 0.;      // [N·m] the load applied on the output
};

class LateralTrainModel
{
public:
  // InputError: non-positive masses, radii, stiffness of a mesh or pin ("Train/masses",
  // "Train/inertias", "Train/planet pin stiffness", ...); "Train/bearing stiffness" for a body
  // that translates freely (nothing holds it in x and y).
  explicit LateralTrainModel(LateralTrain train);

  unsigned int n_bodies() const { return data.bodies.size(); }
  unsigned int n_dofs() const { return 3 * n_bodies(); }
  static unsigned int dof(unsigned int body, unsigned int component)
  {
    return 3 * body + component;
  }
  const std::vector<unsigned int>& free_dofs() const { return free; }
  const LateralTrain& train() const { return data; }

  const Eigen::VectorXd& mass() const { return mass_diagonal; }
  const Eigen::MatrixXd& stiffness() const { return stiffness_matrix; }
  const Eigen::MatrixXd& damping() const { return damping_matrix; }
  const Eigen::VectorXd& pin_error_force() const { return error_force; }

  // Springs (group 0 bearing, 1 torsional support, 2 pin, 3 mesh; `planet` = body for 0–2, mesh
  // line for 3), as lateral_model.h's.
  using Spring = LateralModel::Spring;
  const std::vector<Spring>& springs() const { return spring_list; }
  unsigned int mesh_spring(unsigned int line) const { return mesh_spring_index[line]; }
  double deflection(const Spring& spring, const double* q) const;

  LateralTrainModes modes(double relative_tolerance = 1e-7) const;
  // Input torque [N·m] on body `input`'s rotation, the balancing load on `output`.
  LateralTrainStatics static_state(unsigned int input, unsigned int output,
                                   double input_torque) const;

private:
  void add_springs();
  void assemble();
  void static_forces(LateralTrainStatics& state) const;

  LateralTrain data;
  std::vector<unsigned int> free;
  std::vector<Spring> spring_list;
  std::vector<unsigned int> mesh_spring_index;
  Eigen::VectorXd mass_diagonal;
  Eigen::MatrixXd stiffness_matrix, damping_matrix;
  Eigen::VectorXd error_force;
};
} // namespace gearstiff::dynamics
