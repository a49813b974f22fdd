#include "fem/small_strain.h"

#include "errors/errors.h"
#include "errors/limits.h"

#include <deal.II/grid/grid_tools.h>
#include <sstream>

namespace gearstiff::fem
{
template <int dim>
double displacement_ratio(const dealii::DoFHandler<dim>& dofs, const dealii::Vector<double>& u)
{
  const double diameter = dealii::GridTools::diameter(dofs.get_triangulation());
  return u.linfty_norm() / diameter;
}

template <int dim>
void check_small_strain(const dealii::DoFHandler<dim>& dofs, const dealii::Vector<double>& u,
                        const std::string& load_parameter)
{
  check_small_strain(dealii::GridTools::diameter(dofs.get_triangulation()), u, load_parameter);
}

void check_small_strain(double diameter, const dealii::Vector<double>& u,
                        const std::string& load_parameter)
{
  const double ratio = u.linfty_norm() / diameter;
  // NaN fails the comparison and is refused too.
  if (ratio <= limits::small_strain)
    return;
  std::ostringstream reason;
  reason.precision(3);
  reason << "the solved displacement reaches " << ratio << " of the body size (small-strain limit "
         << limits::small_strain
         << ", docs/limits.md): the linear model is not valid at this load; reduce it";
  throw InputError(load_parameter, reason.str());
}

template double displacement_ratio<2>(const dealii::DoFHandler<2>&, const dealii::Vector<double>&);
template double displacement_ratio<3>(const dealii::DoFHandler<3>&, const dealii::Vector<double>&);
template void check_small_strain<2>(const dealii::DoFHandler<2>&, const dealii::Vector<double>&,
                                    const std::string&);
template void check_small_strain<3>(const dealii::DoFHandler<3>&, const dealii::Vector<double>&,
                                    const std::string&);
} // namespace gearstiff::fem
