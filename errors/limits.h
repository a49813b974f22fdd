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
// bytes, the memory of one 3D contact solve (mesh, matrices, direct factorization) on one
// process, estimated before meshing from the hexahedra, the layers and the element degree
// (geometry::estimate_mesh): the largest accepted solve fits a 16 GB workstation. A cell count
// cannot say it: a Q2 hexahedron carries ~8× the unknowns of a Q1 one (2·10⁵ hexahedra are
// ~7·10⁵ unknowns at Q1, ~5·10⁶ at Q2). A rolling (`once`) sweep factorizes the whole mesh on
// every rank (MPI_COMM_SELF): R ranks hold R such solves.
constexpr double max_solve_bytes_3d = 16e9;
// bytes per unknown of a 3D contact solve on one process, peak RSS over the DoFs (the built-in
// spur pair, 1 rank, frictionless, 2026-12-02; docs/limits.md): Q1 4, 8, 16 layers 105 885,
// 190 593, 279 225 DoFs: 8.0, 9.2, 11.6 kB; Q2 1, 2 layers 244 188, 406 980 DoFs: 8.8,
// 10.6 kB. From 5·10⁵ DoFs
// the factors go out of core (fem/stiffness_factorization): Q1 633 024 DoFs (helical, 2 ranks)
// 11.0 kB, Q2 1 058 148 (6 layers, 2 ranks) 10.1 kB in all. The largest measured per degree.
constexpr double solve_bytes_per_unknown_3d_q1 = 12e3;
constexpr double solve_bytes_per_unknown_3d_q2 = 11e3;
// -, hexahedra of the built-in Hertz case in 3D (`contact` without a mesh, counted exactly; one
// cell through the depth, Q2 by default): the cell limit of the meshes before
// max_solve_bytes_3d, kept for that case alone.
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

// Abaqus/CalculiX decks (fem/abaqus_reader.cc). *INCLUDE expansions of one deck in all: a deck
// that includes 10 files per level over 8 levels expands to 10⁸ files and never finished; real
// decks include a handful (mesh, sets, materials). Nesting deeper than max_deck_include_depth is
// taken for a cycle.
constexpr unsigned int max_deck_includes = 1000;
constexpr unsigned int max_deck_include_depth = 20;
// -, elements of a deck: the most any contact solve of gearstiff can hold (max_cells_2d); a set
// (*ELSET, GENERATE) can list no more than the deck defines. Both are checked before a member is
// stored: GENERATE 1, 4e18 asked for 4·10¹⁸ ids (3·10¹⁹ bytes).
constexpr double max_deck_elements = max_cells_2d;
// m, |coordinate| of a deck node after Mesh/Length unit: beyond a kilometre no gear drive; the
// squares of larger values (1e300) overflow in deal.II's cell measures.
constexpr double max_deck_coordinate = 1e3;

// The work of one run of a sweep command (cycloid-loads: torque levels and crank angles of every
// profile), estimated before the first solve: solves × the measured time of one solve, divided by
// the ranks. Measured: the default cycloid-loads position (Q2, 12 solves) takes 38.5 s on one rank,
// 3.2 s per solve (docs/cycloid.md). An estimate above an hour is refused: 10000 sweep positions
// (2·10⁴ solves, ~18 h) or 1000 torque steps (2000 solves, ~1.8 h) ran without end.
constexpr double max_run_seconds = 3600.;

// -, members of a gear train (copies of a planet and all): each is a degree of freedom of the
// torsional model, integrated over every time step; a planetary stage has a few (3 to 8)
// planets. 2·10⁹ copies were allocated (the kernel killed the run at 24 GB).
constexpr unsigned int max_train_members = 1000;

// -, the largest cell edge at a contact point over the contact size that a mesh may keep after
// gmsh's retries (geometry::mesh_planar_model): gmsh follows the size field only roughly, and
// 128- and 256-position sweeps on a coarse scene failed on cells 1.0006 to 1.05 times the size.
// The contact size is a target the user chose for resolution, not an accuracy guarantee.
constexpr double contact_size_overshoot = 1.10;

// m, the smallest hole, pad or width a scene draws (bolt holes, support pads): the mesher joins
// outline points closer than 1 nm, and a 10⁻⁶ mm hole failed as "boundary piece 0 repeats a point"
// naming no parameter. 0.01 mm is far below any drawn feature of a gear body.
constexpr double min_feature_size = 1e-5;

// N/m, the mesh stiffness of a gear pair (dynamics: constant, Cai, tables, stiffness files).
// Steel teeth have c' ≈ 14 N/(mm·µm) per mm of face width (ISO 6336-1, docs/references.md §5): face
// widths of 1 mm to 1 m give 1.4·10⁷ to 1.4·10¹⁰ N/m, plastic teeth (E ~100× lower) ~10⁵ N/m.
// Outside [10³, 10¹²] N/m (10⁻³ to 10⁶ N/µm) a value is a unit mistake: k = 10⁻¹² N/µm gave a
// dynamic factor of 1 (no gear at all), 10³⁰⁰ N/µm overflowed the modal analysis.
constexpr double min_mesh_stiffness = 1e3;
constexpr double max_mesh_stiffness = 1e12;

// characters of a user's value echoed back in an error message; longer values are cut.
constexpr unsigned int echoed_value_length = 80;
} // namespace gearstiff::limits
