// The split-path pinion and one wheel (docs/references.md §1 dynamic parameters) as a train of one
// pair with constant mesh stiffness, shared by the model and integrator tests: gear 1 drives
// gear 2, whose load T1·r2/r1 balances the input torque T1.
#pragma once

#include "dynamics/torsional_model.h"

#include <cmath>

namespace gearstiff::test_support
{
// Inertias J [kg·m²], base radii r [m] and input torque T1 [N·m] of docs/references.md §1.
constexpr double J1 = 1.47e-4, J2 = 7.81e-3, r1 = 24.7e-3, r2 = 67.0e-3, T1 = 49.4;

inline dynamics::GearTrain single_pair_train(double stiffness, double damping)
{
  dynamics::GearTrain train;
  train.gears = {{"Gear 1", J1, T1}, {"Gear 2", J2, -T1 * r2 / r1}};
  dynamics::Mesh mesh;
  mesh.driver_base_radius = r1;
  mesh.driven_base_radius = r2;
  mesh.driver_teeth = 21;
  mesh.contact_ratio = 1.5;
  mesh.approach_ratio = 0.58;
  mesh.stiffness = dynamics::MeshStiffness::constant(stiffness, "Mesh 1/stiffness");
  mesh.damping = damping;
  train.meshes = {mesh};
  train.input_speed = 1450. * M_PI / 30.;
  return train;
}
} // namespace gearstiff::test_support
