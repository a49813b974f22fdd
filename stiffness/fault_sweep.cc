#include "stiffness/fault_sweep.h"

#include "errors/errors.h"
#include "errors/format.h"
#include "geometry/tooth_fault.h"
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
std::string gear_entry(bool wheel, const std::string& name)
{
  return std::string("Gear pair/") + (wheel ? "Wheel/" : "Pinion/") + name;
}

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
    throw InputError(gear_entry(!spec.wheel, "faulty tooth"),
                     "a fault sweep follows the faulty tooth of one gear: the other gear must be "
                     "healthy");
  if (own.count(spec.faulty_tooth) == 0 || own.size() != 1)
    throw InputError(gear_entry(spec.wheel, "faulty tooth"),
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

template <int dim>
GearMeshStiffnessResult solve_at(MPI_Comm mpi_communicator, GearMeshStiffnessSettings settings,
                                 double position, double base_radius, const std::string& file)
{
  settings.scene.pinion_roll_angle = position / base_radius;
  settings.scene_file = file;
  const GearMeshStiffnessResult result = solve_on_first_rank<dim>(mpi_communicator, settings);
  if (dealii::Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    std::filesystem::remove(file);
  return result;
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
} // namespace

template <int dim>
FaultSweepResult fault_sweep(MPI_Comm mpi_communicator, const GearMeshStiffnessSettings& settings,
                             const FaultSweepSpec& spec, const std::string& scene_file_stem,
                             const std::function<void(const std::string&)>& progress)
{
  const auto start = std::chrono::steady_clock::now();
  if (spec.positions_per_pitch < 1)
    throw InputError("Stiffness/sweep positions", "must be at least 1");
  const SweepScenes scenes = sweep_scenes(settings, spec);
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(settings.scene.pair);
  const double r_b1 = 0.5 * pair.pinion.base_diameter;
  const unsigned int n = spec.positions_per_pitch;
  std::vector<double> positions;
  for (unsigned int i = 0;; ++i)
  {
    const double position = pair.contact_start + (i + 0.5) * pair.transverse_base_pitch / n;
    if (position >= pair.contact_end)
      break;
    positions.push_back(position);
  }
  FaultSweepResult result;
  // The energy method beside the FE: where its section rule has no material left (a crack
  // past the centre line under a thin tip), it fails and the FE rows stand alone.
  std::vector<EnergyPosition> energy_healthy(positions.size()), energy_faulty(positions.size());
  try
  {
    energy_healthy = energy_mesh_stiffness(scenes.healthy.scene, positions);
    energy_faulty = energy_mesh_stiffness(scenes.faulty.scene, positions);
  }
  catch (const SolverFailure& failure)
  {
    result.energy_failure = failure.what();
  }
  std::vector<double> healthy_k, healthy_te;
  for (unsigned int i = 0; i < n; ++i)
  {
    const GearMeshStiffnessResult r =
        solve_at<dim>(mpi_communicator, scenes.healthy, positions[i], r_b1,
                      scene_file_stem + "_healthy_" + std::to_string(i) + ".msh");
    healthy_k.push_back(r.mesh_stiffness);
    healthy_te.push_back(r.transmission_error);
    if (progress)
      progress("healthy position " + std::to_string(i + 1) + "/" + std::to_string(n) + ": k " +
               format_number(r.mesh_stiffness * 1e-6, 5) + " N/µm");
  }
  for (unsigned int i = 0; i < positions.size(); ++i)
  {
    FaultSweepRow row;
    row.position = positions[i];
    row.mesh_position = (positions[i] - pair.contact_start) / pair.transverse_base_pitch;
    row.healthy_stiffness = healthy_k[i % n];
    row.healthy_transmission_error = healthy_te[i % n];
    row.energy_healthy = energy_healthy[i].mesh_stiffness;
    row.energy_faulty = energy_faulty[i].lost_contact ? 0. : energy_faulty[i].mesh_stiffness;
    const std::vector<int> carrying =
        geometry::carrying_gear_pairs(scenes.faulty.scene, positions[i]);
    row.faulty_pairs = carrying.size();
    row.lost_contact = carrying.empty();
    if (!row.lost_contact)
    {
      const GearMeshStiffnessResult r =
          solve_at<dim>(mpi_communicator, scenes.faulty, positions[i], r_b1,
                        scene_file_stem + "_faulty_" + std::to_string(i) + ".msh");
      row.faulty_stiffness = r.mesh_stiffness;
      row.faulty_transmission_error = r.transmission_error;
      if (!r.crack_tips.empty())
      {
        row.mode_one = r.crack_tips.front().mode_one;
        row.mode_two = r.crack_tips.front().mode_two;
      }
    }
    if (progress)
      progress("faulty position " + std::to_string(i + 1) + "/" + std::to_string(positions.size()) +
               ": " +
               (row.lost_contact ? std::string("loss of contact")
                                 : "k " + format_number(row.faulty_stiffness * 1e-6, 5) + " N/µm"));
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
