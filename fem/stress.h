// The stress law of the linear-elastic model, one copy for every place that turns a
// displacement gradient into stress (VTU output, root and von Mises stress of the analyses).
#pragma once

#include "fem/parameters.h"

#include <cmath>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace gearstiff::fem
{
// Pa, the stress σ = λ tr(ε) I + 2μ ε of the displacement gradient ∇u (-, row = component) in
// a body of `material`; in 2D the in-plane components, λ that of `model` (plane stress
// eliminates σ_zz = 0).
template <int dim>
dealii::SymmetricTensor<2, dim> stress(const Material& material, PlanarModel model,
                                       const dealii::Tensor<2, dim>& gradient)
{
  const dealii::SymmetricTensor<2, dim> strain = dealii::symmetrize(gradient);
  return material.lame_lambda(dim, model) * dealii::trace(strain) *
             dealii::unit_symmetric_tensor<dim>() +
         2. * material.lame_mu() * strain;
}

// Pa, the von Mises stress of the same state; in 2D σ_zz = ν(σ_xx + σ_yy) in plane strain and
// 0 in plane stress.
template <int dim>
double von_mises_stress(const Material& material, PlanarModel model,
                        const dealii::Tensor<2, dim>& gradient)
{
  const dealii::SymmetricTensor<2, dim> in_plane = stress(material, model, gradient);
  dealii::SymmetricTensor<2, 3> full;
  for (unsigned int a = 0; a < dim; ++a)
    for (unsigned int b = a; b < dim; ++b)
      full[a][b] = in_plane[a][b];
  if (dim == 2 && model == PlanarModel::plane_strain)
    full[2][2] = material.poisson_ratio * (in_plane[0][0] + in_plane[1][1]);
  const dealii::SymmetricTensor<2, 3> deviator =
      full - dealii::trace(full) / 3. * dealii::unit_symmetric_tensor<3>();
  return std::sqrt(1.5 * dealii::scalar_product(deviator, deviator));
}
} // namespace gearstiff::fem
