// The small contact problem of one gear-mesh position in the influence-coefficient model
// (docs/ltca.md §3–4): the analytic near field of a plane-strain Hertz line contact down to a
// matching depth, and the complementarity problem of the pairs in contact
//
//     g_j = λ_j·(e − s_j) − Σ_k C_jk·F_k − δ(F_j) ≤ 0,  F_j ≥ 0,  F_j·g_j = 0,  Σ λ_j·F_j = W
//
// (with friction, MeshContactProblem's friction forces add to the gaps and to the torque)
// (Conry & Seireg 1971, docs/references.md §19). Plain arithmetic, no deal.II: the FE side
// (stiffness/influence_sweep.h) supplies C.
#pragma once

#include <limits>
#include <vector>

namespace gearstiff::stiffness
{
// One body's elastic constants and the depth (m) at which the FE takes over from the analytic
// layer under its flank.
struct LayerBody
{
  double young_modulus = 210e9; // Pa
  double poisson_ratio = 0.3;   // -
  double matching_depth = 0.;   // m, h
  // -, the layer under a tip edge (a helical pair's tip corner touching beyond the path,
  // docs/ltca.md §3 "Tip edges"): its compression over a half-space's (tip_edge_wedge_factor).
  double wedge_factor = 1.;
  // The body's own sharp tip corner near a contact on its flank (docs/ltca.md "Next to a tip
  // corner"): its tangential offset (m) from the contact's centre along the flank, positive
  // where the strip's x is (NaN: none), and the flank's pressure angle at the tip (rad).
  double corner_offset = std::numeric_limits<double>::quiet_NaN();
  double corner_pressure_angle = 0.;
};

// The compression of a wedge of interior angle π/2 + α_tip (a tooth's tip corner: its flank meets
// the tip land at the flank's pressure angle there) loaded at its apex normal to its flank, over
// a half-space's under the same load, along the load's line: Flamant's wedge (Johnson 1985 §2.2;
// Timoshenko & Goodier §36), σ_r = −(P/r)·[cos β cos θ/(α + ½ sin 2α) + sin β sin θ/(α − ½ sin
// 2α)] with the half-angle α = (π/2 + α_tip)/2 and the load β = π/2 − α off the bisector; the
// ratio of σ_r on the load's line (θ = β) to the half-plane's 2P/(πr). 1 at α_tip = π/2.
double tip_edge_wedge_factor(double tip_pressure_angle);

// m per N/m: how much more the layer 0 ≤ z ≤ h of a body compresses under a line load on its
// flank at distance `distance` (m) from its sharp tip corner than a half-space's layer does. The
// wedge spreads the load as a half-plane out to ~distance and as Flamant's wedge beyond (f times
// the half-plane's stress, tip_edge_wedge_factor), so for distance ≪ h the excess is
// 2(1−ν²)/(πE)·(f − 1)·[ln(h/distance) − 1.8]. Tabulated, as (f − 1)·Ĝ(distance/h, α_tip), from a
// plane-strain FE of the wedge against the half-plane (tools/wedge_layer.py, converged to
// 5e-4; ν 0.3: at ν 0.25 / 0.35 Ĝ moves by −4 / +5 % at s 0.05, ∓12 % at s 0.2).
double corner_layer_excess(double distance, const LayerBody& body);

// -, Ê: how much more the layer 0 ≤ z ≤ h under a 3D node plane compresses, per unit line load,
// than plane strain gives, in units of 2(1−ν²)/(πE), when the face ends at a traction-free end
// plane `plane` node planes of spacing `spacing` (m) away: a line load that runs to a free face
// is held by a quarter-space, not a half-space, and the exact path follows that softening only
// as far as its layers of Δz resolve it (docs/ltca.md §3 "End faces"). Tabulated from a 3D Q1
// FE discretised along the face as the exact path is (tools/end_face_layer.py) for Δz/h 0.5 …
// 16 and planes 0, 1, 2; farther planes take the quarter-space's tail 0.120·h/z out to z = 8·h
// (the FE's 1/z law from z = 3·h, where a tooth's own size, not a half-space's, takes over).
double end_face_layer_excess(double spacing, double matching_depth, unsigned int plane);

// -, D(read, loaded) = K − I between the node planes of one spur contact line: the layer
// 0 ≤ z ≤ h under a line load w on node plane `loaded` alone (of `planes` node planes of
// spacing `spacing` (m) along a face with free ends) compresses at node plane `read` by
// K(read, loaded) times the plane-strain compression of w. The exact path's dual mortar puts
// each plane's contact force on that plane's nodes and its hexahedra interpolate linearly
// between the planes, so its layer is not plane strain plane by plane: K(i, i) 1.5 … 1.8, the
// neighbours −0.3 … −0.5, each interior row summing to 1 (a uniform load is plane strain).
// Tabulated from a 3D Q1 FE discretised along the face as the exact path is
// (tools/end_face_layer.py --rows) for Δz/h 0.5 … 16 (clamped outside), the interior row and
// the rows of planes 0 … layer_kernel_end_planes − 1 from either end; a Hertzian load of
// half-width 0.1·h (a/h 0.05 / 0.2 move the interior diagonal by +0.9 / −1.3 %), ν 0.3
// (docs/ltca.md §3 "End faces").
constexpr unsigned int layer_kernel_end_planes = 5;
double layer_kernel_departure(double spacing, double matching_depth, unsigned int planes,
                              unsigned int read, unsigned int loaded);

// The compression (m) of the layer 0 ≤ z ≤ h of a plane-strain half-space under a Hertzian
// pressure of peak p0 (Pa) and half-width a (m), on the symmetry axis: the integral of ε_z of
// the axis stresses (Johnson 1985 §2.6, docs/ltca.md §3); Weber's formula for h ≫ a.
double hertz_layer_compression(double peak_pressure, double half_width, const LayerBody& body);

// The FE body's coefficients are a point load's, read at the matching depth h under it; the
// contact's load is spread over the zone, and a depth point moves less under a load beside it:
// per unit line load at ξ, by −[(1−ν²)·ln(1 + ξ²/h²) + (1+ν)·ξ²/(ξ²+h²)]/(πE) against the load
// at ξ = 0 (Flamant's half-plane, Johnson 1985 §2.2).
// `spread_load_depth_shift` (m, ≤ 0): that shift of the depth point under a Hertzian line load w
// (N/m) of half-width a (m) against w at its axis, added to each body's approach (docs/ltca.md
// §3 "Spread load at the matching depth"); O((a/h)²): 0.14 % of the built-in pair's single-pair
// compliance, 1.5 % at a/h = 0.7.
double spread_load_depth_shift(double line_load, double half_width, const LayerBody& body);
// The same per unit pressure over the cell ξ ∈ [from, to] (m²/N·Pa⁻¹: m per Pa), for the strip.
double spread_load_depth_cell(double from, double to, const LayerBody& body);

// A Hertz line contact of force F (N) over face width b (m) between two bodies with relative
// radius of curvature R (m, > 0), each compressed down to its matching depth.
struct LineContact
{
  double half_width = 0.;    // m, a = √(4wR/(πE*)), w = F/b
  double peak_pressure = 0.; // Pa, p0 = 2w/(πa)
  double approach = 0.;      // m, δ₁(h₁) + δ₂(h₂)
  double compliance = 0.;    // m/N, dδ/dF
  // m, where the pressure peaks, as a tangential offset from the contact's centre (a strip's:
  // its touching point; Hertz: 0): a contact reaching a relief's start or a rounded tip's arc
  // peaks there, not where it is centred.
  double peak_offset = 0.;
};
LineContact hertz_line_contact(double force, double face_width, double relative_radius,
                               const LayerBody& first, const LayerBody& second);

// A line contact whose gap is not a Hertz parabola: where a relief starts (a kink of the flank)
// within the contact, the pressure peaks at the kink and the zone is narrower (docs/ltca.md,
// "Profile modifications"). The gap across the contact, sampled at the centres of the strip's
// cells: g_i = x_i²/(2R) + the modifications' gap, x_i tangential offsets (m) from the nominal
// contact point over [−half_span, half_span].
struct ContactStrip
{
  double half_span = 0.;       // m, L
  double relative_radius = 0.; // m, R of the pair (the first guess of the zone)
  std::vector<double> gap;     // m, at x_i = −L + (i + ½)·2L/N
};

// The same result as hertz_line_contact for the gap of `strip`: piecewise-constant pressure on
// the strip's cells, each body's surface displaced by the plane-strain half-plane (Flamant,
// Johnson 1985 §2.2) relative to its point at the matching depth under x = 0, the cells in
// contact found by an active set. approach: δ at x = 0's depth points; half_width: half the
// extent of the loaded cells; peak_pressure: the largest cell pressure. SolverFailure when the
// active set does not settle or the contact reaches the strip's ends.
LineContact strip_line_contact(double force, double face_width, const ContactStrip& strip,
                               const LayerBody& first, const LayerBody& second);

// The pressure (Pa) on each of the strip's cells in strip_line_contact's solution (0 off the
// zone): where the loaded surface's normals are weighted (pair_line's force line).
std::vector<double> strip_cell_pressures(double force, double face_width, const ContactStrip& strip,
                                         const LayerBody& first, const LayerBody& second);

// The surface displacement (m, into the body) at tangential offset x (m) of uniform pressure
// 1 Pa on [from, to] (m), relative to the body's point at its matching depth under x = 0: the
// integral of the Flamant kernel (1/(πE))·[(1−ν²)·(ln(ξ²+h²) − 2·ln|x−ξ|) − (1+ν)·h²/(ξ²+h²)].
double half_plane_cell_displacement(double x, double from, double to, const LayerBody& body);

// The problem of one position: n pairs in contact by the kinematics.
struct MeshContactProblem
{
  std::vector<std::vector<double>> compliance; // m/N, C_jk of the bodies below the depths
  std::vector<double> separation;              // m, s_j: designed gap of pair j (≥ 0)
  std::vector<double> relative_radius;         // m, R_j at the pair's contact point
  double total_force = 0.;                     // N, W = T1/r_b1
  // -, arm_j/r_b1 of the pinion's lever arm about pair j's force line: 1 for unmodified
  // involutes; a relief's slope turns the flank normal (docs/ltca.md). Empty: all 1.
  std::vector<double> lever_ratio;
  // Coulomb friction between the flanks (docs/ltca.md §4 "Friction"; μ 0 or empty: none). Each
  // unknown's friction force f_j acts on the pinion's flank along its tangent `across`
  // (stiffness/influence_body.h, FlankPoint) and on the wheel's the opposite way, |f_j| ≤ μ·F_j;
  // it sticks (the pinion's flank does not slip over the wheel's) or slips against the slip.
  // The slip of the pinion's flank over the wheel's at j, from the unloaded state:
  //   t_j = ρ_j·e + Σ_k T_jk·F_k + Σ_k U_jk·f_k + u_j(F_j)·f_j,
  // ρ_j the rigid roll's (slip_per_approach), T, U the FE bodies' (slip_under_force,
  // slip_under_friction), u_j the near field's (its normal compliance dδ/dF: a tangential line
  // load's layer has the normal one's (1 − ν²)·ln term, Johnson 1985 §2.2). The friction forces
  // open the gaps by Σ_k G_jk·f_k (gap_under_friction) and carry the pinion torque
  // Σ_j (λ_j·F_j + a_j·f_j)·r_b1 = T1 (friction_arm a_j).
  double friction_coefficient = 0.;                     // -, μ
  std::vector<double> slip_per_approach;                // -, ρ_j
  std::vector<std::vector<double>> slip_under_force;    // m/N, T_jk
  std::vector<std::vector<double>> slip_under_friction; // m/N, U_jk
  std::vector<std::vector<double>> gap_under_friction;  // m/N, G_jk
  std::vector<double> friction_arm;                     // -, a_j
  // Pair j's near field: empty gap → Hertz (relative_radius[j]); else the strip solution.
  std::vector<ContactStrip> strip;
  double face_width = 0.; // m, b
  // m, the face width each unknown's near field spreads its force over (a 3D model's layer or
  // node plane: its line load is F_j/width_j). Empty: face_width for every unknown.
  std::vector<double> width;
  // Per unknown: its node plane's end_face_layer_excess from both ends of the face (3D), the
  // same for both bodies in units of their own 2(1−ν²)/(πE). Empty: none.
  std::vector<double> end_excess;
  // Per unknown: each body's LayerBody::wedge_factor (a tip edge's, else 1). Empty: all 1.
  std::vector<double> pinion_wedge, wheel_wedge;
  // Per unknown: each body's LayerBody::corner_offset (NaN: no sharp tip corner). Empty: none.
  std::vector<double> pinion_corner, wheel_corner;
  LayerBody pinion, wheel;
};

struct MeshContactSolution
{
  std::vector<double> force;          // N, F_j
  std::vector<double> friction;       // N, f_j (MeshContactProblem; empty: frictionless)
  unsigned int friction_passes = 0;   // -, the normal and the tangential problem in turn
  std::vector<LineContact> contact;   // each loaded pair's near field (zero when unloaded)
  double approach = 0.;               // m, e: the pinion's roll r_b1·Δφ (rigid approach)
  unsigned int active_set_passes = 0; // -
  unsigned int newton_steps = 0;      // -
};

// Newton on the loaded pairs (δ is nonlinear in F), the active set updated until it repeats.
// `start` (N, may be empty or of another size): the neighbouring position's forces, a warm start
// of the active set and the Newton iteration. SolverFailure when it does not converge.
MeshContactSolution solve_mesh_contact(const MeshContactProblem& problem,
                                       const std::vector<double>& start);
} // namespace gearstiff::stiffness
