#include "kinematics/hertz.h"

#include <cmath>

namespace gearstiff::kinematics
{
double effective_modulus(const double young_modulus_1, const double poisson_ratio_1,
                         const double young_modulus_2, const double poisson_ratio_2)
{
  return 1. / ((1. - poisson_ratio_1 * poisson_ratio_1) / young_modulus_1 +
               (1. - poisson_ratio_2 * poisson_ratio_2) / young_modulus_2);
}

HertzLineContact hertz_line_contact(const double load_per_length, const double radius_1,
                                    const double radius_2, const double effective_modulus)
{
  const double inverse_radius = 1. / radius_1 + 1. / radius_2; // 1/∞ = 0 for a flat
  HertzLineContact hertz;
  hertz.half_width = std::sqrt(4. * load_per_length / (M_PI * effective_modulus * inverse_radius));
  hertz.peak_pressure = 2. * load_per_length / (M_PI * hertz.half_width);
  return hertz;
}
} // namespace gearstiff::kinematics
