// The internal (ring-planet) pair of the stiffness tests (tests/kinematics/planet_ring_pair.h),
// face widths 26/24 mm and planet bore 20 mm as the split-path pair. The ring's rim under its root
// circle (d_f2 = 178.75 mm) is a parameter.
#pragma once

#include "kinematics/gear_pair.h"
#include "stiffness/mesh_stiffness.h"
#include "tests/kinematics/planet_ring_pair.h"
#include "tests/stiffness/work_file.h"

#include <filesystem>
#include <string>

inline gearstiff::kinematics::GearPairSpec planet_ring_pair()
{
  gearstiff::kinematics::GearPairSpec spec = gearstiff::kinematics::split_path_pair();
  gearstiff::test_support::make_planet_ring(spec);
  return spec;
}

// The planet as the torque-driven pinion, the ring held fixed on the outer circle of a rim of
// `rim_modules`·m_n, without friction; the scene goes to the work file stem `work_name`.
inline gearstiff::stiffness::GearMeshStiffnessSettings
planet_ring_settings(double rim_modules, const std::string& work_name)
{
  constexpr double mm = 1e-3;
  gearstiff::stiffness::GearMeshStiffnessSettings settings;
  settings.scene.pair = planet_ring_pair();
  settings.scene.wheel_rim_thickness = rim_modules * 2.5 * mm;
  settings.contact.friction_coefficient = 0.;
  settings.scene_file = stiffness_work_stem(work_name) + ".msh";
  return settings;
}

// Runs the analysis and removes its scene file.
template <int dim>
gearstiff::stiffness::GearMeshStiffnessResult
run_and_remove_scene(const gearstiff::stiffness::GearMeshStiffnessSettings& settings)
{
  gearstiff::stiffness::GearMeshStiffness<dim> analysis(MPI_COMM_SELF, settings);
  const gearstiff::stiffness::GearMeshStiffnessResult result = analysis.run();
  std::filesystem::remove(settings.scene_file);
  return result;
}
