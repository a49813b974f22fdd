// mesh_planar_model: the gmsh model of the transverse section (loops, surfaces, physical
// groups), generation with its retries, writing. The face-width stage (3D) is face_width.cc.
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
using namespace detail;

namespace
{
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

// Everything mesh_planar_model refuses before gmsh starts (InputError naming the parameter).
void check_mesh_input(const PlanarModel& model, const SizeGrading& grading,
                      const MeshOptions& options)
{
  if (model.bodies.empty())
    throw InputError("scene", "has no bodies to mesh");
  if (options.dimension != 2 && options.dimension != 3)
    throw InputError(field::mesh("dimension"), "must be 2 or 3");
  if (options.dimension == 3 && !(options.face_width > 0.))
    throw InputError(field::mesh("face_width"), "must be positive for a 3D mesh");
  if (options.dimension == 3 && options.layers < 1)
    throw InputError(field::mesh("layers"), "must be at least 1 for a 3D mesh");
  bool foci_valid = true;
  for (const auto& focus : grading.foci)
    foci_valid &= focus.size > 0. && focus.size <= grading.body_size && focus.radius >= 0. &&
                  focus.point.allFinite();
  if (!foci_valid || !(grading.body_size > 0.) || !(grading.largest_size >= grading.body_size) ||
      !(grading.growth_rate > 0.))
    throw InputError(field::mesh("contact_size"),
                     "needs 0 < contact size <= body size, a positive growth "
                     "rate and a non-negative fine radius");
  if (options.file.empty())
    throw InputError(field::mesh("file"), "no output file given");
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
    if (options.dimension == 3 && moves_nodes(model))
      move_nodes(model, entities);
    statistics.time_meshing += seconds_since(start);
    start = Clock::now();
    try
    {
      check_cells(options, grading, entities.surfaces, entities.volumes, model.twist, statistics);
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

MeshStatistics mesh_planar_model(const PlanarModel& model, const SizeGrading& grading,
                                 const MeshOptions& options)
{
  check_mesh_input(model, grading, options);

  MeshStatistics statistics;
  statistics.layers = options.dimension == 3 ? options.layers : 0;
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
      // The counts of check_cells, taken before the fills' cells were left out.
      for (const auto& [material_id, count] : remove_fill_cells(entities))
      {
        statistics.removed_cells += count;
        statistics.cells_per_body[material_id] -= count;
      }
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
