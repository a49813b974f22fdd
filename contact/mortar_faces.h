// Internal to contact/ (mortar.cc and mortar_faces.cc): the contact surfaces as faces with the
// geometry of MappingQ1 — their collection, the restriction to a pairing window, the search of
// the master faces near a slave face and the closest-point projection onto them. mortar.cc
// integrates the dual mortar coupling over them (contact/mortar.h).
#pragma once

#include "contact/pairing_window.h"

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace gearstiff::contact::mortar_internal
{
using dealii::Point;
using dealii::Tensor;

// A face of a candidate surface with the geometry of MappingQ1: the (bi)linear interpolation
// of its vertices, listed in the cell's numbering so that unit-cell and real points agree.
template <int dim>
struct SurfaceFace
{
  typename dealii::DoFHandler<dim>::active_cell_iterator cell;
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
    n = dealii::cross_product_3d(t[0], t[1]);
  const double measure = n.norm();
  n /= measure;
  if (n * face.outward < 0)
    n = -n;
  return {measure, n};
}

template <int dim>
std::vector<SurfaceFace<dim>> collect_faces(const dealii::DoFHandler<dim>& dof_handler,
                                            const std::vector<dealii::types::boundary_id>& ids);

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
                                     std::vector<SurfaceFace<dim>>& masters);

// The parts of a face's boundary (vertices in 2D, edges in 3D) touched by a clamped
// projection, as sorted global vertex lists.
template <int dim>
std::vector<std::vector<unsigned int>> face_boundary_parts(const SurfaceFace<dim>& face);

struct Projection
{
  bool found = false;
  unsigned int face = 0;
  double distance = std::numeric_limits<double>::max();
  bool beyond_surface = false; // clamped onto a free end/edge of the master surface
};

// The master faces near a slave face: the faces are sorted along the coordinate axis in which
// their centres spread most, so a slave face's candidates lie in one window of that order
// (binary search), and only the faces in it are tested by their bounding spheres. Candidates
// come out in the master faces' own order, as a brute-force test would list them.
template <int dim>
class MasterSearch
{
public:
  MasterSearch(const std::vector<SurfaceFace<dim>>& masters, double search_distance);

  std::vector<unsigned int> candidates(const SurfaceFace<dim>& slave) const;

private:
  const std::vector<SurfaceFace<dim>>& masters;
  double search_distance;                             // m
  double largest_radius = 0.;                         // m, of the master faces' bounding spheres
  unsigned int axis = 0;                              // sorting coordinate
  std::vector<std::pair<double, unsigned int>> order; // (centre coordinate, face)
};

// The closest point to p on the candidate master faces; `beyond_surface` when it was clamped to
// an end (2D) or rim (3D) of the master surface, i.e. to a face-boundary part that only one
// master face uses (`part_count`). Not found when every candidate lies farther than `reach`
// (m, the search distance: such a point is not paired either way).
template <int dim>
Projection project(const Point<dim>& p, const std::vector<SurfaceFace<dim>>& masters,
                   const std::vector<unsigned int>& candidates,
                   const std::map<std::vector<unsigned int>, unsigned int>& part_count,
                   double reach, Point<dim>& best_point);
} // namespace gearstiff::contact::mortar_internal
