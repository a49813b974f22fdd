#include "fem/mesh.h"

#include "errors/errors.h"
#include "fem/cell_shape.h"
#include "fem/parallel.h"

#include <cmath>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <sstream>

namespace gearstiff::fem
{
using namespace dealii;

namespace
{
// $PhysicalNames is plain text in both ASCII and binary .msh files.
PhysicalNames read_physical_names(const std::string& file_name, int dim)
{
  PhysicalNames names;
  std::ifstream in(file_name, std::ios::binary);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("$PhysicalNames", 0) == 0)
    {
      std::getline(in, line);
      const int count = std::stoi(line);
      for (int k = 0; k < count && std::getline(in, line); ++k)
      {
        std::istringstream entry(line);
        int group_dim = 0, tag = 0;
        entry >> group_dim >> tag;
        std::string name;
        std::getline(entry, name);
        const auto first = name.find('"'), last = name.rfind('"');
        if (first != std::string::npos && last > first)
          name = name.substr(first + 1, last - first - 1);
        if (group_dim == dim)
          names.cells[name] = tag;
        else if (group_dim == dim - 1)
          names.faces[name] = tag;
      }
      break;
    }
  return names;
}
} // namespace

template <int dim>
PhysicalNames read_msh(const std::string& file_name, double scale, Triangulation<dim>& tria,
                       const std::string& parameter)
{
  interruption_point(); // between meshing and assembly: another rank of a sweep may have failed
  if (!std::filesystem::is_regular_file(file_name))
    throw InputError(parameter, std::filesystem::is_directory(file_name)
                                    ? "'" + file_name + "' is a folder, not a mesh file"
                                    : "mesh file '" + file_name + "' does not exist");
  // A gmsh geometry script is the usual slip for its mesh.
  if (std::filesystem::path(file_name).extension() == ".geo")
    throw InputError(parameter, "'" + file_name +
                                    "' is a gmsh geometry script, not a mesh: mesh it "
                                    "first (gmsh -" +
                                    std::to_string(dim) + " " + file_name +
                                    ", quadrilaterals recombined) and give the .msh");
  Triangulation<dim> serial;
  try
  {
    GridIn<dim> grid_in(serial);
    std::ifstream in(file_name);
    grid_in.read_msh(in);
  }
  catch (const ExceptionBase& e)
  {
    std::ostringstream message;
    e.print_info(message);
    std::string text = message.str();
    for (auto& c : text)
      if (c == '\n')
        c = ' ';
    // deal.II names an element it does not read by gmsh's type number: say what it is. The
    // common case is a second-order mesh (gmsh -order 2), whose degree gearstiff sets itself.
    const std::smatch found = [&]
    {
      std::smatch match;
      std::regex_search(text, match, std::regex("Element Identifier <([0-9]+)> is not supported"));
      return match;
    }();
    if (!found.empty())
    {
      const int type = std::stoi(found[1].str());
      const std::map<int, std::string> second_order{
          {8, "3-node line"},          {9, "6-node triangle"},     {10, "9-node quadrilateral"},
          {11, "10-node tetrahedron"}, {12, "27-node hexahedron"}, {16, "8-node quadrilateral"},
          {17, "20-node hexahedron"}};
      // A volume element in a 2D read: the file is a 3D mesh (gmsh 4 tetrahedron, 5 hexahedron,
      // 6 prism, 7 pyramid).
      if (dim == 2 && type >= 4 && type <= 7)
        throw InputError(parameter, "'" + file_name + "' holds a 3D mesh (gmsh element type " +
                                        std::to_string(type) +
                                        "), read as 2D: set the mesh dimension to 3 (contact: "
                                        "Mesh/Dimension)");
      if (const auto element = second_order.find(type); element != second_order.end())
        throw InputError(parameter, "'" + file_name + "' has second-order elements (gmsh type " +
                                        std::to_string(type) + ", " + element->second +
                                        "): the mesh is read with first-order " +
                                        (dim == 2 ? "quadrilaterals" : "hexahedra") +
                                        " only (mesh it with order 1; the finite elements' "
                                        "degree is Finite elements/Element degree)");
    }
    // A 2D mesh read as 3D: deal.II finds faces but no cells.
    if (dim == 3 && text.find("did not find any cells") != std::string::npos &&
        std::regex_search(text, std::regex("did find [0-9]+ lines and [1-9][0-9]* facets")))
      throw InputError(parameter, "'" + file_name +
                                      "' holds no volume cells, only lines and "
                                      "faces: a 2D mesh read as 3D? (contact: "
                                      "Mesh/Dimension = 2)");
    throw InputError(parameter, "cannot read '" + file_name + "' as a " + std::to_string(dim) +
                                    "D quadrilateral/hexahedral gmsh mesh: " + text);
  }
  // A NaN or inf coordinate was reported as an overlap or blamed on the length unit.
  for (unsigned int v = 0; v < serial.n_vertices(); ++v)
    for (unsigned int c = 0; c < dim; ++c)
      if (!std::isfinite(serial.get_vertices()[v][c]))
        throw InputError(parameter, "'" + file_name + "': a node (vertex " + std::to_string(v) +
                                        ") has a coordinate that is not a finite number");
  // FE_Q needs quadrilaterals/hexahedra: gmsh meshes triangles and tetrahedra unless told to
  // recombine, and deal.II reads them; the system's set-up refused them later naming "mesh".
  unsigned int simplices = 0;
  types::material_id first_tag = 0;
  for (const auto& cell : serial.active_cell_iterators())
    if (!cell->reference_cell().is_hyper_cube() && simplices++ == 0)
      first_tag = cell->material_id();
  if (simplices > 0)
    throw InputError(parameter,
                     "'" + file_name + "' has " + std::to_string(simplices) + " of " +
                         std::to_string(serial.n_active_cells()) + " cells that are not " +
                         (dim == 2 ? "quadrilaterals" : "hexahedra") +
                         " (the first in physical tag " + std::to_string(first_tag) +
                         "): the elements need " +
                         (dim == 2 ? "quadrilaterals (gmsh: Recombine Surface, or -2 with "
                                     "Mesh.RecombineAll = 1)"
                                   : "hexahedra (gmsh: extruded or transfinite recombined "
                                     "volumes)"));
  // deal.II accepts a cell of zero area (collapsed or bow-tie corners); its assembly then fails
  // the factorization as a "solver failure" for what is a fault of the file.
  const std::vector<unsigned int> order = cyclic_corner_order(dim);
  std::vector<Eigen::Vector3d> corners(order.size());
  for (const auto& cell : serial.active_cell_iterators())
  {
    corners.clear();
    for (const unsigned int v : order)
    {
      Eigen::Vector3d x = Eigen::Vector3d::Zero();
      for (unsigned int c = 0; c < dim; ++c)
        x[c] = cell->vertex(v)[c];
      corners.push_back(x);
    }
    if (!corners_span_a_cell<dim>(corners))
      throw InputError(parameter, "'" + file_name + "': cell " +
                                      std::to_string(cell->active_cell_index()) +
                                      " (physical tag " + std::to_string(cell->material_id()) +
                                      ") is degenerate or twisted (its corners do not span a "
                                      "cell of positive size)");
  }
  GridTools::scale(scale, serial);
  join_bodies<dim>({&serial}, tria);
  return read_physical_names(file_name, dim);
}

