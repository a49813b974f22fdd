// Mesh stiffness of a spur gear pair from a frictional FE contact solve, after the load case of
// Reszuta & Drewniak 2015 (docs/references.md §1): a torque T1 on the pinion whose
// bore is free only to rotate (a rigid hub, torque-controlled), the wheel bore held fixed, tooth
// friction μ; the measured pinion rotation Δφ gives
//
//     k = T1 / (r_b1² · Δφ)                                     (docs/references.md §1, k'_j, k'_d)
//
// at exactly the applied torque: the rotation is the unknown of the solve, not a guess that is
// scaled afterwards. One GearMeshStiffness is one pinion position (one scene); sweeps over
// positions are built from it (see mesh_stiffness_sweep.h).
//
// Each modelled tooth pair j (pinion tooth j meshing wheel tooth −j, geometry/scene_gear_pair.h)
// becomes its own contact pair, so the load sharing between pairs is the exact sum of each pair's
// contact multipliers, not a split guessed afterwards. Without friction the pinion and wheel hub
// torques satisfy |T_wheel / T_pinion| = r_b2 / r_b1 exactly (every contact force acts along the
// line of action); the result carries both so callers can check it.
//
//   GearMeshStiffnessSettings settings;          // split-path pair, single-pair position
//   settings.scene.position = geometry::PairPosition::double_pair;
//   GearMeshStiffness<2> analysis(MPI_COMM_WORLD, settings);
//   const GearMeshStiffnessResult r = analysis.run();   // r.mesh_stiffness in N/m
#pragma once

#include "contact/contact_problem.h"
#include "fem/fields.h"
#include "fem/parameters.h"
#include "geometry/scene_gear_pair.h"
#include "stiffness/crack_tip.h"
#include "stiffness/face_load.h"

#include <functional>
#include <memory>
#include <mpi.h>
#include <string>
#include <vector>

