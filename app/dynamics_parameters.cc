#include "app/dynamics_parameters.h"

#include "app/kinematics_parameters.h"
#include "app/parameter_patterns.h"
#include "app/units.h"
#include "dynamics/split_path_case.h"
#include "dynamics/stiffness_file.h"
#include "dynamics/train_model.h"
#include "errors/errors.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gearstiff::app
{
namespace
{
constexpr double micrometre = 1e-6;
constexpr double newton_per_mm = 1e3;            // N/mm → N/m
constexpr double newton_per_mm_micrometre = 1e9; // N/(mm·µm) → N/m²

std::string gear_section(unsigned int i)
{
  return "Gear " + std::to_string(i + 1);
}
std::string mesh_section(unsigned int m)
{
  return "Mesh " + std::to_string(m + 1);
}
std::string train_mesh_section(unsigned int m)
{
  return "Train mesh " + std::to_string(m + 1);
}

// The comma-separated entries of `text` that are not blank.
std::vector<std::string> comma_entries(const std::string& text)
{
  std::vector<std::string> entries;
  std::istringstream in(text);
  std::string entry;
  while (std::getline(in, entry, ','))
    if (entry.find_first_not_of(" \t") != std::string::npos)
      entries.push_back(entry);
  return entries;
}

// "x:k, x:k, ..." with x in base pitches and k in N/mm.
void parse_table(const std::string& text, const std::string& parameter,
                 std::vector<double>& positions, std::vector<double>& stiffness)
{
  for (const std::string& entry : comma_entries(text))
  {
    const auto colon = entry.find(':');
    try
    {
      if (colon == std::string::npos)
        throw std::invalid_argument("no colon");
      std::size_t used = 0;
      const double x = std::stod(entry.substr(0, colon));
      const double k = std::stod(entry.substr(colon + 1), &used);
      if (entry.substr(colon + 1 + used).find_first_not_of(" \t") != std::string::npos)
        throw std::invalid_argument("trailing text");
      positions.push_back(x);
      stiffness.push_back(k * newton_per_mm);
    }
    catch (const std::exception&)
    {
      throw InputError(parameter,
                       "entry '" + entry + "' is not 'position:stiffness' (base pitches : N/mm)");
    }
  }
}
// The entries a mesh needs whatever describes its gears: stiffness source, damping, friction.
// Shared by "Mesh n" (gears and meshes) and "Train mesh n" (Train description).
// `train_mesh` adds the source 'file' (a stiffness result of the FE commands): only a Train
// mesh knows its gears' teeth and modules, which the file must match.
void declare_mesh_physics(ParameterHandler& prm, double stiffness, double damping, double friction,
                          double driver_arm, double driven_arm, bool train_mesh)
{
  prm.declare_entry(
      "stiffness source", "cai",
      Selection(train_mesh ? "cai|constant|table|cai fit|file" : "cai|constant|table|cai fit"),
      std::string("mesh stiffness: 'cai' (Cai curve, peak = stiffness), 'constant', "
                  "'table' (k(x) table), 'cai fit' (Cai curve least-squares fitted "
                  "to the table)") +
          (train_mesh ? ", 'file' (FE k(x) table or calibrated Cai curve of "
                        "'stiffness file')"
                      : ""));
  if (train_mesh)
    prm.declare_entry("stiffness file", "", Anything(),
                      "summary.json written by `gearstiff stiffness` (mode sweep: its k(x) "
                      "table) or `gearstiff cai` (its calibrated Cai curve) with -o, for the "
                      "same pair (teeth, module, centre distance checked); path relative to the "
                      "working directory");
  prm.declare_entry("stiffness", format_number(stiffness / newton_per_mm, 10), Double(),
                    "constant: the mesh stiffness; cai: one pair's peak k'_j (N/mm)");
  prm.declare_entry("cai shape", "0.55, 1.8, -1.8", Anything(),
                    "c0, c1, c2 of the Cai bracket c2·s² + c1·s + c0, s = engagement "
                    "fraction (-); the published shape peaks at 1");
  prm.declare_entry("stiffness table", "", Anything(),
                    "mesh stiffness samples 'x:k, x:k, ...' with x the mesh position in base "
                    "pitches in [0, 1) (increasing) and k in N/mm");
  prm.declare_entry("fit cai shape", "false", Bool(),
                    "cai fit: fit the three shape coefficients too, not only the scale");
  prm.declare_entry("damping", format_number(damping, 10), Double(),
                    "c_g, mesh damping along the line of action (N·s/m)");
  prm.declare_entry("friction coefficient", format_number(friction, 10), Double(0., 0.99),
                    "mu, tooth friction (-)");
  prm.declare_entry("driver friction arm", format_number(driver_arm / mm, 10), Double(0.),
                    "r_f of the driver (mm)");
  prm.declare_entry("driven friction arm", format_number(driven_arm / mm, 10), Double(0.),
                    "r_f of the driven gear (mm)");
}

struct MeshPhysics
{
  dynamics::MeshStiffness stiffness;
  std::optional<dynamics::CaiFit> fit;
  double damping = 0.;                         // [N·s/m]
  double friction_coefficient = 0.;            // [-]
  double driver_friction_arm = 0.;             // [m]
  double driven_friction_arm = 0.;             // [m]
  std::optional<dynamics::StiffnessFile> file; // source 'file': the FE result it came from
};

// Reads the entries of declare_mesh_physics inside the mesh's subsection `section`.
MeshPhysics parse_mesh_physics(ParameterHandler& prm, const std::string& section,
                               double contact_ratio)
{
  MeshPhysics physics;
  physics.damping = prm.get_double("damping");
  // Without damping the start-up transient never decays: there is no steady state, and the
  // figures read from the window (DTE, K_v) depend on where the window starts.
  if (!(physics.damping > 0.) || !std::isfinite(physics.damping))
    throw InputError(section + "/damping",
                     "must be positive and finite (N·s/m): without mesh damping the start-up "
                     "transient never decays (decay time infinite), so there is no steady state "
                     "to report");
  physics.friction_coefficient = prm.get_double("friction coefficient");
  physics.driver_friction_arm = prm.get_double("driver friction arm") * mm;
  physics.driven_friction_arm = prm.get_double("driven friction arm") * mm;

  const std::string source = prm.get("stiffness source");
  const double stiffness = prm.get_double("stiffness") * newton_per_mm;
  dynamics::CaiParameters cai = dynamics::cai_published_parameters(stiffness);
  {
    std::istringstream shape(prm.get("cai shape"));
    std::string value;
    unsigned int i = 0;
    try
    {
      for (; std::getline(shape, value, ','); ++i)
        if (i < 3)
          cai.shape[i] = std::stod(value);
    }
    catch (const std::exception&)
    {
      i = 0;
    }
    if (i != 3)
      throw InputError(section + "/cai shape", "expects three numbers c0, c1, c2");
  }
  std::vector<double> positions, values;
  parse_table(prm.get("stiffness table"), section + "/stiffness table", positions, values);
  const bool fit_shape = prm.get_bool("fit cai shape");

  if (source == "constant")
    physics.stiffness = dynamics::MeshStiffness::constant(stiffness, section + "/stiffness");
  else if (source == "cai")
    physics.stiffness = dynamics::MeshStiffness::cai(cai, section + "/stiffness");
  else if (source == "table")
    physics.stiffness =
        dynamics::MeshStiffness::table(positions, values, section + "/stiffness table");
  else if (source == "file")
  {
    physics.file =
        dynamics::read_stiffness_file(prm.get("stiffness file"), section + "/stiffness file");
    physics.stiffness = physics.file->stiffness;
  }
  else
  {
    // Validate the samples as a table first so the user gets the table's own message.
    dynamics::MeshStiffness::table(positions, values, section + "/stiffness table");
    std::vector<dynamics::StiffnessSample> samples;
    for (std::size_t i = 0; i < positions.size(); ++i)
      samples.push_back({positions[i], values[i]});
    physics.fit = dynamics::fit_cai_parameters(samples, contact_ratio,
                                               dynamics::StiffnessSampleKind::mesh, fit_shape);
    physics.stiffness =
        dynamics::MeshStiffness::cai(physics.fit->parameters, section + "/stiffness");
  }
  return physics;
}

// parse_mesh_physics in the subsection `section`, which is left also when it throws.
MeshPhysics parse_mesh_physics_section(ParameterHandler& prm, const std::string& section,
                                       double contact_ratio)
{
  prm.enter_subsection(section);
  try
  {
    MeshPhysics physics = parse_mesh_physics(prm, section, contact_ratio);
    prm.leave_subsection();
    return physics;
  }
  catch (...)
  {
    prm.leave_subsection();
    throw;
  }
}

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
    {"face width", &IsoParameters::face_width, mm, Double(0.), "b, common face width (mm)"},
    {"transverse pressure angle", &IsoParameters::pressure_angle, degree, Double(0., 45.),
     "alpha_t: F_t = F_bt·cos alpha_t (degrees)"},
    {"single stiffness", &IsoParameters::single_stiffness, newton_per_mm_micrometre, Double(0.),
     "c' (N/(mm·µm)); 0: c_gamma_alpha/(0.75·epsilon_alpha + 0.25)"},
    {"mesh stiffness", &IsoParameters::mesh_stiffness, newton_per_mm_micrometre, Double(0.),
     "c_gamma_alpha (N/(mm·µm)); 0: the model's mean mesh stiffness / b"},
    {"pitch deviation", &IsoParameters::pitch_deviation, micrometre, Double(0.),
     "f_pb,eff = f_pb - y_p, effective base pitch deviation (µm); the default is ISO 1328 grade "
     "6 for this size without running-in allowance"},
    {"profile deviation", &IsoParameters::profile_deviation, micrometre, Double(0.),
     "f_f,eff = f_f_alpha - y_f, effective profile form deviation (µm)"},
    {"tip relief", &IsoParameters::tip_relief, micrometre, Double(0.), "C_a (µm); 0: none"},
    {"application factor", &IsoParameters::application_factor, 1., Double(0.), "K_A (-)"}};

void apply_mesh_physics(const MeshPhysics& physics, dynamics::Mesh& mesh)
{
  mesh.stiffness = physics.stiffness;
  mesh.damping = physics.damping;
  mesh.friction_coefficient = physics.friction_coefficient;
  mesh.driver_friction_arm = physics.driver_friction_arm;
  mesh.driven_friction_arm = physics.driven_friction_arm;
}

} // namespace

