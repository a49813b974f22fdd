#include "dynamics/train_model.h"

#include "dynamics/fields.h"
#include "errors/errors.h"
#include "errors/format.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>
#include <utility>

namespace gearstiff::dynamics
{
namespace
{
// The message numbers of errors/format.h, five significant digits unless told.
std::string format(double value, int digits = 5)
{
  return format_number(value, digits);
}

double fraction(double x)
{
  return x - std::floor(x);
}

// Rigid bodies of the train (members joined by connections), their copies and DOFs.
struct Bodies
{
  std::vector<std::size_t> body_of_member; // per member (housing last): body index
  std::vector<std::size_t> representative; // per body: first member
  std::vector<unsigned int> copies;        // per body
  std::vector<bool> fixed;                 // per body: holds a fixed member or the housing
  std::vector<int> first_dof;              // per body: first DOF, -1 when not a DOF
};

std::size_t find(std::vector<std::size_t>& parent, std::size_t i)
{
  while (parent[i] != i)
    i = parent[i] = parent[parent[i]];
  return i;
}

unsigned int member_copies(const kinematics::GearTrainSpec& spec, std::size_t i)
{
  return i < spec.members.size() ? spec.members[i].copies : 1u;
}

Bodies find_bodies(const kinematics::GearTrainSpec& spec, const kinematics::TrainSolution& solution)
{
  const std::size_t n = solution.names.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& [a, b] : spec.connections)
    parent[find(parent, solution.index(a))] = find(parent, solution.index(b));
  Bodies bodies;
  std::map<std::size_t, std::size_t> index;
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::size_t root = find(parent, i);
    if (!index.count(root))
    {
      index[root] = bodies.representative.size();
      bodies.representative.push_back(i);
      bodies.copies.push_back(member_copies(spec, i));
      bodies.fixed.push_back(false);
    }
    const std::size_t body = index[root];
    bodies.body_of_member.push_back(body);
    // Members rigid with a single member share its one rotation: the body has the fewest copies.
    bodies.copies[body] = std::min(bodies.copies[body], member_copies(spec, i));
  }
  for (std::size_t i = 0; i < n; ++i)
    if (member_copies(spec, i) % bodies.copies[bodies.body_of_member[i]] != 0)
      throw InputError(field::train("planets"),
                       "member '" + solution.names[i] + "' has " +
                           std::to_string(member_copies(spec, i)) +
                           " copies, not a multiple of the " +
                           std::to_string(bodies.copies[bodies.body_of_member[i]]) +
                           " of the members it is connected to");
  bodies.fixed[bodies.body_of_member[n - 1]] = true; // the housing
  for (const std::string& name : spec.fixed)
    bodies.fixed[bodies.body_of_member[solution.index(name)]] = true;
  return bodies;
}

// Copy k of member i → DOF, or -1 when its body does not move.
int dof_of(const Bodies& bodies, const kinematics::GearTrainSpec& spec, std::size_t member,
           unsigned int copy)
{
  const std::size_t body = bodies.body_of_member[member];
  if (bodies.first_dof[body] < 0)
    return -1;
  const unsigned int per_body = member_copies(spec, member) / bodies.copies[body];
  return bodies.first_dof[body] + static_cast<int>(copy / per_body);
}

void number_dofs(Bodies& bodies, const kinematics::TrainSolution& solution,
                 const std::vector<TrainSuspension>& suspensions, std::size_t input_body,
                 TrainModel& model)
{
  std::vector<bool> suspended(bodies.copies.size(), false);
  for (const TrainSuspension& s : suspensions)
  {
    if (std::find(solution.names.begin(), solution.names.end(), s.member) == solution.names.end())
      throw InputError(field::train("suspended_members"),
                       "unknown member '" + s.member + "' (declare it in gears or carriers)");
    const std::size_t body = bodies.body_of_member[solution.index(s.member)];
    if (!bodies.fixed[body] || s.member == kinematics::housing_name)
      throw InputError(field::train("suspended_members"),
                       "'" + s.member + "' is not a fixed member");
    suspended[body] = true;
  }
  bodies.first_dof.assign(bodies.copies.size(), -1);
  std::vector<std::size_t> order{input_body};
  for (std::size_t b = 0; b < bodies.copies.size(); ++b)
    if (b != input_body)
      order.push_back(b);
  int next = 0;
  for (const std::size_t b : order)
  {
    if (bodies.fixed[b] && !suspended[b])
      continue;
    bodies.first_dof[b] = next;
    for (unsigned int k = 0; k < bodies.copies[b]; ++k)
    {
      const std::string& name = solution.names[bodies.representative[b]];
      model.dof_names.push_back(bodies.copies[b] > 1 ? name + "#" + std::to_string(k + 1) : name);
      model.dof_body.push_back(name);
      ++next;
    }
  }
}

