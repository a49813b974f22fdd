#include "geometry/mesh_planar.h"

#include "errors/errors.h"
#include "errors/format.h"
#include "errors/io.h"
#include "errors/limits.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
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
using Clock = std::chrono::steady_clock;

double seconds_since(const Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// gmsh is a process-wide singleton; this keeps its lifetime to one meshing call so that a
// thrown error never leaves a half-built model behind for the next call (or for deal.II's
// GridIn::read_msh, which initialises and finalises gmsh itself).
class GmshSession
{
public:
  GmshSession()
  {
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 1);
    gmsh::model::add("gearstiff");
  }
  ~GmshSession() { gmsh::finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

// Junctions between pieces are snapped when closer than this (m): profile generators
// compute shared end points independently, so bit-identical coordinates are not required,
// but anything visible at the finest mesh sizes (1e-6 m) is a genuine gap.
constexpr double junction_tolerance = 1e-9;

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

std::vector<BoundaryPiece> counter_clockwise(const BoundaryLoop& loop)
{
  std::vector<BoundaryPiece> pieces = loop.pieces;
  if (loop.signed_area() < 0.)
  {
    std::reverse(pieces.begin(), pieces.end());
    for (auto& piece : pieces)
      std::reverse(piece.points.begin(), piece.points.end());
  }
  return pieces;
}

void check_loop(const BoundaryLoop& loop, const std::string& body_name)
{
  const std::string parameter = "geometry of " + body_name;
  if (loop.pieces.empty())
    throw InputError(parameter, "a boundary loop has no pieces");
  for (std::size_t k = 0; k < loop.pieces.size(); ++k)
  {
    const BoundaryPiece& piece = loop.pieces[k];
    if (piece.points.size() < 2)
      throw InputError(parameter,
                       "boundary piece " + std::to_string(k) + " has fewer than 2 points");
    for (const auto& p : piece.points)
      if (!p.allFinite())
        throw InputError(parameter,
                         "boundary piece " + std::to_string(k) + " has a non-finite point");
    for (std::size_t i = 1; i < piece.points.size(); ++i)
      if ((piece.points[i] - piece.points[i - 1]).norm() <= junction_tolerance)
        throw InputError(parameter, "boundary piece " + std::to_string(k) +
                                        " repeats a point (index " + std::to_string(i) + ")");
    const BoundaryPiece& next = loop.pieces[(k + 1) % loop.pieces.size()];
    const double gap = (piece.points.back() - next.points.front()).norm();
    if (gap > junction_tolerance)
      throw InputError(parameter, "boundary loop is not closed after piece " + std::to_string(k) +
                                      " (gap " + std::to_string(gap) + " m)");
    if (piece.kind == CurveKind::arc)
    {
      const double r0 = (piece.points.front() - piece.arc_centre).norm();
      const double r1 = (piece.points.back() - piece.arc_centre).norm();
      if (std::abs(r0 - r1) > 1e-9 * std::max(1., r0 / 1e-3) || r0 <= 0.)
        throw InputError(parameter, "arc piece " + std::to_string(k) +
                                        " does not keep its radius about its centre");
    }
  }
  if (std::abs(loop.signed_area()) <= 0.)
    throw InputError(parameter, "a boundary loop encloses no area");
}

// The gmsh tags of one loop: per piece (in the order of BoundaryLoop::pieces, not of the
// traversal) its curves and end points in the piece's own direction.
struct LoopTags
{
  int loop = 0;
  std::vector<std::vector<int>> piece_curves; // signed: negative where gmsh's curve runs against
  std::vector<std::pair<int, int>> piece_ends;
};

void add_curve(const BoundaryPiece& piece, const std::vector<int>& point_tags,
               std::vector<int>& new_curves)
{
  switch (piece.kind)
  {
  case CurveKind::spline:
    new_curves.push_back(gmsh::model::geo::addSpline(point_tags));
    break;
  case CurveKind::straight:
    for (std::size_t i = 1; i < point_tags.size(); ++i)
      new_curves.push_back(gmsh::model::geo::addLine(point_tags[i - 1], point_tags[i]));
    break;
  case CurveKind::arc:
  {
    const int centre = gmsh::model::geo::addPoint(piece.arc_centre.x(), piece.arc_centre.y(), 0.);
    new_curves.push_back(
        gmsh::model::geo::addCircleArc(point_tags.front(), centre, point_tags.back()));
    break;
  }
  }
}

int add_point(const Eigen::Vector2d& p)
{
  return gmsh::model::geo::addPoint(p.x(), p.y(), 0.);
}

// Adds one loop to gmsh's built-in kernel; returns its tags and records each curve's boundary id.
LoopTags add_loop(const BoundaryLoop& loop, bool outer,
                  std::map<int, std::vector<int>>& curves_by_id,
                  std::vector<std::pair<int, int>>& curve_ids)
{
  std::vector<BoundaryPiece> pieces = counter_clockwise(loop);
  // Reversed: the traversal runs the pieces backwards (counter_clockwise or a hole).
  const bool reversed = (loop.signed_area() < 0.) == outer;
  if (!outer)
  {
    std::reverse(pieces.begin(), pieces.end());
    for (auto& piece : pieces)
      std::reverse(piece.points.begin(), piece.points.end());
  }
  LoopTags tags_out;
  tags_out.piece_curves.resize(pieces.size());
  tags_out.piece_ends.resize(pieces.size());
  const int first_tag = add_point(pieces.front().points.front());
  int start_tag = first_tag;
  std::vector<int> loop_curves;
  for (std::size_t k = 0; k < pieces.size(); ++k)
  {
    const BoundaryPiece& piece = pieces[k];
    const bool last_piece = (k + 1 == pieces.size());
    std::vector<int> tags{start_tag};
    for (std::size_t i = 1; i + 1 < piece.points.size(); ++i)
      tags.push_back(add_point(piece.points[i]));
    tags.push_back(last_piece ? first_tag : add_point(piece.points.back()));

    std::vector<int> new_curves;
    add_curve(piece, tags, new_curves);
    for (const int c : new_curves)
    {
      loop_curves.push_back(c);
      curve_ids.emplace_back(c, piece.boundary_id);
      if (piece.boundary_id != 0)
        curves_by_id[piece.boundary_id].push_back(c);
    }
    const std::size_t original = reversed ? pieces.size() - 1 - k : k;
    if (reversed)
    {
      std::reverse(new_curves.begin(), new_curves.end());
      for (int& c : new_curves)
        c = -c;
      tags_out.piece_ends[original] = {tags.back(), tags.front()};
    }
    else
      tags_out.piece_ends[original] = {tags.front(), tags.back()};
    tags_out.piece_curves[original] = new_curves;
    start_tag = tags.back();
  }
  tags_out.loop = gmsh::model::geo::addCurveLoop(loop_curves);
  return tags_out;
}

// The surface of a fill (PlanarFill): the body's curves of its pieces first_piece..last_piece
// and the closing pieces back, counter-clockwise (reversed where the polygon runs clockwise).
int add_fill_surface(const PlanarFill& fill, const BoundaryLoop& outer, const LoopTags& tags,
                     std::map<int, std::vector<int>>& curves_by_id,
                     std::vector<std::pair<int, int>>& curve_ids)
{
  if (fill.first_piece > fill.last_piece || fill.last_piece >= outer.pieces.size() ||
      fill.closing.empty())
    throw SolverFailure("gmsh geometry", "a fill's pieces do not lie on its body's outline");
  std::vector<int> curves;
  BoundaryLoop polygon;
  for (std::size_t k = fill.first_piece; k <= fill.last_piece; ++k)
  {
    curves.insert(curves.end(), tags.piece_curves[k].begin(), tags.piece_curves[k].end());
    polygon.pieces.push_back(outer.pieces[k]);
  }
  int start_tag = tags.piece_ends[fill.last_piece].second;
  const int end_tag = tags.piece_ends[fill.first_piece].first;
  for (std::size_t k = 0; k < fill.closing.size(); ++k)
  {
    const BoundaryPiece& piece = fill.closing[k];
    std::vector<int> point_tags{start_tag};
    for (std::size_t i = 1; i + 1 < piece.points.size(); ++i)
      point_tags.push_back(add_point(piece.points[i]));
    point_tags.push_back(k + 1 == fill.closing.size() ? end_tag : add_point(piece.points.back()));
    std::vector<int> new_curves;
    add_curve(piece, point_tags, new_curves);
    for (const int c : new_curves)
    {
      curves.push_back(c);
      curve_ids.emplace_back(c, piece.boundary_id);
      if (piece.boundary_id != 0)
        curves_by_id[piece.boundary_id].push_back(c);
    }
    polygon.pieces.push_back(piece);
    start_tag = point_tags.back();
  }
  if (polygon.signed_area() < 0.)
  {
    std::reverse(curves.begin(), curves.end());
    for (int& c : curves)
      c = -c;
  }
  return gmsh::model::geo::addPlaneSurface({gmsh::model::geo::addCurveLoop(curves)});
}

std::unordered_map<std::size_t, Eigen::Vector3d> node_coordinates()
{
  std::vector<std::size_t> tags;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(tags, coordinates, parametric, -1, -1, false, false);
  std::unordered_map<std::size_t, Eigen::Vector3d> nodes;
  nodes.reserve(tags.size());
  for (std::size_t i = 0; i < tags.size(); ++i)
    nodes[tags[i]] =
        Eigen::Vector3d(coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]);
  return nodes;
}

// Every cell must be a quadrilateral (hexahedron) with positive scaled Jacobian: deal.II's
// parallel::distributed::Triangulation accepts nothing else, and an inverted cell would
// silently corrupt every stiffness computed on the mesh. Fills the cell counts and quality.
void check_cells(const MeshOptions& options, const SizeGrading& grading,
                 const std::vector<std::pair<int, int>>& surfaces,
                 const std::vector<std::pair<int, int>>& volumes, MeshStatistics& statistics)
{
  const int dim = static_cast<int>(options.dimension);
  const int cell_type = (dim == 2) ? 3 : 5; // gmsh: 3 = 4-node quadrangle, 5 = 8-node hexahedron
  const unsigned int n_corners = (dim == 2) ? 4 : 8;
  const auto nodes = node_coordinates();
  statistics.n_vertices = nodes.size();
  statistics.n_cells = 0;
  statistics.cells_per_body.clear();
  statistics.largest_edge_ratio_at_focus = 0.;
  double jacobian_sum = 0.;
  statistics.min_scaled_jacobian = std::numeric_limits<double>::infinity();
  const auto& entities = (dim == 2) ? surfaces : volumes;
  for (const auto& [entity, material_id] : entities)
  {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, element_nodes;
    gmsh::model::mesh::getElements(types, element_tags, element_nodes, dim, entity);
    for (std::size_t t = 0; t < types.size(); ++t)
    {
      if (types[t] != cell_type)
      {
        std::string type_name;
        int type_dim, order, n_nodes, n_primary;
        std::vector<double> local;
        gmsh::model::mesh::getElementProperties(types[t], type_name, type_dim, order, n_nodes,
                                                local, n_primary);
        throw SolverFailure("gmsh quadrilateral meshing",
                            std::to_string(element_tags[t].size()) + " leftover " + type_name +
                                " cells in body with material id " + std::to_string(material_id));
      }
      std::vector<Eigen::Vector3d> corners(n_corners);
      for (std::size_t e = 0; e < element_tags[t].size(); ++e)
      {
        for (unsigned int c = 0; c < n_corners; ++c)
          corners[c] = nodes.at(element_nodes[t][n_corners * e + c]);
        const double q = (dim == 2) ? scaled_jacobian_quad(corners) : scaled_jacobian_hex(corners);
        if (q < statistics.min_scaled_jacobian)
        {
          statistics.min_scaled_jacobian = q;
          statistics.worst_cell_centre = Eigen::Vector3d::Zero();
          for (const auto& corner : corners)
            statistics.worst_cell_centre += corner / n_corners;
        }
        jacobian_sum += q;
        for (const auto& focus : grading.foci)
        {
          bool at_focus = false;
          for (unsigned int c = 0; c < 4; ++c)
            at_focus |= (corners[c].head<2>() - focus.point).norm() <= focus.size;
          if (at_focus)
            for (unsigned int c = 0; c < 4; ++c)
              statistics.largest_edge_ratio_at_focus =
                  std::max(statistics.largest_edge_ratio_at_focus,
                           (corners[(c + 1) % 4] - corners[c]).norm() / focus.size);
        }
      }
      statistics.cells_per_body[material_id] += element_tags[t].size();
      statistics.n_cells += element_tags[t].size();
    }
  }
  if (statistics.n_cells == 0)
    throw SolverFailure("gmsh mesh generation", "produced no cells");
  // gmsh can give up on one body's surface and still write the others (an 800 µm tip relief
  // left the pinion's tip 116 µm wide): the file then references nodes it never wrote, which
  // only deal.II's reader noticed. Refused here, and retried finer like leftover triangles.
  for (const auto& [entity, material_id] : entities)
    if (statistics.cells_per_body[material_id] == 0)
      throw SolverFailure("gmsh quadrilateral meshing",
                          "no cells in the body with material id " + std::to_string(material_id));
  statistics.mean_scaled_jacobian = jacobian_sum / statistics.n_cells;
  if (!(statistics.min_scaled_jacobian > 0.))
    throw SolverFailure("gmsh mesh generation",
                        "inverted or degenerate cell (minimum scaled Jacobian " +
                            std::to_string(statistics.min_scaled_jacobian) + ")");
}
} // namespace

