// One position of the influence-coefficient sweep (docs/ltca.md §4–5): what it needs besides
// the coefficients, each pair's force line and near field on modified flanks (the strip where the
// gap is not a Hertz parabola), its unknowns and the result it reports. Internal to stiffness/
// (stiffness/influence_sweep.cc).
#pragma once

#include "stiffness/influence_geometry.h"
#include "stiffness/ltca_contact.h"
#include "stiffness/mesh_stiffness.h"

#include <array>
#include <cstddef>
#include <vector>

namespace gearstiff::stiffness::influence
{
// What every position needs besides the coefficients: where the flanks are, their gaps and near
// field, and the stations along the face (one in 2D).
struct PositionModel
{
  const PairFrame& frame;
  const PairSeparation& separation;
  LayerBody pinion, wheel;
  double face_width = 0.; // m, b
  FaceStations stations;
  Helix helix;
  double friction_coefficient = 0.; // -, Coulomb μ of the flanks (pair_friction)
};

// The force line of pair j touching at ℓ on modified flanks (docs/ltca.md, "Profile
// modifications"). With S_1(ℓ), S_2(ℓ) the depths removed from the pinion's and the wheel's
// flank where they touch at ℓ, the pinion surface on the line of action lies at ℓ_p − S_1(ℓ_p)
// and the wheel's at ℓ_w + S_2(ℓ_w): the lever arms, d(approach)/dφ, are r_b1·(1 − S_1') and
// r_b2·(1 + S_2'). The force line at those distances from the two centres is the nominal line
// of action turned by τ; the strip carries the local gap where it is not a parabola.
struct PairLine
{
  double pinion_lever = 1.; // -, arm/r_b1
  double wheel_lever = 1.;  // -, arm/r_b2
  double tilt = 0.;         // rad, τ: direction u + τ·m
  ContactStrip strip;       // empty gap: Hertz; else centred on the touching point
  double lowered = 0.;      // m, ≤ 0: the smallest gap near ℓ less the removal at ℓ
};

// The pair's force line and near field where it touches at ℓ = `at` (relative radius R, the
// Hertz zone of `total_force` sizing the strip): unmodified flanks away from a corner give the
// nominal line and Hertz.
PairLine pair_line(const PositionModel& model, double at, double relative_radius,
                   double total_force);

// The ℓ of the pinion's and of the wheel's flank point where a pair whose unmodified flanks
// touch at ℓ = `at` touches on its modified flanks: the touching point's offset x moves gear i's
// point by x·r_bi/ρ_i of roll (geometry::touching_point). There the load acts and the FE body's
// coefficients are read. Measured 2026-12-05 (the planet–ring tip-relief test, μ 0): the exact
// path's relieved pair touches 0.24 mm of the planet's roll below ℓ; read at ℓ its load share
// was 0.012 low and k 0.66 % soft. Kept on the path A–E; solve_position keeps them on the pair's
// flank grid.
std::array<double, 2> touching_flanks(const PairFrame& frame, const PairSeparation& separation,
                                      double at);

// One unknown of a position: the force of pair j at station s, where the pair's contact line
// crosses the station's plane at ℓ on the path of contact A–E (spur: every plane of every pair
// in contact; helical: the planes where ℓ(z) lies on the path, so their number changes along the
// sweep as the pairs in contact do in 2D).
struct Unknown
{
  int pair = 0;
  std::size_t station = 0;
  double at = 0.; // m, ℓ at the station's plane
  PairLine line;
  bool edge = false;    // a helical plane beyond the path: the tip corner at ℓ = A or E
  double touching = 0.; // m, where the unloaded flanks touch: the smallest separation is the
                        // unloaded TE
  std::array<double, 2> flank{}; // m, ℓ of the pinion's and the wheel's point (touching_flanks)
  PairFriction friction;         // the friction force at ℓ (pair_friction; 0: frictionless)
};

// The result of one position at one torque from the solved forces (one per unknown, pair by
// pair, stations ascending), as GearMeshStiffness reports it. Each force is the normal force of
// its station (N; a helical pair's transverse force along the line of action is its cos β_b
// part, its axial force the sin β_b part). The root stresses are NaN here (printed "nan", null in
// JSON): the caller sums them from the FE body's fillets (2D) or leaves them so (3D).
template <int dim>
GearMeshStiffnessResult position_result(const PositionModel& model, double position,
                                        const std::vector<int>& pairs,
                                        const std::vector<Unknown>& unknowns,
                                        const MeshContactSolution& solution, double torque);
} // namespace gearstiff::stiffness::influence
