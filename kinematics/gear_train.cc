#include "kinematics/gear_train.h"

#include "errors/errors.h"
#include "errors/format.h"
#include "errors/limits.h"
#include "kinematics/fields.h"
#include "kinematics/gear_pair.h"
#include "kinematics/gear_train_internal.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace gearstiff::kinematics
{
using namespace train_internal;

namespace
{
constexpr double rpm = 3.14159265358979323846 / 30.; // rad/s per rpm
// -, |teeth| of a train gear: the bound of `gearstiff dynamics`' driver teeth; beyond it no
// gear, and an int holds the count.
constexpr int max_gear_teeth = 10000;

std::string trim(const std::string& text)
{
  const auto first = text.find_first_not_of(" \t\n");
  if (first == std::string::npos)
    return "";
  const auto last = text.find_last_not_of(" \t\n");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> split(const std::string& text, char separator)
{
  std::vector<std::string> parts;
  std::string part;
  std::istringstream stream(text);
  while (std::getline(stream, part, separator))
    parts.push_back(trim(part));
  if (!parts.empty() && parts.back().empty() && !text.empty() && text.back() == separator)
    parts.pop_back();
  return parts;
}

void check_name(const std::string& name, const std::string& parameter)
{
  if (name.empty())
    throw InputError(parameter, "an entry has an empty member name");
  for (const char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_'))
      throw InputError(parameter,
                       "member name '" + name + "' may hold only letters, digits and '_'");
}

double parse_number(const std::string& text, const std::string& parameter)
{
  // The whole text a finite number: strtod's range error is std::stod's out_of_range.
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  if (end == begin || end != begin + text.size() || errno == ERANGE || !std::isfinite(value))
    throw InputError(parameter, "'" + text + "' is not a number");
  return value;
}

// "name: value, name: value" → pairs; an empty string gives none.
std::vector<std::pair<std::string, std::string>> parse_assignments(const std::string& text,
                                                                   const std::string& key)
{
  const std::string parameter = field::train(key);
  std::vector<std::pair<std::string, std::string>> entries;
  if (trim(text).empty())
    return entries;
  for (const std::string& entry : split(text, ','))
  {
    const auto colon = entry.find(':');
    if (colon == std::string::npos)
      throw InputError(parameter, "entry '" + entry + "' is not of the form name: value");
    const std::string name = trim(entry.substr(0, colon));
    check_name(name, parameter);
    entries.emplace_back(name, trim(entry.substr(colon + 1)));
  }
  return entries;
}

std::vector<std::string> parse_names(const std::string& text, const std::string& key)
{
  std::vector<std::string> names;
  if (trim(text).empty())
    return names;
  for (const std::string& name : split(text, ','))
  {
    check_name(name, field::train(key));
    names.push_back(name);
  }
  return names;
}

// Every gear of a mesh either rides on the mesh's frame (a planet of that frame) or shares the
// frame's own axis (it rides where the frame rides: both on the housing, or both on the same
// carrier). Anything else puts the gear's axis somewhere the frame cannot hold it, and its
// copies would be lost (issue 11: "4: 1*9" with meshes on H). Copies need a carrier to ride on.
void check_mesh_frames(const GearTrainSpec& spec, const TrainSolution& solution)
{
  auto carrier_of = [&](const std::string& name)
  { return name == housing_name ? std::string() : member_of(spec, solution, name).carrier; };
  for (const TrainMesh& mesh : spec.meshes)
    for (const std::string& name : {mesh.gear_a, mesh.gear_b})
    {
      const std::string& carrier = member_of(spec, solution, name).carrier;
      if (carrier == mesh.frame || carrier == carrier_of(mesh.frame))
        continue;
      const std::string frame_axis =
          carrier_of(mesh.frame).empty() ? "the housing" : carrier_of(mesh.frame);
      throw InputError(field::train("planets"),
                       "gear '" + name + "' rides on " +
                           (carrier.empty() ? std::string("the housing") : "'" + carrier + "'") +
                           " but its mesh " + mesh.gear_a + "-" + mesh.gear_b + "/" + mesh.frame +
                           " needs it on the frame '" + mesh.frame + "' (a planet) or on " +
                           frame_axis + " (coaxial with the frame)");
    }
  for (const TrainMember& member : spec.members)
    if (member.copies > 1 && member.carrier.empty())
      throw InputError(field::train("planets"), "member '" + member.name + "' has " +
                                                    std::to_string(member.copies) +
                                                    " copies but no carrier to ride on");
}

void check_members(const GearTrainSpec& spec)
{
  std::set<std::string> seen;
  for (const TrainMember& member : spec.members)
  {
    if (member.name == housing_name)
      throw InputError(field::train("gears"), "'housing' is reserved for the fixed frame");
    if (!seen.insert(member.name).second)
      throw InputError(field::train("gears"), "member '" + member.name + "' is declared twice");
    if (member.teeth != 0 && std::abs(member.teeth) < 3)
      throw InputError(field::train("gears"), "gear '" + member.name + "' has " +
                                                  std::to_string(member.teeth) +
                                                  " teeth; at least 3 are needed");
    if (member.copies == 0)
      throw InputError(field::train("planets"), "member '" + member.name + "' has zero copies");
    if (member.module < 0. || member.mass < 0. || member.moment_of_inertia < 0.)
      throw InputError(field::train("modules"),
                       "member '" + member.name + "' has a negative module, mass or inertia");
  }
}

void require_member(const TrainSolution& solution, const std::string& name, const std::string& key)
{
  if (std::find(solution.names.begin(), solution.names.end(), name) == solution.names.end())
    throw InputError(field::train(key), "unknown member '" + name + "'");
}

// Every member named by a carrier, connection, fixed member, input or the output exists.
void check_references(const GearTrainSpec& spec, const TrainSolution& solution)
{
  for (const TrainMember& member : spec.members)
    if (!member.carrier.empty())
    {
      require_member(solution, member.carrier, "planets");
      if (member.carrier == member.name)
        throw InputError(field::train("planets"), "'" + member.name + "' cannot carry itself");
    }
  for (const auto& [a, b] : spec.connections)
  {
    require_member(solution, a, "connections");
    require_member(solution, b, "connections");
  }
  for (const std::string& name : spec.fixed)
    require_member(solution, name, "fixed");
  for (const auto& input : spec.inputs)
    require_member(solution, input.first, "inputs");
  if (!spec.output.empty())
    require_member(solution, spec.output, "output");
}

// A mesh joins two distinct toothed gears of one module, at most one of them internal (and then
// the larger), on a third member as its frame.
void check_mesh(const GearTrainSpec& spec, const TrainSolution& solution, const TrainMesh& mesh)
{
  require_member(solution, mesh.gear_a, "meshes");
  require_member(solution, mesh.gear_b, "meshes");
  require_member(solution, mesh.frame, "meshes");
  if (mesh.gear_a == mesh.gear_b || mesh.frame == mesh.gear_a || mesh.frame == mesh.gear_b)
    throw InputError(field::train("meshes"), "mesh " + mesh.gear_a + "-" + mesh.gear_b + "/" +
                                                 mesh.frame + " names a member twice");
  for (const std::string& name : {mesh.gear_a, mesh.gear_b})
    if (name == housing_name || member_of(spec, solution, name).teeth == 0)
      throw InputError(field::train("meshes"), "'" + name + "' in mesh " + mesh.gear_a + "-" +
                                                   mesh.gear_b +
                                                   " has no teeth (list it in gears)");
  const TrainMember& a = member_of(spec, solution, mesh.gear_a);
  const TrainMember& b = member_of(spec, solution, mesh.gear_b);
  if (a.teeth < 0 && b.teeth < 0)
    throw InputError(field::train("meshes"),
                     "two internal gears " + a.name + " and " + b.name + " cannot mesh");
  const TrainMember& inner = a.teeth < 0 ? b : a;
  const TrainMember& outer = a.teeth < 0 ? a : b;
  if (outer.teeth < 0 && -outer.teeth <= inner.teeth)
    throw InputError(field::train("gears"),
                     "internal gear " + outer.name + " (" + std::to_string(-outer.teeth) +
                         " teeth) must have more teeth than " + inner.name + " (" +
                         std::to_string(inner.teeth) + ") that runs inside it");
  if (a.module > 0. && b.module > 0. && std::abs(a.module - b.module) > 1e-12)
    throw InputError(field::train("modules"),
                     "gears " + a.name + " and " + b.name + " mesh but have different modules");
}

// Orbit radii: a planet's axis sits at the centre distance from its central mate, which
// shares the frame's axis. Two meshes giving two radii mean the train does not close.
void set_orbit_radii(const GearTrainSpec& spec, TrainSolution& solution)
{
  const std::size_t n = solution.names.size();
  solution.orbit_radius.assign(n, 0.);
  solution.mesh_copies.assign(spec.meshes.size(), 1);
  for (std::size_t m = 0; m < spec.meshes.size(); ++m)
  {
    const TrainMesh& mesh = spec.meshes[m];
    if (mesh.frame == housing_name)
      continue;
    const TrainMember& a = member_of(spec, solution, mesh.gear_a);
    const TrainMember& b = member_of(spec, solution, mesh.gear_b);
    const bool a_planet = a.carrier == mesh.frame;
    const bool b_planet = b.carrier == mesh.frame;
    if (a_planet == b_planet)
      continue; // both central (a fixed-axis pair on a carrier) or planet-planet
    const TrainMember& planet = a_planet ? a : b;
    const TrainMember& central = a_planet ? b : a;
    solution.mesh_copies[m] = planet.copies;
    if (planet.teeth < 0)
      throw InputError(field::train("planets"), "planet " + planet.name + " is an internal gear");
    if (planet.module == 0. || central.module == 0.)
      continue;
    const double radius = working_centre_distance(central, planet, spec.pressure_angle);
    double& known = solution.orbit_radius[solution.index(planet.name)];
    if (known > 0. && std::abs(known - radius) > 1e-9)
      throw InputError(field::train("gears"),
                       "the train does not close: planet " + planet.name + " sits " +
                           format_number(known * 1e3, 5) + " mm from the axis of " + mesh.frame +
                           " by one mesh and " + format_number(radius * 1e3, 5) + " mm by mesh " +
                           mesh.gear_a + "-" + mesh.gear_b);
    known = radius;
  }
  // Members rigid with a planet and riding on the same carrier share its axis.
  RigidBodies bodies(spec, solution);
  for (std::size_t i = 0; i + 1 < n; ++i)
    for (std::size_t j = 0; j + 1 < n; ++j)
      if (solution.orbit_radius[i] == 0. && solution.orbit_radius[j] > 0. &&
          bodies.find(i) == bodies.find(j) && !spec.members[i].carrier.empty() &&
          spec.members[i].carrier == spec.members[j].carrier)
        solution.orbit_radius[i] = solution.orbit_radius[j];
}

// Checks names, tooth counts and module agreement; fills orbit radii and mesh copies.
void check_structure(const GearTrainSpec& spec, TrainSolution& solution)
{
  check_members(spec);
  solution.names.clear();
  for (const TrainMember& member : spec.members)
    solution.names.push_back(member.name);
  solution.names.push_back(housing_name);
  check_references(spec, solution);
  for (const TrainMesh& mesh : spec.meshes)
    check_mesh(spec, solution, mesh);
  check_mesh_frames(spec, solution);
  set_orbit_radii(spec, solution);
}
} // namespace

std::size_t TrainSolution::index(const std::string& member) const
{
  const auto found = std::find(names.begin(), names.end(), member);
  if (found == names.end())
    throw InputError(field::train_members, "unknown member '" + member + "'");
  return static_cast<std::size_t>(found - names.begin());
}

double TrainSolution::speed(const std::string& member) const
{
  return speeds[index(member)];
}

namespace
{
// The speed equations: the structural rows (Willis per mesh, connections, fixed members, the
// housing) first, then one row per input speed.
struct SpeedEquations
{
  Eigen::MatrixXd matrix;
  Eigen::VectorXd right_hand_side; // rad/s
  std::size_t structural_rows = 0;
};

SpeedEquations speed_equations(const GearTrainSpec& spec, const TrainSolution& solution)
{
  const std::size_t n = solution.names.size();
  const std::size_t housing = n - 1;
  std::vector<Eigen::VectorXd> rows;
  auto unit_row = [&](std::size_t member)
  {
    Eigen::VectorXd row = Eigen::VectorXd::Zero(n);
    row[member] = 1.;
    return row;
  };
  for (const TrainMesh& mesh : spec.meshes)
  {
    // Willis: z_a·(ω_a − ω_c) + z_b·(ω_b − ω_c) = 0, signed z.
    const std::size_t a = solution.index(mesh.gear_a);
    const std::size_t b = solution.index(mesh.gear_b);
    const std::size_t c = solution.index(mesh.frame);
    Eigen::VectorXd row = Eigen::VectorXd::Zero(n);
    row[a] += spec.members[a].teeth;
    row[b] += spec.members[b].teeth;
    row[c] -= spec.members[a].teeth + spec.members[b].teeth;
    rows.push_back(row);
  }
  for (const auto& [a, b] : spec.connections)
    rows.push_back(unit_row(solution.index(a)) - unit_row(solution.index(b)));
  for (const std::string& name : spec.fixed)
    rows.push_back(unit_row(solution.index(name)));
  rows.push_back(unit_row(housing));
  SpeedEquations equations;
  equations.structural_rows = rows.size();
  for (const auto& input : spec.inputs)
    rows.push_back(unit_row(solution.index(input.first)));

  equations.matrix.resize(rows.size(), n);
  equations.right_hand_side = Eigen::VectorXd::Zero(rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r)
    equations.matrix.row(r) = rows[r].transpose();
  for (std::size_t k = 0; k < spec.inputs.size(); ++k)
    equations.right_hand_side[equations.structural_rows + k] = spec.inputs[k].second;
  return equations;
}

// The inputs leave members free: names them (those the kernel of the equations moves).
[[noreturn]] void throw_under_constrained(const GearTrainSpec& spec, const TrainSolution& solution,
                                          const Eigen::FullPivLU<Eigen::MatrixXd>& full)
{
  const Eigen::MatrixXd kernel = full.kernel();
  std::string free_members;
  for (std::size_t i = 0; i < solution.names.size(); ++i)
    if (kernel.row(i).norm() > 1e-9)
      free_members += (free_members.empty() ? "" : ", ") + solution.names[i];
  throw InputError(field::train("inputs"),
                   "under-constrained: the train has " +
                       std::to_string(solution.degrees_of_freedom) + " degree(s) of freedom but " +
                       std::to_string(spec.inputs.size()) +
                       " input(s) fix fewer; undetermined: " + free_members);
}
} // namespace

TrainSolution solve_train_kinematics(const GearTrainSpec& spec)
{
  TrainSolution solution;
  check_structure(spec, solution);
  if (spec.inputs.empty())
    throw InputError(field::train("inputs"), "no input speed given");

  const std::size_t n = solution.names.size();
  const SpeedEquations equations = speed_equations(spec, solution);
  const Eigen::MatrixXd& matrix = equations.matrix;
  const Eigen::VectorXd& right_hand_side = equations.right_hand_side;

  // Tooth counts are integers of order 100: a relative pivot threshold of 1e-10 separates
  // true rank deficiency from rounding by many orders of magnitude.
  Eigen::FullPivLU<Eigen::MatrixXd> structure(matrix.topRows(equations.structural_rows));
  structure.setThreshold(1e-10);
  solution.degrees_of_freedom = static_cast<unsigned int>(n - structure.rank());

  Eigen::FullPivLU<Eigen::MatrixXd> full(matrix);
  full.setThreshold(1e-10);
  if (full.rank() < static_cast<Eigen::Index>(n))
    throw_under_constrained(spec, solution, full);
  const Eigen::VectorXd speeds = full.solve(right_hand_side);
  const double scale = std::max(1., right_hand_side.cwiseAbs().maxCoeff());
  if ((matrix * speeds - right_hand_side).norm() > 1e-9 * scale)
  {
    if (solution.degrees_of_freedom == 0)
      throw InputError(field::train("meshes"),
                       "over-constrained: meshes, connections and fixed members lock the "
                       "train (it does not close with any motion)");
    throw InputError(field::train("inputs"),
                     "over-constrained: " + std::to_string(spec.inputs.size()) +
                         " input speeds contradict a train with " +
                         std::to_string(solution.degrees_of_freedom) + " degree(s) of freedom");
  }
  solution.speeds.assign(speeds.data(), speeds.data() + n);
  // A member that stands (a fixed ring, what is joined to it) came out as the LU's round-off
  // ("speed of member r: -1.44751e-13 rpm" for an own planetary stage): it stands.
  for (double& speed : solution.speeds)
    if (std::abs(speed) < 1e-12 * scale)
      speed = 0.;
  if (!spec.output.empty())
  {
    const double output_speed = solution.speed(spec.output);
    if (std::abs(output_speed) < 1e-12 * scale)
      throw InputError(field::train("output"), "'" + spec.output + "' does not turn");
    solution.ratio = spec.inputs.front().second / output_speed;
  }
  return solution;
}

double pair_efficiency(int teeth_a, int teeth_b, double tooth_friction)
{
  return 1. - 2.3 * tooth_friction * std::abs(1. / teeth_a + 1. / teeth_b);
}

double epicyclic_efficiency(double base_ratio, double base_efficiency)
{
  return (1. - base_ratio * base_efficiency) / (1. - base_ratio);
}

CarrierMethodEfficiency carrier_method_efficiency(const GearTrainSpec& spec, double tooth_friction)
{
  if (spec.fixed.size() != 1 || spec.inputs.size() != 1 || spec.output.empty())
    throw InputError(field::train("fixed"), "the carrier method needs one fixed member, one input "
                                            "and an output carrier");
  if (std::none_of(spec.meshes.begin(), spec.meshes.end(),
                   [&](const TrainMesh& mesh) { return mesh.frame == spec.output; }))
    throw InputError(field::train("output"), "the carrier method needs the output to be a carrier");
  const TrainSolution solution = solve_train_kinematics(spec);
  const std::string& fixed = spec.fixed.front();
  const double carrier_speed = solution.speed(spec.output);
  const double input_speed = spec.inputs.front().second;

  GearTrainSpec base = spec;
  base.fixed = {spec.output};
  base.output = fixed;
  base.inputs = {{spec.inputs.front().first, input_speed - carrier_speed}};
  const TrainSolution base_solution = solve_train_kinematics(base);

  CarrierMethodEfficiency result;
  result.base_ratio = (input_speed - carrier_speed) / (0. - carrier_speed);
  result.base_efficiency = solve_train_statics(base, base_solution, 1., tooth_friction).efficiency;
  result.efficiency = epicyclic_efficiency(result.base_ratio, result.base_efficiency);
  return result;
}

double reduced_moment_of_inertia(const std::vector<InertiaTerm>& terms)
{
  double sum = 0.;
  for (const InertiaTerm& term : terms)
    sum += term.copies * (term.moment_of_inertia * term.speed_ratio * term.speed_ratio +
                          term.mass * term.velocity_ratio * term.velocity_ratio);
  return sum;
}

std::vector<InertiaTerm> inertia_terms(const GearTrainSpec& spec, const TrainSolution& solution,
                                       const std::string& member)
{
  const double reference = solution.speed(member);
  if (reference == 0.)
    throw InputError(field::train("reduce_inertia_to"), "'" + member + "' does not turn");
  std::vector<InertiaTerm> terms;
  for (std::size_t i = 0; i < spec.members.size(); ++i)
  {
    const TrainMember& body = spec.members[i];
    if (body.moment_of_inertia == 0. && body.mass == 0.)
      continue;
    InertiaTerm term;
    term.member = body.name;
    term.moment_of_inertia = body.moment_of_inertia;
    term.mass = body.mass;
    term.copies = body.copies;
    term.speed_ratio = solution.speeds[i] / reference;
    // Centre speed² = Σ over the carrier chain (ω_carrier·R)²; cross terms cancel between
    // equally spaced copies and average out over a turn for a single one.
    double velocity_squared = 0.;
    std::size_t current = i;
    for (unsigned int depth = 0; !spec.members[current].carrier.empty(); ++depth)
    {
      if (depth > spec.members.size())
        throw InputError(field::train("planets"), "carriers form a loop at '" + body.name + "'");
      const double radius = solution.orbit_radius[current];
      if (radius == 0. && body.mass > 0.)
        throw InputError(field::train("modules"), "the orbit radius of '" +
                                                      spec.members[current].name +
                                                      "' is unknown: give the modules of its mesh");
      const std::size_t carrier = solution.index(spec.members[current].carrier);
      velocity_squared += std::pow(solution.speeds[carrier] * radius, 2);
      if (carrier == solution.names.size() - 1)
        break;
      current = carrier;
    }
    term.velocity_ratio = std::sqrt(velocity_squared) / std::abs(reference);
    terms.push_back(term);
  }
  return terms;
}

double milev_planetary_inertia(double sun_radius, double planet_radius, unsigned int planets,
                               double carrier_thickness_ratio)
{
  const double a = sun_radius, c = planet_radius, k = carrier_thickness_ratio;
  return std::pow(a, 4) / 2. + planets * (2. * a * a * c * c + a * a * std::pow(a + c, 2)) / 4. +
         std::pow(a + c, 4) * a * a / (4. * k * c * c);
}

namespace
{
// The members of a spec being parsed, by name.
class MemberTable
{
public:
  explicit MemberTable(GearTrainSpec& spec) : spec(spec) {}
  bool has(const std::string& name) const { return index.count(name) > 0; }
  // The member of that name, declared now if it is new.
  TrainMember& declare(const std::string& name)
  {
    if (!index.count(name))
    {
      index[name] = spec.members.size();
      spec.members.push_back(TrainMember());
      spec.members.back().name = name;
    }
    return spec.members[index[name]];
  }
  // A member already declared in gears or carriers (else an InputError naming Train/<key>).
  TrainMember& existing(const std::string& name, const std::string& key)
  {
    if (!index.count(name))
      throw InputError(field::train(key),
                       "unknown member '" + name + "' (declare it in gears or carriers)");
    return spec.members[index[name]];
  }

private:
  GearTrainSpec& spec;
  std::map<std::string, std::size_t> index;
};

void parse_gears_and_carriers(const GearTrainText& text, MemberTable& members)
{
  for (const auto& [name, value] : parse_assignments(text.gears, "gears"))
  {
    const double teeth = parse_number(value, field::train("gears"));
    // Bounded before the cast to int (1e20 overflowed it); as `dynamics`' driver teeth.
    if (teeth == 0. || teeth != std::round(teeth) || std::abs(teeth) > max_gear_teeth)
      throw InputError(field::train("gears"), "gear '" + name +
                                                  "' needs a non-zero whole number of "
                                                  "teeth (negative: internal) up to " +
                                                  std::to_string(max_gear_teeth) +
                                                  " in size, got " + value);
    if (members.has(name))
      throw InputError(field::train("gears"), "gear '" + name + "' is listed twice");
    members.declare(name).teeth = static_cast<int>(teeth);
  }
  for (const std::string& name : parse_names(text.carriers, "carriers"))
  {
    if (members.has(name))
      throw InputError(field::train("carriers"), "'" + name + "' is already a gear");
    members.declare(name);
  }
}

// "name: carrier*copies" (copies 1 when left out).
void parse_planets(const std::string& text, MemberTable& members)
{
  for (const auto& [name, value] : parse_assignments(text, "planets"))
  {
    const auto star = value.find('*');
    const std::string carrier = trim(value.substr(0, star));
    check_name(carrier, field::train("planets"));
    TrainMember& planet = members.existing(name, "planets");
    members.existing(carrier, "planets");
    planet.carrier = carrier;
    if (star == std::string::npos)
      continue;
    const double copies = parse_number(trim(value.substr(star + 1)), field::train("planets"));
    if (!(copies >= 1.) || copies != std::round(copies))
      throw InputError(field::train("planets"),
                       "copies of '" + name + "' must be a whole number ≥ 1");
    // Before any member is allocated per copy (2·10⁹ copies filled 24 GB).
    if (copies > limits::max_train_members)
      throw InputError(field::train("planets"),
                       "'" + name + "' has " + trim(value.substr(star + 1)) +
                           " copies, more than the " + std::to_string(limits::max_train_members) +
                           " members a train model holds (limit, docs/limits.md; a planetary "
                           "stage has 3 to 8 planets)");
    planet.copies = static_cast<unsigned int>(copies);
  }
}

// "a-b/frame" (frame the housing when left out).
std::vector<TrainMesh> parse_meshes(const std::string& text, MemberTable& members)
{
  std::vector<TrainMesh> meshes;
  if (trim(text).empty())
    return meshes;
  for (const std::string& entry : split(text, ','))
  {
    TrainMesh mesh;
    const auto slash = entry.find('/');
    const std::string pair = trim(entry.substr(0, slash));
    if (slash != std::string::npos)
      mesh.frame = trim(entry.substr(slash + 1));
    const auto dash = pair.find('-');
    if (dash == std::string::npos)
      throw InputError(field::train("meshes"),
                       "entry '" + entry + "' is not of the form a-b/frame");
    mesh.gear_a = trim(pair.substr(0, dash));
    mesh.gear_b = trim(pair.substr(dash + 1));
    for (const std::string& name : {mesh.gear_a, mesh.gear_b})
      members.existing(name, "meshes");
    if (mesh.frame != housing_name)
      members.existing(mesh.frame, "meshes");
    meshes.push_back(mesh);
  }
  return meshes;
}

// "a=b": members turning as one rigid body.
std::vector<std::pair<std::string, std::string>> parse_connections(const std::string& text,
                                                                   MemberTable& members)
{
  std::vector<std::pair<std::string, std::string>> connections;
  if (trim(text).empty())
    return connections;
  for (const std::string& entry : split(text, ','))
  {
    const auto equals = entry.find('=');
    if (equals == std::string::npos)
      throw InputError(field::train("connections"), "entry '" + entry + "' is not of the form a=b");
    const std::string a = trim(entry.substr(0, equals));
    const std::string b = trim(entry.substr(equals + 1));
    members.existing(a, "connections");
    members.existing(b, "connections");
    connections.emplace_back(a, b);
  }
  return connections;
}

// "name: value" with a value ≥ 0 (`what` names the quantity in the message).
void parse_nonnegative(const std::string& text, const std::string& key, const std::string& what,
                       MemberTable& members, double TrainMember::*field)
{
  for (const auto& [name, value] : parse_assignments(text, key))
  {
    const double number = parse_number(value, field::train(key));
    if (number < 0.)
      throw InputError(field::train(key), what + " of '" + name + "' is negative");
    members.existing(name, key).*field = number;
  }
}
} // namespace

GearTrainSpec parse_gear_train(const GearTrainText& text)
{
  GearTrainSpec spec;
  MemberTable members(spec);
  parse_gears_and_carriers(text, members);
  for (const auto& [name, value] : parse_assignments(text.modules, "modules"))
  {
    const double module = parse_number(value, field::train("modules"));
    if (!(module > 0.))
      throw InputError(field::train("modules"), "module of '" + name + "' must be positive");
    members.existing(name, "modules").module = module * 1e-3;
  }
  parse_planets(text.planets, members);
  spec.meshes = parse_meshes(text.meshes, members);
  spec.connections = parse_connections(text.connections, members);
  for (const std::string& name : parse_names(text.fixed, "fixed"))
  {
    members.existing(name, "fixed");
    spec.fixed.push_back(name);
  }
  for (const auto& [name, value] : parse_assignments(text.inputs, "inputs"))
  {
    members.existing(name, "inputs");
    spec.inputs.emplace_back(name, parse_number(value, field::train("inputs")) * rpm);
  }
  spec.output = trim(text.output);
  if (!spec.output.empty())
    members.existing(spec.output, "output");
  parse_nonnegative(text.inertias, "inertias", "inertia", members, &TrainMember::moment_of_inertia);
  parse_nonnegative(text.masses, "masses", "mass", members, &TrainMember::mass);
  for (const auto& [name, value] : parse_assignments(text.profile_shifts, "profile_shifts"))
  {
    TrainMember& gear = members.existing(name, "profile_shifts");
    const double shift = parse_number(value, field::train("profile_shifts"));
    // The gear-pair command's range (app/kinematics/kinematics_parameters.cc): beyond it no tooth
    // exists.
    if (gear.teeth == 0 || !(std::abs(shift) <= 5.))
      throw InputError(field::train("profile_shifts"),
                       gear.teeth == 0 ? "'" + name + "' has no teeth to shift"
                                       : "x of '" + name + "' must lie in [-5, 5]");
    gear.profile_shift = shift;
  }
  return spec;
}

double working_centre_distance(const TrainMember& a, const TrainMember& b, double pressure_angle)
{
  const double reference = 0.5 * a.module * std::abs(a.teeth + b.teeth);
  const double shift_sum = a.profile_shift + b.profile_shift;
  if (shift_sum == 0.)
    return reference;
  const double inv_working = involute(pressure_angle) +
                             2. * std::tan(pressure_angle) * shift_sum / double(a.teeth + b.teeth);
  if (!(inv_working > 0.))
    throw InputError(field::train("profile_shifts"), "the shifts of " + a.name + " and " + b.name +
                                                         " leave no working pressure angle");
  return reference * std::cos(pressure_angle) / std::cos(inverse_involute(inv_working));
}

std::vector<std::string> builtin_train_names()
{
  return {"bi-planetary", "planetary", "split-path", "cycloidal"};
}

GearTrainText builtin_train(const std::string& name)
{
  // Each as {gears, modules, carriers, planets, meshes, connections, fixed, inputs, output,
  // inertias, masses, profile shifts}.
  static const std::map<std::string, GearTrainText> trains = {
      // Drewniak, Garlicka, Kolber 2016 (docs/references.md §2). Each of the three planets 2
      // carries an inner set: sun 3 on planet 2's axis, three planets 4 on inner carrier H, ring 5
      // fixed to carrier h; H drives planet 6, which runs in the fixed ring 7. Modules are not
      // published: 2 mm for 1-2 and the inner set reproduce the printed forces (1907.94 N =
      // T1/(3·r1), 2453.06 N = T5/(9·r5)); 4 mm for 6-7 makes planet 6 coaxial with planet 2
      // ((72 − 21)·4/2 = (21 + 81)·2/2 = 102 mm).
      {"bi-planetary",
       {"1: 21, 2: 81, 3: 21, 4: 24, 5: -69, 6: 21, 7: -72",
        "1: 2, 2: 2, 3: 2, 4: 2, 5: 2, 6: 4, 7: 4", "h, H",
        "2: h*3, 3: h*3, 5: h*3, 6: h*3, H: h*3, 4: H*9", "1-2/h, 3-4/H, 4-5/H, 6-7/h",
        "3=2, 5=h, H=6", "7", "1: 1470", "h", "", "", ""}},
      {"planetary",
       {"s: 20, p: 10, r: -40", "s: 2, p: 2, r: 2", "c", "p: c*3", "s-p/c, p-r/c", "", "r",
        "s: 1470", "c", "", "", ""}},
      // Reszuta & Drewniak 2015 (docs/references.md §1): pinion 1 drives wheels 2 and 3.
      {"split-path",
       {"1: 21, 2: 57, 3: 57", "1: 2.5, 2: 2.5, 3: 2.5", "", "", "1-2, 1-3", "", "", "1: 1450", "2",
        "", "", ""}},
      // Chmurawa & Łokiec (docs/references.md §4): disc s (19 lobes) on the eccentric e rolls in
      // the fixed ring of 20 rollers k; the pin coupling passes the disc's rotation to `out`. The
      // rolling lobe pair obeys the same Willis relation as a tooth pair.
      {"cycloidal",
       {"s: 19, k: -20", "", "e, out", "s: e*2", "s-k/e", "out=s", "k", "e: 750", "out", "", "",
        ""}}};
  const auto found = trains.find(name);
  if (found == trains.end())
    throw InputError(field::train("builtin"), "unknown built-in train '" + name + "'");
  return found->second;
}
} // namespace gearstiff::kinematics
