#include "fem/supports.h"

#include "errors/errors.h"

#include <cmath>

namespace gearstiff::fem
{
using namespace dealii;

namespace
{
// Displacement of a unit rigid rotation about +z through `axis` at `position`, component c:
// ω × (x − x_axis) = (−(y − y_a), x − x_a, 0).
template <int dim>
double rotation_lever(const Point<dim>& position, const Point<dim>& axis, unsigned int c)
{
  if (c == 0)
    return -(position[1] - axis[1]);
  if (c == 1)
    return position[0] - axis[0];
  return 0.;
}
} // namespace

template <int dim>
Reaction<dim> reaction(const std::vector<Node<dim>>& nodes, const Vector<double>& residual,
                       const Point<dim>& about)
{
  Reaction<dim> result;
  for (const auto& node : nodes)
    for (unsigned int c = 0; c < dim; ++c)
    {
      result.force[c] += residual[node.dofs[c]];
      result.torque += rotation_lever(node.position, about, c) * residual[node.dofs[c]];
    }
  return result;
}

template <int dim>
void add_prescribed_displacement(const std::vector<Node<dim>>& nodes,
                                 const Tensor<1, dim>& displacement,
                                 AffineConstraints<double>& constraints,
                                 const std::vector<bool>& components)
{
  for (const auto& node : nodes)
    for (unsigned int c = 0; c < dim; ++c)
      if ((components.empty() || components[c]) && !constraints.is_constrained(node.dofs[c]))
      {
        constraints.add_line(node.dofs[c]);
        constraints.set_inhomogeneity(node.dofs[c], displacement[c]);
      }
}

template <int dim>
RigidHub<dim>::RigidHub(const ElasticSystem<dim>& system, types::boundary_id boundary,
                        const Point<dim>& axis, Control control, double value,
                        const std::string& parameter)
    : hub_nodes(boundary_nodes(system.get_dof_handler(), {boundary})), axis_point(axis),
      control_type(control), control_value(value), master_dof(numbers::invalid_dof_index),
      master_lever(0.)
{
  if (hub_nodes.empty())
    throw InputError(parameter, "boundary id " + std::to_string(boundary) +
                                    " has no nodes: no bore to couple the hub to");
  for (const auto& node : hub_nodes)
    for (unsigned int c = 0; c < dim; ++c)
      if (std::abs(lever(node, c)) > std::abs(master_lever))
      {
        master_lever = lever(node, c);
        master_dof = node.dofs[c];
      }
  if (master_lever == 0.)
    throw InputError(parameter, "all hub nodes lie on the rotation axis");
}

template <int dim>
double RigidHub<dim>::lever(const Node<dim>& node, unsigned int component) const
{
  return rotation_lever(node.position, axis_point, component);
}

template <int dim>
void RigidHub<dim>::add_constraints(AffineConstraints<double>& constraints,
                                    double load_factor) const
{
  for (const auto& node : hub_nodes)
    for (unsigned int c = 0; c < dim; ++c)
    {
      const types::global_dof_index dof = node.dofs[c];
      if (constraints.is_constrained(dof) || (control_type == Control::torque && dof == master_dof))
        continue;
      constraints.add_line(dof);
      if (control_type == Control::rotation)
        constraints.set_inhomogeneity(dof, load_factor * control_value * lever(node, c));
      else if (lever(node, c) != 0.)
        constraints.add_entry(dof, master_dof, lever(node, c) / master_lever);
    }
}

template <int dim>
void RigidHub<dim>::add_loads(Vector<double>& point_loads, double load_factor) const
{
  if (control_type == Control::torque)
    point_loads[master_dof] += load_factor * control_value / master_lever;
}

template <int dim>
double RigidHub<dim>::rotation(const Vector<double>& solution) const
{
  // Least-squares fit of a rigid rotation; exact for the constrained hub.
  double numerator = 0., denominator = 0.;
  for (const auto& node : hub_nodes)
    for (unsigned int c = 0; c < dim; ++c)
    {
      numerator += lever(node, c) * solution[node.dofs[c]];
      denominator += lever(node, c) * lever(node, c);
    }
  return numerator / denominator;
}

template <int dim>
Reaction<dim> RigidHub<dim>::reaction(const Vector<double>& residual) const
{
  return fem::reaction(hub_nodes, residual, axis_point);
}

template struct Reaction<2>;
template struct Reaction<3>;
template Reaction<2> reaction(const std::vector<Node<2>>&, const Vector<double>&, const Point<2>&);
template Reaction<3> reaction(const std::vector<Node<3>>&, const Vector<double>&, const Point<3>&);
template void add_prescribed_displacement(const std::vector<Node<2>>&, const Tensor<1, 2>&,
                                          AffineConstraints<double>&, const std::vector<bool>&);
template void add_prescribed_displacement(const std::vector<Node<3>>&, const Tensor<1, 3>&,
                                          AffineConstraints<double>&, const std::vector<bool>&);
template class RigidHub<2>;
template class RigidHub<3>;
} // namespace gearstiff::fem
