// The two ways an active-set iteration is solved (contact/contact_problem.h) give the same
// answer: the Schur complement on the contact rows with one factorization of K (the default) and
// the reference that re-assembles and re-solves the condensed system every iteration. Both
// compute the same constrained minimum, so they must agree to round-off amplified by the
// conditioning of the contact problem; 1e-6 relative is the tolerance the contact-speed issue
// set, and the observed agreement is printed.
#include "contact/contact_problem.h"
#include "fem/mesh.h"
#include "tests/contact/hertz_cylinders.h"

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
const fem::Material steel{210e9, 0.3};

// Relative difference of two results: every pair's normal and tangential force, every
// support's force and torque, against the largest of them.
template <int dim>
double relative_difference(const ContactResults<dim>& a, const ContactResults<dim>& b)
{
  double scale = 0., difference = 0.;
  EXPECT_EQ(a.pairs.size(), b.pairs.size());
  for (unsigned int p = 0; p < a.pairs.size(); ++p)
  {
    scale = std::max(scale, std::abs(a.pairs[p].normal_force));
    difference = std::max(difference, std::abs(a.pairs[p].normal_force - b.pairs[p].normal_force));
    difference =
        std::max(difference, std::abs(a.pairs[p].tangential_force - b.pairs[p].tangential_force));
    EXPECT_EQ(a.pairs[p].n_closed, b.pairs[p].n_closed);
    EXPECT_EQ(a.pairs[p].n_stick, b.pairs[p].n_stick);
  }
  for (unsigned int s = 0; s < a.supports.size(); ++s)
    difference = std::max(difference, (a.supports[s].force - b.supports[s].force).norm());
  return difference / scale;
}

// A block pressed onto a base and pulled sideways (non-matching meshes, Coulomb μ = 0.3), as in
// test_friction.cc: the pull decides whether the interface sticks or slips.
ContactResults<2> run_block(double pull, IterationSolves method)
{
  constexpr double width = 1e-3, height = 0.5e-3;
  fem::ElasticityParameters elasticity;
  elasticity.thickness = 1e-3;
  ContactParameters contact;
  contact.friction_coefficient = 0.3;
  contact.iteration_solves = method;
  ContactProblem<2> problem(MPI_COMM_WORLD, elasticity, fem::LinearSolverParameters(), contact);
  Triangulation<2> block, base;
  GridGenerator::subdivided_hyper_rectangle(block, {8, 4}, Point<2>(0, 0), Point<2>(width, height),
                                            true);
  GridGenerator::subdivided_hyper_rectangle(base, {6, 4}, Point<2>(-0.2e-3, -height),
                                            Point<2>(width + 0.2e-3, 0), true);
  // Boundary ids: 1 block bottom (slave), 2 block top, 3 base top (master), 4 base bottom.
  auto relabel = [](Triangulation<2>& tria, types::material_id body,
                    const std::map<types::boundary_id, types::boundary_id>& ids)
  {
    for (auto& cell : tria.active_cell_iterators())
    {
      cell->set_material_id(body);
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
        {
          const auto found = ids.find(cell->face(f)->boundary_id());
          cell->face(f)->set_boundary_id(found == ids.end() ? 0 : found->second);
        }
    }
  };
  relabel(block, 1, {{2, 1}, {3, 2}});
  relabel(base, 2, {{3, 3}, {2, 4}});
  fem::join_bodies<2>({&block, &base}, problem.system().triangulation());
  problem.system().set_materials({{1, steel}, {2, steel}}, "materials");
  problem.add_displacement(4, Tensor<1, 2>(), "base bottom");
  problem.add_displacement(2, Tensor<1, 2>({pull, -0.2e-6}), "block top");
  problem.add_contact_pair({1}, {3}, "block");
  return problem.run();
}
} // namespace

TEST(IterationSolves, HertzCylindersAgree)
{
  using test_support::solve_hertz_cylinders;
  // Displacement control through the supports; the fine size of the Hertz tests' coarse level.
  ContactParameters reference_parameters;
  const auto schur = solve_hertz_cylinders<2>(0.05e-3, 2e-6);
  EXPECT_TRUE(schur.schur_complement);
  // The reference path: the same case with every iteration re-assembled.
  fem::ElasticityParameters elasticity;
  elasticity.thickness = test_support::cylinder_thickness;
  ContactParameters full;
  full.iteration_solves = IterationSolves::full_resolve;
  ContactProblem<2> problem(MPI_COMM_WORLD, elasticity, fem::LinearSolverParameters(), full);
  CylinderPairGeometry geometry;
  geometry.fine_size = 0.05e-3;
  make_cylinder_pair(geometry, problem.system().triangulation());
  problem.system().set_materials({{upper_body, steel}, {lower_body, steel}}, "materials");
  problem.add_displacement(upper_top, Tensor<1, 2>({0., -2e-6}), "upper top");
  problem.add_displacement(lower_bottom, Tensor<1, 2>(), "lower bottom");
  problem.add_contact_pair({upper_contact}, {lower_contact}, "cylinders");
  const ContactResults<2> reference = problem.run();
  EXPECT_FALSE(reference.schur_complement);
  const double difference = relative_difference(schur, reference);
  std::cout << "Hertz: Schur " << schur.active_set_iterations << " iterations, "
            << schur.solve_time + schur.assembly_time << " s; full re-solve "
            << reference.active_set_iterations << " iterations, "
            << reference.solve_time + reference.assembly_time << " s; relative difference "
            << difference << "\n";
  EXPECT_LT(difference, 1e-6);
  EXPECT_EQ(schur.active_set_iterations, reference.active_set_iterations);
}

TEST(IterationSolves, FrictionBlockAgreesInStickAndSlip)
{
  for (const double pull : {0.02e-6, 5e-6})
  {
    const ContactResults<2> schur = run_block(pull, IterationSolves::schur_complement);
    const ContactResults<2> reference = run_block(pull, IterationSolves::full_resolve);
    const double difference = relative_difference(schur, reference);
    std::cout << "block pull " << pull << " m: " << schur.pairs[0].n_stick << " stick, "
              << schur.pairs[0].n_slip << " slip, relative difference " << difference << "\n";
    EXPECT_LT(difference, 1e-6);
    EXPECT_EQ(schur.active_set_iterations, reference.active_set_iterations);
  }
}
