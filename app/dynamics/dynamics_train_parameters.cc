// The train of `gearstiff dynamics`: "Gear n" / "Mesh n" sections (a tree of two-gear meshes) or
// the kinematics command's Train description with "Train mesh n" sections (train_model.h).
#include "app/core/parameter_patterns.h"
#include "app/core/units.h"
#include "app/dynamics/dynamics_parameters_internal.h"
#include "app/dynamics/train_parameter_entries.h"
#include "app/kinematics/kinematics_parameters.h"
#include "dynamics/split_path_case.h"
#include "dynamics/train_model.h"
#include "errors/errors.h"

#include <algorithm>
#include <limits>
#include <sstream>

namespace gearstiff::app::dynamics_input
{
namespace
{
// "Mesh m+1" of a train of `n_gears` "Gear n" sections into p (mesh, placement, stiffness
// description, Cai fit); returns its damping ratio (NaN: damping given).
double parse_numbered_mesh(ParameterHandler& prm, unsigned int m, unsigned int n_gears,
                           DynamicsParameters& p)
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
                     "a mesh joins two different gears among the first " + std::to_string(n_gears));
  mesh.driver = driver - 1;
  mesh.driven = driven - 1;
  const MeshPhysics physics = parse_mesh_physics_section(prm, section, mesh.contact_ratio);
  apply_mesh_physics(physics, mesh);
  if (p.mesh_model == dynamics::MeshModel::nonlinear)
  {
    // Spur: α_n = α_t of the ISO section; m = 2·r_b1/(z1·cos α_n).
    prm.enter_subsection("ISO 6336");
    const double pressure_angle = prm.get_double("transverse pressure angle") * degree;
    prm.leave_subsection();
    const MeshGeometry geometry{2. * mesh.driver_base_radius /
                                    (mesh.driver_teeth * std::cos(pressure_angle)),
                                pressure_angle};
    mesh.nonlinear = build_nonlinear_mesh(
        physics.nonlinear, section, mesh.driver_teeth, geometry,
        [&](const dynamics::StiffnessFile& file, const std::string& parameter)
        { check_numbered_mesh_pair(file, mesh, parameter); },
        p.derived_sizes);
  }
  const std::optional<dynamics::CaiFit>& fit = physics.fit;
  p.stiffness_description.push_back(mesh.stiffness.description() +
                                    (fit ? " (fitted to the table)" : ""));
  p.cai_fit.push_back(fit);
  p.train.meshes.push_back(mesh);
  return physics.damping_ratio;
}

// The gears' torques: numbers, or "balance" for a load taking an equal share of its driver's
// torque [N·m].
std::vector<double> resolve_torques(const std::vector<std::string>& torque_text,
                                    const dynamics::GearTrain& train)
{
  const std::size_t n_gears = torque_text.size();
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
      for (const auto& mesh : train.meshes)
        if (mesh.driven == i)
          feeding = &mesh;
      if (feeding == nullptr || !known[feeding->driver] || !(torque[feeding->driver] > 0.))
        throw InputError(gear_section(i) + "/torque",
                         "'balance' needs a driving gear with a given positive torque");
      unsigned int shares = 0;
      for (const auto& mesh : train.meshes)
        shares += (mesh.driver == feeding->driver);
      torque[i] = -torque[feeding->driver] / shares * feeding->driven_base_radius /
                  feeding->driver_base_radius;
    }
  return torque;
}
} // namespace

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

  std::vector<double> damping_ratios; // per mesh, NaN: damping given
  std::vector<std::string> mesh_sections;
  for (unsigned int m = 0; m + 1 < n_gears; ++m)
  {
    mesh_sections.push_back(mesh_section(m));
    damping_ratios.push_back(parse_numbered_mesh(prm, m, n_gears, p));
  }
  const std::vector<double> torque = resolve_torques(torque_text, p.train);
  for (unsigned int i = 0; i < n_gears; ++i)
    p.train.gears[i].torque = torque[i];
  apply_damping_ratios(p.train, damping_ratios, mesh_sections, p.derived_sizes);
  // The published nominal force F_cn belongs to the split-path case alone: T1 and r_b1 of it.
  const dynamics::SplitPathCase data = dynamics::split_path_case();
  const dynamics::Mesh& first = p.train.meshes.front();
  p.published_reference = p.published_reference &&
                          std::abs(torque[first.driver] - data.input_torque) < 1e-9 &&
                          std::abs(first.driver_base_radius - data.pinion_base_radius) < 1e-9 &&
                          std::abs(first.driven_base_radius - data.wheel_base_radius) < 1e-9;
}

