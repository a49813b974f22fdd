#include "dynamics/lateral_model.h"

#include "dynamics/fields.h"
#include "errors/errors.h"
#include "errors/format.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <sstream>

namespace gearstiff::dynamics
{
namespace
{
// The message numbers of errors/format.h, five significant digits unless told.
std::string format(double value, int digits = 5)
{
  return format_number(value, digits);
}

const LateralMember central_members[3] = {LateralMember::carrier, LateralMember::ring,
                                          LateralMember::sun};

const LateralCentralMember& member_data(const LateralStage& stage, LateralMember member)
{
  switch (member)
  {
  case LateralMember::carrier:
    return stage.carrier;
  case LateralMember::ring:
    return stage.ring;
  default:
    return stage.sun;
  }
}

void require_positive(double value, const std::string& parameter, const std::string& what)
{
  if (!(value > 0.) || !std::isfinite(value))
    throw InputError(parameter, what + " must be positive (is " + format(value) + ")");
}

void require_non_negative(double value, const std::string& parameter, const std::string& what)
{
  if (!(value >= 0.) || !std::isfinite(value))
    throw InputError(parameter, what + " must not be negative (is " + format(value) + ")");
}

// Angle wrapped to [0, 2π).
double wrap(double angle)
{
  const double turn = 2. * M_PI;
  return angle - turn * std::floor(angle / turn);
}
} // namespace

std::string lateral_member_name(LateralMember member)
{
  switch (member)
  {
  case LateralMember::carrier:
    return "carrier";
  case LateralMember::ring:
    return "ring";
  default:
    return "sun";
  }
}

std::string lateral_mode_class_name(LateralModeClass type)
{
  switch (type)
  {
  case LateralModeClass::rotational:
    return "rotational";
  case LateralModeClass::translational:
    return "translational";
  case LateralModeClass::planet:
    return "planet";
  default:
    return "mixed";
  }
}

void assemble_springs(const std::vector<LateralModel::Spring>& springs, unsigned int n,
                      Eigen::MatrixXd& stiffness, Eigen::MatrixXd& damping,
                      Eigen::VectorXd& preload_force)
{
  stiffness = Eigen::MatrixXd::Zero(n, n);
  damping = Eigen::MatrixXd::Zero(n, n);
  preload_force = Eigen::VectorXd::Zero(n);
  for (const LateralModel::Spring& s : springs)
    for (const auto& [i, vi] : s.terms)
    {
      preload_force[i] -= s.stiffness * s.preload * vi;
      for (const auto& [j, vj] : s.terms)
      {
        stiffness(i, j) += s.stiffness * vi * vj;
        damping(i, j) += s.damping * vi * vj;
      }
    }
}

std::vector<double> equally_spaced_angles(unsigned int planets)
{
  std::vector<double> angles(planets);
  for (unsigned int n = 0; n < planets; ++n)
    angles[n] = 2. * M_PI * n / planets;
  return angles;
}

namespace
{
void check_member_data(const LateralStage& stage)
{
  for (const LateralMember j : central_members)
  {
    const LateralCentralMember& m = member_data(stage, j);
    const std::string name = lateral_member_name(j);
    require_positive(m.mass, field::train("masses"), "the mass of the " + name);
    require_positive(m.radius,
                     j == LateralMember::carrier ? field::train("carrier_radii")
                                                 : field::train("base_diameters"),
                     "the radius of the " + name);
    if (!m.held)
      require_positive(m.moment_of_inertia, field::train("inertias"), "J of the " + name);
    require_non_negative(m.bearing_stiffness, field::train("bearing_stiffness"),
                         "the " + name + "'s");
    require_non_negative(m.bearing_damping, field::train("bearing_damping"), "the " + name + "'s");
    require_non_negative(m.torsional_stiffness, field::train("suspended_members"),
                         "the " + name + "'s");
    require_non_negative(m.torsional_damping, field::train("suspended_members"),
                         "the " + name + "'s");
  }
  require_positive(stage.planet_mass, field::train("masses"), "the planet mass");
  require_positive(stage.planet_moment_of_inertia, field::train("inertias"), "J of the planet");
  require_positive(stage.planet_base_radius, field::train("base_diameters"),
                   "the planet base radius");
  require_positive(stage.pin_stiffness, field::train("planet_pin_stiffness"), "the pin stiffness");
  require_non_negative(stage.pin_damping, field::train("planet_pin_stiffness"), "the pin damping");
  require_positive(stage.sun_mesh_stiffness, field::train_mesh(0, "stiffness"),
                   "the sun mesh stiffness");
  require_positive(stage.ring_mesh_stiffness, field::train_mesh(1, "stiffness"),
                   "the ring mesh stiffness");
  require_non_negative(stage.sun_mesh_damping, field::train_mesh(0, "damping"),
                       "the sun mesh damping");
  require_non_negative(stage.ring_mesh_damping, field::train_mesh(1, "damping"),
                       "the ring mesh damping");
  for (const double alpha : {stage.sun_pressure_angle, stage.ring_pressure_angle})
    if (!(alpha >= 0. && alpha < 0.5 * M_PI))
      throw InputError(field::train("pressure_angle"), "must lie in [0, 90) deg");
}

// Planets must not overlap: centres 2·r_c·sin(Δψ/2) apart, at least two tip radii; pin errors
// one per planet.
void check_planet_layout(const LateralStage& data)
{
  const unsigned int n_planet = data.planet_angles.size();
  const double tip = data.planet_tip_radius > 0.
                         ? data.planet_tip_radius
                         : data.planet_base_radius / std::cos(data.sun_pressure_angle);
  std::vector<double> sorted;
  for (const double psi : data.planet_angles)
    sorted.push_back(wrap(psi));
  std::sort(sorted.begin(), sorted.end());
  for (unsigned int n = 0; n < n_planet && n_planet > 1; ++n)
  {
    const double gap =
        n + 1 < n_planet ? sorted[n + 1] - sorted[n] : sorted.front() + 2. * M_PI - sorted.back();
    const double distance = 2. * data.carrier.radius * std::sin(0.5 * gap);
    if (distance <= 2. * tip)
      throw InputError(field::train("planet_angles"),
                       "planets at " + format(sorted[n] * 180. / M_PI) + " and " +
                           format(sorted[(n + 1) % n_planet] * 180. / M_PI) +
                           " deg collide: centres " + format(distance * 1e3) +
                           " mm apart, tip circles need " + format(2e3 * tip) + " mm");
  }
  for (const auto* errors : {&data.pin_error_tangential, &data.pin_error_radial})
  {
    if (!errors->empty() && errors->size() != n_planet)
      throw InputError(field::train("planet_pin_errors"),
                       "needs one value per planet (" + std::to_string(n_planet) + ")");
    for (const double e : *errors)
      if (!std::isfinite(e))
        throw InputError(field::train("planet_pin_errors"), "must be finite");
  }
}

// Bearings and torsional supports of the central members.
void add_support_springs(const LateralStage& stage, std::vector<LateralModel::Spring>& springs)
{
  for (const LateralMember j : central_members)
  {
    const LateralCentralMember& m = member_data(stage, j);
    for (unsigned int c = 0; c < 2; ++c)
      if (m.bearing_stiffness > 0. || m.bearing_damping > 0.)
        springs.push_back({0,
                           0,
                           m.bearing_stiffness,
                           m.bearing_damping,
                           0.,
                           {{LateralModel::central_dof(j, c), 1.}}});
    if (!m.held && (m.torsional_stiffness > 0. || m.torsional_damping > 0.))
    {
      const double r2 = m.radius * m.radius;
      springs.push_back({1,
                         0,
                         m.torsional_stiffness / r2,
                         m.torsional_damping / r2,
                         0.,
                         {{LateralModel::central_dof(j, 2), 1.}}});
    }
  }
}

// Planet p's radial and tangential pins (the header's deflections).
void add_pin_springs(const LateralStage& stage, unsigned int p,
                     std::vector<LateralModel::Spring>& springs)
{
  const double psi = stage.planet_angles[p];
  const double et = stage.pin_error_tangential.empty() ? 0. : stage.pin_error_tangential[p];
  const double er = stage.pin_error_radial.empty() ? 0. : stage.pin_error_radial[p];
  const unsigned int xc = LateralModel::central_dof(LateralMember::carrier, 0),
                     yc = LateralModel::central_dof(LateralMember::carrier, 1),
                     uc = LateralModel::central_dof(LateralMember::carrier, 2);
  const unsigned int zeta = LateralModel::planet_dof(p, 0), eta = LateralModel::planet_dof(p, 1);
  springs.push_back({2,
                     p,
                     stage.pin_stiffness,
                     stage.pin_damping,
                     er,
                     {{xc, std::cos(psi)}, {yc, std::sin(psi)}, {zeta, -1.}}});
  springs.push_back({2,
                     p,
                     stage.pin_stiffness,
                     stage.pin_damping,
                     et,
                     {{xc, -std::sin(psi)}, {yc, std::cos(psi)}, {uc, 1.}, {eta, -1.}}});
}

// Planet p's sun mesh (sun = true) or ring mesh along its line of action.
LateralModel::Spring mesh_spring(const LateralStage& stage, unsigned int p, bool sun)
{
  const double alpha = sun ? stage.sun_pressure_angle : stage.ring_pressure_angle;
  const double psi = stage.planet_angles[p] + (sun ? -alpha : alpha); // ψ_sn, ψ_rn
  const LateralMember j = sun ? LateralMember::sun : LateralMember::ring;
  const double side = sun ? 1. : -1.; // the planet's ζ and u enter with opposite signs
  return {sun ? 3u : 4u,
          p,
          sun ? stage.sun_mesh_stiffness : stage.ring_mesh_stiffness,
          sun ? stage.sun_mesh_damping : stage.ring_mesh_damping,
          0.,
          {{LateralModel::central_dof(j, 0), -std::sin(psi)},
           {LateralModel::central_dof(j, 1), std::cos(psi)},
           {LateralModel::central_dof(j, 2), 1.},
           {LateralModel::planet_dof(p, 0), -side * std::sin(alpha)},
           {LateralModel::planet_dof(p, 1), -std::cos(alpha)},
           {LateralModel::planet_dof(p, 2), side}}};
}

// A translation that nothing holds (zero bearing stiffness where no mesh or pin restrains the
// stage as a whole) makes the stage drift: refuse it, naming the member that moves most.
void refuse_free_translation(const LateralModes& free_modes)
{
  for (Eigen::Index k = 0; k < free_modes.frequencies.size(); ++k)
  {
    if (free_modes.frequencies[k] > 0.)
      break;
    double translation = 0., largest = 0.;
    unsigned int body = 0;
    // Central members only: the stage's rigid rotation carries the planets tangentially.
    for (unsigned int b = 0; b < 3; ++b)
    {
      translation += free_modes.kinetic_energy_share(k, 2 * b);
      if (free_modes.kinetic_energy_share(k, 2 * b) > largest)
      {
        largest = free_modes.kinetic_energy_share(k, 2 * b);
        body = b;
      }
    }
    if (translation > 1e-6)
      throw InputError(field::train("bearing_stiffness"),
                       "the " + lateral_member_name(LateralMember(body)) +
                           " translates freely: zero bearing stiffness with nothing else "
                           "holding the stage in x and y");
  }
}
} // namespace

LateralModel::LateralModel(const LateralStage& stage)
    : data(stage), n_planet(static_cast<unsigned int>(stage.planet_angles.size()))
{
  if (n_planet < 1)
    throw InputError(field::train("planets"), "the lateral model needs at least one planet");
  check_member_data(stage);
  check_planet_layout(stage);

  const unsigned int n = n_dofs();
  mass_diagonal.resize(n);
  for (const LateralMember j : central_members)
  {
    const LateralCentralMember& m = member_data(stage, j);
    mass_diagonal[central_dof(j, 0)] = m.mass;
    mass_diagonal[central_dof(j, 1)] = m.mass;
    mass_diagonal[central_dof(j, 2)] = m.moment_of_inertia / (m.radius * m.radius);
  }
  for (unsigned int p = 0; p < n_planet; ++p)
  {
    mass_diagonal[planet_dof(p, 0)] = stage.planet_mass;
    mass_diagonal[planet_dof(p, 1)] = stage.planet_mass;
    mass_diagonal[planet_dof(p, 2)] =
        stage.planet_moment_of_inertia / (stage.planet_base_radius * stage.planet_base_radius);
  }
  for (unsigned int i = 0; i < n; ++i)
    if (!(i % 3 == 2 && i < 9 && member_data(stage, LateralMember(i / 3)).held))
      free.push_back(i);

  add_support_springs(stage, spring_list);
  for (unsigned int p = 0; p < n_planet; ++p)
  {
    add_pin_springs(stage, p, spring_list);
    sun_mesh_spring.push_back(spring_list.size());
    spring_list.push_back(mesh_spring(stage, p, true));
    ring_mesh_spring.push_back(spring_list.size());
    spring_list.push_back(mesh_spring(stage, p, false));
  }
  assemble_springs(spring_list, n, stiffness_matrix, damping_matrix, error_force);
  refuse_free_translation(modes());
}

std::string LateralModel::dof_name(unsigned int dof) const
{
  static const char* central_names[3] = {"x", "y", "u"};
  static const char* planet_names[3] = {"zeta", "eta", "u"};
  if (dof < 9)
    return lateral_member_name(LateralMember(dof / 3)) + " " + central_names[dof % 3];
  return "planet " + std::to_string((dof - 9) / 3 + 1) + " " + planet_names[(dof - 9) % 3];
}

Eigen::MatrixXd LateralModel::gyroscopic() const
{
  // Per body, with (x, y) in the frame turning at Ω: m(ẍ − 2Ωẏ − Ω²x), m(ÿ + 2Ωẋ − Ω²y)
  // (Cooley & Parker 2012), planets likewise in (ζ, η).
  const unsigned int n = n_dofs();
  Eigen::MatrixXd g = Eigen::MatrixXd::Zero(n, n);
  for (unsigned int b = 0; b < n / 3; ++b)
  {
    g(3 * b, 3 * b + 1) = -2. * mass_diagonal[3 * b];
    g(3 * b + 1, 3 * b) = 2. * mass_diagonal[3 * b];
  }
  return g;
}

Eigen::MatrixXd LateralModel::centripetal() const
{
  const unsigned int n = n_dofs();
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  for (unsigned int b = 0; b < n / 3; ++b)
    k(3 * b, 3 * b) = k(3 * b + 1, 3 * b + 1) = mass_diagonal[3 * b];
  return k;
}

double LateralModel::deflection(const Spring& spring, const double* q) const
{
  double d = spring.preload;
  for (const auto& [i, v] : spring.terms)
    d += v * q[i];
  return d;
}

double LateralModel::sun_mesh_deflection(unsigned int planet, const double* q) const
{
  return deflection(spring_list[sun_mesh_spring[planet]], q);
}

double LateralModel::ring_mesh_deflection(unsigned int planet, const double* q) const
{
  return deflection(spring_list[ring_mesh_spring[planet]], q);
}

std::vector<LateralModeGroup> classify_mode_groups(const Eigen::VectorXd& frequencies,
                                                   const Eigen::MatrixXd& kinetic_energy_share,
                                                   const std::vector<unsigned int>& central,
                                                   double relative_tolerance, double largest)
{
  std::vector<LateralModeGroup> groups;
  const unsigned int nf = frequencies.size();
  for (unsigned int k = 0; k < nf;)
  {
    unsigned int end = k + 1;
    const double lk = frequencies[k] * frequencies[k];
    while (end < nf)
    {
      const double le = frequencies[end] * frequencies[end];
      if (std::abs(le - lk) >
          relative_tolerance * std::max(le, 1e-9 * largest / (4. * M_PI * M_PI)))
        break;
      ++end;
    }
    LateralModeGroup group;
    double translation = 0., rotation = 0., frequency = 0.;
    for (unsigned int m = k; m < end; ++m)
    {
      group.modes.push_back(m);
      frequency += frequencies[m];
      for (const unsigned int b : central)
      {
        translation += kinetic_energy_share(m, 2 * b);
        rotation += kinetic_energy_share(m, 2 * b + 1);
      }
    }
    group.frequency = frequency / (end - k);
    // Exact classes have exactly zero central energy; 1e-9 of the group's energy is far above
    // the eigenvectors' round-off (~1e-26 in energy) and far below any physical coupling.
    const double zero = 1e-9 * (end - k);
    group.type = translation < zero && rotation < zero ? LateralModeClass::planet
                 : translation < zero                  ? LateralModeClass::rotational
                 : rotation < zero                     ? LateralModeClass::translational
                                                       : LateralModeClass::mixed;
    groups.push_back(group);
    k = end;
  }
  return groups;
}

namespace
{
// Groups of equal frequency and their class, judged on the whole group (a degenerate pair's
// basis is arbitrary, its subspace is not): central members' translation and rotation energy.
std::vector<LateralModeGroup> classify_modes(const LateralModes& result, double relative_tolerance,
                                             double largest)
{
  return classify_mode_groups(result.frequencies, result.kinetic_energy_share, {0, 1, 2},
                              relative_tolerance, largest);
}
} // namespace

// Kinetic energy per body and DOF type, strain energy per spring group, of every mode.
void LateralModel::modal_energies(LateralModes& result) const
{
  const unsigned int nf = free.size(), n = n_dofs();
  const unsigned int n_bodies = 3 + n_planet;
  result.kinetic_energy_share = Eigen::MatrixXd::Zero(nf, 2 * n_bodies);
  result.strain_energy_share = Eigen::MatrixXd::Zero(nf, n_spring_groups);
  for (unsigned int k = 0; k < nf; ++k)
  {
    const Eigen::VectorXd v = result.shapes.col(k);
    for (unsigned int i = 0; i < n; ++i)
      result.kinetic_energy_share(k, 2 * (i / 3) + (i % 3 == 2 ? 1 : 0)) +=
          mass_diagonal[i] * v[i] * v[i];
    result.kinetic_energy_share.row(k) /= result.kinetic_energy_share.row(k).sum();
    double total = 0.;
    for (const Spring& s : spring_list)
    {
      double d = 0.;
      for (const auto& [i, c] : s.terms)
        d += c * v[i];
      const double energy = 0.5 * s.stiffness * d * d;
      result.strain_energy_share(k, s.group) += energy;
      total += energy;
    }
    if (result.frequencies[k] > 0. && total > 0.)
      result.strain_energy_share.row(k) /= total;
    else
      result.strain_energy_share.row(k).setZero();
  }
}

double undamped_modes(const Eigen::VectorXd& mass, const Eigen::MatrixXd& stiffness,
                      const std::vector<unsigned int>& free, Eigen::VectorXd& frequencies,
                      Eigen::MatrixXd& shapes)
{
  const unsigned int nf = free.size();
  Eigen::VectorXd scale(nf); // M^(-1/2)
  Eigen::MatrixXd a(nf, nf);
  for (unsigned int i = 0; i < nf; ++i)
    scale[i] = 1. / std::sqrt(mass[free[i]]);
  for (unsigned int i = 0; i < nf; ++i)
    for (unsigned int j = 0; j < nf; ++j)
      a(i, j) = scale[i] * stiffness(free[i], free[j]) * scale[j];
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(a);
  if (solver.info() != Eigen::Success)
    throw SolverFailure("lateral modes", "the symmetric eigensolver did not converge");
  const Eigen::VectorXd& lambda = solver.eigenvalues();
  const double largest = std::max(lambda.cwiseAbs().maxCoeff(), 1e-300);
  frequencies.resize(nf);
  shapes = Eigen::MatrixXd::Zero(mass.size(), nf);
  for (unsigned int k = 0; k < nf; ++k)
  {
    // Eigenvalues of a positive semi-definite K below round-off count as rigid-body modes.
    const double l = lambda[k] > 1e-11 * largest ? lambda[k] : 0.;
    frequencies[k] = std::sqrt(l) / (2. * M_PI);
    for (unsigned int i = 0; i < nf; ++i)
      shapes(free[i], k) = scale[i] * solver.eigenvectors()(i, k);
  }
  return largest;
}

LateralModes LateralModel::modes(double relative_tolerance) const
{
  LateralModes result;
  const double largest =
      undamped_modes(mass_diagonal, stiffness_matrix, free, result.frequencies, result.shapes);
  modal_energies(result);
  result.groups = classify_modes(result, relative_tolerance, largest);
  return result;
}

namespace
{
// Eigenvalues of the first-order form [q; q̇]' = A [q; q̇] of the free coordinates.
Eigen::VectorXcd first_order_eigenvalues(const Eigen::VectorXd& mass_diagonal,
                                         const Eigen::MatrixXd& stiffness_matrix,
                                         const Eigen::MatrixXd& g, const Eigen::MatrixXd& kc,
                                         const std::vector<unsigned int>& free,
                                         double carrier_speed)
{
  const unsigned int nf = free.size();
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * nf, 2 * nf);
  for (unsigned int i = 0; i < nf; ++i)
  {
    a(i, nf + i) = 1.;
    const double inverse_mass = 1. / mass_diagonal[free[i]];
    for (unsigned int j = 0; j < nf; ++j)
    {
      const unsigned int fi = free[i], fj = free[j];
      a(nf + i, j) =
          -inverse_mass * (stiffness_matrix(fi, fj) - carrier_speed * carrier_speed * kc(fi, fj));
      a(nf + i, nf + j) = -inverse_mass * carrier_speed * g(fi, fj);
    }
  }
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(a, false);
  if (solver.info() != Eigen::Success)
    throw SolverFailure("lateral gyroscopic modes", "the eigensolver did not converge");
  return solver.eigenvalues();
}
} // namespace

