// Cycloid disc profile, its correction and roller clearances (docs/references.md §4, after Chmurawa
// & Łokiec). The correction system as printed has one equation fewer than unknowns; with the
// tangency at S read as "equal slopes" it is square:
//   unknowns  α1, α_ok1, α2, α_ok2, α_S, α_okS, q_k, δ   (r_k = r + C·(q_k − q))
//   K(α_ok1) = N(α1) − Δr·n(α1),  K(α_ok2) = N(α2) − Δr·n(α2)   (clearance Δr at the arc ends)
//   K(α_okS) = N(α_S),  n_K(α_okS) ∥ n(α_S)                      (the profiles touch at S)
//   α2 − α1 = ε·α_pc
// N nominal, K corrected profile, n the outward unit normal. Eight equations, eight unknowns,
// solved with Levenberg–Marquardt (Eigen's MINPACK port, central-difference Jacobian).
#include "geometry/cycloid_disc.h"

#include "errors/errors.h"
#include "errors/format.h"
#include "geometry/fields.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

namespace gearstiff::geometry
{
namespace
{
using Vector = Eigen::Vector2d;

Vector unit(double angle)
{
  return Vector(std::cos(angle), std::sin(angle));
}

// The shortened epicycloid of the roller centres and its equidistant, for one disc spec.
struct Equidistant
{
  double r, e, q, delta;
  unsigned int z_k;

  explicit Equidistant(const CycloidDiscSpec& spec)
      : r(spec.roller_circle_radius), e(spec.eccentricity), q(spec.roller_radius),
        delta(spec.rotation), z_k(spec.rollers)
  {
  }

  double m() const { return e * z_k / r; }
  // γ(α) = atan(sin(z_s α) / (1/m + cos(z_s α))): the normal of the epicycloid leans by γ from
  // the radial direction α (1/m > 1, so the denominator stays positive).
  double gamma(double alpha) const
  {
    const double zs = z_k - 1.;
    return std::atan(std::sin(zs * alpha) / (1. / m() + std::cos(zs * alpha)));
  }
  double gamma_rate(double alpha) const
  {
    const double zs = z_k - 1., c = std::cos(zs * alpha), s = std::sin(zs * alpha);
    const double d = 1. / m() + c;
    return zs * (c / m() + 1.) / (d * d + s * s);
  }
  Vector rotated(const Vector& v) const { return Eigen::Rotation2Dd(delta) * v; }
  // Roller-centre path (the epicycloid) and its derivatives.
  Vector centre_path(double alpha) const
  {
    return rotated(r * unit(alpha) + e * unit(z_k * alpha));
  }
  Vector centre_path_rate(double alpha) const
  {
    return rotated(r * unit(alpha + M_PI_2) + e * z_k * unit(z_k * alpha + M_PI_2));
  }
  Vector centre_path_acceleration(double alpha) const
  {
    return rotated(-r * unit(alpha) - e * z_k * z_k * unit(z_k * alpha));
  }
  Vector normal(double alpha) const { return rotated(unit(alpha + gamma(alpha))); }
  Vector point(double alpha) const { return centre_path(alpha) - q * normal(alpha); }
  Vector point_rate(double alpha) const
  {
    return centre_path_rate(alpha) -
           q * (1. + gamma_rate(alpha)) * rotated(unit(alpha + gamma(alpha) + M_PI_2));
  }
};

void check_disc(const CycloidDiscSpec& spec)
{
  if (spec.rollers < 3)
    throw InputError(field::disc("rollers"), "at least 3 rollers");
  if (!(spec.roller_circle_radius > 0.))
    throw InputError(field::disc("roller_circle_radius"), "must be positive");
  if (!(spec.eccentricity > 0.))
    throw InputError(field::disc("eccentricity"), "must be positive");
  if (!(spec.roller_radius > 0.))
    throw InputError(field::disc("roller_radius"), "must be positive");
  const Equidistant curve(spec);
  if (!(curve.m() < 1.))
    throw InputError(field::disc("eccentricity"),
                     "m = e·z_k/r = " + std::to_string(curve.m()) +
                         " must stay below 1 (the epicycloid would loop)");
  // Neighbouring rollers may not overlap.
  const double pitch_limit = spec.roller_circle_radius * std::sin(M_PI / spec.rollers);
  if (!(spec.roller_radius < pitch_limit))
    throw InputError(field::disc("roller_radius"),
                     "rollers overlap: q must stay below r·sin(π/z_k) = " + format_mm(pitch_limit));
  // The equidistant stays free of loops only where q is below the epicycloid's radius of
  // curvature on its convex stretches (the lobe tips). One half lobe suffices (symmetry).
  double smallest_radius = std::numeric_limits<double>::infinity();
  const int samples = 400;
  for (int i = 0; i <= samples; ++i)
  {
    const double alpha = M_PI / (spec.rollers - 1.) * i / samples;
    const Vector d1 = curve.centre_path_rate(alpha), d2 = curve.centre_path_acceleration(alpha);
    const double turning = d1.x() * d2.y() - d1.y() * d2.x();
    if (turning > 0.)
      smallest_radius = std::min(smallest_radius, std::pow(d1.norm(), 3) / turning);
  }
  if (!(spec.roller_radius < smallest_radius))
    throw InputError(field::disc("roller_radius"),
                     "larger than the smallest radius of curvature of the epicycloid (" +
                         format_mm(smallest_radius) + "): the disc profile would loop");
}

// Arc length between two generating angles (geometry::arc_length, tooth_profile.h).
double arc_length(const Equidistant& curve, double a, double b)
{
  return geometry::arc_length([&curve](double t) { return curve.point_rate(t).norm(); }, a, b);
}

// The correction residuals (lengths in mm so that all residuals are of order one).
struct CorrectionResiduals
{
  typedef double Scalar;
  typedef Eigen::VectorXd InputType;
  typedef Eigen::VectorXd ValueType;
  typedef Eigen::MatrixXd JacobianType;
  enum
  {
    InputsAtCompileTime = Eigen::Dynamic,
    ValuesAtCompileTime = Eigen::Dynamic
  };

