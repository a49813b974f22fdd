#include "stiffness/fault_sweep.h"

#include "errors/errors.h"
#include "errors/format.h"
#include "geometry/tooth_fault.h"
#include "kinematics/fields.h"
#include "stiffness/mesh_stiffness_sweep.h"

#include <chrono>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <map>

namespace gearstiff::stiffness
{
namespace
{
// The gear's per-tooth faults removed (micro-geometry kept); returns the removed lists.
std::map<int, std::vector<geometry::ToothModification>>
take_faults(geometry::GearModifications& modifications)
{
  std::map<int, std::vector<geometry::ToothModification>> taken;
  for (auto& [index, list] : modifications.by_tooth)
    if (geometry::has_faults(list))
    {
      taken[index] = list;
      list.clear();
    }
  return taken;
}

// The healthy and the faulty scenes: the fault of tooth f moved to the scene's reference tooth.
struct SweepScenes
{
  GearMeshStiffnessSettings healthy, faulty;
};

SweepScenes sweep_scenes(const GearMeshStiffnessSettings& settings, const FaultSweepSpec& spec)
{
  SweepScenes s{settings, settings};
  auto own = take_faults(spec.wheel ? s.healthy.scene.wheel_modifications
                                    : s.healthy.scene.pinion_modifications);
  const auto other = take_faults(spec.wheel ? s.healthy.scene.pinion_modifications
                                            : s.healthy.scene.wheel_modifications);
  if (!other.empty())
    throw InputError(kinematics::field::gear(!spec.wheel, "faulty_tooth"),
                     "a fault sweep follows the faulty tooth of one gear: the other gear must be "
                     "healthy");
  if (own.count(spec.faulty_tooth) == 0 || own.size() != 1)
    throw InputError(kinematics::field::gear(spec.wheel, "faulty_tooth"),
                     "a fault sweep needs one faulty tooth with a fault (crack, spall, chipping "
                     "or broken tooth)");
  s.faulty = s.healthy;
  // The scene's reference tooth (pair 0) is the faulty one: pinion tooth 0 or wheel tooth 0.
  auto& faulty =
      spec.wheel ? s.faulty.scene.wheel_modifications : s.faulty.scene.pinion_modifications;
  faulty.by_tooth[0] = own.at(spec.faulty_tooth);
  for (GearMeshStiffnessSettings* one : {&s.healthy, &s.faulty})
  {
    one->scene.position = geometry::PairPosition::roll_angle;
    one->warm_start = nullptr;
  }
  return s;
}

// The share of the load (-) pair j carries (0: not among the pairs).
double share_of(const GearMeshStiffnessResult& result, int j)
{
  for (const ToothPairLoad& load : result.pairs)
    if (load.pair == j)
      return load.load_share;
  return 0.;
}

// The FE results at `positions` (m from T1): with `once` a rolling sweep over them (they are
// A + (i + ½)·p_bt/N, i < count: the sweep from A over count/N base pitches), else each position a
// scene of its own on the first rank. Positions in `lost` (no pair touches) are not solved.
template <int dim>
std::vector<GearMeshStiffnessResult>
solve_positions(MPI_Comm mpi_communicator, const GearMeshStiffnessSettings& settings,
                const FaultSweepSpec& spec, const std::vector<double>& positions,
                const std::vector<bool>& lost, const std::string& stem, const std::string& label,
                const std::function<void(const std::string&)>& progress)
{
  const auto report = [&](unsigned int i, const std::string& text)
  {
    if (progress)
      progress(label + " position " + std::to_string(i + 1) + "/" +
               std::to_string(positions.size()) + ": " + text);
  };
  if (spec.mesh == SweepMesh::once)
  {
    StiffnessSweepSpec sweep;
    sweep.start_position = -1.; // A
    sweep.base_pitches = double(positions.size()) / spec.positions_per_pitch;
    sweep.positions = positions.size();
    sweep.mesh = SweepMesh::once;
    std::function<void(const std::string&)> rolled;
    if (progress)
      rolled = [&](const std::string& text) { progress(label + " " + text); };
    return stiffness_sweep<dim>(mpi_communicator, settings, sweep, stem + label, rolled).positions;
  }
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(settings.scene.pair);
  std::vector<GearMeshStiffnessResult> results(positions.size());
  for (unsigned int i = 0; i < positions.size(); ++i)
  {
    if (lost[i])
    {
      report(i, "loss of contact");
      continue;
    }
    GearMeshStiffnessSettings one = settings;
    one.scene.pinion_roll_angle = positions[i] / (0.5 * pair.pinion.base_diameter);
    one.scene_file = stem + "_" + label + "_" + std::to_string(i) + ".msh";
    results[i] = solve_on_first_rank<dim>(mpi_communicator, one);
    if (dealii::Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      std::filesystem::remove(one.scene_file);
    report(i, "k " + format_number(results[i].mesh_stiffness * 1e-6, 5) + " N/µm");
  }
  return results;
}

void fill_revolution_table(const kinematics::GearPairGeometry& pair, const FaultSweepSpec& spec,
                           const std::vector<double>& healthy, FaultSweepResult& result)
{
  const unsigned int n = spec.positions_per_pitch;
  const auto& gear = spec.wheel ? pair.spec.wheel : pair.spec.pinion;
  result.period_pitches = static_cast<unsigned int>(gear.teeth);
  const double r_b1 = 0.5 * pair.pinion.base_diameter;
  const int pinion_tooth = spec.wheel ? -spec.faulty_tooth : spec.faulty_tooth;
  const double entry_angle = (pair.contact_start - pair.pitch_point) / r_b1 -
                             pinion_tooth * pair.transverse_base_pitch / r_b1;
  for (unsigned int i = 0; i < result.period_pitches * n; ++i)
  {
    const double x = (i + 0.5) / n;
    result.revolution_position.push_back(x);
    result.revolution_pinion_angle.push_back(entry_angle + x * pair.transverse_base_pitch / r_b1);
    if (i < result.rows.size())
    {
      result.revolution_stiffness.push_back(result.rows[i].faulty_stiffness);
      result.revolution_lost_contact.push_back(result.rows[i].lost_contact);
    }
    else
    {
      result.revolution_stiffness.push_back(healthy[i % n]);
      result.revolution_lost_contact.push_back(false);
    }
  }
}
// The middles of N equal intervals per base pitch along the whole path of contact [m]: the
// positions where the faulty tooth meshes.
std::vector<double> path_positions(const kinematics::GearPairGeometry& pair, unsigned int n)
{
  std::vector<double> positions;
  for (unsigned int i = 0;; ++i)
  {
    const double position = pair.contact_start + (i + 0.5) * pair.transverse_base_pitch / n;
    if (position >= pair.contact_end)
      return positions;
    positions.push_back(position);
  }
}
} // namespace

template <int dim>
FaultSweepResult fault_sweep(MPI_Comm mpi_communicator, const GearMeshStiffnessSettings& settings,
                             const FaultSweepSpec& spec, const std::string& scene_file_stem,
                             const std::function<void(const std::string&)>& progress)
{
  const auto start = std::chrono::steady_clock::now();
  if (spec.positions_per_pitch < 1)
    throw InputError(stiffness_parameter::positions, "must be at least 1");
  const SweepScenes scenes = sweep_scenes(settings, spec);
  if (spec.mesh == SweepMesh::once &&
      !geometry::flanks_whole(spec.wheel ? scenes.faulty.scene.wheel_modifications
                                         : scenes.faulty.scene.pinion_modifications))
    throw InputError(stiffness_parameter::sweep_mesh,
                     "once cannot roll a broken, chipped or spalled tooth (it changes which pairs "
                     "carry from one position to the next): per position or automatic");
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(settings.scene.pair);
  const unsigned int n = spec.positions_per_pitch;
  const std::vector<double> positions = path_positions(pair, n);
  FaultSweepResult result;
  // The energy method beside the FE: where its section rule has no material left (a crack
  // past the centre line under a thin tip), it fails and the FE rows stand alone.
  std::vector<EnergyPosition> energy_healthy(positions.size()), energy_faulty(positions.size());
  // The method's ring is not modelled: a faulty planet in its ring has the FE alone.
  if (settings.scene.pair.wheel.internal)
    result.energy_failure = "the energy method models external pairs only";
  else
    try
    {
      energy_healthy = energy_mesh_stiffness(scenes.healthy.scene, positions);
      energy_faulty = energy_mesh_stiffness(scenes.faulty.scene, positions);
    }
    catch (const SolverFailure& failure)
    {
      result.energy_failure = failure.what();
    }
  std::vector<bool> lost(positions.size());
  std::vector<int> carrying_count(positions.size());
  for (unsigned int i = 0; i < positions.size(); ++i)
  {
    carrying_count[i] = geometry::carrying_gear_pairs(scenes.faulty.scene, positions[i]).size();
    lost[i] = carrying_count[i] == 0;
  }
  const std::vector<double> healthy_positions(positions.begin(), positions.begin() + n);
  const std::vector<GearMeshStiffnessResult> healthy =
      solve_positions<dim>(mpi_communicator, scenes.healthy, spec, healthy_positions,
                           std::vector<bool>(n, false), scene_file_stem, "healthy", progress);
  const std::vector<GearMeshStiffnessResult> faulty = solve_positions<dim>(
      mpi_communicator, scenes.faulty, spec, positions, lost, scene_file_stem, "faulty", progress);
  std::vector<double> healthy_k;
  for (const GearMeshStiffnessResult& r : healthy)
    healthy_k.push_back(r.mesh_stiffness);
  for (unsigned int i = 0; i < positions.size(); ++i)
  {
    FaultSweepRow row;
    row.position = positions[i];
    row.mesh_position = (positions[i] - pair.contact_start) / pair.transverse_base_pitch;
    row.healthy_stiffness = healthy[i % n].mesh_stiffness;
    row.healthy_transmission_error = healthy[i % n].transmission_error;
    // The faulty tooth is pair i / N of the healthy pitch's scene at the same offset.
    row.healthy_share = share_of(healthy[i % n], static_cast<int>(i / n));
    row.energy_healthy = energy_healthy[i].mesh_stiffness;
    row.energy_faulty = energy_faulty[i].lost_contact ? 0. : energy_faulty[i].mesh_stiffness;
    row.faulty_pairs = carrying_count[i];
    row.lost_contact = lost[i];
    if (!row.lost_contact)
    {
      row.faulty_stiffness = faulty[i].mesh_stiffness;
      row.faulty_transmission_error = faulty[i].transmission_error;
      row.faulty_share = share_of(faulty[i], 0);
      if (!faulty[i].crack_tips.empty())
      {
        result.crack_tip_factors = true;
        row.mode_one = faulty[i].crack_tips.front().mode_one;
        row.mode_two = faulty[i].crack_tips.front().mode_two;
      }
    }
    result.rows.push_back(row);
  }
  fill_revolution_table(pair, spec, healthy_k, result);
  result.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

template FaultSweepResult fault_sweep<2>(MPI_Comm, const GearMeshStiffnessSettings&,
                                         const FaultSweepSpec&, const std::string&,
                                         const std::function<void(const std::string&)>&);
template FaultSweepResult fault_sweep<3>(MPI_Comm, const GearMeshStiffnessSettings&,
                                         const FaultSweepSpec&, const std::string&,
                                         const std::function<void(const std::string&)>&);
} // namespace gearstiff::stiffness
