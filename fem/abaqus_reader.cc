#include "fem/abaqus_reader.h"

#include "errors/errors.h"
#include "errors/limits.h"
#include "fem/cell_shape.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <deal.II/grid/grid_tools.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace gearstiff::fem
{
using namespace dealii;

namespace
{
// *INCLUDE chains deeper than this are taken for a cycle; more expansions than this in one deck
// could not finish (errors/limits.h).
constexpr unsigned int max_include_depth = limits::max_deck_include_depth;
constexpr unsigned int max_includes = limits::max_deck_includes;

// One logical line of the deck (continuation lines joined), with where it came from.
struct DeckLine
{
  std::string text;
  std::string file;
  unsigned int number = 0; // 1-based line number in `file`
  std::string where() const { return file + ":" + std::to_string(number); }
};

std::string upper(std::string text)
{
  for (auto& c : text)
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

std::string trim(const std::string& text)
{
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos)
    return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> fields(const std::string& text)
{
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, ','))
    parts.push_back(trim(part));
  if (!parts.empty() && parts.back().empty())
    parts.pop_back();
  return parts;
}

bool is_keyword(const std::string& text)
{
  return text.size() > 1 && text[0] == '*' && text[1] != '*';
}

// A keyword line: its name ("ELEMENT") and its parameters (upper-case keys; values as written).
struct Keyword
{
  std::string name;
  std::map<std::string, std::string> parameters;
  DeckLine line;

  std::string describe() const { return line.where() + ": *" + name; }
  std::string get(const std::string& key) const
  {
    const auto found = parameters.find(key);
    return found == parameters.end() ? "" : found->second;
  }
};

Keyword parse_keyword(const DeckLine& line)
{
  Keyword keyword;
  keyword.line = line;
  const auto parts = fields(line.text.substr(1));
  keyword.name = parts.empty() ? "" : upper(parts[0]);
  for (std::size_t i = 1; i < parts.size(); ++i)
  {
    const auto equals = parts[i].find('=');
    if (equals == std::string::npos)
      keyword.parameters[upper(parts[i])] = "";
    else
      keyword.parameters[upper(trim(parts[i].substr(0, equals)))] =
          trim(parts[i].substr(equals + 1));
  }
  return keyword;
}

// The deck's lines with *INCLUDEs expanded, comments and blank lines dropped, and data lines that
// end in a comma joined with the next one.
void read_lines(const std::string& file, const std::string& parameter, unsigned int depth,
                std::vector<DeckLine>& lines, unsigned int& includes)
{
  std::ifstream in(file);
  std::string text;
  unsigned int number = 0;
  bool continued = false;
  while (std::getline(in, text))
  {
    ++number;
    text = trim(text);
    if (text.empty() || text.rfind("**", 0) == 0)
      continue;
    if (continued && !is_keyword(text))
      lines.back().text += " " + text;
    else
    {
      const DeckLine line{text, file, number};
      if (is_keyword(text) && upper(parse_keyword(line).name) == "INCLUDE")
      {
        const Keyword include = parse_keyword(line);
        std::filesystem::path target = include.get("INPUT");
        if (target.is_relative())
          target = std::filesystem::path(file).parent_path() / target;
        if (include.get("INPUT").empty() || !std::filesystem::is_regular_file(target))
          throw InputError(parameter, include.describe() + ": cannot open INPUT='" +
                                          include.get("INPUT") + "'");
        if (depth >= max_include_depth)
          throw InputError(parameter, include.describe() + ": nested more than " +
                                          std::to_string(max_include_depth) + " deep (a cycle?)");
        // The fan-out, not only the depth: 10 includes per level over 8 levels are 10⁸ files.
        if (++includes > max_includes)
          throw InputError(parameter, include.describe() + ": the deck expands to more than " +
                                          std::to_string(max_includes) +
                                          " included files (limit, docs/limits.md); a deck "
                                          "includes a handful");
        read_lines(target.string(), parameter, depth + 1, lines, includes);
        continued = false;
        continue;
      }
      lines.push_back(line);
    }
    continued = !is_keyword(text) && lines.back().text.back() == ',';
  }
}

long to_integer(const std::string& text, const Keyword& keyword, const DeckLine& line,
                const std::string& parameter)
{
  try
  {
    std::size_t used = 0;
    const long value = std::stol(text, &used);
    if (used == text.size())
      return value;
  }
  catch (const std::exception&)
  {
  }
  throw InputError(parameter,
                   line.where() + ": *" + keyword.name + ": '" + text + "' is not an integer");
}

double to_double(const std::string& text, const Keyword& keyword, const DeckLine& line,
                 const std::string& parameter)
{
  try
  {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size())
      return value;
  }
  catch (const std::exception&)
  {
  }
  throw InputError(parameter,
                   line.where() + ": *" + keyword.name + ": '" + text + "' is not a number");
}

