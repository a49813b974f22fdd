#include "dynamics/lateral_train_build.h"

#include "dynamics/fields.h"
#include "errors/errors.h"
#include "kinematics/gear_train.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace gearstiff::dynamics
{
namespace
{
struct Placement
{
  Eigen::Vector2d centre = Eigen::Vector2d::Zero(); // [m]
  double angle = 0.; // [rad] direction from its carrier's axis (0 on the main axis)
};

// The members, their rigid bodies (connected components, labelled by their first member) and
// each copy's place at the frozen instant.
struct Layout
{
  const kinematics::GearTrainSpec& spec;
  kinematics::TrainSolution solution;
  std::vector<std::size_t> label;        // per member: first member of its body
  std::vector<unsigned int> body_copies; // per label
  std::vector<int> first_body;           // per label: index of its copy 0 (-1: none)

  std::size_t index(const std::string& name) const
  {
    for (std::size_t i = 0; i < spec.members.size(); ++i)
      if (spec.members[i].name == name)
        return i;
    throw InputError(field::train("gears"),
                     "lateral: no member '" + name + "' (the housing has no body)");
  }
  unsigned int copies(std::size_t i) const { return spec.members[i].copies; }
  Placement place(std::size_t i, unsigned int k, unsigned int depth = 0) const
  {
    const kinematics::TrainMember& m = spec.members[i];
    if (m.carrier.empty() || m.carrier == kinematics::housing_name)
      return {};
    if (depth > spec.members.size())
      throw InputError(field::train("planets"), "carriers form a loop at '" + m.name + "'");
    const std::size_t c = index(m.carrier);
    const unsigned int per = copies(i) / std::max(1u, copies(c));
    const Placement carrier = place(c, k / per, depth + 1);
    Placement p;
    p.angle = carrier.angle + 2. * M_PI * (k % per) / per;
    p.centre = carrier.centre +
               solution.orbit_radius[i] * Eigen::Vector2d(std::cos(p.angle), std::sin(p.angle));
    return p;
  }
  // Body index of copy k of member i.
  unsigned int body(std::size_t i, unsigned int k) const
  {
    const std::size_t l = label[i];
    return first_body[l] + k / (copies(i) / body_copies[l]);
  }
};

Layout find_layout(const kinematics::GearTrainSpec& spec)
{
  Layout layout{spec, kinematics::solve_train_kinematics(spec), {}, {}, {}};
  const std::size_t n = spec.members.size();
  layout.label.resize(n);
  std::iota(layout.label.begin(), layout.label.end(), 0);
  for (bool changed = true; changed;)
  {
    changed = false;
    for (const auto& [a, b] : spec.connections)
    {
      const std::size_t la = layout.label[layout.index(a)], lb = layout.label[layout.index(b)];
      if (la == lb)
        continue;
      for (std::size_t& l : layout.label)
        if (l == std::max(la, lb))
          l = std::min(la, lb);
      changed = true;
    }
  }
  layout.body_copies.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    unsigned int& c = layout.body_copies[layout.label[i]];
    c = c == 0 ? layout.copies(i) : std::min(c, layout.copies(i));
  }
  return layout;
}

double value_in(const std::map<std::string, double>& values, const Layout& layout, std::size_t l,
                double fallback)
{
  for (std::size_t i = 0; i < layout.spec.members.size(); ++i)
    if (layout.label[i] == l && values.count(layout.spec.members[i].name))
      return values.at(layout.spec.members[i].name);
  return fallback;
}

double base_radius(const LateralTrainInput& input, const kinematics::TrainMember& gear)
{
  if (input.base_radius.count(gear.name))
    return input.base_radius.at(gear.name);
  return 0.5 * gear.module * std::abs(gear.teeth) * std::cos(input.train.pressure_angle);
}

// u radius of body l: its axis member's base radius, or a carrier's pin circle (given, else the
// largest orbit radius of the members it carries).
double body_radius(const LateralTrainInput& input, const Layout& layout, std::size_t l,
                   std::size_t axis)
{
  const kinematics::TrainMember& m = layout.spec.members[axis];
  if (m.teeth != 0)
    return base_radius(input, m);
  double radius = value_in(input.carrier_radius, layout, l, 0.);
  for (std::size_t i = 0; radius == 0. && i < layout.spec.members.size(); ++i)
    for (std::size_t j = 0; j < layout.spec.members.size(); ++j)
      if (layout.spec.members[j].carrier == layout.spec.members[i].name && layout.label[i] == l)
        radius = std::max(radius, layout.solution.orbit_radius[j]);
  if (!(radius > 0.))
    throw InputError(field::train("carrier_radii"), "'" + m.name + "' needs its pin-circle radius");
  return radius;
}

// Mass and J of one copy of body l: its members' per copy times how many ride on it.
void add_mass(const Layout& layout, std::size_t l, LateralBody& body)
{
  for (std::size_t i = 0; i < layout.spec.members.size(); ++i)
    if (layout.label[i] == l)
    {
      const double share = layout.copies(i) / layout.body_copies[l];
      body.mass += share * layout.spec.members[i].mass;
      body.moment_of_inertia += share * layout.spec.members[i].moment_of_inertia;
    }
}

void add_supports(const LateralTrainInput& input, const Layout& layout, std::size_t l,
                  LateralBody& body)
{
  body.bearing_stiffness = value_in(input.bearing_stiffness, layout, l, 0.);
  body.bearing_damping = value_in(input.bearing_damping, layout, l, 0.);
  bool fixed = false;
  for (const std::string& name : layout.spec.fixed)
    fixed = fixed || layout.label[layout.index(name)] == l;
  body.held = fixed;
  for (const TrainSuspension& s : input.train.suspensions)
    if (layout.label[layout.index(s.member)] == l)
    {
      body.held = false;
      body.torsional_stiffness = s.stiffness;
      body.torsional_damping = s.damping;
    }
  if (!body.central)
  {
    body.pin_stiffness = value_in(input.pin_stiffness, layout, l, 0.);
    body.pin_damping = value_in(input.pin_damping, layout, l, 0.);
  }
}

// Bodies named by their axis member (h, not 5, for carrier h with its rings 5); `dof_names`:
// the rotational model's names (by the body's first member) for the DOF map.
void add_bodies(const LateralTrainInput& input, Layout& layout, LateralTrainSetup& setup,
                std::vector<std::string>& dof_names)
{
  const kinematics::GearTrainSpec& spec = layout.spec;
  layout.first_body.assign(spec.members.size(), -1);
  std::vector<std::size_t> axis_of;
  for (std::size_t l = 0; l < spec.members.size(); ++l)
  {
    if (layout.label[l] != l)
      continue;
    std::size_t axis = l;
    while (layout.label[axis] != l || layout.copies(axis) != layout.body_copies[l])
      ++axis;
    layout.first_body[l] = setup.train.bodies.size();
    for (unsigned int k = 0; k < layout.body_copies[l]; ++k)
    {
      LateralBody body;
      const std::string copy =
          layout.body_copies[l] > 1 ? "#" + std::to_string(k + 1) : std::string();
      body.name = spec.members[axis].name + copy;
      dof_names.push_back(spec.members[l].name + copy);
      const Placement p = layout.place(axis, k);
      body.centre = p.centre;
      body.frame_angle = p.angle;
      body.central = spec.members[axis].carrier.empty();
      body.orbit_radius = layout.solution.orbit_radius[axis];
      body.radius = body_radius(input, layout, l, axis);
      add_mass(layout, l, body);
      add_supports(input, layout, l, body);
      setup.train.bodies.push_back(body);
      axis_of.push_back(axis);
    }
  }
  // Carriers once every body has its index.
  for (std::size_t b = 0; b < setup.train.bodies.size(); ++b)
    if (!setup.train.bodies[b].central)
    {
      const std::size_t axis = axis_of[b];
      const unsigned int k = b - layout.first_body[layout.label[axis]];
      const std::size_t c = layout.index(spec.members[axis].carrier);
      setup.train.bodies[b].carrier =
          layout.body(c, k / (layout.copies(axis) / std::max(1u, layout.copies(c))));
    }
}

// Orientation of rotational mesh i (train_model.cc turns each mesh so that its static force is
// positive): its coefficient of a DOF against the unoriented r_a·φ_a + r_b·φ_b − (r_a + r_b)·φ_c.
double orientation(const Mesh& mesh, const std::array<int, 3>& dofs, double ra, double rb)
{
  const double unoriented[3] = {ra, rb, -(ra + rb)};
  for (const MeshTerm& term : mesh.terms)
  {
    double expected = 0.;
    for (unsigned int k = 0; k < 3; ++k)
      if (dofs[k] == static_cast<int>(term.dof))
        expected += unoriented[k];
    if (std::abs(expected) > 1e-6 * (std::abs(ra) + std::abs(rb)))
      return term.coefficient / expected > 0. ? 1. : -1.;
  }
  return 1.;
}

// Gear g of a mesh on frame c, copy j of the mesh's `copies`: a planet of c at its own place,
// any other gear on c's axis.
LateralGear mesh_gear(const LateralTrainInput& input, const Layout& layout, std::size_t g,
                      std::size_t c, unsigned int j, unsigned int copies)
{
  const kinematics::TrainMember& gear = layout.spec.members[g];
  const unsigned int kg = j / (copies / layout.copies(g));
  LateralGear result;
  result.body = layout.body(g, kg);
  result.base_radius = base_radius(input, gear);
  result.internal = gear.teeth < 0;
  if (gear.carrier == layout.spec.members[c].name)
    result.centre = layout.place(g, kg).centre;
  else
    result.centre = layout.place(c, j / (copies / layout.copies(c))).centre;
  return result;
}

void add_meshes(const LateralTrainInput& input, const Layout& layout, LateralTrainSetup& setup)
{
  const kinematics::GearTrainSpec& spec = layout.spec;
  const std::vector<Mesh>& rotational = setup.rotational.train.meshes;
  for (std::size_t i = 0; i < rotational.size(); ++i)
  {
    const unsigned int m = setup.rotational.spec_mesh[i], j = setup.rotational.mesh_copy[i];
    const kinematics::TrainMesh& tm = spec.meshes[m];
    if (tm.frame == kinematics::housing_name)
      throw InputError(field::train("meshes"), "lateral: fixed-axis mesh " + tm.gear_a + "-" +
                                                   tm.gear_b +
                                                   " (only planetary meshes, on a carrier)");
    const std::size_t a = layout.index(tm.gear_a), b = layout.index(tm.gear_b),
                      c = layout.index(tm.frame);
    const unsigned int copies = std::max({layout.copies(a), layout.copies(b), layout.copies(c)});
    const LateralGear ga = mesh_gear(input, layout, a, c, j, copies);
    const LateralGear gb = mesh_gear(input, layout, b, c, j, copies);
    const LateralGear gc{layout.body(c, j / (copies / layout.copies(c))), {}, 1., false};
    const double ra = 0.5 * spec.members[a].module * spec.members[a].teeth;
    const double rb = 0.5 * spec.members[b].module * spec.members[b].teeth;
    const double sign = orientation(
        rotational[i], {setup.body_dof[ga.body], setup.body_dof[gb.body], setup.body_dof[gc.body]},
        ra, rb);
    const bool internal = ga.internal || gb.internal;
    LateralMeshLine line = mesh_line(setup.train, ga, gb, input.train.pressure_angle,
                                     static_cast<int>(internal ? -sign : sign));
    line.name = rotational[i].name;
    line.spec_mesh = m;
    line.stiffness = rotational[i].stiffness.mean_stiffness(rotational[i].contact_ratio);
    line.damping = rotational[i].damping;
    setup.train.meshes.push_back(line);
  }
}
} // namespace

