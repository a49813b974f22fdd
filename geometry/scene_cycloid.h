// The FE scene of a cycloidal (Cyclo) drive at one disc position: the disc with its lobes, the
// eccentric-bearing bore and the output-pin holes, and the ring of rollers (each on its pin),
// after docs/references.md §4 (Chmurawa & Łokiec). Ring centre at the origin, roller i centred at
// polar angle 2πi/z_k on the roller circle; the disc turned by ψ about its own centre, which sits
// at −e·(cos z_sψ, −sin z_sψ) — the nominal kinematics with the ring fixed, the same placement as
// roller_clearances() in geometry/cycloid_disc.h.
//
// Ids (scene_common.h): disc material 1, rollers material 2; disc bore 1, roller pins 2, disc
// lobes 3, roller surfaces 4, output-pin holes 8. Contacts: every roller whose clearance to
// the disc is at most `contact_clearance`.
//
// With `output_pin_bodies` every hole also holds its output pin (cycloid_ids below): pin j is
// centred at the hole's vector from the disc centre taken from the ring centre — the
// parallel-crank (W) mechanism of the output, so every pin sits e off its hole's centre, toward
// −(disc centre) — and touches its hole there when the play (hole − pin − e) is zero. The pin's
// bore is where the rigid output member holds it. Each pin adds one contact (the touching point).
#pragma once

#include "geometry/cycloid_disc.h"
#include "geometry/scene_common.h"

#include <string>

namespace gearstiff::geometry
{
// Ids of the output pins (beyond the common scene_ids).
namespace cycloid_ids
{
constexpr int output_pin_body = 3;      // material id of the output pins
constexpr int output_pin_bores = 9;     // boundary id: the pins' bores (the output member)
constexpr int output_pin_surfaces = 10; // boundary id: the pins' outer surfaces
} // namespace cycloid_ids

struct CycloidSceneSpec
{
  // The ring (roller circle r, roller radius q, eccentricity e, z_k): docs/references.md §4
  // nominal.
  CycloidDiscSpec ring = {20, 96e-3, 3e-3, 8.5e-3, 0.};
  // The disc profile; rollers = 0 takes the ring's (the nominal equidistant). A corrected
  // profile (r_k, q_k, δ from solve_cycloid_correction) goes here.
  CycloidDiscSpec disc = {0, 0., 0., 0., 0.};
  double disc_rotation = 0.; // rad, ψ

  // Not published; sized for the nominal disc (lobe roots at r − q − e = 84.5 mm).
  double bore_radius = 25e-3;              // m, eccentric-bearing seat of the disc
  unsigned int output_pins = 8;            // -, holes for the output pins
  double output_pin_circle_radius = 55e-3; // m
  double output_pin_hole_radius = 12e-3;   // m, pin radius + e
  double roller_pin_radius = 4e-3;         // m, pin inside each roller
  // rad, polar angle of hole 0 in the disc frame (the holes turn with the disc by ψ).
  double output_pin_phase = 0.;
  // rad, the pins alone turned about the ring centre against their holes (the holes stay with
  // the disc): the turn that closes their play before the load comes on (stiffness/cycloid_loads).
  double output_pin_turn = 0.;
  bool output_pin_bodies = false;       // mesh the output pins in their holes
  double output_pin_radius = 9e-3;      // m, hole radius − e: no play (not published)
  double output_pin_bore_radius = 4e-3; // m, bore of each pin, held by the output member
  double pin_force = 3776.; // N, Q_max of docs/references.md §4, for the Hertz estimate

  double contact_clearance = 1e-5; // m, rollers this close to the disc are contacts
  double roller_force = 1711.;     // N, P_max of docs/references.md §4, for the Hertz estimate
  double disc_width = 15e-3;       // m, disc thickness (not published; 3D extrusion)
  double young_modulus = 210e9;    // Pa
  double poisson_ratio = 0.3;      // -
  unsigned int points_per_lobe = 121;
  SceneMeshSettings mesh;
};

// The centre of output pin j (m, ring frame): the hole's vector from the disc centre, turned by
// the disc rotation, from the ring centre, and turned by output_pin_turn about it.
Eigen::Vector2d output_pin_centre(const CycloidSceneSpec& spec, unsigned int pin);
// The centre of hole j in the disc (m, ring frame) for the disc centre `disc_centre`: where pin j
// sits without output_pin_turn, offset by the disc centre.
// Whether the output pins have play in their holes: hole − pin − e above a nanometre (below it is
// the round-off of the subtraction, 1.6e-17 m for 12 − 9 − 3 mm; taken as play it sent a scan for
// the pins' closure into ~1e16 steps). The one test every play decision uses.
bool has_output_pin_play(const CycloidSceneSpec& spec);
Eigen::Vector2d output_hole_centre(const CycloidSceneSpec& spec, unsigned int pin,
                                   const Eigen::Vector2d& disc_centre);

// Checks the spec (InputError naming "Cycloid scene/..." or "Cycloid disc/..." before gmsh
// runs), meshes, writes `file`.
SceneInfo write_cycloid_scene(const CycloidSceneSpec& spec, const std::string& file);
} // namespace gearstiff::geometry