// Inertia of every DOF: the members' own J per copy, plus m·R² of every copy orbiting on it.
std::vector<double> dof_inertias(const kinematics::GearTrainSpec& spec,
                                 const kinematics::TrainSolution& solution, const Bodies& bodies,
                                 std::size_t n_dofs)
{
  std::vector<double> inertia(n_dofs, 0.);
  for (std::size_t i = 0; i < spec.members.size(); ++i)
  {
    const kinematics::TrainMember& member = spec.members[i];
    for (unsigned int k = 0; k < member.copies; ++k)
    {
      const int dof = dof_of(bodies, spec, i, k);
      if (dof >= 0)
        inertia[dof] += member.moment_of_inertia;
    }
    if (member.mass == 0.)
      continue;
    std::size_t current = i;
    for (unsigned int depth = 0; !spec.members[current].carrier.empty(); ++depth)
    {
      if (depth > spec.members.size())
        throw InputError(field::train("planets"), "carriers form a loop at '" + member.name + "'");
      const double radius = solution.orbit_radius[current];
      if (radius == 0.)
        throw InputError(field::train("modules"), "the orbit radius of '" +
                                                      spec.members[current].name +
                                                      "' is unknown: give the modules of its mesh");
      const std::size_t carrier = solution.index(spec.members[current].carrier);
      // Copy k of the member rides on copy k/(C_i/C_carrier) of its carrier.
      for (unsigned int k = 0; k < member.copies; ++k)
      {
        const unsigned int carrier_copy =
            k / (member.copies / std::max(1u, member_copies(spec, carrier)));
        const int dof = dof_of(bodies, spec, carrier, carrier_copy);
        if (dof >= 0)
          inertia[dof] += member.mass * radius * radius;
      }
      current = carrier;
      if (current == solution.names.size() - 1)
        break;
    }
  }
  return inertia;
}

double signed_base_radius(const kinematics::TrainMember& gear, double pressure_angle)
{
  return 0.5 * gear.module * gear.teeth * std::cos(pressure_angle);
}

// m* = J/r_b² [kg] of the rotation `dof` (one gear's, in one mesh), shared among the copies
// of the mesh that the same rotation carries (`copy_dofs`: its DOF in every copy); infinite
// when the gear does not turn (ISO 6336-1 6.5.9 for planetary gears: a fixed ring).
double shared_mass(int dof, double base_radius, const std::vector<double>& inertia,
                   const std::vector<int>& copy_dofs)
{
  if (dof < 0)
    return std::numeric_limits<double>::infinity();
  const auto shares = std::count(copy_dofs.begin(), copy_dofs.end(), dof);
  return inertia[dof] / (base_radius * base_radius) / static_cast<double>(shares);
}

TrainIsoPair iso_pair(const kinematics::TrainMember& gear_a, double ra, double rb,
                      double speed_ratio, const std::vector<double>& inertia,
                      const std::vector<std::array<int, 3>>& copy_dofs)
{
  std::vector<int> dofs_a, dofs_b;
  for (const auto& dofs : copy_dofs)
  {
    dofs_a.push_back(dofs[0]);
    dofs_b.push_back(dofs[1]);
  }
  const double ma = shared_mass(dofs_a.front(), ra, inertia, dofs_a);
  const double mb = shared_mass(dofs_b.front(), rb, inertia, dofs_b);
  TrainIsoPair pair;
  pair.pinion_teeth = static_cast<unsigned int>(std::abs(gear_a.teeth));
  pair.pinion_speed_ratio = speed_ratio;
  pair.reduced_mass = std::isinf(ma) ? mb : std::isinf(mb) ? ma : ma * mb / (ma + mb);
  pair.pinion_base_radius = std::abs(ra);
  return pair;
}

