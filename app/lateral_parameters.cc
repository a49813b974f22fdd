#include "app/lateral_parameters.h"

#include "app/dynamics_parameters.h"
#include "app/kinematics_parameters.h"
#include "app/units.h"
#include "dynamics/train_model.h"
#include "errors/errors.h"
#include "errors/format.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace gearstiff::app
{
namespace
{
using dealii::ParameterHandler;
using dealii::Patterns::Anything;
using dealii::Patterns::Bool;
using dealii::Patterns::Double;

std::string trimmed(std::string text)
{
  text.erase(0, text.find_first_not_of(" \t"));
  text.erase(text.find_last_not_of(" \t") + 1);
  return text;
}

// "name: v1 v2 ..., ..." → name → numbers (any sign; `count` of them unless 0: one or more).
std::map<std::string, std::vector<double>> named_values(const std::string& text, unsigned int count,
                                                        const std::string& parameter,
                                                        const std::string& form)
{
  std::map<std::string, std::vector<double>> values;
  std::istringstream in(text);
  std::string entry;
  while (std::getline(in, entry, ','))
  {
    if (trimmed(entry).empty())
      continue;
    const auto colon = entry.find(':');
    const std::string name = colon == std::string::npos ? "" : trimmed(entry.substr(0, colon));
    std::istringstream numbers(colon == std::string::npos ? "" : entry.substr(colon + 1));
    std::vector<double> v;
    std::string word;
    bool good = !name.empty();
    while (good && numbers >> word)
    {
      try
      {
        std::size_t used = 0;
        v.push_back(std::stod(word, &used));
        good = used == word.size() && std::isfinite(v.back());
      }
      catch (const std::exception&)
      {
        good = false;
      }
    }
    if (!good || v.empty() || (count > 0 && v.size() != count) || values.count(name))
      throw InputError(parameter, "entry '" + trimmed(entry) + "' is not '" + form + "'");
    values[name] = v;
  }
  return values;
}

const kinematics::TrainMember& member(const kinematics::GearTrainSpec& spec,
                                      const std::string& name)
{
  for (const kinematics::TrainMember& m : spec.members)
    if (m.name == name)
      return m;
  throw InputError("Train/gears", "no member '" + name + "'");
}
} // namespace

void declare_lateral_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Train");
  prm.declare_entry("bearing stiffness", "", Anything(),
                    "lateral model: radial bearing stiffness of sun, ring and carrier, the same "
                    "in x and y, 'name: k, ...' (N/m); a member not listed floats (0)");
  prm.declare_entry("bearing damping", "", Anything(),
                    "lateral model: bearing damping in x and y, 'name: c, ...' (N·s/m)");
  prm.declare_entry("planet pin stiffness", "", Anything(),
                    "lateral model: carrier pin stiffness of the planets, radial and tangential, "
                    "'planet: k' (N/m)");
  prm.declare_entry("base diameters", "", Anything(),
                    "lateral model: base diameters in place of teeth and modules, 'name: d, ...' "
                    "(mm)");
  prm.declare_entry("carrier radii", "", Anything(),
                    "lateral model: radius of the planet pin circle, 'carrier: r' (mm); default "
                    "the centre distance m·(z_s + z_p)/2");
  prm.declare_entry("planet angles", "", Anything(),
                    "lateral model: position angles of the planet copies on the carrier, "
                    "'planet: psi1 psi2 ...' (degrees); default equally spaced");
  prm.declare_entry("planet pin errors", "", Anything(),
                    "lateral model: carrier pin position errors, 'copy: tangential radial, ...' "
                    "(µm; copy = planet number 1..N or name#number; tangential in the sense of "
                    "the planet angles, radial outwards)");
  prm.declare_entry("gyroscopic", "false", Bool(),
                    "lateral model: Campbell chart over carrier speed with the rotating carrier "
                    "frame's gyroscopic and centripetal terms (Cooley & Parker 2012)");
  prm.declare_entry("backlash", "0", Double(0.),
                    "lateral model: normal backlash of the meshes (µm) for the check of the pin "
                    "errors (0: not checked against it)");
  prm.leave_subsection();
}

bool lateral_model_selected(ParameterHandler& prm)
{
  prm.enter_subsection("Train");
  const bool lateral = prm.get("model") == "lateral";
  prm.leave_subsection();
  return lateral;
}

