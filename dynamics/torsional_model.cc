#include "dynamics/torsional_model.h"

#include "dynamics/fields.h"
#include "errors/errors.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace gearstiff::dynamics
{
namespace
{
void require(bool condition, const std::string& parameter, const std::string& reason)
{
  if (!condition)
    throw InputError(parameter, reason);
}

// The rigid mode is a double zero eigenvalue (a Jordan block) of the first-order system;
// round-off splits it into about ±sqrt(ε)·|λ|max ≈ ±1e-8·|λ|max, so anything below
// 1e-6·|λ|max is the rigid mode, not a vibration.
constexpr double rigid_mode_threshold = 1e-6;

// Classical RK4 amplification factor for y' = λy at z = hλ.
double rk4_amplification(std::complex<double> z)
{
  return std::abs(1. + z * (1. + z * (0.5 + z * (1. / 6. + z / 24.))));
}
} // namespace

double mesh_phase_from_placement(unsigned int driver_teeth, double placement_angle)
{
  const double turns = driver_teeth * placement_angle / (2. * M_PI);
  return turns - std::floor(turns);
}

TorsionalModel::TorsionalModel(const GearTrain& train)
    : description(train), n_gears(train.gears.size()), general(!train.speed_ratios.empty())
{
  require(n_gears >= 2, "gears", "a train needs at least two gears");
  if (!general)
    require(train.meshes.size() + 1 == n_gears, "meshes",
            "a tree-shaped train of " + std::to_string(n_gears) + " gears has " +
                std::to_string(n_gears - 1) + " meshes, got " +
                std::to_string(train.meshes.size()) +
                " (closed loops need the general form: a Train description)");
  require(train.input_speed > 0. && std::isfinite(train.input_speed), "input speed",
          "must be positive, got " + std::to_string(train.input_speed * 30. / M_PI) + " rpm");

  inertia.resize(n_gears);
  torques.resize(n_gears);
  inverse_inertia.resize(n_gears);
  for (unsigned int i = 0; i < n_gears; ++i)
  {
    const Gear& gear = train.gears[i];
    require(gear.inertia > 0. && std::isfinite(gear.inertia), field::train_gear(i, "inertia"),
            "must be positive, got " + std::to_string(gear.inertia) + " kg·m²");
    require(std::isfinite(gear.torque), field::train_gear(i, "torque"), "must be finite");
    inertia[i] = gear.inertia;
    inverse_inertia[i] = 1. / gear.inertia;
    torques[i] = gear.torque;
  }
  for (unsigned int m = 0; m < train.meshes.size(); ++m)
    validate_mesh(train, m);
  for (const Suspension& suspension : train.suspensions)
    require(suspension.dof < n_gears && suspension.stiffness >= 0. && suspension.damping >= 0. &&
                std::isfinite(suspension.stiffness + suspension.damping),
            field::train_gear(std::min(suspension.dof, n_gears - 1), "suspension"),
            "needs a degree of freedom of the train and a non-negative stiffness and damping");
  suspensions = train.suspensions;

  if (general)
  {
    require(train.speed_ratios.size() == n_gears, "speed ratios", "one per degree of freedom");
    speeds.resize(n_gears);
    for (unsigned int i = 0; i < n_gears; ++i)
      speeds[i] = train.speed_ratios[i] * train.input_speed;
  }
  else
  {
    // Nominal speeds: r_a·ω_a = r_b·ω_b along every mesh, gear 0 at the input speed.
    speeds.assign(n_gears, 0.);
    std::vector<bool> known(n_gears, false);
    speeds[0] = train.input_speed;
    known[0] = true;
    for (bool changed = true; changed;)
    {
      changed = false;
      for (const Mesh& mesh : train.meshes)
        if (known[mesh.driver] != known[mesh.driven])
        {
          if (known[mesh.driver])
            speeds[mesh.driven] =
                speeds[mesh.driver] * mesh.driver_base_radius / mesh.driven_base_radius;
          else
            speeds[mesh.driver] =
                speeds[mesh.driven] * mesh.driven_base_radius / mesh.driver_base_radius;
          known[mesh.driver] = known[mesh.driven] = true;
          changed = true;
        }
    }
    for (unsigned int i = 0; i < n_gears; ++i)
      require(known[i], field::train_gear(i), "is not connected to gear 1 by any mesh");
  }
  rigid.resize(n_gears);
  for (unsigned int i = 0; i < n_gears; ++i)
    rigid[i] = speeds[i] / speeds[0];

  compile_meshes(train);
  double rigid_acceleration = 0.;
  std::vector<double> angle;
  nominal_forces =
      general
          ? solve_static_general(std::vector<double>(meshes.size(), 0.), rigid_acceleration, angle)
          : solve_static(std::vector<double>(meshes.size(), 0.), rigid_acceleration, angle);
}

void TorsionalModel::validate_mesh(const GearTrain& train, unsigned int m) const
{
  const Mesh& mesh = train.meshes[m];
  if (mesh.terms.empty())
  {
    require(!general, field::gear_mesh(m, "gears"),
            "a general train needs the terms of every mesh");
    require(mesh.driver < n_gears && mesh.driven < n_gears && mesh.driver != mesh.driven,
            field::gear_mesh(m, "gears"),
            "driver and driven must be two different gears of the train");
    require(mesh.driver_base_radius > 0., field::gear_mesh(m, "driver_base_radius"),
            "must be positive");
    require(mesh.driven_base_radius > 0., field::gear_mesh(m, "driven_base_radius"),
            "must be positive");
    require(mesh.driver_teeth > 0, field::gear_mesh(m, "driver_teeth"), "must be positive");
  }
  else
  {
    require(general && mesh.terms.size() <= 3, field::gear_mesh(m, "gears"),
            "a mesh joins at most two gears and a frame, in a general train");
    for (const MeshTerm& term : mesh.terms)
      require(term.dof < n_gears && std::isfinite(term.coefficient + term.friction_arm),
              field::gear_mesh(m, "gears"), "a term names no degree of freedom of the train");
    require(mesh.position_ratio > 0. && std::isfinite(mesh.position_ratio),
            field::gear_mesh(m, "gears"),
            "the mesh does not roll (no relative speed in its frame)");
  }
  require(mesh.contact_ratio >= 1. && mesh.contact_ratio < 4., field::gear_mesh(m, "contact_ratio"),
          "must lie in [1, 4), got " + std::to_string(mesh.contact_ratio));
  require(mesh.approach_ratio >= 0. && mesh.approach_ratio <= mesh.contact_ratio,
          field::gear_mesh(m, "approach_ratio"), "must lie in [0, contact ratio]");
  require(mesh.damping >= 0. && std::isfinite(mesh.damping), field::gear_mesh(m, "damping"),
          "must not be negative, got " + std::to_string(mesh.damping) + " N·s/m");
  require(mesh.friction_coefficient >= 0. && mesh.friction_coefficient < 1.,
          field::gear_mesh(m, "friction_coefficient"), "must lie in [0, 1)");
  require(mesh.driver_friction_arm >= 0. && mesh.driven_friction_arm >= 0.,
          field::gear_mesh(m, "friction_arms"), "must not be negative");
  // A default-constructed MeshStiffness is a zero constant: the caller forgot the source.
  require(mesh.stiffness.mean_stiffness(mesh.contact_ratio) > 0., field::gear_mesh(m, "stiffness"),
          "no positive mesh stiffness given");
  // A table with positions where no pair touches (a broken tooth, docs/faults.md): the linear
  // law F = k·δ + c·δ̇ would keep the damping force there and cannot separate; only the
  // nonlinear law (F = 0 while k = 0) represents it.
  require(mesh.nonlinear || !mesh.stiffness.loses_contact(), field::gear_mesh(m, "stiffness"),
          "the table has positions without contact (k = 0 from " +
              std::to_string(mesh.stiffness.first_lost_contact()) +
              " base pitches): the linear mesh law cannot separate the teeth there; use "
              "Simulation/mesh model = nonlinear");
  if (mesh.nonlinear)
  {
    check_nonlinear_mesh(*mesh.nonlinear, m);
    require(!mesh.nonlinear->back_stiffness ||
                mesh.nonlinear->back_stiffness->mean_stiffness(mesh.contact_ratio) > 0.,
            field::gear_mesh(m, "back_flank_stiffness"), "no positive back-flank stiffness given");
  }
}

void TorsionalModel::compile_meshes(const GearTrain& train)
{
  for (const Mesh& mesh : train.meshes)
  {
    CompiledMesh c;
    if (mesh.terms.empty())
    {
      // δ = r_a·φ_a − r_b·φ_b; the driven gear's term is written with negated radius and arm
      // so one loop serves both forms (negation is exact: the split path is unchanged).
      c.n_terms = 2;
      c.dof[0] = mesh.driver;
      c.dof[1] = mesh.driven;
      c.c[0] = mesh.driver_base_radius;
      c.c[1] = -mesh.driven_base_radius;
      c.arm[0] = mesh.driver_friction_arm;
      c.arm[1] = -mesh.driven_friction_arm;
      c.position_rate = speeds[mesh.driver] * mesh.driver_teeth / (2. * M_PI);
    }
    else
    {
      c.n_terms = mesh.terms.size();
      for (unsigned int i = 0; i < c.n_terms; ++i)
      {
        c.dof[i] = mesh.terms[i].dof;
        c.c[i] = mesh.terms[i].coefficient;
        c.arm[i] = mesh.terms[i].friction_arm;
      }
      c.position_rate = mesh.position_ratio * train.input_speed;
    }
    c.damping = mesh.damping;
    c.mu = mesh.friction_coefficient;
    c.contact_ratio = mesh.contact_ratio;
    c.approach_ratio = mesh.approach_ratio;
    c.initial_position = mesh.initial_position;
    c.stiffness = mesh.stiffness;
    if (mesh.nonlinear)
    {
      c.nonlinear = any_nonlinear = true;
      c.backlash = mesh.nonlinear->backlash;
      c.transmission_error = mesh.nonlinear->transmission_error;
      c.mean_transmission_error = c.transmission_error.mean();
      // Symmetric teeth: the back flanks run the path of contact the other way.
      c.back_stiffness = mesh.nonlinear->back_stiffness
                             ? *mesh.nonlinear->back_stiffness
                             : mesh.stiffness.reversed(mesh.contact_ratio);
    }
    meshes.push_back(c);
  }
  cached_states.resize(meshes.size());
  cached_nonlinear.resize(meshes.size());
}

double TorsionalModel::deflection(const CompiledMesh& mesh, const double* angle) const
{
  double delta = mesh.c[0] * angle[mesh.dof[0]] + mesh.c[1] * angle[mesh.dof[1]];
  if (mesh.n_terms == 3)
    delta += mesh.c[2] * angle[mesh.dof[2]];
  return delta;
}

MeshStiffnessState TorsionalModel::mesh_state(const CompiledMesh& mesh, double time) const
{
  return mesh.stiffness.evaluate(mesh.initial_position + mesh.position_rate * time,
                                 mesh.contact_ratio, mesh.approach_ratio);
}

void TorsionalModel::update_cache(double time) const
{
  // RK4 evaluates twice at t + h/2, and its last stage at t + h is usually the next step's
  // first: the mesh states of the last time are reused (same time, same values: exact).
  if (time == cached_time)
    return;
  for (std::size_t m = 0; m < meshes.size(); ++m)
  {
    const CompiledMesh& mesh = meshes[m];
    const double x = mesh.initial_position + mesh.position_rate * time;
    // Without friction the direction is not needed (forces only): the stiffness alone.
    cached_states[m] = mesh.mu == 0.
                           ? MeshStiffnessState{mesh.stiffness.stiffness(x, mesh.contact_ratio), 0.}
                           : mesh_state(mesh, time);
    if (mesh.nonlinear)
      cached_nonlinear[m] = {mesh.transmission_error.value(x),
                             mesh.transmission_error.slope(x) * mesh.position_rate,
                             mesh.back_stiffness.stiffness(x, mesh.contact_ratio)};
  }
  cached_time = time;
}

namespace
{
// The mesh force of nonlinear_mesh.h from δ, δ̇ [m, m/s] and the instant's k, e, ė, k_back;
// `in_drive_contact` tells whether tooth friction acts (back-flank friction is neglected).
inline double nonlinear_force(double stiffness, double damping, double backlash, double error,
                              double error_rate, double back_stiffness, double delta, double rate,
                              bool& in_drive_contact)
{
  // k = 0: no pair touches at this position (a broken tooth's table, docs/faults.md), so the
  // flanks are apart whatever z: no force, no damping.
  const double z = delta - error;
  in_drive_contact = z > 0. && stiffness > 0.;
  if (z > 0.)
    return stiffness > 0. ? stiffness * z + damping * (rate - error_rate) : 0.;
  if (z < -backlash)
    return back_stiffness > 0. ? back_stiffness * (z + backlash) + damping * (rate - error_rate)
                               : 0.;
  return 0.;
}
} // namespace

void TorsionalModel::acceleration(double time, const double* angle, const double* velocity,
                                  double* result) const
{
  for (unsigned int i = 0; i < n_gears; ++i)
    result[i] = torques[i];
  for (const Suspension& suspension : suspensions)
    result[suspension.dof] -= suspension.stiffness * angle[suspension.dof] +
                              suspension.damping * velocity[suspension.dof];
  update_cache(time);
  // Always three terms, without branches: a pair's unused third term has c = arm = 0 on DOF 0,
  // which adds exact zeros (compile_meshes).
  for (std::size_t m = 0; m < meshes.size(); ++m)
  {
    const CompiledMesh& mesh = meshes[m];
    const MeshStiffnessState& state = cached_states[m];
    const unsigned int* dof = mesh.dof;
    const double* c = mesh.c;
    const double delta = c[0] * angle[dof[0]] + c[1] * angle[dof[1]] + c[2] * angle[dof[2]];
    const double rate = c[0] * velocity[dof[0]] + c[1] * velocity[dof[1]] + c[2] * velocity[dof[2]];
    double force, friction = mesh.mu * state.friction_direction;
    if (!mesh.nonlinear)
      force = state.stiffness * delta + mesh.damping * rate;
    else
    {
      const NonlinearState& n = cached_nonlinear[m];
      bool drive = true;
      force = nonlinear_force(state.stiffness, mesh.damping, mesh.backlash, n.error, n.error_rate,
                              n.back_stiffness, delta, rate, drive);
      friction = drive ? friction : 0.;
    }
    for (unsigned int i = 0; i < 3; ++i)
      result[dof[i]] -= (c[i] + friction * mesh.arm[i]) * force;
  }
  for (unsigned int i = 0; i < n_gears; ++i)
    result[i] *= inverse_inertia[i];
}

void TorsionalModel::flank_approach(double time, const double* angle, const double* velocity,
                                    double* approach, double* approach_rate) const
{
  update_cache(time);
  for (std::size_t m = 0; m < meshes.size(); ++m)
    if (meshes[m].nonlinear)
    {
      approach[m] = deflection(meshes[m], angle) - cached_nonlinear[m].error;
      approach_rate[m] = deflection(meshes[m], velocity) - cached_nonlinear[m].error_rate;
    }
}

double TorsionalModel::highest_excitation_order() const
{
  double order = 0.;
  for (const CompiledMesh& mesh : meshes)
    if (mesh.nonlinear)
      order = std::max(order, mesh.transmission_error.highest_order());
  return order;
}

double TorsionalModel::largest_stiffness(const CompiledMesh& mesh) const
{
  const double k = mesh.stiffness.max_stiffness(mesh.contact_ratio);
  return mesh.nonlinear ? std::max(k, mesh.back_stiffness.max_stiffness(mesh.contact_ratio)) : k;
}

MeshResponse TorsionalModel::mesh_response(unsigned int m, double time, const double* angle,
                                           const double* velocity) const
{
  const CompiledMesh& mesh = meshes[m];
  const MeshStiffnessState state = mesh_state(mesh, time);
  MeshResponse response;
  response.position = mesh.initial_position + mesh.position_rate * time;
  response.stiffness = state.stiffness;
  response.friction_direction = state.friction_direction;
  response.deflection = deflection(mesh, angle);
  response.deflection_rate = deflection(mesh, velocity);
  if (!mesh.nonlinear)
  {
    response.force =
        state.stiffness * response.deflection + mesh.damping * response.deflection_rate;
    return response;
  }
  const double x = response.position;
  const double error = mesh.transmission_error.value(x);
  bool drive = true;
  response.force = nonlinear_force(state.stiffness, mesh.damping, mesh.backlash, error,
                                   mesh.transmission_error.slope(x) * mesh.position_rate,
                                   mesh.back_stiffness.stiffness(x, mesh.contact_ratio),
                                   response.deflection, response.deflection_rate, drive);
  response.transmission_error = error;
  response.regime = contact_regime(response.deflection - error, mesh.backlash);
  if (response.regime == ContactRegime::drive && !(state.stiffness > 0.))
    response.regime = ContactRegime::separated; // no pair touches here (k = 0)
  return response;
}

void TorsionalModel::assemble(const std::vector<double>& k, const std::vector<double>& sigma,
                              Eigen::MatrixXd& K, Eigen::MatrixXd& C) const
{
  K.setZero(n_gears, n_gears);
  C.setZero(n_gears, n_gears);
  for (unsigned int m = 0; m < meshes.size(); ++m)
  {
    const CompiledMesh& mesh = meshes[m];
    Eigen::VectorXd g = Eigen::VectorXd::Zero(n_gears);
    Eigen::VectorXd h = Eigen::VectorXd::Zero(n_gears);
    const double friction = mesh.mu * sigma[m];
    for (unsigned int i = 0; i < mesh.n_terms; ++i)
    {
      g[mesh.dof[i]] += mesh.c[i] + friction * mesh.arm[i];
      h[mesh.dof[i]] += mesh.c[i];
    }
    K += k[m] * g * h.transpose();
    C += mesh.damping * g * h.transpose();
  }
  for (const Suspension& suspension : suspensions)
  {
    K(suspension.dof, suspension.dof) += suspension.stiffness;
    C(suspension.dof, suspension.dof) += suspension.damping;
  }
}

void TorsionalModel::linearization(double time, Eigen::MatrixXd& K, Eigen::MatrixXd& C) const
{
  std::vector<double> k(meshes.size()), sigma(meshes.size());
  for (unsigned int m = 0; m < meshes.size(); ++m)
  {
    const MeshStiffnessState state = mesh_state(meshes[m], time);
    k[m] = state.stiffness;
    sigma[m] = state.friction_direction;
  }
  assemble(k, sigma, K, C);
}

std::vector<double> TorsionalModel::solve_static(const std::vector<double>& sigma,
                                                 double& rigid_acceleration,
                                                 std::vector<double>& angle_out) const
{
  // Unknowns: the mesh forces and the rigid-mode acceleration a0 (zero when the torques
  // balance). A tree of n gears has n − 1 meshes, so G·F + M·v0·a0 = T is square.
  const unsigned int n_mesh = meshes.size();
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(n_gears, n_gears);
  for (unsigned int m = 0; m < n_mesh; ++m)
  {
    const CompiledMesh& mesh = meshes[m];
    const double friction = mesh.mu * sigma[m];
    system(mesh.dof[0], m) = mesh.c[0] + friction * mesh.arm[0];
    system(mesh.dof[1], m) = mesh.c[1] + friction * mesh.arm[1];
  }
  system.col(n_mesh) = inertia.cwiseProduct(rigid);
  Eigen::FullPivLU<Eigen::MatrixXd> lu(system);
  if (!lu.isInvertible())
    throw SolverFailure("static deflection", "the torque balance of the train is singular");
  const Eigen::VectorXd solution = lu.solve(torques);
  std::vector<double> forces(solution.data(), solution.data() + n_mesh);
  rigid_acceleration = solution[n_mesh];

  // Angles from the deflections δ_m = F_m/k_mean plus "no rigid-mode component".
  Eigen::MatrixXd kinematic = Eigen::MatrixXd::Zero(n_gears, n_gears);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n_gears);
  for (unsigned int m = 0; m < n_mesh; ++m)
  {
    const CompiledMesh& mesh = meshes[m];
    kinematic(m, mesh.dof[0]) = mesh.c[0];
    kinematic(m, mesh.dof[1]) = mesh.c[1];
    rhs[m] = forces[m] / mesh.stiffness.mean_stiffness(mesh.contact_ratio) +
             mesh.mean_transmission_error;
  }
  kinematic.row(n_mesh) = inertia.cwiseProduct(rigid).transpose();
  const Eigen::VectorXd angle = kinematic.fullPivLu().solve(rhs);
  angle_out.assign(angle.data(), angle.data() + n_gears);
  return forces;
}