std::vector<double> LateralModel::gyroscopic_frequencies(double carrier_speed) const
{
  const Eigen::VectorXcd roots = first_order_eigenvalues(
      mass_diagonal, stiffness_matrix, gyroscopic(), centripetal(), free, carrier_speed);
  std::vector<double> all;
  for (Eigen::Index i = 0; i < roots.size(); ++i)
    all.push_back(std::abs(roots[i].imag()) / (2. * M_PI));
  std::sort(all.begin(), all.end());
  // Each frequency appears as a conjugate pair (a divergent or rigid mode as two real roots).
  std::vector<double> frequencies;
  for (std::size_t i = 0; i < all.size(); i += 2)
    frequencies.push_back(0.5 * (all[i] + all[i + 1]));
  return frequencies;
}

GyroscopicStability LateralModel::gyroscopic_stability(double carrier_speed) const
{
  const Eigen::MatrixXd g = gyroscopic(), kc = centripetal();
  const Eigen::VectorXcd roots =
      first_order_eigenvalues(mass_diagonal, stiffness_matrix, g, kc, free, carrier_speed);
  const Eigen::VectorXcd still =
      first_order_eigenvalues(mass_diagonal, stiffness_matrix, g, kc, free, 0.);
  double largest = 0.;
  for (Eigen::Index i = 0; i < still.size(); ++i)
    largest = std::max(largest, std::abs(still[i]));
  // The rigid rotation's double zero root turns into a real pair ±a·Ω with the carrier turning
  // (a ≈ 0.46 on Lin & Parker's stage, whatever the pins): a drift of the free rotation, not an
  // instability of the elastic stage. The roots that are zero at standstill are set aside, the
  // smallest |λ| at this speed standing for them.
  std::size_t rigid = 0;
  for (Eigen::Index i = 0; i < still.size(); ++i)
    rigid += std::abs(still[i]) <= 1e-5 * largest;
  std::vector<std::complex<double>> sorted(roots.data(), roots.data() + roots.size());
  std::sort(sorted.begin(), sorted.end(),
            [](const std::complex<double>& a, const std::complex<double>& b)
            { return std::abs(a) < std::abs(b); });
  GyroscopicStability result;
  for (std::size_t i = rigid; i < sorted.size(); ++i)
    if (sorted[i].real() > 1e-5 * largest && sorted[i].real() > result.growth_rate)
    {
      result.stable = false;
      result.growth_rate = sorted[i].real();
      result.oscillating = std::abs(sorted[i].imag()) > 1e-5 * largest;
    }
  return result;
}

