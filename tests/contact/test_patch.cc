// Contact patch test (Taylor & Papadopoulos 1991, Int. J. Numer. Meth. Eng. 32:1045; for dual
// mortar Wohlmuth 2000, SIAM J. Numer. Anal. 38:989): two blocks of different materials with
// non-matching meshes, the upper one pressed onto the lower one by a uniform pressure p. The
// exact solution is a uniform stress σ_yy = −p in both, so every slave node must carry the
// pressure p and every master interface node the consistent nodal force of a uniform pressure,
// to the precision of the direct solver.
#include "contact/contact_problem.h"
#include "fem/mesh.h"

#include <cmath>
#include <deal.II/grid/grid_generator.h>
#include <gtest/gtest.h>
#include <mpi.h>

using namespace dealii;
using namespace gearstiff;
using namespace gearstiff::contact;

namespace
{
// Boundary ids: upper contact 1, upper top 2, upper left 3, lower contact 4, lower bottom 5,
// lower left 6.
void make_blocks(unsigned int upper_cells, unsigned int lower_cells, Triangulation<2>& tria)
{
  const double width = 1e-3, height = 0.6e-3; // m
  Triangulation<2> upper, lower;
  GridGenerator::subdivided_hyper_rectangle(upper, {upper_cells, 3}, Point<2>(0, 0),
                                            Point<2>(width, height), true);
  GridGenerator::subdivided_hyper_rectangle(lower, {lower_cells, 2}, Point<2>(0, -height),
                                            Point<2>(width, 0), true);
  for (auto& cell : upper.active_cell_iterators())
    cell->set_material_id(1);
  for (auto& cell : lower.active_cell_iterators())
    cell->set_material_id(2);
  const std::map<types::boundary_id, types::boundary_id> upper_ids{{0, 3}, {1, 0}, {2, 1}, {3, 2}};
  const std::map<types::boundary_id, types::boundary_id> lower_ids{{0, 6}, {1, 0}, {2, 5}, {3, 4}};
  for (auto& [tria_part, ids] : {std::pair{&upper, upper_ids}, std::pair{&lower, lower_ids}})
    for (auto& cell : tria_part->active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          cell->face(f)->set_boundary_id(ids.at(cell->face(f)->boundary_id()));
  fem::join_bodies<2>({&upper, &lower}, tria);
}

void run_patch_test(unsigned int degree, unsigned int upper_cells, unsigned int lower_cells)
{
  const double pressure = 100e6; // Pa
  fem::ElasticityParameters elasticity;
  elasticity.degree = degree;
  elasticity.thickness = 2e-3;
  ContactProblem<2> problem(MPI_COMM_WORLD, elasticity, fem::LinearSolverParameters(),
                            ContactParameters());
  make_blocks(upper_cells, lower_cells, problem.system().triangulation());
  problem.system().set_materials({{1, {210e9, 0.3}}, {2, {70e9, 0.33}}}, "materials");
  problem.system().add_traction(2, Tensor<1, 2>({0., -pressure}));
  // Rollers: the lower bottom in y, both left sides in x; the upper block rests on the contact.
  problem.add_displacement(5, Tensor<1, 2>(), "lower bottom", {false, true});
  problem.add_displacement(6, Tensor<1, 2>(), "lower left", {true, false});
  problem.add_displacement(3, Tensor<1, 2>(), "upper left", {true, false});
  problem.add_contact_pair({1}, {4}, "interface");
  const ContactResults<2>& result = problem.run();

  const PairResult<2>& pair = result.pairs.at(0);
  EXPECT_EQ(pair.n_closed, pair.points.size());
  EXPECT_EQ(pair.points.size(), degree * upper_cells + 1);
  for (const auto& point : pair.points)
    // MUMPS solves to round-off (~1e-15 relative); 1e-9 leaves room for the condition number.
    EXPECT_NEAR(point.pressure, pressure, 1e-9 * pressure) << "x = " << point.position[0];
  EXPECT_NEAR(pair.normal_force, pressure * 1e-3 * elasticity.thickness,
              1e-9 * pressure * 1e-3 * elasticity.thickness);
  // The active set is right at once: the blocks touch everywhere from the start.
  EXPECT_LE(result.active_set_iterations, 2u);

  // Master side: the nodal forces the contact puts on the lower block are the consistent
  // loads of a uniform pressure on the lower mesh, although that mesh does not match.
  const auto master = fem::boundary_nodes(problem.system().get_dof_handler(), {4});
  const Vector<double> r = problem.system().residual(problem.solution());
  std::vector<double> consistent(master.size(), 0.);
  const double h = 1e-3 / lower_cells;
  for (unsigned int k = 0; k < master.size(); ++k)
  {
    // ∫ N_m over the surface: Q1 h (h/2 at the ends); Q2 vertices h/3 (h/6 at the ends),
    // midpoints 2h/3.
    const double x = master[k].position[0] / h;
    const bool vertex = std::abs(x - std::round(x)) < 1e-6;
    const bool end = std::abs(x) < 1e-6 || std::abs(x - lower_cells) < 1e-6;
    double weight = degree == 1 ? h : (vertex ? h / 3. : 2. * h / 3.);
    if (end)
      weight /= 2.;
    EXPECT_NEAR(r[master[k].dofs[1]], -pressure * weight * elasticity.thickness,
                1e-9 * pressure * h * elasticity.thickness)
        << "master node x = " << master[k].position[0];
  }
}
} // namespace

TEST(PatchTest, NonMatchingLinear)
{
  run_patch_test(1, 7, 5);
}
TEST(PatchTest, NonMatchingQuadratic)
{
  run_patch_test(2, 5, 3);
}
