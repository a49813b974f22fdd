#include "stiffness/mesh_stiffness_sweep.h"

#include "errors/errors.h"
#include "errors/format.h"
#include "fem/parallel.h"
#include "geometry/fields.h"
#include "geometry/tooth_fault.h"

#include <algorithm>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <cmath>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <memory>
#include <sstream>

namespace gearstiff::stiffness
{
using namespace dealii;

std::vector<double> sweep_positions(const kinematics::GearPairGeometry& pair,
                                    const StiffnessSweepSpec& spec)
{
  if (spec.positions == 0)
    throw InputError(stiffness_parameter::positions,
                     "must be at least 1 (a sweep with zero positions computes nothing)");
  if (!(spec.base_pitches > 0.) || !std::isfinite(spec.base_pitches))
    throw InputError(stiffness_parameter::pitches, "must be positive and finite");
  const double r_b1 = 0.5 * pair.pinion.base_diameter;
  const bool given_start = spec.start_position >= 0.;
  const double start = given_start ? spec.start_position : pair.contact_start;
  // A start off the path is the start's fault, not the span's (inf was blamed on the pitches).
  if (given_start && !(start >= pair.contact_start && start < pair.contact_end))
    throw InputError(stiffness_parameter::start,
                     "the sweep starts off the path of contact: " +
                         format_number(start / r_b1 * 180. / M_PI, 6) + "°, the path spans " +
                         format_number(pair.contact_start / r_b1 * 180. / M_PI, 6) + "° to " +
                         format_number(pair.contact_end / r_b1 * 180. / M_PI, 6) +
                         "° (negative: its start A)");
  const double length = spec.base_pitches * pair.transverse_base_pitch;
  const double step = length / spec.positions;
  std::vector<double> positions;
  for (unsigned int i = 0; i < spec.positions; ++i)
    positions.push_back(start + (i + 0.5) * step);
  // The reference pair must stay on the path of contact, or no pair of the scene would be
  // followed through the sweep.
  if (positions.front() < pair.contact_start || positions.back() > pair.contact_end)
  {
    throw InputError(stiffness_parameter::pitches,
                     "the sweep runs off the path of contact: it spans roll angles " +
                         format_number(positions.front() / r_b1 * 180. / M_PI, 4) + "° to " +
                         format_number(positions.back() / r_b1 * 180. / M_PI, 4) +
                         "°, the path of "
                         "contact " +
                         format_number(pair.contact_start / r_b1 * 180. / M_PI, 4) + "° to " +
                         format_number(pair.contact_end / r_b1 * 180. / M_PI, 4) + "° (" +
                         format_number(pair.transverse_contact_ratio, 4) + " base pitches)");
  }
  return positions;
}

// One position of the sweep under every torque of settings.torques (one result: pinion_torque
// alone when the list is empty), solved serially with one scene and one factorization
// (GearMeshStiffness::run_torques); its scene file is removed whatever happens, and a failure's
// reason starts with `context`.
template <int dim>
std::vector<GearMeshStiffnessResult>
solve_position_torques(const GearMeshStiffnessSettings& settings, const double roll_angle,
                       const std::string& suffix, const std::string& scene_file_stem,
                       const std::string& context)
{
  GearMeshStiffnessSettings local = settings;
  local.scene.position = geometry::PairPosition::roll_angle;
  local.scene.pinion_roll_angle = roll_angle;
  local.scene_file = scene_file_stem + "_" + suffix + ".msh";
  local.output_base = settings.output_base + "_" + suffix;
  std::vector<GearMeshStiffnessResult> results;
  const fem::Failure failure = fem::catch_failure(
      [&]()
      {
        GearMeshStiffness<dim> analysis(MPI_COMM_SELF, local);
        if (settings.torques.empty())
          results = {analysis.run()};
        else
          results = analysis.run_torques(settings.torques);
      });
  std::filesystem::remove(local.scene_file);
  failure.rethrow(context);
  return results;
}

// One position of a rolling sweep: the rank's analysis is made (meshed, factorized) by its
// first position; a failure's reason starts with `context`.
template <int dim>
std::vector<GearMeshStiffnessResult>
roll_position(std::unique_ptr<GearMeshStiffness<dim>>& analysis,
              const GearMeshStiffnessSettings& settings, const double position,
              const std::string& suffix, const std::string& context)
{
  std::vector<GearMeshStiffnessResult> result;
  const fem::Failure failure = fem::catch_failure(
      [&]()
      {
        if (!analysis)
          analysis = std::make_unique<GearMeshStiffness<dim>>(MPI_COMM_SELF, settings);
        const std::string base = settings.output_base + "_" + suffix;
        if (settings.torques.empty())
          result = {analysis->roll_to(position, base)};
        else
          result = analysis->roll_to_torques(position, settings.torques, base);
      });
  if (!analysis || failure.kind != fem::Failure::none)
    std::filesystem::remove(settings.scene_file);
  failure.rethrow(context);
  return result;
}

// Every position's result on every rank, with the rank that solved it; the once and
// per-position times of the sweep.
StiffnessSweepResult gather_positions(
    MPI_Comm mpi_communicator,
    const std::vector<std::pair<unsigned int, std::vector<GearMeshStiffnessResult>>>& mine,
    unsigned int n, SweepMesh mesh, unsigned int n_torques)
{
  StiffnessSweepResult result;
  result.mesh = mesh;
  result.n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
  result.positions.resize(n);
  result.rank_of_position.resize(n);
  // With a torque list, one result per torque and position (run_torques).
  result.by_torque.assign(n_torques, std::vector<GearMeshStiffnessResult>(n));
  const auto gathered = Utilities::MPI::all_gather(mpi_communicator, mine);
  for (unsigned int r = 0; r < gathered.size(); ++r)
    for (const auto& [i, position] : gathered[r])
    {
      result.positions[i] = position.front();
      for (unsigned int t = 0; t < n_torques; ++t)
        result.by_torque[t][i] = position.at(t);
      result.rank_of_position[i] = r;
    }
  for (const auto& position : result.positions)
  {
    // The fixed part of a rolling sweep: the scene, set-up and factorization of each rank's
    // first position (scene_time > 0 only there).
    const double once =
        position.scene_time > 0. && mesh == SweepMesh::once
            ? position.scene_time + position.setup_time + position.factorization_time
            : 0.;
    result.once_time += once;
    result.per_position_time += position.total_time - once;
  }
  return result;
}

// The progress line of position i of n (`once`: with its mesh, set-up and contact times).
std::string position_line(const GearMeshStiffnessResult& r, unsigned int i, unsigned int n,
                          bool once)
{
  return "position " + std::to_string(i + 1) + "/" + std::to_string(n) + " (roll angle " +
         format_number(r.pinion_roll_angle * 180. / M_PI, 5) +
         "°): k = " + format_number(r.mesh_stiffness / 1e6, 5) + " N/µm, " +
         std::to_string(r.loaded_pairs) + " pair(s), " + format_number(r.total_time, 3) + " s" +
         (once ? " (mesh " + format_number(r.scene_time, 3) + " s, set-up " +
                     format_number(r.setup_time, 3) + " s, contact " +
                     format_number(r.solve_time, 3) + " s)"
               : std::string());
}

template <int dim>
StiffnessSweepResult
stiffness_sweep(MPI_Comm mpi_communicator, const GearMeshStiffnessSettings& settings,
                const StiffnessSweepSpec& spec, const std::string& scene_file_stem,
                const std::function<void(const std::string&)>& progress)
{
  if (settings.contact_model == ContactModel::influence_coefficients)
    throw InputError(stiffness_parameter::contact_model,
                     "influence coefficients run through stiffness::influence_sweep "
                     "(stiffness/influence_sweep.h), not the finite-element sweep");
  Timer timer(mpi_communicator, true);
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(settings.scene.pair);
  const std::vector<double> positions = sweep_positions(pair, spec);
  const unsigned int n = positions.size();
  const unsigned int rank = Utilities::MPI::this_mpi_process(mpi_communicator);
  const double r_b1 = 0.5 * pair.pinion.base_diameter;
  // Each rank's positions start from the contact zone of its previous one.
  GearMeshStiffnessSettings warm = settings;
  warm.warm_start = std::make_shared<std::vector<contact::ContactZone>>();

  // `once`: every rank meshes the same scene (at the first position, refined for all of them)
  // and factorizes it when it takes its first position.
  GearMeshStiffnessSettings rolling = warm;
  rolling.scene.position = geometry::PairPosition::roll_angle;
  rolling.scene.pinion_roll_angle = positions.front() / r_b1;
  rolling.scene.swept_positions = positions;
  rolling.scene_file = scene_file_stem + "_once_" + std::to_string(rank) + ".msh";
  std::unique_ptr<GearMeshStiffness<dim>> analysis;

  // Each rank takes the next unsolved item as soon as it is free (fem::distribute_items); a
  // failure stops every rank within about one contact iteration, and the first failing
  // position decides what every rank throws. An item is one position, or with `once` a block of
  // neighbouring positions (2 blocks per rank): a rank then rolls by one step at a time, and
  // the unit responses of a position's contact zone serve its neighbour's too, which overlaps
  // it (3D Q1, 32 positions: see bench/contact_speed.md).
  if (!settings.torques.empty())
    check_torque_list(settings.torques);
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
  const unsigned int block =
      spec.mesh == SweepMesh::once ? std::max(1u, (n + 2 * n_ranks - 1) / (2 * n_ranks)) : 1;
  std::vector<std::pair<unsigned int, std::vector<GearMeshStiffnessResult>>> mine;
  const auto solve_position = [&](const unsigned int i)
  {
    const std::string where = "sweep position " + std::to_string(i + 1) + " (roll angle " +
                              format_number(positions[i] / r_b1 * 180. / M_PI, 5) + "°): ";
    const std::vector<GearMeshStiffnessResult> all =
        spec.mesh == SweepMesh::once
            ? roll_position(analysis, rolling, positions[i], Utilities::int_to_string(i, 3), where)
            : solve_position_torques<dim>(warm, positions[i] / r_b1, Utilities::int_to_string(i, 3),
                                          scene_file_stem, where);
    const GearMeshStiffnessResult& r = all.front();
    mine.emplace_back(i, all);
    if (progress)
      progress(position_line(r, i, n, spec.mesh == SweepMesh::once) + " [rank " +
               std::to_string(rank) + ": " + std::to_string(mine.size()) + " solved]");
  };
  fem::distribute_items(mpi_communicator, (n + block - 1) / block,
                        [&](const unsigned int item)
                        {
                          for (unsigned int i = item * block; i < std::min(n, (item + 1) * block);
                               ++i)
                          {
                            if (i > item * block)
                              fem::interruption_point();
                            solve_position(i);
                          }
                        });

  if (spec.mesh == SweepMesh::once)
    std::filesystem::remove(rolling.scene_file);

  // Every rank receives every position's result.
  StiffnessSweepResult result =
      gather_positions(mpi_communicator, mine, n, spec.mesh, settings.torques.size());
  result.torques = settings.torques;
  result.wall_time = timer.wall_time();
  return result;
}

template <int dim>
GearMeshStiffnessResult solve_on_first_rank(MPI_Comm mpi_communicator,
                                            const GearMeshStiffnessSettings& settings)
{
  return fem::run_on_root(mpi_communicator,
                          [&]()
                          {
                            GearMeshStiffness<dim> analysis(MPI_COMM_SELF, settings);
                            return analysis.run();
                          });
}

geometry::SceneMeshSettings scaled_mesh(const geometry::SceneMeshSettings& mesh, double factor)
{
  if (!(mesh.contact_size > 0.))
    throw InputError(geometry::field::mesh("contact_size"),
                     "a refinement study needs an explicit contact size");
  if (!(mesh.rim_size > 0.))
    throw InputError(geometry::field::mesh("rim_size"),
                     "a refinement study needs an explicit rim size");
  geometry::SceneMeshSettings scaled = mesh;
  scaled.contact_size *= factor;
  scaled.body_size *= factor;
  scaled.rim_size *= factor;
  scaled.growth_rate *= factor;
  return scaled;
}

RichardsonEstimate richardson_estimate(const std::vector<RefinementLevel>& levels)
{
  if (levels.size() < 3)
    throw InputError("refinement levels", "a Richardson estimate needs three levels");
  const std::size_t n = levels.size();
  const double k0 = levels[n - 3].stiffness, k1 = levels[n - 2].stiffness,
               k2 = levels[n - 1].stiffness;
  const double d1 = k1 - k0, d2 = k2 - k1;
  RichardsonEstimate estimate;
  estimate.monotone = d1 * d2 > 0.;
  if (!estimate.monotone || std::abs(d2) >= std::abs(d1))
    throw SolverFailure("Richardson extrapolation",
                        "the three finest levels are not in the asymptotic range (differences " +
                            format_number(d1, 4) + ", " + format_number(d2, 4) + " N/m)");
  const double ratio = levels[n - 2].size_factor / levels[n - 1].size_factor;
  estimate.observed_order = std::log(d1 / d2) / std::log(ratio);
  estimate.extrapolated = k2 + d2 / (std::pow(ratio, estimate.observed_order) - 1.);
  estimate.error_finest = std::abs(k2 - estimate.extrapolated) / estimate.extrapolated;
  return estimate;
}

template GearMeshStiffnessResult solve_on_first_rank<2>(MPI_Comm, const GearMeshStiffnessSettings&);
template GearMeshStiffnessResult solve_on_first_rank<3>(MPI_Comm, const GearMeshStiffnessSettings&);
template StiffnessSweepResult stiffness_sweep<2>(MPI_Comm, const GearMeshStiffnessSettings&,
                                                 const StiffnessSweepSpec&, const std::string&,
                                                 const std::function<void(const std::string&)>&);
template StiffnessSweepResult stiffness_sweep<3>(MPI_Comm, const GearMeshStiffnessSettings&,
                                                 const StiffnessSweepSpec&, const std::string&,
                                                 const std::function<void(const std::string&)>&);
bool once_sweep_valid(
    const GearMeshStiffnessSettings& settings,
    const std::vector<std::pair<geometry::GearModifications, geometry::GearModifications>>&
        variants)
{
  bool whole = geometry::flanks_whole(settings.scene.pinion_modifications) &&
               geometry::flanks_whole(settings.scene.wheel_modifications);
  for (const auto& [pinion, wheel] : variants)
    whole = whole && geometry::flanks_whole(pinion) && geometry::flanks_whole(wheel);
  return settings.scene.mesh.dimension == 2 && whole &&
         settings.contact.iteration_solves != contact::IterationSolves::full_resolve &&
         settings.linear_solver.method == fem::LinearSolverMethod::direct_mumps;
}
} // namespace gearstiff::stiffness
