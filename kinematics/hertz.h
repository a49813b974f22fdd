// Hertz line contact of two parallel cylinders in plane strain (Johnson, Contact Mechanics,
// 1985, §4.3, eq. 4.43–4.45): the one copy of the formulas that size the meshes' contact cells
// (geometry/), verify the contact engine (the `contact` command) and enter the analytic cycloid
// model (stiffness/).
#pragma once

#include <string>

namespace gearstiff::kinematics
{
struct HertzLineContact
{
  double half_width;    // m, a = sqrt(4·P·R / (π·E*))
  double peak_pressure; // Pa, p0 = 2·P / (π·a)
};

// Pa, E* of two linear-elastic bodies: 1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2 (moduli in Pa).
double effective_modulus(double young_modulus_1, double poisson_ratio_1, double young_modulus_2,
                         double poisson_ratio_2);

// The one range of a Poisson's ratio ν in every command (issue 45: one range per physical
// input): [0, 0.5), the parameters' pattern [0, 0.5] without its end. At 0.5 the material is
// incompressible, λ = Eν/((1+ν)(1−2ν)) is infinite and the displacement model has no solution;
// below 0 (auxetic foams) no material of a gear drive. InputError naming `field` otherwise.
void check_poisson_ratio(double poisson_ratio, const std::string& field);

// The one range of a Young's modulus E (Pa) in every command: positive and finite (E = 0 leaves
// a body without stiffness, and reached MUMPS as a singular matrix). InputError naming `field`.
void check_young_modulus(double young_modulus, const std::string& field);

// Load per unit length P (N/m), radii (m; a flat: infinity; concave: negative) with
// 1/R = 1/R1 + 1/R2 > 0, effective modulus E* (Pa). The caller checks that P > 0 and R > 0.
HertzLineContact hertz_line_contact(double load_per_length, double radius_1, double radius_2,
                                    double effective_modulus);
} // namespace gearstiff::kinematics
