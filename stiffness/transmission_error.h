// The transmission error over a mesh cycle as gear designers judge it (docs/references.md §8):
// peak-to-peak, mean and the amplitudes at 1×, 2×, 3× the mesh frequency of TE(θ) from a sweep
// over a whole number of base pitches, with the mean stiffness and the largest pressure at that
// torque — one row of the Harris map (TE peak-to-peak against torque, Harris 1958).
#pragma once

#include "stiffness/mesh_stiffness.h"

#include <vector>

namespace gearstiff::stiffness
{
struct TransmissionErrorSummary
{
  double torque = 0.;                // N·m
  double peak_to_peak = 0.;          // m, max − min of TE over the positions
  double mean = 0.;                  // m
  double harmonics[3] = {};          // m, amplitudes at 1×, 2×, 3× mesh frequency
  double stiffness_mean = 0.;        // N/m
  double max_pressure = 0.;          // Pa, over the positions
  double unloaded_peak_to_peak = 0.; // m, of the unloaded (geometric) TE
};

// Amplitudes at k× mesh frequency of samples y_i taken at roll positions x_i (base pitches):
// |2/N Σ y_i e^{−2πi k x_i}|, exact for equally spaced positions over a whole number of
// pitches (a discrete Fourier coefficient).
double mesh_harmonic(const std::vector<double>& positions, const std::vector<double>& values,
                     unsigned int order);

// One Harris-map row from the positions of a sweep at one torque (SolverFailure when empty).
TransmissionErrorSummary
summarize_transmission_error(const std::vector<GearMeshStiffnessResult>& positions);
} // namespace gearstiff::stiffness