namespace gearstiff::stiffness
{
// The scene the stiffness analysis uses unless told otherwise: the split-path pair with full
// rims and three teeth per gear and explicit mesh sizes (docs/accuracy.md: the cheapest scene
// within 1% of the converged single-pair stiffness).
geometry::GearPairSceneSpec default_stiffness_scene();
// Plane strain with Q2 elements.
fem::ElasticityParameters default_stiffness_elasticity();

// How the contact of the flanks is solved (Stiffness/contact model, docs/ltca.md).
enum class ContactModel
{
  finite_element,        // mortar contact on a mesh that resolves the Hertz zone (the reference)
  influence_coefficients // a coarse FE body's influence coefficients + the analytic near field
};

struct GearMeshStiffnessSettings
{
  // Gear pair, position, teeth modelled, bores, rim and mesh sizes (SI, see the header).
  geometry::GearPairSceneSpec scene = default_stiffness_scene();
  fem::ElasticityParameters elasticity = default_stiffness_elasticity(); // thickness: face width
  fem::LinearSolverParameters linear_solver;
  contact::ContactParameters contact; // μ and the active-set controls
  ContactModel contact_model = ContactModel::finite_element;
  // -, influence coefficients: grid points per flank over the path of contact (docs/ltca.md §2)
  unsigned int influence_grid_points = 64;
  // Helical pairs (Mesh/helical flanks): the contact measures its gaps between the meshed
  // surfaces, whose edges between two layers are chords of the helices (false, the default: the
  // model CalculiX solves on the exported deck), or between the flanks' involute helicoids
  // (true). docs/helical.md "Layers and the helicoids".
  bool helicoid_flanks = false;
  double pinion_torque = 49.4; // N·m, T1 > 0 drives the pinion counter-clockwise
  // N·m, ascending: a sweep solves every position under each (GearMeshStiffness::run_torques);
  // empty: pinion_torque alone.
  std::vector<double> torques;
  fem::Material material;                // both gears (steel 210 GPa, 0.3: not published)
  std::string scene_file;                // path of the .msh to write (rank 0 of the communicator)
  std::string output_directory;          // VTU of the solved position here; empty: none
  std::string output_base = "stiffness"; // VTU base name
  // Shared by the positions a sweep solves in turn (null: none): each starts from the zone the
  // previous one converged to (contact.warm_start) and leaves its own for the next.
  std::shared_ptr<std::vector<contact::ContactZone>> warm_start;
  // Called with one line per stage of run() (scene, setup, solve; with the elapsed time) on
  // rank 0 of the analysis' communicator; empty: silent.
  std::function<void(const std::string&)> progress;
};

// One tooth pair in the scene and what it carries.
struct ToothPairLoad
{
  int pair = 0;              // -, j: pinion tooth j meshing wheel tooth −j (0: reference)
  double position = 0.;      // m, kinematic contact point along the line of action from T1
  double normal_force = 0.;  // N, Σ of the pair's normal contact multipliers
  double load_share = 0.;    // -, normal force over the sum over all pairs
  double max_pressure = 0.;  // Pa
  double contact_length = 0; // m, extent of the closed nodes (2D: across the profile)
  unsigned int closed_nodes = 0;
  // Where the load acts. The FE contact forces act along the pinion flank's normals at the
  // closed nodes; the normal at roll length ℓ_i is the line of action turned by −(ℓ_i − ℓ)/r_b1
  // about the pinion axis, so the pair's resultant leaves the line of action when the loaded
  // zone is not centred on the kinematic point ℓ (tooth deflection, a zone cut off at a tip).
  double resultant = 0.;       // N, magnitude of the pair's contact force on the pinion
  double force_deviation = 0.; // rad, CCW angle of that force from −u
  double closed_roll_min = 0.; // m, smallest roll length √(r² − r_b1²) of a closed pinion node
  double closed_roll_max = 0.; // m, largest
  // Where the pair's largest pressure acts (its closed pinion node of max_pressure): a peak
  // within one contact cell of a tip edge is a tip corner's edge pressure, not a Hertz pressure.
  double max_pressure_roll = 0.; // m, roll length √(r² − r_b1²) of that node
  double max_pressure_face = 0.; // m, its axial coordinate from the middle of the face (2D: 0)
  // m, the same point on the wheel, on the path's scale: where the wheel's involute through it
  // (its distance from the wheel axis) meets the line of action, from T1. On the line of action
  // it equals max_pressure_roll; a wheel tip corner pressing the pinion off the line lies at A
  // on this scale wherever the pinion node is (a corner near a helical face end, issue 46).
  double max_pressure_wheel_roll = 0.;

  // Every member, once: serialisation (results cross MPI ranks, fem/parallel.h) and the
  // completeness check of tests/stiffness/test_result_fields.cc use this list.
  template <class Self, class Visit>
  static void for_each_field(Self& self, Visit&& visit)
  {
    visit("pair", self.pair);
    visit("position", self.position);
    visit("normal_force", self.normal_force);
    visit("load_share", self.load_share);
    visit("max_pressure", self.max_pressure);
    visit("contact_length", self.contact_length);
    visit("closed_nodes", self.closed_nodes);
    visit("resultant", self.resultant);
    visit("force_deviation", self.force_deviation);
    visit("closed_roll_min", self.closed_roll_min);
    visit("closed_roll_max", self.closed_roll_max);
    visit("max_pressure_roll", self.max_pressure_roll);
    visit("max_pressure_face", self.max_pressure_face);
    visit("max_pressure_wheel_roll", self.max_pressure_wheel_roll);
  }
  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    fem::serialize_fields(archive, *this);
  }
};

