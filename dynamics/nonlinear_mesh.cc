#include "dynamics/nonlinear_mesh.h"

#include "dynamics/fields.h"
#include "errors/errors.h"
#include "errors/format.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace gearstiff::dynamics
{
namespace
{
// The message numbers of errors/format.h, 4 significant digits.
std::string format(double value)
{
  return format_number(value, 4);
}

// Samples per longest period for the mean and the peak-to-peak (harmonic orders up to a few
// tens are resolved to better than 1e-4 of their amplitude).
constexpr unsigned int te_samples = 8192;
} // namespace

std::string mesh_model_name(MeshModel model)
{
  return model == MeshModel::linear ? "linear" : "nonlinear";
}

TransmissionError TransmissionError::table(const std::vector<double>& positions,
                                           const std::vector<double>& values,
                                           const std::string& parameter)
{
  if (positions.empty() || positions.size() != values.size())
    throw InputError(parameter, "the transmission-error table needs as many values as positions");
  for (std::size_t i = 0; i < positions.size(); ++i)
  {
    if (!(positions[i] >= 0. && positions[i] < 1.) || (i > 0 && !(positions[i] > positions[i - 1])))
      throw InputError(parameter, "transmission-error positions must increase strictly in [0, 1)");
    if (!std::isfinite(values[i]))
      throw InputError(parameter, "transmission-error values must be finite");
  }
  TransmissionError te;
  te.table_positions = positions;
  te.table_values = values;
  return te;
}

void TransmissionError::add_harmonic(const ExcitationHarmonic& harmonic,
                                     const std::string& parameter)
{
  if (!(harmonic.order > 0.) || !std::isfinite(harmonic.order))
    throw InputError(parameter, "harmonic order must be positive, got " + format(harmonic.order));
  if (!(harmonic.amplitude >= 0.) || !std::isfinite(harmonic.amplitude + harmonic.phase))
    throw InputError(parameter, "harmonic amplitude must not be negative, got " +
                                    format(harmonic.amplitude * 1e6) + " µm");
  if (harmonic.amplitude > 0.)
    harmonics.push_back(harmonic);
}

double TransmissionError::value(double x) const
{
  double e = 0.;
  if (!table_positions.empty())
  {
    const double f = x - std::floor(x);
    const std::size_t n = table_positions.size();
    if (n == 1)
      e = table_values[0];
    else
    {
      const auto upper = std::upper_bound(table_positions.begin(), table_positions.end(), f);
      const std::size_t i1 = upper - table_positions.begin();
      const std::size_t i0 = (i1 == 0) ? n - 1 : i1 - 1;
      const double x0 = table_positions[i0] - (i1 == 0 ? 1. : 0.);
      const double x1 = (i1 == n) ? table_positions[0] + 1. : table_positions[i1];
      const double w = (f - x0) / (x1 - x0);
      e = (1. - w) * table_values[i0] + w * table_values[i1 % n];
    }
  }
  for (const ExcitationHarmonic& h : harmonics)
    e += h.amplitude * std::sin(2. * M_PI * h.order * x + h.phase);
  return e;
}

double TransmissionError::slope(double x) const
{
  double s = 0.;
  if (table_positions.size() > 1)
  {
    const double f = x - std::floor(x);
    const std::size_t n = table_positions.size();
    const auto upper = std::upper_bound(table_positions.begin(), table_positions.end(), f);
    const std::size_t i1 = upper - table_positions.begin();
    const std::size_t i0 = (i1 == 0) ? n - 1 : i1 - 1;
    const double x0 = table_positions[i0] - (i1 == 0 ? 1. : 0.);
    const double x1 = (i1 == n) ? table_positions[0] + 1. : table_positions[i1];
    s = (table_values[i1 % n] - table_values[i0]) / (x1 - x0);
  }
  for (const ExcitationHarmonic& h : harmonics)
    s += h.amplitude * 2. * M_PI * h.order * std::cos(2. * M_PI * h.order * x + h.phase);
  return s;
}

namespace
{
// The longest period [base pitches] of e: 1 for the table, 1/order for each harmonic; capped at
// 1000 pitches (orders below 1e-3 are not periodic on any sensible scale).
double longest_period(const std::vector<ExcitationHarmonic>& harmonics)
{
  double period = 1.;
  for (const ExcitationHarmonic& h : harmonics)
    period = std::max(period, std::min(1000., 1. / h.order));
  return period;
}
} // namespace

double TransmissionError::mean() const
{
  double integral = 0.;
  const std::size_t n = table_positions.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    const double x0 = table_positions[i];
    const double x1 = (i + 1 < n) ? table_positions[i + 1] : table_positions[0] + 1.;
    integral += 0.5 * (x1 - x0) * (table_values[i] + table_values[(i + 1) % n]);
  }
  // Harmonics with integer multiples of 1/period average to zero; others nearly so: sample.
  const double period = longest_period(harmonics);
  double harmonic_mean = 0.;
  for (const ExcitationHarmonic& h : harmonics)
  {
    double sum = 0.;
    for (unsigned int i = 0; i < te_samples; ++i)
      sum += std::sin(2. * M_PI * h.order * (i + 0.5) * period / te_samples + h.phase);
    harmonic_mean += h.amplitude * sum / te_samples;
  }
  return (n == 1 ? table_values[0] : integral) + harmonic_mean;
}

