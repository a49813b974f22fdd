#include "fem/parameters.h"

namespace gearstiff::fem
{
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
