#include "dynamics/lateral_train.h"

#include "dynamics/fields.h"
#include "errors/errors.h"
#include "errors/format.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace gearstiff::dynamics
{
namespace
{
void require_positive(double value, const std::string& parameter, const std::string& what)
{
  if (!(value > 0.) || !std::isfinite(value))
    throw InputError(parameter, what + " must be positive (is " + format_number(value, 5) + ")");
}

void require_non_negative(double value, const std::string& parameter, const std::string& what)
{
  if (!(value >= 0.) || !std::isfinite(value))
    throw InputError(parameter,
                     what + " must not be negative (is " + format_number(value, 5) + ")");
}

void check_body(const LateralTrain& train, const LateralBody& b)
{
  require_positive(b.mass, field::train("masses"), "the mass of '" + b.name + "'");
  require_positive(b.radius, field::train("base_diameters"), "the radius of '" + b.name + "'");
  if (!b.held)
    require_positive(b.moment_of_inertia, field::train("inertias"), "J of '" + b.name + "'");
  require_non_negative(b.bearing_stiffness, field::train("bearing_stiffness"), "'" + b.name + "'");
  require_non_negative(b.bearing_damping, field::train("bearing_damping"), "'" + b.name + "'");
  require_non_negative(b.torsional_stiffness, field::train("suspended_members"),
                       "'" + b.name + "'");
  require_non_negative(b.torsional_damping, field::train("suspended_members"), "'" + b.name + "'");
  if (b.carrier < 0)
    return;
  if (b.carrier >= static_cast<int>(train.bodies.size()))
    throw InputError(field::train("planets"), "'" + b.name + "' rides on an unknown carrier");
  require_positive(b.pin_stiffness, field::train("planet_pin_stiffness"),
                   "the pin of '" + b.name + "'");
  require_non_negative(b.pin_damping, field::train("planet_pin_stiffness"),
                       "the pin of '" + b.name + "'");
  require_positive(b.orbit_radius, field::train("carrier_radii"),
                   "the orbit radius of '" + b.name + "'");
  if (b.bearing_stiffness > 0. || b.bearing_damping > 0.)
    throw InputError(field::train("bearing_stiffness"),
                     "'" + b.name +
                         "' rides on a carrier: its support is the "
                         "pin (Train/planet pin stiffness)");
}

// Body b's translation (q1, q2) projected on the unit vector at angle `angle`.
void add_translation(std::vector<std::pair<unsigned int, double>>& terms, unsigned int body,
                     double frame_angle, double angle, double factor)
{
  terms.push_back({LateralTrainModel::dof(body, 0), factor * std::cos(angle - frame_angle)});
  terms.push_back({LateralTrainModel::dof(body, 1), factor * std::sin(angle - frame_angle)});
}

// A translation that nothing holds: refuse it, naming the central body that moves most.
void refuse_free_translation(const LateralTrain& train, const LateralTrainModes& modes)
{
  for (Eigen::Index k = 0; k < modes.frequencies.size() && modes.frequencies[k] == 0.; ++k)
  {
    double translation = 0., largest = 0.;
    std::size_t body = 0;
    for (std::size_t b = 0; b < train.bodies.size(); ++b)
      if (train.bodies[b].central)
      {
        const double e = modes.kinetic_energy_share(k, 2 * b);
        translation += e;
        if (e > largest)
          largest = e, body = b;
      }
    if (translation > 1e-6)
      throw InputError(field::train("bearing_stiffness"),
                       "'" + train.bodies[body].name +
                           "' translates freely: zero bearing stiffness with nothing else "
                           "holding it in x and y");
  }
}
} // namespace

LateralMeshLine mesh_line(const LateralTrain& train, const LateralGear& gear_a,
                          const LateralGear& gear_b, double pressure_angle, int side)
{
  // The same line either way round: put an internal gear first.
  const bool swap = gear_b.internal && !gear_a.internal;
  const LateralGear& a = swap ? gear_b : gear_a;
  const LateralGear& b = swap ? gear_a : gear_b;
  const double s = side < 0 ? -1. : 1.;
  const Eigen::Vector2d centre_line = b.centre - a.centre;
  const double phi = std::atan2(centre_line.y(), centre_line.x());
  const double tilt = a.internal ? s * pressure_angle : -s * pressure_angle;
  LateralMeshLine line;
  line.body_a = a.body;
  line.body_b = b.body;
  line.direction = phi + 0.5 * M_PI + tilt + (s < 0. ? M_PI : 0.);
  const Eigen::Vector2d n(std::cos(line.direction), std::sin(line.direction));
  // Arms about the gears' centres, then moved to the bodies' axes: + ((G − O) × n)_z.
  auto shift = [&](const LateralGear& g)
  {
    const Eigen::Vector2d offset = g.centre - train.bodies.at(g.body).centre;
    return offset.x() * n.y() - offset.y() * n.x();
  };
  line.arm_a = s * a.base_radius + shift(a);
  line.arm_b = (a.internal ? s : -s) * b.base_radius + shift(b);
  return line;
}

LateralTrain lateral_train_of_stage(const LateralStage& stage)
{
  LateralTrain train;
  const LateralCentralMember* central[3] = {&stage.carrier, &stage.ring, &stage.sun};
  const char* names[3] = {"carrier", "ring", "sun"};
  for (unsigned int j = 0; j < 3; ++j)
  {
    const LateralCentralMember& m = *central[j];
    LateralBody b;
    b.name = names[j];
    b.mass = m.mass;
    b.moment_of_inertia = m.moment_of_inertia;
    b.radius = m.radius;
    b.bearing_stiffness = m.bearing_stiffness;
    b.bearing_damping = m.bearing_damping;
    b.held = m.held;
    b.torsional_stiffness = m.torsional_stiffness;
    b.torsional_damping = m.torsional_damping;
    train.bodies.push_back(b);
  }
  for (std::size_t p = 0; p < stage.planet_angles.size(); ++p)
  {
    const double psi = stage.planet_angles[p];
    LateralBody b;
    b.name = "planet " + std::to_string(p + 1);
    b.mass = stage.planet_mass;
    b.moment_of_inertia = stage.planet_moment_of_inertia;
    b.radius = stage.planet_base_radius;
    b.centre = stage.carrier.radius * Eigen::Vector2d(std::cos(psi), std::sin(psi));
    b.frame_angle = psi;
    b.central = false;
    b.carrier = 0;
    b.orbit_radius = stage.carrier.radius;
    b.pin_stiffness = stage.pin_stiffness;
    b.pin_damping = stage.pin_damping;
    if (!stage.pin_error_tangential.empty())
      b.pin_error_tangential = stage.pin_error_tangential[p];
    if (!stage.pin_error_radial.empty())
      b.pin_error_radial = stage.pin_error_radial[p];
    train.bodies.push_back(b);
  }
  for (std::size_t p = 0; p < stage.planet_angles.size(); ++p)
  {
    const unsigned int body = 3 + p;
    const LateralGear planet{body, train.bodies[body].centre, stage.planet_base_radius, false};
    // Sun (body 2, external) then ring (body 1, internal) mesh of this planet.
    for (const bool sun : {true, false})
    {
      LateralMeshLine line =
          mesh_line(train, {sun ? 2u : 1u, {0., 0.}, (sun ? stage.sun : stage.ring).radius, !sun},
                    planet, sun ? stage.sun_pressure_angle : stage.ring_pressure_angle, 1);
      line.stiffness = sun ? stage.sun_mesh_stiffness : stage.ring_mesh_stiffness;
      line.damping = sun ? stage.sun_mesh_damping : stage.ring_mesh_damping;
      line.spec_mesh = sun ? 0 : 1;
      line.name = (sun ? "sun-planet#" : "planet-ring#") + std::to_string(p + 1);
      train.meshes.push_back(line);
    }
  }
  return train;
}

void LateralTrainModel::add_springs()
{
  for (unsigned int b = 0; b < n_bodies(); ++b)
  {
    const LateralBody& body = data.bodies[b];
    if (body.bearing_stiffness > 0. || body.bearing_damping > 0.)
      for (const double axis : {0., 0.5 * M_PI}) // global x, y
      {
        Spring s{0, b, body.bearing_stiffness, body.bearing_damping, 0., {}};
        add_translation(s.terms, b, body.frame_angle, axis, 1.);
        s.terms.erase(std::remove_if(s.terms.begin(), s.terms.end(),
                                     [](const auto& t) { return t.second == 0.; }),
                      s.terms.end());
        spring_list.push_back(s);
      }
    const double r2 = body.radius * body.radius;
    if (!body.held && (body.torsional_stiffness > 0. || body.torsional_damping > 0.))
      spring_list.push_back({1,
                             b,
                             body.torsional_stiffness / r2,
                             body.torsional_damping / r2,
                             0.,
                             {{dof(b, 2), 1.}}});
    if (body.carrier < 0)
      continue;
    const unsigned int c = body.carrier;
    const LateralBody& carrier = data.bodies[c];
    const double psi = body.frame_angle - carrier.frame_angle;
    spring_list.push_back(
        {2,
         b,
         body.pin_stiffness,
         body.pin_damping,
         body.pin_error_radial,
         {{dof(c, 0), std::cos(psi)}, {dof(c, 1), std::sin(psi)}, {dof(b, 0), -1.}}});
    spring_list.push_back({2,
                           b,
                           body.pin_stiffness,
                           body.pin_damping,
                           body.pin_error_tangential,
                           {{dof(c, 0), -std::sin(psi)},
                            {dof(c, 1), std::cos(psi)},
                            {dof(c, 2), body.orbit_radius / carrier.radius},
                            {dof(b, 1), -1.}}});
  }
  for (unsigned int m = 0; m < data.meshes.size(); ++m)
  {
    const LateralMeshLine& line = data.meshes[m];
    require_positive(line.stiffness, field::train_mesh(line.spec_mesh, "stiffness"),
                     "the stiffness of " + line.name);
    if (line.body_a == line.body_b || line.body_a >= n_bodies() || line.body_b >= n_bodies())
      throw InputError(field::train("meshes"), line.name + " must join two bodies");
    const LateralBody& a = data.bodies[line.body_a];
    const LateralBody& b = data.bodies[line.body_b];
    Spring s{3, m, line.stiffness, line.damping, 0., {}};
    add_translation(s.terms, line.body_a, a.frame_angle, line.direction, 1.);
    s.terms.push_back({dof(line.body_a, 2), line.arm_a / a.radius});
    add_translation(s.terms, line.body_b, b.frame_angle, line.direction, -1.);
    s.terms.push_back({dof(line.body_b, 2), -line.arm_b / b.radius});
    mesh_spring_index.push_back(spring_list.size());
    spring_list.push_back(s);
  }
}

void LateralTrainModel::assemble()
{
  const unsigned int n = n_dofs();
  mass_diagonal.resize(n);
  for (unsigned int b = 0; b < n_bodies(); ++b)
  {
    const LateralBody& body = data.bodies[b];
    mass_diagonal[dof(b, 0)] = mass_diagonal[dof(b, 1)] = body.mass;
    mass_diagonal[dof(b, 2)] = body.moment_of_inertia / (body.radius * body.radius);
    for (unsigned int c = 0; c < 3; ++c)
      if (c < 2 || !body.held)
        free.push_back(dof(b, c));
  }
  assemble_springs(spring_list, n, stiffness_matrix, damping_matrix, error_force);
}

LateralTrainModel::LateralTrainModel(LateralTrain train) : data(std::move(train))
{
  if (data.bodies.empty())
    throw InputError(field::train("gears"), "the lateral model needs bodies");
  for (const LateralBody& b : data.bodies)
    check_body(data, b);
  add_springs();
  assemble();
  refuse_free_translation(data, modes());
}

double LateralTrainModel::deflection(const Spring& spring, const double* q) const
{
  double d = spring.preload;
  for (const auto& [i, v] : spring.terms)
    d += v * q[i];
  return d;
}

LateralTrainModes LateralTrainModel::modes(double relative_tolerance) const
{
  LateralTrainModes result;
  const double largest =
      undamped_modes(mass_diagonal, stiffness_matrix, free, result.frequencies, result.shapes);
  const unsigned int nf = free.size();
  result.kinetic_energy_share = Eigen::MatrixXd::Zero(nf, 2 * n_bodies());
  for (unsigned int k = 0; k < nf; ++k)
  {
    for (const unsigned int d : free)
      result.kinetic_energy_share(k, 2 * (d / 3) + (d % 3 == 2 ? 1 : 0)) +=
          mass_diagonal[d] * result.shapes(d, k) * result.shapes(d, k);
    result.kinetic_energy_share.row(k) /= result.kinetic_energy_share.row(k).sum();
  }
  std::vector<unsigned int> central;
  for (unsigned int b = 0; b < n_bodies(); ++b)
    if (data.bodies[b].central)
      central.push_back(b);
  result.groups = classify_mode_groups(result.frequencies, result.kinetic_energy_share, central,
                                       relative_tolerance, largest);
  return result;
}

LateralTrainStatics LateralTrainModel::static_state(unsigned int input, unsigned int output,
                                                    double input_torque) const
{
  if (input >= n_bodies() || data.bodies[input].held)
    throw InputError(field::train("inputs"), "the input must be a body that turns");
  if (output >= n_bodies() || data.bodies[output].held || output == input)
    throw InputError(field::train("output"), "the output must be another body that turns");
  Eigen::VectorXd f = error_force;
  f[dof(input, 2)] += input_torque / data.bodies[input].radius;
  const LateralTrainModes m = modes();
  std::vector<unsigned int> rigid;
  for (Eigen::Index k = 0; k < m.frequencies.size() && m.frequencies[k] == 0.; ++k)
    rigid.push_back(k);
  if (rigid.size() > 1)
    throw InputError(field::train("fixed"), "the train has " + std::to_string(rigid.size()) +
                                                " free motions: hold or suspend a member");
  LateralTrainStatics state;
  const unsigned int uo = dof(output, 2), extra = rigid.size();
  if (extra)
  {
    // The load on the output that balances the input in the rigid rotation: v0ᵀ·f = 0.
    const Eigen::VectorXd v0 = m.shapes.col(rigid.front());
    if (std::abs(v0[uo]) < 1e-12 * v0.cwiseAbs().maxCoeff())
      throw InputError(field::train("output"), "the output does not turn with the train");
    state.output_torque = -v0.dot(f) / v0[uo] * data.bodies[output].radius;
    f[uo] += state.output_torque / data.bodies[output].radius;
  }
  const Eigen::VectorXd v0 =
      extra ? Eigen::VectorXd(m.shapes.col(rigid.front())) : Eigen::VectorXd();
  state.displacement =
      constrained_deflection(mass_diagonal, stiffness_matrix, free, f, extra ? &v0 : nullptr);
  static_forces(state);
  return state;
}

void LateralTrainModel::static_forces(LateralTrainStatics& state) const
{
  const double* q = state.displacement.data();
  state.bearing_force = Eigen::MatrixXd::Zero(n_bodies(), 2);
  std::vector<unsigned int> seen(n_bodies(), 0);
  for (const Spring& s : spring_list)
  {
    const double force = s.stiffness * deflection(s, q);
    if (s.group == 3)
      state.mesh_force.push_back(force);
    else if (s.group == 2)
      state.pin_force.push_back(force);
    else if (s.group == 0) // add_springs: each body's x spring, then its y spring
      state.bearing_force(s.planet, seen[s.planet]++) = -force;
  }
}
} // namespace gearstiff::dynamics
