// Cell quality: scaled Jacobians and the check every generated mesh passes.
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

namespace detail
{
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

// gmsh can give up on one body's surface and still write the others (an 800 µm tip relief
// left the pinion's tip 116 µm wide): the file then references nodes it never wrote, which
// only deal.II's reader noticed. Refused here, and retried finer like leftover triangles.
void check_every_body_meshed(const std::vector<std::pair<int, int>>& entities,
                             MeshStatistics& statistics)
{
  for (const auto& [entity, material_id] : entities)
    if (statistics.cells_per_body[material_id] == 0)
      throw SolverFailure("gmsh quadrilateral meshing",
                          "no cells in the body with material id " + std::to_string(material_id));
}

// A cell type other than the quadrilateral (hexahedron) gmsh was asked for: what recombination
// left over, refused by its name.
[[noreturn]] void refuse_leftover_cells(int type, std::size_t count, int material_id)
{
  std::string type_name;
  int type_dim, order, n_nodes, n_primary;
  std::vector<double> local;
  gmsh::model::mesh::getElementProperties(type, type_name, type_dim, order, n_nodes, local,
                                          n_primary);
  throw SolverFailure("gmsh quadrilateral meshing",
                      std::to_string(count) + " leftover " + type_name +
                          " cells in body with material id " + std::to_string(material_id));
}

// One cell's scaled Jacobian (the worst one's centre kept) and, for a cell at a contact focus,
// its edges against the focus size. `in_model` turns a corner back into the transverse model.
template <typename InModel>
void measure_cell(const std::vector<Eigen::Vector3d>& corners, const SizeGrading& grading,
                  const InModel& in_model, double& jacobian_sum, MeshStatistics& statistics)
{
  const double q =
      corners.size() == 4 ? scaled_jacobian_quad(corners) : scaled_jacobian_hex(corners);
  if (q < statistics.min_scaled_jacobian)
  {
    statistics.min_scaled_jacobian = q;
    statistics.worst_cell_centre = Eigen::Vector3d::Zero();
    for (const auto& corner : corners)
      statistics.worst_cell_centre += corner / static_cast<double>(corners.size());
  }
  jacobian_sum += q;
  for (const auto& focus : grading.foci)
  {
    bool at_focus = false;
    for (unsigned int c = 0; c < 4; ++c)
      at_focus |= (in_model(corners[c]) - focus.point).norm() <= focus.size;
    if (at_focus)
      for (unsigned int c = 0; c < 4; ++c)
        statistics.largest_edge_ratio_at_focus =
            std::max(statistics.largest_edge_ratio_at_focus,
                     (corners[(c + 1) % 4] - corners[c]).norm() / focus.size);
  }
}

// Every cell must be a quadrilateral (hexahedron) with positive scaled Jacobian: deal.II's
// parallel::distributed::Triangulation accepts nothing else, and an inverted cell would
// silently corrupt every stiffness computed on the mesh. Fills the cell counts and quality.
void check_cells(const MeshOptions& options, const SizeGrading& grading,
                 const std::vector<std::pair<int, int>>& surfaces,
                 const std::vector<std::pair<int, int>>& volumes,
                 const std::map<int, BodyTwist>& twist, MeshStatistics& statistics)
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
    // The foci lie in the transverse model: a twisted body's corners are turned back first.
    const auto body_twist = twist.find(material_id);
    const auto in_model = [&](const Eigen::Vector3d& x) -> Eigen::Vector2d
    {
      if (body_twist == twist.end())
        return x.head<2>();
      return body_twist->second.untwisted(x.head<2>(), x.z());
    };
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, element_nodes;
    gmsh::model::mesh::getElements(types, element_tags, element_nodes, dim, entity);
    for (std::size_t t = 0; t < types.size(); ++t)
    {
      if (types[t] != cell_type)
        refuse_leftover_cells(types[t], element_tags[t].size(), material_id);
      std::vector<Eigen::Vector3d> corners(n_corners);
      for (std::size_t e = 0; e < element_tags[t].size(); ++e)
      {
        for (unsigned int c = 0; c < n_corners; ++c)
          corners[c] = nodes.at(element_nodes[t][n_corners * e + c]);
        measure_cell(corners, grading, in_model, jacobian_sum, statistics);
      }
      statistics.cells_per_body[material_id] += element_tags[t].size();
      statistics.n_cells += element_tags[t].size();
    }
  }
  if (statistics.n_cells == 0)
    throw SolverFailure("gmsh mesh generation", "produced no cells");
  check_every_body_meshed(entities, statistics);
  statistics.mean_scaled_jacobian = jacobian_sum / statistics.n_cells;
  if (!(statistics.min_scaled_jacobian > 0.))
    throw SolverFailure("gmsh mesh generation",
                        "inverted or degenerate cell (minimum scaled Jacobian " +
                            std::to_string(statistics.min_scaled_jacobian) + ")");
}
} // namespace detail
} // namespace gearstiff::geometry
