#include "contact/mortar.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/base/geometry_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/full_matrix.h>
#include <map>
#include <set>

namespace gearstiff::contact
{
using namespace dealii;

namespace
{
constexpr double clamp_tolerance = 1e-9; // of the face's reference coordinate

// A face of a candidate surface with the geometry of MappingQ1: the (bi)linear interpolation
// of its vertices, listed in the cell's numbering so that unit-cell and real points agree.
template <int dim>
struct SurfaceFace
{
  typename DoFHandler<dim>::active_cell_iterator cell;
  unsigned int face_no;
  std::vector<Point<dim>> vertices;       // real, m
  std::vector<Point<dim>> unit_vertices;  // on the unit cell
  std::vector<unsigned int> vertex_index; // global vertex numbers
  Point<dim> centre;
  double radius;          // m, bounding sphere about centre
  Tensor<1, dim> outward; // approximate outward direction (from the cell centre)
};

// Bilinear (3D) or linear (2D) shape weights of the face vertices at reference point ξ.
template <int dim>
std::vector<double> face_weights(const Point<dim - 1>& xi)
{
  if constexpr (dim == 2)
    return {1. - xi[0], xi[0]};
  else
    return {(1. - xi[0]) * (1. - xi[1]), xi[0] * (1. - xi[1]), (1. - xi[0]) * xi[1], xi[0] * xi[1]};
}

template <int dim>
Point<dim> interpolate(const std::vector<Point<dim>>& points, const Point<dim - 1>& xi)
{
  const std::vector<double> w = face_weights<dim>(xi);
  Point<dim> p;
  for (unsigned int v = 0; v < points.size(); ++v)
    p += w[v] * points[v];
  return p;
}

// Tangent vectors ∂x/∂ξ_k of the face at ξ.
template <int dim>
std::array<Tensor<1, dim>, dim - 1> face_tangents(const std::vector<Point<dim>>& v,
                                                  const Point<dim - 1>& xi)
{
  std::array<Tensor<1, dim>, dim - 1> t;
  if constexpr (dim == 2)
    t[0] = v[1] - v[0];
  else
  {
    t[0] = (1. - xi[1]) * (v[1] - v[0]) + xi[1] * (v[3] - v[2]);
    t[1] = (1. - xi[0]) * (v[2] - v[0]) + xi[0] * (v[3] - v[1]);
  }
  return t;
}

// Surface element |∂x/∂ξ| and the unit normal oriented like `outward`.
template <int dim>
std::pair<double, Tensor<1, dim>> face_measure(const SurfaceFace<dim>& face,
                                               const Point<dim - 1>& xi)
{
  const auto t = face_tangents<dim>(face.vertices, xi);
  Tensor<1, dim> n;
  if constexpr (dim == 2)
    n = Tensor<1, 2>({t[0][1], -t[0][0]});
  else
    n = cross_product_3d(t[0], t[1]);
  const double measure = n.norm();
  n /= measure;
  if (n * face.outward < 0)
    n = -n;
  return {measure, n};
}

template <int dim>
std::vector<SurfaceFace<dim>> collect_faces(const DoFHandler<dim>& dof_handler,
                                            const std::vector<types::boundary_id>& ids)
{
  std::vector<SurfaceFace<dim>> faces;
  for (const auto& cell : dof_handler.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() &&
          std::find(ids.begin(), ids.end(), cell->face(f)->boundary_id()) != ids.end())
      {
        SurfaceFace<dim> face;
        face.cell = cell;
        face.face_no = f;
        for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_face; ++v)
        {
          const unsigned int cv = GeometryInfo<dim>::face_to_cell_vertices(f, v);
          face.vertices.push_back(cell->vertex(cv));
          face.unit_vertices.push_back(GeometryInfo<dim>::unit_cell_vertex(cv));
          face.vertex_index.push_back(cell->vertex_index(cv));
        }
        for (const auto& p : face.vertices)
          face.centre += p / static_cast<double>(face.vertices.size());
        face.radius = 0;
        for (const auto& p : face.vertices)
          face.radius = std::max(face.radius, face.centre.distance(p));
        face.outward = face.centre - cell->center();
        faces.push_back(face);
      }
  return faces;
}

// The parts of a face's boundary (vertices in 2D, edges in 3D) touched by a clamped
// projection, as sorted global vertex lists.
template <int dim>
std::vector<std::vector<unsigned int>> face_boundary_parts(const SurfaceFace<dim>& face)
{
  const auto& id = face.vertex_index;
  auto sorted = [](std::vector<unsigned int> v)
  {
    std::sort(v.begin(), v.end());
    return v;
  };
  if constexpr (dim == 2)
    return {{id[0]}, {id[1]}};
  else // ξ0 = 0, ξ0 = 1, ξ1 = 0, ξ1 = 1
    return {sorted({id[0], id[2]}), sorted({id[1], id[3]}), sorted({id[0], id[1]}),
            sorted({id[2], id[3]})};
}

struct Projection
{
  bool found = false;
  unsigned int face = 0;
  double distance = std::numeric_limits<double>::max();
  bool beyond_surface = false; // clamped onto a free end/edge of the master surface
};

// Closest point of a master face to p: reference point ξ (clamped to the face) and the
// face-boundary parts it was clamped to.
template <int dim>
Point<dim - 1> closest_point(const SurfaceFace<dim>& face, const Point<dim>& p,
                             std::vector<unsigned int>& clamped_parts)
{
  Point<dim - 1> xi;
  for (unsigned int k = 0; k < dim - 1; ++k)
    xi[k] = 0.5;
  // Gauss–Newton on |x(ξ) − p|²; exact in one step for straight 2D faces.
  for (unsigned int iteration = 0; iteration < 20; ++iteration)
  {
    const auto t = face_tangents<dim>(face.vertices, xi);
    const Tensor<1, dim> r = interpolate<dim>(face.vertices, xi) - p;
    Point<dim - 1> step;
    if constexpr (dim == 2)
      step[0] = -(r * t[0]) / (t[0] * t[0]);
    else
    {
      const double a = t[0] * t[0], b = t[0] * t[1], c = t[1] * t[1];
      const double g0 = r * t[0], g1 = r * t[1], det = a * c - b * b;
      step[0] = -(c * g0 - b * g1) / det;
      step[1] = -(a * g1 - b * g0) / det;
    }
    double change = 0;
    for (unsigned int k = 0; k < dim - 1; ++k)
    {
      const double next = std::clamp(xi[k] + step[k], -1., 2.);
      change = std::max(change, std::abs(next - xi[k]));
      xi[k] = next;
    }
    if (change < 1e-13)
      break;
  }
  clamped_parts.clear();
  for (unsigned int k = 0; k < dim - 1; ++k)
  {
    if (xi[k] < -clamp_tolerance)
      clamped_parts.push_back(2 * k);
    if (xi[k] > 1. + clamp_tolerance)
      clamped_parts.push_back(2 * k + 1);
    xi[k] = std::clamp(xi[k], 0., 1.);
  }
  return xi;
}

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
} // namespace

