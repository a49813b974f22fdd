// 2D: a root crack whose faces meet (PlanarFill::crack_id): its gmsh entities and the split of
// the mesh along it.
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
#include <gmsh.h>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>

namespace gearstiff::geometry
{
namespace detail
{
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

namespace
{
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
} // namespace

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
} // namespace detail
} // namespace gearstiff::geometry
