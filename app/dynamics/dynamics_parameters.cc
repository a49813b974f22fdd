#include "app/dynamics/dynamics_parameters.h"

#include "app/core/parameter_patterns.h"
#include "app/core/units.h"
#include "app/dynamics/dynamics_parameters_internal.h"
#include "app/kinematics/kinematics_parameters.h"
#include "dynamics/split_path_case.h"
#include "errors/errors.h"

#include <cmath>

namespace gearstiff::app
{
using namespace dynamics_input;
namespace
{
// The entries of "ISO 6336", one a member of IsoParameters, in the unit the file writes it in
// (`unit`: its SI value); declared with IsoParameters' default, read back into the member.
struct IsoEntry
{
  const char* name;
  double IsoParameters::*member;
  double unit;
  Double pattern;
  const char* documentation;
};

const IsoEntry iso_entries[] = {
    {"face width", &IsoParameters::face_width, mm, Double(0.), "b, common face width [mm]"},
    {"transverse pressure angle", &IsoParameters::pressure_angle, degree, Double(0., 45.),
     "alpha_t: F_t = F_bt·cos alpha_t [deg]"},
    {"single stiffness", &IsoParameters::single_stiffness, newton_per_mm_micrometre, Double(0.),
     "c' [N/(mm·µm)]; 0: c_gamma_alpha/(0.75·epsilon_alpha + 0.25)"},
    {"mesh stiffness", &IsoParameters::mesh_stiffness, newton_per_mm_micrometre, Double(0.),
     "c_gamma_alpha [N/(mm·µm)]; 0: the model's mean mesh stiffness / b"},
    {"pitch deviation", &IsoParameters::pitch_deviation, micrometre, Double(0.),
     "f_pb,eff = f_pb - y_p, effective base pitch deviation [µm]; the default is ISO 1328 grade "
     "6 for this size without running-in allowance"},
    {"profile deviation", &IsoParameters::profile_deviation, micrometre, Double(0.),
     "f_f,eff = f_f_alpha - y_f, effective profile form deviation [µm]"},
    {"tip relief", &IsoParameters::tip_relief, micrometre, Double(0.), "C_a [µm]; 0: none"},
    {"application factor", &IsoParameters::application_factor, 1., Double(0.), "K_A [-]"}};
} // namespace

void declare_dynamics_parameters(ParameterHandler& prm)
{
  const dynamics::SplitPathCase data = dynamics::split_path_case();

  prm.enter_subsection("Train");
  prm.declare_entry("number of gears", "3", Integer(2, max_dynamics_gears),
                    "gears (rotational degrees of freedom) of the train; a tree of n gears has "
                    "n - 1 meshes, read from 'Mesh 1' ... [-]");
  prm.declare_entry("input speed", format_number(data.input_speed_rpm, 10), Double(0.),
                    "n1, nominal speed of gear 1 [rpm]; the others follow from the base radii");
  prm.declare_entry("published reference", "true", Bool(),
                    "print the published split-path values (docs/references.md §1, Reszuta & "
                    "Drewniak 2015) beside ours when the train is that case (T1 and the base "
                    "radii of Mesh 1); false: never");
  prm.declare_entry("model", "gears and meshes", Selection("gears and meshes|train|lateral"),
                    "'gears and meshes': the sections Gear n / Mesh n (a tree, default: the "
                    "split path); 'train': the kinematics command's Train description (gears, "
                    "carriers, planets, meshes, ...) with the sections Train mesh n; 'lateral': "
                    "one planetary stage of that description as the planar lateral-torsional "
                    "model (Lin & Parker 1999: modes, classes, load sharing, bearing forces)");
  prm.declare_entry("pressure angle", "20", Double(0., 45.),
                    "train model: pressure angle of the standard teeth (x = 0, h_a* = 1) for "
                    "base radii, contact and approach ratios [deg]");
  prm.declare_entry("suspended members", "", Anything(),
                    "train model: fixed members hung on a torsional spring and damper to the "
                    "housing, 'name: stiffness damping, ...' (N·m/rad, N·m·s/rad)");
  prm.declare_entry("face widths", "", Anything(),
                    "train model: gears whose J and mass come from a steel blank where "
                    "Train/inertias and Train/masses give none, 'name: b, ...' [mm]");
  prm.declare_entry("bore diameters", "", Anything(),
                    "train model: bore of those blanks, 'name: d, ...' (mm; none: solid); for an "
                    "internal gear the rim's outside diameter (required)");
  prm.declare_entry("density", "7850", Double(0.), "train model: density of the blanks [kg/m³]");
  prm.leave_subsection();
  declare_train_parameters(prm); // gears, modules, ..., inertias, masses, input torque

  for (unsigned int m = 0; m < max_train_meshes; ++m)
  {
    prm.enter_subsection(train_mesh_section(m));
    declare_mesh_physics(prm, data.single_pair_stiffness, data.mesh_damping, 0., 0., 0., true);
    prm.leave_subsection();
  }

  for (unsigned int i = 0; i < max_dynamics_gears; ++i)
  {
    prm.enter_subsection(gear_section(i));
    const bool pinion = i == 0;
    prm.declare_entry("inertia",
                      format_number(pinion ? data.pinion_inertia : data.wheel_inertia, 10),
                      Double(0.), "J, mass moment of inertia about the gear axis [kg·m²]");
    prm.declare_entry("torque",
                      pinion ? format_number(data.input_torque, 10) : std::string("balance"),
                      Anything(),
                      "external torque [N·m], positive in the running direction (input), "
                      "negative for a load; 'balance': the load that takes an equal share of "
                      "its driver's torque, T = -T_driver/(meshes of the driver)·r_b/r_b,driver");
    prm.leave_subsection();
  }

  for (unsigned int m = 0; m + 1 < max_dynamics_gears; ++m)
  {
    prm.enter_subsection(mesh_section(m));
    prm.declare_entry("driver gear", "1", Integer(1, max_dynamics_gears),
                      "number of the driving gear [-]");
    prm.declare_entry("driven gear", std::to_string(m + 2), Integer(1, max_dynamics_gears),
                      "number of the driven gear [-]");
    prm.declare_entry("driver teeth", std::to_string(data.pinion_teeth), Integer(1, 10000),
                      "z of the driver: the mesh frequency is z·n_driver/60 [-]");
    prm.declare_entry("driver base radius", format_number(data.pinion_base_radius / mm, 10),
                      Double(0.), "r_b of the driver [mm]");
    prm.declare_entry("driven base radius", format_number(data.wheel_base_radius / mm, 10),
                      Double(0.), "r_b of the driven gear [mm]");
    prm.declare_entry("contact ratio", format_number(data.contact_ratio, 10), Double(1., 4.),
                      "epsilon_alpha, transverse contact ratio [-]; default from the "
                      "kinematics module's split-path pair");
    prm.declare_entry("approach ratio", format_number(data.approach_ratio, 10), Double(0., 4.),
                      "epsilon_f, start of active contact to the pitch point in base pitches "
                      "[-]: where the friction force reverses; default from kinematics");
    prm.declare_entry("placement angle", m == 1 ? "180" : "0", Double(-360., 360.),
                      "theta, angle of the driven gear's centre around the driver axis, "
                      "against the driver's rotation, from the driven gear of the first mesh "
                      "of the same driver [deg]; sets the phase frac(z·theta/360°)");
    declare_mesh_physics(prm, data.single_pair_stiffness, data.mesh_damping,
                         data.friction_coefficient, data.pinion_friction_arm,
                         data.wheel_friction_arm, false);
    prm.leave_subsection();
  }

  prm.enter_subsection("Simulation");
  prm.declare_entry("integrator", "RK4", Selection("RK4|adaptive RK|HHT-alpha"),
                    "RK4: classical Runge-Kutta, fixed step (the published method); adaptive "
                    "RK: Dormand-Prince 5(4) with error control; HHT-alpha: implicit, for "
                    "stiff meshes");
  prm.declare_entry("time step", "5", Double(0.),
                    "step of RK4 and HHT-alpha, output interval of the adaptive method [µs]");
  prm.declare_entry("allow unstable step", "false", Bool(),
                    "run RK4 with a step above the estimated stability limit");
  prm.declare_entry("relative tolerance", "1e-7", Double(0., 0.1),
                    "adaptive RK: local error tolerance relative to the state [-]");
  prm.declare_entry("HHT alpha", "-0.05", Double(-1. / 3., 0.),
                    "HHT-alpha parameter in [-1/3, 0]; 0 is the trapezoidal rule [-]");
  prm.declare_entry("start", "static deflection", Selection("static deflection|rest"),
                    "initial state: static deflection under mean stiffness, or rest (the "
                    "torques applied suddenly)");
  prm.declare_entry("initial mesh position", "0", Double(0., 1.),
                    "position of mesh 1 at t = 0 in base pitches [-]; 0: a pair enters contact");
  prm.declare_entry("steady state start", "-1", Double(),
                    "start of the K_v window [s]; negative: automatic, when the slowest mode "
                    "has decayed to 1/1000");
  prm.declare_entry("simulated time", "0", Double(0.),
                    "end time [s]; 0: the window start plus 'window periods' mesh periods");
  prm.declare_entry("window periods", "40", Integer(1, 100000),
                    "length of the automatic K_v window in periods of mesh 1 [-]");
  prm.declare_entry("output interval", "20", Double(0.),
                    "spacing of the rows of the time-series CSV [µs]; K_v uses every step");
  prm.declare_entry("mesh model", "linear", Selection("linear|nonlinear"),
                    "linear: F = k·delta + c·delta'; nonlinear: F = k·h(delta - e) + c·(delta' - "
                    "e')·[in contact] with the unloaded TE e, free play (backlash), tooth "
                    "separation and back-flank contact, switches located by RK4 (issue 29, "
                    "dynamics/README.md)");
  prm.leave_subsection();

  prm.enter_subsection("Speed sweep");
  prm.declare_entry("points", "60", Integer(0, 100000),
                    "speeds in the K_v resonance chart [-]; 0: no sweep");
  prm.declare_entry("minimum speed", "500", Double(0.), "first input speed [rpm]");
  prm.declare_entry("maximum speed", "45000", Double(0.), "last input speed [rpm]");
  prm.declare_entry("steps per mesh period", "40", Integer(8, 10000),
                    "the step is reduced so each mesh period holds at least this many [-]");
  prm.declare_entry("direction", "up", Selection("up|down|both"),
                    "order of the speeds: up, down, or both (up, then down from the top); with "
                    "the nonlinear mesh model each speed starts from the previous speed's final "
                    "state, so multi-valued responses show both branches");
  prm.leave_subsection();

  // The split-path pair's b, α_t = 20°, ISO 1328 grade 6 deviations (iso_entries).
  IsoParameters iso;
  iso.face_width = data.face_width;
  iso.pressure_angle = 20. * degree;
  iso.pitch_deviation = 8. * micrometre;
  iso.profile_deviation = 8. * micrometre;
  prm.enter_subsection("ISO 6336");
  for (const IsoEntry& entry : iso_entries)
    prm.declare_entry(entry.name, format_number(iso.*entry.member / entry.unit, 10), entry.pattern,
                      entry.documentation);
  prm.leave_subsection();
}

namespace
{
// issue 29: Simulation/mesh model and Speed sweep/direction (read before the meshes).
void parse_nonlinear_settings(ParameterHandler& prm, DynamicsParameters& p)
{
  prm.enter_subsection("Simulation");
  p.mesh_model = prm.get("mesh model") == "nonlinear" ? dynamics::MeshModel::nonlinear
                                                      : dynamics::MeshModel::linear;
  prm.leave_subsection();
  prm.enter_subsection("Speed sweep");
  const std::string direction = prm.get("direction");
  p.sweep_direction = direction == "down"   ? dynamics::SweepDirection::down
                      : direction == "both" ? dynamics::SweepDirection::both
                                            : dynamics::SweepDirection::up;
  prm.leave_subsection();
}
} // namespace

DynamicsParameters parse_dynamics_parameters(ParameterHandler& prm)
{
  DynamicsParameters p;
  prm.enter_subsection("Train");
  p.train_description = prm.get("model") == "train";
  prm.leave_subsection();
  parse_nonlinear_settings(prm, p);
  if (!p.train_description)
    parse_numbered_train(prm, p);

  prm.enter_subsection("Simulation");
  const std::string integrator = prm.get("integrator");
  p.simulation.integrator.type = integrator == "RK4" ? dynamics::IntegratorType::rk4
                                 : integrator == "adaptive RK"
                                     ? dynamics::IntegratorType::adaptive_rk
                                     : dynamics::IntegratorType::hht_alpha;
  p.simulation.integrator.time_step = prm.get_double("time step") * micrometre;
  p.simulation.integrator.allow_unstable_step = prm.get_bool("allow unstable step");
  p.simulation.integrator.relative_tolerance = prm.get_double("relative tolerance");
  p.simulation.integrator.hht_alpha = prm.get_double("HHT alpha");
  p.simulation.start = prm.get("start") == "rest" ? dynamics::StartState::rest
                                                  : dynamics::StartState::static_deflection;
  p.initial_position = prm.get_double("initial mesh position");
  p.simulation.steady_state_start = prm.get_double("steady state start");
  p.simulation.end_time = prm.get_double("simulated time");
  p.simulation.window_periods = prm.get_integer("window periods");
  p.output_interval = prm.get_double("output interval") * micrometre;
  p.simulation.record_interval = p.output_interval;
  prm.leave_subsection();
  if (!(p.simulation.integrator.time_step > 0.))
    throw InputError("Simulation/time step", "must be positive");

  prm.enter_subsection("Speed sweep");
  p.sweep.points = prm.get_integer("points");
  p.sweep.minimum_speed = prm.get_double("minimum speed") * rpm;
  p.sweep.maximum_speed = prm.get_double("maximum speed") * rpm;
  p.sweep.steps_per_mesh_period = prm.get_integer("steps per mesh period");
  prm.leave_subsection();
  if (p.sweep.points > 0 &&
      !(p.sweep.minimum_speed > 0. && p.sweep.maximum_speed >= p.sweep.minimum_speed))
    throw InputError("Speed sweep/maximum speed", "needs 0 < minimum speed <= maximum speed");

  prm.enter_subsection("ISO 6336");
  for (const IsoEntry& entry : iso_entries)
    p.iso.*entry.member = prm.get_double(entry.name) * entry.unit;
  prm.leave_subsection();

  if (p.train_description)
  {
    parse_train_description(prm, p);
    return p;
  }
  // Mesh phases from the placement angles: each mesh relative to the first mesh of its driver.
  for (unsigned int m = 0; m < p.train.meshes.size(); ++m)
    p.train.meshes[m].initial_position =
        p.initial_position +
        dynamics::mesh_phase_from_placement(p.train.meshes[m].driver_teeth, p.placement_angle[m]);
  return p;
}
} // namespace gearstiff::app
