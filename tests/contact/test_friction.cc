// Coulomb friction on a block pressed onto a base (non-matching meshes): pulled far enough, the
// block slides and the interface transmits exactly T = μ·N (Coulomb's law, each slip node at
// |λ_τ| = μ λ_n); under a tangential load below μ·N it sticks and carries the load; above μ·N no
// equilibrium exists and the solver must say so instead of returning a number.
#include "contact/contact_problem.h"
#include "errors/errors.h"
#include "fem/mesh.h"

#include <cmath>
#include <deal.II/grid/grid_generator.h>
#include <gtest/gtest.h>
#include <iostream>
#include <mpi.h>

using namespace dealii;
using namespace gearstiff;
using namespace gearstiff::contact;

namespace
{
constexpr double width = 1e-3, height = 0.5e-3, thickness = 1e-3; // m
constexpr double pressure = 50e6;                                 // Pa, force control
constexpr double press = 0.2e-6;                                  // m, displacement control
constexpr double mu = 0.3;
const fem::Material steel{210e9, 0.3};

// Boundary ids: 1 block bottom (slave), 2 block top, 3 base top (master), 4 base bottom.
void make_block_on_base(Triangulation<2>& tria)
{
  Triangulation<2> block, base;
  GridGenerator::subdivided_hyper_rectangle(block, {8, 4}, Point<2>(0, 0), Point<2>(width, height),
                                            true);
  GridGenerator::subdivided_hyper_rectangle(base, {6, 4}, Point<2>(-0.2e-3, -height),
                                            Point<2>(width + 0.2e-3, 0), true);
  for (auto& cell : block.active_cell_iterators())
  {
    cell->set_material_id(1);
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary())
      {
        const auto id = cell->face(f)->boundary_id();
        cell->face(f)->set_boundary_id(id == 2 ? 1 : id == 3 ? 2 : 0);
      }
  }
  for (auto& cell : base.active_cell_iterators())
  {
    cell->set_material_id(2);
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary())
      {
        const auto id = cell->face(f)->boundary_id();
        cell->face(f)->set_boundary_id(id == 3 ? 3 : id == 2 ? 4 : 0);
      }
  }
  fem::join_bodies<2>({&block, &base}, tria);
}

// The block's top is moved by (pull, −press); the base bottom is fixed. Holding the whole top
// keeps the block from rocking, so N and T follow from the interface alone.
ContactResults<2> run_block(double pull, double shear_traction = 0.)
{
  fem::ElasticityParameters elasticity;
  elasticity.thickness = thickness;
  ContactParameters contact;
  contact.friction_coefficient = mu;
  ContactProblem<2> problem(MPI_COMM_WORLD, elasticity, fem::LinearSolverParameters(), contact);
  make_block_on_base(problem.system().triangulation());
  problem.system().set_materials({{1, steel}, {2, steel}}, "materials");
  problem.add_displacement(4, Tensor<1, 2>(), "base bottom");
  if (shear_traction != 0.)
  {
    // Force control: pressure and shear on the top, which is otherwise free.
    problem.system().add_traction(2, Tensor<1, 2>({shear_traction, -pressure}));
  }
  else
    problem.add_displacement(2, Tensor<1, 2>({pull, -press}), "block top");
  problem.add_contact_pair({1}, {3}, "block");
  return problem.run();
}
} // namespace

TEST(Friction, SlidingBlockTransmitsMuTimesNormalForce)
{
  // 5 µm is far beyond the elastic tangential compliance (~0.1 µm at μN): gross sliding.
  const ContactResults<2> result = run_block(5e-6);
  const PairResult<2>& pair = result.pairs.at(0);
  std::cout << "slip: N = " << pair.normal_force << " N, T = " << pair.tangential_force
            << " N, T/N = " << pair.tangential_force / pair.normal_force << ", iterations "
            << result.active_set_iterations << ", slip nodes " << pair.n_slip << "/"
            << pair.points.size() << "\n";
  EXPECT_EQ(pair.n_slip, pair.points.size());
  // T = μN to the fixed-point tolerance on the friction forces (1e-8 relative).
  EXPECT_NEAR(pair.tangential_force, mu * pair.normal_force, 1e-7 * pair.normal_force);
  // The top support holds the block against friction: equilibrium in x and y.
  EXPECT_NEAR(result.supports.at(1).force[0], -pair.force_on_slave[0], 1e-9 * pair.normal_force);
  EXPECT_NEAR(result.supports.at(1).force[1], -pair.force_on_slave[1], 1e-9 * pair.normal_force);
  // The slip forces converge as a fixed point on the Coulomb bound: observed 13 iterations at
  // μ = 0.3, each cutting the force change by ~10 (at the gear's μ = 0.01 it takes 3-4).
  EXPECT_LE(result.active_set_iterations, 16u);
}

TEST(Friction, BelowMuTimesNormalForceTheBlockSticks)
{
  // A tangential pull of 0.02 µm needs a shear far below μN: the whole interface sticks.
  const ContactResults<2> result = run_block(0.02e-6);
  const PairResult<2>& pair = result.pairs.at(0);
  double largest_slip = 0;
  for (const auto& point : pair.points)
    largest_slip = std::max(largest_slip, point.slip.norm());
  std::cout << "stick: T/N = " << pair.tangential_force / pair.normal_force << ", stick nodes "
            << pair.n_stick << "/" << pair.points.size() << ", largest slip " << largest_slip
            << " m, iterations " << result.active_set_iterations << "\n";
  EXPECT_LT(pair.tangential_force, mu * pair.normal_force);
  EXPECT_EQ(pair.n_slip, 0u);
  EXPECT_EQ(pair.n_stick, pair.points.size());
  // Stick is exact: the relative tangential displacement is zero to round-off.
  EXPECT_LT(largest_slip, 1e-15);
}

TEST(Friction, ShearAboveMuTimesPressureHasNoEquilibrium)
{
  // Force control: a shear traction of 1.2 μ p on a block held only by the contact cannot be
  // balanced by friction; the block is free to slide and the solver must say so.
  EXPECT_THROW(run_block(0., 1.2 * mu * pressure), SolverFailure);
}