Eigen::VectorXd constrained_deflection(const Eigen::VectorXd& mass,
                                       const Eigen::MatrixXd& stiffness,
                                       const std::vector<unsigned int>& free,
                                       const Eigen::VectorXd& f, const Eigen::VectorXd* rigid)
{
  const unsigned int nf = free.size();
  const unsigned int extra = rigid ? 1 : 0;
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(nf + extra, nf + extra);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nf + extra);
  for (unsigned int i = 0; i < nf; ++i)
  {
    rhs[i] = f[free[i]];
    for (unsigned int j = 0; j < nf; ++j)
      system(i, j) = stiffness(free[i], free[j]);
    if (rigid)
      system(i, nf) = system(nf, i) = mass[free[i]] * (*rigid)[free[i]];
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(system);
  if (!lu.isInvertible())
    throw SolverFailure("lateral statics", "the stiffness matrix is singular");
  const Eigen::VectorXd solution = lu.solve(rhs);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(f.size());
  for (unsigned int i = 0; i < nf; ++i)
    q[free[i]] = solution[i];
  return q;
}

// The deflection orthogonal to the rigid rotation v0 (when there is one).
Eigen::VectorXd LateralModel::deflection_under(const Eigen::VectorXd& f,
                                               const std::vector<Eigen::VectorXd>& rigid) const
{
  return constrained_deflection(mass_diagonal, stiffness_matrix, free, f,
                                rigid.empty() ? nullptr : &rigid.front());
}

