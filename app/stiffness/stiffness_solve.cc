#include "app/stiffness/stiffness_solve.h"

#include "app/core/parameter_patterns.h"
#include "app/core/units.h"
#include "app/kinematics/kinematics_parameters.h"
#include "app/scenes/fe_contact_parameters.h"
#include "app/scenes/geometry_parameters.h"
#include "dynamics/train_model.h"
#include "errors/errors.h"
#include "errors/format.h"
#include "errors/limits.h"
#include "geometry/fields.h"
#include "geometry/tooth_fault.h"
#include "kinematics/gear_pair.h"
#include "stiffness/influence_sweep.h"
#include "stiffness/layer_extrapolation.h"
#include "stiffness/transmission_error.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <sstream>
#include <unistd.h>

namespace gearstiff::app
{
namespace
{
// A scratch path in the temporary folder; with `shared` every rank gets rank 0's name (one
// distributed solve reads one file), otherwise each rank its own.
std::string scratch_stem(MPI_Comm communicator, const std::string& name, bool shared)
{
  // In the process's scratch folder (removed at exit and on signals); shared: rank 0's.
  const std::string folder = shared ? shared_scratch_directory(communicator) : scratch_directory();
  return (std::filesystem::path(folder) / name).string();
}

// VTU files go straight into vtu/ of the staging folder; registering each position's PVTU
// record also yields the folder.
std::string vtu_directory(const StiffnessParameters& p, CommandContext& context,
                          const std::vector<std::string>& bases)
{
  if (!p.write_vtu || !context.writes_files())
    return "";
  std::string directory;
  for (const auto& base : bases)
    directory =
        std::filesystem::path(context.output_file("vtu/" + base + ".pvtu",
                                                  "displacement, stress, contact state (VTU)"))
            .parent_path()
            .string();
  return directory;
}

// One position on the scene's own layers.
stiffness::GearMeshStiffnessResult solve_position(const StiffnessParameters& p,
                                                  CommandContext& context, const std::string& label)
{
  stiffness::GearMeshStiffnessSettings settings = p.settings;
  settings.scene_file = scratch_stem(context.mpi_communicator, label, true) + ".msh";
  settings.output_directory = vtu_directory(p, context, {label});
  settings.output_base = label;
  // The stages of the one position (a 3D Q2 scene takes minutes): meshing, setup, solve.
  settings.progress = [&context, &label](const std::string& line)
  { context.progress(label, line); };
  // A 2D position is solved on rank 0 alone: distributed over 2 ranks the default Q2 scene
  // (53k DoFs) took 6.3 s against 6.6 s on one (tests/stiffness, DistributedPositionEqualsSerial
  // checks they agree). A 3D position is distributed over all ranks.
  // With -o, a 2D position also gets a picture of its deformed shape and contact pressure
  // (tools/plot_deformed.py), drawn from its VTU: written to scratch when 'write vtu' is off.
  const bool picture = context.writes_files() && settings.scene.mesh.dimension == 2;
  std::filesystem::path scratch_vtu;
  if (picture && settings.output_directory.empty())
  {
    scratch_vtu = scratch_stem(context.mpi_communicator, label + "-vtu", true);
    if (context.is_root())
      std::filesystem::create_directories(scratch_vtu);
    settings.output_directory = scratch_vtu.string();
  }
  const auto remove_scratch = [&]()
  {
    if (!scratch_vtu.empty() && context.is_root())
      std::filesystem::remove_all(scratch_vtu);
  };
  stiffness::GearMeshStiffnessResult result;
  try
  {
    result = with_parameter_names(
        stiffness_parameter_names(),
        [&]
        {
          return settings.scene.mesh.dimension == 3
                     ? stiffness::GearMeshStiffness<3>(context.mpi_communicator, settings).run()
                     : stiffness::solve_on_first_rank<2>(context.mpi_communicator, settings);
        });
  }
  catch (...)
  {
    if (context.is_root())
      std::filesystem::remove(settings.scene_file);
    remove_scratch();
    throw;
  }
  if (context.is_root())
    std::filesystem::remove(settings.scene_file);
  if (picture && context.is_root())
  {
    std::vector<std::string> pieces;
    for (const std::string& file : result.output_files)
      if (std::filesystem::path(file).extension() == ".vtu")
        pieces.push_back((std::filesystem::path(settings.output_directory) / file).string());
    if (!pieces.empty())
      context.plot("plot_deformed.py", pieces, label + "_deformed.png",
                   label + ": deformed shape (von Mises) and contact pressure at the position");
  }
  remove_scratch();
  return result;
}

// The sweep on the scene's own layers.
stiffness::StiffnessSweepResult solve_sweep(const StiffnessParameters& p, CommandContext& context,
                                            const std::string& label)
{
  stiffness::GearMeshStiffnessSettings settings = p.settings;
  std::vector<std::string> bases;
  for (unsigned int i = 0; i < p.sweep.positions; ++i)
    bases.push_back(label + "_" + dealii::Utilities::int_to_string(i, 3));
  settings.output_directory = vtu_directory(p, context, bases);
  settings.output_base = label;
  const std::string stem = scratch_stem(context.mpi_communicator, label, false);
  const unsigned int ranks = dealii::Utilities::MPI::n_mpi_processes(context.mpi_communicator);
  context.pcout << label << ": " << p.sweep.positions << " positions over " << p.sweep.base_pitches
                << " base pitch(es) on " << ranks << " rank(s), estimated at least "
                << format_number(p.estimated_seconds, 2) << " s in all" << std::endl;
  // From the rank that solved the position (each takes its own, fem::distribute_items). The
  // influence-coefficient model reports its once-per-sweep steps instead (rank 0 alone): a
  // position count and a time left would be wrong for them.
  const auto counter = context.progress_counter(label, double(p.sweep.positions) / ranks);
  const std::function<void(const std::string&)> steps = [&context, &label](const std::string& text)
  { context.progress(label, text); };
  const auto& progress =
      settings.contact_model == stiffness::ContactModel::influence_coefficients ? steps : counter;
  return with_parameter_names(
      stiffness_parameter_names(),
      [&]
      {
        // The two contact models are separate sweeps (neither stiffness module includes the
        // other): the choice is the command's.
        if (settings.contact_model == stiffness::ContactModel::influence_coefficients)
          return settings.scene.mesh.dimension == 3
                     ? stiffness::influence_sweep<3>(context.mpi_communicator, settings, p.sweep,
                                                     stem, progress)
                     : stiffness::influence_sweep<2>(context.mpi_communicator, settings, p.sweep,
                                                     stem, progress);
        return settings.scene.mesh.dimension == 3
                   ? stiffness::stiffness_sweep<3>(context.mpi_communicator, settings, p.sweep,
                                                   stem, progress)
                   : stiffness::stiffness_sweep<2>(context.mpi_communicator, settings, p.sweep,
                                                   stem, progress);
      });
}

// Mesh/layer extrapolation around one solve (a position or a sweep): the solve on 2L layers
// first (its VTU is the one written; a level over the memory limit is refused before any work),
// then on L layers with the body size the 2L scene was meshed with — an automatic body size
// coarsens to fit the larger mesh, and the two levels must differ in their layers alone —,
// combined by stiffness::extrapolate_layers. Without the option the solve itself.
template <class Solve, class BodySize>
auto solve_layer_levels(const StiffnessParameters& p, CommandContext& context,
                        const std::string& label, Solve&& solve, BodySize&& body_size_of)
{
  if (!p.layer_extrapolation)
    return solve(p);
  const unsigned int layers = p.settings.scene.mesh.layers;
  context.pcout << label << ": Mesh/layer extrapolation = richardson: solving on " << 2 * layers
                << " layers, then on " << layers << std::endl;
  StiffnessParameters level = p;
  level.layer_extrapolation = false;
  level.settings.scene.mesh.layers = 2 * layers;
  // A refusal of the 2L solve says which solve it was; one of its layers is the extrapolation's
  // (the user set L, not 2L). The scene names its own field (mapped to the parameter path by
  // the command's tables).
  const auto fine = [&]
  {
    try
    {
      return solve(level);
    }
    catch (const InputError& e)
    {
      const std::string which =
          "the solve on 2 × Mesh/layers = " + std::to_string(2 * layers) + " layers";
      if (e.parameter() == geometry::field::mesh("layers") || e.parameter() == "Mesh/layers")
        throw InputError("Mesh/layer extrapolation", which + ": " + e.reason());
      throw InputError(e.parameter(), e.reason() + " (Mesh/layer extrapolation: " + which + ")");
    }
  }();
  level.settings.scene.mesh.layers = layers;
  level.write_vtu = false;
  level.settings.scene.mesh.body_size = body_size_of(fine);
  level.settings.scene.mesh.body_size_fits_cell_limit = false;
  return stiffness::extrapolate_layers(solve(level), fine, layers);
}
} // namespace

stiffness::GearMeshStiffnessResult solve_stiffness_position(const StiffnessParameters& p,
                                                            CommandContext& context,
                                                            const std::string& label)
{
  return solve_layer_levels(
      p, context, label,
      [&](const StiffnessParameters& level) { return solve_position(level, context, label); },
      [](const stiffness::GearMeshStiffnessResult& fine) { return fine.body_size; });
}

stiffness::StiffnessSweepResult solve_stiffness_sweep(const StiffnessParameters& p,
                                                      CommandContext& context,
                                                      const std::string& label)
{
  // One body size for the L sweep: per position, each 2L scene may have coarsened its own.
  const auto body_size_of = [](const stiffness::StiffnessSweepResult& fine)
  {
    const double body_size = fine.positions.front().body_size;
    for (const stiffness::GearMeshStiffnessResult& r : fine.positions)
      if (r.body_size != body_size)
        throw InputError("Mesh/body size",
                         "Mesh/layer extrapolation: the automatic body size of the 2L-layer "
                         "solves coarsened to " +
                             format_number(body_size * 1e3, 4) + " mm at one position and " +
                             format_number(r.body_size * 1e3, 4) +
                             " mm at another (to fit the memory limit): set one");
    return body_size;
  };
  return solve_layer_levels(
      p, context, label,
      [&](const StiffnessParameters& level) { return solve_sweep(level, context, label); },
      body_size_of);
}
} // namespace gearstiff::app