void declare_dynamics_parameters(ParameterHandler& prm)
{
  const dynamics::SplitPathCase data = dynamics::split_path_case();

  prm.enter_subsection("Train");
  prm.declare_entry("number of gears", "3", Integer(2, max_dynamics_gears),
                    "gears (rotational degrees of freedom) of the train; a tree of n gears has "
                    "n - 1 meshes, read from 'Mesh 1' ... (-)");
  prm.declare_entry("input speed", format_number(data.input_speed_rpm, 10), Double(0.),
                    "n1, nominal speed of gear 1 (rpm); the others follow from the base radii");
  prm.declare_entry("published reference", "true", Bool(),
                    "print the published split-path values (docs/references.md §1, Reszuta & "
                    "Drewniak 2015) beside ours; set false for other trains");
  prm.declare_entry("model", "gears and meshes", Selection("gears and meshes|train"),
                    "'gears and meshes': the sections Gear n / Mesh n (a tree, default: the "
                    "split path); 'train': the kinematics command's Train description (gears, "
                    "carriers, planets, meshes, ...) with the sections Train mesh n");
  prm.declare_entry("pressure angle", "20", Double(0., 45.),
                    "train model: pressure angle of the standard teeth (x = 0, h_a* = 1) for "
                    "base radii, contact and approach ratios (degrees)");
  prm.declare_entry("suspended members", "", Anything(),
                    "train model: fixed members hung on a torsional spring and damper to the "
                    "housing, 'name: stiffness damping, ...' (N·m/rad, N·m·s/rad)");
  prm.declare_entry("face widths", "", Anything(),
                    "train model: gears whose J and mass come from a steel blank where "
                    "Train/inertias and Train/masses give none, 'name: b, ...' (mm)");
  prm.declare_entry("bore diameters", "", Anything(),
                    "train model: bore of those blanks, 'name: d, ...' (mm; none: solid); for an "
                    "internal gear the rim's outside diameter (required)");
  prm.declare_entry("density", "7850", Double(0.), "train model: density of the blanks (kg/m³)");
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
                      Double(0.), "J, mass moment of inertia about the gear axis (kg·m²)");
    prm.declare_entry("torque",
                      pinion ? format_number(data.input_torque, 10) : std::string("balance"),
                      Anything(),
                      "external torque (N·m), positive in the running direction (input), "
                      "negative for a load; 'balance': the load that takes an equal share of "
                      "its driver's torque, T = -T_driver/(meshes of the driver)·r_b/r_b,driver");
    prm.leave_subsection();
  }

  for (unsigned int m = 0; m + 1 < max_dynamics_gears; ++m)
  {
    prm.enter_subsection(mesh_section(m));
    prm.declare_entry("driver gear", "1", Integer(1, max_dynamics_gears),
                      "number of the driving gear (-)");
    prm.declare_entry("driven gear", std::to_string(m + 2), Integer(1, max_dynamics_gears),
                      "number of the driven gear (-)");
    prm.declare_entry("driver teeth", std::to_string(data.pinion_teeth), Integer(1, 10000),
                      "z of the driver: the mesh frequency is z·n_driver/60 (-)");
    prm.declare_entry("driver base radius", format_number(data.pinion_base_radius / mm, 10),
                      Double(0.), "r_b of the driver (mm)");
    prm.declare_entry("driven base radius", format_number(data.wheel_base_radius / mm, 10),
                      Double(0.), "r_b of the driven gear (mm)");
    prm.declare_entry("contact ratio", format_number(data.contact_ratio, 10), Double(1., 4.),
                      "epsilon_alpha, transverse contact ratio (-); default from the "
                      "kinematics module's split-path pair");
    prm.declare_entry("approach ratio", format_number(data.approach_ratio, 10), Double(0., 4.),
                      "epsilon_f, start of active contact to the pitch point in base pitches "
                      "(-): where the friction force reverses; default from kinematics");
    prm.declare_entry("placement angle", m == 1 ? "180" : "0", Double(-360., 360.),
                      "theta, angle of the driven gear's centre around the driver axis, "
                      "against the driver's rotation, from the driven gear of the first mesh "
                      "of the same driver (degrees); sets the phase frac(z·theta/360°)");
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
                    "step of RK4 and HHT-alpha, output interval of the adaptive method (µs)");
  prm.declare_entry("allow unstable step", "false", Bool(),
                    "run RK4 with a step above the estimated stability limit");
  prm.declare_entry("relative tolerance", "1e-7", Double(0., 0.1),
                    "adaptive RK: local error tolerance relative to the state (-)");
  prm.declare_entry("HHT alpha", "-0.05", Double(-1. / 3., 0.),
                    "HHT-alpha parameter in [-1/3, 0]; 0 is the trapezoidal rule (-)");
  prm.declare_entry("start", "static deflection", Selection("static deflection|rest"),
                    "initial state: static deflection under mean stiffness, or rest (the "
                    "torques applied suddenly)");
  prm.declare_entry("initial mesh position", "0", Double(0., 1.),
                    "position of mesh 1 at t = 0, in base pitches (0: a pair enters contact)");
  prm.declare_entry("steady state start", "-1", Double(),
                    "start of the K_v window (s); negative: automatic, when the slowest mode "
                    "has decayed to 1/1000");
  prm.declare_entry("simulated time", "0", Double(0.),
                    "end time (s); 0: the window start plus 'window periods' mesh periods");
  prm.declare_entry("window periods", "40", Integer(1, 100000),
                    "length of the automatic K_v window in periods of mesh 1 (-)");
  prm.declare_entry("output interval", "20", Double(0.),
                    "spacing of the rows of the time-series CSV (µs); K_v uses every step");
  prm.leave_subsection();

  prm.enter_subsection("Speed sweep");
  prm.declare_entry("points", "60", Integer(0, 100000),
                    "speeds in the K_v resonance chart (-); 0: no sweep");
  prm.declare_entry("minimum speed", "500", Double(0.), "first input speed (rpm)");
  prm.declare_entry("maximum speed", "45000", Double(0.), "last input speed (rpm)");
  prm.declare_entry("steps per mesh period", "40", Integer(8, 10000),
                    "the step is reduced so each mesh period holds at least this many (-)");
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
// "Gear n" / "Mesh n" sections: a tree-shaped train in the two-gear mesh form.
void parse_numbered_train(ParameterHandler& prm, DynamicsParameters& p)
{
  prm.enter_subsection("Train");
  const unsigned int n_gears = prm.get_integer("number of gears");
  p.train.input_speed = prm.get_double("input speed") * rpm;
  p.published_reference = prm.get_bool("published reference");
  prm.leave_subsection();
  if (!(p.train.input_speed > 0.) || !std::isfinite(p.train.input_speed))
    throw InputError("Train/input speed", "must be positive (rpm), got " +
                                              format_number(p.train.input_speed / rpm, 6) + " rpm");

  std::vector<std::string> torque_text(n_gears);
  for (unsigned int i = 0; i < n_gears; ++i)
  {
    prm.enter_subsection(gear_section(i));
    dynamics::Gear gear;
    gear.name = gear_section(i);
    gear.inertia = prm.get_double("inertia");
    torque_text[i] = prm.get("torque");
    prm.leave_subsection();
    p.train.gears.push_back(gear);
  }

  for (unsigned int m = 0; m + 1 < n_gears; ++m)
  {
    const std::string section = mesh_section(m);
    prm.enter_subsection(section);
    dynamics::Mesh mesh;
    mesh.name = section;
    const unsigned int driver = prm.get_integer("driver gear");
    const unsigned int driven = prm.get_integer("driven gear");
    mesh.driver_teeth = prm.get_integer("driver teeth");
    mesh.driver_base_radius = prm.get_double("driver base radius") * mm;
    mesh.driven_base_radius = prm.get_double("driven base radius") * mm;
    mesh.contact_ratio = prm.get_double("contact ratio");
    mesh.approach_ratio = prm.get_double("approach ratio");
    p.placement_angle.push_back(prm.get_double("placement angle") * degree);
    prm.leave_subsection();
    if (driver > n_gears || driven > n_gears || driver == driven)
      throw InputError(section + "/driven gear",
                       "a mesh joins two different gears among the first " +
                           std::to_string(n_gears));
    mesh.driver = driver - 1;
    mesh.driven = driven - 1;
    const MeshPhysics physics = parse_mesh_physics_section(prm, section, mesh.contact_ratio);
    apply_mesh_physics(physics, mesh);
    const std::optional<dynamics::CaiFit>& fit = physics.fit;
    p.stiffness_description.push_back(mesh.stiffness.description() +
                                      (fit ? " (fitted to the table)" : ""));
    p.cai_fit.push_back(fit);
    p.train.meshes.push_back(mesh);
  }

  // Torques: numbers, or "balance" for a load taking an equal share of its driver's torque.
  std::vector<bool> known(n_gears, false);
  std::vector<double> torque(n_gears, 0.);
  for (unsigned int i = 0; i < n_gears; ++i)
    if (torque_text[i] != "balance")
    {
      std::size_t used = 0;
      try
      {
        torque[i] = std::stod(torque_text[i], &used);
      }
      catch (const std::exception&)
      {
        used = 0;
      }
      if (used == 0 || torque_text[i].find_first_not_of(" \t", used) != std::string::npos)
        throw InputError(gear_section(i) + "/torque",
                         "expects a number (N·m) or 'balance', got '" + torque_text[i] + "'");
      known[i] = true;
    }
  for (unsigned int i = 0; i < n_gears; ++i)
    if (!known[i])
    {
      const dynamics::Mesh* feeding = nullptr;
      for (const auto& mesh : p.train.meshes)
        if (mesh.driven == i)
          feeding = &mesh;
      if (feeding == nullptr || !known[feeding->driver] || !(torque[feeding->driver] > 0.))
        throw InputError(gear_section(i) + "/torque",
                         "'balance' needs a driving gear with a given positive torque");
      unsigned int shares = 0;
      for (const auto& mesh : p.train.meshes)
        shares += (mesh.driver == feeding->driver);
      torque[i] = -torque[feeding->driver] / shares * feeding->driven_base_radius /
                  feeding->driver_base_radius;
    }
  for (unsigned int i = 0; i < n_gears; ++i)
    p.train.gears[i].torque = torque[i];
}