LateralTrainSetup build_lateral_train(const LateralTrainInput& input)
{
  return build_lateral_train(input, build_train_model(input.train));
}

LateralTrainSetup build_lateral_train(const LateralTrainInput& input, const TrainModel& rotational)
{
  LateralTrainSetup setup;
  setup.rotational = rotational;
  Layout layout = find_layout(input.train.spec);
  for (const auto* list : {&input.bearing_stiffness, &input.bearing_damping, &input.pin_stiffness,
                           &input.pin_damping, &input.base_radius, &input.carrier_radius})
    for (const auto& [name, value] : *list)
      layout.index(name); // names a member
  std::vector<std::string> dof_names;
  add_bodies(input, layout, setup, dof_names);
  for (const std::string& name : dof_names)
  {
    const auto& names = setup.rotational.dof_names;
    const auto found = std::find(names.begin(), names.end(), name);
    setup.body_dof.push_back(found == names.end() ? -1 : static_cast<int>(found - names.begin()));
  }
  add_meshes(input, layout, setup);
  const kinematics::GearTrainSpec& spec = input.train.spec;
  setup.input_body = layout.body(layout.index(spec.inputs.front().first), 0);
  setup.output_body = layout.body(layout.index(spec.output), 0);
  setup.input_torque = setup.rotational.train.gears.front().torque;
  return setup;
}
} // namespace gearstiff::dynamics
