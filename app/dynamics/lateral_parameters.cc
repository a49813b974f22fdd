#include "app/dynamics/lateral_parameters.h"

#include "app/core/units.h"
#include "app/dynamics/dynamics_parameters.h"
#include "app/dynamics/dynamics_parameters_internal.h"
#include "app/dynamics/train_parameter_entries.h"
#include "app/kinematics/kinematics_parameters.h"
#include "dynamics/train_model.h"
#include "errors/errors.h"
#include "errors/format.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace gearstiff::app
{
namespace
{
using dealii::ParameterHandler;
using NamedValues = std::map<std::string, std::vector<double>>;
using dynamics_input::iso_approximate_single_stiffness;
using dynamics_input::train_mesh_section;

// parse_named_numbers (any sign: the model names the parameter of a negative value; a name
// given twice refused) as a map.
NamedValues named_values(const std::string& text, unsigned int count, const std::string& parameter,
                         const std::string& units)
{
  NamedValues values;
  for (auto& [name, v] : parse_named_numbers(text, count, parameter, units, NumberSign::any))
    values.emplace(name, v);
  return values;
}

// The member `name`; InputError naming `parameter`, the list that named it, when there is none.
const kinematics::TrainMember& member(const kinematics::GearTrainSpec& spec,
                                      const std::string& name,
                                      const std::string& parameter = "Train/gears")
{
  for (const kinematics::TrainMember& m : spec.members)
    if (m.name == name)
      return m;
  throw InputError(parameter, "no member '" + name + "' (Train/gears, Train/carriers)");
}

// The lateral entries of the Train subsection, read and split into their lists.
struct LateralEntries
{
  double pressure_angle = 0.; // [rad]
  NamedValues bearings, dampings, pins, diameters, radii, angles, errors, suspensions;
};

LateralEntries read_lateral_entries(ParameterHandler& prm, LateralParameters& p)
{
  prm.enter_subsection("Train");
  LateralEntries e;
  e.pressure_angle = prm.get_double("pressure angle") * degree;
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

  e.bearings = named_values(bearing_text, 1, "Train/bearing stiffness", "k");
  e.dampings = named_values(damping_text, 1, "Train/bearing damping", "c");
  e.pins = named_values(pin_text, 1, "Train/planet pin stiffness", "k");
  e.diameters = named_values(diameter_text, 1, "Train/base diameters", "d");
  e.radii = named_values(radius_text, 1, "Train/carrier radii", "r");
  e.angles = named_values(angle_text, 0, "Train/planet angles", "psi1 psi2 ...");
  e.errors = named_values(error_text, 2, "Train/planet pin errors", "tangential radial");
  e.suspensions = named_values(suspended, 2, "Train/suspended members", "stiffness damping");
  return e;
}

// One planetary stage: one planet member on one carrier, meshing an external sun and an
// internal ring that turn about the housing's axis.
const kinematics::TrainMember& find_stage_members(const kinematics::GearTrainSpec& spec,
                                                  LateralParameters& p)
{
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
  return planet;
}

void check_member_lists(const kinematics::GearTrainSpec& spec, const LateralEntries& e,
                        const LateralParameters& p)
{
  for (const auto& [list, parameter] :
       {std::pair{&e.bearings, "Train/bearing stiffness"},
        std::pair{&e.dampings, "Train/bearing damping"}, std::pair{&e.radii, "Train/carrier radii"},
        std::pair{&e.diameters, "Train/base diameters"}})
    for (const auto& [name, v] : *list)
    {
      member(spec, name, parameter); // names a member
      if (v[0] < 0.)
        throw InputError(parameter, "'" + name + "' must not be negative");
    }
  // Entries of the planet alone: another name was ignored.
  for (const auto& [list, parameter] : {std::pair{&e.pins, "Train/planet pin stiffness"},
                                        std::pair{&e.angles, "Train/planet angles"}})
    for (const auto& [name, v] : *list)
      if (name != p.planet)
        throw InputError(parameter, "'" + name + "' is not the planet member '" + p.planet + "'");
  if (e.radii.size() > 1 || (e.radii.size() == 1 && !e.radii.count(p.carrier)))
    throw InputError("Train/carrier radii",
                     "names the carrier '" + p.carrier + "' alone (one stage)");
  auto central = [&](const std::string& name)
  { return name == p.sun || name == p.ring || name == p.carrier; };
  for (const auto& [name, c] : e.suspensions)
    if (!central(name))
      throw InputError("Train/suspended members", "'" + name + "' is not a central member");
  for (const auto& [name, v] : e.bearings)
    if (!central(name))
      throw InputError("Train/bearing stiffness",
                       "'" + name +
                           "': only sun, ring and carrier have bearings (planets: "
                           "Train/planet pin stiffness)");
}

double base_radius(const kinematics::GearTrainSpec& spec, const LateralEntries& e,
                   const std::string& name)
{
  const kinematics::TrainMember& m = member(spec, name);
  if (e.diameters.count(name))
    return 0.5 * e.diameters.at(name)[0] * mm;
  if (!(m.module > 0.))
    throw InputError("Train/base diameters",
                     "'" + name + "' needs a base diameter or a module (Train/modules)");
  return 0.5 * m.module * std::abs(m.teeth) * std::cos(e.pressure_angle);
}

dynamics::LateralCentralMember central_member(const kinematics::GearTrainSpec& spec,
                                              const LateralEntries& e, const std::string& name,
                                              double radius)
{
  auto value_or = [&](const NamedValues& list, double fallback)
  { return list.count(name) ? list.at(name)[0] : fallback; };
  const kinematics::TrainMember& m = member(spec, name);
  dynamics::LateralCentralMember c;
  c.mass = m.mass;
  c.moment_of_inertia = m.moment_of_inertia;
  c.radius = radius;
  c.bearing_stiffness = value_or(e.bearings, 0.);
  c.bearing_damping = value_or(e.dampings, 0.);
  const bool fixed = std::find(spec.fixed.begin(), spec.fixed.end(), name) != spec.fixed.end();
  if (e.suspensions.count(name))
  {
    if (!fixed)
      throw InputError("Train/suspended members", "'" + name + "' is not a fixed member");
    c.torsional_stiffness = e.suspensions.at(name)[0];
    c.torsional_damping = e.suspensions.at(name)[1];
  }
  else
    c.held = fixed;
  return c;
}

double carrier_radius(const kinematics::GearTrainSpec& spec, const LateralEntries& e,
                      const LateralParameters& p, const kinematics::TrainMember& planet)
{
  const kinematics::TrainMember& sun = member(spec, p.sun);
  if (e.radii.count(p.carrier))
    return e.radii.at(p.carrier)[0] * mm;
  if (sun.module > 0. && planet.module > 0.)
    return 0.5 * sun.module * (sun.teeth + planet.teeth);
  throw InputError("Train/carrier radii", "'" + p.carrier +
                                              "' needs its pin-circle radius "
                                              "(or the modules of sun and planet)");
}

// Planet copy of a pin-error entry: "k" or "planet#k", 1..n.
unsigned int pin_error_copy(const std::string& name, const std::string& planet, unsigned int n)
{
  const std::string copy = name.rfind(planet + "#", 0) == 0 ? name.substr(planet.size() + 1) : name;
  unsigned long k = 0;
  try
  {
    std::size_t used = 0;
    // Compared with n as read, not after a cast: 4294967297 cast to unsigned int was copy 1.
    k = std::stoul(copy, &used);
    if (used != copy.size() || copy.find_first_not_of("0123456789") != std::string::npos)
      k = 0;
  }
  catch (const std::exception&)
  {
    k = 0;
  }
  if (k < 1 || k > n)
    throw InputError("Train/planet pin errors",
                     "'" + name + "' is not a planet copy 1.." + std::to_string(n));
  return static_cast<unsigned int>(k);
}

void read_planet_layout(const LateralEntries& e, const kinematics::TrainMember& planet,
                        double backlash, dynamics::LateralStage& stage)
{
  const unsigned int n = planet.copies;
  stage.planet_angles = dynamics::equally_spaced_angles(n);
  if (e.angles.count(planet.name))
  {
    const std::vector<double>& psi = e.angles.at(planet.name);
    if (psi.size() != n)
      throw InputError("Train/planet angles", "'" + planet.name + "' has " + std::to_string(n) +
                                                  " copies, " + std::to_string(psi.size()) +
                                                  " angles given");
    for (unsigned int k = 0; k < n; ++k)
      stage.planet_angles[k] = psi[k] * degree;
  }
  if (e.errors.empty())
    return;
  stage.pin_error_tangential.assign(n, 0.);
  stage.pin_error_radial.assign(n, 0.);
  std::map<unsigned int, std::string> spelled; // copy → the entry that named it
  for (const auto& [name, v] : e.errors)
  {
    const unsigned int k = pin_error_copy(name, planet.name, n);
    // "p#2" and "2" are one copy: two entries for it would keep one silently.
    if (const auto [at, added] = spelled.emplace(k, name); !added)
      throw InputError("Train/planet pin errors", "'" + at->second + "' and '" + name +
                                                      "' name the same planet copy " +
                                                      std::to_string(k));
    stage.pin_error_tangential[k - 1] = v[0] * 1e-6;
    stage.pin_error_radial[k - 1] = v[1] * 1e-6;
    const double size = std::hypot(v[0], v[1]) * 1e-6;
    if (backlash > 0. && size > backlash)
      throw InputError("Train/planet pin errors", "the error of planet " + std::to_string(k) +
                                                      " (" + format_number(size * 1e6, 4) +
                                                      " µm) exceeds the backlash " +
                                                      format_number(backlash * 1e6, 4) +
                                                      " µm: the planet could not be assembled");
  }
}

// The pin circle and the backlash against the stage's gears. A planet's centre lies between
// the sun's and the ring's base circles (its meshes' centre distances exceed the base radii):
// a pin circle inside the sun (1 mm) gave modes, one beyond the ring (1 km) failed later naming
// Simulation/time step. (Lin & Parker's example: 38.7 < 88.4 < 137.5 mm.) A backlash of a base
// pitch or more leaves no tooth in the gap (1e12 µm was accepted).
void check_stage_sizes(const dynamics::LateralStage& stage, const kinematics::TrainMember& planet,
                       double backlash)
{
  const double r_c = stage.carrier.radius;
  if (!(r_c > stage.sun.radius && r_c < stage.ring.radius))
    throw InputError("Train/carrier radii",
                     "the pin circle " + format_mm(r_c) +
                         " must lie between the base radii of sun and ring (" +
                         format_mm(stage.sun.radius) + " and " + format_mm(stage.ring.radius) +
                         "): the planets sit between them");
  const double base_pitch = 2. * M_PI * stage.planet_base_radius / std::abs(planet.teeth);
  if (!(backlash < base_pitch))
    throw InputError("Train/backlash", "must be less than the planet's base pitch (" +
                                           format_number(base_pitch * 1e6, 4) +
                                           " µm): a gap of a pitch has no tooth in it");
}

void build_stage(const kinematics::GearTrainSpec& spec, const LateralEntries& e,
                 const kinematics::TrainMember& planet, LateralParameters& p)
{
  check_member_lists(spec, e, p);
  dynamics::LateralStage& stage = p.stage;
  stage.sun = central_member(spec, e, p.sun, base_radius(spec, e, p.sun));
  stage.ring = central_member(spec, e, p.ring, base_radius(spec, e, p.ring));
  stage.carrier = central_member(spec, e, p.carrier, carrier_radius(spec, e, p, planet));
  stage.planet_mass = planet.mass;
  stage.planet_moment_of_inertia = planet.moment_of_inertia;
  stage.planet_base_radius = base_radius(spec, e, planet.name);
  stage.planet_tip_radius =
      planet.module > 0. ? 0.5 * planet.module * (std::abs(planet.teeth) + 2) : 0.;
  if (!e.pins.count(planet.name))
    throw InputError("Train/planet pin stiffness",
                     "give the pin stiffness of '" + planet.name + "' (N/m)");
  stage.pin_stiffness = e.pins.at(planet.name)[0];
  stage.sun_pressure_angle = stage.ring_pressure_angle = e.pressure_angle;
  check_stage_sizes(stage, planet, p.backlash);
  read_planet_layout(e, planet, p.backlash, stage);
}

// Which gear drives in the carrier frame: the sun when its torque and its speed relative to the
// carrier have one sign (T_s·(ω_s − ω_c) > 0). With the ideal torque ratios of the stage
// (T_r = T_s·|z_r|/z_s, T_c = −(T_s + T_r)), T_s follows from the input torque.
bool sun_drives(const kinematics::GearTrainSpec& spec, const kinematics::TrainSolution& solution,
                const LateralParameters& p)
{
  const double ring_per_sun =
      std::abs(double(member(spec, p.ring).teeth)) / member(spec, p.sun).teeth;
  const double sun_per_input = p.load.input == dynamics::LateralMember::sun ? 1.
                               : p.load.input == dynamics::LateralMember::ring
                                   ? 1. / ring_per_sun
                                   : -1. / (1. + ring_per_sun);
  return sun_per_input * p.load.input_torque * (solution.speed(p.sun) - p.carrier_speed) > 0.;
}

// Whether Train mesh m+1 reads `stiffness = auto`.
bool automatic_stiffness_used(ParameterHandler& prm, unsigned int m)
{
  prm.enter_subsection(train_mesh_section(m));
  const bool automatic = prm.get("stiffness") == "auto";
  prm.leave_subsection();
  return automatic;
}

// damping = auto of Train mesh m+1 (issue 44: the lateral stage read it as no damping at all,
// so no speed sweep could settle): c = 2ζ·√(k·m_e), m_e = 1/(r_b,g²/J_g + r_b,p²/J_p) of the
// mesh's gears (a member without J adds nothing), as the train model's damping ratio does.
double automatic_damping(ParameterHandler& prm, unsigned int m, double stiffness,
                         const dynamics::LateralCentralMember& gear,
                         const dynamics::LateralStage& stage, LateralParameters& p)
{
  prm.enter_subsection(train_mesh_section(m));
  const bool automatic = prm.get("damping") == "auto";
  const double ratio = prm.get_double("damping ratio");
  prm.leave_subsection();
  if (!automatic)
    return 0.;
  double compliance = 0.; // Σ r_b²/J [1/kg]
  if (gear.moment_of_inertia > 0.)
    compliance += gear.radius * gear.radius / gear.moment_of_inertia;
  if (stage.planet_moment_of_inertia > 0.)
    compliance +=
        stage.planet_base_radius * stage.planet_base_radius / stage.planet_moment_of_inertia;
  if (!(compliance > 0.))
    throw InputError(train_mesh_section(m) + "/damping",
                     "auto needs the inertias of the mesh's gears (Train/inertias or a blank in "
                     "Train/face widths); or give the damping in N·s/m");
  const double damping = 2. * ratio * std::sqrt(stiffness / compliance);
  p.notes.push_back(train_mesh_section(m) + "/damping = " + format_number(damping, 5) +
                    " N·s/m (auto: ζ = " + format_number(ratio, 3) +
                    " of the mean stiffness and the gears' inertias)");
  return damping;
}

// Train/face widths and bore diameters: the J and mass of a member that Train/inertias and
// masses leave at 0 come from its steel blank, as in the train model (issue 44: "the mass of
// the ring must be positive (is 0)" although its blank was given). Returns the face widths [m].
std::map<std::string, double> apply_blanks(ParameterHandler& prm, kinematics::GearTrainSpec& spec,
                                           LateralParameters& p)
{
  prm.enter_subsection("Train");
  const std::string widths = prm.get("face widths"), bores = prm.get("bore diameters");
  const double density = prm.get_double("density");
  prm.leave_subsection();
  std::map<std::string, double> face_widths, bore_diameters;
  for (const auto& [name, v] : parse_named_numbers(widths, 1, "Train/face widths", "b"))
    face_widths[name] = v[0] * mm;
  for (const auto& [name, v] : parse_named_numbers(bores, 1, "Train/bore diameters", "d"))
  {
    if (!face_widths.count(name))
      throw InputError("Train/bore diameters", "'" + name + "' has no face width");
    bore_diameters[name] = v[0] * mm;
  }
  for (const auto& [name, width] : face_widths)
  {
    const auto m =
        std::find_if(spec.members.begin(), spec.members.end(),
                     [&, n = name](const kinematics::TrainMember& t) { return t.name == n; });
    if (m == spec.members.end())
      throw InputError("Train/face widths", "'" + name + "' is not a gear of the train");
    const dynamics::BlankInertia blank = dynamics::blank_inertia(
        *m, {name, width, bore_diameters.count(name) ? bore_diameters.at(name) : 0.}, density,
        "Train/bore diameters");
    if (!(m->moment_of_inertia > 0.))
      m->moment_of_inertia = blank.moment_of_inertia;
    if (!(m->mass > 0.))
      m->mass = blank.mass;
    p.notes.push_back("blank of " + name + ": J = " + format_number(m->moment_of_inertia, 6) +
                      " kg·m², m = " + format_number(m->mass, 6) + " kg (b = " +
                      format_number(width / mm, 5) + " mm; Train/inertias and masses win)");
  }
  return face_widths;
}

// Meshes: the mean stiffness of Train mesh 1 and 2 along the lines of action.
void read_meshes(ParameterHandler& prm, const kinematics::GearTrainSpec& spec,
                 const kinematics::TrainMember& planet, double pressure_angle, bool drives,
                 LateralParameters& p, const std::map<std::string, double>& face_widths = {})
{
  dynamics::LateralStage& stage = p.stage;
  prm.enter_subsection("ISO 6336");
  const double iso_face_width = prm.get_double("face width") * mm;
  prm.leave_subsection();
  for (std::size_t m = 0; m < spec.meshes.size(); ++m)
  {
    const kinematics::TrainMesh& mesh = spec.meshes[m];
    const std::string other = mesh.gear_a == planet.name ? mesh.gear_b : mesh.gear_a;
    const kinematics::TrainMember& gear = member(spec, other);
    const double contact_ratio =
        gear.module > 0. && planet.module > 0.
            ? dynamics::standard_mesh(gear, planet, pressure_angle, 0).contact_ratio
            : 1.5;
    const kinematics::TrainMember &a = member(spec, mesh.gear_a), &b = member(spec, mesh.gear_b);
    // stiffness = auto, as for a train mesh: ISO 6336-1's c' times the smaller face width of
    // the two gears (Train/face widths), else ISO 6336/face width.
    double width = 0.;
    for (const std::string& name : {mesh.gear_a, mesh.gear_b})
      if (face_widths.count(name) && (width == 0. || face_widths.at(name) < width))
        width = face_widths.at(name);
    const bool own_width = width > 0.;
    if (!own_width)
      width = iso_face_width;
    const TrainMeshMean mean = parse_train_mesh_mean(
        prm, m, contact_ratio, a.teeth, b.teeth, gear.module,
        gear.module > 0. ? kinematics::working_centre_distance(a, b, pressure_angle) : 0.,
        iso_approximate_single_stiffness * width);
    if (automatic_stiffness_used(prm, m))
      p.notes.push_back(
          "Train mesh " + std::to_string(m + 1) +
          "/stiffness = " + format_number(iso_approximate_single_stiffness * width / 1e6, 5) +
          " N/µm (auto: ISO 6336-1 c' = 14 N/(mm·µm) × b = " + format_number(width / mm, 5) +
          " mm from " + (own_width ? "Train/face widths" : "ISO 6336/face width") + ")");
    const bool sun = other == p.sun;
    // The FE pinion drove in the table; where the other gear drives here the contact runs the
    // path the other way: k(ε_α − x), and the TE likewise (the train model's rule).
    const std::string driver = (sun == drives) ? other : planet.name;
    const std::string fe_driver =
        mean.stiffness_driver ? (*mean.stiffness_driver == 0 ? mesh.gear_a : mesh.gear_b) : driver;
    TrainMeshMean law = mean;
    if (fe_driver != driver)
    {
      law.curve = law.curve.reversed(law.contact_ratio);
      if (law.nonlinear)
        law.nonlinear->transmission_error =
            law.nonlinear->transmission_error.reversed(law.contact_ratio);
      p.notes.push_back("Train mesh " + std::to_string(m + 1) + ": " + driver +
                        " drives, the FE table's pinion " + fe_driver +
                        " drove: k(x) and TE reversed along the path");
    }
    (sun ? p.excitation.sun_nonlinear : p.excitation.ring_nonlinear) = law.nonlinear;
    (sun ? p.excitation.sun_mesh : p.excitation.ring_mesh) = law.curve;
    (sun ? p.excitation.sun_contact_ratio : p.excitation.ring_contact_ratio) = mean.contact_ratio;
    (sun ? stage.sun_mesh_stiffness : stage.ring_mesh_stiffness) = mean.stiffness;
    (sun ? stage.sun_mesh_damping : stage.ring_mesh_damping) =
        mean.damping > 0.
            ? mean.damping
            : automatic_damping(prm, m, mean.stiffness, sun ? stage.sun : stage.ring, stage, p);
    p.notes.push_back("Train mesh " + std::to_string(m + 1) + " (" + other + "-" + planet.name +
                      "): " + mean.description);
  }
}

// Loads: the input torque on the input, the loss-free load on the output.
void read_loads(const kinematics::GearTrainSpec& spec, const kinematics::TrainSolution& solution,
                double input_torque, LateralParameters& p)
{
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
  p.load.input_torque = (p.input_speed >= 0. ? 1. : -1.) * input_torque;
  p.carrier_speed = solution.speed(p.carrier);
}

// The ring mesh of a planet after its sun mesh (Parker & Lin 2004, dynamics/README.md): with
// standard teeth (modules given) ε_f,r − ε_f,s + (z_p + 1)/2; without modules the approach
// ratios are unknown and only the (z_p + 1)/2 term is applied.
double ring_mesh_offset(const kinematics::GearTrainSpec& spec,
                        const kinematics::TrainSolution& solution, double pressure_angle,
                        LateralParameters& p)
{
  const kinematics::TrainMember& planet = member(spec, p.planet);
  const kinematics::TrainMember& sun = member(spec, p.sun);
  const kinematics::TrainMember& ring = member(spec, p.ring);
  const bool drives = sun_drives(spec, solution, p);
  double sun_approach = 0., ring_approach = 0.;
  if (sun.module > 0. && planet.module > 0. && ring.module > 0.)
  {
    sun_approach =
        dynamics::standard_mesh(sun, planet, pressure_angle, drives ? 0 : 1).approach_ratio;
    ring_approach =
        dynamics::standard_mesh(ring, planet, pressure_angle, drives ? 1 : 0).approach_ratio;
  }
  p.notes.push_back(std::string("sun/ring mesh phase of a planet (Parker & Lin 2004): ") +
                    (drives ? "sun drives the planets" : "the planets drive the sun") +
                    (ring_approach > 0.
                         ? ", approach ratios " + format_number(sun_approach, 5) + " (sun) and " +
                               format_number(ring_approach, 5) + " (ring)"
                         : ", no modules: approach ratios not applied"));
  return dynamics::planet_ring_mesh_offset(planet.teeth, sun_approach, ring_approach);
}

// Time response: each planet copy's meshes at their own phase. A copy at ψ meets a central
// gear g (z_g teeth, turning at ω_g − ω_c in the carrier frame) −sign(ω_g − ω_c)·|z_g|·ψ/2π
// base pitches later (the train model's placement rule, dynamics/README.md); its ring mesh runs
// ring_mesh_offset after its sun mesh.
void phase_meshes(const kinematics::GearTrainSpec& spec, const kinematics::TrainSolution& solution,
                  double pressure_angle, LateralParameters& p)
{
  const double relative_sun = solution.speed(p.sun) - p.carrier_speed;
  const double relative_ring = solution.speed(p.ring) - p.carrier_speed;
  const int sun_teeth = member(spec, p.sun).teeth, ring_teeth = member(spec, p.ring).teeth;
  p.ring_mesh_offset = ring_mesh_offset(spec, solution, pressure_angle, p);
  p.excitation.varying = true;
  p.excitation.mesh_frequency = std::abs(sun_teeth * relative_sun) / (2. * M_PI);
  for (const double psi : p.stage.planet_angles)
  {
    p.excitation.sun_phase.push_back(-(relative_sun >= 0. ? 1. : -1.) * std::abs(sun_teeth) * psi /
                                     (2. * M_PI));
    p.excitation.ring_phase.push_back(-(relative_ring >= 0. ? 1. : -1.) * std::abs(ring_teeth) *
                                          psi / (2. * M_PI) +
                                      p.ring_mesh_offset);
  }
  p.notes.push_back("time response: RK4, mesh frequency " +
                    format_number(p.excitation.mesh_frequency, 6) +
                    " Hz; planet copies phased by their angles, each ring mesh " +
                    format_number(p.ring_mesh_offset, 6) + " base pitches after its sun mesh");
}

void read_run_settings(ParameterHandler& prm, LateralParameters& p)
{
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
}
// Speed sweep over the input speed (Speed sweep section; the rotational sweep's entries).
void read_sweep_settings(ParameterHandler& prm, LateralParameters& p)
{
  prm.enter_subsection("Speed sweep");
  p.sweep_points = prm.get_integer("points");
  p.sweep_minimum_speed = prm.get_double("minimum speed") * rpm;
  p.sweep_maximum_speed = prm.get_double("maximum speed") * rpm;
  p.sweep.steps_per_mesh_period = prm.get_integer("steps per mesh period");
  const std::string direction = prm.get("direction");
  prm.leave_subsection();
  prm.enter_subsection("Simulation");
  p.sweep.settle_time = prm.get_double("steady state start");
  p.sweep.window_periods = prm.get_integer("window periods");
  prm.leave_subsection();
  if (p.sweep_points == 0)
    return;
  if (!(p.sweep_minimum_speed > 0. && p.sweep_maximum_speed >= p.sweep_minimum_speed))
    throw InputError("Speed sweep/maximum speed", "needs 0 < minimum speed <= maximum speed");
  p.sweep.direction = direction == "down"   ? dynamics::SweepDirection::down
                      : direction == "both" ? dynamics::SweepDirection::both
                                            : dynamics::SweepDirection::up;
  p.sweep.continuation = p.excitation.sun_nonlinear || p.excitation.ring_nonlinear;
  p.sweep.nominal_input_speed = p.input_speed;
  p.sweep.nominal_carrier_speed = p.carrier_speed;
  for (unsigned int i = 0; i < p.sweep_points; ++i)
    p.sweep.input_speeds.push_back(p.sweep_points == 1
                                       ? p.sweep_minimum_speed
                                       : p.sweep_minimum_speed +
                                             (p.sweep_maximum_speed - p.sweep_minimum_speed) * i /
                                                 (p.sweep_points - 1));
  // The input turns the way the description's input does.
  for (double& w : p.sweep.input_speeds)
    w *= p.input_speed >= 0. ? 1. : -1.;
}
} // namespace

void declare_lateral_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Train");
  declare_text_entries(
      prm,
      {{"bearing stiffness", "",
        "lateral model: radial bearing stiffness of sun, ring and carrier (several stages: any "
        "member on the main axis), the same in x and y, 'name: k, ...' [N/m]; a member not "
        "listed floats (0)"},
       {"bearing damping", "", "lateral model: bearing damping in x and y, 'name: c, ...' [N·s/m]"},
       {"planet pin stiffness", "",
        "lateral model: carrier pin stiffness of the planets, radial and tangential, "
        "'planet: k' [N/m]"},
       {"base diameters", "",
        "lateral model: base diameters in place of teeth and modules, 'name: d, ...' [mm]"},
       {"carrier radii", "",
        "lateral model: radius of the planet pin circle, 'carrier: r' [mm]; default the centre "
        "distance m·(z_s + z_p)/2"},
       {"planet angles", "",
        "lateral model: position angles of the planet copies on the carrier, "
        "'planet: psi1 psi2 ...' [deg]; default equally spaced"},
       {"planet pin errors", "",
        "lateral model: carrier pin position errors, 'copy: tangential radial, ...' (µm; copy = "
        "planet number 1..N or name#number; several stages: member#copy as the report lists the "
        "bodies; tangential in the sense of the planet angles, radial outwards)"}});
  prm.declare_entry("gyroscopic", "false", dealii::Patterns::Bool(),
                    "lateral model: Campbell chart over carrier speed with the rotating carrier "
                    "frame's gyroscopic and centripetal terms (Cooley & Parker 2012)");
  prm.declare_entry("backlash", "0", dealii::Patterns::Double(0.),
                    "lateral model: normal backlash of the meshes [µm] for the check of the pin "
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
  const LateralEntries entries = read_lateral_entries(prm, p);
  kinematics::GearTrainSpec spec = kinematics::parse_gear_train(train.text);
  spec.pressure_angle = entries.pressure_angle; // the working centre distances of shifted gears
  const std::map<std::string, double> face_widths = apply_blanks(prm, spec, p);
  const kinematics::TrainSolution solution = kinematics::solve_train_kinematics(spec);
  const kinematics::TrainMember& planet = find_stage_members(spec, p);
  build_stage(spec, entries, planet, p);
  read_loads(spec, solution, train.input_torque, p);
  read_meshes(prm, spec, planet, entries.pressure_angle, sun_drives(spec, solution, p), p,
              face_widths);
  phase_meshes(spec, solution, entries.pressure_angle, p);
  read_run_settings(prm, p);
  read_sweep_settings(prm, p);
  return p;
}

bool lateral_train_selected(ParameterHandler& prm)
{
  if (!lateral_model_selected(prm))
    return false;
  const kinematics::GearTrainSpec spec =
      kinematics::parse_gear_train(parse_train_parameters(prm).text);
  return std::count_if(spec.members.begin(), spec.members.end(),
                       [](const kinematics::TrainMember& m) { return !m.carrier.empty(); }) > 1;
}

namespace
{
std::map<std::string, double> first_values(const NamedValues& values, double unit)
{
  std::map<std::string, double> result;
  for (const auto& [name, v] : values)
    result[name] = v[0] * unit;
  return result;
}

void read_lateral_train_run(ParameterHandler& prm, LateralTrainParameters& p)
{
  prm.enter_subsection("Simulation");
  p.settle_time = std::max(0., prm.get_double("steady state start"));
  p.window_periods = prm.get_integer("window periods");
  prm.leave_subsection();
  prm.enter_subsection("Speed sweep");
  const unsigned int points = prm.get_integer("points");
  const double low = prm.get_double("minimum speed") * rpm;
  const double high = prm.get_double("maximum speed") * rpm;
  p.steps_per_mesh_period = prm.get_integer("steps per mesh period");
  prm.leave_subsection();
  if (points > 0 && !(low > 0. && high >= low))
    throw InputError("Speed sweep/maximum speed", "needs 0 < minimum speed <= maximum speed");
  for (unsigned int i = 0; i < points; ++i)
    p.sweep_speeds.push_back(points == 1 ? low : low + (high - low) * i / (points - 1));
}
// Train/planet pin errors on a train of several stages: 'body: tangential radial' [µm], the body
// named as the report lists it (member#copy, e.g. 2#1).
void set_pin_errors(const NamedValues& errors, dynamics::LateralTrain& train)
{
  for (const auto& [name, v] : errors)
  {
    const auto body =
        std::find_if(train.bodies.begin(), train.bodies.end(),
                     [&, n = name](const dynamics::LateralBody& b) { return b.name == n; });
    if (body == train.bodies.end() || body->carrier < 0)
      throw InputError("Train/planet pin errors",
                       "'" + name + "' is not a planet copy (member#copy, e.g. 2#1)");
    body->pin_error_tangential = v[0] * 1e-6;
    body->pin_error_radial = v[1] * 1e-6;
  }
}

// Settings of the one-stage lateral model that a train of several stages does not use: refused,
// not dropped. Its planets sit at the orbit radii of the kinematics (Train/modules): a carrier's
// radius only scaled its coordinate (0, −5, 1e9 gave the same modes).
void refuse_one_stage_settings(ParameterHandler& prm, const LateralEntries& e,
                               const LateralParameters& read)
{
  const std::string several = "not available for a train of several stages";
  if (!e.radii.empty())
    throw InputError("Train/carrier radii", several + " (the planets sit at the orbit radii "
                                                      "of their meshes, Train/modules)");
  if (read.backlash != 0.)
    throw InputError("Train/backlash", several + " (it checks one stage's pin errors)");
  if (read.gyroscopic)
    throw InputError("Train/gyroscopic", several + " (a carrier frame at rest)");
  prm.enter_subsection("Simulation");
  const bool nonlinear = prm.get("mesh model") == "nonlinear";
  prm.leave_subsection();
  if (nonlinear)
    throw InputError("Simulation/mesh model",
                     "nonlinear: " + several + " (linear meshes; nonlinear is one stage only)");
}
} // namespace

LateralTrainParameters parse_lateral_train_parameters(ParameterHandler& prm,
                                                      const dynamics::TrainModel& rotational)
{
  const TrainParameters train = parse_train_parameters(prm);
  LateralParameters unused;
  const LateralEntries e = read_lateral_entries(prm, unused);
  if (!e.angles.empty())
    throw InputError("Train/planet angles",
                     "not available for a train of several stages (equally spaced copies)");
  refuse_one_stage_settings(prm, e, unused);
  dynamics::LateralTrainInput input;
  input.train.spec = kinematics::parse_gear_train(train.text);
  input.train.spec.pressure_angle = e.pressure_angle;
  input.train.input_torque = train.input_torque;
  input.train.pressure_angle = e.pressure_angle;
  for (const auto& [name, v] : e.suspensions)
    input.train.suspensions.push_back({name, v[0], v[1]});
  input.bearing_stiffness = first_values(e.bearings, 1.);
  input.bearing_damping = first_values(e.dampings, 1.);
  input.pin_stiffness = first_values(e.pins, 1.);
  input.base_radius = first_values(e.diameters, 0.5 * mm);
  input.carrier_radius = first_values(e.radii, mm);
  LateralTrainParameters p;
  p.setup = dynamics::build_lateral_train(input, rotational);
  set_pin_errors(e.errors, p.setup.train);
  p.input_speed = std::abs(input.train.spec.inputs.front().second);
  read_lateral_train_run(prm, p);
  return p;
}
} // namespace gearstiff::app
