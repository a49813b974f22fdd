// Tooth faults (issue 31) as modification kinds of geometry/tooth_modification.h: a chipped tip,
// a broken tooth, a spall (pit) on the loaded flank and a root crack, each applied to one tooth
// (GearModifications::by_tooth) after its profile modifications. The 2D outline is extruded
// through the face in 3D; a fault over part of the face width (a crack width fraction below 1, a
// spall or chipped corner narrower than the face) is a fill of the extruded body
// (FaultFill, fault_fills below), so only the through-the-face faults change the outline here.
//
// Shapes (tooth frame of geometry/tooth_profile.h, external gears only):
//  - tip chipping h: the tooth cut by the circle r_a − h (a flat, radial-normal new tip);
//    h must leave the involute (r_a − h above the form circle);
//  - broken tooth: the tooth removed down to the root circle (the outline between the two gap
//    middles becomes the root arc);
//  - spall of depth d over the involute arc length L centred on roll length ρ_c = ξ·r_b of the
//    loaded flank (ξ its roll angle; default the reference circle): the flank between the arc
//    lengths s_c ± L/2 (s = ρ²/(2 r_b)) moved inwards by d along its normal, with straight walls at
//    both ends (a rectangular pit through the face, the shape of Chaari et al. 2008's spall model,
//    docs/references.md §13). The pit's floor and walls are free surfaces (segment root: no
//    flank, no contact id): a pit deeper than the pair's approach (a few µm) is not reached, and
//    a pair whose contact point lies over it carries nothing (flank_carries), the contact width
//    lost in Chaari et al.'s model;
//  - root crack of depth a at angle ν to the tooth centre line, starting on the loaded flank's
//    fillet (tension side) at the 30° tangent point of ISO 6336-3 (the critical section,
//    docs/references.md §13) or at a given radius: an open slit of width crack_opening whose
//    faces run parallel to the crack path and meet at the tip in a 90° V. ν = 90° runs across the
//    tooth perpendicular to its centre line; smaller ν dips towards the root (Tian 2004,
//    Chaari et al. 2009 measure ν the same way). The slit's faces are free surfaces (an open
//    crack). With ToothModification::crack_contact (2D) the crack has no width instead: the
//    tooth is cut along mouth → tip → the point where the ray from the tip parallel to the
//    centre line (towards the tooth tip) leaves the outline (the tooth's outline keeps its
//    flanks, with the mouth and that point as corners); the mesh's outline runs along that cut
//    and the material beyond it is a fill (fault_fills, geometry/mesh_planar.h PlanarFill) sharing
//    the cut's curves, so every quadrilateral mesh follows the crack. The mesh is then split
//    along mouth → tip (the tip node stays shared), its two faces a contact pair of the body
//    with itself with the contact's friction coefficient (0 by default: frictionless;
//    stiffness/mesh_stiffness.cc add_crack_pairs), so they may close under compression
//    (docs/faults.md).
// Every kink a fault makes (spall walls, slit mouth, faces, tip) is a ProfilePoint::corner, so
// the scene starts a new outline piece there.
#pragma once

#include "geometry/mesh_planar.h"
#include "geometry/tooth_modification.h"

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