namespace
{
// Appends the coarse cells of `part` whose material `keep` accepts, with their boundary faces'
// ids, their vertex indices shifted by `offset`.
template <int dim>
void append_cells(const Triangulation<dim>& part, unsigned int offset,
                  const std::function<bool(types::material_id)>& keep,
                  std::vector<CellData<dim>>& cells, SubCellData& faces)
{
  for (const auto& cell : part.active_cell_iterators())
  {
    if (!keep(cell->material_id()))
      continue;
    CellData<dim> data(cell->n_vertices());
    for (unsigned int v = 0; v < cell->n_vertices(); ++v)
      data.vertices[v] = cell->vertex_index(v) + offset;
    data.material_id = cell->material_id();
    cells.push_back(data);
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() != 0)
      {
        CellData<dim - 1> face(cell->face(f)->n_vertices());
        for (unsigned int v = 0; v < face.vertices.size(); ++v)
          face.vertices[v] = cell->face(f)->vertex_index(v) + offset;
        face.boundary_id = cell->face(f)->boundary_id();
        if constexpr (dim == 2)
          faces.boundary_lines.push_back(face);
        else
          faces.boundary_quads.push_back(face);
      }
  }
}
} // namespace

template <int dim>
void join_bodies(const std::vector<const Triangulation<dim>*>& parts, Triangulation<dim>& result)
{
  std::vector<Point<dim>> vertices;
  std::vector<CellData<dim>> cells;
  SubCellData faces;
  for (const auto* part : parts)
  {
    const unsigned int offset = vertices.size();
    vertices.insert(vertices.end(), part->get_vertices().begin(), part->get_vertices().end());
    append_cells<dim>(
        *part, offset, [](types::material_id) { return true; }, cells, faces);
  }
  // Vertices are never merged: coincident ones belong to different bodies.
  result.create_triangulation(vertices, cells, faces);
}

template <int dim>
void one_body(const Triangulation<dim>& scene, types::material_id body, Triangulation<dim>& result)
{
  std::vector<Point<dim>> vertices = scene.get_vertices();
  std::vector<CellData<dim>> cells;
  SubCellData faces;
  append_cells<dim>(
      scene, 0, [body](types::material_id id) { return id == body; }, cells, faces);
  GridTools::delete_unused_vertices(vertices, cells, faces);
  result.create_triangulation(vertices, cells, faces);
}

template PhysicalNames read_msh(const std::string&, double, Triangulation<2>&, const std::string&);
template PhysicalNames read_msh(const std::string&, double, Triangulation<3>&, const std::string&);
template void join_bodies(const std::vector<const Triangulation<2>*>&, Triangulation<2>&);
template void one_body(const Triangulation<2>&, types::material_id, Triangulation<2>&);
template void one_body(const Triangulation<3>&, types::material_id, Triangulation<3>&);
template void join_bodies(const std::vector<const Triangulation<3>*>&, Triangulation<3>&);
} // namespace gearstiff::fem