// "name: v1 v2 ..., ..." with `count` non-negative finite numbers per name (`units` for the
// message): suspensions (stiffness damping), face widths, bore diameters.
std::vector<std::pair<std::string, std::vector<double>>>
parse_named_numbers(const std::string& text, unsigned int count, const std::string& parameter,
                    const std::string& units)
{
  std::vector<std::pair<std::string, std::vector<double>>> entries_read;
  for (const std::string& entry : comma_entries(text))
  {
    const auto colon = entry.find(':');
    std::istringstream values(colon == std::string::npos ? "" : entry.substr(colon + 1));
    std::string name = colon == std::string::npos ? "" : entry.substr(0, colon);
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t") + 1);
    std::vector<double> numbers(count);
    bool good = !name.empty();
    for (double& v : numbers)
      good = good && (values >> v) && v >= 0. && std::isfinite(v);
    std::string rest;
    if (!good || (values >> rest))
      throw InputError(parameter, "entry '" + entry + "' is not 'name: " + units +
                                      "' with non-negative numbers");
    entries_read.emplace_back(name, numbers);
  }
  return entries_read;
}

// The Train entries of the dynamics beyond the kinematics' description.
void parse_train_extras(ParameterHandler& prm, dynamics::TrainDynamicsInput& input)
{
  prm.enter_subsection("Train");
  input.pressure_angle = prm.get_double("pressure angle") * degree;
  input.density = prm.get_double("density");
  const std::string suspended = prm.get("suspended members");
  const std::string widths = prm.get("face widths");
  const std::string bores = prm.get("bore diameters");
  prm.leave_subsection();
  for (const auto& [name, v] :
       parse_named_numbers(suspended, 2, "Train/suspended members", "stiffness damping"))
    input.suspensions.push_back({name, v[0], v[1]});
  for (const auto& [name, v] : parse_named_numbers(widths, 1, "Train/face widths", "b"))
    input.blanks.push_back({name, v[0] * mm, 0.});
  for (const auto& [name, v] : parse_named_numbers(bores, 1, "Train/bore diameters", "d"))
  {
    const auto blank =
        std::find_if(input.blanks.begin(), input.blanks.end(),
                     [&, n = name](const dynamics::GearBlank& b) { return b.member == n; });
    if (blank == input.blanks.end())
      throw InputError("Train/bore diameters", "'" + name + "' has no face width");
    blank->bore_diameter = v[0] * mm;
  }
}

