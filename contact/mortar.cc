#include "contact/mortar.h"

#include "contact/mortar_faces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/full_matrix.h>
#include <limits>
#include <map>
#include <set>

namespace gearstiff::contact
{
using namespace dealii;
using namespace mortar_internal;

namespace
{
// Reference points and weights on [0,1]^(dim−1) of a slave face: in 2D Gauss rules on the
// pieces between the projections of the master vertices (so that every integrand is a
// polynomial on each piece), in 3D an iterated Gauss rule.
template <int dim>
Quadrature<dim - 1>
slave_face_quadrature(const SurfaceFace<dim>& slave, const std::vector<SurfaceFace<dim>>& masters,
                      const std::vector<unsigned int>& candidates, unsigned int degree)
{
  const QGauss<1> gauss(degree + 2);
  if constexpr (dim == 2)
  {
    std::vector<double> breaks{0., 1.};
    const Tensor<1, 2> t = slave.vertices[1] - slave.vertices[0];
    for (const unsigned int m : candidates)
      for (const auto& v : masters[m].vertices)
      {
        const double s = (v - slave.vertices[0]) * t / (t * t);
        if (s > 1e-10 && s < 1. - 1e-10)
          breaks.push_back(s);
      }
    std::sort(breaks.begin(), breaks.end());
    std::vector<Point<1>> points;
    std::vector<double> weights;
    for (unsigned int k = 0; k + 1 < breaks.size(); ++k)
    {
      const double length = breaks[k + 1] - breaks[k];
      if (length < 1e-12)
        continue;
      for (unsigned int q = 0; q < gauss.size(); ++q)
      {
        points.emplace_back(breaks[k] + length * gauss.point(q)[0]);
        weights.push_back(length * gauss.weight(q));
      }
    }
    return Quadrature<1>(points, weights);
  }
  else
  {
    (void)masters;
    (void)candidates;
    return QIterated<dim - 1>(gauss, 4);
  }
}

struct NodeAccumulator
{
  double full_weight = 0.;                           // ∫ N_s over all its faces
  double paired_weight = 0.;                         // ∫ Φ_s over the paired part
  std::vector<double> offset;                        // ∫ Φ_s (x̄ − x)
  std::vector<double> normal;                        // ∫ N_s n
  std::map<types::global_dof_index, double> masters; // ∫ Φ_s N_m
};

// Base-element indices of the nodes on a face.
template <int dim>
std::vector<unsigned int> face_node_indices(const FiniteElement<dim>& base, unsigned int face_no)
{
  std::vector<unsigned int> indices;
  for (unsigned int i = 0; i < base.n_dofs_per_cell(); ++i)
    if (base.has_support_on_face(i, face_no))
      indices.push_back(i);
  return indices;
}

// A slave face at its quadrature points: the shape values of its nodes, the surface measure,
// normal and position, and the dual basis coefficients (Φ_i = Σ_j dual(i,j) N_j).
template <int dim>
struct SlaveFaceValues
{
  std::vector<unsigned int> node_indices; // base-element indices of the face's nodes
  std::vector<std::vector<double>> shape;
  std::vector<double> JxW;
  std::vector<Tensor<1, dim>> normals;
  std::vector<Point<dim>> positions;  // m
  std::vector<double> shape_integral; // ∫ N_i
  FullMatrix<double> dual;

  SlaveFaceValues(const SurfaceFace<dim>& slave, const FiniteElement<dim>& base,
                  const Quadrature<dim - 1>& quadrature)
  {
    node_indices = face_node_indices(base, slave.face_no);
    const unsigned int n = node_indices.size();
    shape.assign(quadrature.size(), std::vector<double>(n));
    JxW.resize(quadrature.size());
    normals.resize(quadrature.size());
    positions.resize(quadrature.size());
    shape_integral.assign(n, 0.);
    FullMatrix<double> mass(n, n);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
    {
      const auto [measure, normal] = face_measure(slave, quadrature.point(q));
      JxW[q] = measure * quadrature.weight(q);
      normals[q] = normal;
      positions[q] = interpolate<dim>(slave.vertices, quadrature.point(q));
      const Point<dim> unit = interpolate<dim>(slave.unit_vertices, quadrature.point(q));
      for (unsigned int i = 0; i < n; ++i)
        shape[q][i] = base.shape_value(node_indices[i], unit);
      for (unsigned int i = 0; i < n; ++i)
      {
        shape_integral[i] += shape[q][i] * JxW[q];
        for (unsigned int j = 0; j < n; ++j)
          mass(i, j) += shape[q][i] * shape[q][j] * JxW[q];
      }
    }
    // Dual basis Φ_i = Σ_j A_ij N_j with A = D M⁻¹ (biorthogonality ∫Φ_i N_j = δ_ij ∫N_i).
    FullMatrix<double> inverse(n, n);
    inverse.invert(mass);
    dual.reinit(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        dual(i, j) = shape_integral[i] * inverse(i, j);
  }

  // Φ_i at quadrature point q.
  std::vector<double> dual_values(unsigned int q) const
  {
    std::vector<double> phi(node_indices.size(), 0.);
    for (unsigned int i = 0; i < phi.size(); ++i)
      for (unsigned int j = 0; j < phi.size(); ++j)
        phi[i] += dual(i, j) * shape[q][j];
    return phi;
  }
};

// The nodes of a face (base-element indices `indices`), with their positions.
template <int dim>
std::vector<fem::Node<dim>> face_nodes(const SurfaceFace<dim>& face,
                                       const std::vector<unsigned int>& indices,
                                       const Mapping<dim>& mapping)
{
  const FiniteElement<dim>& fe = face.cell->get_fe();
  const FiniteElement<dim>& base = fe.base_element(0);
  std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
  face.cell->get_dof_indices(dofs);
  std::vector<fem::Node<dim>> nodes;
  for (const unsigned int k : indices)
  {
    fem::Node<dim> node;
    for (unsigned int c = 0; c < dim; ++c)
      node.dofs[c] = dofs[fe.component_to_system_index(c, k)];
    node.position =
        mapping.transform_unit_to_real_cell(face.cell, base.get_unit_support_points()[k]);
    nodes.push_back(node);
  }
  return nodes;
}

// What the mortar integrals accumulate, per slave node, over every slave face.
template <int dim>
struct MortarIntegrals
{
  explicit MortarIntegrals(const std::vector<SurfaceFace<dim>>& masters)
      : masters(masters), master_nodes(masters.size())
  {
  }