// Corner counts and dimension of the element types read.
struct ElementType
{
  unsigned int dim;
  unsigned int n_nodes;
};

const std::map<std::string, ElementType>& element_types()
{
  static const std::map<std::string, ElementType> types = {
      {"CPE4", {2, 4}}, {"CPE4R", {2, 4}}, {"CPS4", {2, 4}}, {"CPS4R", {2, 4}},
      {"C3D8", {3, 8}}, {"C3D8R", {3, 8}}, {"C3D8I", {3, 8}}};
  return types;
}

// Abaqus faces as corner positions: 2D S1 = 1-2 ... S4 = 4-1; C3D8 S1 = 1-2-3-4, S2 = 5-8-7-6,
// S3 = 1-5-6-2, S4 = 2-6-7-3, S5 = 3-7-8-4, S6 = 4-8-5-1.
const std::vector<std::vector<unsigned int>>& element_faces(unsigned int dim)
{
  static const std::vector<std::vector<unsigned int>> quad = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  static const std::vector<std::vector<unsigned int>> hex = {
      {0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};
  return dim == 2 ? quad : hex;
}

struct Element
{
  std::vector<long> nodes;
  DeckLine line;
};

// A named group in the order it first appears; members resolved when the deck is complete.
struct Group
{
  std::string name;
  std::vector<long> elements;                       // element sets
  std::vector<std::pair<long, unsigned int>> faces; // surfaces: element, 0-based face
  // What is listed already: a member listed again is not stored again, so a group never holds
  // more than the deck's elements (faces) however often a line repeats a set.
  std::set<long> listed_elements;
  std::set<std::pair<long, unsigned int>> listed_faces;

  void add_element(long id)
  {
    if (listed_elements.insert(id).second)
      elements.push_back(id);
  }
  void add_face(long id, unsigned int face)
  {
    if (listed_faces.emplace(id, face).second)
      faces.emplace_back(id, face);
  }
};

// Everything the reader keeps of a deck.
struct Deck
{
  std::map<long, std::array<double, 3>> nodes;
  std::map<long, Element> elements;
  std::vector<Group> element_sets, surfaces;
  std::map<std::string, std::size_t> element_set_index, surface_index; // upper-case name

  Group& group(std::vector<Group>& groups, std::map<std::string, std::size_t>& index,
               const std::string& name)
  {
    const auto [found, added] = index.emplace(upper(name), groups.size());
    if (added)
      groups.push_back({name, {}, {}, {}, {}});
    return groups[found->second];
  }
  const Group* element_set(const std::string& name) const
  {
    const auto found = element_set_index.find(upper(name));
    return found == element_set_index.end() ? nullptr : &element_sets[found->second];
  }
};

template <int dim>
class DeckParser
{
public:
  DeckParser(const std::string& parameter, double scale) : parameter(parameter), scale(scale) {}

  Deck parse(const std::vector<DeckLine>& lines)
  {
    Keyword keyword;
    for (const auto& line : lines)
      if (is_keyword(line.text))
        keyword = start(parse_keyword(line));
      else if (keyword.name == "NODE")
        node(keyword, line);
      else if (keyword.name == "ELEMENT")
        element(keyword, line);
      else if (keyword.name == "ELSET")
        element_set(keyword, line);
      else if (keyword.name == "SURFACE")
        surface(keyword, line);
    return std::move(deck);
  }

private:
  [[noreturn]] void fail(const Keyword& keyword, const DeckLine& line,
                         const std::string& reason) const
  {
    throw InputError(parameter, line.where() + ": *" + keyword.name + ": " + reason);
  }

  // Checks the keyword's parameters; a keyword whose data this reader skips becomes "".
  Keyword start(Keyword keyword)
  {
    if (keyword.name == "ELEMENT")
    {
      const std::string type = upper(keyword.get("TYPE"));
      const auto found = element_types().find(type);
      if (found == element_types().end())
        fail(keyword, keyword.line,
             "TYPE=" + type + " is not supported (CPE4, CPE4R, CPS4, CPS4R, C3D8, C3D8R, C3D8I)");
      if (found->second.dim != dim)
        fail(keyword, keyword.line,
             "TYPE=" + type + " is a " + std::to_string(found->second.dim) +
                 "D element; the mesh is read as " + std::to_string(dim) + "D (Mesh/Dimension)");
      element_nodes = found->second.n_nodes;
      if (!keyword.get("ELSET").empty())
        deck.group(deck.element_sets, deck.element_set_index, keyword.get("ELSET"));
    }
    else if (keyword.name == "ELSET")
    {
      if (keyword.get("ELSET").empty())
        fail(keyword, keyword.line, "the ELSET= parameter is missing");
      deck.group(deck.element_sets, deck.element_set_index, keyword.get("ELSET"));
    }
    else if (keyword.name == "SURFACE")
    {
      const std::string type = upper(keyword.get("TYPE"));
      if (!type.empty() && type != "ELEMENT")
        return Keyword(); // node-based surfaces are no face groups
      if (keyword.get("NAME").empty())
        fail(keyword, keyword.line, "the NAME= parameter is missing");
      deck.group(deck.surfaces, deck.surface_index, keyword.get("NAME"));
    }
    else if (keyword.name != "NODE")
      return Keyword();
    return keyword;
  }

  void node(const Keyword& keyword, const DeckLine& line)
  {
    const auto parts = fields(line.text);
    if (parts.size() < 1 + dim)
      fail(keyword, line, "a node needs an id and " + std::to_string(dim) + " coordinates");
    std::array<double, 3> x{};
    for (unsigned int c = 0; c < dim; ++c)
    {
      x[c] = to_double(parts[1 + c], keyword, line, parameter);
      if (!std::isfinite(x[c]))
        fail(keyword, line, "coordinate '" + parts[1 + c] + "' is not a finite number");
      if (!(std::abs(x[c] * scale) <= limits::max_deck_coordinate))
        fail(keyword, line,
             "coordinate " + parts[1 + c] + " lies beyond " +
                 std::to_string(int(limits::max_deck_coordinate)) +
                 " m after Mesh/Length unit (no gear drive; check the length unit)");
    }
    const long id = to_integer(parts[0], keyword, line, parameter);
    const auto [found, added] = node_lines.emplace(id, line);
    if (!added)
      fail(keyword, line,
           "node " + std::to_string(id) + " is defined twice (first at " + found->second.where() +
               ")");
    deck.nodes[id] = x;
  }

  void element(const Keyword& keyword, const DeckLine& line)
  {
    const auto parts = fields(line.text);
    if (parts.size() != 1 + element_nodes)
      fail(keyword, line,
           "TYPE=" + upper(keyword.get("TYPE")) + " needs an id and " +
               std::to_string(element_nodes) + " nodes, the line has " +
               std::to_string(parts.size()) + " entries");
    Element element;
    element.line = line;
    for (unsigned int n = 0; n < element_nodes; ++n)
      element.nodes.push_back(to_integer(parts[1 + n], keyword, line, parameter));
    const long id = to_integer(parts[0], keyword, line, parameter);
    const auto [found, added] = deck.elements.emplace(id, element);
    if (!added)
      fail(keyword, line,
           "element " + std::to_string(id) + " is defined twice (first at " +
               found->second.line.where() + ")");
    for (unsigned int a = 0; a < element_nodes; ++a)
      for (unsigned int b = a + 1; b < element_nodes; ++b)
        if (element.nodes[a] == element.nodes[b])
          fail(keyword, line,
               "element " + std::to_string(id) + " lists node " + std::to_string(element.nodes[a]) +
                   " twice (a degenerate element)");
    if (double(deck.elements.size()) > limits::max_deck_elements)
      fail(keyword, line,
           "the deck defines more than " + std::to_string(long(limits::max_deck_elements)) +
               " elements, more than a contact solve can hold (limit, docs/limits.md)");
    if (!keyword.get("ELSET").empty())
      deck.group(deck.element_sets, deck.element_set_index, keyword.get("ELSET")).add_element(id);
  }

  void element_set(const Keyword& keyword, const DeckLine& line)
  {
    const auto parts = fields(line.text);
    std::vector<long> members;
    if (keyword.parameters.count("GENERATE"))
    {
      if (parts.size() < 2 || parts.size() > 3)
        fail(keyword, line, "GENERATE needs 'first, last[, step]'");
      const long first = to_integer(parts[0], keyword, line, parameter);
      const long last = to_integer(parts[1], keyword, line, parameter);
      const long step = parts.size() == 3 ? to_integer(parts[2], keyword, line, parameter) : 1;
      if (step < 1 || last < first)
        fail(keyword, line, "GENERATE needs first <= last and a positive step");
      // The count before a member is stored (4·10¹⁸ ids were asked for), without overflow:
      // every member must be an element the deck defines.
      const unsigned long count =
          (static_cast<unsigned long>(last) - static_cast<unsigned long>(first)) /
              static_cast<unsigned long>(step) +
          1;
      if (count > deck.elements.size())
        fail(keyword, line,
             "GENERATE " + parts[0] + ", " + parts[1] + (parts.size() == 3 ? ", " + parts[2] : "") +
                 " lists " + std::to_string(count) + " elements, the deck defines " +
                 std::to_string(deck.elements.size()) +
                 " so far (elements are defined before "
                 "the sets that list them)");
      for (unsigned long k = 0; k < count; ++k)
        members.push_back(first + static_cast<long>(k * static_cast<unsigned long>(step)));
    }
    std::set<std::string> sets_listed;
    if (!keyword.parameters.count("GENERATE"))
      for (const auto& part : parts)
      {
        if (!part.empty() && (std::isdigit(static_cast<unsigned char>(part[0])) || part[0] == '-'))
          members.push_back(to_integer(part, keyword, line, parameter));
        else if (const Group* set = deck.element_set(part))
        {
          // A set named again on the line adds nothing (a line of 10⁵ names of one set).
          if (sets_listed.insert(upper(part)).second)
            members.insert(members.end(), set->elements.begin(), set->elements.end());
        }
        else
          fail(keyword, line, "element set '" + part + "' is not defined");
      }
    for (const long id : members)
      if (deck.elements.count(id) == 0)
        fail(keyword, line, "element " + std::to_string(id) + " is not defined");
    auto& group = deck.group(deck.element_sets, deck.element_set_index, keyword.get("ELSET"));
    for (const long id : members)
      group.add_element(id);
  }

  void surface(const Keyword& keyword, const DeckLine& line)
  {
    const auto parts = fields(line.text);
    const std::string label = parts.size() == 2 ? upper(parts[1]) : "";
    const unsigned int n_faces = element_faces(dim).size();
    unsigned int face = 0;
    if (label.size() == 2 && label[0] == 'S' && label[1] >= '1' && label[1] < char('1' + n_faces))
      face = label[1] - '1';
    else
      fail(keyword, line,
           "expected 'element or element set, S1..S" + std::to_string(n_faces) + "'");
    if (parts[0].empty())
      fail(keyword, line, "the element or element set is missing");
    std::vector<long> members;
    if (std::isdigit(static_cast<unsigned char>(parts[0][0])))
      members.push_back(to_integer(parts[0], keyword, line, parameter));
    else if (const Group* set = deck.element_set(parts[0]))
      members = set->elements;
    else
      fail(keyword, line, "element set '" + parts[0] + "' is not defined");
    auto& group = deck.group(deck.surfaces, deck.surface_index, keyword.get("NAME"));
    for (const long id : members)
    {
      if (deck.elements.count(id) == 0)
        fail(keyword, line, "element " + std::to_string(id) + " is not defined");
      group.add_face(id, face);
    }
  }

  std::string parameter;
  double scale; // m per deck length unit (Mesh/Length unit)
  unsigned int element_nodes = 0;
  Deck deck;
  std::map<long, DeckLine> node_lines; // where each node was defined
};

// Each element's material id: its first element set's number (1-based), 0 for none; the sets'
// names go into `names`.
std::map<long, types::material_id> element_materials(const Deck& deck, PhysicalNames& names)
{
  std::map<long, types::material_id> material;
  for (std::size_t s = deck.element_sets.size(); s-- > 0;) // the first set listing a cell wins
    for (const long id : deck.element_sets[s].elements)
      material[id] = static_cast<types::material_id>(s + 1);
  for (std::size_t s = 0; s < deck.element_sets.size(); ++s)
    names.cells[group_name_from_abaqus(deck.element_sets[s].name)] = s + 1;
  return material;
}

// The deck's nodes and elements as deal.II vertices (m) and cells.
template <int dim>
struct DeckCells
{
  std::map<long, unsigned int> vertex_of_node;
  std::vector<Point<dim>> vertices;
  std::vector<CellData<dim>> cells;
};

template <int dim>
DeckCells<dim> deck_cells(const Deck& deck, const double scale, const std::string& parameter,
                          const std::map<long, types::material_id>& material)
{
  DeckCells<dim> result;
  const auto order = cyclic_corner_order(dim);
  const auto vertex = [&](long node, const Element& element)
  {
    const auto [found, added] = result.vertex_of_node.emplace(node, result.vertices.size());
    if (added)
    {
      const auto x = deck.nodes.find(node);
      if (x == deck.nodes.end())
        throw InputError(parameter, element.line.where() + ": *ELEMENT: node " +
                                        std::to_string(node) + " is not defined");
      Point<dim> p;
      for (unsigned int c = 0; c < dim; ++c)
        p[c] = scale * x->second[c];
      result.vertices.push_back(p);
    }
    return found->second;
  };
  for (const auto& [id, element] : deck.elements)
  {
    CellData<dim> cell(order.size());
    for (unsigned int v = 0; v < order.size(); ++v)
      cell.vertices[v] = vertex(element.nodes[order[v]], element);
    const auto found = material.find(id);
    cell.material_id = found == material.end() ? 0 : found->second;
    result.cells.push_back(cell);
  }
  return result;
}

// The deck's surfaces as boundary faces, boundary id = the surface's number (1-based); their
// names go into `names`.
template <int dim>
SubCellData surface_faces(const Deck& deck, const std::map<long, unsigned int>& vertex_of_node,
                          PhysicalNames& names)
{
  SubCellData faces;
  for (std::size_t s = 0; s < deck.surfaces.size(); ++s)
  {
    names.faces[group_name_from_abaqus(deck.surfaces[s].name)] = s + 1;
    for (const auto& [id, face] : deck.surfaces[s].faces)
    {
      const Element& element = deck.elements.at(id);
      const auto& corners = element_faces(dim)[face];
      CellData<dim - 1> data(corners.size());
      for (unsigned int v = 0; v < corners.size(); ++v)
        data.vertices[v] = vertex_of_node.at(element.nodes[corners[v]]);
      if constexpr (dim == 3)
        std::swap(data.vertices[2], data.vertices[3]); // face corners in lexicographic order
      data.boundary_id = static_cast<types::boundary_id>(s + 1);
      if constexpr (dim == 2)
        faces.boundary_lines.push_back(data);
      else
        faces.boundary_quads.push_back(data);
    }
  }
  return faces;
}

// Faces of a surface must lie on the boundary: a face two elements share is interior.
template <int dim>
void check_surfaces_on_boundary(const Deck& deck, const DeckCells<dim>& mesh,
                                const std::string& parameter)
{
  const auto order = cyclic_corner_order(dim);
  std::map<std::vector<unsigned int>, unsigned int> face_uses; // sorted vertices -> elements
  for (const auto& cell : mesh.cells)
    for (const auto& corners : element_faces(dim))
    {
      std::vector<unsigned int> key;
      for (const unsigned int c : corners)
        key.push_back(cell.vertices[order[c]]);
      std::sort(key.begin(), key.end());
      ++face_uses[key];
    }
  for (const auto& surface : deck.surfaces)
    for (const auto& [id, face] : surface.faces)
    {
      const Element& element = deck.elements.at(id);
      std::vector<unsigned int> key;
      for (const unsigned int c : element_faces(dim)[face])
        key.push_back(mesh.vertex_of_node.at(element.nodes[c]));
      std::sort(key.begin(), key.end());
      if (face_uses[key] > 1)
        throw InputError(parameter, "*SURFACE NAME=" + surface.name + ": face S" +
                                        std::to_string(face + 1) + " of element " +
                                        std::to_string(id) +
                                        " is shared by two elements (an interior face; a "
                                        "surface lies on the boundary)");
    }
}

// Each element's corners must span a cell: the Jacobian at every corner non-zero and of one
// sign (a degenerate element made the factorization fail with "PETSc error code 81").
template <int dim>
void check_element_shapes(const Deck& deck, const std::string& parameter)
{
  for (const auto& [id, element] : deck.elements)
  {
    std::vector<Eigen::Vector3d> corners;
    for (const long node : element.nodes)
    {
      const auto& x = deck.nodes.at(node);
      corners.emplace_back(x[0], x[1], x[2]);
    }
    if (!corners_span_a_cell<dim>(corners))
      throw InputError(parameter,
                       element.line.where() + ": *ELEMENT: element " + std::to_string(id) +
                           " is degenerate or twisted (its corners, in the Abaqus order, do not "
                           "span a cell of positive size)");
  }
}

template <int dim>
void build_triangulation(const Deck& deck, const double scale, Triangulation<dim>& tria,
                         const std::string& parameter, PhysicalNames& names)
{
  DeckCells<dim> mesh = deck_cells<dim>(deck, scale, parameter, element_materials(deck, names));
  const SubCellData faces = surface_faces<dim>(deck, mesh.vertex_of_node, names);
  check_surfaces_on_boundary<dim>(deck, mesh, parameter);
  check_element_shapes<dim>(deck, parameter);

  GridTools::invert_all_negative_measure_cells(mesh.vertices, mesh.cells);
  GridTools::consistently_order_cells(mesh.cells);
  Triangulation<dim> serial;
  try
  {
    serial.create_triangulation(mesh.vertices, mesh.cells, faces);
  }
  catch (const ExceptionBase& e)
  {
    // What the checks above do not catch is still the deck's fault, not a failed method.
    std::ostringstream text;
    e.print_info(text);
    std::string reason = text.str();
    std::replace(reason.begin(), reason.end(), '\n', ' ');
    throw InputError(parameter, "the deck's elements do not form a valid mesh: " + reason);
  }
  join_bodies<dim>({&serial}, tria);
}
} // namespace