template <int dim>
std::vector<SlaveNode<dim>> mortar_coupling(const DoFHandler<dim>& dof_handler,
                                            const std::vector<types::boundary_id>& slave_ids,
                                            const std::vector<types::boundary_id>& master_ids,
                                            double search_distance, double depth)
{
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  const FiniteElement<dim>& base = fe.base_element(0);
  const MappingQ<dim> mapping(1);
  const std::vector<SurfaceFace<dim>> slaves = collect_faces(dof_handler, slave_ids);
  const std::vector<SurfaceFace<dim>> masters = collect_faces(dof_handler, master_ids);

  // A face-boundary part used by one master face only is an end (2D) or rim (3D) of the
  // master surface: a projection clamped there falls beyond the surface.
  std::map<std::vector<unsigned int>, unsigned int> part_count;
  for (const auto& m : masters)
    for (const auto& part : face_boundary_parts(m))
      ++part_count[part];

  std::map<types::global_dof_index, NodeAccumulator> accumulators;
  std::map<types::global_dof_index, fem::Node<dim>> nodes;
  std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
  std::vector<unsigned int> clamped;

  for (const auto& slave : slaves)
  {
    std::vector<unsigned int> candidates;
    for (unsigned int m = 0; m < masters.size(); ++m)
      if (slave.centre.distance(masters[m].centre) <=
          slave.radius + masters[m].radius + search_distance)
        candidates.push_back(m);

    const Quadrature<dim - 1> quadrature =
        slave_face_quadrature(slave, masters, candidates, fe.degree);
    slave.cell->get_dof_indices(dofs);
    std::vector<unsigned int> face_nodes; // base-element indices
    for (unsigned int i = 0; i < base.n_dofs_per_cell(); ++i)
      if (base.has_support_on_face(i, slave.face_no))
        face_nodes.push_back(i);
    const unsigned int n = face_nodes.size();

    // Slave shape values at the quadrature points, the face mass matrix and D.
    std::vector<std::vector<double>> shape(quadrature.size(), std::vector<double>(n));
    std::vector<double> JxW(quadrature.size());
    std::vector<Tensor<1, dim>> normals(quadrature.size());
    std::vector<Point<dim>> positions(quadrature.size());
    FullMatrix<double> mass(n, n), dual(n, n);
    std::vector<double> shape_integral(n, 0.);
    for (unsigned int q = 0; q < quadrature.size(); ++q)
    {
      const auto [measure, normal] = face_measure(slave, quadrature.point(q));
      JxW[q] = measure * quadrature.weight(q);
      normals[q] = normal;
      positions[q] = interpolate<dim>(slave.vertices, quadrature.point(q));
      const Point<dim> unit = interpolate<dim>(slave.unit_vertices, quadrature.point(q));
      for (unsigned int i = 0; i < n; ++i)
        shape[q][i] = base.shape_value(face_nodes[i], unit);
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
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        dual(i, j) = shape_integral[i] * inverse(i, j);

    std::vector<types::global_dof_index> face_node_dof(n);
    for (unsigned int i = 0; i < n; ++i)
    {
      fem::Node<dim> node;
      for (unsigned int c = 0; c < dim; ++c)
        node.dofs[c] = dofs[fe.component_to_system_index(c, face_nodes[i])];
      node.position = mapping.transform_unit_to_real_cell(
          slave.cell, base.get_unit_support_points()[face_nodes[i]]);
      face_node_dof[i] = node.dofs[0];
      nodes.emplace(node.dofs[0], node);
      auto& acc = accumulators[node.dofs[0]];
      acc.offset.resize(dim, 0.);
      acc.normal.resize(dim, 0.);
      acc.full_weight += shape_integral[i];
    }

    std::vector<types::global_dof_index> master_dofs(fe.n_dofs_per_cell());
    for (unsigned int q = 0; q < quadrature.size(); ++q)
    {
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int c = 0; c < dim; ++c)
          accumulators[face_node_dof[i]].normal[c] += shape[q][i] * normals[q][c] * JxW[q];

      Projection best;
      Point<dim> best_point;
      for (const unsigned int m : candidates)
      {
        const Point<dim - 1> xi = closest_point(masters[m], positions[q], clamped);
        const Point<dim> x = interpolate<dim>(masters[m].vertices, xi);
        const double distance = x.distance(positions[q]);
        if (distance < best.distance)
        {
          best.found = true;
          best.face = m;
          best.distance = distance;
          best_point = x;
          best.beyond_surface = false;
          const auto parts = face_boundary_parts(masters[m]);
          for (const unsigned int k : clamped)
            if (part_count[parts[k]] == 1)
              best.beyond_surface = true;
        }
      }
      if (!best.found || best.beyond_surface || best.distance > search_distance)
        continue;

      const SurfaceFace<dim>& master = masters[best.face];
      const Point<dim> unit = mapping.transform_real_to_unit_cell(master.cell, best_point);
      master.cell->get_dof_indices(master_dofs);
      std::vector<double> phi(n, 0.);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          phi[i] += dual(i, j) * shape[q][j];
      for (unsigned int i = 0; i < n; ++i)
      {
        auto& acc = accumulators[face_node_dof[i]];
        acc.paired_weight += phi[i] * JxW[q];
        for (unsigned int c = 0; c < dim; ++c)
          acc.offset[c] += phi[i] * (best_point[c] - positions[q][c]) * JxW[q];
      }
      for (unsigned int k = 0; k < base.n_dofs_per_cell(); ++k)
      {
        if (!base.has_support_on_face(k, master.face_no))
          continue;
        const double value = base.shape_value(k, unit);
        fem::Node<dim> node;
        for (unsigned int c = 0; c < dim; ++c)
          node.dofs[c] = master_dofs[fe.component_to_system_index(c, k)];
        if (nodes.count(node.dofs[0]) == 0)
        {
          node.position =
              mapping.transform_unit_to_real_cell(master.cell, base.get_unit_support_points()[k]);
          nodes.emplace(node.dofs[0], node);
        }
        for (unsigned int i = 0; i < n; ++i)
          accumulators[face_node_dof[i]].masters[node.dofs[0]] += phi[i] * value * JxW[q];
      }
    }
  }

  std::vector<SlaveNode<dim>> result;
  for (const auto& [dof, acc] : accumulators)
  {
    // A node whose dual support is less than half paired lies at or beyond the end of the
    // master surface; its weights M/D would be ill-conditioned, so it is not coupled.
    if (acc.paired_weight < 0.5 * acc.full_weight)
      continue;
    SlaveNode<dim> slave;
    slave.node = nodes.at(dof);
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
    result.push_back(slave);
  }
  return result;
}

template std::vector<SlaveNode<2>> mortar_coupling(const DoFHandler<2>&,
                                                   const std::vector<types::boundary_id>&,
                                                   const std::vector<types::boundary_id>&, double,
                                                   double);
template std::vector<SlaveNode<3>> mortar_coupling(const DoFHandler<3>&,
                                                   const std::vector<types::boundary_id>&,
                                                   const std::vector<types::boundary_id>&, double,
                                                   double);
} // namespace gearstiff::contact
