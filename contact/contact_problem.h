// Two-body (or more) small-sliding frictional contact on top of fem::ElasticSystem.
//
// Method: dual-mortar coupling (contact/mortar.h) frozen in the reference configuration and a
// primal–dual active-set iteration (Hüeber & Wohlmuth 2005, CMAME 194:3147; step-41/42 of
// deal.II for one body). Each slave node is open, stick or slip:
//   open:  no constraint;
//   stick: the weighted normal gap and the tangential slip increment of the step are zero — the
//          node's DoFs become affine functions of the master DoFs (AffineConstraints);
//   slip:  the normal gap is zero (one DoF constrained), the tangential force is μ·λ_n against the
//          slip direction, with λ_n from the previous iterate (a fixed point on the Coulomb bound,
//          which contracts at a rate of order μ).
// The Coulomb bound μ λ_n is held fixed while the stick/slip/open states of that Tresca problem
// converge, then updated from the new λ_n (successive Tresca approximations). The first load
// step starts frictionless; its converged zone and slip give the initial stick/slip states.
// Multipliers are the residual r = K u − f at the slave nodes; every linear system is a
// symmetric positive definite solve. A node opens when its normal force turns tensile and closes
// when it penetrates; a sticking node slips when |λ_τ| > μ λ_n, along λ_τ; a slipping node that
// slid along its own friction force reverses once per load step if |λ_τ − c·s| > μ λ_n
// (c ≈ E/(10 h)), and sticks otherwise. c only steers the iteration: the converged state
// satisfies the contact conditions exactly, so no result depends on a user-tuned penalty. The
// initial active set is the nodes touching in the reference configuration, or those at the
// smallest gap when none touches. The iteration ends when the state repeats and the friction
// forces have converged; a state met three times (cycling) or the iteration limit is a
// SolverFailure, so is a body left free to move.
//
// Linear algebra: the element work is done once. K is condensed with the supports and factorized
// once (fem/stiffness_factorization.h); the closed contacts enter as Lagrange multipliers, and each
// iteration solves only the small Schur complement S = G P Gᵀ on the contact rows G, with the
// rigid-body modes of the bodies held only through the contacts as extra unknowns. The columns
// P Gᵀ are computed once per slave node, when it first closes, and kept. The result is the same
// constrained minimum as eliminating the contact constraints in a re-assembled matrix (the
// `full re-solve` method, kept as the reference and for iterative linear solvers), to round-off.
#pragma once

