// Load distribution across the face width of a 3D gear-pair solve (issue 27): the line load
// w(z) of a tooth pair at each face-width coordinate z, the transverse load per unit face width
// (ISO's F_t/b): the normal contact forces of the flank's slave nodes on the plane z, their
// transverse parts (× |n_xy|, cos β_b on a helicoid, 1 on a spur flank) summed and divided by
// the width of face the plane stands for (FacePlanes::width). So ∫ w dz = F_bt: the plane's
// nodal forces are what the solve balanced, not a pressure integrated again across the profile
// (that read a node where a contact line starts, whose mortar share reaches past its last paired
// neighbour, up to 38 % low: invariants case 4 of seed 20261201, ∫ w dz 1 % under F_bt). The
// normal line load is w/cos β_b. And the face load factor K_Hβ = max w / mean w of the pairs'
// summed line load (ISO 6336-1 defines K_Hβ as the ratio of the largest to the mean line load
// over the face width; docs/references.md §5). The extruded mesh (geometry/mesh_planar.h) puts
// its flank nodes on planes of constant z (layers, and with Q2 their middles), so each plane's
// nodes give one w(z).
#pragma once

#include "fem/fields.h"

#include <vector>

namespace gearstiff::contact
{
template <int dim>
struct PairResult;
}

namespace gearstiff::stiffness
{
struct FaceLoadPoint
{
  int pair = 0;          // -, j of the tooth pair (geometry/scene_gear_pair.h)
  double z = 0.;         // m, face-width coordinate (0 … b)
  double line_load = 0.; // N/m, transverse load per unit face width at z
  double width = 0.;     // m, the face the plane stands for: ∫ w dz = Σ line_load × width

  template <class Self, class Visit>
  static void for_each_field(Self& self, Visit&& visit)
  {
    visit("pair", self.pair);
    visit("z", self.z);
    visit("line_load", self.line_load);
    visit("width", self.width);
  }
  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    fem::serialize_fields(archive, *this);
  }
};

// The planes of the extruded mesh: `layers` equal layers across the common face width, and with
// Q2 their middles. width(z): the face the plane at z stands for, the integral of its 1D Lagrange
// shape function across the face (m) — the plane's share of every nodal force.
struct FacePlanes
{
  double face_width = 0.;       // m
  unsigned int layers = 1;      // -
  unsigned int degree = 1;      // -, element degree (1 or 2)
  double width(double z) const; // m
};

// Appends the line loads of one contact pair (pair index j) of a 3D solve, z ascending (N/m).
void append_face_load(const contact::PairResult<3>& contact, int pair, const FacePlanes& planes,
                      std::vector<FaceLoadPoint>& face_load);

// The pairs' summed line load at every z (z ascending; N/m) and its summary.
struct FaceLoadSummary
{
  std::vector<double> z;         // m
  std::vector<double> line_load; // N/m, Σ over the pairs
  double mean = 0.;              // N/m, ∫ w dz / (z_max − z_min)
  double peak = 0.;              // N/m
  double peak_z = 0.;            // m, where the peak is (nearest z = 0 of the planes within
                                 // peak_tie of it)
  double factor = 0.;            // -, K_Hβ = peak/mean (0: no load)
  double force = 0.;             // N, ∫ w dz = Σ w × width: the pairs' transverse force F_bt
};
// -, line loads within this fraction of the peak are the peak: the report prints 7 significant
// digits, and the FE solution's line loads on a face loaded uniformly agree to ~1e-9, not to the
// last bit.
constexpr double peak_tie = 1e-6;
FaceLoadSummary summarise_face_load(const std::vector<FaceLoadPoint>& face_load);
} // namespace gearstiff::stiffness
