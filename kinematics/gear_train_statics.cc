// The statics of a gear train (kinematics/gear_train.h, solve_train_statics): torque balances of
// the rigid bodies with each mesh's efficiency in the direction of its relative power flow,
// reactions, tooth forces and planet axis loads. The kinematics and parsing are gear_train.cc.
#include "errors/errors.h"
#include "errors/format.h"
#include "errors/limits.h"
#include "kinematics/fields.h"
#include "kinematics/gear_pair.h"
#include "kinematics/gear_train.h"
#include "kinematics/gear_train_internal.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace gearstiff::kinematics
{
using namespace train_internal;

namespace
{
// The rigid bodies of the statics: which are held (the housing's and every fixed member's), and
// the row of its torque balance for each free one.
struct StaticsBodies
{
  StaticsBodies(const GearTrainSpec& spec, const TrainSolution& solution)
      : bodies(spec, solution), grounded(solution.names.size(), false)
  {
  }
  bool held(std::size_t member) { return grounded[bodies.find(member)]; }

  RigidBodies bodies;
  std::vector<bool> grounded;                     // per body root
  std::map<std::size_t, std::size_t> equation_of; // free body root → row
};

StaticsBodies statics_bodies(const GearTrainSpec& spec, const TrainSolution& solution,
                             std::size_t input, std::size_t output)
{
  const std::size_t n = solution.names.size();
  StaticsBodies b(spec, solution);
  b.grounded[b.bodies.find(n - 1)] = true;
  for (const std::string& name : spec.fixed)
    b.grounded[b.bodies.find(solution.index(name))] = true;
  if (b.bodies.find(input) == b.bodies.find(output))
    throw InputError(field::train("output"), "input and output are the same rigid body");
  if (b.held(output) || b.held(input))
    throw InputError(field::train("output"), "input or output is held fixed");

  for (std::size_t i = 0; i < n; ++i)
    if (!b.held(i) && !b.equation_of.count(b.bodies.find(i)))
      b.equation_of.emplace(b.bodies.find(i), b.equation_of.size());
  const std::size_t meshes = spec.meshes.size();
  if (b.equation_of.size() != meshes + 1)
    throw InputError(field::train("output"),
                     "statics undetermined: " + std::to_string(b.equation_of.size()) +
                         " free bodies for " + std::to_string(meshes) +
                         " mesh torques and one output torque (one degree of freedom needed)");
  return b;
}

// One pass of the torque balances: unknowns the torque on gear a of each mesh and the output
// torque; `ratio` receives each mesh's torque ratio on b / on a with the pass's efficiencies.
Eigen::VectorXd solve_torque_balances(const GearTrainSpec& spec, const TrainSolution& solution,
                                      StaticsBodies& b, std::size_t input, std::size_t output,
                                      double input_torque, const std::vector<double>& eta,
                                      const std::vector<int>& a_drives, std::vector<double>& ratio)
{
  const std::size_t meshes = spec.meshes.size();
  Eigen::MatrixXd matrix = Eigen::MatrixXd::Zero(meshes + 1, meshes + 1);
  Eigen::VectorXd right_hand_side = Eigen::VectorXd::Zero(meshes + 1);
  auto add = [&](std::size_t member, std::size_t column, double value)
  {
    const std::size_t root = b.bodies.find(member);
    if (!b.grounded[root])
      matrix(b.equation_of.at(root), column) += value;
  };
  for (std::size_t m = 0; m < meshes; ++m)
  {
    const TrainMesh& mesh = spec.meshes[m];
    const double z_a = spec.members[solution.index(mesh.gear_a)].teeth;
    const double z_b = spec.members[solution.index(mesh.gear_b)].teeth;
    ratio[m] = z_b / z_a * (a_drives[m] ? eta[m] : 1. / eta[m]);
    add(solution.index(mesh.gear_a), m, 1.);
    add(solution.index(mesh.gear_b), m, ratio[m]);
    add(solution.index(mesh.frame), m, -(1. + ratio[m]));
  }
  add(output, meshes, 1.);
  right_hand_side[b.equation_of.at(b.bodies.find(input))] = -input_torque;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(matrix);
  lu.setThreshold(1e-10);
  if (lu.rank() < static_cast<Eigen::Index>(meshes + 1))
    throw InputError(field::train("output"), "statics undetermined: the torque equations are "
                                             "singular for this input/output choice");
  return lu.solve(right_hand_side);
}

// The mesh torques, passes repeated until the directions of relative power flow settle (pass 0
// is loss-free and only sets them). Returns the output torque.
double solve_mesh_torques(const GearTrainSpec& spec, const TrainSolution& solution,
                          StaticsBodies& b, std::size_t input, std::size_t output,
                          double input_torque, double tooth_friction, TrainStatics& statics)
{
  const std::size_t meshes = spec.meshes.size();
  statics.meshes.resize(meshes);
  std::vector<int> a_drives(meshes, 1);
  std::vector<double> efficiency(meshes);
  for (std::size_t m = 0; m < meshes; ++m)
    efficiency[m] =
        pair_efficiency(spec.members[solution.index(spec.meshes[m].gear_a)].teeth,
                        spec.members[solution.index(spec.meshes[m].gear_b)].teeth, tooth_friction);
  const std::vector<double> loss_free(meshes, 1.);
  Eigen::VectorXd unknowns;
  for (unsigned int pass = 0;; ++pass)
  {
    if (pass > 20)
      throw SolverFailure("train statics", "directions of power flow did not settle after 20 "
                                           "passes (self-locking train?)");
    std::vector<double> ratio(meshes);
    unknowns = solve_torque_balances(spec, solution, b, input, output, input_torque,
                                     pass == 0 ? loss_free : efficiency, a_drives, ratio);
    bool changed = false;
    for (std::size_t m = 0; m < meshes; ++m)
    {
      const TrainMesh& mesh = spec.meshes[m];
      const double relative_speed = solution.speed(mesh.gear_a) - solution.speed(mesh.frame);
      // Gear a drives when the mesh draws power from it in the frame's reference.
      const int drives = unknowns[m] * relative_speed <= 0. ? 1 : 0;
      if (drives != a_drives[m] && std::abs(relative_speed) > 0.)
      {
        a_drives[m] = drives;
        changed = true;
      }
      MeshTorques& out = statics.meshes[m];
      out.on_a = unknowns[m];
      out.on_b = ratio[m] * unknowns[m];
      out.on_frame = -(1. + ratio[m]) * unknowns[m];
      out.efficiency = pass == 0 ? 1. : efficiency[m];
      out.a_drives = a_drives[m];
    }
    statics.power_flow_iterations = pass;
    if (pass > 0 && !changed)
      break;
    if (tooth_friction == 0. && !changed)
      break;
  }
  return unknowns[meshes];
}

// Reactions: each grounded body takes what its meshes put on it, assigned to its fixed member
// (or the housing); the mesh torques reaching the output body are its paths.
void add_reactions(const GearTrainSpec& spec, const TrainSolution& solution, StaticsBodies& b,
                   std::size_t output, TrainStatics& statics)
{
  std::map<std::size_t, double> ground_load;
  for (std::size_t m = 0; m < spec.meshes.size(); ++m)
  {
    const TrainMesh& mesh = spec.meshes[m];
    const MeshTorques& t = statics.meshes[m];
    for (const auto& [name, torque] :
         {std::pair{mesh.gear_a, t.on_a}, std::pair{mesh.gear_b, t.on_b},
          std::pair{mesh.frame, t.on_frame}})
    {
      const std::size_t root = b.bodies.find(solution.index(name));
      if (b.grounded[root])
        ground_load[root] += torque;
      if (root == b.bodies.find(output))
        statics.output_paths.emplace_back(m, torque);
    }
  }
  for (const auto& [root, load] : ground_load)
  {
    std::size_t holder = solution.names.size() - 1;
    for (const std::string& name : spec.fixed)
      if (b.bodies.find(solution.index(name)) == root)
      {
        holder = solution.index(name);
        break;
      }
    statics.applied_torque[holder] -= load;
  }
}

// Tooth forces per copy at the pitch circle; planet axis loads as the vector sum over the
// planet's meshes (mate external: contact towards the carrier axis, internal: away).
void add_tooth_forces(const GearTrainSpec& spec, const TrainSolution& solution, StaticsBodies& b,
                      TrainStatics& statics)
{
  std::map<std::size_t, std::pair<double, std::string>> planet_force; // body → (F_y, name)
  for (std::size_t m = 0; m < spec.meshes.size(); ++m)
  {
    const TrainMesh& mesh = spec.meshes[m];
    const TrainMember& a = member_of(spec, solution, mesh.gear_a);
    const TrainMember& gear_b = member_of(spec, solution, mesh.gear_b);
    MeshTorques& t = statics.meshes[m];
    const double copies = solution.mesh_copies[m];
    if (a.module > 0.)
      t.tangential_force = std::abs(t.on_a) / (copies * std::abs(pitch_radius(a)));
    if (mesh.frame == housing_name || a.module == 0. || gear_b.module == 0.)
      continue;
    for (const bool planet_is_a : {true, false})
    {
      const TrainMember& planet = planet_is_a ? a : gear_b;
      const TrainMember& mate = planet_is_a ? gear_b : a;
      if (planet.carrier != mesh.frame || mate.carrier == mesh.frame)
        continue;
      const double torque = planet_is_a ? t.on_a : t.on_b;
      // t(θ) = (−sin θ, cos θ): θ = π towards the axis gives −y, θ = 0 gives +y.
      const double direction = mate.teeth > 0 ? -1. : 1.;
      auto& entry = planet_force[b.bodies.find(solution.index(planet.name))];
      entry.first += direction * torque / (copies * pitch_radius(planet));
      if (entry.second.empty())
        entry.second = planet.name;
    }
  }
  for (const auto& [root, force] : planet_force)
    statics.planet_axis_forces.emplace_back(force.second, std::abs(force.first));
}
} // namespace

TrainStatics solve_train_statics(const GearTrainSpec& spec, const TrainSolution& solution,
                                 double input_torque, double tooth_friction)
{
  if (spec.inputs.size() != 1 || spec.output.empty())
    throw InputError(field::train("inputs"), "statics need exactly one input and an output");
  const std::size_t n = solution.names.size();
  const std::size_t input = solution.index(spec.inputs.front().first);
  const std::size_t output = solution.index(spec.output);
  StaticsBodies bodies = statics_bodies(spec, solution, input, output);

  TrainStatics statics;
  statics.input_torque = input_torque;
  statics.output_torque = solve_mesh_torques(spec, solution, bodies, input, output, input_torque,
                                             tooth_friction, statics);
  statics.efficiency =
      -statics.output_torque * solution.speeds[output] / (input_torque * solution.speeds[input]);
  statics.applied_torque.assign(n, 0.);
  statics.applied_torque[input] = input_torque;
  statics.applied_torque[output] = statics.output_torque;
  add_reactions(spec, solution, bodies, output, statics);
  add_tooth_forces(spec, solution, bodies, statics);
  return statics;
}

} // namespace gearstiff::kinematics
