#include "stiffness/layer_extrapolation.h"

#include "errors/errors.h"
#include "errors/format.h"

#include <cmath>
#include <string>

namespace gearstiff::stiffness
{
namespace
{
// Richardson's extrapolation of a value with an error ∝ Δz², from L and 2L layers.
double limit(double coarse, double fine)
{
  return fine + (fine - coarse) / 3.;
}

std::string where(const GearMeshStiffnessResult& r)
{
  return "at the pinion roll angle " + format_number(r.pinion_roll_angle * 180. / M_PI, 6) + "°";
}
} // namespace

GearMeshStiffnessResult extrapolate_layers(const GearMeshStiffnessResult& coarse,
                                           const GearMeshStiffnessResult& fine,
                                           unsigned int coarse_layers)
{
  const std::string levels =
      std::to_string(coarse_layers) + " and " + std::to_string(2 * coarse_layers) + " layers";
  // The same analysis on two meshes: the same position, load and tooth pairs.
  bool same = coarse.pairs.size() == fine.pairs.size() &&
              std::abs(coarse.reference_position - fine.reference_position) <=
                  1e-12 * (1. + std::abs(fine.reference_position)) &&
              coarse.pinion_torque == fine.pinion_torque;
  for (std::size_t i = 0; same && i < fine.pairs.size(); ++i)
    same = coarse.pairs[i].pair == fine.pairs[i].pair;
  if (!same)
    throw SolverFailure("layer extrapolation",
                        where(fine) + ": the solves on " + levels +
                            " model different positions, loads or tooth pairs");

  GearMeshStiffnessResult r = fine;
  r.pinion_rotation = limit(coarse.pinion_rotation, fine.pinion_rotation);
  const double correction = std::abs(r.pinion_rotation - fine.pinion_rotation) / r.pinion_rotation;
  if (!(r.pinion_rotation > 0.) || !(correction <= max_layer_correction))
    throw SolverFailure(
        "layer extrapolation",
        where(fine) + ": k moved from " + format_number(coarse.mesh_stiffness / 1e6, 6) + " to " +
            format_number(fine.mesh_stiffness / 1e6, 6) + " N/µm between " + levels +
            ", a correction of " + format_number(correction * 100., 3) + " % (at most " +
            format_number(max_layer_correction * 100., 3) +
            " % is trusted): not yet in the range where the layers' error falls as their height "
            "squared; more Mesh/layers");
  const double r_b1 = fine.pinion_base_radius;
  r.mesh_stiffness = fine.pinion_torque / (r_b1 * r_b1 * r.pinion_rotation);
  r.transmission_error =
      fine.transmission_error + r_b1 * (r.pinion_rotation - fine.pinion_rotation);
  for (std::size_t i = 0; i < r.pairs.size(); ++i)
  {
    ToothPairLoad& load = r.pairs[i];
    load.normal_force = limit(coarse.pairs[i].normal_force, load.normal_force);
    load.load_share = limit(coarse.pairs[i].load_share, load.load_share);
    load.resultant = limit(coarse.pairs[i].resultant, load.resultant);
  }
  r.wheel_torque = limit(coarse.wheel_torque, fine.wheel_torque);
  r.torque_ratio = std::abs(r.wheel_torque / r.pinion_torque);
  r.tangential_force = limit(coarse.tangential_force, fine.tangential_force);
  r.axial_force = limit(coarse.axial_force, fine.axial_force);
  r.tilting_moment = limit(coarse.tilting_moment, fine.tilting_moment);

  r.extrapolated_layers = coarse_layers;
  r.stiffness_coarse_layers = coarse.mesh_stiffness;
  r.stiffness_fine_layers = fine.mesh_stiffness;
  // The cost is both solves'.
  r.active_set_iterations += coarse.active_set_iterations;
  r.scene_time += coarse.scene_time;
  r.setup_time += coarse.setup_time;
  r.solve_time += coarse.solve_time;
  r.factorization_time += coarse.factorization_time;
  r.total_time += coarse.total_time;
  return r;
}

StiffnessSweepResult extrapolate_layers(const StiffnessSweepResult& coarse,
                                        const StiffnessSweepResult& fine,
                                        unsigned int coarse_layers)
{
  if (coarse.positions.size() != fine.positions.size() ||
      coarse.by_torque.size() != fine.by_torque.size())
    throw SolverFailure("layer extrapolation", "the sweeps on " + std::to_string(coarse_layers) +
                                                   " and " + std::to_string(2 * coarse_layers) +
                                                   " layers solved different positions or torques");
  StiffnessSweepResult r = fine;
  for (std::size_t i = 0; i < r.positions.size(); ++i)
    r.positions[i] = extrapolate_layers(coarse.positions[i], fine.positions[i], coarse_layers);
  for (std::size_t t = 0; t < r.by_torque.size(); ++t)
  {
    if (coarse.by_torque[t].size() != fine.by_torque[t].size())
      throw SolverFailure("layer extrapolation", "the sweeps solved different positions");
    for (std::size_t i = 0; i < r.by_torque[t].size(); ++i)
      r.by_torque[t][i] =
          extrapolate_layers(coarse.by_torque[t][i], fine.by_torque[t][i], coarse_layers);
  }
  r.wall_time += coarse.wall_time;
  r.once_time += coarse.once_time;
  r.per_position_time += coarse.per_position_time;
  return r;
}
} // namespace gearstiff::stiffness
