// A written scene as a CalculiX/Abaqus input deck (.inp), so that `ccx -i scene` solves the same
// mesh and load case as gearstiff with no editing: nodes, elements, one element set per body, an
// element-face surface and a node set per boundary group, the material, the candidate contact
// pairs (penalty face-to-face contact, Coulomb friction), bores as rigid bodies whose rotation
// nodes carry the torques (gear pair: the pinion bore; cycloid: the disc bearing, torque-free,
// and the output member over every pin bore) or, for the Hertz cylinders, a flat face as a
// rigid body whose reference node carries the force, bores or faces held fixed, and the output
// requests.
//
// Element choice. 3D scenes are written as C3D8 (fully integrated, the same trilinear element as
// deal.II's FE_Q(1) hexahedron). 2D scenes are written by default as a one-element-thick C3D8
// slice of thickness `slice_thickness` with u_z = 0 at every node, which is exactly plane strain
// with FE_Q(1) quadrilaterals: ccx expands CPE4/CPS4 into such a C3D8 slice internally anyway
// (ccx manual, "Four-node plane strain element"), but with generated nodes tied by MPCs, and its
// rigid bodies, contact surfaces and printed node results then refer to nodes that are not in
// the deck; writing the slice makes the solved model the written one. CPE4/CPS4 are available
// (Element2D::plane_strain/plane_stress) for other solvers and for re-import into gearstiff;
// ccx 2.20 did not converge with them once the rigid bore was released (docs/calculix.md).
//
// Names. A physical group "pinion body" becomes the set PINION_BODY (upper case, spaces to '_');
// fem/abaqus_reader.h maps them back. Units: those of the mesh (SI: m, N, Pa, N·m).
//
// Load case (ccx needs a closed contact before a torque-only rigid body is statically
// determined): step 1 turns every rigid body's rotation node by its `closing_rotation` (a
// fraction of the expected deflection, so every contact that carries load is closed); step 2
// releases them and applies the torques. The rotation of a rotation node at the end of step 2 is
// its body's Δφ.
#pragma once