  CycloidDiscSpec nominal;
  double arc, clearance, slope_c;
  static constexpr double unit_length = 1e-3; // m

  int inputs() const { return 8; }
  int values() const { return 8; }

  CycloidDiscSpec corrected(const Eigen::VectorXd& x) const
  {
    CycloidDiscSpec k = nominal;
    k.roller_radius = x[6] * unit_length;
    k.roller_circle_radius =
        nominal.roller_circle_radius + slope_c * (k.roller_radius - nominal.roller_radius);
    k.rotation = x[7];
    return k;
  }

  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& f) const
  {
    const Equidistant n(nominal), k(corrected(x));
    const Vector end1 = (k.point(x[1]) - n.point(x[0]) + clearance * n.normal(x[0])) / unit_length;
    const Vector end2 = (k.point(x[3]) - n.point(x[2]) + clearance * n.normal(x[2])) / unit_length;
    const Vector touch = (k.point(x[5]) - n.point(x[4])) / unit_length;
    const Vector nk = k.normal(x[5]), nn = n.normal(x[4]);
    f << end1.x(), end1.y(), end2.x(), end2.y(), touch.x(), touch.y(),
        nk.x() * nn.y() - nk.y() * nn.x(), x[2] - x[0] - arc;
    return 0;
  }
};

// Signed normal gap (m) of a disc `k` below the nominal profile at nominal angle α, to first
// order in the difference (a tangential offset of the parameter does not change it).
double first_order_gap(const Equidistant& nominal, const Equidistant& k, double alpha)
{
  return (nominal.point(alpha) - k.point(alpha)).dot(nominal.normal(alpha));
}
} // namespace

double shortening_coefficient(const CycloidDiscSpec& spec)
{
  return spec.eccentricity * spec.rollers / spec.roller_circle_radius;
}

Eigen::Vector2d cycloid_point(const CycloidDiscSpec& spec, double generating_angle)
{
  return Equidistant(spec).point(generating_angle);
}

ToothProfile generate_cycloid_disc(const CycloidDiscSpec& spec, unsigned int points_per_lobe)
{
  check_disc(spec);
  const Equidistant curve(spec);
  const unsigned int lobes = spec.rollers - 1;
  const unsigned int n = std::max(3u, points_per_lobe | 1u); // odd: a point on the lobe tip
  ToothProfile lobe;
  lobe.teeth = lobes;
  lobe.angular_pitch = 2. * M_PI / lobes;
  lobe.tip_radius = spec.roller_circle_radius + spec.eccentricity - spec.roller_radius;
  lobe.root_radius = spec.roller_circle_radius - spec.eccentricity - spec.roller_radius;
  lobe.form_radius = lobe.root_radius;
  lobe.tip_relief_start_radius = lobe.tip_radius;
  double previous = -M_PI / lobes, length = 0.;
  for (unsigned int i = 0; i < n; ++i)
  {
    // Generating angle from one valley (α = −π/z_s) over the lobe tip (α = 0) to the next.
    const double alpha = -M_PI / lobes + 2. * M_PI / lobes * i / (n - 1);
    length += arc_length(curve, previous, alpha);
    previous = alpha;
    ProfilePoint p;
    p.position = curve.point(alpha);
    p.normal = curve.normal(alpha);
    p.arc_length = length;
    p.segment = ProfileSegment::flank;
    p.side = 2 * i + 1 < n ? -1 : (2 * i + 1 == n ? 0 : 1);
    lobe.points.push_back(p);
  }
  return lobe;
}

