// The limits gearstiff enforces before it starts work that could not finish or whose result would
// be outside the model's validity. One place for all of them, so that docs/limits.md, the
// checks and their messages agree. Each check names the parameter to change and the estimate.
#pragma once

namespace gearstiff::limits
{
// -, cells of one mesh (2D quadrilaterals, or 3D hexahedra = quadrilaterals × layers), estimated
// from the size field before meshing. Measured: the default stiffness position (6389 Q2 cells,
// 53 320 unknowns) peaks at 303 MB and solves in 8 s; about 4 kB per unknown beyond a 100 MB
// base. 5·10⁵ Q2 cells are about 4·10⁶ unknowns, ~16 GB for the direct factorisation and many
// minutes per active-set iteration: the most a workstation (here 23 GB) can finish. gmsh alone
// meshed 1.1·10⁵ cells (cycloid scene) in 15 s, so meshing up to the limit takes minutes.
constexpr double max_cells_2d = 5.0e5;
// -, hexahedra: a 3D Q2 direct solve fills far more per unknown than a 2D one; the default 3D
// gear scene has 5.3·10⁴.
constexpr double max_cells_3d = 2.0e5;
// bytes per 2D Q2 cell of a contact solve (measured as above: (303 − 100) MB / 6389 cells), for
// the memory stated beside a refused cell estimate.
constexpr double solve_bytes_per_cell_2d = 32e3;

// -, the small-strain (linear kinematics) model: the largest displacement of a solve divided by
// the size of the body (mesh diameter) must stay below this. Rigid-body rotations are linearised
// (an angle θ moves points by θ·r instead of along the arc; the error is θ²/2), and linear
// elasticity is only valid for strains far below 1%: beyond 10⁻² the numbers are not a
// stiffness of the real drive. At the published gear load case (49.4 N·m) the ratio is about
// 3·10⁻⁵ (measured 519 at 10⁹ N·m, scaled linearly).
constexpr double small_strain = 1e-2;

// characters of a user's value echoed back in an error message; longer values are cut.
constexpr unsigned int echoed_value_length = 80;
} // namespace gearstiff::limits
