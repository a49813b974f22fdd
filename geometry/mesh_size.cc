// The size field of a planar model (SizeGrading) and the work estimate before meshing.
#include "errors/errors.h"
#include "errors/format.h"
#include "errors/io.h"
#include "errors/limits.h"
#include "geometry/fields.h"
#include "geometry/mesh_internal.h"
#include "geometry/mesh_planar.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <gmsh.h>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>

namespace gearstiff::geometry
{
namespace
{
// -, quadrilaterals per h² of area in gmsh's recombined meshes. With 1 the estimate over actual
// count was (measured, default sizes) gear pair 1.5, cylinders 0.66, cycloid 1.4, 3D gear pair
// 1.5, stiffness scene 3.4 (its rims grow coarser than the body size, which the estimate does
// not credit): within the factor the limit needs.
constexpr double cells_per_square = 1.0;

// Cells of a disc of radius `radius` at size `size` plus the annulus around it where the size
// grows at `rate` up to `coarse`: ∫ dA/h², h = size + rate·s at distance radius + s.
double focus_cells(double size, double radius, double rate, double coarse)
{
  const double disc = M_PI * radius * radius / (size * size);
  const double annulus =
      2. * M_PI / rate *
      ((radius - size / rate) * (1. / size - 1. / coarse) + std::log(coarse / size) / rate);
  return disc + std::max(0., annulus);
}

// -, nodes of a section's boundary beyond one per quadrilateral, over its quadrilaterals, at
// degree 1 (degree p: this over p, the boundary's share of a p² node block). A section of n
// quadrilaterals and B boundary edges has n + B/2 vertices and 2n + B/2 edges (Euler), so
// FE_Q(p) places p²·n + p·B/2 nodes on each of its p·layers + 1 planes. Measured on real meshes
// (count → formula with 0.085): spur Q1 4 and 8 layers 105 885 → 105 904, 190 593 → 190 626;
// spur Q2 1, 2 and 6 layers 244 188 → 244 200, 406 980 → 407 007, 1 058 148 → 1 058 237; helical Q1
// 13 layers 633 024 → 653 697 (+3 %, its rims give fewer boundary nodes a cell).
constexpr double boundary_nodes_per_cell = 0.085;

// -, unknowns of FE_Q(degree) (3 components a node) on `hexahedra` extruded in `layers` layers.
double hexahedron_unknowns(double hexahedra, unsigned int layers, unsigned int degree)
{
  const double p = degree, section = hexahedra / layers;
  return 3. * p * p * section * (p * layers + 1.) * (1. + boundary_nodes_per_cell / p);
}

double solve_bytes_3d(double unknowns, unsigned int degree)
{
  return unknowns * (degree == 1 ? limits::solve_bytes_per_unknown_3d_q1
                                 : limits::solve_bytes_per_unknown_3d_q2);
}
} // namespace

double SizeGrading::size_at(const Eigen::Vector2d& point, const double contact_scale) const
{
  double size = coarse_size ? std::min(coarse_size(point), largest_size) : body_size;
  for (const auto& focus : foci)
    size =
        std::min(size, contact_scale * focus.size +
                           growth_rate * std::max(0., (point - focus.point).norm() - focus.radius));
  return size;
}

double SizeGrading::smallest_size() const
{
  double size = body_size;
  for (const auto& focus : foci)
    size = std::min(size, focus.size);
  return size;
}

namespace
{
// -, the most grid points union_focus_cells samples (beyond it the per-focus sum stands).
constexpr double union_grid_points = 4e6;

// ∫ c/h(x)² dA over the union of the foci's graded discs, h(x) = min over the foci of
// (size + growth·(distance − radius)) up to `coarse`, less the body-size cells c/coarse² the
// union covers: what the foci add when they overlap (a rolling sweep's band along every flank,
// one focus every half fine radius, where the per-focus sum counts each point up to ~30 times).
// Sampled on a grid of a quarter of the smallest fine radius (the density is constant within a
// fine disc, and varies by growth·step/h ≤ 0.5 between points of the graded annulus); returns
// {fine cells, graded cells}, or nothing when a focus has no fine radius or the grid would exceed
// union_grid_points.
std::optional<std::pair<double, double>> union_focus_cells(const SizeGrading& grading,
                                                           double size_scale, double coarse)
{
  double step = std::numeric_limits<double>::max(), reach = 0.;
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector2d high = -low;
  for (const auto& focus : grading.foci)
  {
    step = std::min(step, 0.25 * focus.radius);
    const double size = size_scale * focus.size;
    reach = std::max(reach, focus.radius + std::max(0., coarse - size) / grading.growth_rate);
    low = low.cwiseMin(focus.point);
    high = high.cwiseMax(focus.point);
  }
  if (grading.foci.empty() || !(step > 0.))
    return std::nullopt;
  low.array() -= reach;
  high.array() += reach;
  const double nx = std::ceil((high.x() - low.x()) / step) + 1.,
               ny = std::ceil((high.y() - low.y()) / step) + 1.;
  if (nx * ny > union_grid_points)
    return std::nullopt;
  const auto columns = static_cast<std::size_t>(nx), rows = static_cast<std::size_t>(ny);
  std::vector<double> h(columns * rows, coarse);
  std::vector<char> fine(columns * rows, 0);
  for (const auto& focus : grading.foci)
  {
    const double size = size_scale * focus.size;
    const double r = focus.radius + std::max(0., coarse - size) / grading.growth_rate;
    const auto first = [&](double x, double origin)
    { return static_cast<std::size_t>(std::max(0., std::floor((x - r - origin) / step))); };
    for (std::size_t j = first(focus.point.y(), low.y());
         j < rows && low.y() + j * step <= focus.point.y() + r; ++j)
      for (std::size_t i = first(focus.point.x(), low.x());
           i < columns && low.x() + i * step <= focus.point.x() + r; ++i)
      {
        const double d =
            (Eigen::Vector2d(low.x() + i * step, low.y() + j * step) - focus.point).norm();
        const std::size_t k = j * columns + i;
        h[k] = std::min(h[k], size + grading.growth_rate * std::max(0., d - focus.radius));
        fine[k] |= d <= focus.radius;
      }
  }
  double fine_cells = 0., graded_cells = 0.;
  for (std::size_t k = 0; k < h.size(); ++k)
  {
    const double added =
        cells_per_square * step * step * (1. / (h[k] * h[k]) - 1. / (coarse * coarse));
    (fine[k] ? fine_cells : graded_cells) += added;
  }
  return std::pair{fine_cells, graded_cells};
}
} // namespace

MeshEstimate estimate_mesh(const PlanarModel& model, const SizeGrading& grading,
                           const MeshOptions& options)
{
  MeshEstimate estimate;
  for (const auto& body : model.bodies)
  {
    estimate.area += std::abs(body.outer.signed_area());
    for (const auto& hole : body.holes)
      estimate.area -= std::abs(hole.signed_area());
  }
  estimate.area = std::max(estimate.area, 0.);
  const double coarse = grading.body_size;
  estimate.body_cells = cells_per_square * estimate.area / (coarse * coarse);
  for (const auto& focus : grading.foci)
  {
    const double size = grading.initial_contact_scale * focus.size;
    const double whole = cells_per_square * estimate.area / (size * size);
    const double fine =
        std::min(whole, cells_per_square * M_PI * focus.radius * focus.radius / (size * size));
    const double graded =
        cells_per_square * focus_cells(size, focus.radius, grading.growth_rate, coarse) - fine;
    estimate.fine_cells += fine;
    estimate.graded_cells += std::min(std::max(graded, 0.), whole - fine);
  }
  // Overlapping foci: the union counts each point once (never more than the per-focus sum).
  if (const auto united = union_focus_cells(grading, grading.initial_contact_scale, coarse);
      united && united->first + united->second < estimate.fine_cells + estimate.graded_cells)
  {
    estimate.fine_cells = united->first;
    estimate.graded_cells = united->second;
  }
  estimate.cells = estimate.fine_cells + estimate.graded_cells + estimate.body_cells;
  if (options.dimension == 3)
  {
    estimate.cells *= options.layers;
    estimate.unknowns = hexahedron_unknowns(estimate.cells, options.layers, options.element_degree);
    estimate.solve_bytes = solve_bytes_3d(estimate.unknowns, options.element_degree);
  }
  return estimate;
}

bool over_work_limit(const MeshEstimate& estimate, const MeshOptions& options)
{
  return options.dimension == 3 ? estimate.solve_bytes > options.memory_limit
                                : estimate.cells > limits::max_cells_2d;
}

void check_mesh_estimate(const PlanarModel& model, const SizeGrading& grading,
                         const MeshOptions& options)
{
  const MeshEstimate estimate = estimate_mesh(model, grading, options);
  if (!over_work_limit(estimate, options))
    return;
  const bool solid = options.dimension == 3;
  double fine_radius = 0.;
  for (const auto& focus : grading.foci)
    fine_radius = std::max(fine_radius, focus.radius);
  // 2D: the cells against their limit; 3D: the unknowns and memory of the solve against its.
  const std::string size =
      solid ? "about " + format_number(estimate.cells, 2) + " hexahedra, " +
                  format_number(estimate.unknowns, 2) + " unknowns at element degree " +
                  std::to_string(options.element_degree) + ", about " +
                  format_number(estimate.solve_bytes / 1e9, 2) +
                  " GB for the direct contact solve (limit " +
                  format_number(options.memory_limit / 1e9, 3) +
                  " GB: Mesh/memory limit, raise it on a machine with more memory; docs/limits.md)"
            : "about " + format_number(estimate.cells, 2) + " cells (limit " +
                  format_number(limits::max_cells_2d, 2) + ", docs/limits.md)";
  const std::string reason =
      "the mesh would have " + size + ": " + format_number(estimate.fine_cells, 2) +
      " at the contact size " + format_number(grading.smallest_size() * 1e3, 3) +
      " mm within the fine radius " + format_number(fine_radius * 1e3, 3) +
      " mm (0: 1.5 Hertz half-widths of the load), " +
      format_number(estimate.graded_cells + estimate.body_cells, 2) + " elsewhere (body size " +
      format_number(grading.body_size * 1e3, 3) + " mm" +
      (solid ? ", " + std::to_string(options.layers) + " layers" : "") + ")" +
      (solid
           ? ""
           : ", about " + format_number(estimate.cells * limits::solve_bytes_per_cell_2d / 1e9, 2) +
                 " GB for a Q2 contact solve") +
      "; meshing and solving it could not finish";
  // In 3D the layers multiply the section: when the section would fit with the default layers,
  // the layers are what the user raised (1000 layers were blamed on the body size).
  if (solid)
  {
    const double section_cells = estimate.cells / options.layers;
    const auto fits = [&](unsigned int layers)
    {
      return solve_bytes_3d(
                 hexahedron_unknowns(section_cells * layers, layers, options.element_degree),
                 options.element_degree) <= options.memory_limit;
    };
    unsigned int most = 0;
    while (most < options.layers && fits(most + 1))
      ++most;
    if (fits(MeshOptions().layers) && most >= options.least_layers)
      throw InputError(field::mesh("layers"),
                       reason + ": use at most " + std::to_string(most) + " layers");
  }
  if (estimate.body_cells > estimate.fine_cells + estimate.graded_cells)
    throw InputError(field::mesh("body_size"), reason + ": use a larger body size");
  throw InputError(field::mesh("contact_size"),
                   reason + ": use a larger contact size, a smaller fine radius or a smaller load");
}
} // namespace gearstiff::geometry