  const MappingQ<dim> mapping{1};
  const std::vector<SurfaceFace<dim>>& masters;
  std::map<types::global_dof_index, NodeAccumulator> accumulators; // by the node's x DoF
  std::map<types::global_dof_index, fem::Node<dim>> nodes;         // slave and master nodes
  // Per master face, once paired: its base-element node indices and nodes.
  std::vector<std::pair<std::vector<unsigned int>, std::vector<fem::Node<dim>>>> master_nodes;

  // The accumulator of a slave node (created empty).
  NodeAccumulator& node(const fem::Node<dim>& node)
  {
    nodes.emplace(node.dofs[0], node);
    NodeAccumulator& acc = accumulators[node.dofs[0]];
    acc.offset.resize(dim, 0.);
    acc.normal.resize(dim, 0.);
    return acc;
  }

  // One slave quadrature point paired with the master point x̄ on master face `m`: D, the
  // offset and M_sm of every slave node of the face. `position` and `master_exact` are the points
  // the two meshed surfaces stand for (the mesh's own without a SurfaceGeometry); `master_point`
  // locates x̄ on the meshed master face.
  void add_pairing(const std::vector<fem::Node<dim>>& slave_nodes, const std::vector<double>& phi,
                   double JxW, const Point<dim>& position, unsigned int m,
                   const Point<dim>& master_point, const Point<dim>& master_exact)
  {
    const SurfaceFace<dim>& master = masters[m];
    const FiniteElement<dim>& base = master.cell->get_fe().base_element(0);
    const Point<dim> unit = mapping.transform_real_to_unit_cell(master.cell, master_point);
    for (unsigned int i = 0; i < slave_nodes.size(); ++i)
    {
      NodeAccumulator& acc = accumulators[slave_nodes[i].dofs[0]];
      acc.paired_weight += phi[i] * JxW;
      for (unsigned int c = 0; c < dim; ++c)
        acc.offset[c] += phi[i] * (master_exact[c] - position[c]) * JxW;
    }
    auto& [indices, face] = master_nodes[m];
    if (face.empty())
    {
      indices = face_node_indices(base, master.face_no);
      face = face_nodes(master, indices, mapping);
      for (const auto& node : face)
        nodes.emplace(node.dofs[0], node);
    }
    for (unsigned int k = 0; k < face.size(); ++k)
    {
      const double value = base.shape_value(indices[k], unit);
      for (unsigned int i = 0; i < slave_nodes.size(); ++i)
        accumulators[slave_nodes[i].dofs[0]].masters[face[k].dofs[0]] += phi[i] * value * JxW;
    }
  }
};

// The slave node's constraint data from its accumulated integrals.
template <int dim>
SlaveNode<dim> make_slave_node(const fem::Node<dim>& node, const NodeAccumulator& acc,
                               const std::map<types::global_dof_index, fem::Node<dim>>& nodes,
                               double depth)
{
  SlaveNode<dim> slave;
  slave.node = node;
  for (unsigned int c = 0; c < dim; ++c)
  {
    slave.normal[c] = acc.normal[c];
    slave.initial_offset[c] = acc.offset[c] / acc.paired_weight;
  }
  slave.normal /= slave.normal.norm();
  if constexpr (dim == 2)
    slave.tangents = {Tensor<1, 2>({-slave.normal[1], slave.normal[0]})};
  else
  {
    unsigned int least = 0;
    for (unsigned int c = 1; c < 3; ++c)
      if (std::abs(slave.normal[c]) < std::abs(slave.normal[least]))
        least = c;
    Tensor<1, 3> axis;
    axis[least] = 1.;
    Tensor<1, 3> t1 = cross_product_3d(axis, slave.normal);
    t1 /= t1.norm();
    slave.tangents = {t1, cross_product_3d(slave.normal, t1)};
  }
  slave.area = acc.paired_weight * depth;
  slave.initial_gap = slave.normal * slave.initial_offset;
  for (const auto& [master_dof, weight] : acc.masters)
    if (weight != 0.)
      slave.masters.push_back({nodes.at(master_dof), weight / acc.paired_weight});
  return slave;
}
} // namespace

template <int dim>
std::vector<SlaveNode<dim>> mortar_coupling(const DoFHandler<dim>& dof_handler,
                                            const std::vector<types::boundary_id>& slave_ids,
                                            const std::vector<types::boundary_id>& master_ids,
                                            double search_distance, double depth,
                                            const PairingWindow<dim>& window,
                                            const SurfaceGeometry<dim>& geometry)
{
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  std::vector<SurfaceFace<dim>> slaves = collect_faces(dof_handler, slave_ids);
  std::vector<SurfaceFace<dim>> masters = collect_faces(dof_handler, master_ids);
  const std::vector<bool> touches_outside =
      window.radius > 0. ? restrict_to_window(window, search_distance, slaves, masters)
                         : std::vector<bool>(slaves.size(), false);
  const MasterSearch<dim> search(masters, search_distance);

  // A face-boundary part used by one master face only is an end (2D) or rim (3D) of the
  // master surface: a projection clamped there falls beyond the surface.
  std::map<std::vector<unsigned int>, unsigned int> part_count;
  for (const auto& m : masters)
    for (const auto& part : face_boundary_parts(m))
      ++part_count[part];

  MortarIntegrals<dim> integrals(masters);
  std::set<types::global_dof_index> uncoupled; // window: nodes with a face outside (x DoF)
  for (unsigned int s = 0; s < slaves.size(); ++s)
  {
    const SurfaceFace<dim>& slave = slaves[s];
    if (touches_outside[s])
    {
      for (const auto& node : face_nodes(
               slave, face_node_indices(fe.base_element(0), slave.face_no), integrals.mapping))
        uncoupled.insert(node.dofs[0]);
      continue;
    }
    const std::vector<unsigned int> candidates = search.candidates(slave);
    const SlaveFaceValues<dim> values(slave, fe.base_element(0),
                                      slave_face_quadrature(slave, masters, candidates, fe.degree));
    const std::vector<fem::Node<dim>> nodes =
        face_nodes(slave, values.node_indices, integrals.mapping);
    for (unsigned int i = 0; i < nodes.size(); ++i)
      integrals.node(nodes[i]).full_weight += values.shape_integral[i];

    for (unsigned int q = 0; q < values.JxW.size(); ++q)
    {
      for (unsigned int i = 0; i < nodes.size(); ++i)
        for (unsigned int c = 0; c < dim; ++c)
          integrals.accumulators[nodes[i].dofs[0]].normal[c] +=
              values.shape[q][i] * values.normals[q][c] * values.JxW[q];
      Point<dim> master_point;
      const Projection best = project(values.positions[q], masters, candidates, part_count,
                                      search_distance, master_point);
      if (!best.found || best.beyond_surface || best.distance > search_distance)
        continue;
      const Point<dim> position =
          geometry ? geometry(values.positions[q], slave.cell->material_id()) : values.positions[q];
      const Point<dim> master_exact =
          geometry ? geometry(master_point, masters[best.face].cell->material_id()) : master_point;
      integrals.add_pairing(nodes, values.dual_values(q), values.JxW[q], position, best.face,
                            master_point, master_exact);
    }
  }

  std::vector<SlaveNode<dim>> result;
  for (const auto& [dof, acc] : integrals.accumulators)
    // A node whose dual support is less than half paired lies at or beyond the end of the
    // master surface; its weights M/D would be ill-conditioned, so it is not coupled. A node
    // of both surfaces (the tip of a crack, whose two faces are the pair) has no gap to close.
    if (acc.paired_weight >= 0.5 * acc.full_weight && uncoupled.count(dof) == 0 &&
        acc.masters.count(dof) == 0)
      result.push_back(make_slave_node(integrals.nodes.at(dof), acc, integrals.nodes, depth));
  return result;
}

template std::vector<SlaveNode<2>> mortar_coupling(const DoFHandler<2>&,
                                                   const std::vector<types::boundary_id>&,
                                                   const std::vector<types::boundary_id>&, double,
                                                   double, const PairingWindow<2>&,
                                                   const SurfaceGeometry<2>&);
template std::vector<SlaveNode<3>> mortar_coupling(const DoFHandler<3>&,
                                                   const std::vector<types::boundary_id>&,
                                                   const std::vector<types::boundary_id>&, double,
                                                   double, const PairingWindow<3>&,
                                                   const SurfaceGeometry<3>&);
} // namespace gearstiff::contact
