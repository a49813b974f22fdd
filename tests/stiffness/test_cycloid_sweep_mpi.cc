// A crank sweep of the cycloid drive of docs/references.md §4 on the default scene,
// its cases spread over two MPI ranks (solve_cycloid_cases: case k on rank k mod 2, results
// gathered on every rank), against the same cases solved serially (solve_cycloid_case): the
// distribution over ranks must change no number. Each rank re-solves the other rank's cases, so
// every case is compared. The cases include a corrected profile under −M_c (the mirrored solve
// and its backlash) so that every field of the gathered rows is exercised.
#include "geometry/cycloid_disc.h"
#include "stiffness/cycloid_sweep.h"
#include "tests/stiffness/work_file.h"

#include <cmath>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <gtest/gtest.h>
#include <iostream>

using namespace gearstiff;
using namespace gearstiff::stiffness;

namespace
{
// The default mesh (coarser ones leave gmsh with triangles in the rollers); three cases keep the
// test at three solves per rank.
CycloidLoadSettings load_case(double crank_angle, double torque)
{
  CycloidLoadSettings s;
  s.crank_angle = crank_angle;
  s.output_torque = torque;
  return s;
}
} // namespace

TEST(CycloidSweep, TwoRanksGiveTheSerialSweep)
{
  const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const unsigned int ranks = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  std::vector<CycloidLoadSettings> cases;
  for (const double angle : crank_angles(0., 2. * M_PI / 20., 2))
    cases.push_back(load_case(angle, 440.));
  cases.push_back(load_case(0., -440.));
  cases.back().scene.disc = geometry::solve_cycloid_correction(cases.back().scene.ring, 0.27, 1e-5)
                                .corrected_disc(cases.back().scene.ring);
  const std::string stem = stiffness_work_stem("cycloid-sweep") + "-" + std::to_string(rank);
  const std::vector<CycloidLoadResult> gathered = solve_cycloid_cases(MPI_COMM_WORLD, cases, stem);
  ASSERT_EQ(gathered.size(), cases.size());

  // The same serial code on the same scene: the results agree to round-off (observed: bit for
  // bit); 1e-9 of each force scale leaves room for nothing else.
  for (unsigned int k = 0; k < cases.size(); ++k)
  {
    if (ranks > 1 && k % ranks == rank)
      continue; // solved here already: compare the other rank's cases
    CycloidLoadSettings serial = cases[k];
    serial.scene_file = stem + "-serial.msh";
    const CycloidLoadResult r = solve_cycloid_case(serial);
    std::filesystem::remove(serial.scene_file);
    const CycloidLoadResult& g = gathered[k];
    const double p = 1e-9 * r.max_roller_force, q = 1e-9 * r.max_pin_force;
    EXPECT_NEAR(g.max_roller_force, r.max_roller_force, p) << "case " << k;
    EXPECT_NEAR(g.max_pin_force, r.max_pin_force, q) << "case " << k;
    EXPECT_NEAR(g.bearing_force, r.bearing_force, 1e-9 * r.bearing_force) << "case " << k;
    EXPECT_NEAR(g.output_rotation, r.output_rotation, 1e-9 * std::abs(r.output_rotation));
    EXPECT_NEAR(g.closing_rotation, r.closing_rotation, 1e-9 * std::abs(r.output_rotation));
    EXPECT_EQ(g.loaded_rollers, r.loaded_rollers);
    EXPECT_EQ(g.n_dofs, r.n_dofs);
    ASSERT_EQ(g.rollers.size(), r.rollers.size());
    for (unsigned int i = 0; i < r.rollers.size(); ++i)
      EXPECT_NEAR(g.rollers[i].force, r.rollers[i].force, p) << "case " << k << " roller " << i;
    for (unsigned int j = 0; j < r.pins.size(); ++j)
      EXPECT_NEAR(g.pins[j].force, r.pins[j].force, q) << "case " << k << " pin " << j;
    std::cout << "rank " << rank << ", case " << k << ": P_max = " << r.max_roller_force
              << " N, θ = " << r.output_rotation * 180. / M_PI * 60. << " arcmin, " << r.total_time
              << " s" << std::endl;
  }
}
