#include "kinematics/hertz.h"

#include "errors/errors.h"

#include <cmath>

namespace gearstiff::kinematics
{
void check_poisson_ratio(double poisson_ratio, const std::string& field)
{
  if (!(poisson_ratio >= 0. && poisson_ratio < 0.5))
    throw InputError(field, "must lie in [0, 0.5) (-): at 0.5 the material is incompressible, "
                            "λ = Eν/((1+ν)(1−2ν)) is infinite and the displacement model has no "
                            "solution");
}

void check_young_modulus(double young_modulus, const std::string& field)
{
  if (!(young_modulus > 0.) || !std::isfinite(young_modulus))
    throw InputError(field, "must be positive and finite (GPa): E = 0 leaves the body without "
                            "stiffness");
}

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
