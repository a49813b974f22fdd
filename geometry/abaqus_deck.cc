#include "geometry/abaqus_deck.h"

#include "errors/errors.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <gmsh.h>
#include <iomanip>
#include <map>
#include <set>
#include <unordered_map>

namespace gearstiff::geometry
{
namespace
{
// gmsh is a process-wide singleton: one session per read, finalised even when reading throws.
class GmshReadSession
{
public:
  explicit GmshReadSession(const std::string& file)
  {
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 1);
    gmsh::open(file);
  }
  ~GmshReadSession() { gmsh::finalize(); }
  GmshReadSession(const GmshReadSession&) = delete;
  GmshReadSession& operator=(const GmshReadSession&) = delete;
};

// Elements of the entities of one physical group, as node tags, `n_nodes` per element.
std::vector<std::vector<std::size_t>> group_elements(int dim, int tag, int element_type,
                                                     unsigned int n_nodes)
{
  std::vector<std::vector<std::size_t>> elements;
  std::vector<int> entities;
  gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
  for (const int entity : entities)
  {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, dim, entity);
    for (std::size_t t = 0; t < types.size(); ++t)
    {
      if (types[t] != element_type)
        throw SolverFailure("reading the scene mesh", "physical group " + std::to_string(tag) +
                                                          " holds gmsh elements of type " +
                                                          std::to_string(types[t]) + ", expected " +
                                                          std::to_string(element_type));
      for (std::size_t e = 0; e < tags[t].size(); ++e)
        elements.emplace_back(nodes[t].begin() + n_nodes * e, nodes[t].begin() + n_nodes * (e + 1));
    }
  }
  return elements;
}

