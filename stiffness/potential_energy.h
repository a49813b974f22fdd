// Mesh stiffness of a spur gear pair by the potential-energy method (issue 31), beside the FE:
// each tooth a cantilever on the root circle, loaded at its contact point along the line of
// action, its compliance the sum of
//
//   bending  1/k_b = ∫ (cos α₁·(x_c − x) − sin α₁·y_c)² / (E'·I_x) dx
//   shear    1/k_s = ∫ 1.2·cos² α₁ / (G·A_x) dx
//   axial    1/k_a = ∫ sin² α₁ / (E'·A_x) dx                   (Yang & Lin 1987; Tian 2004)
//
// over the sections x from the root circle to the load point (x_c, y_c) (x along the tooth
// centre line, y_c the load point's distance from it, α₁ the angle between the force and the
// normal to the centre line), plus the fillet-foundation compliance of Sainsot et al. 2004
//
//   δ_f/F = cos² α₁/(E'·b)·(L*·(u_f/S_f)² + M*·(u_f/S_f) + P*·(1 + Q*·tan² α₁)),
//   X* = A/θ_f² + B·h_f² + C·h_f/θ_f + D/θ_f + E·h_f + F, h_f = r_f/r_bore
//
// (u_f: the force line's crossing of the centre line above the root circle; S_f = 2 r_f sin θ_f
// the tooth's chord at the root circle, θ_f its half angle), and the Hertz stiffness of the pair
// k_h = π·E·b/(4(1 − ν²)) (Yang & Lin 1987). A pair's stiffness is 1/(1/k_h + Σ_gears (1/k_b +
// 1/k_s + 1/k_a + 1/k_f)); the mesh stiffness the sum over the pairs in contact.
//
// The sections A_x = (h₁ + h₂)·b, I_x = (h₁ + h₂)³·b/12 come from the modelled outline
// itself (geometry::ToothProfiles: fillets, profile modifications, a chipped tip, a spall's pit),
// not from the idealised involute-to-base-circle tooth of Tian; a root crack reduces the loaded
// side's half height h₁ above the crack tip's section to the tip's distance from the centre line
// (the crack-shadow rule of Tian 2004 and Chaari et al. 2009); the foundation term is that of
// the healthy tooth (as in both papers). A crack over part of the face (3D: crack width
// fraction, parabolic front) is taken by slices along the face (Chen & Shao 2011): the tooth's
// bending, shear and axial stiffness is the mean over the face of that of the full-width tooth
// with each slice's crack depth (slices side by side, no shear between them; against the 3D FE in
// docs/faults.md). A through-face spall
// under the contact point and a broken or chipped flank carry nothing (the pair's k = 0): where no
// pair carries, the mesh has lost contact and no stiffness is returned. E' = E/(1 − ν²): the FE
// beside it is plane strain, and so are wide spur teeth (b ≫ tooth thickness). Sources:
// docs/references.md §13.
#pragma once

#include "geometry/scene_gear_pair.h"
#include "geometry/tooth_profiles.h"

#include <vector>

namespace gearstiff::stiffness
{
struct EnergyMethodSettings
{
  unsigned int sections = 400;   // -, midpoint sections from the root circle to the load point
  unsigned int face_slices = 48; // -, midpoint slices across the face of a partial crack
};

// One tooth at one contact point: compliances (m/N) of a face width b.
struct ToothCompliance
{
  double bending = 0.;    // m/N
  double shear = 0.;      // m/N
  double axial = 0.;      // m/N
  double foundation = 0.; // m/N
  double total() const { return bending + shear + axial + foundation; }
};

struct EnergyPair
{
  int pair = 0;           // -, j (pinion tooth j meets wheel tooth −j)
  double position = 0.;   // m, contact point along the line of action from T1
  bool carries = true;    // false: a broken, chipped or spalled flank at the contact point
  ToothCompliance pinion; // m/N
  ToothCompliance wheel;  // m/N
  double hertz = 0.;      // N/m, k_h
  double stiffness = 0.;  // N/m, the pair's k (0 where it does not carry)
};

struct EnergyPosition
{
  double position = 0.;       // m, reference pair's contact point from T1
  double mesh_position = 0.;  // -, (ℓ − A)/p_bt
  bool lost_contact = false;  // no pair carries: no stiffness exists (mesh_stiffness 0, unused)
  double mesh_stiffness = 0.; // N/m, Σ of the pairs' k (valid only without lost_contact)
  std::vector<EnergyPair> pairs;
};

// The energy method on the scene's gears (pair, faults, bores, material from `scene`):
// the reference pair at each position ℓ (m from T1) with the pairs in contact there.
// InputError as the scene (the faults' checks); SolverFailure when a section or the foundation
// falls outside the method (no tooth material at a section).
std::vector<EnergyPosition> energy_mesh_stiffness(const geometry::GearPairSceneSpec& scene,
                                                  const std::vector<double>& positions,
                                                  const EnergyMethodSettings& settings = {});

// Sainsot et al. 2004's fillet-foundation polynomial X*(h_f, θ_f) (rows L*, M*, P*, Q*).
double sainsot_coefficient(unsigned int row, double h_f, double theta_f);
} // namespace gearstiff::stiffness