// Pin, mesh and bearing forces and load sharing of `state.displacement`.
void LateralModel::static_forces(LateralStaticState& state) const
{
  const double* q = state.displacement.data();
  state.pin_radial_force.assign(n_planet, 0.);
  state.pin_tangential_force.assign(n_planet, 0.);
  for (const Spring& s : spring_list)
    if (s.group == 2)
    {
      // Pin force on the planet: −∂U/∂ζ = k·δ (outwards), likewise tangentially.
      const bool radial = s.terms.size() == 3;
      (radial ? state.pin_radial_force : state.pin_tangential_force)[s.planet] =
          s.stiffness * deflection(s, q);
    }
  double sun_total = 0., ring_total = 0.;
  for (unsigned int p = 0; p < n_planet; ++p)
  {
    state.sun_mesh_force.push_back(data.sun_mesh_stiffness * sun_mesh_deflection(p, q));
    state.ring_mesh_force.push_back(data.ring_mesh_stiffness * ring_mesh_deflection(p, q));
    sun_total += state.sun_mesh_force.back();
    ring_total += state.ring_mesh_force.back();
  }
  for (unsigned int p = 0; p < n_planet; ++p)
  {
    state.sun_load_sharing.push_back(n_planet * state.sun_mesh_force[p] / sun_total);
    state.ring_load_sharing.push_back(n_planet * state.ring_mesh_force[p] / ring_total);
  }
  for (const LateralMember j : central_members)
  {
    const double k = member_data(data, j).bearing_stiffness;
    for (unsigned int c = 0; c < 2; ++c)
      state.bearing_force(static_cast<int>(j), c) = -k * q[central_dof(j, c)];
  }
}

