#include "dynamics/split_path_case.h"

#include "kinematics/gear_pair.h"

#include <cmath>

namespace gearstiff::dynamics
{
SplitPathCase split_path_case()
{
  SplitPathCase data;
  const kinematics::GearPairGeometry pair =
      kinematics::compute_gear_pair(kinematics::split_path_pair());
  data.base_pitch = pair.transverse_base_pitch;
  data.contact_ratio = pair.transverse_contact_ratio;
  data.approach_ratio = (pair.pitch_point - pair.contact_start) / pair.transverse_base_pitch;
  data.face_width = pair.common_face_width;
  return data;
}

GearTrain split_path_train(const SplitPathCase& data, const MeshStiffness& stiffness,
                           double initial_position)
{
  GearTrain train;
  const double load = -0.5 * data.input_torque * data.wheel_base_radius / data.pinion_base_radius;
  train.gears = {{"Gear 1", data.pinion_inertia, data.input_torque},
                 {"Gear 2", data.wheel_inertia, load},
                 {"Gear 3", data.wheel_inertia, load}};
  train.input_speed = data.input_speed_rpm * M_PI / 30.;
  const double phase = mesh_phase_from_placement(data.pinion_teeth, data.wheel_placement_angle);
  for (unsigned int wheel = 1; wheel <= 2; ++wheel)
  {
    Mesh mesh;
    mesh.name = "Mesh " + std::to_string(wheel);
    mesh.driver = 0;
    mesh.driven = wheel;
    mesh.driver_base_radius = data.pinion_base_radius;
    mesh.driven_base_radius = data.wheel_base_radius;
    mesh.driver_teeth = data.pinion_teeth;
    mesh.contact_ratio = data.contact_ratio;
    mesh.approach_ratio = data.approach_ratio;
    mesh.stiffness = stiffness;
    mesh.damping = data.mesh_damping;
    mesh.friction_coefficient = data.friction_coefficient;
    mesh.driver_friction_arm = data.pinion_friction_arm;
    mesh.driven_friction_arm = data.wheel_friction_arm;
    mesh.initial_position = initial_position + (wheel == 2 ? phase : 0.);
    train.meshes.push_back(mesh);
  }
  return train;
}
} // namespace gearstiff::dynamics