// Abaqus face numbers of a cell's facets, with their corner positions in the cell's node list.
// 2D (CPE4/CPS4): S1 = 1-2, S2 = 2-3, S3 = 3-4, S4 = 4-1. C3D8: S1 = 1-2-3-4, S2 = 5-8-7-6,
// S3 = 1-5-6-2, S4 = 2-6-7-3, S5 = 3-7-8-4, S6 = 4-8-5-1.
const std::vector<std::vector<unsigned int>>& cell_faces(unsigned int dim)
{
  static const std::vector<std::vector<unsigned int>> quad = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  static const std::vector<std::vector<unsigned int>> hex = {
      {0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};
  return dim == 2 ? quad : hex;
}

std::vector<unsigned int> sorted(std::vector<unsigned int> nodes)
{
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

// For every labelled facet: (cell index, 0-based face number in cell_faces order).
std::multimap<int, std::pair<std::size_t, unsigned int>> facet_faces(const SceneMesh& mesh)
{
  std::map<std::vector<unsigned int>, std::pair<std::size_t, unsigned int>> faces;
  const auto& local = cell_faces(mesh.dimension);
  for (std::size_t c = 0; c < mesh.cells.size(); ++c)
    for (unsigned int f = 0; f < local.size(); ++f)
    {
      std::vector<unsigned int> nodes;
      for (const unsigned int i : local[f])
        nodes.push_back(mesh.cells[c].nodes[i]);
      faces[sorted(nodes)] = {c, f};
    }
  std::multimap<int, std::pair<std::size_t, unsigned int>> result;
  for (const auto& facet : mesh.facets)
  {
    const auto found = faces.find(sorted(facet.nodes));
    if (found == faces.end())
      throw SolverFailure("writing the Abaqus deck", "a facet of boundary id " +
                                                         std::to_string(facet.boundary_id) +
                                                         " is not the face of any cell");
    result.emplace(facet.boundary_id, found->second);
  }
  return result;
}

// The deck's element layout: type, nodes per element, id of node i in the slice's top layer.
struct DeckLayout
{
  bool slice = false;
  std::string element_type;
  std::size_t top_offset = 0; // slice: top node = bottom node + offset
  // Abaqus face label of 0-based face `f` of cell_faces: the slice turns in-plane edge f into
  // the C3D8 side face S(f + 3).
  std::string face_label(unsigned int f) const
  {
    return "S" + std::to_string(slice ? f + 3 : f + 1);
  }
};

DeckLayout deck_layout(const SceneMesh& mesh, const AbaqusDeckSpec& spec)
{
  DeckLayout layout;
  if (mesh.dimension == 3)
    layout.element_type = "C3D8";
  else if (spec.element_2d == Element2D::slice)
  {
    layout.slice = true;
    layout.element_type = "C3D8";
    layout.top_offset = mesh.nodes.size();
  }
  else
    layout.element_type = spec.element_2d == Element2D::plane_strain ? "CPE4" : "CPS4";
  return layout;
}

// Data lines of at most 8 numbers (the Abaqus limit for set and node lists is 16 per line).
template <typename Number>
void write_list(std::ostream& out, const std::vector<Number>& values)
{
  for (std::size_t i = 0; i < values.size(); ++i)
    out << values[i] << ((i + 1) % 8 == 0 || i + 1 == values.size() ? "\n" : ", ");
}

void write_nodes(std::ostream& out, const SceneMesh& mesh, const DeckLayout& layout,
                 double thickness)
{
  out << "*NODE, NSET=NALL\n";
  const auto write = [&](std::size_t id, const Eigen::Vector3d& x)
  { out << id << ", " << x.x() << ", " << x.y() << ", " << x.z() << "\n"; };
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
    write(n + 1, mesh.nodes[n]);
  if (layout.slice)
    for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
      write(n + 1 + layout.top_offset, mesh.nodes[n] + Eigen::Vector3d(0., 0., thickness));
}

void write_elements(std::ostream& out, const SceneMesh& mesh, const SceneInfo& info,
                    const DeckLayout& layout)
{
  for (const auto& [id, name] : info.material_names)
  {
    out << "*ELEMENT, TYPE=" << layout.element_type << ", ELSET=" << abaqus_name(name) << "\n";
    for (std::size_t c = 0; c < mesh.cells.size(); ++c)
      if (mesh.cells[c].material_id == id)
      {
        std::vector<std::size_t> nodes;
        for (const unsigned int n : mesh.cells[c].nodes)
          nodes.push_back(n + 1);
        if (layout.slice)
          for (const unsigned int n : mesh.cells[c].nodes)
            nodes.push_back(n + 1 + layout.top_offset);
        out << c + 1;
        for (const auto n : nodes)
          out << ", " << n;
        out << "\n";
      }
  }
}

// Node ids of the cells' faces that carry boundary id `id` (both layers of a slice).
std::vector<std::size_t> boundary_nodes(const SceneMesh& mesh, const DeckLayout& layout, int id)
{
  std::set<std::size_t> nodes;
  for (const auto& facet : mesh.facets)
    if (facet.boundary_id == id)
      for (const unsigned int n : facet.nodes)
      {
        nodes.insert(n + 1);
        if (layout.slice)
          nodes.insert(n + 1 + layout.top_offset);
      }
  return {nodes.begin(), nodes.end()};
}

void write_groups(std::ostream& out, const SceneMesh& mesh, const SceneInfo& info,
                  const DeckLayout& layout)
{
  const auto faces = facet_faces(mesh);
  for (const auto& [id, name] : info.boundary_names)
  {
    if (faces.count(id) == 0)
      continue;
    out << "*NSET, NSET=" << abaqus_name(name) << "_NODES\n";
    write_list(out, boundary_nodes(mesh, layout, id));
    out << "*SURFACE, NAME=" << abaqus_name(name) << ", TYPE=ELEMENT\n";
    const auto [first, last] = faces.equal_range(id);
    for (auto it = first; it != last; ++it)
      out << it->second.first + 1 << ", " << layout.face_label(it->second.second) << "\n";
  }
}

std::string boundary_name(const SceneInfo& info, int id, const std::string& parameter)
{
  const auto found = info.boundary_names.find(id);
  if (found == info.boundary_names.end())
    throw InputError(parameter, "the scene has no boundary id " + std::to_string(id));
  return abaqus_name(found->second);
}

void write_model(std::ostream& out, const SceneMesh& mesh, const SceneInfo& info,
                 const AbaqusDeckSpec& spec, const DeckLayout& layout)
{
  out << "*MATERIAL, NAME=STEEL\n*ELASTIC\n"
      << spec.young_modulus << ", " << spec.poisson_ratio << "\n";
  for (const auto& [id, name] : info.material_names)
  {
    out << "*SOLID SECTION, ELSET=" << abaqus_name(name) << ", MATERIAL=STEEL\n";
    if (mesh.dimension == 2 && !layout.slice)
      out << spec.slice_thickness << "\n";
  }
  out << "*SURFACE INTERACTION, NAME=CONTACT\n"
      << "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
      << spec.penalty << "\n";
  if (spec.friction > 0.)
    out << "*FRICTION\n" << spec.friction << ", " << spec.stick_slope << "\n";
  for (const auto& [slave, master] : spec.contact_pairs)
    out << "*CONTACT PAIR, INTERACTION=CONTACT, TYPE=SURFACE TO SURFACE\n"
        << boundary_name(info, slave, "Abaqus deck/contact pairs") << ", "
        << boundary_name(info, master, "Abaqus deck/contact pairs") << "\n";

  // The driven bore: a rigid body about its centre, REF NODE and ROT NODE after all mesh nodes.
  const std::size_t ref = mesh.nodes.size() * (layout.slice ? 2 : 1) + 1, rot = ref + 1;
  out << "** REF NODE " << ref << " (axis of the driven bore), ROT NODE " << rot
      << " (its displacements are the rotations about x, y, z)\n"
      << "*NODE, NSET=DRIVEN_REF\n"
      << ref << ", " << spec.driven_centre.x() << ", " << spec.driven_centre.y() << ", 0\n"
      << "*NODE, NSET=DRIVEN_ROT\n"
      << rot << ", " << spec.driven_centre.x() << ", " << spec.driven_centre.y() << ", 0\n";
  const std::string driven = boundary_name(info, spec.driven_bore, "Abaqus deck/driven bore");
  const std::string fixed = boundary_name(info, spec.fixed_bore, "Abaqus deck/fixed bore");
  out << "*RIGID BODY, NSET=" << driven << "_NODES, REF NODE=" << ref << ", ROT NODE=" << rot
      << "\n";
  if (layout.slice)
  {
    // Plane strain: u_z = 0 everywhere but on the rigid bore, whose u_z follows from the
    // reference node (fixed below) and the rotations about x and y (fixed below).
    const auto driven_nodes = boundary_nodes(mesh, layout, spec.driven_bore);
    std::vector<std::size_t> plane;
    for (std::size_t n = 1; n <= 2 * mesh.nodes.size(); ++n)
      if (!std::binary_search(driven_nodes.begin(), driven_nodes.end(), n))
        plane.push_back(n);
    out << "*NSET, NSET=PLANE_STRAIN\n";
    write_list(out, plane);
  }
}

// The supports of both steps: the fixed bore, the reference node, the out-of-plane rotations.
void write_supports(std::ostream& out, const SceneInfo& info, const AbaqusDeckSpec& spec,
                    const DeckLayout& layout, const std::string& parameters)
{
  const unsigned int in_plane_dofs = layout.slice || info.dimension == 3 ? 3 : 2;
  out << "*BOUNDARY" << parameters << "\n"
      << boundary_name(info, spec.fixed_bore, "") << "_NODES, 1, " << in_plane_dofs << "\n"
      << "DRIVEN_REF, 1, " << in_plane_dofs << "\n"
      << "DRIVEN_ROT, 1, 2\n"; // ccx's rigid bodies are 3D, also over CPE4/CPS4
  if (layout.slice)
    out << "PLANE_STRAIN, 3, 3\n";
}

void write_steps(std::ostream& out, const SceneInfo& info, const AbaqusDeckSpec& spec,
                 const DeckLayout& layout)
{
  write_supports(out, info, spec, layout, "");
  out << "** Step 1: a prescribed rotation closes the contacts that will carry load.\n"
      << "*STEP\n*STATIC\n1., 1.\n*BOUNDARY\nDRIVEN_ROT, 3, 3, " << spec.closing_rotation
      << "\n*END STEP\n";
  // One increment: the problem is linear but for the contact, whose active set ccx's Newton
  // iteration settles within the increment (split into four, it took 32 iterations, not 14).
  out << "** Step 2: the rotation is released and the torque applied.\n"
      << "*STEP, INC=1000\n*STATIC\n1., 1.\n";
  write_supports(out, info, spec, layout, ", OP=NEW");
  out << "*CLOAD\nDRIVEN_ROT, 3, " << spec.torque << "\n"
      << "*NODE PRINT, NSET=DRIVEN_ROT\nU\n"
      << "*NODE PRINT, NSET=DRIVEN_REF\nRF\n"
      << "*NODE FILE\nU\n*EL FILE\nS\n*CONTACT FILE\nCSTR, CDIS\n*END STEP\n";
}
} // namespace

std::string abaqus_name(const std::string& group_name)
{
  std::string name = group_name;
  for (auto& c : name)
    c = c == ' ' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return name;
}

Element2D parse_element_2d(const std::string& text, const std::string& parameter)
{
  if (text == "slice")
    return Element2D::slice;
  if (text == "CPE4")
    return Element2D::plane_strain;
  if (text == "CPS4")
    return Element2D::plane_stress;
  throw InputError(parameter, "'" + text + "' is not one of slice, CPE4, CPS4");
}

SceneMesh read_scene_mesh(const std::string& msh_file, const unsigned int dimension)
{
  const GmshReadSession session(msh_file);
  SceneMesh mesh;
  mesh.dimension = dimension;
  std::vector<std::size_t> tags;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(tags, coordinates, parametric, -1, -1, false, false);
  std::unordered_map<std::size_t, unsigned int> index;
  for (std::size_t i = 0; i < tags.size(); ++i)
  {
    index[tags[i]] = static_cast<unsigned int>(i);
    mesh.nodes.emplace_back(coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]);
  }
  const auto local = [&](const std::vector<std::size_t>& element)
  {
    std::vector<unsigned int> nodes;
    for (const auto tag : element)
      nodes.push_back(index.at(tag));
    return nodes;
  };
  // gmsh element types: 1 line, 3 quadrangle, 5 hexahedron (first order).
  const int cell_type = dimension == 2 ? 3 : 5, facet_type = dimension == 2 ? 1 : 3;
  const unsigned int cell_nodes = dimension == 2 ? 4 : 8, facet_nodes = dimension == 2 ? 2 : 4;
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  for (const auto& [dim, tag] : groups)
    if (dim == static_cast<int>(dimension))
      for (const auto& element : group_elements(dim, tag, cell_type, cell_nodes))
        mesh.cells.push_back({local(element), tag});
    else if (dim == static_cast<int>(dimension) - 1)
      for (const auto& element : group_elements(dim, tag, facet_type, facet_nodes))
        mesh.facets.push_back({local(element), tag});
  if (mesh.cells.empty())
    throw SolverFailure("reading the scene mesh",
                        "'" + msh_file + "' holds no " + std::to_string(dimension) + "D cells");
  return mesh;
}