CycloidDiscSpec CycloidCorrection::corrected_disc(const CycloidDiscSpec& nominal) const
{
  CycloidDiscSpec k = nominal;
  k.roller_circle_radius = roller_circle_radius;
  k.roller_radius = roller_radius;
  k.rotation = nominal.rotation + rotation;
  return k;
}

namespace
{
using CorrectionSolver =
    Eigen::LevenbergMarquardt<Eigen::NumericalDiff<CorrectionResiduals, Eigen::Central>>;

// Levenberg–Marquardt from x; true when the residual vanishes (1e-9 mm: far below the printed
// digits) with S inside the contact arc and the arc on the flank between lobe tip and valley.
bool refine(const CorrectionResiduals& residuals, Eigen::VectorXd& x, double half_lobe,
            unsigned int& iterations, unsigned int& evaluations)
{
  Eigen::NumericalDiff<CorrectionResiduals, Eigen::Central> numeric(residuals);
  CorrectionSolver lm(numeric);
  lm.parameters.xtol = 1e-15;
  lm.parameters.ftol = 1e-15;
  lm.parameters.maxfev = 2000;
  lm.minimize(x);
  iterations += lm.iter;
  evaluations += lm.nfev;
  Eigen::VectorXd f(8);
  residuals(x, f);
  return f.norm() < 1e-9 && x[0] < x[4] && x[4] < x[2] && x[0] > 0. && x[2] < half_lobe;
}

// Starting points from the first-order gap g(α) = dq·A(α) + δ·B(α) of a small correction (dq
// with dr = C·dq, and a rotation δ). A tangency at S needs g(S) = g'(S) = 0, i.e. A'B − AB' = 0
// there, and δ = −dq·A(S)/B(S). The gap per unit dq, G(α) = A − (A(S)/B(S))·B, is then zero at S;
// the arc is the stretch around S where G stays below a level λ, with λ chosen so that the
// stretch is ε·α_pc long, and dq = Δr/λ puts the clearance Δr at both ends.
std::vector<Eigen::VectorXd> starting_points(const CorrectionResiduals& residuals, double half_lobe)
{
  const CycloidDiscSpec& nominal = residuals.nominal;
  const Equidistant n(nominal);
  const double h = 1e-6;
  auto gap_for = [&](double dq, double delta, double alpha)
  {
    CycloidDiscSpec k = nominal;
    k.roller_radius += dq;
    k.roller_circle_radius += residuals.slope_c * dq;
    k.rotation = delta;
    return first_order_gap(n, Equidistant(k), alpha);
  };
  const int samples = 2000;
  std::vector<double> alpha(samples + 1), a(samples + 1), b(samples + 1);
  for (int i = 0; i <= samples; ++i)
  {
    alpha[i] = half_lobe * i / samples;
    a[i] = gap_for(h * nominal.roller_radius, 0., alpha[i]) / (h * nominal.roller_radius);
    b[i] = gap_for(0., h, alpha[i]) / h;
  }
  std::vector<Eigen::VectorXd> starts;
  for (int i = 2; i < samples - 1; ++i)
  {
    // Sign change of A'B − AB' (central differences on the grid).
    auto stationary = [&](int j)
    { return (a[j + 1] - a[j - 1]) * b[j] - a[j] * (b[j + 1] - b[j - 1]); };
    if ((stationary(i) < 0.) == (stationary(i + 1) < 0.))
      continue;
    const double ratio = a[i] / b[i];
    std::vector<double> per_dq(samples + 1);
    for (int j = 0; j <= samples; ++j)
      per_dq[j] = a[j] - ratio * b[j];
    // The sub-level stretch around S, edges interpolated on the grid.
    auto edge = [&](double level, int direction)
    {
      for (int j = i; j > 0 && j < samples; j += direction)
        if (per_dq[j + direction] >= level)
          return alpha[j] + (alpha[j + direction] - alpha[j]) * (level - per_dq[j]) /
                                (per_dq[j + direction] - per_dq[j]);
      return direction > 0 ? half_lobe : 0.;
    };
    double low = 0., high = *std::max_element(per_dq.begin(), per_dq.end());
    if (!(high > 0.))
      continue;
    for (int k = 0; k < 60; ++k)
    {
      const double level = 0.5 * (low + high);
      (edge(level, 1) - edge(level, -1) < residuals.arc ? low : high) = level;
    }
    const double level = 0.5 * (low + high);
    const double alpha_1 = edge(level, -1), alpha_2 = edge(level, 1), alpha_s = alpha[i];
    const double dq = residuals.clearance / level;
    if (!std::isfinite(dq) || !(level > 0.) || alpha_1 <= 0. || alpha_2 >= half_lobe)
      continue;
    Eigen::VectorXd x(8);
    x << alpha_1, alpha_1, alpha_2, alpha_2, alpha_s, alpha_s,
        (nominal.roller_radius + dq) / CorrectionResiduals::unit_length, -ratio * dq;
    starts.push_back(x);
  }
  return starts;
}
// Far from ε ≈ 0.3 the correction is no longer small and the first-order start can miss:
// solves at the nearest ε in [0.2, 0.4] first and follows the solution to the requested ε in
// steps (halved when a step fails). SolverFailure when no step converges.
Eigen::VectorXd continue_correction(CorrectionResiduals& residuals, double contact_arc_ratio,
                                    unsigned int lobes, unsigned int& iterations,
                                    unsigned int& evaluations)
{
  const double half_lobe = M_PI / lobes;
  const double start_ratio = std::min(0.4, std::max(0.2, contact_arc_ratio));
  Eigen::VectorXd x;
  bool solved = false;
  residuals.arc = start_ratio * 2. * M_PI / lobes;
  for (Eigen::VectorXd start : starting_points(residuals, half_lobe))
    if (refine(residuals, start, half_lobe, iterations, evaluations))
    {
      x = start;
      solved = true;
      break;
    }
  double ratio = start_ratio, step = 0.02;
  while (solved && ratio != contact_arc_ratio)
  {
    const double next = std::abs(contact_arc_ratio - ratio) <= step
                            ? contact_arc_ratio
                            : ratio + std::copysign(step, contact_arc_ratio - ratio);
    Eigen::VectorXd trial = x;
    // keep the arc centred where it was, stretched to the new length
    const double centre = 0.5 * (x[0] + x[2]), length = next * 2. * M_PI / lobes;
    trial[0] = trial[1] = centre - length / 2.;
    trial[2] = trial[3] = centre + length / 2.;
    residuals.arc = length;
    if (refine(residuals, trial, half_lobe, iterations, evaluations))
    {
      x = trial;
      ratio = next;
    }
    else if ((step /= 2.) < 1e-4)
      solved = false;
  }
  if (!solved)
    throw SolverFailure("cycloid correction (Levenberg-Marquardt)",
                        "no converged correction with the tangency point inside the contact arc "
                        "for ε = " +
                            std::to_string(contact_arc_ratio));
  return x;
}
} // namespace

