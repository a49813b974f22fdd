// Meshing machinery shared by every scene: planar bodies bounded by labelled curves are meshed
// with the gmsh C++ API into all-quadrilateral cells (2D) or extruded into hexahedra (3D), with a
// mesh size graded from a fine size at a few focus points (the predicted contact points) to a
// coarse body size, and written as ASCII .msh 4.1 that deal.II's GridIn::read_msh reads.
//
// Ids: deal.II takes the gmsh physical tag of an entity as its material id (cells) or boundary id
// (faces) and accepts only one physical tag per entity. So every body surface carries exactly one
// physical group (its material id) and every boundary curve at most one (its boundary id);
// curves with boundary id 0 get no physical group, are not written, and deal.II gives them its
// default boundary id 0 ("free surface").
//
// Failure is never silent: a mesh with any non-quadrilateral (non-hexahedral) cell or with a cell
// whose scaled Jacobian is not positive raises SolverFailure; bad geometry raises InputError.
#pragma once

#include "errors/limits.h"

#include <Eigen/Core>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace gearstiff::geometry
{
// How a boundary piece passes through its points.
enum class CurveKind
{
  spline,   // interpolating spline through all points (tooth flanks, fillets)
  straight, // straight segments between consecutive points (cuts)
  arc       // circular arc from the first to the last point about `arc_centre` (< 180°)
};

// One labelled piece of a closed boundary loop.
struct BoundaryPiece
{
  std::vector<Eigen::Vector2d> points; // m, scene frame, at least 2, in loop order
  CurveKind kind = CurveKind::spline;
  Eigen::Vector2d arc_centre = Eigen::Vector2d::Zero(); // m, only for CurveKind::arc
  int boundary_id = 0; // physical tag of the curve (deal.II boundary id); 0: free, unlabelled
};

// A closed loop: the last point of each piece is the first point of the next one, and the last
// piece ends where the first begins. Orientation does not matter (it is normalised).
struct BoundaryLoop
{
  std::vector<BoundaryPiece> pieces;
  double signed_area() const; // m², positive when counter-clockwise
};

// 3D: material of a body that a fault removes over part of the face width only (a partial root
// crack, a spall narrower than the face, a chipped corner; geometry/tooth_fault.h). The region
// between the pieces outer.pieces[first_piece..last_piece] of its body (in the loop's order) and
// `closing` (from the end of the last of them back to the start of the first) is meshed as a
// surface of the body's material that shares those curves with it, extruded with it, and its
// hexahedra whose centre satisfies `removed` are left out of the mesh with the boundary faces on
// them: the body has the fault there and its full outline elsewhere, in one conforming mesh.
struct PlanarFill
{
  std::size_t first_piece = 0, last_piece = 0;
  std::vector<BoundaryPiece> closing;
  std::function<bool(const Eigen::Vector3d&)> removed; // m, scene frame
  // 2D, > 0: a crack whose faces meet. One of the pieces first_piece..last_piece (the crack,
  // from the mouth on the outline to the tip inside the body) carries this boundary id, the other
  // (the cut from the tip back to the outline) boundary id 0; the fill is the material beyond the
  // cut, meshed as a surface of its own so that every quadrilateral mesh follows the crack. The
  // mesh is then split along the crack: the body's cells keep its nodes (faces crack_id), the
  // fill's cells get their own copies (faces crack_id + 1), but the tip's node, which both keep.
  // Copies lie crack_face_parting towards the fill. `removed` is not used.
  int crack_id = 0;
};

// m: the copies of a crack's nodes lie this far from the originals (PlanarFill::crack_id):
// deal.II's GridIn may merge coincident vertices, which would seal the crack; 0.1 nm is far below
// any deflection the faces see (µm), and the contact takes the faces as touching.
constexpr double crack_face_parting = 1e-10;

// 3D: a body twisted about its axis along the face width: the section at height z is the
// transverse model turned counter-clockwise by φ(z) = rate·(z − origin) about `axis` (a helical
// gear's lead: rate = tan β_b / r_b, signed by the hand and the side the gear turns).
struct BodyTwist
{
  Eigen::Vector2d axis = Eigen::Vector2d::Zero(); // m, scene frame
  double rate = 0.;                               // rad/m, dφ/dz
  double origin = 0.;                             // m, z where the section is the model's
  double angle(double z) const { return rate * (z - origin); }             // rad
  Eigen::Vector2d turned(const Eigen::Vector2d& point, double z) const;    // m
  Eigen::Vector2d untwisted(const Eigen::Vector2d& point, double z) const; // m, the inverse
  // m, the point of the twisted body that a point x of its meshed geometry stands for, x lying
  // between the layer planes z_below and z_above. A hexahedron's edge between two layers is the
  // chord of its nodes' helix: a trilinear point is the section point q turned by the blend
  // (1 − t)·R(φ_below) + t·R(φ_above) = ρ·R(φ_below + ψ), which lies inside the helicoid by
  // r·(1 − ρ) (r·Δφ²/8 at mid-layer). This returns R(φ(z))·q, on the helicoid.
  Eigen::Vector3d on_helix(const Eigen::Vector3d& x, double z_below, double z_above) const;
};

struct PlanarBody
{
  std::string name;                // physical group name, e.g. "pinion body"
  int material_id = 1;             // physical tag (deal.II material id), > 0; may be shared
  BoundaryLoop outer;              // the body's outline
  std::vector<BoundaryLoop> holes; // bores, pin holes
  std::vector<PlanarFill> fills;   // 3D partial-width faults (the outline is the faulty one)
};

struct PlanarModel
{
  std::vector<PlanarBody> bodies;            // disjoint bodies (they may touch at points)
  std::map<int, std::string> boundary_names; // boundary id -> physical group name
  // 3D only: after the extrusion every node of a body with material id m moves in-plane by
  // node_offset(m, x) (m; x the node, m): the lead modifications of gear teeth
  // (geometry/tooth_modification_lead.h). Empty: no node moves.
  std::function<Eigen::Vector2d(int, const Eigen::Vector3d&)> node_offset;
  // 3D only, the extrusion path (geometry/face_width.cc): the bodies listed by material id are
  // twisted along z (helical gears); the others are extruded straight.
  std::map<int, BodyTwist> twist;
};

// A point where the mesh must be fine (a predicted contact): cells of `size` within `radius`.
struct SizeFocus
{
  Eigen::Vector2d point = Eigen::Vector2d::Zero(); // m, scene frame
  double size = 1e-5;                              // m, h_c there
  double radius = 2e-4;                            // m
};

// Target cell size: a focus's size within its radius, then growing linearly with distance at
// `growth_rate` (size increase per unit distance) up to the coarse size: the constant
// `body_size`, or `coarse_size(point)` where a scene lets the size grow further away from the
// region that matters (deep in a gear rim), never above `largest_size`.
struct SizeGrading
{
  std::vector<SizeFocus> foci;
  double growth_rate = 0.25; // m/m; 0.25 keeps neighbour size ratios near 1.3
  double body_size = 5e-4;   // m
  std::function<double(const Eigen::Vector2d&)> coarse_size; // m; empty: body_size everywhere
  double largest_size = 5e-4; // m, upper bound of coarse_size (gmsh's size limit)
  // -, the contact_scale of the first generation. gmsh's longest edges at a focus reach about
  // 1.45 times the requested size on convex–convex contacts (gear teeth, cylinders), so 0.6
  // meets h_c at once there; a scene that needs less says so (if an edge at a contact still
  // exceeds h_c, the mesh is generated again finer, at the cost of a whole generation).
  double initial_contact_scale = 0.6;

  // m; `contact_scale` scales the focus sizes only (not the coarse sizes or the growth): the
  // mesher aims below h_c with it because gmsh's edges scatter around the requested size.
  double size_at(const Eigen::Vector2d& point, double contact_scale = 1.) const;
  double smallest_size() const; // m, over the foci and the body size
};

struct MeshOptions
{
  unsigned int dimension = 2; // 2: quadrilaterals in the xy-plane; 3: hexahedra
  double face_width = 0.;     // m, extrusion length along +z (3D only)
  unsigned int layers = 8;    // hexahedron layers across the face width (3D only)
  // -, the fewest layers the scene accepts (a helical pair's twist rule): a cell estimate over
  // the limit names the layers only when fewer would still be accepted, else the sizes.
  unsigned int least_layers = 1;
  // -, FE_Q degree of the solve the mesh is made for: a 3D estimate is held to the memory of its
  // direct solve (errors/limits.h), whose unknowns per hexahedron grow as degree³.
  unsigned int element_degree = 1;
  // bytes, the most one 3D contact solve of the mesh may take on one process (estimated from
  // the hexahedra at element_degree); errors/limits.h's 16 GB unless the user has more
  // (Mesh/memory limit).
  double memory_limit = limits::max_solve_bytes_3d;
  int side_face_boundary_id = 0; // boundary id of the z = 0 and z = face width faces (3D)
  std::string file;              // output path of the ASCII .msh 4.1 file
};

struct MeshStatistics
{
  unsigned long n_cells = 0; // quadrilaterals (2D) or hexahedra (3D)
  unsigned long n_vertices = 0;
  std::map<int, unsigned long> cells_per_body;                 // material id -> cell count
  double min_scaled_jacobian = 0.;                             // -, 1 for a perfect square/cube
  double mean_scaled_jacobian = 0.;                            // -
  Eigen::Vector3d worst_cell_centre = Eigen::Vector3d::Zero(); // m, where the minimum occurs
  // -, over the foci: the longest in-plane edge of the cells with a corner within the focus
  // size of its point, divided by that size (the achieved contact size; ≤ 1 is guaranteed).
  double largest_edge_ratio_at_focus = 0.;
  double contact_scale = 1.;         // -, the scale of the contact-driven size that achieved it
  unsigned int meshing_attempts = 0; // -, mesh generations needed to achieve it
  double time_geometry = 0.;         // s, building the gmsh model
  double time_meshing = 0.;          // s, generating the mesh
  double time_checking = 0.;         // s, element types and quality
  double time_writing = 0.;          // s, writing the .msh file
  unsigned long removed_cells = 0;   // -, hexahedra of fills left out (PlanarFill::removed)
  unsigned int layers = 0;           // -, hexahedron layers across the face (3D; 0 in 2D)
};

// Scaled Jacobian of a cell given its corner coordinates in gmsh/deal.II-lexicographic order
// (gmsh order: quad 0-1-2-3 counter-clockwise; hex bottom 0-3, top 4-7): the minimum over the
// corners of the corner's Jacobian determinant divided by the product of its edge lengths.
double scaled_jacobian_quad(const std::vector<Eigen::Vector3d>& corners);
double scaled_jacobian_hex(const std::vector<Eigen::Vector3d>& corners);

// Work estimate of a mesh, from the size field before meshing.
struct MeshEstimate
{
  double area = 0.;         // m², of the bodies (outlines minus holes)
  double fine_cells = 0.;   // -, within the fine radii of the foci
  double graded_cells = 0.; // -, where the size grows from a focus size to the body size
  double body_cells = 0.;   // -, the rest at the body size
  double cells = 0.;        // -, total (3D: times the layers)
  double unknowns = 0.;     // -, 3D: of FE_Q(element_degree) on the cells (0 in 2D)
  double solve_bytes = 0.;  // bytes, 3D: of one direct contact solve of them (0 in 2D)
};

// Cells ≈ ∫ c/h(x)² dA over the bodies, summed in closed form per focus (disc of h_c within
// the fine radius, annulus where h grows linearly to the body size) plus the rest at the body
// size; each focus's part is capped at the whole area at its size. Foci that overlap (a rolling
// sweep's band of foci along every flank) are counted once: the same integral over their union,
// sampled on a grid, when it is smaller than the per-focus sum. Measured against gmsh's
// counts on the scenes: 0.66 to 3.4 times the real count (mesh_size.cc), enough to refuse a
// mesh far beyond the limit; not a cost prediction.
MeshEstimate estimate_mesh(const PlanarModel& model, const SizeGrading& grading,
                           const MeshOptions& options);

// Whether the estimate is over the work limit (errors/limits.h): 2D its cells over
// limits::max_cells_2d, 3D the memory of its direct solve over limits::max_solve_bytes_3d.
bool over_work_limit(const MeshEstimate& estimate, const MeshOptions& options);

// InputError naming "Mesh/contact size" (or "Mesh/body size" when the coarse part dominates, or
// "Mesh/layers" when they do), with the estimate, when over_work_limit. mesh_planar_model calls
// it before gmsh starts.
void check_mesh_estimate(const PlanarModel& model, const SizeGrading& grading,
                         const MeshOptions& options);

// Meshes `model` with the sizes of `grading`, checks that every cell is a quadrilateral
// (hexahedron) with positive scaled Jacobian and writes options.file. Throws InputError for
// inconsistent geometry and SolverFailure when gmsh fails or the checks do not pass.
MeshStatistics mesh_planar_model(const PlanarModel& model, const SizeGrading& grading,
                                 const MeshOptions& options);
} // namespace gearstiff::geometry
