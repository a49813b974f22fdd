// Supports of an elastic system expressed as AffineConstraints: fixed or prescribed displacement
// of a boundary, and a rigid hub coupling a boundary (a bore) to its axis, driven by a prescribed
// rotation or by a torque with the rotation solved for. Reactions come from the residual
// r = K u − f (ElasticSystem::residual), so they balance the applied loads to solver precision.
//
// The rotation axis is the z direction through `axis` (in 2D the plane's normal); in 3D the hub
// also holds the bore axially. A DoF already constrained (by an earlier support) keeps its first
// constraint.
#pragma once

#include "fem/elastic_system.h"

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>
#include <string>
#include <vector>

namespace gearstiff::fem
{
// Resultant of nodal forces: force (N) and moment about the z axis through a point (N·m).
template <int dim>
struct Reaction
{
  dealii::Tensor<1, dim> force; // N
  double torque = 0.;           // N·m, about +z through the reference point
};

// Sum of the residual (the forces the supports exert) over the nodes.
template <int dim>
Reaction<dim> reaction(const std::vector<Node<dim>>& nodes, const dealii::Vector<double>& residual,
                       const dealii::Point<dim>& about);

// Every DoF of the boundary's nodes gets u = displacement (m); a fixed support is displacement 0.
// `components` selects the constrained components (default all).
template <int dim>
void add_prescribed_displacement(const std::vector<Node<dim>>& nodes,
                                 const dealii::Tensor<1, dim>& displacement,
                                 dealii::AffineConstraints<double>& constraints,
                                 const std::vector<bool>& components = {});

template <int dim>
class RigidHub
{
public:
  enum class Control
  {
    rotation, // the rotation is prescribed
    torque    // a torque is applied, the rotation is an unknown
  };

  // Throws InputError(parameter) when the boundary has no nodes or all of them lie on the axis.
  RigidHub(const ElasticSystem<dim>& system, dealii::types::boundary_id boundary,
           const dealii::Point<dim>& axis, Control control, double value,
           const std::string& parameter);

  // rotation control: u_i = θ·w_i at every hub DoF (w_i the DoF's lever about the axis);
  // torque control: one DoF (the longest lever) stays free and carries θ, the others follow it.
  // `load_factor` scales a prescribed rotation (load stepping).
  void add_constraints(dealii::AffineConstraints<double>& constraints,
                       double load_factor = 1.) const;
  // Torque control: T enters as the work-conjugate force T/w_m on the free DoF.
  void add_loads(dealii::Vector<double>& point_loads, double load_factor = 1.) const;

  double rotation(const dealii::Vector<double>& solution) const;        // rad, about +z
  Reaction<dim> reaction(const dealii::Vector<double>& residual) const; // about the axis
  const std::vector<Node<dim>>& nodes() const { return hub_nodes; }
  const dealii::Point<dim>& axis() const { return axis_point; }
  Control control() const { return control_type; }
  double value() const { return control_value; } // rad or N·m

private:
  double lever(const Node<dim>& node, unsigned int component) const;

  std::vector<Node<dim>> hub_nodes;
  dealii::Point<dim> axis_point; // m
  Control control_type;
  double control_value;                       // rad or N·m
  dealii::types::global_dof_index master_dof; // torque control: the free DoF
  double master_lever;                        // m, its lever
};
} // namespace gearstiff::fem
