// Hertz line contact of two cylinders in plane strain (K.L. Johnson, Contact Mechanics, 1985,
// §4.3 eq. 4.43–4.45): a = sqrt(4PR/(πE*)), p0 = 2P/(πa), with the load P per unit length taken
// from the computed reaction. A refinement study of the mesh at the contact: the half-width and
// peak pressure must approach Hertz and be within 2 % at the finest level.
#include "contact/cylinder_pair.h"
#include "kinematics/hertz.h"
#include "tests/contact/hertz_cylinders.h"

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>

using namespace gearstiff;
using namespace gearstiff::contact;
using namespace gearstiff::test_support;

namespace
{
struct HertzRun
{
  double load_per_length;   // N/m
  double fitted_half_width; // m, of the elliptic fit p² = p0²(1 − x²/a²)
  double fitted_peak;       // Pa
  double peak_pressure;     // Pa, largest nodal pressure
  double closed_extent;     // m, half of the extent of the closed nodes
  unsigned int iterations;
  unsigned int n_dofs;
};

HertzRun run_hertz(double fine_size, double approach)
{
  const ContactResults<2> result = solve_hertz_cylinders<2>(fine_size, approach);

  HertzRun run;
  run.load_per_length = result.supports.at(1).force[1] / cylinder_thickness;
  const PairResult<2>& pair = result.pairs.at(0);
  run.peak_pressure = pair.max_pressure;
  run.closed_extent = 0.5 * pair.contact_length;
  const HertzLineContact fitted = fit_closed_nodes(pair);
  run.fitted_half_width = fitted.half_width;
  run.fitted_peak = fitted.peak_pressure;
  run.iterations = result.active_set_iterations;
  run.n_dofs = result.n_dofs;
  return run;
}
} // namespace

TEST(Hertz, PlaneStrainCylindersRefinementStudy)
{
  const double effective_modulus = steel.youngs_modulus / (2. * (1. - 0.3 * 0.3));
  const double approach = 4e-6; // m, gives P ≈ 129 N/mm and a ≈ 0.1 mm (a/R = 0.017)
  HertzRun run;
  kinematics::HertzLineContact hertz;
  double fine_size = 0;
  // Cell size at the contact a/8, a/16, a/32.
  for (const double h : {12.5e-6, 6.25e-6, 3.125e-6})
  {
    fine_size = h;
    run = run_hertz(fine_size, approach);
    hertz = kinematics::hertz_line_contact(run.load_per_length, 10e-3, 15e-3, effective_modulus);
    std::cout << "h = " << fine_size * 1e6 << " um, DoFs " << run.n_dofs << ", iterations "
              << run.iterations << ", P = " << run.load_per_length * 1e-3
              << " N/mm, a_fit/a_Hertz - 1 = " << run.fitted_half_width / hertz.half_width - 1.
              << ", p_max/p0 - 1 = " << run.peak_pressure / hertz.peak_pressure - 1.
              << ", closed half-extent/a = " << run.closed_extent / hertz.half_width << "\n";
    // Few active-set steps: the set grows from the single touching node to ~60 nodes.
    EXPECT_LE(run.iterations, 12u);
  }
  // Finest level, measured 2026-11-26: a −0.073 %, p_max −0.0021 %; tolerances about three times
  // those (the 12.5 and 6.25 µm levels: a −0.84 %, +0.20 %; p_max −0.10 %, +0.016 %).
  EXPECT_NEAR(run.fitted_half_width / hertz.half_width, 1., 0.0025);
  EXPECT_NEAR(run.peak_pressure / hertz.peak_pressure, 1., 7e-5);
  // The last closed node lies within about one (lower, 1.3× coarser) cell of the Hertz edge.
  EXPECT_NEAR(run.closed_extent, hertz.half_width, 2. * fine_size);
}
