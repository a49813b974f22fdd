// Whether the corners of a linear element span a cell: shared by the readers of meshes that come
// from outside (gmsh .msh, Abaqus/CalculiX .inp), since a degenerate cell otherwise surfaces only
// as a failed factorization ("PETSc error code 81") — a solver failure for what is bad input.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace gearstiff::fem
{
// True when the corner Jacobians of an element (Abaqus corner order: quadrilateral
// counter-clockwise or clockwise; hexahedron bottom 1-4 then top 5-8) are all non-zero and of one
// sign: each corner's edges to its neighbours, crossed (2D) or as a triple product (3D), divided
// by the product of their lengths (the scaled Jacobian) must exceed 1e-8 in size.
// The corner order of an Abaqus element (counter-clockwise; hexahedron bottom then top) to
// deal.II's lexicographic one, and back: the permutation is its own inverse.
std::vector<unsigned int> cyclic_corner_order(unsigned int dim);

template <int dim>
bool corners_span_a_cell(const std::vector<Eigen::Vector3d>& x);
} // namespace gearstiff::fem
