#include "stiffness/transmission_error.h"

#include "errors/errors.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace gearstiff::stiffness
{
double mesh_harmonic(const std::vector<double>& positions, const std::vector<double>& values,
                     unsigned int order)
{
  std::complex<double> sum = 0.;
  for (std::size_t i = 0; i < values.size(); ++i)
    sum += values[i] * std::polar(1., -2. * M_PI * order * positions[i]);
  return 2. * std::abs(sum) / values.size();
}

TransmissionErrorSummary
summarize_transmission_error(const std::vector<GearMeshStiffnessResult>& positions)
{
  if (positions.empty())
    throw SolverFailure("transmission error summary", "no positions");
  TransmissionErrorSummary summary;
  summary.torque = positions.front().pinion_torque;
  std::vector<double> x, te, unloaded;
  for (const auto& r : positions)
  {
    x.push_back(r.mesh_position);
    te.push_back(r.transmission_error);
    unloaded.push_back(r.unloaded_transmission_error);
    summary.stiffness_mean += r.mesh_stiffness / positions.size();
    summary.mean += r.transmission_error / positions.size();
    summary.max_pressure = std::max(summary.max_pressure, r.max_contact_pressure);
  }
  const auto [low, high] = std::minmax_element(te.begin(), te.end());
  summary.peak_to_peak = *high - *low;
  const auto [low0, high0] = std::minmax_element(unloaded.begin(), unloaded.end());
  summary.unloaded_peak_to_peak = *high0 - *low0;
  for (unsigned int k = 0; k < 3; ++k)
    summary.harmonics[k] = mesh_harmonic(x, te, k + 1);
  return summary;
}
} // namespace gearstiff::stiffness
