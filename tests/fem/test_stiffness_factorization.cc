// StiffnessFactorization's two ways to the responses of sparse loads
// (fem/stiffness_factorization.h): responses() asks K⁻¹ column by column for every DoF a load
// touches, load_responses() solves for the load vectors themselves (MUMPS sparse right-hand sides,
// in blocks). They are the same linear map, so they must agree to round-off, also for what the
// influence model's loads can be: spread over several DoFs, on held (constrained) DoFs, empty, and
// whole blocks of those; and both must agree with response() of the complete load vector.
#include "fem/elastic_system.h"
#include "fem/stiffness_factorization.h"
#include "fem/supports.h"

#include <algorithm>
#include <cmath>
#include <deal.II/grid/grid_generator.h>
#include <gtest/gtest.h>
#include <iostream>
#include <mpi.h>
#include <random>

using namespace dealii;
using namespace gearstiff;
using namespace gearstiff::fem;

TEST(StiffnessFactorization, LoadResponsesEqualResponses)
{
  ElasticityParameters elasticity;
  elasticity.degree = 1;
  elasticity.thickness = 0.02; // m
  ElasticSystem<2> system(MPI_COMM_SELF, elasticity, LinearSolverParameters());
  // An annulus (radii 10 and 30 mm) held at its outer circle (boundary id 1).
  GridGenerator::hyper_shell(system.triangulation(), Point<2>(), 0.01, 0.03, 8, true);
  system.triangulation().refine_global(3);
  system.set_materials({{0, Material{210e9, 0.3}}}, "material");
  system.setup_system();
  const auto held = boundary_nodes(system.get_dof_handler(), {1});
  AffineConstraints<double> constraints;
  add_prescribed_displacement(held, Tensor<1, 2>(), constraints);
  constraints.close();
  const StiffnessFactorization<2> factorization(system, constraints, Vector<double>());

  const types::global_dof_index n = system.get_dof_handler().n_dofs();
  std::vector<types::global_dof_index> held_dofs;
  for (types::global_dof_index i = 0; i < n; ++i)
    if (constraints.is_constrained(i))
      held_dofs.push_back(i);
  ASSERT_FALSE(held_dofs.empty());
  // 2^24/n DoFs > 256: blocks of 256 loads. Loads 256-511 form a block with no free DoF at all
  // (empty, or on held DoFs only); the others touch 1-4 DoFs anywhere, held ones included.
  std::mt19937 random(20261205);
  std::uniform_int_distribution<types::global_dof_index> any(0, n - 1);
  std::uniform_int_distribution<std::size_t> any_held(0, held_dofs.size() - 1);
  std::uniform_real_distribution<double> value(-1., 1.);
  std::vector<SparseLoad> loads(700);
  for (std::size_t j = 0; j < loads.size(); ++j)
  {
    const bool nothing_free = j >= 256 && j < 512;
    const std::size_t entries = nothing_free && j % 2 == 0 ? 0 : 1 + j % 4;
    for (std::size_t e = 0; e < entries; ++e)
      loads[j].emplace_back(nothing_free ? held_dofs[any_held(random)] : any(random),
                            value(random));
  }
  std::vector<types::global_dof_index> rows;
  for (unsigned int i = 0; i < 40; ++i)
    rows.push_back(any(random));
  rows.push_back(held_dofs.front()); // a held row reads 0

  const auto column = factorization.responses(loads, rows);
  const auto solved = factorization.load_responses(loads, rows);
  ASSERT_EQ(solved.size(), loads.size());
  double largest = 0.;
  for (const auto& row : column)
    for (const double u : row)
      largest = std::max(largest, std::abs(u));
  ASSERT_GT(largest, 0.);
  // Round-off of two MUMPS solves of a well-conditioned system (measured ≤ 1e-15 of the largest
  // response, 2026-12-05); 1e-10 leaves room for other BLAS.
  double worst = 0.;
  for (std::size_t j = 0; j < loads.size(); ++j)
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
      EXPECT_NEAR(solved[j][i], column[j][i], 1e-10 * largest) << "load " << j << ", row " << i;
      worst = std::max(worst, std::abs(solved[j][i] - column[j][i]));
    }
  std::cout << "load_responses against responses: worst " << worst / largest
            << " of the largest response\n";
  for (std::size_t j = 256; j < 512; ++j)
    for (std::size_t i = 0; i < rows.size(); ++i)
      EXPECT_EQ(solved[j][i], 0.) << "load " << j << " has no free DoF";
  for (const std::size_t j : {0, 1, 600})
  {
    Vector<double> load(n);
    for (const auto& [dof, f] : loads[j])
      load[dof] += f;
    const Vector<double> u = factorization.response(load);
    for (std::size_t i = 0; i < rows.size(); ++i)
      EXPECT_NEAR(solved[j][i], u[rows[i]], 1e-10 * largest) << "load " << j << ", row " << i;
  }
}
