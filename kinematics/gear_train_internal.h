// What kinematics/gear_train.cc and kinematics/gear_train_statics.cc share privately: the rigid
// bodies of a train and member lookups. Included by those two files only.
#pragma once

#include "kinematics/gear_train.h"

#include <numeric>
#include <string>
#include <vector>

namespace gearstiff::kinematics::train_internal
{
// Rigid bodies: union-find over the connections.
class RigidBodies
{
public:
  RigidBodies(const GearTrainSpec& spec, const TrainSolution& solution)
      : parent(solution.names.size())
  {
    std::iota(parent.begin(), parent.end(), 0);
    for (const auto& [a, b] : spec.connections)
      parent[find(solution.index(a))] = find(solution.index(b));
  }
  std::size_t find(std::size_t member)
  {
    while (parent[member] != member)
      member = parent[member] = parent[parent[member]];
    return member;
  }

private:
  std::vector<std::size_t> parent;
};

inline const TrainMember& member_of(const GearTrainSpec& spec, const TrainSolution& solution,
                                    const std::string& name)
{
  return spec.members[solution.index(name)];
}

inline double pitch_radius(const TrainMember& gear)
{
  return 0.5 * gear.module * gear.teeth;
}
} // namespace gearstiff::kinematics::train_internal
