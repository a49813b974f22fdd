// The FE scene of a spur gear pair at one pinion position: a few teeth of each gear around the
// predicted contacts, their rim down to the bore (a sector with cut faces, or the full rim with
// the other teeth removed, as in the ANSYS model of Reszuta & Drewniak 2015), the wheel placed in
// mesh, contact points predicted along the line of action.
//
// Scene frame: pinion centre at the origin, wheel centre at (a_w, 0); the pinion drives counter-
// clockwise, so the line of action runs from T1 = r_b1·(cos α_wt, −sin α_wt) on the pinion base
// circle upwards through the pitch point to T2 on the wheel base circle, with direction
// u = (sin α_wt, cos α_wt). Loaded flanks: the +y side (side +1 of tooth_profile.h) of every
// pinion tooth and of every wheel tooth in its own frame. Positions along the line of action are
// distances ℓ from T1 (kinematics/gear_pair.h); the pinion roll angle is ℓ/r_b1.
//
// Tooth indices: pinion tooth j sits j angular pitches counter-clockwise of the reference tooth
// (j = 0, the pair at the chosen position); it meshes with wheel tooth −j. The pair j touches at
// ℓ_ref + j·p_bt.
#pragma once

#include "geometry/scene_common.h"
#include "geometry/tooth_profile.h"
#include "kinematics/gear_pair.h"

#include <string>

namespace gearstiff::geometry
{
enum class RimModel
{
  sector, // the rim of the modelled teeth only, cut radially through the outer gaps (ids 5, 6)
  full    // the whole rim and bore, teeth other than the modelled ones removed
};

struct GearPairSceneSpec
{
  kinematics::GearPairSpec pair = kinematics::split_path_pair();

  // Position: "single" (pitch point if it lies in the single-contact zone, else that zone's
  // middle), "double" (middle of the first double-contact zone; the second pair then sits in
  // the middle of the last one), or "roll angle" (pinion_roll_angle below).
  std::string position = "single";
  double pinion_roll_angle = 0.; // rad, ℓ_ref/r_b1 of the reference pair, within [A, E]

  unsigned int pinion_teeth_modelled = 5; // -, teeth of the pinion in the scene
  unsigned int wheel_teeth_modelled = 5;  // -, teeth of the wheel in the scene
  double pinion_bore_radius = 0.;         // m; 0: half of pair.pinion.bore_diameter
  double wheel_bore_radius = 0.;          // m; 0: half of pair.wheel.bore_diameter
  RimModel rim = RimModel::sector;
  bool both_flanks = false; // also mark the unloaded flanks as candidate contact surfaces

  // The load and material only set the Hertz estimate of the default contact size.
  double pinion_torque = 49.4;  // N·m, T1 (gear-data.md §1: 7.5 kW at 1450 rpm)
  double young_modulus = 210e9; // Pa, both gears (steel; not published)
  double poisson_ratio = 0.3;   // -, both gears

  SceneMeshSettings mesh;
  // Points per profile segment: dense enough that the spline through them follows the
  // involute to well below the contact size.
  ProfileResolution resolution = {4, 32, 160, 24, 12};
};

// Checks the spec (InputError naming the parameter; all before gmsh runs), builds the scene,
// meshes it into `file` and returns what the FE module needs. Cost: well under a second in 2D.
SceneInfo write_gear_pair_scene(const GearPairSceneSpec& spec, const std::string& file);

// Parses "sector" or "full" (InputError naming `parameter` otherwise).
RimModel parse_rim_model(const std::string& text, const std::string& parameter);
} // namespace gearstiff::geometry
