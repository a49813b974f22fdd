// What every scene shares: the ids written into the mesh, the mesh settings a user chooses, the
// plain SceneInfo handed to the FE module, the Hertz half-width estimate that sets the default
// contact size, and small outline builders.
//
// A scene has two kinds of bodies ("first", "second": pinion/wheel, disc/rollers, lower/upper
// cylinder). Their ids are the same in every scene so the FE and contact code need one mapping:
//
//   material ids (cells)      1 first body (pinion, disc, cylinder A)
//                             2 second body (wheel, rollers, cylinder B)
//   boundary ids (faces)      0 free surface (deal.II's default; not written to the file)
//                             1 first bore        2 second bore (roller pins)
//                             3 first candidate contact surface (pinion flanks, disc lobes)
//                             4 second candidate contact surface (wheel flanks, rollers)
//                             5 first sector cuts 6 second sector cuts
//                             7 side faces z = 0 and z = face width (3D only)
//                             8 output-pin holes of a cycloid disc
#pragma once

#include "geometry/mesh_planar.h"

#include <Eigen/Core>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace gearstiff::geometry
{
namespace scene_ids
{
constexpr int first_body = 1;
constexpr int second_body = 2;

constexpr int free_surface = 0;
constexpr int first_bore = 1;
constexpr int second_bore = 2;
constexpr int first_contact = 3;
constexpr int second_contact = 4;
constexpr int first_cuts = 5;
constexpr int second_cuts = 6;
constexpr int side_faces = 7;
constexpr int output_pin_holes = 8;

// The same ids under the names of a gear pair.
constexpr int pinion_body = first_body;
constexpr int wheel_body = second_body;
constexpr int pinion_bore = first_bore;
constexpr int wheel_bore = second_bore;
constexpr int pinion_flanks = first_contact;
constexpr int wheel_flanks = second_contact;
constexpr int pinion_cuts = first_cuts;
constexpr int wheel_cuts = second_cuts;
} // namespace scene_ids

// Mesh choices common to every scene. Zero selects the documented default.
struct SceneMeshSettings
{
  unsigned int dimension = 2; // -, 2: quadrilaterals; 3: hexahedra extruded over the face width
  unsigned int layers = 8;    // -, hexahedron layers across the face width (3D)
  // m, h_c, cell size at the predicted contact points; 0: at each contact a tenth of its
  // Hertz half-width estimate.
  double contact_size = 0.;
  // m, radius around each contact point meshed at h_c; 0: 1.5 times its Hertz half-width (the
  // contact zone, plus a margin far larger than its shift under load: the pair deflection is ~6 µm
  // against a ≈ 80 µm in the split-path case).
  double fine_radius = 0.;
  double growth_rate = 0.25; // m/m, size increase per unit distance beyond the fine radius
  double body_size = 5e-4;   // m, the coarse size in the teeth (bodies) away from contact
  // m, where a scene lets the size keep growing (gear rims below the root circle), it stops at
  // this size; 0: four times the body size.
  double rim_size = 0.;
  // The body size is a default (`auto`), not the user's: in 3D, where the layers multiply the
  // cells, a scene whose estimate exceeds the work limit (errors/limits.h: the memory of a 3D
  // solve at MeshOptions::element_degree) coarsens it in steps
  // of body_size_step, at most body_size_steps of them, before refusing (mesh_scene). A wide
  // helical face needs its layers for the contact lines and its contact size for the Hertz
  // zone; only the bodies away from the flanks can give (docs/helical.md "Default mesh").
  bool body_size_fits_cell_limit = false;
  // -, MeshOptions::least_layers: set by the scene (a helical pair's twist rule), not a user
  // parameter.
  unsigned int least_layers = 1;
  // -, MeshOptions::element_degree: the FE_Q degree the scene is solved with (set by the
  // analysis from its elasticity parameters; the `mesh` command's deck is first order).
  unsigned int element_degree = 1;
  // bytes, MeshOptions::memory_limit (Mesh/memory limit): the estimate a 3D scene is held to,
  // and what the automatic body size coarsens to fit.
  double memory_limit = limits::max_solve_bytes_3d;
  // -, 15 %: the face-width study's steps; 5 steps are 2.01 × the default.
  static constexpr double body_size_step = 1.15;
  static constexpr unsigned int body_size_steps = 5;
  // -, SizeGrading::initial_contact_scale: set by the scene, not a user parameter.
  double initial_contact_scale = 0.6;
};

// A predicted contact point (kinematics, before load).
struct SceneContact
{
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  // m, scene frame
  Eigen::Vector2d normal = Eigen::Vector2d::Zero(); // unit, out of the first body (towards 2nd)
  double first_curvature_radius = 0.;  // m, of the first body's surface at the point (> 0 convex)
  double second_curvature_radius = 0.; // m, of the second body's surface (> 0 convex)
  double normal_force = 0.;            // N, share of the load assumed for the Hertz estimate
  double hertz_half_width = 0.;        // m, plane-strain Hertz estimate a
  double gap = 0.;                     // m, initial gap along the normal (0: touching)
  double contact_size = 0.;            // m, h_c used at this contact
  double fine_radius = 0.;             // m, radius meshed at h_c around it
  int first_feature = 0;  // tooth index of the pinion (roller-facing lobe of a disc), or 0
  int second_feature = 0; // tooth index of the wheel (roller index), or 0
};

// A scene-specific number (extent, position) for reports: value in the SI unit named.
struct SceneQuantity
{
  std::string key;         // snake_case, e.g. "pinion_bore_radius"
  double value = 0.;       // in `unit`
  std::string unit;        // "m", "rad" or "-"
  std::string description; // human label
};

// What the FE module needs to know about a written scene. Plain data; SI units.
struct SceneInfo
{
  std::string kind; // "gear pair", "cylinders", "blocks", "cycloid"
  std::string file; // path of the written ASCII .msh 4.1 file
  unsigned int dimension = 2;
  double face_width = 0.; // m, extrusion length (3D) and the width the loads refer to

  // Ids written into the mesh (see scene_ids); names as in the file's physical groups.
  std::map<int, std::string> material_names; // material id -> name
  std::map<int, std::string> boundary_names; // boundary id -> name

  Eigen::Vector2d first_centre = Eigen::Vector2d::Zero();  // m, rotation centre (pinion, disc)
  Eigen::Vector2d second_centre = Eigen::Vector2d::Zero(); // m, rotation centre (wheel, ring)
  double first_rotation = 0.;  // rad, angle applied to the first body's profile (CCW)
  double second_rotation = 0.; // rad, angle applied to the second body's profile (CCW)

  std::vector<SceneContact> contacts; // predicted contact points
  // m, a reference segment: the line of action T1 -> T2 of a gear pair (empty otherwise).
  std::vector<Eigen::Vector2d> reference_line;
  std::vector<SceneQuantity> quantities; // extent and position of the scene, for reports

  double contact_size = 0.; // m, smallest h_c over the contacts (each: SceneContact)
  double fine_radius = 0.;  // m, largest fine radius over the contacts
  double body_size = 0.;    // m
  double rim_size = 0.;     // m, largest size (deep in rims)
  double growth_rate = 0.;  // m/m

  MeshStatistics mesh;    // cell counts, quality, timings of the meshing stage
  double time_total = 0.; // s, scene construction + meshing + writing
};

// Plane-strain Hertz contact half-width of two parallel cylinders (kinematics/hertz.h), after
// checking that the load and the relative curvature are positive (InputError otherwise).
// force_per_length in N/m, radii in m (a flat: infinity; concave: negative), moduli in Pa.
double hertz_half_width(double force_per_length, double radius_1, double radius_2,
                        double young_modulus_1, double poisson_ratio_1, double young_modulus_2,
                        double poisson_ratio_2);

// Resolves the defaults of `settings` from the Hertz half-widths of `contacts` (filling each
// contact's contact_size and fine_radius) and returns the size grading focused on them.
// `depth_below_surface` (m, optional) lets the size grow beyond the body size with depth into a
// rim, at the growth rate, up to the rim size.
SizeGrading
contact_size_grading(const SceneMeshSettings& settings, std::vector<SceneContact>& contacts,
                     const std::function<double(const Eigen::Vector2d&)>& depth_below_surface = {});

// A circle as a closed loop of four quarter arcs carrying `boundary_id` (m).
BoundaryLoop circle_loop(const Eigen::Vector2d& centre, double radius, int boundary_id);

// Arc pieces from polar angle `from` to `to` (rad, either direction) about `centre`, split so no
// piece exceeds a quarter turn (gmsh arcs must stay below half a turn).
std::vector<BoundaryPiece> arc_pieces(const Eigen::Vector2d& centre, double radius, double from,
                                      double to, int boundary_id);

// Meshes `model` with `settings` (resolving the defaults from the contacts), writes `file` and
// fills the common part of SceneInfo (ids, sizes, contacts, statistics, file).
// `extra_foci`: further places meshed finer (a tooth fault's crack, geometry/tooth_fault.h); the
// SceneInfo sizes stay those of the contacts.
SceneInfo mesh_scene(const PlanarModel& model, std::vector<SceneContact> contacts,
                     const SceneMeshSettings& settings, double face_width, const std::string& file,
                     const std::function<double(const Eigen::Vector2d&)>& depth_below_surface = {},
                     const std::vector<SizeFocus>& extra_foci = {});
} // namespace gearstiff::geometry
