// Parameters of the linear-elastic finite-element model shared by every analysis built on fem/:
// the kinematic model (plane strain, plane stress, 3D), the element degree, the materials of the
// bodies and the linear solver, in SI. Their parameter-file form (subsections "Finite elements"
// and "Linear solver", units in the documentation strings) is declared and parsed in
// app/scenes/fe_contact_parameters.cc, as every parameter of the project is in app/.
#pragma once

#include <map>
#include <string>

namespace gearstiff::fem
{
enum class PlanarModel
{
  plane_strain, // 2D, ε_zz = 0 (thick gears); forces are per `thickness`
  plane_stress  // 2D, σ_zz = 0 (thin webs); forces are per `thickness`
};

struct Material
{
  double youngs_modulus = 210e9; // Pa
  double poisson_ratio = 0.3;    // -

  // Lamé constants of the 3D law, Pa.
  double lame_lambda() const;
  double lame_mu() const;

  // Pa, λ of the law a `dim`-dimensional model uses: plane stress (2D only) eliminates σ_zz = 0
  // and replaces λ by 2λμ/(λ + 2μ); plane strain and 3D keep the 3D λ.
  double lame_lambda(int dim, PlanarModel model) const;
};

// Subsection "Finite elements". The space dimension comes from the mesh; `model` and
// `thickness` only matter for 2D meshes.
struct ElasticityParameters
{
  PlanarModel model = PlanarModel::plane_strain;
  unsigned int degree = 1; // FE_Q polynomial degree, 1 or 2
  double thickness = 1.0;  // m, out-of-plane extent of a 2D model (ignored in 3D)
};

enum class LinearSolverMethod
{
  direct_mumps, // sparse Cholesky (MUMPS): robust default for 2D
  cg_gamg,      // CG + PETSc GAMG with the rigid-body modes as near-null space (large 3D)
  cg_boomeramg  // CG + hypre BoomerAMG with nodal coarsening (large 3D)
};

// Subsection "Linear solver".
struct LinearSolverParameters
{
  LinearSolverMethod method = LinearSolverMethod::direct_mumps;
  double relative_tolerance = 1e-10; // -, iterative methods: |r| / |b|
  unsigned int max_iterations = 5000;
};

std::string to_string(PlanarModel model);
std::string to_string(LinearSolverMethod method);
} // namespace gearstiff::fem