std::string group_name_from_abaqus(const std::string& set_name)
{
  std::string name = set_name;
  for (auto& c : name)
    c = c == '_' ? ' ' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return name;
}

template <int dim>
PhysicalNames read_abaqus(const std::string& file_name, const double scale,
                          Triangulation<dim>& tria, const std::string& parameter)
{
  if (std::filesystem::is_directory(file_name))
    throw InputError(parameter, "'" + file_name + "' is a folder, not a mesh file");
  if (!std::filesystem::is_regular_file(file_name))
    throw InputError(parameter, "mesh file '" + file_name + "' does not exist");
  std::vector<DeckLine> lines;
  unsigned int includes = 0;
  read_lines(file_name, parameter, 0, lines, includes);
  const Deck deck = DeckParser<dim>(parameter, scale).parse(lines);
  if (deck.elements.empty())
    throw InputError(parameter, file_name + ": *ELEMENT: the deck defines no elements");
  PhysicalNames names;
  build_triangulation<dim>(deck, scale, tria, parameter, names);
  return names;
}

template PhysicalNames read_abaqus(const std::string&, double, Triangulation<2>&,
                                   const std::string&);
template PhysicalNames read_abaqus(const std::string&, double, Triangulation<3>&,
                                   const std::string&);
} // namespace gearstiff::fem
