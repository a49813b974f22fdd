// Rolling sweeps (GearMeshStiffness::roll_to): one mesh and one factorization, the bodies
// turned rigidly to every position. A body's small-strain stiffness matrix in its own frame does
// not change when it turns, and both supports turn with their bodies (the pinion hub about the
// pinion axis, the fixed wheel bore about the wheel axis), so K, the support constraints and
// the factorization of the scene's own position serve every position; only the contact pairing
// is made afresh on the turned geometry (contact::ContactProblem::roll).
#include "errors/errors.h"
#include "errors/format.h"
#include "stiffness/contact_solve.h"
#include "stiffness/mesh_stiffness.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/timer.h>
#include <functional>

namespace gearstiff::stiffness
{
using namespace dealii;

namespace
{
// R of the pairing windows (contact::PairingWindow), in transverse modules: 0.4·m_t = 1 mm for
// the default pair. A pair at ℓ touches at its point of the line of action (at A or E, the tip
// corners, beyond the path); its flanks are paired only within R of there. The margin: the
// closed zone is a Hertz zone (half-width ≈ 0.1 mm at the default load, 0.2 mm at 4× it) and at
// R the unloaded gap s²/2ρ (ρ ≤ 8 mm, the relative radius of curvature along the path) is
// ≥ 60 µm, about ten times the loaded TE; each position checks that every closed node lies
// within R/2 (the gap there ≥ 15 µm) and otherwise pairs the whole flanks and solves again.
constexpr double pairing_window_modules = 0.4;

// The pairs of `loads` as contact pairs of `problem` (those it had are replaced), each paired
// only in its window (`windowed`) or along the whole flanks.
template <int dim>
void add_rolled_pairs(contact::ContactProblem<dim>& problem,
                      const kinematics::GearPairGeometry& pair,
                      const std::vector<ToothPairLoad>& loads, bool windowed)
{
  problem.clear_contact_pairs();
  // A helical pair's contact line runs b·tan β_b along the line of action across the face, far
  // beyond a window round its mid-face point (6 mm against R = 1 mm on the built-in pair at
  // 15°): its flanks are paired whole.
  windowed = windowed && pair.spec.pinion.helix_angle == 0.;
  for (const ToothPairLoad& load : loads)
  {
    contact::PairingWindow<dim> window;
    if (windowed)
    {
      const Eigen::Vector2d centre = geometry::line_of_action_point(
          pair, std::clamp(load.position, pair.contact_start, pair.contact_end));
      window.centre[0] = centre.x();
      window.centre[1] = centre.y();
      window.radius = pairing_window_modules * pair.transverse_module;
    }
    problem.add_contact_pair(
        {static_cast<types::boundary_id>(geometry::pinion_flank_id(load.pair))},
        {static_cast<types::boundary_id>(geometry::wheel_flank_id(load.pair))},
        "tooth pair " + std::to_string(load.pair), window);
  }
}

// The contact on the windowed pairing; should it reach beyond half a window, the whole flanks
// are paired (`pair_whole_flanks`) and it is solved again from the same start.
template <int dim>
void solve_in_windows(contact::ContactProblem<dim>& problem, GearMeshStiffnessResult& result,
                      std::vector<contact::ContactZone>* warm_start,
                      const std::function<void()>& pair_whole_flanks)
{
  const std::vector<contact::ContactZone> start =
      warm_start ? *warm_start : std::vector<contact::ContactZone>();
  solve_set_up_contact_problem(problem, result, warm_start);
  if (problem.closed_within_windows())
    return;
  pair_whole_flanks();
  if (warm_start)
    *warm_start = start;
  solve_set_up_contact_problem(problem, result, warm_start);
}

// Every flank a position of the sweep pairs (its boundary ids): the responses at their DoFs
// are kept for the whole sweep.
std::vector<types::boundary_id> swept_flanks(const kinematics::GearPairGeometry& pair,
                                             const std::vector<double>& swept)
{
  std::vector<types::boundary_id> flanks;
  for (const double swept_position : swept)
    for (const int j : geometry::gear_pairs_across_face(pair, swept_position))
      for (const int flank : {geometry::pinion_flank_id(j), geometry::wheel_flank_id(j)})
      {
        const auto id = static_cast<types::boundary_id>(flank);
        if (std::find(flanks.begin(), flanks.end(), id) == flanks.end())
          flanks.push_back(id);
      }
  return flanks;
}
} // namespace

template <int dim>
void GearMeshStiffness<dim>::set_candidate_pairs(double position)
{
  candidate_pairs.clear();
  for (const int j : geometry::gear_pairs_across_face(pair, position))
  {
    ToothPairLoad load;
    load.pair = j;
    load.position = position + j * pair.transverse_base_pitch;
    candidate_pairs.push_back(load);
  }
  result.reference_position = position;
  result.kinematic_pairs = candidate_pairs.size();
  result.pinion_roll_angle = position / result.pinion_base_radius;
  result.mesh_position = (position - pair.contact_start) / pair.transverse_base_pitch;
}

template <int dim>
std::vector<contact::BodyRotation<dim>>
GearMeshStiffness<dim>::body_rotations(double position) const
{
  // The pinion turns counter-clockwise by Δℓ/r_b1; an external wheel the other way by
  // Δℓ/r_b2, a ring the same way (geometry/scene_gear_pair.h: add_swept_contacts).
  const double roll = position - scene_position;
  contact::BodyRotation<dim> pinion, wheel;
  pinion.body = geometry::scene_ids::pinion_body;
  pinion.angle = roll / (0.5 * pair.pinion.base_diameter);
  wheel.body = geometry::scene_ids::wheel_body;
  wheel.axis[0] = pair.spec.wheel.internal ? -pair.centre_distance : pair.centre_distance;
  wheel.angle = (pair.spec.wheel.internal ? 1. : -1.) * roll / (0.5 * pair.wheel.base_diameter);
  return {pinion, wheel};
}

template <int dim>
double GearMeshStiffness<dim>::unloaded_transmission_error_at(double position)
{
  // The modifications' gap is geometry: every rank computes it (milliseconds, no mesh), once
  // for every swept position.
  const std::vector<double>& swept = settings.scene.swept_positions;
  if (swept_unloaded_errors.size() != swept.size())
    swept_unloaded_errors = geometry::unloaded_transmission_errors(settings.scene, swept);
  for (std::size_t i = 0; i < swept.size(); ++i)
    if (std::abs(swept[i] - position) <= 1e-9) // the same formulas give both
      return swept_unloaded_errors[i];
  return geometry::unloaded_transmission_errors(settings.scene, {position}).front();
}

template <int dim>
GearMeshStiffnessResult GearMeshStiffness<dim>::roll_to(double position,
                                                        const std::string& output_base)
{
  Timer timer(mpi_communicator, true);
  const std::vector<double>& swept = settings.scene.swept_positions;
  // 1e-9 m: the positions come from the same formulas as the swept ones.
  if (swept.empty() || position < *std::min_element(swept.begin(), swept.end()) - 1e-9 ||
      position > *std::max_element(swept.begin(), swept.end()) + 1e-9)
    throw InputError(stiffness_parameter::sweep_mesh,
                     "'once': the position " + format_number(position * 1e3, 6) +
                         " mm lies outside the positions the mesh was refined for; the flanks "
                         "are refined only along the swept positions");
  const bool first = !problem;
  const auto solve_rolled = [&]()
  {
    solve_in_windows(*problem, result,
                     settings.contact.warm_start ? settings.warm_start.get() : nullptr,
                     [&]()
                     {
                       add_rolled_pairs(*problem, pair, candidate_pairs, false);
                       add_crack_pairs(); // add_rolled_pairs cleared them
                       problem->roll(body_rotations(position));
                     });
  };
  result = GearMeshStiffnessResult();
  result.dimension = dim;
  if (first)
  {
    make_scene(); // at the scene's own position, refined for every swept one
    scene_position = result.reference_position;
    scene_contact_size = result.contact_size;
    scene_body_size = result.body_size;
    set_candidate_pairs(position);
    setup_problem();
    add_rolled_pairs(*problem, pair, candidate_pairs, true);
    add_crack_pairs(); // add_rolled_pairs cleared them
    problem->keep_columns_on(swept_flanks(pair, swept));
    problem->roll(body_rotations(position));
    problem->setup_system(); // DoFs, K, pairing on the turned bodies
    // What a position reports (hub rotations and reactions, pair forces, fillet stresses, the
    // crack tip's K from the crack faces) is linear in the contact loads: the solution is
    // completed only at the fillets and crack faces (and at the contact and support DoFs) from
    // the kept unit responses, the whole field only for VTU.
    problem->complete_only_at(reported_dofs());
    // The scene's own unloaded TE is that of its reference position; the rolled one's is set
    // before evaluate() adds it to the deflection.
    result.unloaded_transmission_error = unloaded_transmission_error_at(position);
    solve_rolled(); // the factorization, then the contact
    evaluate();
  }
  else
  {
    result.pinion_base_radius = 0.5 * pair.pinion.base_diameter;
    result.wheel_base_radius = 0.5 * pair.wheel.base_diameter;
    // The same mesh: its h_c (the tip-edge flag's tolerance; a position without it flagged
    // only peaks exactly at A or E).
    result.contact_size = scene_contact_size;
    result.body_size = scene_body_size;
    set_candidate_pairs(position);
    add_rolled_pairs(*problem, pair, candidate_pairs, true);
    add_crack_pairs(); // add_rolled_pairs cleared them
    problem->roll(body_rotations(position));
    result.unloaded_transmission_error = unloaded_transmission_error_at(position);
    solve_rolled();
    result.n_cells = problem->system().triangulation().n_active_cells();
    evaluate();
  }
  result.factorization_time = problem->results().factorization_time;
  settings.output_base = output_base;
  output_results();
  result.total_time = timer.wall_time();
  return result;
}

template <int dim>
std::vector<GearMeshStiffnessResult>
GearMeshStiffness<dim>::roll_to_torques(double position, const std::vector<double>& torques,
                                        const std::string& output_base)
{
  check_torque_list(torques);
  // Each position starts again from the first torque (the factorization does not depend on it).
  settings.pinion_torque = torques.front();
  if (problem)
    problem->set_hub_target("pinion bore", torques.front());
  std::vector<GearMeshStiffnessResult> results{roll_to(position, output_base)};
  for (std::size_t t = 1; t < torques.size(); ++t)
    results.push_back(next_torque(torques[t]));
  return results;
}

template std::vector<GearMeshStiffnessResult>
GearMeshStiffness<2>::roll_to_torques(double, const std::vector<double>&, const std::string&);
template std::vector<GearMeshStiffnessResult>
GearMeshStiffness<3>::roll_to_torques(double, const std::vector<double>&, const std::string&);
template GearMeshStiffnessResult GearMeshStiffness<2>::roll_to(double, const std::string&);
template GearMeshStiffnessResult GearMeshStiffness<3>::roll_to(double, const std::string&);
} // namespace gearstiff::stiffness