// The kinematics command's "Train" description plus "Train mesh n" sections.
void parse_train_description(ParameterHandler& prm, DynamicsParameters& p)
{
  const TrainParameters train = parse_train_parameters(prm);
  dynamics::TrainDynamicsInput input;
  input.spec = kinematics::parse_gear_train(train.text);
  // 'Train/input speed' belongs to the 'gears and meshes' model; the train model's speeds come
  // from Train/inputs. A value set to something else would be ignored: refuse the conflict.
  prm.enter_subsection("Train");
  const double input_speed = prm.get_double("input speed");
  prm.leave_subsection();
  const double default_speed = dynamics::split_path_case().input_speed_rpm;
  if (std::abs(input_speed - default_speed) > 1e-9 * default_speed)
  {
    const bool same = input.spec.inputs.size() == 1 &&
                      std::abs(input_speed * rpm - input.spec.inputs.front().second) <=
                          1e-9 * std::abs(input.spec.inputs.front().second);
    if (!same)
      throw InputError("Train/input speed",
                       "is not used by Train/model = train, whose speeds come from Train/inputs "
                       "(" +
                           (input.spec.inputs.empty()
                                ? std::string("none given")
                                : input.spec.inputs.front().first + " at " +
                                      format_number(input.spec.inputs.front().second / rpm, 6) +
                                      " rpm") +
                           "): give the speed there and leave 'input speed' at its default");
  }
  input.input_torque = train.input_torque;
  parse_train_extras(prm, input);
  input.initial_position = p.initial_position;
  if (input.spec.meshes.size() > max_train_meshes)
    throw InputError("Train/meshes", "at most " + std::to_string(max_train_meshes) +
                                         " meshes (sections 'Train mesh 1' ...)");
  for (std::size_t m = 0; m < input.spec.meshes.size(); ++m)
  {
    const std::string section = train_mesh_section(m);
    // The contact ratio of standard teeth, for a Cai fit (the model recomputes it).
    const kinematics::TrainMesh& tm = input.spec.meshes[m];
    double contact_ratio = 1.5, module = 0.;
    int teeth[2] = {0, 0};
    for (const auto& a : input.spec.members)
      for (const auto& b : input.spec.members)
        if (a.name == tm.gear_a && b.name == tm.gear_b && a.module > 0.)
        {
          contact_ratio =
              dynamics::standard_mesh(a.teeth, b.teeth, a.module, input.pressure_angle, 0)
                  .contact_ratio;
          module = a.module;
          teeth[0] = a.teeth;
          teeth[1] = b.teeth;
        }
    const MeshPhysics physics = parse_mesh_physics_section(prm, section, contact_ratio);
    dynamics::TrainMeshDynamics mesh{physics.stiffness,
                                     physics.damping,
                                     physics.friction_coefficient,
                                     physics.driver_friction_arm,
                                     physics.driven_friction_arm,
                                     {},
                                     {},
                                     {}};
    std::string origin = physics.fit ? " (fitted to the table)" : "";
    if (physics.file)
    {
      mesh.stiffness_driver = dynamics::match_stiffness_file(*physics.file, teeth[0], teeth[1],
                                                             module, section + "/stiffness file");
      // The FE pair's path of contact (its tips) sets the cycle the table is measured on.
      mesh.contact_ratio = physics.file->pair.contact_ratio;
      if (std::isfinite(physics.file->pair.approach_ratio))
        mesh.approach_ratio = physics.file->pair.approach_ratio;
      origin =
          " from `gearstiff " + physics.file->command + "` (" + physics.file->pair.describe() + ")";
    }
    input.meshes.push_back(mesh);
    p.stiffness_description.push_back(physics.stiffness.description() + origin);
    p.cai_fit.push_back(physics.fit);
  }
  p.train_model = dynamics::build_train_model(input);
  p.train = p.train_model.train;
  p.published_reference = false;
  // Per model mesh (every copy): the description of its Train mesh.
  std::vector<std::string> descriptions;
  std::vector<std::optional<dynamics::CaiFit>> fits;
  for (const unsigned int m : p.train_model.spec_mesh)
  {
    descriptions.push_back(p.stiffness_description[m]);
    fits.push_back(p.cai_fit[m]);
  }
  p.stiffness_description = descriptions;
  p.cai_fit = fits;
  p.placement_angle.assign(p.train.meshes.size(), std::nan(""));
}
} // namespace

DynamicsParameters parse_dynamics_parameters(ParameterHandler& prm)
{
  DynamicsParameters p;
  prm.enter_subsection("Train");
  p.train_description = prm.get("model") == "train";
  prm.leave_subsection();
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