namespace gearstiff::geometry
{
constexpr double crack_opening = 40e-6;     // m, width of the slit between the crack faces
constexpr double crack_tip_size = 10e-6;    // m, cell size within crack_tip_radius of the tip
constexpr double crack_tip_radius = 0.1e-3; // m
// m, cell size along the crack faces (half the opening: two cells across the slit's width)
constexpr double crack_face_size = 0.5 * crack_opening;

// m, the cell size at a crack's tip: its crack_tip_size, or the default crack_tip_size.
double crack_tip_cell_size(const ToothModification& crack);

// Whether every fault of the gear (by_tooth) is a root crack, or it has none: every flank is
// whole, so the pairs in contact carry at every position and a scene rolls with its cracked
// tooth (`Stiffness/sweep mesh = once`). A broken, chipped or spalled tooth changes which pairs
// carry from one position to the next.
bool flanks_whole(const GearModifications& modifications);

// The faults' checks against the nominal tooth (InputError naming the gear's field of the entry,
// field::gear_entry(parameter, "spall depth") = "pinion.spall_depth", geometry/fields.h):
// chipping taller than the tooth or reaching below the form circle, a spall outside the flank
// or deeper than a quarter of the tooth's chordal thickness there, a crack deeper than the tooth
// along its path, an internal gear.
void check_faults(const std::vector<ToothModification>& modifications, const ToothProfile& nominal,
                  const FlankRollRange& range, int loaded_side, const std::string& parameter);

// The faults of `modifications` applied to `tooth` (the nominal outline with the profile
// modifications already applied).
ToothProfile apply_faults(const ToothProfile& tooth,
                          const std::vector<ToothModification>& modifications, int loaded_side);

// Whether the loaded flank exists at roll length `roll` (m): not where the tooth is broken,
// chipped away or over a spall's pit through the face (a pair whose contact point lies there
// carries nothing); a partial-width spall or chipped corner (3D) leaves the rest of the face.
bool flank_carries(const std::vector<ToothModification>& modifications, const ToothProfile& nominal,
                   double roll);
// Depth (m) a spall removes from the loaded flank at roll length `roll` (its share of the
// unloaded transmission error).
double fault_flank_depth(const std::vector<ToothModification>& modifications,
                         const ToothProfile& nominal, double roll);

// Where the mesh must be finer because of the faults (tooth frame): along a crack's faces
// (crack_face_size) and at its tip (crack_tip_size within crack_tip_radius); a crack whose faces
// meet: 2 h_tip along the faces and h_tip within 10 h_tip of the tip (h_tip =
// crack_tip_cell_size).
std::vector<SizeFocus> fault_foci(const std::vector<ToothModification>& modifications,
                                  const ToothProfile& nominal, int loaded_side);

// 3D, a fault over part of the face width (a root crack with a crack width fraction below 1 or a
// parabolic front): the faulty outline is meshed with the material between its corners `from`
// and `to` (the slit) and the healthy outline `closing` (from `from` to `to`), and the cells of
// that material inside the fault are left out (geometry/mesh_planar.h, PlanarFill): `removed`
// takes a point in the tooth frame (m) and its distance z from the end face z = 0 (m).
//  - crack of depth a, width fraction f, face width b: over 0 <= z < f·b the slit reaches the
//    depth a (straight front) or a·√(1 − z/(f·b)) (parabolic front: the front is the parabola
//    z = f·b·(1 − (s/a)²) in the plane of the crack, s the depth along the path, deepest at the
//    end face z = 0 and reaching the surface at z = f·b); beyond f·b the tooth is whole;
//  - spall of width w (< b): the pit over |z − b/2| < w/2 (centred on the face), the flank whole
//    beside it (a pair over the pit carries on the rest of the face: flank_carries);
//  - tip chipping of height h over the width w (< b) from the end face z = 0: a chipped corner
//    (a rectangular block h × w removed), the tooth whole beyond w.
struct FaultFill
{
  Eigen::Vector2d from = Eigen::Vector2d::Zero(), to = Eigen::Vector2d::Zero(); // m
  std::vector<ProfilePoint> closing;
  std::function<bool(const Eigen::Vector2d&, double)> removed;
  // The material beyond the cut of a crack whose faces meet (crack_contact, 2D): nothing is
  // removed, the mesh is split along the crack (PlanarFill::crack_id), and the body is meshed
  // with `outline`, the tooth's outline with the cut mouth → tip → end in place of `closing`.
  bool crack = false;
  std::vector<ProfilePoint> outline;
};
// Whether a fault is modelled over part of the face only (3D: a fill, else the outline extruded).
bool is_partial_width(const ToothModification& fault);
// The fills of the partial-width faults of `modifications` on `tooth` (as apply_faults; 3D,
// face_width > 0) and of the cracks whose faces meet (2D).
// InputError (the gear's field "<gear>.spall_width" or "<gear>.tip_chipping_width") for a spall or
// chipped corner not narrower than the face.
std::vector<FaultFill> fault_fills(const ToothProfile& tooth,
                                   const std::vector<ToothModification>& modifications,
                                   int loaded_side, double face_width,
                                   const std::string& parameter);

// A root crack's path (tooth frame).
struct CrackPath
{
  Eigen::Vector2d start;     // m, on the loaded fillet
  Eigen::Vector2d direction; // unit, into the tooth
  double depth = 0.;         // m, a
  double across = 0.;        // m, length of the path from the start to the opposite outline
};
CrackPath crack_path(const ToothModification& crack, const ToothProfile& nominal, int loaded_side);

// The fillet point of side `side` whose tangent is inclined at 30° to the tooth centre line
// (ISO 6336-3 critical section), m, tooth frame.
Eigen::Vector2d critical_section_point(const ToothProfile& nominal, int side);
} // namespace gearstiff::geometry
