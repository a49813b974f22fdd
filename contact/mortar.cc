#include "contact/mortar.h"

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
  Point<dim> low, high;   // m, the box of the vertices (it holds the face)
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
        face.low = face.high = face.vertices.front();
        for (const auto& p : face.vertices)
          for (unsigned int c = 0; c < dim; ++c)
          {
            face.low[c] = std::min(face.low[c], p[c]);
            face.high[c] = std::max(face.high[c], p[c]);
          }
        faces.push_back(face);
      }
  return faces;
}

// Restricts the faces to a window (PairingWindow) and returns, per kept slave face, whether it
// shares a vertex with a slave face outside (its nodes are then not coupled: some of their
// dual support lies outside). The order of the faces is kept. The master faces kept are those
// within R + d + 3·r_max of the centre (d the search distance, r_max the largest bounding
// radius of any face): a kept slave face (centre within R) has every candidate master face
// (centres within r_s + r_m + d, MasterSearch) among them, and a vertex a kept master face
// shares with a dropped one lies more than R + d + 2·r_max from the centre, farther than d from
// every point of a kept slave face, so a projection clamped there is never paired, as before.
template <int dim>
std::vector<bool> restrict_to_window(const PairingWindow<dim>& window, double search_distance,
                                     std::vector<SurfaceFace<dim>>& slaves,
                                     std::vector<SurfaceFace<dim>>& masters)
{
  double largest_radius = 0.;
  for (const auto* faces : {&slaves, &masters})
    for (const auto& face : *faces)
      largest_radius = std::max(largest_radius, face.radius);
  const double master_reach = window.radius + search_distance + 3. * largest_radius;
  masters.erase(std::remove_if(masters.begin(), masters.end(),
                               [&](const SurfaceFace<dim>& face)
                               { return window.distance(face.centre) > master_reach; }),
                masters.end());
  const auto outside = [&](const SurfaceFace<dim>& face)
  { return window.distance(face.centre) > window.radius; };
  std::set<unsigned int> outside_vertices;
  for (const auto& face : slaves)
    if (outside(face))
      outside_vertices.insert(face.vertex_index.begin(), face.vertex_index.end());
  slaves.erase(std::remove_if(slaves.begin(), slaves.end(), outside), slaves.end());
  std::vector<bool> touches_outside(slaves.size(), false);
  for (unsigned int k = 0; k < slaves.size(); ++k)
    for (const unsigned int v : slaves[k].vertex_index)
      touches_outside[k] = touches_outside[k] || outside_vertices.count(v) > 0;
  return touches_outside;
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

// The master faces near a slave face: the faces are sorted along the coordinate axis in which
// their centres spread most, so a slave face's candidates lie in one window of that order
// (binary search), and only the faces in it are tested by their bounding spheres. Candidates
// come out in the master faces' own order, as a brute-force test would list them.
template <int dim>
class MasterSearch
{
public:
  MasterSearch(const std::vector<SurfaceFace<dim>>& masters, double search_distance)
      : masters(masters), search_distance(search_distance)
  {
    if (masters.empty())
      return;
    Point<dim> low = masters.front().centre, high = low;
    for (const auto& face : masters)
    {
      largest_radius = std::max(largest_radius, face.radius);
      for (unsigned int c = 0; c < dim; ++c)
      {
        low[c] = std::min(low[c], face.centre[c]);
        high[c] = std::max(high[c], face.centre[c]);
      }
    }
    for (unsigned int c = 1; c < dim; ++c)
      if (high[c] - low[c] > high[axis] - low[axis])
        axis = c;
    for (unsigned int m = 0; m < masters.size(); ++m)
      order.emplace_back(masters[m].centre[axis], m);
    std::sort(order.begin(), order.end());
  }

  std::vector<unsigned int> candidates(const SurfaceFace<dim>& slave) const
  {
    const double reach = slave.radius + largest_radius + search_distance;
    const auto first = std::lower_bound(order.begin(), order.end(),
                                        std::make_pair(slave.centre[axis] - reach, 0u));
    std::vector<unsigned int> found;
    for (auto it = first; it != order.end() && it->first <= slave.centre[axis] + reach; ++it)
      if (slave.centre.distance(masters[it->second].centre) <=
          slave.radius + masters[it->second].radius + search_distance)
        found.push_back(it->second);
    std::sort(found.begin(), found.end());
    return found;
  }

private:
  const std::vector<SurfaceFace<dim>>& masters;
  double search_distance;                             // m
  double largest_radius = 0.;                         // m, of the master faces' bounding spheres
  unsigned int axis = 0;                              // sorting coordinate
  std::vector<std::pair<double, unsigned int>> order; // (centre coordinate, face)
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

// The distance from p to the box of a face's vertices: no point of the face is nearer.
template <int dim>
double box_distance(const SurfaceFace<dim>& face, const Point<dim>& p)
{
  double squared = 0.;
  for (unsigned int c = 0; c < dim; ++c)
  {
    const double outside = std::max({face.low[c] - p[c], p[c] - face.high[c], 0.});
    squared += outside * outside;
  }
  return std::sqrt(squared);
}

// The closest point to p on the candidate master faces; `beyond_surface` when it was clamped to
// an end (2D) or rim (3D) of the master surface, i.e. to a face-boundary part that only one
// master face uses (`part_count`). Not found when every candidate lies farther than `reach`
// (m, the search distance: such a point is not paired either way).
template <int dim>
Projection project(const Point<dim>& p, const std::vector<SurfaceFace<dim>>& masters,
                   const std::vector<unsigned int>& candidates,
                   const std::map<std::vector<unsigned int>, unsigned int>& part_count,
                   double reach, Point<dim>& best_point)
{
  Projection best;
  std::vector<unsigned int> clamped;
  // A face lies within its bounding sphere, so the nearest face is at most
  // min over candidates of |p − c| + r from p (`nearest_bound`); a face whose vertex box lies
  // farther than that, than the best distance so far or than `reach` cannot be taken: skipped
  // unprojected (1e-12 m is far above the rounding of the distances), the same face is found,
  // first of equals in the candidates' order. In 3D the candidates by bounding spheres are many:
  // faces are slivers (a contact size across the profile, a layer along the face width).
  double nearest_bound = reach;
  for (const unsigned int m : candidates)
    nearest_bound = std::min(nearest_bound, p.distance(masters[m].centre) + masters[m].radius);
  for (const unsigned int m : candidates)
  {
    if (box_distance(masters[m], p) > std::min(best.distance, nearest_bound) + 1e-12)
      continue;
    const Point<dim - 1> xi = closest_point(masters[m], p, clamped);
    const Point<dim> x = interpolate<dim>(masters[m].vertices, xi);
    const double distance = x.distance(p);
    if (distance < best.distance)
    {
      best.found = true;
      best.face = m;
      best.distance = distance;
      best_point = x;
      best.beyond_surface = false;
      const auto parts = face_boundary_parts(masters[m]);
      for (const unsigned int k : clamped)
        if (part_count.at(parts[k]) == 1)
          best.beyond_surface = true;
    }
  }
  return best;
}

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
  // offset and M_sm of every slave node of the face.
  void add_pairing(const std::vector<fem::Node<dim>>& slave_nodes, const std::vector<double>& phi,
                   double JxW, const Point<dim>& position, unsigned int m,
                   const Point<dim>& master_point)
  {
    const SurfaceFace<dim>& master = masters[m];
    const FiniteElement<dim>& base = master.cell->get_fe().base_element(0);
    const Point<dim> unit = mapping.transform_real_to_unit_cell(master.cell, master_point);
    for (unsigned int i = 0; i < slave_nodes.size(); ++i)
    {
      NodeAccumulator& acc = accumulators[slave_nodes[i].dofs[0]];
      acc.paired_weight += phi[i] * JxW;
      for (unsigned int c = 0; c < dim; ++c)
        acc.offset[c] += phi[i] * (master_point[c] - position[c]) * JxW;
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
                                            const PairingWindow<dim>& window)
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
      integrals.add_pairing(nodes, values.dual_values(q), values.JxW[q], values.positions[q],
                            best.face, master_point);
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
                                                   double, const PairingWindow<2>&);
template std::vector<SlaveNode<3>> mortar_coupling(const DoFHandler<3>&,
                                                   const std::vector<types::boundary_id>&,
                                                   const std::vector<types::boundary_id>&, double,
                                                   double, const PairingWindow<3>&);
} // namespace gearstiff::contact
