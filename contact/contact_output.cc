// Results of ContactProblem: per-pair contact profiles, support reactions, VTU output.
#include "contact/contact_problem_internal.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace gearstiff::contact
{
using namespace dealii;

namespace
{
// The centre of the nodes and their principal direction (largest spread; its largest component
// positive): the coordinate of a pair's profiles.
template <int dim, typename Nodes>
std::pair<Point<dim>, Tensor<1, dim>> principal_axis(const Nodes& nodes)
{
  Point<dim> centre;
  for (const auto& node : nodes)
    centre += node.node.position / static_cast<double>(nodes.size());
  Eigen::Matrix<double, dim, dim> covariance = Eigen::Matrix<double, dim, dim>::Zero();
  for (const auto& node : nodes)
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        covariance(i, j) +=
            (node.node.position[i] - centre[i]) * (node.node.position[j] - centre[j]);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, dim, dim>> eigen(covariance);
  Tensor<1, dim> axis;
  for (unsigned int i = 0; i < dim; ++i)
    axis[i] = eigen.eigenvectors()(i, dim - 1);
  unsigned int largest = 0;
  for (unsigned int i = 1; i < dim; ++i)
    if (std::abs(axis[i]) > std::abs(axis[largest]))
      largest = i;
  if (axis[largest] < 0)
    axis = -axis;
  return {centre, axis};
}
} // namespace

template <int dim>
void ContactProblem<dim>::collect_results(const Vector<double>& residual)
{
  residual_forces = residual;
  result.pairs.clear();
  for (const auto& pair : pairs)
    result.pairs.push_back(pair_result(pair, residual));
  result.supports.clear();
  for (const auto& support : supports)
  {
    SupportResult<dim> out;
    out.name = support.name;
    out.is_hub = support.is_hub;
    out.axis = support.axis;
    const fem::Reaction<dim> reaction = fem::reaction(support.nodes, residual, support.axis);
    out.force = reaction.force;
    out.torque = reaction.torque;
    if (support.hub)
      out.rotation = support.hub->rotation(displacement);
    result.supports.push_back(out);
  }
}

template <int dim>
PairResult<dim> ContactProblem<dim>::pair_result(const Pair& pair,
                                                 const Vector<double>& residual) const
{
  PairResult<dim> out;
  out.name = pair.name;
  // Coordinate along the principal direction of the slave nodes, for profiles.
  const auto [centre, axis] = principal_axis<dim>(pair.nodes);
  double low = std::numeric_limits<double>::max(), high = -low;
  Tensor<1, dim> tangential_sum;
  for (unsigned int k = 0; k < pair.nodes.size(); ++k)
  {
    const SlaveNode<dim>& node = pair.nodes[k];
    SurfacePoint<dim> point;
    point.position = node.node.position;
    point.coordinate = (node.node.position - centre) * axis;
    const Tensor<1, dim> force = nodal_force(node, residual); // N, on the slave
    const double normal_force = -(force * node.normal);
    const Tensor<1, dim> tangential_force = force + normal_force * node.normal;
    point.state = pair.memory[k].state;
    point.area = node.area;
    point.normal = node.normal;
    const Tensor<1, dim> relative = relative_displacement(node, displacement);
    point.initial_gap = node.initial_gap;
    point.gap = point.state == NodeState::open ? node.initial_gap - relative * node.normal : 0.;
    point.slip = relative - (relative * node.normal) * node.normal;
    if (point.state != NodeState::open)
    {
      point.pressure = normal_force / node.area;
      point.shear = tangential_force / node.area;
      ++out.n_closed;
      out.n_stick += point.state == NodeState::stick;
      out.n_slip += point.state == NodeState::slip;
      low = std::min(low, point.coordinate);
      high = std::max(high, point.coordinate);
    }
    out.force_on_slave += force;
    out.normal_force += normal_force;
    tangential_sum += tangential_force;
    out.max_pressure = std::max(out.max_pressure, point.pressure);
    out.points.push_back(point);
  }
  out.tangential_force = tangential_sum.norm();
  out.contact_length = out.n_closed > 0 ? high - low : 0.;
  std::sort(out.points.begin(), out.points.end(),
            [](const auto& a, const auto& b) { return a.coordinate < b.coordinate; });
  return out;
}

template <int dim>
std::vector<std::string> ContactProblem<dim>::output_results(const std::string& directory,
                                                             const std::string& base) const
{
  std::vector<fem::NodalField> fields{
      {"contact_pressure", {}}, {"contact_gap", {}}, {"contact_slip", {}}, {"contact_state", {}}};
  for (const auto& pair : pairs)
    for (unsigned int k = 0; k < pair.nodes.size(); ++k)
    {
      const SlaveNode<dim>& node = pair.nodes[k];
      const types::global_dof_index key = node.node.dofs[0];
      const Tensor<1, dim> relative = relative_displacement(node, displacement);
      const bool closed = pair.memory[k].state != NodeState::open;
      const Tensor<1, dim> force = nodal_force(node, residual_forces); // N, on the slave
      fields[0].values[key] = closed ? -(force * node.normal) / node.area : 0.;
      fields[1].values[key] = closed ? 0. : node.initial_gap - relative * node.normal;
      fields[2].values[key] = (relative - (relative * node.normal) * node.normal).norm();
      fields[3].values[key] = static_cast<double>(pair.memory[k].state);
    }
  return elastic.write_vtu(displacement, fields, directory, base);
}

template class ContactProblem<2>;
template class ContactProblem<3>;
} // namespace gearstiff::contact