struct GearMeshStiffnessResult
{
  // Position.
  double pinion_roll_angle = 0.;    // rad, ℓ_ref / r_b1 of the reference pair
  double reference_position = 0.;   // m, ℓ_ref along the line of action from T1
  double mesh_position = 0.;        // -, (ℓ_ref − A)/p_bt: the reference pair's roll position
  unsigned int kinematic_pairs = 0; // -, pairs in contact by the kinematics (no load)
  unsigned int loaded_pairs = 0;    // -, pairs carrying more than 1e-6 of the load
  // Stiffness and its ingredients.
  double pinion_torque = 0.;      // N·m, T1 applied
  double pinion_rotation = 0.;    // rad, Δφ from the unloaded touching position (> 0)
  double initial_gap = 0.;        // m, smallest initial normal gap of the meshed flanks
  double pinion_base_radius = 0.; // m, r_b1
  double wheel_base_radius = 0.;  // m, r_b2
  double mesh_stiffness = 0.;     // N/m, T1/(r_b1²·Δφ)
  // m, the loaded transmission error (wheel fixed): r_b1·Δφ + the unloaded one below, i.e. the
  // pinion's roll from the position where unmodified flanks would touch.
  double transmission_error = 0.;
  // m, the modifications' kinematic error at this position (geometry::GearPairScene): the
  // smallest designed separation of the pairs in contact; 0 for unmodified teeth.
  double unloaded_transmission_error = 0.;
  double wheel_torque = 0.;      // N·m, reaction of the fixed wheel bore about its axis
  double torque_ratio = 0.;      // -, |T_wheel / T1| (= r_b2/r_b1 without friction, for
                                 //    forces on the line of action: ToothPairLoad)
  double pinion_hub_torque = 0.; // N·m, reaction at the pinion hub (−T1 to solver precision)
  // Contact and root.
  std::vector<ToothPairLoad> pairs; // modelled pairs with contact candidates, by j
  double max_contact_pressure = 0.; // Pa, over all pairs
  double pinion_root_stress = 0.;   // Pa, largest first principal stress on the pinion fillets
  double wheel_root_stress = 0.;    // Pa, the same on the wheel fillets
  // 2D, every root crack whose faces meet (the pinion's faulty teeth, then the wheel's, by
  // index): K_I, K_II at its tip (stiffness/crack_tip.h); empty without such cracks.
  std::vector<CrackTipFactors> crack_tips;
  // 3D: the line load across the face width of every pair (stiffness/face_load.h) and
  // K_Hβ = peak/mean of the pairs' summed line load (-; 2D: empty and 0).
  std::vector<FaceLoadPoint> face_load;
  double face_load_factor = 0.;
  // 3D: the forces of the mesh on the pinion (Σ of the pairs' contact resultants): along the
  // line of action (F_bt, > 0 against the pinion's turn), along +z (F_a, a helical pair's axial
  // force; 0 for spur), and the magnitude of their moment about the x and y axes through the
  // pinion centre at the middle of the face (tilting moment; the closed nodes' pressure-weighted
  // centre as each pair's point of action).
  double tangential_force = 0.; // N
  double axial_force = 0.;      // N
  double tilting_moment = 0.;   // N·m
  // Model and cost.
  unsigned int dimension = 2;
  unsigned int n_cells = 0;
  unsigned int n_dofs = 0;
  double contact_size = 0.; // m, h_c of the scene
  // m, the body size the scene was meshed with (an automatic one after any coarsening to fit
  // the memory limit: geometry::SceneMeshSettings::body_size_fits_cell_limit)
  double body_size = 0.;
  // 3D, Mesh/layer extrapolation (stiffness/layer_extrapolation.h): the layers L of the coarser
  // solve (0: not extrapolated) and k solved on L and on 2L layers (N/m); the values above that
  // the layer height's error enters (k, TE, load shares, forces) are then extrapolated from them.
  unsigned int extrapolated_layers = 0;
  double stiffness_coarse_layers = 0.; // N/m, k on L layers
  double stiffness_fine_layers = 0.;   // N/m, k on 2L layers
  unsigned int active_set_iterations = 0;
  double scene_time = 0.;         // s, wall: geometry, meshing, writing (rank 0)
  double setup_time = 0.;         // s, wall: reading, DoFs, stiffness, mortar coupling
  double solve_time = 0.;         // s, wall: contact iterations (assembly + linear solves)
  double factorization_time = 0.; // s, wall: the stiffness factorization, when this run made it
  double total_time = 0.;         // s, wall: the whole run
  std::vector<std::string> output_files; // VTU/PVTU written (relative to the directory)

