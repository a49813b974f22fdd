// The same frictional Hertz problem solved on all ranks together (METIS partition, distributed
// PETSc matrix, MUMPS) and on each rank alone (MPI_COMM_SELF) must give the same answer: the
// partition may change round-off, never the result.
#include "contact/contact_problem.h"
#include "contact/cylinder_pair.h"

#include <cmath>
#include <deal.II/base/mpi.h>
#include <gtest/gtest.h>
#include <mpi.h>

using namespace dealii;
using namespace gearstiff;
using namespace gearstiff::contact;

namespace
{
struct Outcome
{
  ContactResults<2> result;
  Vector<double> solution;
  unsigned int n_subdomains;
};

Outcome solve_on(MPI_Comm communicator)
{
  fem::ElasticityParameters elasticity;
  elasticity.thickness = 1e-3;
  ContactParameters contact;
  contact.friction_coefficient = 0.1;
  ContactProblem<2> problem(communicator, elasticity, fem::LinearSolverParameters(), contact);
  CylinderPairGeometry geometry;
  geometry.fine_size = 12.5e-6;
  make_cylinder_pair(geometry, problem.system().triangulation());
  problem.system().set_materials({{upper_body, {210e9, 0.3}}, {lower_body, {210e9, 0.3}}},
                                 "materials");
  // A small sideways motion of the upper body gives stick and slip zones.
  problem.add_displacement(upper_top, Tensor<1, 2>({0.3e-6, -4e-6}), "upper top");
  problem.add_displacement(lower_bottom, Tensor<1, 2>(), "lower bottom");
  problem.add_contact_pair({upper_contact}, {lower_contact}, "cylinders");
  Outcome outcome{problem.run(), problem.solution(), 0};
  std::set<types::subdomain_id> subdomains;
  for (const auto& cell : problem.system().triangulation().active_cell_iterators())
    subdomains.insert(cell->subdomain_id());
  outcome.n_subdomains = subdomains.size();
  return outcome;
}
} // namespace

TEST(Mpi, OneAndTwoRanksAgree)
{
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  ASSERT_EQ(n_ranks, 2u) << "run with mpiexec -np 2";
  const Outcome parallel = solve_on(MPI_COMM_WORLD);
  const Outcome serial = solve_on(MPI_COMM_SELF);
  EXPECT_EQ(parallel.n_subdomains, 2u);
  EXPECT_EQ(serial.n_subdomains, 1u);

  const auto& p = parallel.result.pairs.at(0);
  const auto& s = serial.result.pairs.at(0);
  EXPECT_EQ(p.n_stick, s.n_stick);
  EXPECT_EQ(p.n_slip, s.n_slip);
  EXPECT_GT(p.n_stick, 0u);
  EXPECT_GT(p.n_slip, 0u);
  EXPECT_EQ(parallel.result.active_set_iterations, serial.result.active_set_iterations);
  // Same discrete problem, different elimination order in MUMPS: agreement to ~1e-12 relative;
  // 1e-9 leaves margin for the friction fixed point stopping at 1e-8 in both runs alike.
  EXPECT_NEAR(p.normal_force, s.normal_force, 1e-9 * s.normal_force);
  EXPECT_NEAR(p.tangential_force, s.tangential_force, 1e-9 * s.normal_force);
  EXPECT_NEAR(p.max_pressure, s.max_pressure, 1e-9 * s.max_pressure);
  // Point by point along the surface (DoF numbers differ between partitions, positions do not).
  ASSERT_EQ(p.points.size(), s.points.size());
  for (unsigned int k = 0; k < p.points.size(); ++k)
  {
    EXPECT_EQ(p.points[k].position.distance(s.points[k].position), 0.);
    EXPECT_EQ(p.points[k].state, s.points[k].state);
    EXPECT_NEAR(p.points[k].pressure, s.points[k].pressure, 1e-9 * s.max_pressure);
    EXPECT_NEAR(p.points[k].shear[0], s.points[k].shear[0], 1e-9 * s.max_pressure);
    EXPECT_NEAR(p.points[k].slip[0], s.points[k].slip[0], 1e-9 * 0.3e-6);
  }
  // Reactions agree too.
  for (unsigned int k = 0; k < 2; ++k)
    for (unsigned int c = 0; c < 2; ++c)
      EXPECT_NEAR(parallel.result.supports[k].force[c], serial.result.supports[k].force[c],
                  1e-9 * s.normal_force);
}
