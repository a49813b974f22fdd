// The Hertz case extruded into hexahedra (one cell through the 1 mm depth, u_z = 0 on both z
// faces: plane strain) must reproduce the 2D plane-strain result. The 3D mortar integrates the
// slave faces with an iterated Gauss rule instead of the exact 2D segmentation, so the two
// agree to that quadrature error (tolerances below: three times the measured deviations).
#include "contact/cylinder_pair.h"
#include "tests/contact/hertz_cylinders.h"

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>

using namespace gearstiff;
using namespace gearstiff::contact;
using namespace gearstiff::test_support;

namespace
{
struct Summary
{
  double load;       // N, total normal force
  double half_width; // m, Hertz-profile fit
  double peak;       // Pa, largest nodal pressure
  unsigned int iterations;
};

template <int dim>
Summary run(double fine_size)
{
  const ContactResults<dim> result = solve_hertz_cylinders<dim>(fine_size, 4e-6);
  const PairResult<dim>& pair = result.pairs.at(0);
  const HertzLineContact fitted = fit_closed_nodes(pair);
  return {std::abs(result.supports.at(1).force[1]), fitted.half_width, pair.max_pressure,
          result.active_set_iterations};
}
} // namespace

TEST(Hertz3d, ExtrudedHexahedraAgreeWithPlaneStrain)
{
  const double h = 12.5e-6; // m, a/8: the 2D study shows ~1 % from Hertz here
  const Summary planar = run<2>(h);
  const Summary solid = run<3>(h);
  std::cout << "2D: P = " << planar.load << " N, a = " << planar.half_width * 1e3
            << " mm, p_max = " << planar.peak * 1e-6 << " MPa, " << planar.iterations
            << " iterations\n3D: P = " << solid.load << " N, a = " << solid.half_width * 1e3
            << " mm, p_max = " << solid.peak * 1e-6 << " MPa, " << solid.iterations
            << " iterations\n";
  // With u_z = 0 on both z faces and one cell through the depth the 3D problem is plane strain
  // exactly, so the two agree up to the quadrature of the 3D mortar. Measured 2026-11-26: P equal
  // to 1e-6, a to 2e-5, p_max to 2e-4; tolerances three times those.
  EXPECT_NEAR(solid.load / planar.load, 1., 3e-6);
  EXPECT_NEAR(solid.half_width / planar.half_width, 1., 6e-5);
  EXPECT_NEAR(solid.peak / planar.peak, 1., 6e-4);
}
