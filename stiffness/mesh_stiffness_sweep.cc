#include "stiffness/mesh_stiffness_sweep.h"

#include "errors/errors.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <sstream>

namespace gearstiff::stiffness
{
using namespace dealii;

namespace
{
// Results cross ranks as fixed-length rows of doubles (a position's row is zero on the
// ranks that did not solve it, so one sum gathers them all).
constexpr unsigned int max_pairs = 6;
constexpr unsigned int pair_fields = 7;
constexpr unsigned int scalar_fields = 26;
constexpr unsigned int row_length = scalar_fields + max_pairs * pair_fields;

std::vector<double> pack(const GearMeshStiffnessResult& r)
{
  std::vector<double> row{r.pinion_roll_angle,    r.reference_position,
                          r.mesh_position,        double(r.kinematic_pairs),
                          double(r.loaded_pairs), r.pinion_torque,
                          r.pinion_rotation,      r.pinion_base_radius,
                          r.wheel_base_radius,    r.mesh_stiffness,
                          r.transmission_error,   r.wheel_torque,
                          r.torque_ratio,         r.pinion_hub_torque,
                          r.max_contact_pressure, r.pinion_root_stress,
                          r.wheel_root_stress,    double(r.dimension),
                          double(r.n_cells),      double(r.n_dofs),
                          r.contact_size,         double(r.active_set_iterations),
                          r.scene_time,           r.setup_time,
                          r.solve_time,           r.total_time};
  row.resize(row_length, 0.);
  if (r.pairs.size() > max_pairs)
    throw SolverFailure("stiffness sweep", "more tooth pairs than the result rows hold");
  for (unsigned int k = 0; k < r.pairs.size(); ++k)
  {
    const ToothPairLoad& p = r.pairs[k];
    double* slot = &row[scalar_fields + k * pair_fields];
    // The first field marks the slot as used (a pair index shifted away from zero).
    slot[0] = p.pair + 1000.;
    slot[1] = p.position;
    slot[2] = p.normal_force;
    slot[3] = p.load_share;
    slot[4] = p.max_pressure;
    slot[5] = p.contact_length;
    slot[6] = p.closed_nodes;
  }
  return row;
}

GearMeshStiffnessResult unpack(const double* row)
{
  GearMeshStiffnessResult r;
  unsigned int i = 0;
  r.pinion_roll_angle = row[i++];
  r.reference_position = row[i++];
  r.mesh_position = row[i++];
  r.kinematic_pairs = std::lround(row[i++]);
  r.loaded_pairs = std::lround(row[i++]);
  r.pinion_torque = row[i++];
  r.pinion_rotation = row[i++];
  r.pinion_base_radius = row[i++];
  r.wheel_base_radius = row[i++];
  r.mesh_stiffness = row[i++];
  r.transmission_error = row[i++];
  r.wheel_torque = row[i++];
  r.torque_ratio = row[i++];
  r.pinion_hub_torque = row[i++];
  r.max_contact_pressure = row[i++];
  r.pinion_root_stress = row[i++];
  r.wheel_root_stress = row[i++];
  r.dimension = std::lround(row[i++]);
  r.n_cells = std::lround(row[i++]);
  r.n_dofs = std::lround(row[i++]);
  r.contact_size = row[i++];
  r.active_set_iterations = std::lround(row[i++]);
  r.scene_time = row[i++];
  r.setup_time = row[i++];
  r.solve_time = row[i++];
  r.total_time = row[i++];
  for (unsigned int k = 0; k < max_pairs; ++k)
  {
    const double* slot = row + scalar_fields + k * pair_fields;
    if (slot[0] == 0.)
      break;
    ToothPairLoad p;
    p.pair = static_cast<int>(std::lround(slot[0] - 1000.));
    p.position = slot[1];
    p.normal_force = slot[2];
    p.load_share = slot[3];
    p.max_pressure = slot[4];
    p.contact_length = slot[5];
    p.closed_nodes = std::lround(slot[6]);
    r.pairs.push_back(p);
  }
  return r;
}

std::string format(double value, int precision = 4)
{
  std::ostringstream s;
  s.precision(precision);
  s << value;
  return s.str();
}
} // namespace

std::vector<double> sweep_positions(const kinematics::GearPairGeometry& pair,
                                    const StiffnessSweepSpec& spec)
{
  if (spec.positions == 0)
    throw InputError(stiffness_parameter::positions,
                     "must be at least 1 (a sweep with zero positions computes nothing)");
  if (!(spec.base_pitches > 0.))
    throw InputError(stiffness_parameter::pitches, "must be positive");
  const double start = spec.start_position < 0. ? pair.contact_start : spec.start_position;
  const double length = spec.base_pitches * pair.transverse_base_pitch;
  const double step = length / spec.positions;
  std::vector<double> positions;
  for (unsigned int i = 0; i < spec.positions; ++i)
    positions.push_back(start + (i + 0.5) * step);
  // The reference pair must stay on the path of contact, or no pair of the scene would be
  // followed through the sweep.
  if (positions.front() < pair.contact_start || positions.back() > pair.contact_end)
  {
    const double r_b1 = 0.5 * pair.pinion.base_diameter;
    throw InputError(stiffness_parameter::pitches,
                     "the sweep runs off the path of contact: it spans roll angles " +
                         format(positions.front() / r_b1 * 180. / M_PI) + "° to " +
                         format(positions.back() / r_b1 * 180. / M_PI) +
                         "°, the path of "
                         "contact " +
                         format(pair.contact_start / r_b1 * 180. / M_PI) + "° to " +
                         format(pair.contact_end / r_b1 * 180. / M_PI) + "° (" +
                         format(pair.transverse_contact_ratio) + " base pitches)");
  }
  return positions;
}

template <int dim>
StiffnessSweepResult
stiffness_sweep(MPI_Comm mpi_communicator, const GearMeshStiffnessSettings& settings,
                const StiffnessSweepSpec& spec, const std::string& scene_file_stem,
                const std::function<void(const std::string&)>& progress)
{
  Timer timer(mpi_communicator, true);
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(settings.scene.pair);
  const std::vector<double> positions = sweep_positions(pair, spec);
  const unsigned int n = positions.size();
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
  const unsigned int rank = Utilities::MPI::this_mpi_process(mpi_communicator);
  const double r_b1 = 0.5 * pair.pinion.base_diameter;

  // Round-robin: neighbouring positions cost about the same, so each rank gets a fair share.
  std::vector<double> rows(std::size_t(n) * row_length, 0.);
  std::vector<double> owner(n, 0.);
  int failed_position = static_cast<int>(n); // first failure on this rank (n: none)
  int failure_kind = 0;                      // 1 InputError, 2 SolverFailure, 3 other
  std::string failure_first, failure_second;
  unsigned int done = 0, mine = 0;
  for (unsigned int i = rank; i < n; i += n_ranks)
    ++mine;
  for (unsigned int i = rank; i < n && failure_kind == 0; i += n_ranks)
  {
    GearMeshStiffnessSettings local = settings;
    local.scene.position = geometry::PairPosition::roll_angle;
    local.scene.pinion_roll_angle = positions[i] / r_b1;
    local.scene_file = scene_file_stem + "_" + Utilities::int_to_string(i, 3) + ".msh";
    local.output_base = settings.output_base + "_" + Utilities::int_to_string(i, 3);
    try
    {
      GearMeshStiffness<dim> analysis(MPI_COMM_SELF, local);
      const GearMeshStiffnessResult r = analysis.run();
      std::filesystem::remove(local.scene_file);
      const std::vector<double> row = pack(r);
      std::copy(row.begin(), row.end(), rows.begin() + std::size_t(i) * row_length);
      owner[i] = rank;
      ++done;
      if (progress)
        progress("position " + std::to_string(i + 1) + "/" + std::to_string(n) + " (roll angle " +
                 format(r.pinion_roll_angle * 180. / M_PI, 5) +
                 "°): k = " + format(r.mesh_stiffness / 1e6, 5) + "e6 N/m, " +
                 std::to_string(r.loaded_pairs) + " pair(s), " + format(r.total_time, 3) +
                 " s [rank 0: " + std::to_string(done) + "/" + std::to_string(mine) + "]");
    }
    catch (const InputError& e)
    {
      failure_kind = 1;
      failure_first = e.parameter();
      failure_second = e.reason();
    }
    catch (const SolverFailure& e)
    {
      failure_kind = 2;
      failure_first = e.method();
      const std::string what = e.what();
      failure_second = what.substr(std::min(what.size(), failure_first.size() + 2));
    }
    catch (const std::exception& e)
    {
      failure_kind = 3;
      failure_second = e.what();
    }
    if (failure_kind != 0)
    {
      failed_position = static_cast<int>(i);
      std::filesystem::remove(local.scene_file);
    }
  }

  // The first failing position (lowest index) decides the exception every rank throws.
  struct
  {
    int position;
    int rank;
  } local_failure{failed_position, static_cast<int>(rank)}, first_failure{};
  MPI_Allreduce(&local_failure, &first_failure, 1, MPI_2INT, MPI_MINLOC, mpi_communicator);
  if (first_failure.position < static_cast<int>(n))
  {
    MPI_Bcast(&failure_kind, 1, MPI_INT, first_failure.rank, mpi_communicator);
    failure_first = Utilities::MPI::broadcast(mpi_communicator, failure_first, first_failure.rank);
    failure_second =
        Utilities::MPI::broadcast(mpi_communicator, failure_second, first_failure.rank);
    const std::string where =
        "sweep position " + std::to_string(first_failure.position + 1) + " (roll angle " +
        format(positions[first_failure.position] / r_b1 * 180. / M_PI, 5) + "°): ";
    if (failure_kind == 1)
      throw InputError(failure_first, where + failure_second);
    if (failure_kind == 2)
      throw SolverFailure(failure_first, where + failure_second);
    throw std::runtime_error(where + failure_second);
  }

  Utilities::MPI::sum(rows, mpi_communicator, rows);
  Utilities::MPI::sum(owner, mpi_communicator, owner);
  StiffnessSweepResult result;
  result.n_ranks = n_ranks;
  for (unsigned int i = 0; i < n; ++i)
  {
    result.positions.push_back(unpack(&rows[std::size_t(i) * row_length]));
    result.rank_of_position.push_back(std::lround(owner[i]));
  }
  result.wall_time = timer.wall_time();
  return result;
}

template <int dim>
GearMeshStiffnessResult solve_on_first_rank(MPI_Comm mpi_communicator,
                                            const GearMeshStiffnessSettings& settings)
{
  std::vector<double> row(row_length, 0.);
  int kind = 0; // 1 InputError, 2 SolverFailure, 3 other
  std::string first, second;
  if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
  {
    try
    {
      GearMeshStiffness<dim> analysis(MPI_COMM_SELF, settings);
      row = pack(analysis.run());
    }
    catch (const InputError& e)
    {
      kind = 1;
      first = e.parameter();
      second = e.reason();
    }
    catch (const SolverFailure& e)
    {
      kind = 2;
      first = e.method();
      const std::string what = e.what();
      second = what.substr(std::min(what.size(), first.size() + 2));
    }
    catch (const std::exception& e)
    {
      kind = 3;
      second = e.what();
    }
  }
  MPI_Bcast(&kind, 1, MPI_INT, 0, mpi_communicator);
  if (kind != 0)
  {
    first = Utilities::MPI::broadcast(mpi_communicator, first, 0);
    second = Utilities::MPI::broadcast(mpi_communicator, second, 0);
    if (kind == 1)
      throw InputError(first, second);
    if (kind == 2)
      throw SolverFailure(first, second);
    throw std::runtime_error(second);
  }
  MPI_Bcast(row.data(), row_length, MPI_DOUBLE, 0, mpi_communicator);
  return unpack(row.data());
}

geometry::SceneMeshSettings scaled_mesh(const geometry::SceneMeshSettings& mesh, double factor)
{
  if (!(mesh.contact_size > 0.))
    throw InputError("Mesh/contact size", "a refinement study needs an explicit contact size");
  if (!(mesh.rim_size > 0.))
    throw InputError("Mesh/rim size", "a refinement study needs an explicit rim size");
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
                            format(d1) + ", " + format(d2) + " N/m)");
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
} // namespace gearstiff::stiffness
