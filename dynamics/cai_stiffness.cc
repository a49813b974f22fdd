#include "dynamics/cai_stiffness.h"

#include "errors/errors.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

namespace gearstiff::dynamics
{
namespace
{
double shape_value(const std::array<double, 3>& c, double s)
{
  return (c[2] * s + c[1]) * s + c[0];
}

// Smallest and largest value of the quadratic shape on [0, 1]: at the ends or the vertex.
std::pair<double, double> shape_range(const std::array<double, 3>& c)
{
  double low = std::min(shape_value(c, 0.), shape_value(c, 1.));
  double high = std::max(shape_value(c, 0.), shape_value(c, 1.));
  if (c[2] != 0.)
  {
    const double vertex = -c[1] / (2. * c[2]);
    if (vertex > 0. && vertex < 1.)
    {
      low = std::min(low, shape_value(c, vertex));
      high = std::max(high, shape_value(c, vertex));
    }
  }
  return {low, high};
}

// Adds the basis (1, s, s²) of every pair in contact for one sample; the mesh stiffness is
// linear in scale·c, so a sample's row is the sum of the pairs' basis rows.
Eigen::RowVector3d sample_row(double position, double contact_ratio, StiffnessSampleKind kind)
{
  Eigen::RowVector3d row = Eigen::RowVector3d::Zero();
  auto add_pair = [&](double roll_position)
  {
    const double s = roll_position / contact_ratio;
    row += Eigen::RowVector3d(1., s, s * s);
  };
  if (kind == StiffnessSampleKind::single_pair)
    add_pair(position);
  else
    for (double p = position; p < contact_ratio; p += 1.)
      add_pair(p);
  return row;
}
} // namespace

CaiParameters cai_published_parameters(double single_pair_peak)
{
  CaiParameters parameters;
  parameters.scale = single_pair_peak;
  return parameters;
}

double cai_pair_stiffness(const CaiParameters& parameters, double engagement_fraction)
{
  if (engagement_fraction < 0. || engagement_fraction > 1.)
    return 0.;
  return parameters.scale * shape_value(parameters.shape, engagement_fraction);
}

double cai_mesh_stiffness(const CaiParameters& parameters, double mesh_position,
                          double contact_ratio)
{
  double stiffness = 0.;
  for (double p = mesh_position - std::floor(mesh_position); p < contact_ratio; p += 1.)
    stiffness += cai_pair_stiffness(parameters, p / contact_ratio);
  return stiffness;
}

namespace
{
// InputError for a contact ratio below 1, too few samples for `n_unknowns`, a position outside
// the sample kind's range or a stiffness that is not positive.
void check_samples(const std::vector<StiffnessSample>& samples, double contact_ratio,
                   StiffnessSampleKind kind, unsigned int n_unknowns)
{
  const std::string parameter = "stiffness samples";
  if (!(contact_ratio >= 1.))
    throw InputError("contact ratio", "must be at least 1 for continuous meshing, got " +
                                          std::to_string(contact_ratio));
  if (samples.size() < n_unknowns)
    throw InputError(parameter, "need at least " + std::to_string(n_unknowns) +
                                    " samples for this fit, got " + std::to_string(samples.size()));
  const double position_limit = kind == StiffnessSampleKind::mesh ? 1. : contact_ratio;
  for (const auto& sample : samples)
  {
    if (!(sample.position >= 0. && sample.position < position_limit))
      throw InputError(parameter, "position " + std::to_string(sample.position) +
                                      " base pitches outside [0, " +
                                      std::to_string(position_limit) + ")");
    if (!(sample.stiffness > 0.))
      throw InputError(parameter, "stiffness must be positive, got " +
                                      std::to_string(sample.stiffness) + " N/m");
  }
}
} // namespace

CaiFit fit_cai_parameters(const std::vector<StiffnessSample>& samples, double contact_ratio,
                          StiffnessSampleKind kind, bool fit_shape)
{
  check_samples(samples, contact_ratio, kind, fit_shape ? 3 : 1);

  // Scale the unknowns to O(1) so the QR rank decision is not fooled by N/m magnitudes.
  double reference = 0.;
  for (const auto& sample : samples)
    reference = std::max(reference, sample.stiffness);

  const CaiParameters published = cai_published_parameters(1.);
  Eigen::MatrixXd basis(samples.size(), 3);
  Eigen::VectorXd values(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    basis.row(i) = sample_row(samples[i].position, contact_ratio, kind);
    values[i] = samples[i].stiffness / reference;
  }

  CaiFit fit;
  fit.n_samples = samples.size();
  fit.shape_fitted = fit_shape;
  if (fit_shape)
  {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(basis);
    if (qr.rank() < 3)
      throw SolverFailure("Cai shape fit", "the sample positions do not determine three shape "
                                           "coefficients (rank " +
                                               std::to_string(qr.rank()) +
                                               "); add positions or fit the scale only");
    const Eigen::Vector3d product = qr.solve(values);
    const std::array<double, 3> raw = {product[0], product[1], product[2]};
    const auto [low, high] = shape_range(raw);
    if (!(low > 0.))
      throw SolverFailure("Cai shape fit",
                          "the fitted pair stiffness is not positive over the whole "
                          "engagement (minimum " +
                              std::to_string(low * reference) + " N/m)");
    fit.parameters.scale = high * reference;
    for (unsigned int i = 0; i < 3; ++i)
      fit.parameters.shape[i] = raw[i] / high;
  }
  else
  {
    const Eigen::Vector3d shape(published.shape[0], published.shape[1], published.shape[2]);
    const Eigen::VectorXd column = basis * shape;
    fit.parameters.shape = published.shape;
    fit.parameters.scale = reference * column.dot(values) / column.squaredNorm();
  }

  double sum_squares = 0.;
  for (const auto& sample : samples)
  {
    const double model = kind == StiffnessSampleKind::mesh
                             ? cai_mesh_stiffness(fit.parameters, sample.position, contact_ratio)
                             : cai_pair_stiffness(fit.parameters, sample.position / contact_ratio);
    const double residual = sample.stiffness - model;
    sum_squares += residual * residual;
    fit.max_residual = std::max(fit.max_residual, std::abs(residual));
  }
  fit.rms_residual = std::sqrt(sum_squares / samples.size());
  return fit;
}
} // namespace gearstiff::dynamics