// Where the copies of a planet member sit around its carrier copy [rad]: equally spaced when the
// assembly condition allows it (Q/N whole, Q = |z_1 − z_2| of two central gears it meshes in
// that frame, signed z), otherwise at the nearest assemblable angles 2π·round(l·Q/N)/Q.
std::vector<double> planet_angles(const kinematics::GearTrainSpec& spec,
                                  const kinematics::TrainSolution& solution,
                                  const kinematics::TrainMember& planet, TrainModel& model)
{
  const unsigned int per_carrier =
      planet.copies / std::max(1u, member_copies(spec, solution.index(planet.carrier)));
  std::vector<int> central;
  for (const kinematics::TrainMesh& mesh : spec.meshes)
    if (mesh.frame == planet.carrier && (mesh.gear_a == planet.name || mesh.gear_b == planet.name))
    {
      const auto& other =
          spec.members[solution.index(mesh.gear_a == planet.name ? mesh.gear_b : mesh.gear_a)];
      if (other.carrier != planet.carrier)
        central.push_back(other.teeth);
    }
  std::vector<double> angles(per_carrier);
  const int q = central.size() >= 2 ? std::abs(central[0] - central[1]) : 0;
  const bool equal = q == 0 || q % static_cast<int>(per_carrier) == 0;
  for (unsigned int l = 0; l < per_carrier; ++l)
    angles[l] = equal ? 2. * M_PI * l / per_carrier
                      : 2. * M_PI * std::round(double(l) * q / per_carrier) / q;
  if (!equal)
  {
    std::string list;
    for (const double a : angles)
      list += (list.empty() ? "" : ", ") + format(a * 180. / M_PI, 6);
    model.notes.push_back(
        "planets " + planet.name + " on " + planet.carrier + ": " + std::to_string(per_carrier) +
        " copies cannot be equally spaced (assembly condition: " + std::to_string(q) + "/" +
        std::to_string(per_carrier) + " is not whole); placed at " + list + " deg");
  }
  return angles;
}
} // namespace

BlankInertia blank_inertia(const kinematics::TrainMember& gear, const GearBlank& blank,
                           double density, const std::string& parameter)
{
  const double reference = gear.module * std::abs(gear.teeth);
  if (gear.teeth == 0 || !(gear.module > 0.))
    throw InputError(parameter, "'" + gear.name +
                                    "' needs teeth and a module for its blank (carriers: give "
                                    "Train/inertias)");
  const double inner = gear.teeth > 0 ? blank.bore_diameter : reference;
  const double outer = gear.teeth > 0 ? reference : blank.bore_diameter;
  if (!(outer > inner) || inner < 0.)
    throw InputError(parameter, "'" + gear.name + "': " +
                                    (gear.teeth > 0 ? "the bore must lie inside"
                                                    : "an internal gear needs an outer "
                                                      "diameter beyond") +
                                    " the reference diameter " + format(reference * 1e3) + " mm");
  const double area = M_PI / 4. * (outer * outer - inner * inner);
  return {density * blank.face_width * area * (outer * outer + inner * inner) / 8.,
          density * blank.face_width * area};
}

StandardMesh standard_mesh(const kinematics::TrainMember& a, const kinematics::TrainMember& b,
                           double pressure_angle, unsigned int driver)
{
  // Signed pitch radii r = m·z/2 (an internal gear's negative), base radii r·cos α; tips
  // r + m(1 + x) signed as the gear-pair module writes them (an internal tip lies inside).
  const double module = a.module;
  const double working_angle =
      std::acos(0.5 * module * std::abs(a.teeth + b.teeth) * std::cos(pressure_angle) /
                kinematics::working_centre_distance(a, b, pressure_angle));
  auto tip_length = [&](const kinematics::TrainMember& g) // base tangency to the tip circle
  {
    const double radius = 0.5 * module * g.teeth;
    const double tip = radius + module * (1. + g.profile_shift); // d_a = d + 2m(1 + x), signed
    const double base = radius * std::cos(pressure_angle);
    return std::sqrt(std::max(0., tip * tip - base * base));
  };
  auto pitch_length = [&](const kinematics::TrainMember& g)
  { return 0.5 * module * std::abs(g.teeth) * std::cos(pressure_angle) * std::tan(working_angle); };
  const double base_pitch = M_PI * module * std::cos(pressure_angle);
  // Addendum path of each gear beyond the pitch point (an internal gear's lies before it).
  auto addendum_path = [&](const kinematics::TrainMember& g)
  { return g.teeth > 0 ? tip_length(g) - pitch_length(g) : pitch_length(g) - tip_length(g); };
  StandardMesh mesh;
  mesh.contact_ratio = (addendum_path(a) + addendum_path(b)) / base_pitch;
  // Contact starts where the driven gear's tip cuts the line of action.
  mesh.approach_ratio = addendum_path(driver == 0 ? b : a) / base_pitch;
  return mesh;
}