double BoundaryLoop::signed_area() const
{
  // Shoelace formula over the polygon through all piece points; arcs and splines are
  // represented by their points, enough for the sign and a plausibility check.
  double twice_area = 0.;
  for (const auto& piece : pieces)
    for (std::size_t i = 1; i < piece.points.size(); ++i)
    {
      const auto& a = piece.points[i - 1];
      const auto& b = piece.points[i];
      twice_area += a.x() * b.y() - b.x() * a.y();
    }
  return 0.5 * twice_area;
}

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

double scaled_jacobian_quad(const std::vector<Eigen::Vector3d>& corners)
{
  double minimum = std::numeric_limits<double>::infinity();
  for (unsigned int i = 0; i < 4; ++i)
  {
    const Eigen::Vector3d e1 = corners[(i + 1) % 4] - corners[i];
    const Eigen::Vector3d e2 = corners[(i + 3) % 4] - corners[i];
    // The z component of the cross product: positive for counter-clockwise corners in the
    // xy-plane, which is where all planar scenes live.
    const double det = e1.x() * e2.y() - e1.y() * e2.x();
    minimum = std::min(minimum, det / (e1.norm() * e2.norm()));
  }
  return minimum;
}

double scaled_jacobian_hex(const std::vector<Eigen::Vector3d>& corners)
{
  // Edge triples (right-handed for a positively oriented hexahedron), as in the Verdict library.
  static constexpr unsigned int neighbours[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                                    {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
  double minimum = std::numeric_limits<double>::infinity();
  for (unsigned int i = 0; i < 8; ++i)
  {
    const Eigen::Vector3d e1 = corners[neighbours[i][0]] - corners[i];
    const Eigen::Vector3d e2 = corners[neighbours[i][1]] - corners[i];
    const Eigen::Vector3d e3 = corners[neighbours[i][2]] - corners[i];
    minimum = std::min(minimum, e1.cross(e2).dot(e3) / (e1.norm() * e2.norm() * e3.norm()));
  }
  return minimum;
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
    estimate.cells *= options.layers;
  return estimate;
}

void check_mesh_estimate(const PlanarModel& model, const SizeGrading& grading,
                         const MeshOptions& options)
{
  const MeshEstimate estimate = estimate_mesh(model, grading, options);
  const double limit = options.dimension == 3 ? limits::max_cells_3d : limits::max_cells_2d;
  if (estimate.cells <= limit)
    return;
  double fine_radius = 0.;
  for (const auto& focus : grading.foci)
    fine_radius = std::max(fine_radius, focus.radius);
  const std::string kind = options.dimension == 3 ? "hexahedra" : "cells";
  const std::string reason =
      "the mesh would have about " + format_number(estimate.cells, 2) + " " + kind + " (limit " +
      format_number(limit, 2) + ", docs/limits.md): " + format_number(estimate.fine_cells, 2) +
      " at the contact size " + format_number(grading.smallest_size() * 1e3, 3) +
      " mm within the fine radius " + format_number(fine_radius * 1e3, 3) +
      " mm (0: 1.5 Hertz half-widths of the load), " +
      format_number(estimate.graded_cells + estimate.body_cells, 2) + " elsewhere (body size " +
      format_number(grading.body_size * 1e3, 3) + " mm" +
      (options.dimension == 3 ? ", " + std::to_string(options.layers) + " layers" : "") + ")" +
      (options.dimension == 2
           ? ", about " + format_number(estimate.cells * limits::solve_bytes_per_cell_2d / 1e9, 2) +
                 " GB for a Q2 contact solve"
           : "") +
      "; meshing and solving it could not finish";
  // In 3D the layers multiply the section: when the section would fit with the default layers,
  // the layers are what the user raised (1000 layers were blamed on the body size).
  const double section_cells = estimate.cells / (options.dimension == 3 ? options.layers : 1.);
  if (options.dimension == 3 && section_cells * MeshOptions().layers <= limit)
    throw InputError("Mesh/layers", reason + ": use at most " +
                                        std::to_string(static_cast<unsigned int>(
                                            std::floor(limit / section_cells))) +
                                        " layers");
  if (estimate.body_cells > estimate.fine_cells + estimate.graded_cells)
    throw InputError("Mesh/body size", reason + ": use a larger body size");
  throw InputError("Mesh/contact size",
                   reason + ": use a larger contact size, a smaller fine radius or a smaller load");
}

namespace
{
// Everything mesh_planar_model refuses before gmsh starts (InputError naming the parameter).
void check_mesh_input(const PlanarModel& model, const SizeGrading& grading,
                      const MeshOptions& options)
{
  if (model.bodies.empty())
    throw InputError("scene", "has no bodies to mesh");
  if (options.dimension != 2 && options.dimension != 3)
    throw InputError("Mesh/dimension", "must be 2 or 3");
  if (options.dimension == 3 && !(options.face_width > 0.))
    throw InputError("Mesh/face width", "must be positive for a 3D mesh");
  if (options.dimension == 3 && options.layers < 1)
    throw InputError("Mesh/layers", "must be at least 1 for a 3D mesh");
  bool foci_valid = true;
  for (const auto& focus : grading.foci)
    foci_valid &= focus.size > 0. && focus.size <= grading.body_size && focus.radius >= 0. &&
                  focus.point.allFinite();
  if (!foci_valid || !(grading.body_size > 0.) || !(grading.largest_size >= grading.body_size) ||
      !(grading.growth_rate > 0.))
    throw InputError("Mesh/contact size", "needs 0 < contact size <= body size, a positive growth "
                                          "rate and a non-negative fine radius");
  if (options.file.empty())
    throw InputError("Scene/mesh file", "no output file given");
  for (const auto& body : model.bodies)
  {
    if (body.material_id <= 0)
      throw InputError("material id of " + body.name, "must be positive");
    check_loop(body.outer, body.name);
    for (const auto& hole : body.holes)
      check_loop(hole, body.name);
  }
  check_mesh_estimate(model, grading, options);
}

// The gmsh entities of the model and their ids.
struct GmshEntities
{
  std::map<int, std::vector<int>> curves_by_id;
  std::vector<std::pair<int, int>> curve_ids;             // (curve tag, boundary id), every curve
  std::vector<std::pair<int, int>> surfaces;              // (surface tag, material id)
  std::vector<std::pair<int, int>> volumes;               // (volume tag, material id), 3D
  std::map<int, std::vector<int>> lateral_surfaces_by_id; // boundary id -> surfaces, 3D
  std::vector<int> side_faces;                            // z = 0 and z = face width, 3D
  std::vector<int> lateral_surfaces;                      // 3D
  // Per body: its surface's index in `surfaces` and its fills' (PlanarFill) surface tags.
  std::vector<std::pair<std::size_t, std::vector<int>>> body_fills;
  // 3D: the fills' volumes and the test of the cells they leave out.
  std::vector<std::pair<int, std::function<bool(const Eigen::Vector3d&)>>> fill_volumes;
  // 2D: the cracks whose faces meet (PlanarFill::crack_id)
  struct Crack
  {
    int id = 0;              // boundary id of the body's face (the fill's: id + 1)
    int fill = 0;            // surface tag of the fill
    std::vector<int> curves; // curve tags from the mouth to the tip
    int tip = 0;             // point tag
  };
  std::vector<Crack> cracks;
};

// The gmsh entities of a fill's crack (PlanarFill::crack_id): the piece among first..last that
// carries the crack's id; its tip is its end shared with the other piece (the cut).
GmshEntities::Crack crack_entities(const PlanarFill& fill, const BoundaryLoop& outer,
                                   const LoopTags& tags, int surface)
{
  GmshEntities::Crack crack;
  crack.id = fill.crack_id;
  crack.fill = surface;
  for (std::size_t k = fill.first_piece; k <= fill.last_piece; ++k)
    if (outer.pieces[k].boundary_id == fill.crack_id)
    {
      for (const int c : tags.piece_curves[k])
        crack.curves.push_back(std::abs(c));
      crack.tip = k == fill.first_piece ? tags.piece_ends[k].second : tags.piece_ends[k].first;
    }
  if (crack.curves.empty() || fill.first_piece == fill.last_piece)
    throw SolverFailure("gmsh geometry", "a crack's fill has no crack piece and cut");
  return crack;
}

// 3D: extrude each body's surface together with its fills (one call, so that their shared
// curves sweep one lateral surface); gmsh returns, per surface, the top surface, the volume and
// the lateral surfaces.
void extrude_surfaces(const PlanarModel& model, const MeshOptions& options, GmshEntities& entities)
{
  const std::vector<std::pair<int, int>> bodies = entities.surfaces;
  std::set<int> seen; // a curve shared by a body and its fill sweeps one lateral surface
  for (std::size_t b = 0; b < entities.body_fills.size(); ++b)
  {
    const auto& [index, fills] = entities.body_fills[b];
    const auto [surface, material_id] = bodies[index];
    gmsh::vectorpair input{{2, surface}};
    for (const int fill : fills)
      input.emplace_back(2, fill);
    gmsh::vectorpair extruded;
    gmsh::model::geo::extrude(input, 0., 0., options.face_width, extruded,
                              {static_cast<int>(options.layers)}, {}, true);
    std::vector<std::size_t> starts; // where each input's (top, volume, laterals) begin
    for (std::size_t i = 0; i + 1 < extruded.size(); ++i)
      if (extruded[i].first == 2 && extruded[i + 1].first == 3)
        starts.push_back(i);
    if (starts.size() != input.size())
      throw SolverFailure("gmsh extrusion",
                          "unexpected result for surface " + std::to_string(surface));
    for (std::size_t k = 0; k < starts.size(); ++k)
    {
      entities.side_faces.push_back(input[k].second);
      entities.side_faces.push_back(extruded[starts[k]].second);
      if (k == 0)
        entities.volumes.emplace_back(extruded[starts[k] + 1].second, material_id);
      else
      {
        entities.fill_volumes.emplace_back(extruded[starts[k] + 1].second,
                                           model.bodies[b].fills[k - 1].removed);
        entities.volumes.emplace_back(extruded[starts[k] + 1].second, material_id);
      }
      const std::size_t end = k + 1 < starts.size() ? starts[k + 1] : extruded.size();
      for (std::size_t i = starts[k] + 2; i < end; ++i)
        if (extruded[i].first == 2 && seen.insert(std::abs(extruded[i].second)).second)
          entities.lateral_surfaces.push_back(std::abs(extruded[i].second));
    }
  }
}

// The order of the lateral surfaces follows gmsh's own walk of the curve loops, which reverses a
// hole's curves (harmless for a bore of one id, wrong for a ring whose teeth line its hole), so
// each lateral surface takes the id of the base curve it was swept from (its boundary).
void label_lateral_surfaces(GmshEntities& entities)
{
  const std::map<int, int> id_of_curve(entities.curve_ids.begin(), entities.curve_ids.end());
  for (const int lateral : entities.lateral_surfaces)
  {
    gmsh::vectorpair edges;
    gmsh::model::getBoundary({{2, lateral}}, edges, false, false, false);
    std::optional<int> id;
    for (const auto& [edge_dim, edge] : edges)
      if (const auto found = id_of_curve.find(std::abs(edge)); found != id_of_curve.end())
        id = found->second;
    if (!id)
      throw SolverFailure("gmsh extrusion",
                          "lateral surface " + std::to_string(lateral) + " has no base curve");
    if (*id != 0)
      entities.lateral_surfaces_by_id[*id].push_back(lateral);
  }
}

GmshEntities build_geometry(const PlanarModel& model, const MeshOptions& options)
{
  GmshEntities entities;
  for (const auto& body : model.bodies)
  {
    const LoopTags outer = add_loop(body.outer, true, entities.curves_by_id, entities.curve_ids);
    std::vector<int> loops{outer.loop};
    for (const auto& hole : body.holes)
      loops.push_back(add_loop(hole, false, entities.curves_by_id, entities.curve_ids).loop);
    entities.surfaces.emplace_back(gmsh::model::geo::addPlaneSurface(loops), body.material_id);
    entities.body_fills.emplace_back(entities.surfaces.size() - 1, std::vector<int>{});
    for (const PlanarFill& fill : body.fills)
    {
      const int surface =
          add_fill_surface(fill, body.outer, outer, entities.curves_by_id, entities.curve_ids);
      entities.body_fills.back().second.push_back(surface);
      if (options.dimension == 2)
        entities.surfaces.emplace_back(surface, body.material_id);
      if (fill.crack_id > 0 && options.dimension != 2)
        throw SolverFailure("gmsh geometry", "a crack whose faces meet is meshed in 2D only");
      if (fill.crack_id > 0)
        entities.cracks.push_back(crack_entities(fill, body.outer, outer, surface));
    }
  }
  if (options.dimension == 3)
    extrude_surfaces(model, options, entities);
  gmsh::model::geo::synchronize();
  if (options.dimension == 3)
    label_lateral_surfaces(entities);
  return entities;
}

void add_physical_groups(const PlanarModel& model, const MeshOptions& options,
                         GmshEntities& entities)
{
  const auto name_of_boundary = [&](const int id)
  {
    const auto found = model.boundary_names.find(id);
    return found != model.boundary_names.end() ? found->second : "boundary " + std::to_string(id);
  };
  // Bodies with the same material id (e.g. all rollers of a cycloid drive) share one group,
  // named after the first of them.
  const auto add_body_groups = [&](const int dim, const std::vector<std::pair<int, int>>& bodies)
  {
    std::map<int, std::vector<int>> entities_by_id;
    std::map<int, std::string> names;
    for (const auto& [tag, material_id] : bodies)
      entities_by_id[material_id].push_back(tag);
    for (const PlanarBody& body : model.bodies)
      names.emplace(body.material_id, body.name);
    for (const auto& [id, tags] : entities_by_id)
    {
      gmsh::model::addPhysicalGroup(dim, tags, id);
      gmsh::model::setPhysicalName(dim, id, names[id]);
    }
  };
  const bool planar = options.dimension == 2;
  add_body_groups(planar ? 2 : 3, planar ? entities.surfaces : entities.volumes);
  if (!planar && options.side_face_boundary_id != 0)
  {
    if (entities.lateral_surfaces_by_id.count(options.side_face_boundary_id))
      throw InputError("side face boundary id", "is already used by a boundary curve");
    entities.lateral_surfaces_by_id[options.side_face_boundary_id] = entities.side_faces;
  }
  for (const auto& [id, tags] : planar ? entities.curves_by_id : entities.lateral_surfaces_by_id)
  {
    gmsh::model::addPhysicalGroup(planar ? 1 : 2, tags, id);
    gmsh::model::setPhysicalName(planar ? 1 : 2, id, name_of_boundary(id));
  }
}

void set_meshing_options(const SizeGrading& grading)
{
  // Sizes come from the grading alone: point and curvature sizes would override the contact
  // size with the spacing of the profile points.
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.1 * grading.smallest_size());
  gmsh::option::setNumber("Mesh.MeshSizeMax", grading.largest_size);
  // Frontal-Delaunay triangles recombined by the simple full-quad algorithm: all quadrilaterals,
  // minimum scaled Jacobian about 0.35 on the gear scenes, 10-20% faster than full-quad Blossom
  // (RecombinationAlgorithm 3) at slightly better quality. (gmsh 4.8's "Frontal-Delaunay for
  // quads", algorithm 8, crashes inside its cross-field background mesh when a size callback
  // is set; the simple recombination leaves triangles.)
  gmsh::option::setNumber("Mesh.Algorithm", 6);
  gmsh::option::setNumber("Mesh.RecombineAll", 1);
  gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 2);
  gmsh::option::setNumber("Mesh.Smoothing", 5);
  gmsh::option::setNumber("Mesh.ElementOrder", 1);
}

// 3D: every node of each volume moved in-plane by model.node_offset (lead modifications); the
// bodies are disjoint, so each node belongs to one volume.
void move_nodes(const PlanarModel& model, const GmshEntities& entities)
{
  for (const auto& [volume, material_id] : entities.volumes)
  {
    std::vector<std::size_t> tags;
    std::vector<double> coordinates, parametric;
    gmsh::model::mesh::getNodes(tags, coordinates, parametric, 3, volume, true, false);
    for (std::size_t i = 0; i < tags.size(); ++i)
    {
      const Eigen::Vector3d x(coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]);
      const Eigen::Vector2d offset = model.node_offset(material_id, x);
      if (offset.x() != 0. || offset.y() != 0.)
        gmsh::model::mesh::setNode(tags[i], {x.x() + offset.x(), x.y() + offset.y(), x.z()}, {});
    }
  }
}

