// The FE body of the influence-coefficient model (docs/ltca.md §1–2), of its 2D and 3D sweep
// (stiffness/influence_sweep.cc): where the flanks of
// the meshed scene are (the transverse frame of geometry/scene_gear_pair.h), the flank grid
// along the line of action, and the FE model of both gears — bores clamped, K factored once —
// whose compliance between load points on the flanks and read points at the matching depth
// below them are MUMPS's selected entries of K⁻¹. Internal to stiffness/.
#pragma once

#include "fem/elastic_system.h"
#include "fem/stiffness_factorization.h"
#include "geometry/scene_gear_pair.h"
#include "kinematics/gear_pair.h"
#include "stiffness/ltca_contact.h"
#include "stiffness/mesh_stiffness_sweep.h"
#include "stiffness/root_stress.h"

#include <chrono>
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace gearstiff::stiffness::influence
{
// Where the flanks of the pair are, as the geometry module places them (scene frame of
// geometry/scene_gear_pair.h: pinion centre at the origin, line of action T1 + ℓ·u).
struct PairFrame
{
  kinematics::GearPairGeometry pair;
  double scene_position = 0.; // m, ℓ_s of the meshed scene's reference pair
  double t2 = 0.;             // m, T2 from T1 (a ring's behind T1: negative)
  dealii::Point<2> wheel_centre;
  dealii::Tensor<1, 2> u; // the line of action's direction: the pinion's outward flank normal

  explicit PairFrame(const kinematics::GearPairGeometry& pair);
  double pinion_base_radius() const { return 0.5 * pair.pinion.base_diameter; }
  double wheel_base_radius() const { return 0.5 * pair.wheel.base_diameter; }
};

// A flank point: the point of pair j's pinion (or wheel) flank that touches at ℓ, in the
// meshed scene's transverse frame, the direction of the force the mate exerts on it, its body.
struct FlankPoint
{
  dealii::Point<2> surface;
  dealii::Tensor<1, 2> inward; // unit: the mate's force on this flank, into the body
  // unit, ⊥ inward: a force line turned by τ (rad) loads along inward + τ·across
  dealii::Tensor<1, 2> across;
  dealii::types::material_id body;
};
FlankPoint flank_point(const PairFrame& frame, int j, double position, bool wheel);

// The geometry a friction force at ℓ = `at` needs (docs/ltca.md §4 "Friction"): it acts on the
// pinion's flank along its `across` (FlankPoint) and on the wheel's the opposite way.
struct PairFriction
{
  // -, how far the pinion's rigid roll e (along u, r_b1·Δφ) moves its flank point along its
  // `across`, over e: ρ₁/r_b1 signed (the pinion's slip over the held wheel).
  double slip_per_approach = 0.;
  // -, a friction force's moment about each gear's centre over a normal force's of the same size
  // (ρ_i/r_bi, signed as the moments).
  double pinion_arm = 0., wheel_arm = 0.;
};
PairFriction pair_friction(const PairFrame& frame, double at);

// Every position of a sweep in order, `solve` giving one position at every one of `n_torques`
// torques, each position warm-started from the forces the one before left in `warm`; returned
// as [torque][position].
std::vector<std::vector<GearMeshStiffnessResult>> solve_positions(
    const std::vector<double>& positions, std::size_t n_torques,
    const std::function<std::vector<GearMeshStiffnessResult>(double, std::map<int, double>&)>&
        solve);

// Wall seconds since `start`.
double seconds_since(std::chrono::steady_clock::time_point start);

// One position of a sweep at every torque of `torques` (N·m): `problem_under(F)` the position's
// contact problem under Σ F = T1/r_b1 of `frame` (its force lines depend on the load on modified
// flanks), each solve started from the forces `warm` holds for the unknowns `keys` (0 for one it
// has not seen); the first torque's forces go back into `warm` for the next position (a neighbour's
// active set). `report(solution, torque)` builds each torque's result, whose solve and total
// time are set here; `newton_steps` counts the solves' Newton steps.
std::vector<GearMeshStiffnessResult> solve_torques(
    const std::function<MeshContactProblem&(double)>& problem_under, const PairFrame& frame,
    const std::vector<int>& keys, const std::vector<double>& torques, std::map<int, double>& warm,
    unsigned int& newton_steps,
    const std::function<GearMeshStiffnessResult(const MeshContactSolution&, double)>& report);

// Pair j of a solved position into `r`: its point on the line of action ℓ_j = position + j·p_bt
// (m), normal force (N; the resultant: frictionless), share of `total` (N), peak pressure (Pa)
// and the contact band ±half_width (m) about ℓ_j; counts it as loaded above a share of 1e-6.
void add_pair_load(GearMeshStiffnessResult& r, const PairFrame& frame, double position, int j,
                   double force, double total, double peak_pressure, double half_width);

// What the 2D and 3D sweeps report alike for the position ℓ = `position` (m) under T1 = `torque`
// (N·m) with `kinematic_pairs` pairs: the position and load, the base radii, the root stresses
// NaN (the caller sums them from the fillet responses, FlankCompliance::root_stress), TE = the
// rigid approach of `solution` (m), the unloaded TE `unloaded` (m), k = T1/(r_b1²·Δφ) with Δφ =
// (approach − unloaded)/r_b1, and the solve's active-set passes; SolverFailure when the pinion did
// not turn forward.
GearMeshStiffnessResult result_at(const PairFrame& frame, unsigned int dimension, double position,
                                  std::size_t kinematic_pairs, double torque,
                                  const MeshContactSolution& solution, double unloaded);

// The grid of one pair's flanks: `count` points at ℓ = first + g·step.
struct FlankGrid
{
  int pair = 0;
  double first = 0.; // m
  unsigned int count = 0;
};

// The interval of pair j's flank grid (in `grids`, points numbered grid after grid, `step` m
// apart) that holds ℓ = `at` (m): its first point's index and the fraction past it. InputError
// naming Stiffness/sweep mesh for a position off the grid or a pair without one.
std::pair<std::size_t, double> locate_on_grid(const std::vector<FlankGrid>& grids, double step,
                                              int j, double at);
// Every pair in contact at a position gets the grid points that cover the ℓ it takes in the
// sweep (one step of margin each side, within the path of contact A–E).
std::vector<FlankGrid> flank_grids(const kinematics::GearPairGeometry& pair,
                                   const std::vector<double>& positions, double step);

// The cells of the FE body with their bounding boxes (MappingQ1: straight-sided cells lie
// within the box of their vertices). A scan of the boxes finds the cell around a flank grid
// point in microseconds; deal.II's vertex search (GridTools::find_active_cell_around_point, with
// or without GridTools::Cache) took 0.55 s for the 134 points of the default 2D sweep (79.6k
// DoFs, 2026-12-01), a quarter of the whole once-part.
template <int dim>
struct CellLocator
{
  std::vector<
      std::pair<dealii::BoundingBox<dim>, typename dealii::DoFHandler<dim>::active_cell_iterator>>
      cells;
  explicit CellLocator(const dealii::DoFHandler<dim>& dof_handler);
};

// The FE body model: the gears of one scene, each bore clamped (the pinion's rigid turn is the
// contact problem's approach e). The gears are separate bodies, so each gear's coefficients need
// only its own mesh and factor: the model holds the scene as read and, in turn, one gear's
// system, factored (docs/ltca.md "Cost": on two ranks each takes one gear).
template <int dim>
struct BodyModel
{
  std::unique_ptr<dealii::Triangulation<dim>> scene; // both gears, as read
  std::unique_ptr<fem::ElasticSystem<dim>> system;   // the gear of `wheel` alone
  std::unique_ptr<fem::StiffnessFactorization<dim>> factorization;
  std::unique_ptr<CellLocator<dim>> locator; // the cell search of the flank grid points
  bool wheel = false;                        // which gear `system` holds
};
// Reads the scene `file` on this rank alone (no system yet).
template <int dim>
BodyModel<dim> read_body_model(const std::string& file);
// Sets up and factors the pinion's (`wheel` false) or the wheel's body of `model`, replacing the
// other's: `settings.elasticity`, `.material` and `.linear_solver` (made direct: the
// coefficients need a factorization), on MPI_COMM_SELF.
template <int dim>
void factor_body_model(const GearMeshStiffnessSettings& settings, BodyModel<dim>& model,
                       bool wheel);

// A load: unit total force (N) along `direction`, shared by `points` with `weights` (Σ = 1).
// A read: the displacement along `direction` at `points.front()` (weights ignored).
template <int dim>
struct BodyPoint
{
  std::vector<dealii::Point<dim>> points;
  std::vector<double> weights;
  dealii::Tensor<1, dim> direction;
  dealii::types::material_id body;
};

// m/N: result[a][b] = the displacement read b under the load a (P b of the factorization).
// `solved` (may be empty) hears the loads solved so far, block by block. With `fillet`, also
// the displacements of its rows under each load into `fillet_values` [load][row] (m/N; the same
// solves: the root stress at any set of forces is their sum, docs/ltca.md "Root stress").
// SolverFailure when a point lies outside its body's mesh.
template <int dim>
std::vector<std::vector<double>>
body_compliance(const BodyModel<dim>& model, const std::vector<BodyPoint<dim>>& loads,
                const std::vector<BodyPoint<dim>>& reads,
                const std::function<void(std::size_t)>& solved = {},
                const FilletStressPoints* fillet = nullptr,
                std::vector<std::vector<double>>* fillet_values = nullptr);

// The fillets of the gear `model` holds (its system: root_stress.h).
template <int dim>
FilletStressPoints body_fillet_points(const BodyModel<dim>& model,
                                      const kinematics::GearPairGeometry& pair);

// The scene of the FE body (`dimension` 2 or 3): the sweep's first position, every flank that
// meshes in the sweep refined along its contacts at `band_cell` (m) out to the matching `depth`
// (m) plus two cells of `cell` (m, h_f).
geometry::GearPairSceneSpec body_scene(const GearMeshStiffnessSettings& settings,
                                       const kinematics::GearPairGeometry& pair,
                                       const std::vector<double>& positions, double cell,
                                       double band_cell, double depth, unsigned int dimension);

} // namespace gearstiff::stiffness::influence
