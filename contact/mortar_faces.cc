#include "contact/mortar_faces.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/geometry_info.h>
#include <set>

namespace gearstiff::contact::mortar_internal
{
using namespace dealii;

namespace
{
constexpr double clamp_tolerance = 1e-9; // of the face's reference coordinate

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
} // namespace

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

template <int dim>
MasterSearch<dim>::MasterSearch(const std::vector<SurfaceFace<dim>>& masters,
                                double search_distance)
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

template <int dim>
std::vector<unsigned int> MasterSearch<dim>::candidates(const SurfaceFace<dim>& slave) const
{
  const double reach = slave.radius + largest_radius + search_distance;
  const auto first =
      std::lower_bound(order.begin(), order.end(), std::make_pair(slave.centre[axis] - reach, 0u));
  std::vector<unsigned int> found;
  for (auto it = first; it != order.end() && it->first <= slave.centre[axis] + reach; ++it)
    if (slave.centre.distance(masters[it->second].centre) <=
        slave.radius + masters[it->second].radius + search_distance)
      found.push_back(it->second);
  std::sort(found.begin(), found.end());
  return found;
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

template std::vector<SurfaceFace<2>> collect_faces(const DoFHandler<2>&,
                                                   const std::vector<types::boundary_id>&);
template std::vector<SurfaceFace<3>> collect_faces(const DoFHandler<3>&,
                                                   const std::vector<types::boundary_id>&);
template std::vector<bool> restrict_to_window(const PairingWindow<2>&, double,
                                              std::vector<SurfaceFace<2>>&,
                                              std::vector<SurfaceFace<2>>&);
template std::vector<bool> restrict_to_window(const PairingWindow<3>&, double,
                                              std::vector<SurfaceFace<3>>&,
                                              std::vector<SurfaceFace<3>>&);
template std::vector<std::vector<unsigned int>> face_boundary_parts(const SurfaceFace<2>&);
template std::vector<std::vector<unsigned int>> face_boundary_parts(const SurfaceFace<3>&);
template class MasterSearch<2>;
template class MasterSearch<3>;
template Projection project(const Point<2>&, const std::vector<SurfaceFace<2>>&,
                            const std::vector<unsigned int>&,
                            const std::map<std::vector<unsigned int>, unsigned int>&, double,
                            Point<2>&);
template Projection project(const Point<3>&, const std::vector<SurfaceFace<3>>&,
                            const std::vector<unsigned int>&,
                            const std::map<std::vector<unsigned int>, unsigned int>&, double,
                            Point<3>&);
} // namespace gearstiff::contact::mortar_internal
