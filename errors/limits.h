// The limits gearstiff enforces before it starts work that could not finish or whose result would
// be outside the model's validity. One place for all of them, so that docs/limits.md, the
// checks and their messages agree. Each check names the parameter to change and the estimate.
#pragma once

namespace gearstiff::limits
{
// -, cells of one mesh (2D quadrilaterals, or 3D hexahedra = quadrilaterals × layers), estimated
// from the size field before meshing. The default stiffness scene has about 2·10⁴ cells and
// solves in seconds; with Q2 elements 10⁶ cells are about 8·10⁶ unknowns, whose direct
// factorisation needs several GB and many minutes per active-set iteration on this class of
// machine, and gmsh's quadrilateral recombination at that size runs for hours.
constexpr double max_cells_2d = 1.0e6;
// -, hexahedra: a 3D Q2 direct solve fills far more per unknown than a 2D one.
constexpr double max_cells_3d = 2.0e5;

// -, the small-strain (linear kinematics) model: the largest displacement of a solve divided by
// the size of the body (mesh diameter) must stay below this. Rigid-body rotations are linearised
// (an angle θ moves points by θ·r instead of along the arc; the error is θ²/2), and linear
// elasticity is only valid for strains far below 1%: beyond 10⁻² the numbers are not a
// stiffness of the real drive. At the published gear load case the ratio is about 10⁻⁴.
constexpr double small_strain = 1e-2;

// characters of a user's value echoed back in an error message; longer values are cut.
constexpr unsigned int echoed_value_length = 80;
} // namespace gearstiff::limits
