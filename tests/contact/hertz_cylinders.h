// The Hertz case of the contact tests: the cylinder pair of contact/cylinder_pair.h (R1 = 10 mm
// on R2 = 15 mm, steel, 1 mm thick), the upper top pressed down by `approach`, the lower bottom
// fixed; in 3D one hexahedron over the 1 mm depth with u_z = 0 on both z faces (plane strain).
#pragma once

#include "contact/contact_problem.h"
#include "contact/cylinder_pair.h"

#include <mpi.h>
#include <vector>

namespace gearstiff::test_support
{
inline const fem::Material steel{210e9, 0.3};
constexpr double cylinder_thickness = 1e-3; // m, the 2D thickness and the 3D depth

template <int dim>
contact::ContactResults<dim> solve_hertz_cylinders(double fine_size, double approach)
{
  using namespace contact;
  fem::ElasticityParameters elasticity;
  elasticity.thickness = cylinder_thickness;
  ContactProblem<dim> problem(MPI_COMM_WORLD, elasticity, fem::LinearSolverParameters(),
                              ContactParameters());
  CylinderPairGeometry geometry;
  geometry.fine_size = fine_size;
  geometry.depth = dim == 3 ? cylinder_thickness : 0.;
  geometry.depth_cells = 1;
  make_cylinder_pair(geometry, problem.system().triangulation());
  problem.system().set_materials({{upper_body, steel}, {lower_body, steel}}, "materials");
  dealii::Tensor<1, dim> displacement;
  displacement[1] = -approach;
  problem.add_displacement(upper_top, displacement, "upper top");
  problem.add_displacement(lower_bottom, dealii::Tensor<1, dim>(), "lower bottom");
  if (dim == 3)
  {
    std::vector<bool> z_only(dim, false);
    z_only[dim - 1] = true;
    problem.add_displacement(extrusion_faces, dealii::Tensor<1, dim>(), "z faces", z_only);
  }
  problem.add_contact_pair({upper_contact}, {lower_contact}, "cylinders");
  return problem.run();
}

// The elliptic Hertz profile p² = p0²(1 − x²/a²) fitted to the pressure at the closed nodes.
template <int dim>
contact::HertzLineContact fit_closed_nodes(const contact::PairResult<dim>& pair)
{
  std::vector<double> x, p;
  for (const auto& point : pair.points)
    if (point.state != contact::NodeState::open)
    {
      x.push_back(point.position[0]);
      p.push_back(point.pressure);
    }
  return contact::fit_hertz_profile(x, p);
}
} // namespace gearstiff::test_support
