// The planar lateral–torsional model (lateral_train.h) of a train described for the kinematics
// module (kinematics::GearTrainSpec, the input of train_model.h): one body per rigid body
// (members joined by connections) and copy, placed at one instant — planets equally spaced on
// their carriers, a nested carrier's planets at the same angles in its own frame turned to its
// radial line (so the train keeps the cyclic symmetry of its outer planets). A gear that a mesh
// a-b/c holds on frame c's axis (not a planet of c: the sun or ring of a nested set) sits on
// that axis, even when its body turns about another (a ring rigid with the outer carrier). Each
// mesh's flank follows the static load of the rotational model of the same train (its mesh
// orientation), so every static mesh force is compressive.
#pragma once

#include "dynamics/lateral_train.h"
#include "dynamics/train_model.h"

#include <map>
#include <string>
#include <vector>

namespace gearstiff::dynamics
{
struct LateralTrainInput
{
  TrainDynamicsInput train; // the rotational model's input (mesh k(x), loads)
  std::map<std::string, double> bearing_stiffness; // [N/m] per member on the main axis (0: floats)
  std::map<std::string, double> bearing_damping;   // [N·s/m]
  std::map<std::string, double> pin_stiffness;     // [N/m] per planet member, radial and tangential
  std::map<std::string, double> pin_damping;       // [N·s/m]
  std::map<std::string, double> base_radius;       // [m] in place of m·|z|·cos α/2
  std::map<std::string, double> carrier_radius;    // [m] a carrier's u radius (its pin circle)
};

struct LateralTrainSetup
{
  TrainModel rotational;     // the purely rotational model of the same train (k(x), phases)
  LateralTrain train;        // meshes in the order of rotational.train.meshes
  std::vector<int> body_dof; // per body: its rotational DOF (−1: held)
  unsigned int input_body = 0, output_body = 0;
  double input_torque = 0.; // [N·m] on the input body, in the rotational model's sense
};

// InputError naming the Train parameter: members unknown to the description, bearings on a body
// that rides on a carrier, planets without pin stiffness, missing masses or radii. `rotational`:
// the rotational model of input.train (build_train_model, with its meshes' damping as used).
LateralTrainSetup build_lateral_train(const LateralTrainInput& input, const TrainModel& rotational);
// The same with build_train_model(input.train).
LateralTrainSetup build_lateral_train(const LateralTrainInput& input);
} // namespace gearstiff::dynamics