#include "geometry/scene_common.h"
#include "geometry/scene_cycloid.h"
#include "geometry/scene_cylinders.h"
#include "geometry/scene_gear_pair.h"

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace gearstiff::geometry
{
// The cells and labelled boundary facets of a written .msh (first-order quadrilaterals and
// lines in 2D, hexahedra and quadrilaterals in 3D), node indices 0-based into `nodes`.
struct SceneMesh
{
  unsigned int dimension = 2;
  std::vector<Eigen::Vector3d> nodes; // m
  struct Cell
  {
    std::vector<unsigned int> nodes; // gmsh order (quad counter-clockwise; hex bottom, top)
    int material_id = 0;
  };
  struct Facet
  {
    std::vector<unsigned int> nodes;
    int boundary_id = 0;
  };
  std::vector<Cell> cells;
  std::vector<Facet> facets; // boundary facets with a non-zero boundary id
};

// Reads a .msh written by mesh_planar_model through gmsh's API. SolverFailure when the file
// cannot be opened or holds cells other than quadrilaterals (hexahedra).
SceneMesh read_scene_mesh(const std::string& msh_file, unsigned int dimension);

enum class Element2D
{
  slice,        // one-element-thick C3D8, u_z = 0: plane strain (default, see above)
  plane_strain, // CPE4
  plane_stress  // CPS4
};

// Parses "slice", "CPE4" or "CPS4" (InputError naming `parameter` otherwise).
Element2D parse_element_2d(const std::string& text, const std::string& parameter);

// A rigid body over the nodes of one boundary group (a bore or a flat face), its REF NODE at
// `centre`, its ROT NODE's u_1, u_2 (rotations about x, y) held. Its node sets are NAME_REF and
// NAME_ROT. Two kinds:
// - turning (default): the REF NODE is held in translation; the rotation about z is prescribed
//   to `closing_rotation` in step 1 and free under `torque` in step 2 (torque 0: a bearing);
// - pushed: the rotation about z and the REF NODE's u_x (and u_z) are held; its u_y is
//   prescribed to `closing_displacement` in step 1 and free under `force` in step 2 (the
//   loaded flat face or bore of the cylinders scene). U and RF of its REF NODE are printed.
struct AbaqusRigidBody
{
  std::string name;                                 // deck prefix, e.g. DRIVEN
  int boundary_id = 0;                              // the group whose nodes it holds
  Eigen::Vector2d centre = Eigen::Vector2d::Zero(); // m, its axis (z direction)
  double torque = 0.;                               // N·m about +z in step 2
  double closing_rotation = 0.;                     // rad, prescribed in step 1
  bool pushed = false;                              // translates along y instead of turning
  double force = 0.;                                // N along +y in step 2 (pushed)
  double closing_displacement = 0.;                 // m along +y, prescribed in step 1 (pushed)
};

// A part of a boundary group written as a surface of its own: the facets of `boundary_id` whose
// centroid lies nearer to centres[index] than to any other of `centres` (one roller of the
// group of all roller surfaces, the lobe faces facing it), so that each has its contact pair.
struct AbaqusSurfacePart
{
  std::string name; // deck surface name
  int boundary_id = 0;
  std::vector<Eigen::Vector2d> centres; // m
  unsigned int index = 0;
};

struct AbaqusDeckSpec
{
  Element2D element_2d = Element2D::slice;
  double slice_thickness = 0.;  // m, 2D: thickness of the slice / of CPE4, CPS4 (face width)
  bool plane_stress = false;    // slice: plane stress through plane-strain-equivalent constants
  double young_modulus = 210e9; // Pa, every body
  double poisson_ratio = 0.3;   // -
  double friction = 0.;         // -, Coulomb μ between the contact surfaces (0: none)
  double penalty = 0.;          // Pa/m, slope of the linear pressure-overclosure law
  double stick_slope = 0.;      // Pa/m, tangential penalty of friction (used when μ > 0)
  std::vector<AbaqusSurfacePart> surface_parts;                   // surfaces beyond the groups
  std::vector<std::pair<std::string, std::string>> contact_pairs; // (slave, master) surfaces
  std::vector<AbaqusRigidBody> rigid_bodies; // the first one's ROT NODE is printed as Δφ
  bool print_contact_forces = false;         // *CONTACT PRINT CF per contact pair
  std::vector<int> fixed_bores;              // boundary ids of the groups held fixed
  std::string title;                         // *HEADING text
};

// The deck for the gear-pair scene: pinion flanks (slave) on wheel flanks (master) of the tooth
// pairs inside the path of contact (scene.contact_pairs, the pairs `gearstiff stiffness` pairs;
// see gear_pair_deck_spec in the .cc for why not every modelled pair), pinion bore driven by
// spec.pinion_torque, wheel bore fixed, Young's modulus and Poisson's ratio of `spec`;
// `penalty_factor` (-) times E/h_c gives the penalty slope, the closing rotation is a tenth of
// the rotation an ISO-like 14 N/(mm·µm) stiffness would give plus the turn that closes the
// designed separation of modified teeth (scene.unloaded_transmission_error / r_b1).
AbaqusDeckSpec gear_pair_deck_spec(const GearPairSceneSpec& spec, const GearPairScene& scene,
                                   double friction, double penalty_factor);

// A cycloid scene's deck closes no output-pin play: InputError naming the pin radius when the
// scene has play (hole − pin − e above a nanometre). Checked before meshing and by
// cycloid_deck_spec.
void check_cycloid_deck_play(const CycloidSceneSpec& spec);

// The deck for the cycloid scene (geometry/scene_cycloid.h, with its output pins meshed), the
// load case of stiffness/cycloid_loads.h: the disc bore a rigid body whose centre is held and
// which turns freely (the eccentric bearing), the roller pins fixed, every output-pin bore on one
// rigid output member about the ring centre carrying `output_torque` (N·m, counter-clockwise > 0);
// one contact pair per roller within the scene's contact clearance (roller surface on the lobe
// faces nearest to it) and per output pin (pin surface on its hole), frictionless; plane stress
// of the disc width. InputError("Cycloid scene/output pin bodies") without meshed pins,
// InputError("Abaqus deck/output torque") for a zero torque.
AbaqusDeckSpec cycloid_deck_spec(const CycloidSceneSpec& spec, const SceneInfo& info,
                                 double output_torque, double penalty_factor);

// The deck for the cylinders scene (geometry/scene_cylinders.h), the Hertz case of `gearstiff
// contact` as a load: cylinder 1's flat face (or bore) fixed, cylinder 2's flat face (or bore) a
// rigid body pushed down by F = spec.force_per_length times the slice thickness (the scene's
// length), turning and sliding sideways held, as gearstiff's built-in case moves its flat top
// face rigidly; cylinder 2's surface (slave) on cylinder 1's (master), Coulomb `friction`; the
// total contact force printed. The closing displacement of step 1 is a tenth of a²/R* (Hertz
// half-width a, R* = R1·R2/(R1 + R2)): the loaded approach is several times a²/R*.
AbaqusDeckSpec cylinders_deck_spec(const CylindersSceneSpec& spec, const SceneInfo& info,
                                   double friction, double penalty_factor);

// Writes `inp_file` from the mesh of `info.file`. InputError("Abaqus deck/...") for a spec that
// names ids the mesh lacks.
void write_abaqus_deck(const SceneInfo& info, const AbaqusDeckSpec& spec,
                       const std::string& inp_file);

// "pinion body" -> "PINION_BODY".
std::string abaqus_name(const std::string& group_name);
} // namespace gearstiff::geometry
