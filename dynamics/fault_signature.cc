#include "dynamics/fault_signature.h"

#include "dynamics/fields.h"
#include "errors/errors.h"

#include <algorithm>
#include <cmath>

namespace gearstiff::dynamics
{
namespace
{
// Amplitude of the spectrum line at `frequency` [Hz] (the nearest bin; NaN beyond the spectrum).
double line(const std::vector<double>& frequencies, const std::vector<double>& amplitudes,
            double frequency)
{
  if (frequencies.size() < 2)
    return std::nan("");
  const double resolution = frequencies[1] - frequencies[0];
  const std::size_t bin = static_cast<std::size_t>(std::llround(frequency / resolution));
  return bin < amplitudes.size() ? amplitudes[bin] : std::nan("");
}

// δ at time t [s] by linear interpolation of the stored series (t inside it).
double at(const std::vector<double>& time, const std::vector<double>& values, double t)
{
  const auto upper = std::upper_bound(time.begin(), time.end(), t);
  const std::size_t i1 = std::min<std::size_t>(upper - time.begin(), time.size() - 1);
  const std::size_t i0 = i1 == 0 ? 0 : i1 - 1;
  if (i0 == i1)
    return values[i0];
  const double w = std::clamp((t - time[i0]) / (time[i1] - time[i0]), 0., 1.);
  return (1. - w) * values[i0] + w * values[i1];
}

// Impulse ratio and revolution repeat of mesh `mesh` from the stored series over the window.
void time_measures(const SimulationResult& result, const MeshResult& mesh, double revolution,
                   FaultSignature& signature)
{
  const std::vector<double>& time = result.trajectory.time;
  const double mesh_period = 1. / mesh.mesh_frequency;
  const double spacing = time.size() > 1 ? time[1] - time[0] : INFINITY;
  if (!(spacing <= mesh_period / 8.))
    throw InputError(field::simulation("output_interval"),
                     "the stored series has " + std::to_string(mesh_period / spacing) +
                         " samples per mesh period; the fault signature needs at least 8");
  const double tolerance = 1e-9 * mesh_period;
  // Peak force of every mesh period of the window.
  const std::size_t periods = static_cast<std::size_t>(
      std::llround((result.window_end - result.window_start) / mesh_period));
  std::vector<double> peaks(std::max<std::size_t>(periods, 1), -INFINITY);
  double low = INFINITY, high = -INFINITY;
  for (std::size_t i = 0; i < time.size(); ++i)
  {
    if (time[i] < result.window_start - tolerance || time[i] > result.window_end + tolerance)
      continue;
    const std::size_t k = std::min<std::size_t>(
        peaks.size() - 1,
        static_cast<std::size_t>(std::max(0., (time[i] - result.window_start) / mesh_period)));
    peaks[k] = std::max(peaks[k], mesh.force[i]);
    low = std::min(low, mesh.deflection[i]);
    high = std::max(high, mesh.deflection[i]);
  }
  std::vector<double> sorted = peaks;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  signature.impulse_ratio =
      *std::max_element(peaks.begin(), peaks.end()) / sorted[sorted.size() / 2];
  // The last revolution against the one before it (needs two revolutions in the window).
  double repeat = std::nan("");
  if (result.window_end - result.window_start >= 2. * revolution - tolerance)
  {
    repeat = 0.;
    for (std::size_t i = 0; i < time.size(); ++i)
      if (time[i] >= result.window_end - revolution - tolerance &&
          time[i] <= result.window_end + tolerance)
        repeat = std::max(
            repeat, std::abs(mesh.deflection[i] - at(time, mesh.deflection, time[i] - revolution)));
  }
  signature.revolution_repeat = repeat / (high - low);
}
} // namespace

FaultSignature fault_signature(const SimulationResult& result, unsigned int m, unsigned int period,
                               unsigned int harmonics, int orders)
{
  const MeshResult& mesh = result.meshes.at(m);
  FaultSignature signature;
  signature.period = period;
  signature.revolution_frequency = mesh.mesh_frequency / period;
  const double revolution = 1. / signature.revolution_frequency;
  signature.revolutions = (result.window_end - result.window_start) / revolution;
  const double fundamental =
      line(mesh.spectrum_frequency, mesh.spectrum_amplitude, mesh.mesh_frequency);
  for (unsigned int h = 1; h <= harmonics; ++h)
    for (int s = -orders; s <= orders; ++s)
    {
      SidebandLine sideband;
      sideband.harmonic = h;
      sideband.order = s;
      sideband.frequency = h * mesh.mesh_frequency + s * signature.revolution_frequency;
      sideband.force = line(mesh.spectrum_frequency, mesh.spectrum_amplitude, sideband.frequency);
      sideband.deflection =
          line(mesh.dte_spectrum_frequency, mesh.dte_spectrum_amplitude, sideband.frequency);
      if (!std::isfinite(sideband.force))
        continue;
      if (s != 0)
        signature.largest_sideband_ratio =
            std::max(signature.largest_sideband_ratio, sideband.force / fundamental);
      signature.lines.push_back(sideband);
    }
  time_measures(result, mesh, revolution, signature);
  return signature;
}
} // namespace gearstiff::dynamics