AbaqusDeckSpec gear_pair_deck_spec(const GearPairSceneSpec& spec, const GearPairScene& scene,
                                   const double friction, const double penalty_factor)
{
  const SceneInfo& info = scene.info;
  AbaqusDeckSpec deck;
  deck.slice_thickness = info.face_width;
  deck.young_modulus = spec.young_modulus;
  deck.poisson_ratio = spec.poisson_ratio;
  deck.friction = friction;
  // A contact pressure p closes the penalty law by p/K; with K = f·E/h_c that is a fraction
  // p/(f·E) of a contact cell, ~1e-4 of h_c at f = 50 and 1 GPa: far below the Hertz
  // approach, so the penalty bias is small and is extrapolated away by the bench.
  deck.penalty = penalty_factor * spec.young_modulus / info.contact_size;
  // A stick slope as stiff as the normal penalty keeps the elastic slip of sticking points
  // as small as the penetration.
  deck.stick_slope = deck.penalty;
  // One contact pair per tooth pair inside the path of contact, exactly the pairs the stiffness
  // analysis (stiffness/mesh_stiffness.cc) pairs; the other modelled pairs stay free surfaces.
  // Pairing them too changes the model, not only the solver: next to an end of the single-pair
  // zone (24/69 with standard tips, C 0.06 mm past B) the neighbouring pair's pinion tip corner
  // lies within the chord error of the mate's coarsely meshed flank (ring: 1.4 µm overlap, the
  // sagitta of its 0.65 mm chords; external wheel: 0.46 µm gap) and ccx carried up to half of
  // the load through that one corner node, k +30 % (external) and +74 % (ring) above the
  // one-pair model (docs/calculix.md).
  // (write_gear_pair_scene models every pair in contact.)
  for (const int j : scene.contact_pairs)
    deck.contact_pairs.emplace_back(pinion_flank_id(j), wheel_flank_id(j));
  deck.driven_bore = scene_ids::pinion_bore;
  deck.driven_centre = info.first_centre;
  deck.torque = spec.pinion_torque;
  deck.fixed_bore = scene_ids::wheel_bore;
  // Δφ ≈ T/(c'·b·r_b1²) with c' = 14 N/(mm·µm), the order of a steel spur pair's single stiffness
  // (ISO 6336-1); a tenth of it closes the loaded contacts without passing the loaded state.
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  const double base_radius = 0.5 * pair.pinion.base_diameter;
  deck.closing_rotation =
      0.1 * spec.pinion_torque / (14e9 * info.face_width * base_radius * base_radius);
  deck.title = "gearstiff gear pair scene (" + to_string(spec.position) + " position), " +
               std::to_string(info.mesh.n_cells) + " cells";
  return deck;
}

void write_abaqus_deck(const SceneInfo& info, const AbaqusDeckSpec& spec,
                       const std::string& inp_file)
{
  const SceneMesh mesh = read_scene_mesh(info.file, info.dimension);
  const DeckLayout layout = deck_layout(mesh, spec);
  if (mesh.dimension == 2 && !(spec.slice_thickness > 0.))
    throw InputError("Abaqus deck/thickness", "must be positive for a 2D scene");
  std::ofstream out(inp_file);
  if (!out)
    throw InputError("Abaqus deck", "cannot write '" + inp_file + "'");
  out << std::setprecision(12);
  out << "*HEADING\n" << spec.title << "\n";
  out << "** Written by gearstiff (geometry/abaqus_deck.h). Units: m, N, Pa.\n";
  write_nodes(out, mesh, layout, spec.slice_thickness);
  write_elements(out, mesh, info, layout);
  write_groups(out, mesh, info, layout);
  write_model(out, mesh, info, spec, layout);
  write_steps(out, info, spec, layout);
  if (!out)
    throw InputError("Abaqus deck", "writing '" + inp_file + "' failed");
}
} // namespace gearstiff::geometry
