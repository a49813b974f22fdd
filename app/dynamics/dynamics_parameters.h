// Parameters of `gearstiff dynamics`: the gear train (gears, meshes, stiffness sources), the
// simulation, the speed sweep and the ISO 6336-1 method B comparison. Parameter files use
// engineering units (rpm, mm, N/mm, µs, degrees); parse_dynamics_parameters converts to SI.
#pragma once
#include "dynamics/cai_stiffness.h"
#include "dynamics/simulation.h"
#include "dynamics/train_model.h"

#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <optional>
#include <string>
#include <vector>

namespace gearstiff::app
{
constexpr unsigned int max_dynamics_gears = 6;
constexpr unsigned int max_train_meshes = 8; // sections "Train mesh 1" ... of the train model

struct SweepParameters
{
  unsigned int points = 0;                 // [-] 0: no sweep
  double minimum_speed = 0.;               // [rad/s]
  double maximum_speed = 0.;               // [rad/s]
  unsigned int steps_per_mesh_period = 40; // [-]
};

struct IsoParameters
{
  double face_width = 0.;         // [m] b
  double pressure_angle = 0.;     // [rad] transverse α_t: F_t = F_bt·cos α_t
  double single_stiffness = 0.;   // [N/m²] c'; 0: from the model (c_γα/(0.75 ε_α + 0.25))
  double mesh_stiffness = 0.;     // [N/m²] c_γα; 0: mean model stiffness / b
  double pitch_deviation = 0.;    // [m] f_pb,eff
  double profile_deviation = 0.;  // [m] f_f,eff
  double tip_relief = 0.;         // [m] C_a
  double application_factor = 1.; // [-] K_A
};

struct DynamicsParameters
{
  // Train/model = train: the kinematics description, built into train_model (its general-form
  // GearTrain is copied to `train`); otherwise Gear n / Mesh n.
  bool train_description = false;
  dynamics::TrainModel train_model;
  dynamics::GearTrain train;
  std::vector<double> placement_angle;            // [rad] per mesh
  std::vector<std::string> stiffness_description; // per mesh, for the report
  std::vector<std::string> derived_sizes; // values derived from `auto` (Train mesh stiffness)
  std::vector<std::optional<dynamics::CaiFit>> cai_fit; // per mesh when "cai fit" was used
  dynamics::SimulationSettings simulation;
  double output_interval = 0.;     // [s] spacing of the time-series CSV rows
  double initial_position = 0.;    // [base pitches] mesh 1 at t = 0
  bool published_reference = true; // compare with docs/references.md §1
  SweepParameters sweep;
  IsoParameters iso;
  // issue 29: the mesh law (Simulation/mesh model) and the sweep order (Speed sweep/direction;
  // nonlinear sweeps continue from the previous speed's state). The per-mesh law is in
  // train.meshes[m].nonlinear.
  dynamics::MeshModel mesh_model = dynamics::MeshModel::linear;
  dynamics::SweepDirection sweep_direction = dynamics::SweepDirection::up;
};

void declare_dynamics_parameters(dealii::ParameterHandler& prm);
// Throws InputError naming "Section/parameter" for values the patterns cannot catch.
DynamicsParameters parse_dynamics_parameters(dealii::ParameterHandler& prm);
} // namespace gearstiff::app

namespace gearstiff::app
{
// issue 30 (Train/model = lateral): Train mesh m + 1 reduced to what the lateral model uses,
// its mean stiffness over a mesh cycle (ε_α `contact_ratio`, or the FE file's own) and damping.
struct TrainMeshMean
{
  double stiffness = 0.;         // [N/m]
  double damping = 0.;           // [N·s/m]
  std::string description;       // the stiffness source, for the report
  dynamics::MeshStiffness curve; // k(x) for the time response
  double contact_ratio = 0.;     // [-] ε_α of k(x)
  // Simulation/mesh model = nonlinear: the mesh law of the section (teeth: the mesh's gears,
  // signed, for the pitch deviation's order and the TE file's check when `module` > 0 [m]).
  std::optional<dynamics::NonlinearMesh> nonlinear;
  // An FE file's pair checked against the mesh's gears (`module` > 0): 0 when gear a was the FE
  // pinion (drove), 1 when gear b was; empty otherwise.
  std::optional<unsigned int> stiffness_driver;
};
// `automatic_stiffness` [N/m]: what 'stiffness = auto' stands for (NaN: auto not offered).
TrainMeshMean parse_train_mesh_mean(dealii::ParameterHandler& prm, unsigned int m,
                                    double contact_ratio, int teeth_a = 0, int teeth_b = 0,
                                    double module = 0., double centre_distance = 0.,
                                    double automatic_stiffness = std::nan(""));
} // namespace gearstiff::app