std::vector<double> TorsionalModel::solve_static_general(const std::vector<double>& sigma,
                                                         double& rigid_acceleration,
                                                         std::vector<double>& angle_out) const
{
  // K·φ + M·v0·a0 = T with v0ᵀ·M·φ = 0 (no rigid-mode component): square and regular when
  // the meshes hold every rotation but the rigid mode. The mesh forces follow from φ.
  std::vector<double> k(meshes.size());
  for (unsigned int m = 0; m < meshes.size(); ++m)
    k[m] = meshes[m].stiffness.mean_stiffness(meshes[m].contact_ratio);
  Eigen::MatrixXd K, C;
  assemble(k, sigma, K, C);
  const bool has_rigid_mode =
      suspensions.empty() || std::all_of(suspensions.begin(), suspensions.end(),
                                         [&](const Suspension& s) { return rigid[s.dof] == 0.; });
  const unsigned int size = n_gears + (has_rigid_mode ? 1 : 0);
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(size, size);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(size);
  system.topLeftCorner(n_gears, n_gears) = K;
  rhs.head(n_gears) = torques;
  // The mean unloaded TE e of a nonlinear mesh: F = k·(δ − e) adds k·e·g to the load side.
  for (unsigned int m = 0; m < meshes.size(); ++m)
    for (unsigned int i = 0; meshes[m].nonlinear && i < meshes[m].n_terms; ++i)
      rhs[meshes[m].dof[i]] += k[m] * meshes[m].mean_transmission_error *
                               (meshes[m].c[i] + meshes[m].mu * sigma[m] * meshes[m].arm[i]);
  if (has_rigid_mode)
  {
    const Eigen::VectorXd momentum = inertia.cwiseProduct(rigid);
    system.block(0, n_gears, n_gears, 1) = momentum;
    system.block(n_gears, 0, 1, n_gears) = momentum.transpose();
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(system);
  if (!lu.isInvertible())
    throw SolverFailure("static deflection",
                        "the meshes do not hold the train: a rotation other than the nominal "
                        "one has no stiffness (a member without a mesh?)");
  const Eigen::VectorXd solution = lu.solve(rhs);
  angle_out.assign(solution.data(), solution.data() + n_gears);
  rigid_acceleration = has_rigid_mode ? solution[n_gears] : 0.;
  std::vector<double> forces(meshes.size());
  for (unsigned int m = 0; m < meshes.size(); ++m)
    forces[m] =
        k[m] * (deflection(meshes[m], angle_out.data()) - meshes[m].mean_transmission_error);
  return forces;
}

StaticState TorsionalModel::static_state(bool include_friction) const
{
  std::vector<double> sigma(meshes.size(), 0.);
  if (include_friction)
    for (unsigned int m = 0; m < meshes.size(); ++m)
      sigma[m] = meshes[m].stiffness.mean_friction_direction(meshes[m].contact_ratio,
                                                             meshes[m].approach_ratio);
  StaticState state;
  state.mesh_force = general ? solve_static_general(sigma, state.rigid_acceleration, state.angle)
                             : solve_static(sigma, state.rigid_acceleration, state.angle);
  for (unsigned int m = 0; m < meshes.size(); ++m)
    state.deflection.push_back(state.mesh_force[m] /
                                   meshes[m].stiffness.mean_stiffness(meshes[m].contact_ratio) +
                               meshes[m].mean_transmission_error);
  return state;
}

ModalProperties TorsionalModel::modal_properties() const
{
  std::vector<double> k(meshes.size()), sigma(meshes.size(), 0.);
  for (unsigned int m = 0; m < meshes.size(); ++m)
    k[m] = meshes[m].stiffness.mean_stiffness(meshes[m].contact_ratio);
  Eigen::MatrixXd K, C;
  assemble(k, sigma, K, C);
  const Eigen::MatrixXd Minv = inertia.cwiseInverse().asDiagonal();

  ModalProperties modes;
  const Eigen::VectorXcd undamped = (Minv * K).eigenvalues();
  double largest = 0.;
  for (const auto& value : undamped)
    largest = std::max(largest, std::abs(value));
  for (const auto& value : undamped)
    if (std::abs(value) > 1e-9 * largest) // the rigid mode has eigenvalue 0
      modes.natural_frequencies.push_back(std::sqrt(std::abs(value)) / (2. * M_PI));
  std::sort(modes.natural_frequencies.begin(), modes.natural_frequencies.end());

  const Eigen::VectorXcd damped = state_matrix(K, C).eigenvalues();
  double largest_damped = 0.;
  for (const auto& value : damped)
    largest_damped = std::max(largest_damped, std::abs(value));
  // Without damping the real parts are round-off of either sign, ~1e-13·|λ|: a "decay rate"
  // from them would make the automatic window wait for ever (issue 11), so anything below
  // 1e-9·|λ| is no decay.
  for (const auto& value : damped)
    if (std::abs(value) > rigid_mode_threshold * largest_damped && value.imag() >= 0.)
      modes.decay_rates.push_back(-value.real() > 1e-9 * std::abs(value) ? -value.real() : 0.);
  std::sort(modes.decay_rates.begin(), modes.decay_rates.end());
  return modes;
}

void TorsionalModel::assemble_at_largest_stiffness(Eigen::MatrixXd& K, Eigen::MatrixXd& C) const
{
  std::vector<double> k(meshes.size()), sigma(meshes.size(), 1.);
  for (unsigned int m = 0; m < meshes.size(); ++m)
    k[m] = largest_stiffness(meshes[m]);
  assemble(k, sigma, K, C);
}

Eigen::MatrixXd TorsionalModel::state_matrix(const Eigen::MatrixXd& K,
                                             const Eigen::MatrixXd& C) const
{
  const Eigen::MatrixXd Minv = inertia.cwiseInverse().asDiagonal();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n_gears, 2 * n_gears);
  A.topRightCorner(n_gears, n_gears).setIdentity();
  A.bottomLeftCorner(n_gears, n_gears) = -Minv * K;
  A.bottomRightCorner(n_gears, n_gears) = -Minv * C;
  return A;
}