namespace
{
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
} // namespace

namespace
{
// 'Train/input speed' belongs to the 'gears and meshes' model; the train model's speeds come
// from Train/inputs. A value set to something else would be ignored: refuse the conflict.
void check_train_input_speed(ParameterHandler& prm, const kinematics::GearTrainSpec& spec)
{
  prm.enter_subsection("Train");
  const double input_speed = prm.get_double("input speed");
  prm.leave_subsection();
  const double default_speed = dynamics::split_path_case().input_speed_rpm;
  if (std::abs(input_speed - default_speed) <= 1e-9 * default_speed)
    return;
  const bool same =
      spec.inputs.size() == 1 && std::abs(input_speed * rpm - spec.inputs.front().second) <=
                                     1e-9 * std::abs(spec.inputs.front().second);
  if (!same)
    throw InputError("Train/input speed",
                     "is not used by Train/model = train, whose speeds come from Train/inputs (" +
                         (spec.inputs.empty()
                              ? std::string("none given")
                              : spec.inputs.front().first + " at " +
                                    format_number(spec.inputs.front().second / rpm, 6) + " rpm") +
                         "): give the speed there and leave 'input speed' at its default");
}

// The pair of Train mesh m with standard addenda and its gears' profile shifts: contact ratio
// (for a Cai fit; the model recomputes it), module [m], teeth of gear a and b and the working
// centre distance [m] an FE table's pair must have.
struct TrainMeshPair
{
  double contact_ratio = 1.5;
  double module = 0.;
  int teeth[2] = {0, 0};
  double centre_distance = 0.;
};
TrainMeshPair train_mesh_pair(const dynamics::TrainDynamicsInput& input, std::size_t m)
{
  const kinematics::TrainMesh& tm = input.spec.meshes[m];
  TrainMeshPair pair;
  for (const auto& a : input.spec.members)
    for (const auto& b : input.spec.members)
      if (a.name == tm.gear_a && b.name == tm.gear_b && a.module > 0.)
      {
        pair.contact_ratio = dynamics::standard_mesh(a, b, input.pressure_angle, 0).contact_ratio;
        pair.module = a.module;
        pair.teeth[0] = a.teeth;
        pair.teeth[1] = b.teeth;
        pair.centre_distance = kinematics::working_centre_distance(a, b, input.pressure_angle);
      }
  return pair;
}

// stiffness = auto of Train mesh m: c'·b with this mesh's own face width (the smaller of its
// gears'), so that no mesh inherits the split-path pair's peak [N/m]; `origin` tells where b
// came from and `width` [m] is b.
double automatic_train_stiffness(const dynamics::TrainDynamicsInput& input, std::size_t m,
                                 double iso_face_width, double& width, std::string& origin)
{
  const kinematics::TrainMesh& tm = input.spec.meshes[m];
  width = 0.;
  origin = "ISO 6336/face width";
  for (const dynamics::GearBlank& blank : input.blanks)
    if ((blank.member == tm.gear_a || blank.member == tm.gear_b) &&
        (width == 0. || blank.face_width < width))
    {
      width = blank.face_width;
      origin = "Train/face widths";
    }
  if (width == 0.)
    width = iso_face_width;
  return iso_approximate_single_stiffness * width;
}

// "Train mesh m+1" into input.meshes and p (stiffness description, Cai fit, derived sizes);
// returns its damping ratio (NaN: damping given).
double parse_train_mesh(ParameterHandler& prm, std::size_t m, double iso_face_width,
                        dynamics::TrainDynamicsInput& input, DynamicsParameters& p)
{
  const std::string section = train_mesh_section(m);
  const TrainMeshPair pair = train_mesh_pair(input, m);
  double width = 0.;
  std::string width_origin;
  const double automatic_stiffness =
      automatic_train_stiffness(input, m, iso_face_width, width, width_origin);
  const MeshPhysics physics =
      parse_mesh_physics_section(prm, section, pair.contact_ratio, automatic_stiffness);
  check_contact_loss(physics, p.mesh_model == dynamics::MeshModel::nonlinear, section);
  prm.enter_subsection(section);
  // Listed only where the number is used (sources cai and constant).
  const std::string source = prm.get("stiffness source");
  const bool automatic =
      prm.get("stiffness") == "auto" && (source == "cai" || source == "constant");
  prm.leave_subsection();
  if (automatic)
    p.derived_sizes.push_back(
        section + "/stiffness = " + format_number(automatic_stiffness / 1e6, 5) +
        " N/µm (auto: ISO 6336-1 c' = 14 N/(mm·µm) × b = " + format_number(width / mm, 5) +
        " mm from " + width_origin + ")");
  dynamics::TrainMeshDynamics mesh{physics.stiffness,
                                   physics.damping,
                                   physics.friction_coefficient,
                                   physics.driver_friction_arm,
                                   physics.driven_friction_arm,
                                   {},
                                   {},
                                   {},
                                   {},
                                   std::numeric_limits<double>::quiet_NaN()};
  if (p.mesh_model == dynamics::MeshModel::nonlinear)
    mesh.nonlinear = build_nonlinear_mesh(
        physics.nonlinear, section, static_cast<unsigned int>(std::abs(pair.teeth[0])),
        {pair.module, input.pressure_angle},
        [&](const dynamics::StiffnessFile& file, const std::string& parameter)
        {
          dynamics::match_stiffness_file(file, pair.teeth[0], pair.teeth[1], pair.module,
                                         pair.centre_distance, parameter);
        },
        p.derived_sizes);
  std::string origin = physics.fit ? " (fitted to the table)" : "";
  if (physics.file)
  {
    mesh.stiffness_driver =
        dynamics::match_stiffness_file(*physics.file, pair.teeth[0], pair.teeth[1], pair.module,
                                       pair.centre_distance, section + "/stiffness file");
    // The FE pair's path of contact (its tips) sets the cycle the table is measured on.
    mesh.contact_ratio = physics.file->pair.contact_ratio;
    mesh.table_force = physics.file->pair.tooth_force();
    if (std::isfinite(physics.file->pair.approach_ratio))
      mesh.approach_ratio = physics.file->pair.approach_ratio;
    origin =
        " from `gearstiff " + physics.file->command + "` (" + physics.file->pair.describe() + ")";
  }
  input.meshes.push_back(mesh);
  p.stiffness_description.push_back(physics.stiffness.description() + origin);
  p.cai_fit.push_back(physics.fit);
  return physics.damping_ratio;
}

// From Train meshes to the model's meshes (every copy): damping from the ratios (reported once
// per Train mesh), stiffness descriptions and Cai fits.
void expand_to_mesh_copies(const std::vector<double>& spec_damping_ratios, DynamicsParameters& p)
{
  std::vector<double> ratios;
  std::vector<std::string> sections;
  for (std::size_t m = 0; m < p.train.meshes.size(); ++m)
  {
    ratios.push_back(spec_damping_ratios[p.train_model.spec_mesh[m]]);
    sections.push_back(p.train_model.mesh_copy[m] == 0
                           ? train_mesh_section(p.train_model.spec_mesh[m])
                           : std::string());
  }
  apply_damping_ratios(p.train, ratios, sections, p.derived_sizes);
  std::vector<std::string> descriptions;
  std::vector<std::optional<dynamics::CaiFit>> fits;
  for (const unsigned int m : p.train_model.spec_mesh)
  {
    descriptions.push_back(p.stiffness_description[m]);
    fits.push_back(p.cai_fit[m]);
  }
  p.stiffness_description = descriptions;
  p.cai_fit = fits;
}
} // namespace