double TransmissionError::peak_to_peak() const
{
  if (is_zero())
    return 0.;
  const double period = longest_period(harmonics);
  double low = value(0.), high = low;
  for (unsigned int i = 1; i < te_samples; ++i)
  {
    const double e = value(i * period / te_samples);
    low = std::min(low, e);
    high = std::max(high, e);
  }
  for (const double x : table_positions) // the table's kinks, exactly, when alone
    if (harmonics.empty())
    {
      low = std::min(low, value(x));
      high = std::max(high, value(x));
    }
  return high - low;
}

double TransmissionError::highest_order() const
{
  double order = 0.;
  for (const ExcitationHarmonic& h : harmonics)
    order = std::max(order, h.order);
  return order;
}

TransmissionError TransmissionError::reversed(double contact_ratio) const
{
  TransmissionError te = *this;
  std::vector<std::pair<double, double>> nodes;
  for (std::size_t i = 0; i < table_positions.size(); ++i)
  {
    const double x = contact_ratio - table_positions[i];
    const double f = x - std::floor(x);
    nodes.emplace_back(f < 1. ? f : 0., table_values[i]);
  }
  std::sort(nodes.begin(), nodes.end());
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    te.table_positions[i] = nodes[i].first;
    te.table_values[i] = nodes[i].second;
  }
  // sin(2πq(ε − x) + φ) = sin(2πq·x + π − 2πqε − φ)
  for (ExcitationHarmonic& h : te.harmonics)
    h.phase = M_PI - 2. * M_PI * h.order * contact_ratio - h.phase;
  return te;
}

std::string TransmissionError::description() const
{
  if (is_zero())
    return "zero";
  std::ostringstream s;
  if (!table_positions.empty())
    s << "table of " << table_positions.size() << " points";
  for (const ExcitationHarmonic& h : harmonics)
    s << (s.tellp() > 0 ? " + " : "") << format(h.amplitude * 1e6) << " µm at order "
      << format(h.order);
  s << " (peak-to-peak " << format(peak_to_peak() * 1e6) << " µm)";
  return s.str();
}

void check_nonlinear_mesh(const NonlinearMesh& mesh, unsigned int m)
{
  if (!(mesh.backlash >= 0.) || !std::isfinite(mesh.backlash))
    throw InputError(field::gear_mesh(m, "backlash"),
                     "must not be negative, got " + format(mesh.backlash * 1e6) + " µm");
  const double variation = mesh.transmission_error.peak_to_peak();
  // Relative slack for round-off of an FE split (e = s − W/k to 1e-12 m).
  if (variation > mesh.backlash + 1e-12)
    throw InputError(field::gear_mesh(m, "transmission_error"),
                     "the unloaded transmission error varies by " + format(variation * 1e6) +
                         " µm, more than the free play (backlash " + format(mesh.backlash * 1e6) +
                         " µm): the back flanks would be pressed together without load, the pair "
                         "cannot mesh; reduce the deviations or give more backlash");
}

LoadedTransmissionErrorSplit split_loaded_transmission_error(
    const std::vector<double>& positions, const std::vector<double>& stiffness,
    const std::vector<double>& loaded_error, const std::vector<double>& unloaded_error,
    const std::string& parameter)
{
  const std::size_t n = positions.size();
  const bool given = !unloaded_error.empty();
  if (n == 0 || stiffness.size() != n || loaded_error.size() != n ||
      (given && unloaded_error.size() != n))
    throw InputError(parameter, "the transmission-error table needs one stiffness and one loaded "
                                "TE per position");
  std::vector<double> load(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const double elastic = loaded_error[i] - (given ? unloaded_error[i] : 0.);
    if (!(stiffness[i] > 0.) || !(elastic > 0.))
      throw InputError(parameter, std::string(given ? "loaded minus unloaded TE" : "loaded TE") +
                                      " and stiffness must be positive (row " +
                                      std::to_string(i + 1) + ")");
    load[i] = stiffness[i] * elastic;
  }
  LoadedTransmissionErrorSplit split;
  split.load = std::accumulate(load.begin(), load.end(), 0.) / n;
  for (std::size_t i = 0; i < n; ++i)
    if (std::abs(load[i] - split.load) > 1e-3 * split.load)
      throw InputError(parameter, std::string(given ? "k·(s − e)" : "k·s") +
                                      " differs between rows (" + format(load[i]) + " N against " +
                                      format(split.load) + " N): the table is not one load case");
  std::vector<double> e(n);
  double mean_s = 0.;
  for (std::size_t i = 0; i < n; ++i)
  {
    e[i] = given ? unloaded_error[i] : loaded_error[i] - split.load / stiffness[i];
    split.largest_unloaded_error = std::max(split.largest_unloaded_error, std::abs(e[i]));
    mean_s += loaded_error[i];
  }
  mean_s /= n;
  // Unmodified teeth: k = W/s (gearstiff stiffness), e is round-off then.
  if (split.largest_unloaded_error <= 1e-9 * mean_s)
    std::fill(e.begin(), e.end(), 0.);
  else
    split.unloaded = TransmissionError::table(positions, e, parameter);
  // Mean loaded TE over the cycle, the periodic piecewise-linear s(x).
  double integral = 0.;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double x0 = positions[i];
    const double x1 = (i + 1 < n) ? positions[i + 1] : positions[0] + 1.;
    integral += 0.5 * (x1 - x0) * (loaded_error[i] + loaded_error[(i + 1) % n]);
  }
  split.mean_loaded_error = n == 1 ? loaded_error[0] : integral;
  return split;
}
} // namespace gearstiff::dynamics
