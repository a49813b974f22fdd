// The vibration signature of a faulty tooth (issue 31): with a whole-revolution stiffness table
// (period P base pitches, P the faulty gear's teeth, docs/faults.md) the mesh excitation repeats
// once per revolution of that gear, f_r = f_m/P, so the response's spectrum has sidebands at
// h·f_m ± s·f_r around the mesh harmonics h·f_m, and the time trace a once-per-revolution impulse
// (the signature of a local tooth fault in the dynamic response of Chaari et al. 2008,
// docs/references.md §13). Why the spacing is exactly f_r: the excitation, and so the steady
// response, is periodic with the revolution period 1/f_r, so its spectrum holds only multiples
// of f_r; the mesh harmonics h·f_m = h·P·f_r are among them, the lines between are the sidebands.
//
// Read from a finished run (simulation.h) whose window spans whole revolutions (the window is
// made of excitation_period() units), so every line h·f_m + s·f_r falls on an FFT bin exactly.
#pragma once

#include "dynamics/simulation.h"

#include <vector>

namespace gearstiff::dynamics
{
struct SidebandLine
{
  unsigned int harmonic = 0; // [-] h of the mesh harmonic h·f_m
  int order = 0;             // [-] s: the line h·f_m + s·f_r (0: the mesh harmonic itself)
  double frequency = 0.;     // [Hz]
  double force = 0.;         // [N] single-sided amplitude of the mesh force
  double deflection = 0.;    // [m] single-sided amplitude of the DTE δ
};

struct FaultSignature
{
  unsigned int period = 1;          // [base pitches] P, the table's period
  double revolution_frequency = 0.; // [Hz] f_r = f_m/P, the faulty gear's rotation frequency
  double revolutions = 0.;          // [-] revolutions in the window
  std::vector<SidebandLine> lines;  // h = 1..harmonics, s = −orders..orders (within the spectra)
  // [-] largest sideband (s ≠ 0, any h) of the force over the force's mesh-frequency line
  double largest_sideband_ratio = 0.;
  // [-] the largest mesh-force peak of a mesh period in the window over the median of the
  // mesh periods' peaks: the once-per-revolution impulse (1 when every pitch is alike)
  double impulse_ratio = 0.;
  // [-] max |δ(t) − δ(t − 1/f_r)| over the window's last revolution over the peak-to-peak of δ
  // in the window: 0 for a response that repeats once per revolution
  double revolution_repeat = 0.;
};

// Mesh `m` of `result` (time series kept, simulation.h); `period` P ≥ 1 base pitches of its
// stiffness table; lines up to `harmonics` mesh harmonics and ±`orders` sidebands. InputError
// naming Simulation/output interval when the stored series is too coarse (fewer than 8 samples
// per mesh period) for the impulse and repeat measures.
FaultSignature fault_signature(const SimulationResult& result, unsigned int m, unsigned int period,
                               unsigned int harmonics = 3, int orders = 3);
} // namespace gearstiff::dynamics
