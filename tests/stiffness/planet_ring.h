// The internal (ring-planet) pair of the stiffness tests, planet z = 24 in ring z = 69 (the inner
// set of the bi-planetary train, docs/references.md §2): module 2.5 mm, 20°, no profile shift (the
// paper's modules and shifts of §2 are not in the reference data: stated defaults), face widths
// 26/24 mm and planet bore 20 mm as the split-path pair, the ring tip at an addendum of 0.5·m_n
// (d_a2 = 170 mm): a standard ring tip interferes with the planet's fillet
// (tests/kinematics/test_gear_pair.cc, InternalPair). The ring's rim under its root circle
// (d_f2 = 178.75 mm) is a parameter.
#pragma once

#include "kinematics/gear_pair.h"
#include "stiffness/mesh_stiffness.h"
#include "tests/stiffness/work_file.h"

#include <filesystem>
#include <string>

inline gearstiff::kinematics::GearPairSpec planet_ring_pair()
{
  constexpr double mm = 1e-3;
  gearstiff::kinematics::GearPairSpec spec = gearstiff::kinematics::split_path_pair();
  spec.pinion.teeth = 24;
  spec.wheel.teeth = 69;
  spec.wheel.internal = true;
  spec.pinion.profile_shift = 0.;
  spec.wheel.profile_shift = 0.;
  spec.pinion.tip_diameter = 0.;                               // standard
  spec.wheel.tip_diameter = (69. * 2.5 - 2. * 2.5 * 0.5) * mm; // addendum 0.5·m_n
  spec.wheel.bore_diameter = 0.;                               // the rim thickness sets it
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