LateralParameters parse_lateral_parameters(ParameterHandler& prm)
{
  LateralParameters p;
  const TrainParameters train = parse_train_parameters(prm);
  const kinematics::GearTrainSpec spec = kinematics::parse_gear_train(train.text);
  const kinematics::TrainSolution solution = kinematics::solve_train_kinematics(spec);

  prm.enter_subsection("Train");
  const double pressure_angle = prm.get_double("pressure angle") * degree;
  const std::string suspended = prm.get("suspended members");
  const std::string bearing_text = prm.get("bearing stiffness");
  const std::string damping_text = prm.get("bearing damping");
  const std::string pin_text = prm.get("planet pin stiffness");
  const std::string diameter_text = prm.get("base diameters");
  const std::string radius_text = prm.get("carrier radii");
  const std::string angle_text = prm.get("planet angles");
  const std::string error_text = prm.get("planet pin errors");
  p.gyroscopic = prm.get_bool("gyroscopic");
  p.backlash = prm.get_double("backlash") * 1e-6;
  prm.leave_subsection();

  // One planetary stage: one planet member on one carrier, meshing an external sun and an
  // internal ring that turn about the housing's axis.
  std::vector<const kinematics::TrainMember*> planets;
  for (const kinematics::TrainMember& m : spec.members)
    if (!m.carrier.empty())
      planets.push_back(&m);
  if (planets.size() != 1)
    throw InputError("Train/model", "lateral: one planetary stage (one planet member on one "
                                    "carrier) only; the description has " +
                                        std::to_string(planets.size()) + " planet members");
  const kinematics::TrainMember& planet = *planets.front();
  p.planet = planet.name;
  p.carrier = planet.carrier;
  for (const kinematics::TrainMesh& mesh : spec.meshes)
  {
    if (mesh.gear_a != planet.name && mesh.gear_b != planet.name)
      throw InputError("Train/model", "lateral: mesh " + mesh.gear_a + "-" + mesh.gear_b +
                                          " does not involve the planets");
    const std::string other = mesh.gear_a == planet.name ? mesh.gear_b : mesh.gear_a;
    (member(spec, other).teeth > 0 ? p.sun : p.ring) = other;
  }
  if (p.sun.empty() || p.ring.empty() || spec.meshes.size() != 2)
    throw InputError("Train/model",
                     "lateral: a stage needs a sun-planet and a ring-planet mesh, nothing else");
  if (!spec.connections.empty())
    throw InputError("Train/model", "lateral: connections are not supported (one stage)");

  const auto bearings = named_values(bearing_text, 1, "Train/bearing stiffness", "name: k");
  const auto dampings = named_values(damping_text, 1, "Train/bearing damping", "name: c");
  const auto pins = named_values(pin_text, 1, "Train/planet pin stiffness", "planet: k");
  const auto diameters = named_values(diameter_text, 1, "Train/base diameters", "name: d");
  const auto radii = named_values(radius_text, 1, "Train/carrier radii", "carrier: r");
  const auto angles = named_values(angle_text, 0, "Train/planet angles", "planet: psi1 psi2 ...");
  const auto errors =
      named_values(error_text, 2, "Train/planet pin errors", "copy: tangential radial");
  std::map<std::string, std::vector<double>> suspensions;
  for (const auto& [name, v] :
       named_values(suspended, 2, "Train/suspended members", "name: stiffness damping"))
    suspensions[name] = v;
  for (const auto* list : {&bearings, &dampings, &diameters, &radii})
    for (const auto& [name, v] : *list)
    {
      member(spec, name); // names a member
      if (v[0] < 0.)
        throw InputError(list == &bearings   ? "Train/bearing stiffness"
                         : list == &dampings ? "Train/bearing damping"
                         : list == &radii    ? "Train/carrier radii"
                                             : "Train/base diameters",
                         "'" + name + "' must not be negative");
    }

  auto value_or = [](const std::map<std::string, std::vector<double>>& list,
                     const std::string& name, double fallback)
  { return list.count(name) ? list.at(name)[0] : fallback; };
  auto base_radius = [&](const std::string& name)
  {
    const kinematics::TrainMember& m = member(spec, name);
    if (diameters.count(name))
      return 0.5 * diameters.at(name)[0] * mm;
    if (!(m.module > 0.))
      throw InputError("Train/base diameters",
                       "'" + name + "' needs a base diameter or a module (Train/modules)");
    return 0.5 * m.module * std::abs(m.teeth) * std::cos(pressure_angle);
  };
  auto central = [&](const std::string& name, double radius)
  {
    const kinematics::TrainMember& m = member(spec, name);
    dynamics::LateralCentralMember c;
    c.mass = m.mass;
    c.moment_of_inertia = m.moment_of_inertia;
    c.radius = radius;
    c.bearing_stiffness = value_or(bearings, name, 0.);
    c.bearing_damping = value_or(dampings, name, 0.);
    const bool fixed = std::find(spec.fixed.begin(), spec.fixed.end(), name) != spec.fixed.end();
    if (suspensions.count(name))
    {
      if (!fixed)
        throw InputError("Train/suspended members", "'" + name + "' is not a fixed member");
      c.torsional_stiffness = suspensions.at(name)[0];
      c.torsional_damping = suspensions.at(name)[1];
    }
    else
      c.held = fixed;
    return c;
  };
  dynamics::LateralStage& stage = p.stage;
  stage.sun = central(p.sun, base_radius(p.sun));
  stage.ring = central(p.ring, base_radius(p.ring));
  const kinematics::TrainMember& sun = member(spec, p.sun);
  double carrier_radius = 0.;
  if (radii.count(p.carrier))
    carrier_radius = radii.at(p.carrier)[0] * mm;
  else if (sun.module > 0. && planet.module > 0.)
    carrier_radius = 0.5 * sun.module * (sun.teeth + planet.teeth);
  else
    throw InputError("Train/carrier radii", "'" + p.carrier +
                                                "' needs its pin-circle radius "
                                                "(or the modules of sun and planet)");
  stage.carrier = central(p.carrier, carrier_radius);
  for (const auto& [name, c] : suspensions)
    if (name != p.sun && name != p.ring && name != p.carrier)
      throw InputError("Train/suspended members", "'" + name + "' is not a central member");
  for (const auto& [name, v] : bearings)
    if (name != p.sun && name != p.ring && name != p.carrier)
      throw InputError("Train/bearing stiffness",
                       "'" + name +
                           "': only sun, ring and carrier have bearings (planets: "
                           "Train/planet pin stiffness)");

  stage.planet_mass = planet.mass;
  stage.planet_moment_of_inertia = planet.moment_of_inertia;
  stage.planet_base_radius = base_radius(planet.name);
  stage.planet_tip_radius =
      planet.module > 0. ? 0.5 * planet.module * (std::abs(planet.teeth) + 2) : 0.;
  if (!pins.count(planet.name))
    throw InputError("Train/planet pin stiffness",
                     "give the pin stiffness of '" + planet.name + "' (N/m)");
  stage.pin_stiffness = pins.at(planet.name)[0];
  stage.sun_pressure_angle = stage.ring_pressure_angle = pressure_angle;

  const unsigned int n = planet.copies;
  stage.planet_angles = dynamics::equally_spaced_angles(n);
  if (angles.count(planet.name))
  {
    const std::vector<double>& psi = angles.at(planet.name);
    if (psi.size() != n)
      throw InputError("Train/planet angles", "'" + planet.name + "' has " + std::to_string(n) +
                                                  " copies, " + std::to_string(psi.size()) +
                                                  " angles given");
    for (unsigned int k = 0; k < n; ++k)
      stage.planet_angles[k] = psi[k] * degree;
  }
  if (!errors.empty())
  {
    stage.pin_error_tangential.assign(n, 0.);
    stage.pin_error_radial.assign(n, 0.);
    for (const auto& [name, v] : errors)
    {
      const std::string copy =
          name.rfind(planet.name + "#", 0) == 0 ? name.substr(planet.name.size() + 1) : name;
      unsigned int k = 0;
      try
      {
        std::size_t used = 0;
        k = static_cast<unsigned int>(std::stoul(copy, &used));
        if (used != copy.size())
          k = 0;
      }
      catch (const std::exception&)
      {
        k = 0;
      }
      if (k < 1 || k > n)
        throw InputError("Train/planet pin errors",
                         "'" + name + "' is not a planet copy 1.." + std::to_string(n));
      stage.pin_error_tangential[k - 1] = v[0] * 1e-6;
      stage.pin_error_radial[k - 1] = v[1] * 1e-6;
      const double size = std::hypot(v[0], v[1]) * 1e-6;
      if (p.backlash > 0. && size > p.backlash)
        throw InputError("Train/planet pin errors", "the error of planet " + std::to_string(k) +
                                                        " (" + format_number(size * 1e6, 4) +
                                                        " µm) exceeds the backlash " +
                                                        format_number(p.backlash * 1e6, 4) +
                                                        " µm: the planet could not be assembled");
    }
  }

  // Meshes: the mean stiffness of Train mesh 1 and 2 along the lines of action.
  for (std::size_t m = 0; m < spec.meshes.size(); ++m)
  {
    const kinematics::TrainMesh& mesh = spec.meshes[m];
    const std::string other = mesh.gear_a == planet.name ? mesh.gear_b : mesh.gear_a;
    const kinematics::TrainMember& gear = member(spec, other);
    const double contact_ratio =
        gear.module > 0. && planet.module > 0.
            ? dynamics::standard_mesh(gear.teeth, planet.teeth, gear.module, pressure_angle, 0)
                  .contact_ratio
            : 1.5;
    const TrainMeshMean mean = parse_train_mesh_mean(prm, m, contact_ratio);
    (other == p.sun ? p.excitation.sun_mesh : p.excitation.ring_mesh) = mean.curve;
    (other == p.sun ? p.excitation.sun_contact_ratio : p.excitation.ring_contact_ratio) =
        mean.contact_ratio;
    (other == p.sun ? stage.sun_mesh_stiffness : stage.ring_mesh_stiffness) = mean.stiffness;
    (other == p.sun ? stage.sun_mesh_damping : stage.ring_mesh_damping) = mean.damping;
    p.notes.push_back("Train mesh " + std::to_string(m + 1) + " (" + other + "-" + planet.name +
                      "): " + mean.description);
  }

  // Loads: the input torque on the input, the loss-free load on the output.
  if (spec.inputs.size() != 1)
    throw InputError("Train/inputs", "the lateral model needs exactly one input");
  auto which = [&](const std::string& name, const std::string& parameter)
  {
    if (name == p.sun)
      return dynamics::LateralMember::sun;
    if (name == p.ring)
      return dynamics::LateralMember::ring;
    if (name == p.carrier)
      return dynamics::LateralMember::carrier;
    throw InputError(parameter, "'" + name + "' is not sun, ring or carrier");
  };
  p.load.input = which(spec.inputs.front().first, "Train/inputs");
  p.load.output = which(spec.output, "Train/output");
  p.input_speed = spec.inputs.front().second;
  p.load.input_torque = (p.input_speed >= 0. ? 1. : -1.) * train.input_torque;
  p.carrier_speed = solution.speed(p.carrier);

  // Time response: each planet copy's meshes at their own phase. A copy at ψ meets a central
  // gear g (z_g teeth, turning at ω_g − ω_c in the carrier frame) −sign(ω_g − ω_c)·|z_g|·ψ/2π
  // base pitches later (the train model's placement rule, dynamics/README.md); the sun and ring
  // meshes of one planet start in phase (the train model's (z_p + 1)/2 offset is not applied).
  const double relative_sun = solution.speed(p.sun) - p.carrier_speed;
  const double relative_ring = solution.speed(p.ring) - p.carrier_speed;
  p.excitation.varying = true;
  p.excitation.mesh_frequency = std::abs(sun.teeth * relative_sun) / (2. * M_PI);
  for (const double psi : stage.planet_angles)
  {
    p.excitation.sun_phase.push_back(-(relative_sun >= 0. ? 1. : -1.) * std::abs(sun.teeth) * psi /
                                     (2. * M_PI));
    p.excitation.ring_phase.push_back(-(relative_ring >= 0. ? 1. : -1.) *
                                      std::abs(member(spec, p.ring).teeth) * psi / (2. * M_PI));
  }
  p.notes.push_back("time response: RK4, mesh frequency " +
                    format_number(p.excitation.mesh_frequency, 6) +
                    " Hz; planet copies phased by their angles, sun and ring meshes of a planet "
                    "in phase");
  prm.enter_subsection("Simulation");
  p.run.time_step = prm.get_double("time step") * 1e-6;
  p.run.end_time = prm.get_double("simulated time");
  // 0: 'window periods' mesh periods (10 ms when the meshes do not turn).
  if (p.run.end_time == 0.)
    p.run.end_time = p.excitation.mesh_frequency > 0.
                         ? prm.get_integer("window periods") / p.excitation.mesh_frequency
                         : 0.01;
  p.run.start_static = prm.get("start") != "rest";
  p.run.allow_unstable_step = prm.get_bool("allow unstable step");
  prm.leave_subsection();
  if (!(p.run.time_step > 0.))
    throw InputError("Simulation/time step", "must be positive");
  const double steps = p.run.end_time / p.run.time_step;
  if (steps > 2e8)
    throw InputError("Simulation/simulated time",
                     "the run would need " + format_number(steps, 3) + " steps (limit 2e8)");
  // About 4000 recorded points whatever the span.
  p.run.record_stride = std::max(1u, static_cast<unsigned int>(steps / 4000.));
  return p;
}
} // namespace gearstiff::app
