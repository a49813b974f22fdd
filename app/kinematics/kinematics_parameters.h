// Parameter-file form of the kinematics module's inputs: the gear pair (subsection "Gear pair"
// with "Pinion" and "Wheel", mm and degrees) and a gear train (subsection "Train", lists in
// text). Shared by the gear-pair and kinematics commands and by any command that needs a gear
// pair (the stiffness command compares its FE value with ISO c'·b).
#pragma once

#include "kinematics/automatic_sizes.h"
#include "kinematics/gear_pair.h"
#include "kinematics/gear_train.h"
#include "kinematics/iso_stiffness.h"

#include <deal.II/base/parameter_handler.h>

namespace gearstiff::app
{
// Defaults: the split-path pair of docs/references.md §1 (kinematics::split_path_pair()).
void declare_gear_pair_parameters(dealii::ParameterHandler& prm);
// Converts to SI and resolves the sizes that read `auto` (kinematics/automatic_sizes.h); the
// checks that need the whole pair are in kinematics::compute_gear_pair. `derived` receives one
// entry per size the rules derived (for the report).
kinematics::GearPairSpec parse_gear_pair_parameters(dealii::ParameterHandler& prm);
kinematics::GearPairSpec parse_gear_pair_parameters(dealii::ParameterHandler& prm,
                                                    std::vector<kinematics::DerivedSize>& derived);
// The parameter path of a per-gear key: "Gear pair/Pinion/<key>" (wheel: "Gear pair/Wheel/").
std::string gear_pair_parameter(bool wheel, const std::string& key);
// Subsection "ISO 6336": C_M and the specific load.
kinematics::IsoStiffnessOptions parse_iso_parameters(dealii::ParameterHandler& prm);

struct TrainParameters
{
  kinematics::GearTrainText text;
  double input_torque = 0.;   // N·m, on the first input (0: no statics)
  double tooth_friction = 0.; // -, μ_z for the pair efficiencies
  std::string reduce_to;      // member the inertia is reduced to ("": the first input)
};
// Defaults: the bi-planetary train of docs/references.md §2.
void declare_train_parameters(dealii::ParameterHandler& prm);
TrainParameters parse_train_parameters(dealii::ParameterHandler& prm);
} // namespace gearstiff::app