LateralStaticState LateralModel::static_state(const LateralStaticLoad& load) const
{
  const LateralCentralMember& in = member_data(data, load.input);
  const LateralCentralMember& out = member_data(data, load.output);
  if (in.held)
    throw InputError(field::train("inputs"),
                     "the input " + lateral_member_name(load.input) + " is held");
  if (out.held || load.output == load.input)
    throw InputError(field::train("output"),
                     "the output " + lateral_member_name(load.output) + " must turn");
  Eigen::VectorXd f = error_force;
  f[central_dof(load.input, 2)] += load.input_torque / in.radius;

  // Rigid-body modes of the free coordinates: the stage's free rotation (none when every
  // member has a torsional support).
  const LateralModes m = modes();
  std::vector<Eigen::VectorXd> rigid;
  for (Eigen::Index k = 0; k < m.frequencies.size() && m.frequencies[k] == 0.; ++k)
    rigid.push_back(m.shapes.col(k));
  if (rigid.size() > 1)
    throw InputError(field::train("fixed"), "the stage has " + std::to_string(rigid.size()) +
                                                " free rotations: hold or suspend a member");
  const unsigned int uo = central_dof(load.output, 2);
  double output_torque = 0.;
  if (!rigid.empty())
  {
    // The load on the output that balances the input in the rigid rotation: v0ᵀ·f = 0.
    const Eigen::VectorXd& v0 = rigid.front();
    if (std::abs(v0[uo]) < 1e-12 * v0.cwiseAbs().maxCoeff())
      throw InputError(field::train("output"), "the output does not turn with the stage");
    output_torque = -v0.dot(f) / v0[uo] * out.radius;
    f[uo] += output_torque / out.radius;
  }
  LateralStaticState state;
  state.displacement = deflection_under(f, rigid);
  state.output_torque = output_torque;
  static_forces(state);
  return state;
}
} // namespace gearstiff::dynamics