#include "contact/active_set.h"
#include "contact/mortar.h"
#include "fem/elastic_system.h"
#include "fem/supports.h"

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace gearstiff::contact
{
// How each active-set iteration solves its linear system.
enum class IterationSolves
{
  automatic,        // Schur complement with the direct solver, full re-solve otherwise
  schur_complement, // one factorization, a Schur complement on the contact rows per iteration
  full_resolve      // re-assemble and re-solve the condensed system every iteration (reference)
};

// The contact controls (their parameter-file form, subsection "Contact", is declared in
// app/scenes/fe_contact_parameters.cc).
struct ContactParameters
{
  IterationSolves iteration_solves = IterationSolves::automatic;
  double friction_coefficient = 0.; // -, Coulomb μ
  unsigned int max_iterations = 40; // active-set iterations per load step
  unsigned int load_steps = 1;      // -, loads applied in equal increments (friction history)
  double search_distance = 1e-3;    // m, slave points farther from the master are not paired
  double overlap_tolerance = 1e-6;  // m, initial overlap beyond this is an input error
  double friction_tolerance = 1e-8; // -, friction-force change relative to the normal force
  bool warm_start = true; // analyses of similar scenes (sweeps) start from their neighbour's zone
};

// How the reason of the InputError for an initial overlap beyond `overlap_tolerance` begins,
// followed by the overlap in mm: an analysis that knows which of its parameters cures an overlap
// (a helical scene's layers: stiffness/mesh_stiffness.cc) names that parameter instead.
inline constexpr const char* overlap_reason = "the bodies overlap by ";

// One slave node of a contact pair in the result.
template <int dim>
struct SurfacePoint
{
  dealii::Point<dim> position;  // m, reference
  double coordinate = 0.;       // m, along the surface's principal direction (for plots)
  double pressure = 0.;         // Pa, normal contact pressure (compressive > 0)
  dealii::Tensor<1, dim> shear; // Pa, tangential traction on the slave
  double gap = 0.;              // m, current normal gap (0 when closed)
  double initial_gap = 0.;      // m
  dealii::Tensor<1, dim> slip;  // m, accumulated tangential slip (slave relative to master)
  // m² (m in 2D), the slave node's paired share of the surface (its mortar weight): pressure ×
  // area is the node's normal force, the quantity loads are summed from (stiffness/face_load.h).
  double area = 0.;
  dealii::Tensor<1, dim> normal; // -, unit, the slave's outward normal at the node
  NodeState state = NodeState::open;
};

template <int dim>
struct PairResult
{
  std::string name;
  std::vector<SurfacePoint<dim>> points; // sorted by coordinate
  dealii::Tensor<1, dim> force_on_slave; // N, resultant contact force on the slave body
  double normal_force = 0.;              // N, Σ λ_n
  double tangential_force = 0.;          // N, |Σ λ_τ| (resultant of the tangential forces)
  double max_pressure = 0.;              // Pa
  double contact_length = 0.;            // m, extent of the closed nodes along `coordinate`
  unsigned int n_closed = 0, n_stick = 0, n_slip = 0;
};

template <int dim>
struct SupportResult
{
  std::string name;
  dealii::Tensor<1, dim> force; // N, exerted by the support on the body (residual)
  double torque = 0.;           // N·m, about +z through `axis`
  double rotation = 0.;         // rad, rigid hubs only
  bool is_hub = false;
  dealii::Point<dim> axis; // m
};

struct IterationRecord
{
  unsigned int load_step = 0, iteration = 0;
  unsigned int n_closed = 0, n_stick = 0, n_slip = 0, n_changed = 0;
  double friction_change = 0.; // -, relative
  double time = 0.;            // s, wall, assembly + solve
  unsigned int n_rows = 0;     // -, contact constraint rows (Schur complement size)
};

template <int dim>
struct ContactResults
{
  std::vector<PairResult<dim>> pairs;
  std::vector<SupportResult<dim>> supports;
  std::vector<IterationRecord> history;
  unsigned int active_set_iterations = 0; // total over the load steps ("Newton steps")
  unsigned int load_steps = 0;
  dealii::types::global_dof_index n_dofs = 0;
  unsigned int n_mpi_ranks = 1;
  double setup_time = 0.;            // s: DoFs, K, mortar coupling
  double assembly_time = 0.;         // s, summed over iterations (Schur: the one factorization)
  double factorization_time = 0.;    // s, the one factorization when this solve made it
  double solve_time = 0.;            // s, summed over iterations
  double total_time = 0.;            // s
  bool schur_complement = false;     // the iterations solved the contact Schur complement
  bool warm_start = false;           // started from a given zone (false: cold, or it failed)
  unsigned int right_hand_sides = 0; // -, solves with the factorization (Schur complement)
};

// A converged contact zone to start another analysis of a similar scene from (the
// neighbouring position of a sweep). The meshes of such scenes differ, so the zone is kept by
// geometry, not by node: per pair (by name), the largest initial gap of its closed nodes above
// the pair's smallest initial gap. Near a smooth first touch the closed zone is where the
// initial gap stays below a level (exactly so for Hertz's parabolic gap), and that level moves
// little between neighbouring positions even where the zone itself moves along the surface.
struct ContactZone
{
  std::string pair;
  double gap_range = 0.; // m, closed nodes: initial gap − smallest initial gap of the pair
};

// A rigid turn of one body about the z axis (rolling: ContactProblem::roll).
template <int dim>
struct BodyRotation
{
  dealii::types::material_id body = 0; // material id of the body's cells
  dealii::Point<dim> axis;             // m, a point of the rotation axis (parallel to z)
  double angle = 0.;                   // rad, counter-clockwise about +z
};

template <int dim>
class ContactProblem
{
public:
  ContactProblem(MPI_Comm mpi_communicator, const fem::ElasticityParameters& elasticity,
                 const fem::LinearSolverParameters& linear_solver,
                 const ContactParameters& contact);
  ~ContactProblem();

  // Fill the mesh, materials and tractions through this before setup_system().
  fem::ElasticSystem<dim>& system() { return elastic; }

  // Supports; `name` labels the result and error messages (e.g. the physical group).
  void add_displacement(dealii::types::boundary_id boundary,
                        const dealii::Tensor<1, dim>& displacement, const std::string& name,
                        const std::vector<bool>& components = {});
  void add_rigid_hub(dealii::types::boundary_id boundary, const dealii::Point<dim>& axis,
                     typename fem::RigidHub<dim>::Control control, double value,
                     const std::string& name);
  // `window` (radius > 0): only the surfaces near its centre are paired (contact/mortar.h,
  // PairingWindow); check closed_within_windows() after the solve. `within_one_body`: both
  // surfaces belong to one body (the two faces of a crack), so the pair cannot hold that
  // body; nodes the two surfaces share (a crack tip) are not coupled.
  void add_contact_pair(const std::vector<dealii::types::boundary_id>& slave,
                        const std::vector<dealii::types::boundary_id>& master,
                        const std::string& name, const PairingWindow<dim>& window = {},
                        bool within_one_body = false);

  // DoFs, stiffness, supports and the mortar coupling; InputError when a pair has no
  // candidates or the bodies overlap beyond the tolerance.
  void setup_system();
  // After setup_system(): the pairs named in `zones` start with the nodes within their gap
  // range closed (others as usual). Should the warm start fail, solve() starts cold.
  void start_from(const std::vector<ContactZone>& zones);
  // The load steps with their active-set iterations.
  const ContactResults<dim>& solve();
  // Continuation — quasi-static incremental friction along a load path. After solve(), a hub's
  // target (rad for rotation control, N·m for torque control; `name` as given to
  // add_rigid_hub) may change; solve_next_step() then solves one more load step from the
  // converged state of the last one, at full load with the new targets. The nodes keep their
  // stick/slip/open states, friction bounds and slip directions, and stick means no tangential
  // relative displacement since that state (the return mapping of incremental Coulomb
  // friction), so loading and unloading follow different paths. The factorization is reused:
  // a target change adds the hub's unit response once per change (one solve).
  void set_hub_target(const std::string& name, double value);
  const ContactResults<dim>& solve_next_step();
  // Rolling — one mesh, one factorization, many positions. The small-strain stiffness of a body
  // is invariant under a rigid rotation of its own frame, so a body's DoFs may keep its own,
  // unrotated frame while the contact is paired on the bodies turned by `rotations` (bodies not
  // listed stay): the normals, gaps and mortar weights come from the turned geometry, and each
  // contact row turns the DoF components into the normal's frame. Called before setup_system()
  // (first position) or after a solve (next positions: the pairs are coupled afresh, the
  // contact starts cold — or from start_from() —, and K, the supports and the factorization are
  // kept). `pairs` of add_contact_pair may be replaced in between (clear_contact_pairs). Needs
  // the Schur complement (InputError naming field::contact("iteration_solves"), contact/fields.h),
  // supports that turn with their bodies (hubs about their own axes), and leaves solution() and
  // output_results() in the bodies' own frames; the pair results (positions, forces) are in the
  // turned frame.
  void roll(const std::vector<BodyRotation<dim>>& rotations);
  void clear_contact_pairs() { pairs.clear(); }
  // The exact surfaces of the bodies (contact/mortar.h, SurfaceGeometry), e.g. a helical gear's
  // flanks on their helicoids; before setup_system() or roll(). Empty (the default): the mesh.
  void set_surface_geometry(SurfaceGeometry<dim> exact) { surface_geometry = std::move(exact); }
  // After a solve: whether every closed node of a pair paired in a window lies within half the
  // window's radius of its centre. When not, the contact may reach nodes the window left out:
  // the caller pairs the whole surfaces again.
  bool closed_within_windows() const;
  // Rolling: the boundary ids every pairing of the sweep draws from (slave and master). The
  // responses to unit loads at their DoFs are then computed once for the whole sweep (each
  // when a node there first closes) and kept across positions, at these surfaces' DoFs in 2D,
  // at those near the pairing's contact DoFs in 3D; a kept response that lacks a contact DoF
  // of a later pairing is computed afresh.
  void keep_columns_on(const std::vector<dealii::types::boundary_id>& surfaces);
  // Rolling, after setup_system(): in 2D the solution of each position is completed only at
  // these DoFs (besides the contact DoFs, and every DoF of the cells at the supports, whose
  // reactions need them), from the kept unit responses — no full back-substitution per
  // position; in 3D by one back-substitution (contact_condensed.cc: completes_from_kept_rows).
  // The results (pairs, support reactions and hub rotations) are those of the full field to
  // round-off; solution() is exact at those DoFs (2D: 0 elsewhere until complete_field()).
  void complete_only_at(const std::vector<dealii::types::global_dof_index>& dofs);
  // The whole displacement field of the last solve (one back-substitution), e.g. for VTU output;
  // nothing to do unless complete_only_at() left it partial.
  void complete_field();
  // The converged zone of every pair with closed nodes, to start a neighbouring analysis from.
  std::vector<ContactZone> converged_zones() const;
  // VTU/PVTU: displacement, von Mises, material id, subdomain, contact pressure, gap, slip,
  // state. Returns the file names written into `directory`.
  std::vector<std::string> output_results(const std::string& directory,
                                          const std::string& base) const;
  const ContactResults<dim>& run();
  // Progress of long solves: called on every rank (the caller decides which one prints) with one
  // line after the set-up and after each active-set iteration; empty (the default): silent.
  void set_progress(std::function<void(const std::string&)> report) { progress = report; }

  const ContactResults<dim>& results() const { return result; }
  const dealii::Vector<double>& solution() const { return displacement; }

private:
  struct Pair
  {
    std::string name;
    std::vector<dealii::types::boundary_id> slave, master;
    PairingWindow<dim> window;    // radius 0: the whole surfaces
    bool within_one_body = false; // the two faces of a crack (add_contact_pair)
    std::vector<SlaveNode<dim>> nodes;
    std::vector<NodeMemory<dim>> memory; // contact state of each node (contact/active_set.h)
  };
  struct Support
  {
    std::string name;
    dealii::types::boundary_id boundary;
    dealii::Tensor<1, dim> displacement; // m, displacement supports
    std::vector<bool> components;        // constrained components (empty: all)
    bool is_hub = false;
    dealii::Point<dim> axis; // m, hubs
    typename fem::RigidHub<dim>::Control control = fem::RigidHub<dim>::Control::rotation;
    double value = 0.;                       // rad or N·m, hubs
    std::vector<fem::Node<dim>> nodes;       // resolved by setup_system()
    std::unique_ptr<fem::RigidHub<dim>> hub; // owned, resolved by setup_system()
  };

  struct Condensed; // the factorization, column cache and contact DoFs of the Schur method
  struct RowSet;    // rolling: the rows a kept unit response holds

  // The steps of setup_system(): m, diagonal of the mesh's bounding box; the supports' nodes
  // and hubs; the mortar coupling of every pair (InputError: no candidates, overlap); the
  // initial active set.
  double mesh_diameter() const;
  void resolve_supports();
  void couple_pairs();
  void check_candidates(const Pair& pair) const;
  void set_cold_start();
  // Rolling: the turned vertices (temporarily), the frames of the coupled nodes.
  void turn_bodies(const std::vector<dealii::Point<dim>>& reference, bool turn);
  void set_node_frames(Pair& pair) const;
  // The Schur method's contact DoFs and what depends on the pairing (map_contact).
  void collect_contact_dofs(Condensed& c) const;
  void map_contact(Condensed& c) const;
  // Rolling: the DoFs of the boundary faces with these ids (sorted); the targets of the
  // current pairing; the rows of the responses computed now; room for `n_new` more kept
  // values; the columns of `loads` at the contact DoFs from the kept unit responses.
  std::vector<dealii::types::global_dof_index>
  surface_dofs(const std::vector<dealii::types::boundary_id>& ids) const;
  void map_unit_rows(Condensed& c) const;
  std::shared_ptr<RowSet> rows_for_new_responses(Condensed& c) const;
  std::vector<dealii::types::global_dof_index> rows_near_targets(const Condensed& c,
                                                                 double distance) const;
  void make_room_for_columns(Condensed& c, std::size_t n_new) const;
  std::vector<std::vector<double>> rolling_columns(
      const std::vector<std::vector<std::pair<dealii::types::global_dof_index, double>>>& loads);

  // The load steps from the current states; SolverFailure when one does not converge.
  void solve_load_steps(dealii::Vector<double>& residual);
  // solve_load_steps, and on a failure again from the cold start with 2× and 4× the load steps.
  void solve_refining_load_steps(dealii::Vector<double>& residual);
  void solve_load_step(unsigned int step, const std::vector<std::vector<NodeState>>& initial_states,
                       dealii::Vector<double>& residual);
  // Schur complement: the particular solution and mode loads follow a hub target changed by
  // `change` (rad or N·m), by superposition of the hub's unit response.
  void add_hub_change(const Support& support, double change);
  // Back to the states of setup_system(), no displacement, no friction history.
  void restore_cold_start();

  dealii::AffineConstraints<double> make_constraints(double load_factor) const;
  void add_support_constraints(dealii::AffineConstraints<double>& constraints,
                               double load_factor) const;
  // Supports only (hubs, prescribed displacements) at the given load factor.
  dealii::AffineConstraints<double> make_support_constraints(double load_factor) const;
  // One iteration: `displacement` and the contact forces `residual` (r = K u − f), by
  // re-assembly (reference) or through the Schur complement; the latter may leave both valid
  // only at the contact DoFs until complete_solution().
  void solve_iteration(double load_factor, IterationRecord& record,
                       dealii::Vector<double>& residual);
  void solve_schur_complement(double load_factor, IterationRecord& record,
                              dealii::Vector<double>& residual);
  // The steps of solve_schur_complement.
  struct ContactTerm; // coefficient × a node's relative displacement (row) or force (friction)
  struct ContactRow;  // one closed-contact constraint row
  // Once per solve(): supports, the one factorization, the contact DoFs and functionals.
  void build_condensed(double load_factor);
  // The columns P R_cᵀ of the nodes closed for the first time.
  void add_new_columns();
  std::vector<ContactRow> contact_rows() const;
  std::vector<ContactTerm> friction_terms() const;
  // The multipliers λ (N) of `rows` and the rigid amplitudes α, and u_base (m) at the contact
  // DoFs: SolverFailure when the rows are dependent or leave a body free.
  void solve_contact_system(const std::vector<ContactRow>& rows,
                            const std::vector<ContactTerm>& friction_loads, double load_factor,
                            std::vector<double>& multipliers, std::vector<double>& amplitudes,
                            std::vector<double>& base) const;
  // `displacement` (at the contact DoFs, or complete) and `residual` from λ and α.
  void apply_contact_solution(const std::vector<ContactRow>& rows,
                              const std::vector<ContactTerm>& friction_loads,
                              const std::vector<double>& multipliers,
                              const std::vector<double>& amplitudes,
                              const std::vector<double>& base, double load_factor,
                              dealii::Vector<double>& residual);
  // The whole displacement field and residual of the converged iteration (`whole`: even when
  // complete_only_at() asks for the kept rows only).
  void complete_solution(dealii::Vector<double>& residual, bool whole = false);
  // complete_only_at(): the displacement at the kept rows and the residual, from the kept unit
  // responses; false when they do not cover the loads (then the whole field is computed).
  bool complete_at_kept_rows(dealii::Vector<double>& residual);
  bool use_schur_complement() const;
  dealii::Vector<double> make_point_loads(double load_factor) const;
  // Updates the states from the latest solution with the friction bounds held fixed; returns
  // the number of changed nodes.
  unsigned int update_states(const dealii::Vector<double>& residual);
  // Sets the friction bounds to μ λ_n of the latest solution; returns their largest change
  // relative to the largest normal force.
  double update_friction_bounds(const dealii::Vector<double>& residual);
  // Switches the friction on after a frictionless start: closed nodes slip against their
  // frictionless slip (stick where it vanishes), bounded by μ λ_n of that solution.
  void start_friction(const dealii::Vector<double>& residual);
  void collect_results(const dealii::Vector<double>& residual);
  PairResult<dim> pair_result(const Pair& pair, const dealii::Vector<double>& residual) const;
  // Contact force on a slave node from a residual r = K u − f, N.
  dealii::Tensor<1, dim> nodal_force(const SlaveNode<dim>& node,
                                     const dealii::Vector<double>& residual) const;
  // Tangential slip of a node in the current load step (slave − master), m.
  dealii::Tensor<1, dim> step_slip(const SlaveNode<dim>& node) const;
  // m, gaps and slips below this are round-off.
  double round_off_gap() const;
  // Relative tangential displacement (slave − master) of a node, m.
  dealii::Tensor<1, dim> relative_displacement(const SlaveNode<dim>& node,
                                               const dealii::Vector<double>& u) const;

  MPI_Comm mpi_communicator;
  ContactParameters parameters;
  fem::ElasticSystem<dim> elastic;
  std::vector<Support> supports;
  std::vector<Pair> pairs;
  SurfaceGeometry<dim> surface_geometry;  // empty: the mesh is the geometry
  dealii::Vector<double> displacement;    // m, complete
  dealii::Vector<double> step_start;      // m, converged solution of the previous step
  dealii::Vector<double> residual_forces; // N, r = K u − f of the converged solution
  double characteristic_length = 1.;      // m, mesh diameter
  // Whether Coulomb friction is in force (false during a frictionless start); μ itself is kept
  // once, in parameters.friction_coefficient.
  bool friction_in_force = false;
  // -, the μ the active set applies now: parameters.friction_coefficient once in force, else 0
  double applied_friction() const
  {
    return friction_in_force ? parameters.friction_coefficient : 0.;
  }
  // -, largest turn of a slip force in the last update_states, relative to the largest normal
  // force (3D: slip directions converge as a fixed point with the bounds).
  double direction_change = 0.;
  ContactResults<dim> result;
  std::function<void(const std::string&)> progress;
  std::vector<std::vector<NodeState>> cold_start; // [pair][node], the initial states
  bool warm_started = false;                      // start_from() set the states
  std::unique_ptr<Condensed> condensed;           // owned; built by the first Schur iteration
  bool rolling = false;                           // roll() was called
  std::vector<BodyRotation<dim>> rotations;       // of roll()
  std::vector<dealii::types::boundary_id> rolling_surfaces; // of keep_columns_on()
  std::vector<dealii::types::global_dof_index> output_dofs; // of complete_only_at(), sorted
  bool complete_only_at_rows = false;                       // complete_only_at() was called
  bool field_partial = false; // solution() holds only the kept rows (complete_field())
};
} // namespace gearstiff::contact