double TorsionalModel::highest_natural_frequency() const
{
  Eigen::MatrixXd K, C;
  assemble_at_largest_stiffness(K, C);
  const Eigen::VectorXcd values = (inertia.cwiseInverse().asDiagonal() * K).eigenvalues();
  double largest = 0.;
  for (const auto& value : values)
    largest = std::max(largest, std::abs(value));
  return std::sqrt(largest);
}

double TorsionalModel::rk4_limit_for(const Eigen::MatrixXd& K, const Eigen::MatrixXd& C) const
{
  const Eigen::VectorXcd values = state_matrix(K, C).eigenvalues();
  double largest = 0.;
  for (const auto& value : values)
    largest = std::max(largest, std::abs(value));

  // Along each ray z = h·λ find where |R(z)| first exceeds 1 (the RK4 region is bounded by
  // |z| < 3 in every direction): a coarse scan, then bisection. The tolerance 1e-9 ignores
  // the round-off real part of an undamped eigenvalue, which is ~1e-13 of its size.
  double limit = std::numeric_limits<double>::infinity();
  for (const auto& value : values)
  {
    const double size = std::abs(value);
    if (size < rigid_mode_threshold * largest)
      continue; // rigid mode
    const std::complex<double> direction = value / size;
    double stable = 0., unstable = 0.;
    for (double t = 0.01; t < 4.; t += 0.01)
      if (rk4_amplification(t * direction) > 1. + 1e-9)
      {
        unstable = t;
        break;
      }
      else
        stable = t;
    if (unstable == 0.)
      continue;
    for (int i = 0; i < 60; ++i)
    {
      const double middle = 0.5 * (stable + unstable);
      (rk4_amplification(middle * direction) > 1. + 1e-9 ? unstable : stable) = middle;
    }
    limit = std::min(limit, stable / size);
  }
  return limit;
}