using FaceKey = std::array<std::size_t, 4>;

FaceKey face_key(std::array<std::size_t, 4> nodes)
{
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

// The nodes of entity (dim, tag) that `used` holds, added back after its mesh was cleared.
void add_used_nodes(int dim, int tag, const std::set<std::size_t>& used,
                    const std::vector<std::size_t>& node_tags,
                    const std::vector<double>& node_coordinates)
{
  std::vector<std::size_t> tags;
  std::vector<double> coordinates;
  for (std::size_t i = 0; i < node_tags.size(); ++i)
    if (used.count(node_tags[i]))
    {
      tags.push_back(node_tags[i]);
      coordinates.insert(coordinates.end(), node_coordinates.begin() + 3 * i,
                         node_coordinates.begin() + 3 * i + 3);
    }
  gmsh::model::mesh::addNodes(dim, tag, tags, coordinates);
}

// A fill volume's own surface (bounding no other volume) with the quadrilaterals it keeps.
struct OwnSurface
{
  int tag;
  std::vector<std::size_t> quad_tags, quad_nodes;
};

// The own surfaces of `volume`, without the faces of removed cells; their nodes added to `used`.
std::vector<OwnSurface> own_surfaces(int volume, const std::set<FaceKey>& removed_faces,
                                     std::set<std::size_t>& used)
{
  gmsh::vectorpair boundary;
  gmsh::model::getBoundary({{3, volume}}, boundary, false, false, false);
  std::vector<OwnSurface> own;
  for (const auto& [dim, surface] : boundary)
  {
    std::vector<int> upward, downward;
    gmsh::model::getAdjacencies(2, std::abs(surface), upward, downward);
    if (upward.size() != 1)
      continue;
    OwnSurface o{std::abs(surface), {}, {}};
    std::vector<std::size_t> tags, quads;
    gmsh::model::mesh::getElementsByType(3, tags, quads, o.tag);
    for (std::size_t q = 0; q < tags.size(); ++q)
      if (!removed_faces.count(
              face_key({quads[4 * q], quads[4 * q + 1], quads[4 * q + 2], quads[4 * q + 3]})))
      {
        o.quad_tags.push_back(tags[q]);
        o.quad_nodes.insert(o.quad_nodes.end(), quads.begin() + 4 * q, quads.begin() + 4 * q + 4);
      }
    used.insert(o.quad_nodes.begin(), o.quad_nodes.end());
    own.push_back(o);
  }
  return own;
}

// 3D: the hexahedra of each fill whose centre lies in its fault left out, with the faces of its
// own boundary surfaces (end faces, the closing pieces' lateral surfaces) on them; the rest
// stays the body's material. Returns the number of hexahedra left out.
unsigned long remove_fill_cells(const GmshEntities& entities)
{
  static constexpr unsigned int hex_faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                   {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  const auto nodes = node_coordinates();
  unsigned long removed_count = 0;
  for (const auto& [volume, removed] : entities.fill_volumes)
  {
    std::vector<std::size_t> hex_tags, hex_nodes;
    gmsh::model::mesh::getElementsByType(5, hex_tags, hex_nodes, volume);
    std::vector<std::size_t> kept_tags, kept_nodes;
    std::set<FaceKey> removed_faces;
    std::set<std::size_t> used;
    for (std::size_t e = 0; e < hex_tags.size(); ++e)
    {
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (unsigned int c = 0; c < 8; ++c)
        centre += nodes.at(hex_nodes[8 * e + c]) / 8.;
      if (removed(centre))
        for (const auto& face : hex_faces)
          removed_faces.insert(face_key({hex_nodes[8 * e + face[0]], hex_nodes[8 * e + face[1]],
                                         hex_nodes[8 * e + face[2]], hex_nodes[8 * e + face[3]]}));
      else
      {
        kept_tags.push_back(hex_tags[e]);
        kept_nodes.insert(kept_nodes.end(), hex_nodes.begin() + 8 * e,
                          hex_nodes.begin() + 8 * e + 8);
      }
    }
    if (kept_tags.size() == hex_tags.size())
      continue;
    removed_count += hex_tags.size() - kept_tags.size();
    used.insert(kept_nodes.begin(), kept_nodes.end());
    const std::vector<OwnSurface> own = own_surfaces(volume, removed_faces, used);
    std::vector<std::size_t> node_tags;
    std::vector<double> coordinates, parametric;
    gmsh::model::mesh::getNodes(node_tags, coordinates, parametric, 3, volume, false, false);
    std::vector<std::vector<std::size_t>> own_node_tags(own.size());
    std::vector<std::vector<double>> own_coordinates(own.size());
    for (std::size_t k = 0; k < own.size(); ++k)
      gmsh::model::mesh::getNodes(own_node_tags[k], own_coordinates[k], parametric, 2, own[k].tag,
                                  false, false);
    gmsh::model::mesh::clear({{3, volume}});
    for (const OwnSurface& o : own)
      gmsh::model::mesh::clear({{2, o.tag}});
    // Every node back before any element refers to it.
    add_used_nodes(3, volume, used, node_tags, coordinates);
    for (std::size_t k = 0; k < own.size(); ++k)
      add_used_nodes(2, own[k].tag, used, own_node_tags[k], own_coordinates[k]);
    gmsh::model::mesh::addElementsByType(volume, 5, kept_tags, kept_nodes);
    for (const OwnSurface& o : own)
      if (!o.quad_tags.empty())
        gmsh::model::mesh::addElementsByType(o.tag, 3, o.quad_tags, o.quad_nodes);
  }
  return removed_count;
}

// The mesh of entity (dim, tag) taken out: its own nodes and its elements.
struct EntityMesh
{
  int dim = 0, tag = 0;
  std::vector<std::size_t> node_tags;
  std::vector<double> coordinates;
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, element_nodes;
};

EntityMesh entity_mesh(int dim, int tag)
{
  EntityMesh m{dim, tag, {}, {}, {}, {}, {}};
  std::vector<double> parametric;
  gmsh::model::mesh::getNodes(m.node_tags, m.coordinates, parametric, dim, tag, false, false);
  gmsh::model::mesh::getElements(m.types, m.element_tags, m.element_nodes, dim, tag);
  return m;
}

// The crack's nodes but the tip's, each with the tag of its copy (new tags from the largest in
// use); `tip` set to the tip's node.
std::map<std::size_t, std::size_t>
crack_copies(const GmshEntities::Crack& crack,
             const std::unordered_map<std::size_t, Eigen::Vector3d>& nodes, std::size_t& tip)
{
  std::size_t next_node = 1;
  for (const auto& [tag, x] : nodes)
    next_node = std::max(next_node, tag + 1);
  std::vector<std::size_t> tags;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(tags, coordinates, parametric, 0, crack.tip, false, false);
  if (tags.size() != 1)
    throw SolverFailure("gmsh crack splitting", "the crack's tip has no node");
  tip = tags.front();
  std::map<std::size_t, std::size_t> copy_of;
  for (const int c : crack.curves)
  {
    gmsh::model::mesh::getNodes(tags, coordinates, parametric, 1, c, true, false);
    for (const std::size_t t : tags)
      if (t != tip && !copy_of.count(t))
        copy_of[t] = next_node++;
  }
  return copy_of;
}

// The unit normal of the crack (mouth to tip) towards the side of the fill's cells.
Eigen::Vector2d towards_fill(const EntityMesh& fill,
                             const std::map<std::size_t, std::size_t>& copy_of,
                             const std::unordered_map<std::size_t, Eigen::Vector3d>& nodes,
                             std::size_t tip)
{
  const Eigen::Vector2d tip_point = nodes.at(tip).head<2>();
  Eigen::Vector2d mouth_point = tip_point;
  for (const auto& [original, copy] : copy_of)
    if ((nodes.at(original).head<2>() - tip_point).norm() > (mouth_point - tip_point).norm())
      mouth_point = nodes.at(original).head<2>();
  const Eigen::Vector2d along = (tip_point - mouth_point).normalized();
  const Eigen::Vector2d normal(-along.y(), along.x());
  const auto& quads = fill.element_nodes.at(0);
  for (std::size_t e = 0; 4 * e < quads.size(); ++e)
    for (unsigned int k = 0; k < 4; ++k)
      if (copy_of.count(quads[4 * e + k]))
      {
        Eigen::Vector2d centre = Eigen::Vector2d::Zero();
        for (unsigned int j = 0; j < 4; ++j)
          centre += 0.25 * nodes.at(quads[4 * e + j]).head<2>();
        return (centre - nodes.at(quads[4 * e + k]).head<2>()).dot(normal) < 0. ? -normal : normal;
      }
  throw SolverFailure("gmsh crack splitting", "no cell of the fill touches the crack");
}

// Splits the 2D mesh along a crack whose faces meet (PlanarFill::crack_id): every node of the
// crack's curves but the tip's gets a copy (crack_face_parting towards the fill), the fill's
// cells and its other boundary curves (the one at the mouth) take the copies, and a new curve
// carries the fill's face (boundary id crack.id + 1) on them.
void split_crack(const PlanarModel& model, const GmshEntities::Crack& crack)
{
  const auto nodes = node_coordinates();
  std::size_t tip = 0, next_element = 1;
  const std::map<std::size_t, std::size_t> copy_of = crack_copies(crack, nodes, tip);
  // The fill and its boundary curves other than the crack's whose elements use a crack node.
  std::vector<EntityMesh> taken{entity_mesh(2, crack.fill)};
  gmsh::vectorpair boundary;
  gmsh::model::getBoundary({{2, crack.fill}}, boundary, false, false, false);
  for (const auto& [dim, signed_curve] : boundary)
    if (std::find(crack.curves.begin(), crack.curves.end(), std::abs(signed_curve)) ==
        crack.curves.end())
    {
      EntityMesh m = entity_mesh(1, std::abs(signed_curve));
      for (const auto& list : m.element_nodes)
        if (std::any_of(list.begin(), list.end(), [&](std::size_t n) { return copy_of.count(n); }))
        {
          taken.push_back(std::move(m));
          break;
        }
    }
  const Eigen::Vector2d normal = towards_fill(taken.front(), copy_of, nodes, tip);
  std::vector<std::size_t> copy_tags;
  std::vector<double> copy_coordinates;
  for (const auto& [original, copy] : copy_of)
  {
    copy_tags.push_back(copy);
    const Eigen::Vector2d x = nodes.at(original).head<2>() + crack_face_parting * normal;
    copy_coordinates.insert(copy_coordinates.end(), {x.x(), x.y(), 0.});
  }
  {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, element_nodes;
    gmsh::model::mesh::getElements(types, tags, element_nodes, -1, -1);
    for (const auto& list : tags)
      for (const std::size_t t : list)
        next_element = std::max(next_element, t + 1);
  }
  gmsh::vectorpair cleared;
  for (EntityMesh& m : taken)
  {
    cleared.emplace_back(m.dim, m.tag);
    for (auto& list : m.element_nodes)
      for (std::size_t& n : list)
        if (const auto found = copy_of.find(n); found != copy_of.end())
          n = found->second;
  }
  gmsh::model::mesh::clear(cleared);
  const int face = gmsh::model::addDiscreteEntity(1);
  gmsh::model::mesh::addNodes(1, face, copy_tags, copy_coordinates);
  for (const EntityMesh& m : taken)
    gmsh::model::mesh::addNodes(m.dim, m.tag, m.node_tags, m.coordinates);
  for (auto it = taken.rbegin(); it != taken.rend(); ++it) // the curves first
    gmsh::model::mesh::addElements(it->dim, it->tag, it->types, it->element_tags,
                                   it->element_nodes);
  // The fill's face: the crack's line elements on the copies.
  std::vector<std::size_t> line_tags, line_nodes;
  for (const int c : crack.curves)
  {
    std::vector<std::size_t> crack_tags, crack_nodes;
    gmsh::model::mesh::getElementsByType(1, crack_tags, crack_nodes, c);
    for (const std::size_t n : crack_nodes)
      line_nodes.push_back(n == tip ? tip : copy_of.at(n));
    for (std::size_t k = 0; k < crack_tags.size(); ++k)
      line_tags.push_back(next_element++);
  }
  gmsh::model::mesh::addElementsByType(face, 1, line_tags, line_nodes);
  gmsh::model::addPhysicalGroup(1, {face}, crack.id + 1);
  const auto name = model.boundary_names.find(crack.id + 1);
  gmsh::model::setPhysicalName(1, crack.id + 1,
                               name != model.boundary_names.end()
                                   ? name->second
                                   : "boundary " + std::to_string(crack.id + 1));
}

// Generates the mesh, checks it and regenerates it finer until the cells at the contact points
// meet the contact size (or fail: SolverFailure).
void generate_mesh(const PlanarModel& model, const SizeGrading& grading, const MeshOptions& options,
                   const GmshEntities& entities, MeshStatistics& statistics)
{
  constexpr unsigned int max_attempts = 3;
  double contact_scale = grading.initial_contact_scale;
  // Sizes near the size of a body can leave triangles the recombination cannot pair (100 mm
  // sizes: "4 leftover Triangle 3 cells"); each such generation is repeated with every size 0.7
  // times smaller, up to max_recombination_retries times.
  constexpr unsigned int max_recombination_retries = 4;
  unsigned int recombination_retries = 0;
  double size_scale = 1.;
  for (unsigned int attempt = 1;; ++attempt)
  {
    auto start = Clock::now();
    gmsh::model::mesh::clear();
    gmsh::option::setNumber("Mesh.MeshSizeMax", size_scale * grading.largest_size);
    gmsh::model::mesh::setSizeCallback(
        [&grading, contact_scale, size_scale](int, int, double x, double y, double) {
          return size_scale * grading.size_at({x, y}, contact_scale);
        });
    try
    {
      gmsh::model::mesh::generate(options.dimension);
    }
    catch (const std::exception& e)
    {
      throw SolverFailure("gmsh mesh generation", e.what());
    }
    if (options.dimension == 3 && model.node_offset)
      move_nodes(model, entities);
    statistics.time_meshing += seconds_since(start);
    start = Clock::now();
    try
    {
      check_cells(options, grading, entities.surfaces, entities.volumes, statistics);
    }
    catch (const SolverFailure& e)
    {
      if (e.method() != "gmsh quadrilateral meshing" ||
          recombination_retries == max_recombination_retries)
        throw;
      ++recombination_retries;
      size_scale *= 0.7;
      --attempt; // not an attempt at the contact size
      continue;
    }
    statistics.time_checking += seconds_since(start);
    statistics.contact_scale = contact_scale;
    statistics.meshing_attempts = attempt;
    if (statistics.largest_edge_ratio_at_focus <= 1.)
      return;
    // gmsh's cells at a focus follow the size field only roughly: after the retries a cell up to
    // limits::contact_size_overshoot times the contact size is accepted (the mesh command reports
    // the ratio) — 128-position sweeps failed on cells 1.0006 to 1.05 times the size.
    if (attempt == max_attempts &&
        statistics.largest_edge_ratio_at_focus <= limits::contact_size_overshoot)
      return;
    if (attempt == max_attempts)
      throw SolverFailure("gmsh mesh generation",
                          "the cells at the contact points stay larger than the contact size (" +
                              std::to_string(statistics.largest_edge_ratio_at_focus) +
                              " times the requested size, " +
                              format_number(limits::contact_size_overshoot, 3) +
                              " accepted) after " + std::to_string(max_attempts) + " attempts");
    // Each retry aims further below the size: the overshoot varies between generations.
    contact_scale *= (attempt == 1 ? 0.95 : 0.9) / statistics.largest_edge_ratio_at_focus;
  }
}
} // namespace

MeshStatistics mesh_planar_model(const PlanarModel& model, const SizeGrading& grading,
                                 const MeshOptions& options)
{
  check_mesh_input(model, grading, options);

  MeshStatistics statistics;
  GmshSession session;

  auto start = Clock::now();
  GmshEntities entities;
  try // gmsh 4.8's API reports its errors as a thrown message (std::string)
  {
    entities = build_geometry(model, options);
    add_physical_groups(model, options, entities);
    statistics.time_geometry = seconds_since(start);

    set_meshing_options(grading);
    generate_mesh(model, grading, options, entities, statistics);
    if (!entities.fill_volumes.empty())
    {
      statistics.removed_cells = remove_fill_cells(entities);
      statistics.n_cells -= statistics.removed_cells;
    }
    for (const GmshEntities::Crack& crack : entities.cracks)
      split_crack(model, crack);
  }
  catch (const std::string& message)
  {
    throw SolverFailure("gmsh", message);
  }

  start = Clock::now();
  gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
  gmsh::option::setNumber("Mesh.Binary", 0);
  gmsh::option::setNumber("Mesh.SaveAll", 0);
  try
  {
    gmsh::write(options.file);
  }
  catch (const std::string& message)
  {
    throw IoError(options.file, message);
  }
  // gmsh does not check its writes: a full file system or the file-size limit leaves a truncated
  // mesh that the reader would call bad input. A whole .msh ends with an "$End..." line.
  check_complete_file(options.file, "$End");
  statistics.time_writing = seconds_since(start);
  return statistics;
}
} // namespace gearstiff::geometry
