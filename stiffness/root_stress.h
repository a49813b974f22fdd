// The root stress of a gear pair's FE model: the largest first principal stress on the fillets
// (ISO 6336-3 takes the tensile fillet stress), one definition for the exact path
// (GearMeshStiffness::evaluate_root_stress) and the influence-coefficient model, whose FE body
// carries the fillets of the modelled teeth (docs/ltca.md "Root stress"). Internal to stiffness/.
#pragma once

#include "fem/parameters.h"
#include "kinematics/gear_pair.h"

#include <boost/serialization/vector.hpp>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <utility>
#include <vector>

namespace gearstiff::stiffness
{
// The fillet faces (cell, face number) of a mesh of the pair's scene (geometry/scene_gear_pair.h:
// pinion axis at the origin, the wheel's on the x axis): the free surface between the root and the
// form circle of each body, not the faces on the root circle itself (the rim between removed
// teeth of a full-rim scene).
template <int dim>
std::vector<std::pair<typename dealii::DoFHandler<dim>::active_cell_iterator, unsigned int>>
fillet_faces(const dealii::DoFHandler<dim>& dof_handler, const kinematics::GearPairGeometry& pair);

// The fillet stress as a linear function of a displacement field known only at some DoFs
// (`dofs`): at each quadrature point of the fillet faces (Gauss, degree + 1 points a direction)
// the terms ∂u_c/∂x_d = Σ u[row]·gradient[d] over the point's cell DoFs.
struct FilletStressPoints
{
  unsigned int dim = 2;
  std::vector<dealii::types::global_dof_index> dofs; // the rows, each once
  std::vector<unsigned int> point_start;             // terms of point q: [start[q], start[q+1])
  std::vector<unsigned int> term_row;                // index into `dofs`
  std::vector<unsigned int> term_component;          // c
  std::vector<double> term_gradient;                 // 1/m, dim a term: ∂φ/∂x_d
  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    archive& dim& dofs& point_start& term_row& term_component& term_gradient;
  }
};

// The points of `faces` of the FE field of `dof_handler` (vector-valued, dim components).
template <int dim>
FilletStressPoints fillet_stress_points(
    const dealii::Mapping<dim>& mapping, const dealii::DoFHandler<dim>& dof_handler,
    const std::vector<
        std::pair<typename dealii::DoFHandler<dim>::active_cell_iterator, unsigned int>>& faces);

// Pa, the largest first principal stress over the points under the displacements `values` (m,
// one per row of `points`), of `material` (2D: the in-plane stress of `model`, as the VTU
// output); 0 without points.
double largest_fillet_stress(const FilletStressPoints& points, const std::vector<double>& values,
                             const fem::Material& material, fem::PlanarModel model);
} // namespace gearstiff::stiffness
