// Load distribution across the face width of a 3D gear-pair solve (issue 27): the line load
// w(z) = ∫ p ds along the contact line of a tooth pair at each face-width coordinate z (the
// contact pressure integrated across the transverse profile, from the pinion flank's slave
// nodes): on a helical flank the transverse load per unit face width, ∫ w dz = F_bt (measured to
// 1e-4 on a β 10° pair), the normal line load being w/cos β_b; on a spur flank both. And the
// face load factor K_Hβ = max w / mean w of the pairs' summed line load (ISO 6336-1 defines
// K_Hβ as the ratio of the largest to the mean line load over the face width; docs/references.md
// §5). The extruded mesh (geometry/mesh_planar.h) puts its flank nodes on planes of constant z
// (layers, and with Q2 their middles), so each plane's nodes give one w(z).
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
  double line_load = 0.; // N/m, ∫ p ds across the profile at z

  template <class Self, class Visit>
  static void for_each_field(Self& self, Visit&& visit)
  {
    visit("pair", self.pair);
    visit("z", self.z);
    visit("line_load", self.line_load);
  }
  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    fem::serialize_fields(archive, *this);
  }
};

// Appends the line loads of one contact pair (pair index j) of a 3D solve, z ascending: at each
// plane of slave nodes, the trapezoidal integral of the nodal pressures along the nodes sorted
// by their roll length about the pinion axis (the scene origin). `base_radius`: r_b1 (m).
void append_face_load(const contact::PairResult<3>& contact, int pair, double base_radius,
                      std::vector<FaceLoadPoint>& face_load);

// The pairs' summed line load at every z (z ascending; N/m) and its summary.
struct FaceLoadSummary
{
  std::vector<double> z;         // m
  std::vector<double> line_load; // N/m, Σ over the pairs
  double mean = 0.;              // N/m, ∫ w dz / (z_max − z_min) (trapezoidal)
  double peak = 0.;              // N/m
  double peak_z = 0.;            // m, where the peak is
  double factor = 0.;            // -, K_Hβ = peak/mean (0: no load)
  double force = 0.;             // N, ∫ w dz: the pairs' transverse force F_bt (spur: normal)
};
FaceLoadSummary summarise_face_load(const std::vector<FaceLoadPoint>& face_load);
} // namespace gearstiff::stiffness
