// Tooth mesh stiffness by ISO 6336-1:2006 method B (clause 9): single stiffness c' of one
// tooth pair and mesh stiffness c_γα / c_γβ, for steel/steel spur and helical gears. The
// empirical q' polynomial comes from tests on solid steel gears with the standard basic rack
// (α = 20°, h_fP = 1.2·m_n); the factors C_M, C_R, C_B carry it to other designs, and every
// range the method was fitted on is checked and reported, not silently extrapolated.
#pragma once

#include "kinematics/gear_pair.h"

#include <string>
#include <vector>

namespace gearstiff::kinematics
{
struct IsoStiffnessOptions
{
  double theoretical_correction = 0.8; // -, C_M, 0.8 for solid discs (ISO 6336-1 9.3.3)
  // N/m, F_t·K_A / b per unit face width; 0 = not given (no load correction applied).
  double specific_load = 0.;
};

// One ISO 6336-1 validity condition and whether the pair meets it.
struct ValidityCheck
{
  std::string condition; // e.g. "−0.5 ≤ x1 + x2 ≤ 2.0"
  double value = 0.;     // the pair's value, in the unit of the condition
  bool satisfied = true;
};

struct IsoStiffness
{
  double flexibility = 0.;           // m·m/N, q' (ISO: mm·µm/N, converted)
  double theoretical_single = 0.;    // N/m², c'_th = 1/q' per unit face width
  double blank_factor = 1.;          // -, C_R (mean of the two gears)
  double basic_rack_factor = 1.;     // -, C_B (mean of the two gears)
  double theoretical_correction = 0; // -, C_M
  double single = 0.;                // N/m², c' = c'_th·C_M·C_R·C_B·cos β
  double load_factor = 1.;           // -, (F_t·K_A/b / 100 N/mm)^0.25 below 100 N/mm, else 1
  double single_loaded = 0.;         // N/m², c'·load_factor
  double mesh_alpha = 0.;            // N/m², c_γα = c'·(0.75·ε_α + 0.25) (with load factor)
  double mesh_beta = 0.;             // N/m², c_γβ = 0.85·c_γα
  double face_width = 0.;            // m, b used for c'·b (common face width)
  double single_per_width = 0.;      // N/m, c'·b (without load factor)
  double mesh_alpha_per_width = 0.;  // N/m, c_γα·b
  std::vector<ValidityCheck> validity;
  bool valid() const;
};

// ISO 6336-1 method B for the pair. Cost: microseconds.
IsoStiffness iso_mesh_stiffness(const GearPairGeometry& pair,
                                const IsoStiffnessOptions& options = IsoStiffnessOptions());
} // namespace gearstiff::kinematics