namespace
{
// The spec with the blanks' J and mass where Train/inertias and Train/masses give none.
kinematics::GearTrainSpec with_blank_inertias(const TrainDynamicsInput& input,
                                              std::vector<std::string>& notes)
{
  kinematics::GearTrainSpec spec = input.spec;
  for (const GearBlank& blank : input.blanks)
  {
    const auto member =
        std::find_if(spec.members.begin(), spec.members.end(),
                     [&](const kinematics::TrainMember& m) { return m.name == blank.member; });
    if (member == spec.members.end())
      throw InputError(field::train("face_widths"),
                       "'" + blank.member + "' is not a gear of the train");
    const BlankInertia blank_values =
        blank_inertia(*member, blank, input.density, field::train("bore_diameters"));
    const bool given_j = member->moment_of_inertia > 0., given_m = member->mass > 0.;
    if (!given_j)
      member->moment_of_inertia = blank_values.moment_of_inertia;
    if (!given_m)
      member->mass = blank_values.mass;
    notes.push_back("blank of " + blank.member + ": J = " + format(member->moment_of_inertia, 6) +
                    " kg·m²" + (given_j ? " (given)" : "") + ", m = " + format(member->mass, 6) +
                    " kg" + (given_m ? " (given)" : "") + " (ρ = " + format(input.density, 6) +
                    " kg/m³, b = " + format(blank.face_width * 1e3) + " mm)");
  }
  return spec;
}

// What the steps of build_train_model pass on to each other.
struct TrainBuild
{
  explicit TrainBuild(const TrainDynamicsInput& input)
      : input(input), spec(with_blank_inertias(input, model.notes)),
        solution(kinematics::solve_train_kinematics(spec))
  {
  }
  const TrainDynamicsInput& input;
  TrainModel model; // declared before spec: the blanks' notes go into it
  kinematics::GearTrainSpec spec;
  kinematics::TrainSolution solution;
  Bodies bodies;
  double input_speed = 0.;                   // [rad/s] signed speed of the input member
  std::vector<double> inertia;               // [kg·m²] per DOF
  std::vector<std::array<int, 3>> mesh_dofs; // per model mesh: DOF of a, b, frame (-1: still)
  std::vector<double> forces;                // [N] per model mesh: static force, unoriented
  std::vector<int> a_drives;                 // per Train mesh: 1 when gear a drives
};

// Bodies and DOFs, their inertias and speed ratios, the input torque and the output's load,
// suspensions and the reduced inertia J*.
void add_gears(TrainBuild& build)
{
  const kinematics::GearTrainSpec& spec = build.spec;
  const kinematics::TrainSolution& solution = build.solution;
  TrainModel& model = build.model;
  const TrainDynamicsInput& input = build.input;
  if (spec.inputs.size() != 1 || spec.output.empty())
    throw InputError(field::train("inputs"), "the dynamics needs exactly one input and an output");
  if (input.meshes.size() != spec.meshes.size())
    throw InputError(input.mesh_section, "one set of mesh data per Train mesh is needed");
  Bodies& bodies = build.bodies;
  bodies = find_bodies(spec, solution);
  const std::size_t input_member = solution.index(spec.inputs.front().first);
  const std::size_t input_body = bodies.body_of_member[input_member];
  if (bodies.fixed[input_body] || bodies.copies[input_body] != 1)
    throw InputError(field::train("inputs"), "the input must be a single member that turns");
  number_dofs(bodies, solution, input.suspensions, input_body, model);
  const std::size_t n_dofs = model.dof_names.size();
  const double input_speed = build.input_speed = spec.inputs.front().second;

  GearTrain& train = model.train;
  train.input_speed = std::abs(input_speed);
  const std::vector<double>& inertia = build.inertia = dof_inertias(spec, solution, bodies, n_dofs);
  train.speed_ratios.resize(n_dofs);
  for (std::size_t b = 0; b < bodies.copies.size(); ++b)
    for (unsigned int k = 0; bodies.first_dof[b] >= 0 && k < bodies.copies[b]; ++k)
      train.speed_ratios[bodies.first_dof[b] + k] =
          solution.speeds[bodies.representative[b]] / std::abs(input_speed);
  for (std::size_t i = 0; i < n_dofs; ++i)
  {
    if (!(inertia[i] > 0.))
      throw InputError(field::train("inertias"),
                       "'" + model.dof_names[i] +
                           "' has zero inertia: give J of its members (Train/inertias) or the "
                           "masses of planets riding on it");
    train.gears.push_back({model.dof_names[i], inertia[i], 0.});
  }
  // Input torque on the input (in its running sense), the loss-free load on the output.
  const std::size_t output_member = solution.index(spec.output);
  const int output_dof = dof_of(bodies, spec, output_member, 0);
  if (output_dof < 0 || bodies.copies[bodies.body_of_member[output_member]] != 1)
    throw InputError(field::train("output"), "the output must be a single member that turns");
  const double input_sign = input_speed > 0. ? 1. : -1.;
  train.gears[0].torque = input_sign * input.input_torque;
  train.gears[output_dof].torque -=
      input_sign * input.input_torque * train.speed_ratios[0] / train.speed_ratios[output_dof];
  for (const TrainSuspension& s : input.suspensions)
    train.suspensions.push_back(
        {static_cast<unsigned int>(dof_of(bodies, spec, solution.index(s.member), 0)), s.stiffness,
         s.damping});

  model.reduced_inertia = kinematics::reduced_moment_of_inertia(
      kinematics::inertia_terms(spec, solution, spec.inputs.front().first));
}

// Meshes, one per copy: terms, speeds, stiffness. Contact ratio first (needed for the mean
// stiffness); the approach ratio, force sign and phase follow the static solution.
void add_meshes(TrainBuild& build)
{
  const kinematics::GearTrainSpec& spec = build.spec;
  const kinematics::TrainSolution& solution = build.solution;
  TrainModel& model = build.model;
  const TrainDynamicsInput& input = build.input;
  for (std::size_t m = 0; m < spec.meshes.size(); ++m)
  {
    const kinematics::TrainMesh& tm = spec.meshes[m];
    const std::size_t a = solution.index(tm.gear_a), b = solution.index(tm.gear_b),
                      c = solution.index(tm.frame);
    const kinematics::TrainMember& gear_a = spec.members[a];
    const kinematics::TrainMember& gear_b = spec.members[b];
    if (!(gear_a.module > 0. && gear_b.module > 0.))
      throw InputError(field::train("modules"),
                       "mesh " + tm.gear_a + "-" + tm.gear_b +
                           " needs the modules of both gears (base radii)");
    const unsigned int copies =
        std::max({member_copies(spec, a), member_copies(spec, b), member_copies(spec, c)});
    for (const std::size_t i : {a, b, c})
      if (copies % member_copies(spec, i) != 0)
        throw InputError(field::train("planets"), "mesh " + tm.gear_a + "-" + tm.gear_b + "/" +
                                                      tm.frame +
                                                      ": copies of its members do not divide");
    // A whole-revolution table (docs/faults.md) follows one faulty tooth through one pair; the
    // copies of a planetary mesh meet that tooth at different times, which one table with one
    // phase per copy does not say.
    if (copies > 1 && input.meshes[m].stiffness.period() > 1)
      throw InputError(input.mesh_section + " " + std::to_string(m + 1) + "/stiffness file",
                       "a whole-revolution table (period " +
                           std::to_string(input.meshes[m].stiffness.period()) +
                           " base pitches) on mesh " + tm.gear_a + "-" + tm.gear_b +
                           ", which has " + std::to_string(copies) +
                           " copies (planets): the copies' phases over a revolution are not "
                           "modelled; use it on a mesh of one pair");
    const double ra = signed_base_radius(gear_a, input.pressure_angle);
    const double rb = signed_base_radius(gear_b, input.pressure_angle);
    const StandardMesh geometry = standard_mesh(gear_a, gear_b, input.pressure_angle, 0);
    const double contact_ratio = input.meshes[m].contact_ratio.value_or(geometry.contact_ratio);
    model.spec_mesh_contact_ratio.push_back(contact_ratio);
    for (unsigned int j = 0; j < copies; ++j)
    {
      Mesh mesh;
      mesh.name = tm.gear_a + "-" + tm.gear_b + (copies > 1 ? "#" + std::to_string(j + 1) : "");
      std::map<unsigned int, double> coefficient;
      const std::pair<std::size_t, double> members[3] = {{a, ra}, {b, rb}, {c, -(ra + rb)}};
      std::array<int, 3> dofs;
      for (unsigned int k = 0; k < 3; ++k)
      {
        const auto& [member, r] = members[k];
        dofs[k] = dof_of(build.bodies, spec, member, j / (copies / member_copies(spec, member)));
        if (dofs[k] >= 0)
          coefficient[dofs[k]] += r;
      }
      build.mesh_dofs.push_back(dofs);
      for (const auto& [dof, r] : coefficient)
        mesh.terms.push_back({dof, r, 0.});
      mesh.position_ratio = std::abs(gear_a.teeth) *
                            std::abs(solution.speeds[a] - solution.speeds[c]) /
                            (2. * M_PI * std::abs(build.input_speed));
      mesh.contact_ratio = contact_ratio;
      mesh.stiffness = input.meshes[m].stiffness;
      mesh.damping = input.meshes[m].damping;
      mesh.friction_coefficient = input.meshes[m].friction_coefficient;
      mesh.table_force = input.meshes[m].table_force;
      mesh.driver_friction_arm = input.meshes[m].driver_friction_arm;
      mesh.driven_friction_arm = input.meshes[m].driven_friction_arm;
      mesh.nonlinear = input.meshes[m].nonlinear;
      model.train.meshes.push_back(mesh);
      model.spec_mesh.push_back(m);
      model.mesh_copy.push_back(j);
    }
    model.spec_mesh_iso.push_back(
        iso_pair(gear_a, ra, rb,
                 std::abs(solution.speeds[a] - solution.speeds[c]) / std::abs(build.input_speed),
                 build.inertia, {build.mesh_dofs.end() - copies, build.mesh_dofs.end()}));
  }
}

// The model before orientation, for the meshes' static forces. Its refusals name the model's
// gears and meshes by number ("gear3.inertia", "mesh2.damping"), which no input of the caller
// spells (the model's numbering exists only once it is built): they are named as the input they
// came from, the train's inertias and the data of the Train mesh a model mesh copies.
TorsionalModel preliminary_model(const TrainBuild& build)
{
  const GearTrain& train = build.model.train;
  try
  {
    return TorsionalModel(train);
  }
  catch (const InputError& e)
  {
    for (unsigned int i = 0; i < train.gears.size(); ++i)
      if (e.parameter() == field::train_gear(i, "inertia"))
        throw InputError(field::train("inertias"), "'" + train.gears[i].name + "': " + e.reason());
    for (unsigned int m = 0; m < train.meshes.size(); ++m)
      for (std::string member : field::gear_mesh_fields())
        if (e.parameter() == field::gear_mesh(m, member))
        {
          std::replace(member.begin(), member.end(), '_', ' ');
          throw InputError(build.input.mesh_section + " " +
                               std::to_string(build.model.spec_mesh[m] + 1) + "/" + member,
                           "'" + train.meshes[m].name + "': " + e.reason());
        }
    throw;
  }
}

// Load direction: orient every mesh so its static force is positive (K_v = F/F_nominal), then
// the driver in the frame's reference is the gear the mesh draws power from; an FE table
// computed with the other gear driving is reversed (contact runs the other way).
void orient_meshes(TrainBuild& build)
{
  const kinematics::GearTrainSpec& spec = build.spec;
  const kinematics::TrainSolution& solution = build.solution;
  TrainModel& model = build.model;
  GearTrain& train = model.train;
  {
    const TorsionalModel preliminary = preliminary_model(build);
    build.forces.resize(train.meshes.size());
    for (std::size_t i = 0; i < build.forces.size(); ++i)
      build.forces[i] = preliminary.nominal_force(i);
  }
  build.a_drives.assign(spec.meshes.size(), -1);
  for (std::size_t i = 0; i < train.meshes.size(); ++i)
  {
    Mesh& mesh = train.meshes[i];
    const std::size_t m = model.spec_mesh[i];
    const kinematics::TrainMesh& tm = spec.meshes[m];
    const double sign = build.forces[i] < 0. ? -1. : 1.;
    for (MeshTerm& term : mesh.terms)
      term.coefficient *= sign;
    if (build.a_drives[m] < 0)
    {
      // Torque of the mesh on gear a: −s·r_a·F; power out of a in the frame: s·r_a·F·(ω_a − ω_c).
      const double ra = sign * signed_base_radius(spec.members[solution.index(tm.gear_a)],
                                                  build.input.pressure_angle);
      const double relative = solution.speed(tm.gear_a) - solution.speed(tm.frame);
      build.a_drives[m] = ra * relative >= 0. ? 1 : 0;
    }
  }
  for (std::size_t i = 0; i < train.meshes.size(); ++i)
  {
    const std::size_t m = model.spec_mesh[i];
    const std::optional<unsigned int>& fe_driver = build.input.meshes[m].stiffness_driver;
    if (fe_driver && (*fe_driver == 0) != (build.a_drives[m] == 1))
    {
      const double contact_ratio = model.spec_mesh_contact_ratio[m];
      train.meshes[i].stiffness = build.input.meshes[m].stiffness.reversed(contact_ratio);
      if (std::optional<NonlinearMesh>& nonlinear = train.meshes[i].nonlinear)
      {
        nonlinear->transmission_error = nonlinear->transmission_error.reversed(contact_ratio);
        if (nonlinear->back_stiffness)
          nonlinear->back_stiffness = nonlinear->back_stiffness->reversed(contact_ratio);
      }
    }
  }
}

// Approach ratios per Train mesh (the driven gear's tip starts the contact).
void add_approach_ratios(TrainBuild& build)
{
  const kinematics::GearTrainSpec& spec = build.spec;
  TrainModel& model = build.model;
  for (std::size_t m = 0; m < spec.meshes.size(); ++m)
  {
    const kinematics::TrainMesh& tm = spec.meshes[m];
    const TrainMeshDynamics& data = build.input.meshes[m];
    if (data.approach_ratio && data.stiffness_driver)
    {
      // The FE pair's own path: driven the other way, contact starts at the other end (E), so
      // the approach becomes the FE recess ε_α − ε_f.
      const bool fe_pinion_drives = (*data.stiffness_driver == 0) == (build.a_drives[m] == 1);
      model.spec_mesh_approach_ratio.push_back(fe_pinion_drives ? *data.approach_ratio
                                                                : model.spec_mesh_contact_ratio[m] -
                                                                      *data.approach_ratio);
      continue;
    }
    const auto& gear_a = spec.members[build.solution.index(tm.gear_a)];
    const auto& gear_b = spec.members[build.solution.index(tm.gear_b)];
    model.spec_mesh_approach_ratio.push_back(
        standard_mesh(gear_a, gear_b, build.input.pressure_angle, build.a_drives[m] ? 0 : 1)
            .approach_ratio);
  }
}

// Sun–planet and ring–planet meshes of one planet (Parker & Lin 2004; README): with standard
// teeth the ring mesh runs ε_f,r − ε_f,s + (z_p + 1)/2 base pitches after the sun mesh; other
// meshes start at 0. Per Train mesh [base pitches].
std::vector<double> ring_mesh_phases(const TrainBuild& build)
{
  const kinematics::GearTrainSpec& spec = build.spec;
  const kinematics::TrainSolution& solution = build.solution;
  std::vector<double> phase(spec.meshes.size(), 0.);
  for (std::size_t m = 0; m < spec.meshes.size(); ++m)
  {
    const kinematics::TrainMesh& tm = spec.meshes[m];
    for (const std::string& planet_name : {tm.gear_a, tm.gear_b})
    {
      const auto& planet = spec.members[solution.index(planet_name)];
      const auto& central =
          spec.members[solution.index(planet_name == tm.gear_a ? tm.gear_b : tm.gear_a)];
      if (planet.carrier != tm.frame || central.carrier == tm.frame || central.teeth > 0)
        continue;
      for (std::size_t s = 0; s < spec.meshes.size(); ++s)
      {
        const kinematics::TrainMesh& ts = spec.meshes[s];
        const bool has_planet = ts.gear_a == planet_name || ts.gear_b == planet_name;
        const std::string other = ts.gear_a == planet_name ? ts.gear_b : ts.gear_a;
        if (s == m || ts.frame != tm.frame || !has_planet ||
            spec.members[solution.index(other)].teeth < 0)
          continue;
        phase[m] = fraction(build.model.spec_mesh_approach_ratio[m] -
                            build.model.spec_mesh_approach_ratio[s] + 0.5 * (planet.teeth + 1));
        break;
      }
    }
  }
  return phase;
}

// Friction arms (torsional_model.h) of model mesh i: each gear's arm with the sign of its
// (oriented) coefficient, the frame takes minus their sum.
void set_friction_arms(const TrainBuild& build, std::size_t i, Mesh& mesh)
{
  const std::size_t m = build.model.spec_mesh[i];
  const kinematics::TrainMesh& tm = build.spec.meshes[m];
  const double orientation = build.forces[i] < 0. ? -1. : 1.;
  const bool a_drives = build.a_drives[m] == 1;
  const double arm_a = a_drives ? mesh.driver_friction_arm : mesh.driven_friction_arm;
  const double arm_b = a_drives ? mesh.driven_friction_arm : mesh.driver_friction_arm;
  const std::size_t a = build.solution.index(tm.gear_a), b = build.solution.index(tm.gear_b);
  const double pressure_angle = build.input.pressure_angle;
  const double signed_a =
      (orientation * signed_base_radius(build.spec.members[a], pressure_angle) > 0. ? 1. : -1.) *
      arm_a;
  const double signed_b =
      (orientation * signed_base_radius(build.spec.members[b], pressure_angle) > 0. ? 1. : -1.) *
      arm_b;
  const std::array<double, 3> arms = {signed_a, signed_b, -(signed_a + signed_b)};
  for (MeshTerm& term : mesh.terms)
  {
    term.friction_arm = 0.;
    for (unsigned int k = 0; k < 3; ++k)
      if (build.mesh_dofs[i][k] == static_cast<int>(term.dof))
        term.friction_arm += arms[k];
  }
}

// Approach ratio, friction arms and initial position of every model mesh. Copy phase: planet
// copy at angle ψ on its carrier, central gear g turning at ω_g − ω_c in the frame:
// x = x_0 − sign(ω_g − ω_c)·|z_g|·ψ/2π (docs/references.md §1's placement rule).
void set_arms_and_phases(TrainBuild& build)
{
  const kinematics::GearTrainSpec& spec = build.spec;
  const kinematics::TrainSolution& solution = build.solution;
  TrainModel& model = build.model;
  const std::vector<double> base_phase = ring_mesh_phases(build);
  std::map<std::string, std::vector<double>> angles;
  for (std::size_t i = 0; i < model.train.meshes.size(); ++i)
  {
    Mesh& mesh = model.train.meshes[i];
    const std::size_t m = model.spec_mesh[i];
    const kinematics::TrainMesh& tm = spec.meshes[m];
    mesh.approach_ratio = model.spec_mesh_approach_ratio[m];
    set_friction_arms(build, i, mesh);
    double phase = base_phase[m];
    for (const std::string& planet_name : {tm.gear_a, tm.gear_b})
    {
      const auto& planet = spec.members[solution.index(planet_name)];
      const std::string central_name = planet_name == tm.gear_a ? tm.gear_b : tm.gear_a;
      const auto& central = spec.members[solution.index(central_name)];
      if (planet.carrier != tm.frame || central.carrier == tm.frame || planet.copies < 2)
        continue;
      if (!angles.count(planet_name))
        angles[planet_name] = planet_angles(spec, solution, planet, model);
      const std::vector<double>& psi = angles[planet_name];
      const double psi_copy = psi[model.mesh_copy[i] % psi.size()];
      const double relative = solution.speed(central_name) - solution.speed(tm.frame);
      phase -= (relative >= 0. ? 1. : -1.) * std::abs(central.teeth) * psi_copy / (2. * M_PI);
    }
    mesh.initial_position = fraction(build.input.initial_position + phase);
  }
}
} // namespace

TrainModel build_train_model(const TrainDynamicsInput& input)
{
  TrainBuild build(input);
  add_gears(build);
  add_meshes(build);
  orient_meshes(build);
  add_approach_ratios(build);
  set_arms_and_phases(build);
  return std::move(build.model);
}

Eigen::MatrixXd modal_energy_distribution(const TorsionalModel& model,
                                          const std::vector<unsigned int>& group_of_dof,
                                          unsigned int n_groups)
{
  const ModeShapes modes = model.mode_shapes();
  const Eigen::VectorXd& inertia = model.inertias();
  Eigen::MatrixXd share = Eigen::MatrixXd::Zero(modes.shapes.cols(), n_groups);
  for (Eigen::Index k = 0; k < modes.shapes.cols(); ++k)
  {
    const Eigen::VectorXd v = modes.shapes.col(k);
    const double total = v.cwiseProduct(inertia).dot(v);
    for (Eigen::Index i = 0; i < v.size(); ++i)
      share(k, group_of_dof[i]) += inertia[i] * v[i] * v[i] / total;
  }
  return share;
}
} // namespace gearstiff::dynamics
