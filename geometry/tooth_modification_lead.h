// Lead modifications of a gear (ISO 21771, docs/references.md §8; 3D scenes only): material
// removed normal to the flank as a function of the face-width coordinate z ∈ [0, b] (the scene is
// extruded along +z from z = 0, geometry/mesh_planar.h), the same on every tooth of the gear:
//  - lead crowning C_β: δ = C_β·(2z/b − 1)², 0 in the middle of the face, C_β at both ends;
//  - lead slope f_Hβ: δ = f_Hβ·z/b for f_Hβ > 0 (removed at the z = b end), |f_Hβ|·(b − z)/b for
//    f_Hβ < 0 (removed at z = 0): material is only ever removed;
//  - end relief C_I over the length L_I from each end: δ = C_I·(1 − d/L_I) for d < L_I, d the
//    distance from the nearer end (linear, the same at both ends: C_I = C_II).
//
// How the mesh carries it: the 2D outline is meshed and extruded in layers (every layer the
// same transverse mesh); then every node of a gear body is turned about the gear axis by
//
//     φ = (−w₊·δ₊(z) + w₋·δ₋(z)) / r_b,
//
// δ± the removal of the tooth's side ±1 flank at the node's z, w± ∈ [0, 1] weights that are 1 on
// that flank and fall linearly to 0 on the other one (across the tooth along the base circle's
// tangent), multiplied by a radial weight that is 1 from the form circle to the tip and falls to
// 0 at the root circle (rim nodes stay put). Turning an involute about its gear axis by φ moves it
// to the parallel involute at the normal distance r_b·φ (both are involutes of the same base
// circle), so a flank node moves by exactly δ(z) along the flank normal; interior nodes take a
// smooth share of it, which keeps the cells' shape (gradient δ/s_tooth ~ 1e-2). The fillets take
// a blend of the flank's removal (no contact there).
//
// A ring gear (internal) takes the same construction: its tooth (tip towards the centre, root
// circle outside the form circle) also lies between its two flanks, which are involutes of its
// base circle unwinding the other way (flank angle c + inv(α_r) instead of c − inv(α_r)); the
// depth below a flank is again r_b times the angle to it, and removing δ from side ±1 turns that
// flank towards the tooth axis by ∓δ/r_b, as on an external tooth. The radial weight runs from
// the root circle (outside, 0) to the form circle (1): rim nodes beyond the root stay put.
#pragma once

#include "geometry/tooth_modification.h"
#include "geometry/tooth_profile.h"

#include <Eigen/Core>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace gearstiff::geometry
{
// The removal (m) of one flank at z (m) over the face width b (m): `loaded` says which flank
// (LeadModification::flanks = loaded leaves the other one unmodified).
double lead_removed_depth(const LeadModification& lead, double z, double face_width, bool loaded);

// The smallest over z ∈ [0, b] of the loaded flanks' summed lead removal of a pair (m): what the
// lead modifications add to the pair's designed separation (sampled at 2001 points; the
// functions are piecewise quadratic, so the sample is within 1e-4·max(δ) of the minimum).
double smallest_lead_separation(const LeadModification& first, const LeadModification& second,
                                double face_width);

// Checks a gear's lead modifications against its tooth and face width (InputError naming the
// field of gear `parameter` (field::modified_gear: "pinion") and the entry, field::gear_entry:
// "pinion.lead_crowning", "pinion.lead_slope", "pinion.end_relief", "pinion.end_relief_length",
// geometry/fields.h; app maps them to "Gear pair/Pinion/lead crowning" etc.): amounts
// finite and (but the slope) not negative, an end relief with a length in (0, b/2], the removal
// of both flanks at the worst end within the tip thickness.
void check_lead_modification(const LeadModification& lead, const ToothProfile& nominal,
                             double face_width, const std::string& parameter);

// The node displacement of one gear body in a 3D scene (header). Built from the nominal tooth of
// the gear and its placement in the scene (centre, rotation of tooth 0's axis from +x).
class LeadModifier
{
public:
  LeadModifier(const ToothProfile& nominal, const LeadModification& lead, int loaded_side,
               double face_width, const Eigen::Vector2d& centre, double rotation,
               const std::string& parameter);
  // m, the in-plane displacement of the body node at `point` (scene frame, m).
  Eigen::Vector2d offset(const Eigen::Vector3d& point) const;
  // m, the depth of `point` (scene frame, in-plane) below the nominal flank of side ±1 of its
  // tooth, measured along the flank normal (r_b times the angle between the flank's involute
  // and the involute through the point); negative outside the nominal tooth.
  double depth_below_flank(const Eigen::Vector2d& point, int side) const;
  bool empty() const { return lead.empty(); }
  const LeadModification& modification() const { return lead; }

private:
  // Angle from the tooth axis (rad) of the nominal flank at radius r, and the node's tooth-frame
  // polar angle.
  double flank_angle(double radius) const;
  double local_angle(const Eigen::Vector2d& point) const;

  LeadModification lead;
  int loaded_side = 1;
  double face_width = 0.;     // m
  Eigen::Vector2d centre;     // m
  double rotation = 0.;       // rad
  double pitch = 0.;          // rad
  double base_radius = 0.;    // m
  double flank_constant = 0.; // rad, c of flank_angle = c + σ·inv(α_r) (σ = −1 external)
  double sigma = -1.;
  double root_radius = 0., form_radius = 0.; // m
};

// The PlanarModel::node_offset (geometry/mesh_planar.h) of a scene's gear bodies, each given by
// its material id and modifier; empty when no gear has lead modifications. A 2D scene
// (`dimension` 2) with lead modifications is refused (InputError naming the entry of the first
// modified gear's `parameters` (field::modified_gear), "pinion.lead_crowning" etc.: a 2D model
// has no face width to vary over).
std::function<Eigen::Vector2d(int, const Eigen::Vector3d&)>
lead_node_offset(unsigned int dimension, const std::vector<std::pair<int, LeadModifier>>& bodies,
                 const std::vector<std::string>& parameters);
} // namespace gearstiff::geometry
