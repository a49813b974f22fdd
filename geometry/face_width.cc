// The face-width stage: how a transverse (2D) model becomes 3D. One place holds every operation
// along the face width z ∈ [0, b]:
//  1. the extrusion of each body's section (with its fills) in `layers` equal layers along +z;
//  2. the path: a body listed in PlanarModel::twist is turned about its axis by φ(z) (the lead of
//     a helical gear, φ = (z − z₀)·tan β_b / r_b, ISO 21771), so every section is the transverse
//     model turned; not listed: straight;
//  3. the lead modifications (PlanarModel::node_offset, geometry/tooth_modification_lead.h),
//     applied on the untwisted section before the turn;
//  4. partial-width faults (PlanarFill::removed): the cells of a fill whose centre lies in the
//     fault are left out with the faces on them (a twisted body's centre turned back first).
// The cell checks (mesh_quality.cc) run after 2 and 3, so a twist too coarse for its layers is a
// failed check, not a silent mesh.
#include "errors/errors.h"
#include "errors/format.h"
#include "errors/io.h"
#include "errors/limits.h"
#include "geometry/mesh_internal.h"
#include "geometry/mesh_planar.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <gmsh.h>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

namespace gearstiff::geometry
{
Eigen::Vector2d BodyTwist::turned(const Eigen::Vector2d& point, const double z) const
{
  const double phi = angle(z);
  return axis + Eigen::Rotation2Dd(phi) * (point - axis);
}

Eigen::Vector2d BodyTwist::untwisted(const Eigen::Vector2d& point, const double z) const
{
  return axis + Eigen::Rotation2Dd(-angle(z)) * (point - axis);
}

Eigen::Vector3d BodyTwist::on_helix(const Eigen::Vector3d& x, const double z_below,
                                    const double z_above) const
{
  const double height = z_above - z_below;
  if (!(height > 0.) || rate == 0.)
    return x;
  const double t = std::clamp((x.z() - z_below) / height, 0., 1.);
  const std::complex<double> chord = (1. - t) + t * std::polar(1., angle(z_above) - angle(z_below));
  const double turn = angle(x.z()) - angle(z_below) - std::arg(chord);
  const Eigen::Vector2d section = Eigen::Rotation2Dd(turn) * (x.head<2>() - axis) / std::abs(chord);
  return {axis.x() + section.x(), axis.y() + section.y(), x.z()};
}

namespace detail
{
namespace
{
// A fault's test of a cell centre, which it states in the transverse model: the cells are tested
// after the path's turn (step 2 before 4), so a twisted body's centre is turned back first — a
// helical tooth's partial crack follows the tooth along its helix, as its through-face outline
// does.
std::function<bool(const Eigen::Vector3d&)>
section_test(const std::function<bool(const Eigen::Vector3d&)>& removed,
             const std::map<int, BodyTwist>& twists, const int material_id)
{
  const auto twist = twists.find(material_id);
  if (twist == twists.end())
    return removed;
  return [removed, body = twist->second](const Eigen::Vector3d& centre)
  {
    const Eigen::Vector2d section = body.untwisted(centre.head<2>(), centre.z());
    return removed(Eigen::Vector3d(section.x(), section.y(), centre.z()));
  };
}
} // namespace

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
        entities.fill_volumes.emplace_back(
            extruded[starts[k] + 1].second,
            section_test(model.bodies[b].fills[k - 1].removed, model.twist, material_id));
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

bool moves_nodes(const PlanarModel& model)
{
  return static_cast<bool>(model.node_offset) || !model.twist.empty();
}

// The path and the lead modifications: every node of each volume moved in-plane, first by
// model.node_offset (lead modifications, defined on the untwisted section), then turned about its
// body's axis by the twist at its z. The bodies are disjoint, but a body and its fills share the
// nodes of their common surfaces: each node moves once.
void move_nodes(const PlanarModel& model, const GmshEntities& entities)
{
  std::unordered_set<std::size_t> moved;
  for (const auto& [volume, material_id] : entities.volumes)
  {
    std::vector<std::size_t> tags;
    std::vector<double> coordinates, parametric;
    gmsh::model::mesh::getNodes(tags, coordinates, parametric, 3, volume, true, false);
    const auto twist = model.twist.find(material_id);
    for (std::size_t i = 0; i < tags.size(); ++i)
    {
      if (!moved.insert(tags[i]).second)
        continue;
      const Eigen::Vector3d x(coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]);
      Eigen::Vector2d y = x.head<2>();
      if (model.node_offset)
        y += model.node_offset(material_id, x);
      if (twist != model.twist.end())
        y = twist->second.turned(y, x.z());
      if (y.x() != x.x() || y.y() != x.y())
        gmsh::model::mesh::setNode(tags[i], {y.x(), y.y(), x.z()}, {});
    }
  }
}

namespace
{
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
} // namespace

// 3D: the hexahedra of each fill whose centre lies in its fault left out, with the faces of its
// own boundary surfaces (end faces, the closing pieces' lateral surfaces) on them; the rest
// stays the body's material. Returns the number of hexahedra left out of each material.
std::map<int, unsigned long> remove_fill_cells(const GmshEntities& entities)
{
  static constexpr unsigned int hex_faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                   {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  const auto nodes = node_coordinates();
  const std::map<int, int> material_of(entities.volumes.begin(), entities.volumes.end());
  std::map<int, unsigned long> removed_count;
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
    removed_count[material_of.at(volume)] += hex_tags.size() - kept_tags.size();
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
} // namespace detail
} // namespace gearstiff::geometry