CycloidCorrection solve_cycloid_correction(const CycloidDiscSpec& nominal, double contact_arc_ratio,
                                           double clearance_limit)
{
  check_disc(nominal);
  if (nominal.rotation != 0.)
    throw InputError(field::disc("rotation"), "the nominal disc is not rotated");
  // The contact arc lies on one flank, which spans half a lobe pitch.
  if (!(contact_arc_ratio > 0. && contact_arc_ratio < 0.5))
    throw InputError(field::correction("contact_arc_ratios"),
                     "ε must lie between 0 and 0.5 (the arc must fit on one flank)");
  if (!(clearance_limit > 0. && clearance_limit < 0.1 * nominal.roller_radius))
    throw InputError(field::correction("clearance_limit"), "must be positive and small against q");

  const unsigned int lobes = nominal.rollers - 1;
  const double m = shortening_coefficient(nominal);
  CorrectionResiduals residuals;
  residuals.nominal = nominal;
  residuals.clearance = clearance_limit;
  // docs/references.md §4: r_k = C·(q_k − q) + e·z_k/m.
  residuals.slope_c = (std::sqrt(1. + m * m) - 1.) / (1. - std::sqrt(1. - m * m));

  unsigned int iterations = 0, evaluations = 0;
  const Eigen::VectorXd x =
      continue_correction(residuals, contact_arc_ratio, lobes, iterations, evaluations);

  Eigen::VectorXd f(8);
  residuals(x, f);
  const CycloidDiscSpec corrected = residuals.corrected(x);
  CycloidCorrection result;
  result.contact_arc_ratio = contact_arc_ratio;
  result.clearance_limit = clearance_limit;
  result.alpha_1 = x[0];
  result.alpha_ok_1 = x[1];
  result.alpha_2 = x[2];
  result.alpha_ok_2 = x[3];
  result.alpha_s = x[4];
  result.alpha_ok_s = x[5];
  result.roller_radius = corrected.roller_radius;
  result.roller_circle_radius = corrected.roller_circle_radius;
  result.rotation = corrected.rotation;
  result.shortening = shortening_coefficient(corrected);
  result.residual_norm = f.norm() * CorrectionResiduals::unit_length;
  result.iterations = iterations;
  result.function_evaluations = evaluations;
  return result;
}

