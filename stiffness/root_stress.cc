// The root stress of a gear pair's FE model (stiffness/root_stress.h).
#include "stiffness/root_stress.h"

#include "fem/stress.h"
#include "geometry/scene_gear_pair.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>
#include <limits>
#include <map>

namespace gearstiff::stiffness
{
using namespace dealii;

template <int dim>
std::vector<std::pair<typename DoFHandler<dim>::active_cell_iterator, unsigned int>>
fillet_faces(const DoFHandler<dim>& dof_handler, const kinematics::GearPairGeometry& pair)
{
  // The wheel's axis: an external wheel at +a_w, a ring at −a_w.
  const double wheel_x = pair.spec.wheel.internal ? -pair.centre_distance : pair.centre_distance;
  std::vector<std::pair<typename DoFHandler<dim>::active_cell_iterator, unsigned int>> fillets;
  for (const auto& cell : dof_handler.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
    {
      if (!cell->face(f)->at_boundary() ||
          cell->face(f)->boundary_id() != geometry::scene_ids::free_surface)
        continue;
      const bool pinion = cell->material_id() == geometry::scene_ids::pinion_body;
      const double x0 = pinion ? 0. : wheel_x;
      const double root = 0.5 * (pinion ? pair.pinion.root_diameter : pair.wheel.root_diameter);
      const double form = 0.5 * (pinion ? pair.pinion.form_diameter : pair.wheel.form_diameter);
      // Between the root and the form circle (a ring's root circle is the larger one).
      const double low = std::min(root * (1. - 1e-6), form);
      const double high = std::max(root * (1. + 1e-6), form);
      bool inside = true, on_root_circle = true;
      for (const unsigned int v : cell->face(f)->vertex_indices())
      {
        const Point<dim>& p = cell->face(f)->vertex(v);
        const double r = std::hypot(p[0] - x0, p[1]);
        inside = inside && r <= high && r >= low;
        on_root_circle = on_root_circle && std::abs(r - root) < 1e-9;
      }
      if (inside && !on_root_circle)
        fillets.emplace_back(cell, f);
    }
  return fillets;
}

template <int dim>
FilletStressPoints fillet_stress_points(
    const Mapping<dim>& mapping, const DoFHandler<dim>& dof_handler,
    const std::vector<std::pair<typename DoFHandler<dim>::active_cell_iterator, unsigned int>>&
        faces)
{
  FilletStressPoints points;
  points.dim = dim;
  points.point_start.push_back(0);
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  const QGauss<dim - 1> quadrature(fe.degree + 1);
  FEFaceValues<dim> fe_face(mapping, fe, quadrature, update_gradients);
  std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
  std::map<types::global_dof_index, unsigned int> row_of;
  for (const auto& [cell, f] : faces)
  {
    fe_face.reinit(cell, f);
    cell->get_dof_indices(cell_dofs);
    for (const unsigned int q : fe_face.quadrature_point_indices())
    {
      for (unsigned int i = 0; i < cell_dofs.size(); ++i)
      {
        const auto [it, added] =
            row_of.emplace(cell_dofs[i], static_cast<unsigned int>(points.dofs.size()));
        if (added)
          points.dofs.push_back(cell_dofs[i]);
        const unsigned int c = fe.system_to_component_index(i).first;
        points.term_row.push_back(it->second);
        points.term_component.push_back(c);
        const Tensor<1, dim> gradient = fe_face.shape_grad_component(i, q, c);
        for (unsigned int d = 0; d < dim; ++d)
          points.term_gradient.push_back(gradient[d]);
      }
      points.point_start.push_back(static_cast<unsigned int>(points.term_row.size()));
    }
  }
  return points;
}

namespace
{
template <int dim>
double largest(const FilletStressPoints& points, const std::vector<double>& values,
               const fem::Material& material, fem::PlanarModel model)
{
  double stress = 0.;
  for (std::size_t q = 0; q + 1 < points.point_start.size(); ++q)
  {
    Tensor<2, dim> gradient;
    for (unsigned int t = points.point_start[q]; t < points.point_start[q + 1]; ++t)
      for (unsigned int d = 0; d < dim; ++d)
        gradient[points.term_component[t]][d] +=
            values[points.term_row[t]] * points.term_gradient[dim * t + d];
    stress = std::max(stress, eigenvalues(fem::stress(material, model, gradient))[0]);
  }
  return stress;
}
} // namespace

double largest_fillet_stress(const FilletStressPoints& points, const std::vector<double>& values,
                             const fem::Material& material, fem::PlanarModel model)
{
  return points.dim == 3 ? largest<3>(points, values, material, model)
                         : largest<2>(points, values, material, model);
}

template std::vector<std::pair<DoFHandler<2>::active_cell_iterator, unsigned int>>
fillet_faces<2>(const DoFHandler<2>&, const kinematics::GearPairGeometry&);
template std::vector<std::pair<DoFHandler<3>::active_cell_iterator, unsigned int>>
fillet_faces<3>(const DoFHandler<3>&, const kinematics::GearPairGeometry&);
template FilletStressPoints fillet_stress_points<2>(
    const Mapping<2>&, const DoFHandler<2>&,
    const std::vector<std::pair<DoFHandler<2>::active_cell_iterator, unsigned int>>&);
template FilletStressPoints fillet_stress_points<3>(
    const Mapping<3>&, const DoFHandler<3>&,
    const std::vector<std::pair<DoFHandler<3>::active_cell_iterator, unsigned int>>&);
} // namespace gearstiff::stiffness
