// Parameter-file form of the FE mesh-stiffness analysis (stiffness/mesh_stiffness.h), shared by the
// `stiffness`, `cai` and `run` commands: the gear pair (app/kinematics/kinematics_parameters.h),
// the scene (subsections "Gear pair scene" and "Mesh" of app/scenes/geometry_parameters.h, mm and
// degrees), the FE model ("Finite elements", "Linear solver", "Contact" of
// app/scenes/fe_contact_parameters.h) and the load case and sweep ("Stiffness"). Defaults: the
// split-path pair of docs/references.md §1 under its published load case (T1 = 49.4 N·m, μ = 0.01,
// pinion bore free to rotate, wheel bore fixed) on the default scene chosen by the
// accuracy-versus-cost study (docs/accuracy.md).
#pragma once

#include "app/scenes/geometry_parameters.h"
#include "app/scenes/tooth_modification_parameters.h"
#include "dynamics/cai_stiffness.h"
#include "kinematics/automatic_sizes.h"
#include "stiffness/mesh_stiffness.h"
#include "stiffness/mesh_stiffness_sweep.h"

#include <deal.II/base/parameter_handler.h>
#include <string>

namespace gearstiff::app
{
// What "Stiffness/mode" asks for: one position of the scene, or a sweep.
enum class StiffnessMode
{
  single,
  double_pair,
  roll_angle,
  sweep
};
// The parameter-file spelling: "single", "double", "roll angle", "sweep".
std::string mode_name(StiffnessMode mode);

// One modification set of `Stiffness/variants` (the micro-geometry of both gears).
struct StiffnessVariant
{
  std::string label; // as written, e.g. "tip relief = 10"
  geometry::GearModifications pinion, wheel;
};

// The settings a variant of Stiffness/variants is swept with: the base set's, with the
// variant's modifications.
stiffness::GearMeshStiffnessSettings with_variant(const stiffness::GearMeshStiffnessSettings& base,
                                                  const StiffnessVariant& variant);

struct StiffnessParameters
{
  stiffness::GearMeshStiffnessSettings settings; // SI, scene_file left empty
  StiffnessMode mode = StiffnessMode::single;
  stiffness::StiffnessSweepSpec sweep;
  bool write_vtu = false;
  // Compare with docs/references.md §1: asked for and the pair is the split-path pair
  // (kinematics::is_split_path_pair).
  bool published_reference = true;
  std::vector<kinematics::DerivedSize> derived_sizes; // the `auto` sizes of the gear pair
  // Values that run but look like a unit slip (a relief typed in mm where µm are due), one
  // sentence each naming the parameter; the report prints them beside the result.
  std::vector<std::string> input_notes;
  // `Stiffness/variants`: further modification sets, each swept like the base one.
  std::vector<StiffnessVariant> variants;
  // Mesh/layer extrapolation = richardson (3D): every position solved on the scene's layers L
  // and on 2L, the results extrapolated (stiffness/layer_extrapolation.h).
  bool layer_extrapolation = false;
  // s, mode sweep: the lower bound of the sweep's work on the ranks (checked against
  // limits::max_run_seconds, printed before the sweep starts)
  double estimated_seconds = 0.;
};

// Gear pair, scene, mesh, finite elements, linear solver, contact and "Stiffness".
void declare_stiffness_parameters(dealii::ParameterHandler& prm);
// The same with the defaults "Stiffness/mode = sweep" and "sweep positions = `positions`".
void declare_stiffness_sweep_parameters(dealii::ParameterHandler& prm, unsigned int positions);
// Parses and checks everything the analysis checks before it meshes (gear pair, scene
// extent, torque, sweep positions), so that bad input fails before any FE work.
StiffnessParameters parse_stiffness_parameters(dealii::ParameterHandler& prm);
// The stiffness and scene fields (stiffness::stiffness_parameter, geometry::scene_field) as the
// stiffness, cai and run commands declare them.
ParameterNames stiffness_parameter_names();
} // namespace gearstiff::app