double cycloid_curvature_radius(const CycloidDiscSpec& disc, double alpha)
{
  // Central differences of the exact curve.
  const double h = 1e-4;
  const Eigen::Vector2d a = cycloid_point(disc, alpha - h), b = cycloid_point(disc, alpha),
                        c = cycloid_point(disc, alpha + h);
  const Eigen::Vector2d d1 = (c - a) / (2. * h), d2 = (c - 2. * b + a) / (h * h);
  const double cross = d1.x() * d2.y() - d1.y() * d2.x();
  return std::pow(d1.norm(), 3) / cross; // ±∞ for a straight stretch
}

double disc_rotation_at_crank_angle(const CycloidDiscSpec& ring, double crank_angle)
{
  return (M_PI - crank_angle) / (ring.rollers - 1.);
}

std::vector<RollerContact> roller_contacts(const CycloidDiscSpec& nominal,
                                           const CycloidDiscSpec& disc, double disc_rotation)
{
  check_disc(nominal);
  check_disc(disc);
  const Equidistant curve(disc);
  const unsigned int z_k = nominal.rollers, z_s = z_k - 1;
  // Nominal kinematics with the ring fixed: for a disc turned by ψ the disc centre sits at
  // −e·(cos(z_s ψ), −sin(z_s ψ)), which puts every roller centre on the nominal epicycloid
  // (the disc frame sees roller i at generating angle 2πi/z_k − ψ).
  const Vector disc_centre = -nominal.eccentricity * unit(-double(z_s) * disc_rotation);
  const Eigen::Rotation2Dd to_disc(-disc_rotation), to_ring(disc_rotation);
  std::vector<RollerContact> contacts(z_k);
  for (unsigned int i = 0; i < z_k; ++i)
  {
    const double roller_angle = 2. * M_PI * i / z_k;
    const Vector ring_centre = nominal.roller_circle_radius * unit(roller_angle);
    const Vector centre = to_disc * (ring_centre - disc_centre);
    // Closest point of the disc's epicycloid (Newton on (E − Q)·E' = 0 from the nominal match).
    double alpha = roller_angle - disc_rotation - disc.rotation;
    for (int it = 0; it < 50; ++it)
    {
      const Vector d = curve.centre_path(alpha) - centre, d1 = curve.centre_path_rate(alpha);
      const double step =
          d.dot(d1) / (d1.squaredNorm() + d.dot(curve.centre_path_acceleration(alpha)));
      alpha -= step;
      if (std::abs(step) < 1e-15)
        break;
    }
    const Vector d = centre - curve.centre_path(alpha);
    if (std::abs(d.dot(curve.centre_path_rate(alpha).normalized())) >
        1e-9 * nominal.roller_circle_radius)
      throw SolverFailure("roller clearance", "closest-point iteration did not converge");
    RollerContact& c = contacts[i];
    // Distance from the roller centre to the disc profile (q_disc inside the epicycloid) minus
    // the roller radius.
    c.clearance = d.dot(curve.normal(alpha)) + disc.roller_radius - nominal.roller_radius;
    c.roller_centre = ring_centre;
    c.point = disc_centre + to_ring * curve.point(alpha);
    c.normal = to_ring * curve.normal(alpha);
    c.generating_angle = alpha;
  }
  return contacts;
}

std::vector<double> roller_clearances(const CycloidDiscSpec& nominal, const CycloidDiscSpec& disc,
                                      double disc_rotation)
{
  std::vector<double> clearance;
  for (const RollerContact& c : roller_contacts(nominal, disc, disc_rotation))
    clearance.push_back(c.clearance);
  return clearance;
}
} // namespace gearstiff::geometry