  // Every member, once: serialisation (results cross MPI ranks, fem/parallel.h) and the
  // completeness check of tests/stiffness/test_result_fields.cc use this list.
  template <class Self, class Visit>
  static void for_each_field(Self& self, Visit&& visit)
  {
    visit("pinion_roll_angle", self.pinion_roll_angle);
    visit("reference_position", self.reference_position);
    visit("mesh_position", self.mesh_position);
    visit("kinematic_pairs", self.kinematic_pairs);
    visit("loaded_pairs", self.loaded_pairs);
    visit("pinion_torque", self.pinion_torque);
    visit("pinion_rotation", self.pinion_rotation);
    visit("initial_gap", self.initial_gap);
    visit("pinion_base_radius", self.pinion_base_radius);
    visit("wheel_base_radius", self.wheel_base_radius);
    visit("mesh_stiffness", self.mesh_stiffness);
    visit("transmission_error", self.transmission_error);
    visit("unloaded_transmission_error", self.unloaded_transmission_error);
    visit("wheel_torque", self.wheel_torque);
    visit("torque_ratio", self.torque_ratio);
    visit("pinion_hub_torque", self.pinion_hub_torque);
    visit("pairs", self.pairs);
    visit("max_contact_pressure", self.max_contact_pressure);
    visit("pinion_root_stress", self.pinion_root_stress);
    visit("wheel_root_stress", self.wheel_root_stress);
    visit("crack_tips", self.crack_tips);
    visit("face_load", self.face_load);
    visit("face_load_factor", self.face_load_factor);
    visit("tangential_force", self.tangential_force);
    visit("axial_force", self.axial_force);
    visit("tilting_moment", self.tilting_moment);
    visit("dimension", self.dimension);
    visit("n_cells", self.n_cells);
    visit("n_dofs", self.n_dofs);
    visit("contact_size", self.contact_size);
    visit("body_size", self.body_size);
    visit("extrapolated_layers", self.extrapolated_layers);
    visit("stiffness_coarse_layers", self.stiffness_coarse_layers);
    visit("stiffness_fine_layers", self.stiffness_fine_layers);
    visit("active_set_iterations", self.active_set_iterations);
    visit("scene_time", self.scene_time);
    visit("setup_time", self.setup_time);
    visit("solve_time", self.solve_time);
    visit("factorization_time", self.factorization_time);
    visit("total_time", self.total_time);
    visit("output_files", self.output_files);
  }
  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    fem::serialize_fields(archive, *this);
  }
};

template <int dim>
class GearMeshStiffness
{
public:
  // Checks the settings (InputError naming the parameter) before anything is meshed.
  GearMeshStiffness(MPI_Comm mpi_communicator, const GearMeshStiffnessSettings& settings);

  // Scene, contact solve, evaluation. Throws InputError for an impossible scene (e.g. no pair
  // in contact), SolverFailure when the contact iteration fails or the pinion does not rotate
  // forward (the torque did not close the mesh).
  GearMeshStiffnessResult run();

