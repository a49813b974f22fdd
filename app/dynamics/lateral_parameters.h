// Parameters of `gearstiff dynamics` with `Train/model = lateral` (issue 30): the kinematics
// command's Train description of one planetary stage (sun, planets on a carrier, ring) read into
// the planar lateral–torsional model of dynamics/lateral_model.h (Lin & Parker 1999), plus its
// own entries in the Train subsection: bearing stiffness and damping, planet pin stiffness,
// base diameters and carrier radii, planet angles, pin errors, gyroscopic terms.
#pragma once

#include "dynamics/lateral_model.h"
#include "dynamics/lateral_response.h"
#include "dynamics/lateral_sweep.h"
#include "dynamics/lateral_train_build.h"

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <vector>

namespace gearstiff::app
{
struct LateralParameters
{
  dynamics::LateralStage stage;
  dynamics::LateralStaticLoad load;
  std::string sun, ring, carrier, planet; // member names of the Train description
  double carrier_speed = 0.;              // [rad/s] nominal, from the kinematics
  double input_speed = 0.;                // [rad/s]
  bool gyroscopic = false;                // Campbell chart with Cooley & Parker's terms
  double backlash = 0.;                   // [m] along the line of action (0: not given)
  std::vector<std::string> notes;         // where each value came from
  // Time response (Simulation/time step, simulated time, start; RK4): mesh k(x) per planet.
  dynamics::LateralMeshExcitation excitation;
  dynamics::LateralRunSettings run;
  // [base pitches] each planet's ring mesh after its sun mesh (Parker & Lin 2004)
  double ring_mesh_offset = 0.;
  // Speed sweep (section Speed sweep, Simulation/mesh model; 0 points: none).
  unsigned int sweep_points = 0;
  double sweep_minimum_speed = 0., sweep_maximum_speed = 0.; // [rad/s] input
  dynamics::LateralSweepSettings sweep;
};

// Train/model = lateral with several planet members (stages, nested carriers): the general form
// of dynamics/lateral_train.h. The rotational model of the same train (its Train mesh k(x),
// damping and phases) comes from the train model's parameters.
struct LateralTrainParameters
{
  dynamics::LateralTrainSetup setup;
  double input_speed = 0.;                 // [rad/s] nominal, |ω_input|
  double settle_time = 0.;                 // [s] Simulation/steady state start (0: decay time)
  unsigned int window_periods = 20;        // [-] of the slowest mesh
  unsigned int steps_per_mesh_period = 40; // [-] of the fastest mesh
  std::vector<double> sweep_speeds;        // [rad/s] (empty: no sweep)
};
bool lateral_train_selected(dealii::ParameterHandler& prm);
// `rotational`: the train model of the same description (Train/model = train's parameters).
LateralTrainParameters parse_lateral_train_parameters(dealii::ParameterHandler& prm,
                                                      const dynamics::TrainModel& rotational);

// The lateral entries of the Train subsection (the rest of Train is the kinematics command's).
void declare_lateral_parameters(dealii::ParameterHandler& prm);
bool lateral_model_selected(dealii::ParameterHandler& prm);
// InputError naming the Train parameter for anything that is not one planetary stage or whose
// values are out of range.
LateralParameters parse_lateral_parameters(dealii::ParameterHandler& prm);
} // namespace gearstiff::app
