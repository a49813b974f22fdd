#include "fem/parameters.h"

namespace gearstiff::fem
{
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;

double Material::lame_lambda() const
{
  return youngs_modulus * poisson_ratio / ((1. + poisson_ratio) * (1. - 2. * poisson_ratio));
}

double Material::lame_mu() const
{
  return youngs_modulus / (2. * (1. + poisson_ratio));
}

double Material::lame_lambda(const int dim, const PlanarModel model) const
{
  const double lambda = lame_lambda(), mu = lame_mu();
  if (dim == 2 && model == PlanarModel::plane_stress)
    return 2. * lambda * mu / (lambda + 2. * mu);
  return lambda;
}

void ElasticityParameters::declare_parameters(dealii::ParameterHandler& prm)
{
  prm.declare_entry("Planar model", "plane strain", Selection("plane strain|plane stress"),
                    "2D meshes only: plane strain (thick gears, ε_zz = 0) or plane stress "
                    "(thin webs, σ_zz = 0)");
  prm.declare_entry("Element degree", "1", Integer(1, 2),
                    "polynomial degree of the FE_Q displacement elements (1 or 2)");
  prm.declare_entry("Thickness", "1", Double(1e-9),
                    "mm; out-of-plane depth of a 2D model (face width): all forces and torques "
                    "are totals over it");
}

void ElasticityParameters::parse_parameters(dealii::ParameterHandler& prm)
{
  model = prm.get("Planar model") == "plane stress" ? PlanarModel::plane_stress
                                                    : PlanarModel::plane_strain;
  degree = prm.get_integer("Element degree");
  thickness = prm.get_double("Thickness") * 1e-3;
}

void LinearSolverParameters::declare_parameters(dealii::ParameterHandler& prm)
{
  prm.declare_entry("Method", "direct", Selection("direct|cg-gamg|cg-boomeramg"),
                    "direct: MUMPS sparse Cholesky (default, robust in 2D); cg-gamg: CG with "
                    "PETSc GAMG and the rigid-body modes; cg-boomeramg: CG with hypre "
                    "BoomerAMG (nodal coarsening); the iterative ones for large 3D meshes");
  prm.declare_entry("Relative tolerance", "1e-10", Double(1e-16, 1e-2),
                    "-, iterative methods: stop when |b - A x| <= tolerance |b|");
  prm.declare_entry("Max iterations", "5000", Integer(1),
                    "-, iterative methods: iteration limit (reaching it is a solver failure)");
}

void LinearSolverParameters::parse_parameters(dealii::ParameterHandler& prm)
{
  const std::string name = prm.get("Method");
  method = name == "cg-gamg"        ? LinearSolverMethod::cg_gamg
           : name == "cg-boomeramg" ? LinearSolverMethod::cg_boomeramg
                                    : LinearSolverMethod::direct_mumps;
  relative_tolerance = prm.get_double("Relative tolerance");
  max_iterations = prm.get_integer("Max iterations");
}

std::string to_string(PlanarModel model)
{
  return model == PlanarModel::plane_stress ? "plane stress" : "plane strain";
}

std::string to_string(LinearSolverMethod method)
{
  switch (method)
  {
  case LinearSolverMethod::cg_gamg:
    return "CG + GAMG";
  case LinearSolverMethod::cg_boomeramg:
    return "CG + BoomerAMG";
  default:
    return "MUMPS Cholesky";
  }
}
} // namespace gearstiff::fem
