// The built-in case: the split-path spur gearbox of Reszuta & Drewniak 2015 (docs/references.md
// §1), one pinion (gear 1) driving two wheels (gears 2, 3) through meshes 1-2 and 1-3.
//
// Published dynamic parameters: J1 = 1.47e-4, J2 = J3 = 7.81e-3 kg·m²; r_b1/r_b2 = 24.7/67.0 mm;
// c_g = 100 N·s/m; μ = 0.01 with arms r_f1/r_f2 = 7.47/20.27 mm; T1 = 49.4 N·m at 1450 rpm;
// loads T2 = T3 = (T1/2)·(r_b2/r_b1); RK4 at 5 µs. Stiffness: the Cai curve scaled so that one
// pair's peak equals the ANSYS single-pair stiffness k'_j = 327.2e6 N/m. The second wheel sits
// θ = 180° from the first around the pinion, so mesh 1-3 runs frac(21·180°/360°) = 0.5 of a mesh
// period behind mesh 1-2. Geometry that the paper leaves implicit comes from kinematics
// (split_path_pair(): tips reduced so ε_α = 1.500): base pitch, contact ratio and the approach
// ratio ε_f that locates the pitch point for the friction sign.
#pragma once

#include "dynamics/torsional_model.h"
#include "kinematics/gear_pair.h"

namespace gearstiff::dynamics
{
struct SplitPathCase
{
  unsigned int pinion_teeth = 21;         // [-] z1
  unsigned int wheel_teeth = 57;          // [-] z2 = z3
  double input_torque = 49.4;             // [N·m] T1
  double input_speed_rpm = 1450.;         // [rpm] n1
  double pinion_inertia = 1.47e-4;        // [kg·m²] J1
  double wheel_inertia = 7.81e-3;         // [kg·m²] J2 = J3
  double pinion_base_radius = 24.7e-3;    // [m] r_b1 (dynamic table value)
  double wheel_base_radius = 67.0e-3;     // [m] r_b2 = r_b3
  double single_pair_stiffness = 327.2e6; // [N/m] k'_j (ANSYS), the Cai peak
  double mesh_damping = 100.;             // [N·s/m] c_g
  double friction_coefficient = kinematics::split_path_published::tooth_friction; // [-] μ
  double pinion_friction_arm = 7.47e-3;                                           // [m] r_f1
  double wheel_friction_arm = 20.27e-3;                                           // [m] r_f2 = r_f3
  double wheel_placement_angle = M_PI; // [rad] θ between the wheel centres
  double face_width = 24e-3;           // [m] b of the wheels (common face width)
  double base_pitch = 0.;              // [m] p_et, from kinematics
  double contact_ratio = 0.;           // [-] ε_α, from kinematics
  double approach_ratio = 0.;          // [-] ε_f, from kinematics
};

// The published case with the kinematic quantities filled in from kinematics::split_path_pair().
SplitPathCase split_path_case();

// The 3-DOF train of a SplitPathCase with the given stiffness source on both meshes; the mesh
// 1-2 starts at `initial_position` [base pitches], mesh 1-3 at that plus the placement phase.
GearTrain split_path_train(const SplitPathCase& data, const MeshStiffness& stiffness,
                           double initial_position = 0.);
} // namespace gearstiff::dynamics
