// Parameter-file form of the geometry module's inputs, shared by the commands that build them:
// the cycloid disc (subsection "Cycloid disc": `cycloid`, `mesh`), the mesh sizes of a scene
// ("Mesh") and the gear-pair scene ("Gear pair scene"; both `mesh`, `stiffness`, `cai`, `run`).
// Lengths in mm; parse_* convert to SI.
#pragma once

#include "app/core/field_names.h"
#include "errors/errors.h"
#include "geometry/cycloid_disc.h"
#include "geometry/scene_gear_pair.h"
#include "kinematics/automatic_sizes.h"

#include <deal.II/base/parameter_handler.h>
#include <map>
#include <string>
#include <vector>

namespace gearstiff::app
{
// Subsection "Cycloid disc": z_k, r, e, q of docs/references.md §4 (Chmurawa & Łokiec) by default.
void declare_cycloid_disc_parameters(dealii::ParameterHandler& prm);
geometry::CycloidDiscSpec parse_cycloid_disc_parameters(dealii::ParameterHandler& prm);

// Subsection "Mesh" (dimension, layers, sizes) with `defaults` as default values. With
// `sizes_follow_module` (gear-pair scenes) the four sizes default to `auto`: `defaults` for the
// built-in pair's module (2.5 mm), scaled by m_n / 2.5 mm for any other gear, so that a module-10
// gear is not meshed at 0.7 mm nor a module-0.5 gear at a cell larger than its tooth.
void declare_scene_mesh_parameters(dealii::ParameterHandler& prm,
                                   const geometry::SceneMeshSettings& defaults,
                                   bool sizes_follow_module = false);
// `auto` sizes take `defaults` × `module_scale`; each one that differs from `defaults` is listed
// in `derived` (when given) for the report.
geometry::SceneMeshSettings parse_scene_mesh_parameters(
    dealii::ParameterHandler& prm, const geometry::SceneMeshSettings& defaults = {},
    double module_scale = 1., std::vector<kinematics::DerivedSize>* derived = nullptr);
// The `auto` mesh settings of a gear-pair scene: `spur` for a spur pair, for a helical pair
// geometry::helical_mesh_defaults (more layers, coarser bodies).
geometry::SceneMeshSettings gear_pair_mesh_defaults(const geometry::SceneMeshSettings& spur,
                                                    const kinematics::GearPairSpec& pair);
// m_n / 2.5 mm, exactly 1 for the teeth of the built-in pair (its results stay bit-identical).
double mesh_module_scale(const kinematics::GearPairSpec& pair);

// Subsection "Gear pair scene": teeth modelled, bores and rim, `defaults` as default values.
// The position and the load and material of the Hertz size estimate are not declared here: the
// analysis that meshes the scene supplies them; the sizes are in "Mesh" (above).
// `sector_cuts_free`: the analysis leaves the sector cut faces free, and the rim's documentation
// says so (the `mesh` command only names them).
void declare_gear_scene_parameters(dealii::ParameterHandler& prm,
                                   const geometry::GearPairSceneSpec& defaults,
                                   bool sector_cuts_free);
// Fills pinion/wheel_teeth_modelled (`auto`: spec's count kept, following the pairs),
// pinion/wheel_bore_radius and rim.
void parse_gear_scene_parameters(dealii::ParameterHandler& prm, geometry::GearPairSceneSpec& spec);

// "Young's modulus" [GPa] and "Poisson's ratio" [-] of `bodies` ("both gears") in the current
// subsection; steel by default (docs/references.md publishes neither). parse_ returns them in SI
// (E in Pa, ν).
void declare_elastic_constants(dealii::ParameterHandler& prm, const std::string& bodies);
void parse_elastic_constants(dealii::ParameterHandler& prm, double& young_modulus,
                             double& poisson_ratio);

// The gear-pair scene's fields (geometry::scene_field) as the `mesh` command declares them
// ("Gear pair scene/..."): mapped at the call (app/core/field_names.h), since `stiffness` names
// them otherwise.
ParameterNames gear_scene_parameter_names();
} // namespace gearstiff::app