  // The same position under each torque of `torques` (N·m, > 0, ascending; InputError naming
  // stiffness_parameter::torques otherwise), one result per torque in that order. One scene,
  // one factorization: the stiffness operator does not depend on the torque, only the contact
  // active set does. The first torque is solved as run() solves it (its result is bit-identical
  // to run() at that torque); each further torque is one more step of the contact continuation
  // (contact::ContactProblem::solve_next_step) from the converged state of the previous one: a
  // monotone loading path, which with friction (incremental Coulomb) differs from a fresh solve
  // by the friction's path dependence only.
  std::vector<GearMeshStiffnessResult> run_torques(const std::vector<double>& torques);
  // Rolling (a sweep with one mesh, stiffness/mesh_stiffness_rolling.cc): the reference pair at
  // `position` (m from T1 along the line of action). The first call meshes the scene at its own
  // position (settings.scene: roll angle) with the flanks refined for every position of
  // settings.scene.swept_positions, and factorizes the stiffness; every call turns both bodies
  // rigidly to `position`, pairs the teeth in contact there afresh and solves the contact on the
  // one factorization. `output_base`: VTU base name of this position (bodies in their own,
  // unturned frames). InputError naming "Stiffness/sweep mesh" for a position outside the
  // swept ones (the flanks are refined only there).
  GearMeshStiffnessResult roll_to(double position, const std::string& output_base);
  // roll_to under each torque of `torques` (as run_torques: the first solved afresh at the
  // position, each further one a continuation step), one result per torque in that order.
  std::vector<GearMeshStiffnessResult> roll_to_torques(double position,
                                                       const std::vector<double>& torques,
                                                       const std::string& output_base);

private:
  // Rolling: the pairs in contact with the reference pair at `position` (m), and the bodies'
  // turns from the scene's own position.
  void set_candidate_pairs(double position);
  std::vector<contact::BodyRotation<dim>> body_rotations(double position) const;
  double scene_position = 0.;     // m, ℓ_ref of the meshed scene (rolling)
  double scene_contact_size = 0.; // m, its h_c (rolling: every position reports it)
  double scene_body_size = 0.;    // m, its body size (likewise)
  // The unloaded TE at ℓ = `position` (m): a rolled position's own, not the meshed scene's.
  double unloaded_transmission_error_at(double position);
  std::vector<double> swept_unloaded_errors; // m, at settings.scene.swept_positions (lazily)
  double mesh_diameter = 0.; // m, GridTools::diameter of the mesh (0: not yet computed)

  // The next torque of a torque list: one continuation step from the converged state.
  GearMeshStiffnessResult next_torque(double torque);
  void make_scene();
  void setup_problem();
  void solve();
  // k, TE, hub torques; then each pair's load (evaluate_pairs) and the fillet stresses.
  void evaluate();
  void evaluate_pairs(const contact::ContactResults<dim>& contact);
  void evaluate_root_stress();
  // The fillet faces (cell, face number) evaluate_root_stress() reads, found once per mesh; and
  // the DoFs of their cells (a rolling sweep completes the solution only there, issue 28).
  const std::vector<
      std::pair<typename dealii::DoFHandler<dim>::active_cell_iterator, unsigned int>>&
  fillet_faces();
  std::vector<dealii::types::global_dof_index> reported_dofs();
  void evaluate_crack_tips();
  void add_crack_pairs();
  void output_results();

  MPI_Comm mpi_communicator;
  GearMeshStiffnessSettings settings;
  kinematics::GearPairGeometry pair;
  std::vector<ToothPairLoad> candidate_pairs; // pairs given to the contact problem
  double pinion_rotation_angle = 0.;          // rad, scene rotation of the pinion profile
  double wheel_rotation_angle = 0.;           // rad
  std::unique_ptr<contact::ContactProblem<dim>> problem; // owned
  std::vector<std::pair<typename dealii::DoFHandler<dim>::active_cell_iterator, unsigned int>>
      fillets; // of fillet_faces(), for `problem`'s mesh
  GearMeshStiffnessResult result;
};

// Names of the settings' fields in the InputError this module throws ("stiffness.<member>",
// "sweep.<member>"; the scene's are geometry::scene_field). The command that fills the
// settings maps them to its parameter names.
namespace stiffness_parameter
{
inline const std::string torque = "stiffness.pinion_torque";
inline const std::string torques = "stiffness.torques";
inline const std::string positions = "sweep.positions";
inline const std::string pitches = "sweep.base_pitches";
inline const std::string start = "sweep.start_position";
inline const std::string scene_file = "stiffness.scene_file";
inline const std::string sweep_mesh = "sweep.mesh";
inline const std::string contact_model = "stiffness.contact_model";
inline const std::string influence_grid_points = "stiffness.influence_grid_points";
} // namespace stiffness_parameter

// The checks of the settings the constructor makes before anything is meshed (InputError
// naming the field): a positive torque that closes the mesh, one loaded flank per tooth.
void check_stiffness_settings(const GearMeshStiffnessSettings& settings);
// A torque list for run_torques: not empty, every torque positive, ascending (InputError naming
// stiffness_parameter::torques otherwise).
void check_torque_list(const std::vector<double>& torques);
} // namespace gearstiff::stiffness