void parse_train_description(ParameterHandler& prm, DynamicsParameters& p)
{
  const TrainParameters train = parse_train_parameters(prm);
  prm.enter_subsection("ISO 6336");
  const double iso_face_width = prm.get_double("face width") * mm;
  prm.leave_subsection();
  dynamics::TrainDynamicsInput input;
  input.spec = kinematics::parse_gear_train(train.text);
  check_train_input_speed(prm, input.spec);
  input.input_torque = train.input_torque;
  parse_train_extras(prm, input);
  input.spec.pressure_angle = input.pressure_angle; // shifted gears' working centre distances
  input.initial_position = p.initial_position;
  if (input.spec.meshes.size() > max_train_meshes)
    throw InputError("Train/meshes", "at most " + std::to_string(max_train_meshes) +
                                         " meshes (sections 'Train mesh 1' ...)");
  std::vector<double> spec_damping_ratios; // per Train mesh, NaN: damping given
  for (std::size_t m = 0; m < input.spec.meshes.size(); ++m)
    spec_damping_ratios.push_back(parse_train_mesh(prm, m, iso_face_width, input, p));
  p.train_model = dynamics::build_train_model(input);
  p.train = p.train_model.train;
  expand_to_mesh_copies(spec_damping_ratios, p);
  p.published_reference = false;
  p.placement_angle.assign(p.train.meshes.size(), std::nan(""));
}
} // namespace gearstiff::app::dynamics_input