double TorsionalModel::rk4_step_limit() const
{
  Eigen::MatrixXd K, C;
  assemble_at_largest_stiffness(K, C);
  return rk4_limit_for(K, C);
}

double TorsionalModel::vibration_energy(double time, const double* angle,
                                        const double* velocity) const
{
  const Eigen::Map<const Eigen::VectorXd> v(velocity, n_gears);
  const double rigid_speed =
      (rigid.cwiseProduct(inertia)).dot(v) / (rigid.cwiseProduct(inertia)).dot(rigid);
  const Eigen::VectorXd relative = v - rigid_speed * rigid;
  return 0.5 * relative.cwiseProduct(inertia).dot(relative) + strain_energy(time, angle);
}

double TorsionalModel::total_energy(double time, const double* angle, const double* velocity) const
{
  const Eigen::Map<const Eigen::VectorXd> v(velocity, n_gears);
  const Eigen::Map<const Eigen::VectorXd> phi(angle, n_gears);
  return 0.5 * v.cwiseProduct(inertia).dot(v) - torques.dot(phi) + strain_energy(time, angle);
}

double TorsionalModel::strain_energy(double time, const double* angle) const
{
  double energy = 0.;
  for (const CompiledMesh& mesh : meshes)
  {
    const double delta = deflection(mesh, angle);
    if (!mesh.nonlinear)
    {
      energy += 0.5 * mesh_state(mesh, time).stiffness * delta * delta;
      continue;
    }
    // ½·k·h(z)², with the flank in contact's stiffness.
    const double x = mesh.initial_position + mesh.position_rate * time;
    const double z = delta - mesh.transmission_error.value(x);
    const double elastic = backlash_function(z, mesh.backlash);
    const double k = z > 0. ? mesh.stiffness.stiffness(x, mesh.contact_ratio)
                            : mesh.back_stiffness.stiffness(x, mesh.contact_ratio);
    energy += 0.5 * k * elastic * elastic;
  }
  for (const Suspension& suspension : suspensions)
    energy += 0.5 * suspension.stiffness * angle[suspension.dof] * angle[suspension.dof];
  return energy;
}

Eigen::MatrixXd TorsionalModel::mean_stiffness_matrix() const
{
  std::vector<double> k(meshes.size()), sigma(meshes.size(), 0.);
  for (unsigned int m = 0; m < meshes.size(); ++m)
    k[m] = meshes[m].stiffness.mean_stiffness(meshes[m].contact_ratio);
  Eigen::MatrixXd K, C;
  assemble(k, sigma, K, C);
  return K;
}

ModeShapes TorsionalModel::mode_shapes() const
{
  const Eigen::MatrixXd K = mean_stiffness_matrix();
  const Eigen::MatrixXd M = inertia.asDiagonal();
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(0.5 * (K + K.transpose()), M);
  if (solver.info() != Eigen::Success)
    throw SolverFailure("modal analysis", "the generalised eigenproblem did not converge");
  ModeShapes modes;
  modes.frequencies = solver.eigenvalues().cwiseMax(0.).cwiseSqrt() / (2. * M_PI);
  modes.shapes = solver.eigenvectors();
  return modes;
}
} // namespace gearstiff::dynamics
