#include "geometry/abaqus_deck.h"

#include "errors/errors.h"
#include "errors/format.h"
#include "errors/io.h"
#include "geometry/fields.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <functional>
#include <gmsh.h>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

namespace gearstiff::geometry
{
namespace
{
// N/m², c' = 14 N/(mm·µm): the order of a steel spur pair's single stiffness (ISO 6336-1), for
// the closing rotations of step 1 (a tenth of an estimate of the loaded rotation).
constexpr double single_pair_stiffness = 14e9;

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

// A labelled facet as a cell face: cell index, 0-based face number in cell_faces order, and the
// facet's index in SceneMesh::facets.
struct CellFace
{
  std::size_t cell = 0;
  unsigned int face = 0;
  std::size_t facet = 0;
};

// For every labelled facet, by boundary id.
std::multimap<int, CellFace> facet_faces(const SceneMesh& mesh)
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
  std::multimap<int, CellFace> result;
  for (std::size_t i = 0; i < mesh.facets.size(); ++i)
  {
    const auto& facet = mesh.facets[i];
    const auto found = faces.find(sorted(facet.nodes));
    if (found == faces.end())
      throw SolverFailure("writing the Abaqus deck", "a facet of boundary id " +
                                                         std::to_string(facet.boundary_id) +
                                                         " is not the face of any cell");
    result.emplace(facet.boundary_id, CellFace{found->second.first, found->second.second, i});
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

// Index of the point of `centres` nearest to the centroid of `facet` (in the plane).
unsigned int nearest_centre(const SceneMesh& mesh, const SceneMesh::Facet& facet,
                            const std::vector<Eigen::Vector2d>& centres)
{
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (const unsigned int n : facet.nodes)
    centroid += mesh.nodes[n].head<2>() / double(facet.nodes.size());
  unsigned int best = 0;
  for (unsigned int k = 1; k < centres.size(); ++k)
    if ((centres[k] - centroid).norm() < (centres[best] - centroid).norm())
      best = k;
  return best;
}

void write_groups(std::ostream& out, const SceneMesh& mesh, const SceneInfo& info,
                  const AbaqusDeckSpec& spec, const DeckLayout& layout)
{
  const auto faces = facet_faces(mesh);
  const auto write_faces = [&](int id, const std::function<bool(const CellFace&)>& take)
  {
    const auto [first, last] = faces.equal_range(id);
    for (auto it = first; it != last; ++it)
      if (take(it->second))
        out << it->second.cell + 1 << ", " << layout.face_label(it->second.face) << "\n";
  };
  for (const auto& [id, name] : info.boundary_names)
  {
    if (faces.count(id) == 0)
      continue;
    out << "*NSET, NSET=" << abaqus_name(name) << "_NODES\n";
    write_list(out, boundary_nodes(mesh, layout, id));
    out << "*SURFACE, NAME=" << abaqus_name(name) << ", TYPE=ELEMENT\n";
    write_faces(id, [](const CellFace&) { return true; });
  }
  for (const AbaqusSurfacePart& part : spec.surface_parts)
  {
    if (part.index >= part.centres.size())
      throw InputError(field::deck("surface_parts"),
                       part.name + ": no centre " + std::to_string(part.index));
    out << "*SURFACE, NAME=" << part.name << ", TYPE=ELEMENT\n";
    write_faces(part.boundary_id, [&](const CellFace& f)
                { return nearest_centre(mesh, mesh.facets[f.facet], part.centres) == part.index; });
  }
}

std::string boundary_name(const SceneInfo& info, int id, const std::string& parameter)
{
  const auto found = info.boundary_names.find(id);
  if (found == info.boundary_names.end())
    throw InputError(parameter, "the scene has no boundary id " + std::to_string(id));
  return abaqus_name(found->second);
}

// The material; a plane-stress slice takes the constants whose plane-strain response is the
// plane-stress one of (E, ν): E' = E(1 + 2ν)/(1 + ν)², ν' = ν/(1 + ν) (in-plane stresses and
// strains exactly; the slice's σ_zz is then not the plane-stress zero).
void write_material(std::ostream& out, const SceneMesh& mesh, const SceneInfo& info,
                    const AbaqusDeckSpec& spec, const DeckLayout& layout)
{
  double e = spec.young_modulus, nu = spec.poisson_ratio;
  if (layout.slice && spec.plane_stress)
  {
    out << "** plane stress of E = " << e << ", nu = " << nu
        << " as plane strain of the equivalent constants\n";
    e = spec.young_modulus * (1. + 2. * nu) / ((1. + nu) * (1. + nu));
    nu = spec.poisson_ratio / (1. + spec.poisson_ratio);
  }
  out << "*MATERIAL, NAME=STEEL\n*ELASTIC\n" << e << ", " << nu << "\n";
  for (const auto& [id, name] : info.material_names)
  {
    out << "*SOLID SECTION, ELSET=" << abaqus_name(name) << ", MATERIAL=STEEL\n";
    if (mesh.dimension == 2 && !layout.slice)
      out << spec.slice_thickness << "\n";
  }
}

void write_contact(std::ostream& out, const SceneInfo& info, const AbaqusDeckSpec& spec)
{
  std::set<std::string> surfaces;
  for (const auto& [id, name] : info.boundary_names)
    surfaces.insert(abaqus_name(name));
  for (const auto& part : spec.surface_parts)
    surfaces.insert(part.name);
  const auto surface = [&](const std::string& name) -> const std::string&
  {
    if (surfaces.count(name) == 0)
      throw InputError(field::deck("contact_pairs"), "no surface named " + name);
    return name;
  };
  out << "*SURFACE INTERACTION, NAME=CONTACT\n"
      << "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
      << spec.penalty << "\n";
  if (spec.friction > 0.)
    out << "*FRICTION\n" << spec.friction << ", " << spec.stick_slope << "\n";
  for (const auto& [slave, master] : spec.contact_pairs)
    out << "*CONTACT PAIR, INTERACTION=CONTACT, TYPE=SURFACE TO SURFACE\n"
        << surface(slave) << ", " << surface(master) << "\n";
}

// The rigid bodies, REF NODE and ROT NODE of each after all mesh nodes, and (slice) the set of
// the nodes held in plane strain.
void write_rigid_bodies(std::ostream& out, const SceneMesh& mesh, const SceneInfo& info,
                        const AbaqusDeckSpec& spec, const DeckLayout& layout)
{
  std::size_t next = mesh.nodes.size() * (layout.slice ? 2 : 1) + 1;
  std::set<std::size_t> rigid_nodes;
  for (const AbaqusRigidBody& body : spec.rigid_bodies)
  {
    const std::size_t ref = next++, rot = next++;
    const Eigen::Vector2d& c = body.centre;
    out << "** " << body.name << ": REF NODE " << ref << " (axis), ROT NODE " << rot
        << " (its displacements are the rotations about x, y, z)\n"
        << "*NODE, NSET=" << body.name << "_REF\n"
        << ref << ", " << c.x() << ", " << c.y() << ", 0\n"
        << "*NODE, NSET=" << body.name << "_ROT\n"
        << rot << ", " << c.x() << ", " << c.y() << ", 0\n"
        << "*RIGID BODY, NSET="
        << boundary_name(info, body.boundary_id, field::deck("rigid_bodies"))
        << "_NODES, REF NODE=" << ref << ", ROT NODE=" << rot << "\n";
    const auto nodes = boundary_nodes(mesh, layout, body.boundary_id);
    rigid_nodes.insert(nodes.begin(), nodes.end());
  }
  if (layout.slice)
  {
    // Plane strain: u_z = 0 everywhere but on the rigid bores, whose u_z follows from their
    // reference nodes (fixed below) and the rotations about x and y (fixed below).
    std::vector<std::size_t> plane;
    for (std::size_t n = 1; n <= 2 * mesh.nodes.size(); ++n)
      if (rigid_nodes.count(n) == 0)
        plane.push_back(n);
    out << "*NSET, NSET=PLANE_STRAIN\n";
    write_list(out, plane);
  }
}

void write_model(std::ostream& out, const SceneMesh& mesh, const SceneInfo& info,
                 const AbaqusDeckSpec& spec, const DeckLayout& layout)
{
  write_material(out, mesh, info, spec, layout);
  write_contact(out, info, spec);
  write_rigid_bodies(out, mesh, info, spec, layout);
  // The supports are written per step with the group names; a bad id stops here, named.
  for (const int id : spec.fixed_bores)
    boundary_name(info, id, field::deck("fixed_bores"));
}

// The supports of both steps: the fixed bores, the reference nodes, the out-of-plane rotations.
void write_supports(std::ostream& out, const SceneInfo& info, const AbaqusDeckSpec& spec,
                    const DeckLayout& layout, const std::string& parameters)
{
  const unsigned int in_plane_dofs = layout.slice || info.dimension == 3 ? 3 : 2;
  out << "*BOUNDARY" << parameters << "\n";
  for (const int id : spec.fixed_bores)
    out << boundary_name(info, id, "") << "_NODES, 1, " << in_plane_dofs << "\n";
  // ccx's rigid bodies are 3D, also over CPE4/CPS4: the rotations about x and y are held.
  for (const AbaqusRigidBody& body : spec.rigid_bodies)
    if (body.pushed)
    {
      // Free along y only: no sideways sliding, no turning (u_y is set per step).
      out << body.name << "_REF, 1, 1\n";
      if (in_plane_dofs == 3)
        out << body.name << "_REF, 3, 3\n";
      out << body.name << "_ROT, 1, 3\n";
    }
    else
      out << body.name << "_REF, 1, " << in_plane_dofs << "\n" << body.name << "_ROT, 1, 2\n";
  if (layout.slice)
    out << "PLANE_STRAIN, 3, 3\n";
}

void write_steps(std::ostream& out, const SceneInfo& info, const AbaqusDeckSpec& spec,
                 const DeckLayout& layout)
{
  write_supports(out, info, spec, layout, "");
  out << "** Step 1: prescribed rigid-body motions close the contacts that will carry load.\n"
      << "*STEP\n*STATIC\n1., 1.\n*BOUNDARY\n";
  for (const AbaqusRigidBody& body : spec.rigid_bodies)
    if (body.pushed)
      out << body.name << "_REF, 2, 2, " << body.closing_displacement << "\n";
    else
      out << body.name << "_ROT, 3, 3, " << body.closing_rotation << "\n";
  out << "*END STEP\n";
  // One increment: the problem is linear but for the contact, whose active set ccx's Newton
  // iteration settles within the increment (split into four, it took 32 iterations, not 14).
  out << "** Step 2: the motions are released and the torques or forces applied.\n"
      << "*STEP, INC=1000\n*STATIC\n1., 1.\n";
  write_supports(out, info, spec, layout, ", OP=NEW");
  out << "*CLOAD\n";
  for (const AbaqusRigidBody& body : spec.rigid_bodies)
    if (body.pushed && body.force != 0.)
      out << body.name << "_REF, 2, " << body.force << "\n";
    else if (!body.pushed && body.torque != 0.)
      out << body.name << "_ROT, 3, " << body.torque << "\n";
  for (const AbaqusRigidBody& body : spec.rigid_bodies)
    out << "*NODE PRINT, NSET=" << body.name << "_ROT\nU\n"
        << "*NODE PRINT, NSET=" << body.name << "_REF\n"
        << (body.pushed ? "U, RF" : "RF") << "\n";
  out << "*NODE FILE\nU\n*EL FILE\nS\n*CONTACT FILE\nCSTR, CDIS\n";
  // Per contact pair (ccx: CF needs its SLAVE and MASTER) the total force on its slave surface:
  // the roller and pin forces.
  if (spec.print_contact_forces)
    for (const auto& [slave, master] : spec.contact_pairs)
      out << "*CONTACT PRINT, SLAVE=" << slave << ", MASTER=" << master << "\nCF\n";
  out << "*END STEP\n";
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

namespace
{
// The settings every scene's deck shares: thickness, material, penalty, friction.
AbaqusDeckSpec common_deck_spec(const SceneInfo& info, double young_modulus, double poisson_ratio,
                                double friction, double penalty_factor)
{
  AbaqusDeckSpec deck;
  deck.slice_thickness = info.face_width;
  deck.young_modulus = young_modulus;
  deck.poisson_ratio = poisson_ratio;
  deck.friction = friction;
  // A contact pressure p closes the penalty law by p/K; with K = f·E/h_c that is a fraction
  // p/(f·E) of a contact cell, ~1e-4 of h_c at f = 50 and 1 GPa: far below the Hertz
  // approach, so the penalty bias is small and is extrapolated away by the bench.
  deck.penalty = penalty_factor * young_modulus / info.contact_size;
  // A stick slope as stiff as the normal penalty keeps the elastic slip of sticking points
  // as small as the penetration.
  deck.stick_slope = deck.penalty;
  return deck;
}
} // namespace

AbaqusDeckSpec gear_pair_deck_spec(const GearPairSceneSpec& spec, const GearPairScene& scene,
                                   const double friction, const double penalty_factor)
{
  const SceneInfo& info = scene.info;
  AbaqusDeckSpec deck =
      common_deck_spec(info, spec.young_modulus, spec.poisson_ratio, friction, penalty_factor);
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
    deck.contact_pairs.emplace_back(abaqus_name(info.boundary_names.at(pinion_flank_id(j))),
                                    abaqus_name(info.boundary_names.at(wheel_flank_id(j))));
  AbaqusRigidBody pinion;
  pinion.name = "DRIVEN";
  pinion.boundary_id = scene_ids::pinion_bore;
  pinion.centre = info.first_centre;
  pinion.torque = spec.pinion_torque;
  deck.fixed_bores = {scene_ids::wheel_bore};
  // Δφ ≈ T/(c'·b·r_b1²) with c' = 14 N/(mm·µm), the order of a steel spur pair's single stiffness
  // (ISO 6336-1); a tenth of it closes the loaded contacts without passing the loaded state.
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(spec.pair);
  const double base_radius = 0.5 * pair.pinion.base_diameter;
  // Tooth modifications (issue 27) that leave every pair a designed separation (relief on both
  // gears) add the turn that closes the smallest of them, the unloaded TE: otherwise step 1 ends
  // with no contact and step 2's free, torque-driven pinion runs away (Δφ ~ 1e4 rad). Step 2
  // starts from the prescribed state but its equilibrium does not depend on it (frictionless:
  // linear elasticity and contact; with friction the stick zones depend on the path by a
  // tenth of the loaded slip).
  pinion.closing_rotation =
      scene.unloaded_transmission_error / base_radius +
      0.1 * spec.pinion_torque /
          (single_pair_stiffness * info.face_width * base_radius * base_radius);
  deck.rigid_bodies = {pinion};
  deck.title = "gearstiff gear pair scene (" + to_string(spec.position) + " position), " +
               std::to_string(info.mesh.n_cells) + " cells";
  return deck;
}

void check_cycloid_deck_play(const CycloidSceneSpec& spec)
{
  // Step 1 turns the output member by a tenth of its elastic rotation, which closes no play:
  // ccx would find the member free. cycloid-loads turns the pins through their play first
  // (stiffness/cycloid_loads.cc); the deck does not.
  const double play = spec.output_pin_hole_radius - spec.output_pin_radius - spec.ring.eccentricity;
  if (has_output_pin_play(spec))
    throw InputError(field::cycloid_scene("output_pin_radius"),
                     "the CalculiX deck closes no output-pin play (hole − pin − e = " +
                         format_number(play * 1e3, 4) +
                         " mm): ccx would find the output member free; the deck needs pin + e = "
                         "hole (`gearstiff cycloid-loads` solves a drive with play)");
}

AbaqusDeckSpec cycloid_deck_spec(const CycloidSceneSpec& spec, const SceneInfo& info,
                                 const double output_torque, const double penalty_factor)
{
  if (spec.output_pins == 0)
    throw InputError(field::cycloid_scene("output_pins"),
                     "the deck ties the output pins to the output member: at least one is needed");
  if (!spec.output_pin_bodies)
    throw InputError(field::cycloid_scene("output_pin_bodies"),
                     "the deck ties the output pins to the output member: mesh them");
  if (!(std::abs(output_torque) > 0.) || !std::isfinite(output_torque))
    throw InputError(field::deck("output_torque"),
                     "must not be zero: without a torque nothing is loaded (N·m)");
  check_cycloid_deck_play(spec);
  // Frictionless, plane stress: the load case of stiffness/cycloid_loads.h.
  AbaqusDeckSpec deck =
      common_deck_spec(info, spec.young_modulus, spec.poisson_ratio, 0., penalty_factor);
  deck.plane_stress = true;

  // Surfaces per roller and per pin: the roller's surface on the lobe faces nearest to it, the
  // pin's surface on its hole. The rollers paired are those the scene meshed finely (clearance
  // within Cycloid scene/contact clearance), as cycloid-loads pairs them.
  const CycloidDiscSpec& ring = spec.ring;
  const CycloidDiscSpec disc = spec.disc.rollers == 0 ? ring : spec.disc;
  const std::vector<double> clearances = roller_clearances(ring, disc, spec.disc_rotation);
  std::vector<Eigen::Vector2d> rollers, pins, holes;
  for (unsigned int i = 0; i < ring.rollers; ++i)
    rollers.push_back(ring.roller_circle_radius *
                      Eigen::Vector2d(std::cos(2. * M_PI * i / ring.rollers),
                                      std::sin(2. * M_PI * i / ring.rollers)));
  for (unsigned int j = 0; j < spec.output_pins; ++j)
  {
    pins.push_back(output_pin_centre(spec, j));
    holes.push_back(output_hole_centre(spec, j, info.first_centre));
  }
  const auto add_pair =
      [&deck](const std::string& slave, int slave_id,
              const std::vector<Eigen::Vector2d>& slave_centres, const std::string& master,
              int master_id, const std::vector<Eigen::Vector2d>& master_centres, unsigned int index)
  {
    deck.surface_parts.push_back({slave, slave_id, slave_centres, index});
    deck.surface_parts.push_back({master, master_id, master_centres, index});
    deck.contact_pairs.emplace_back(slave, master);
  };
  for (unsigned int i = 0; i < ring.rollers; ++i)
    if (clearances[i] <= spec.contact_clearance)
      add_pair("ROLLER_" + std::to_string(i), scene_ids::second_contact, rollers,
               "LOBES_" + std::to_string(i), scene_ids::first_contact, rollers, i);
  for (unsigned int j = 0; j < spec.output_pins; ++j)
    add_pair("PIN_" + std::to_string(j), cycloid_ids::output_pin_surfaces, pins,
             "HOLE_" + std::to_string(j), scene_ids::output_pin_holes, holes, j);

  // The output member turns by θ ≈ M_c/(c'·b·r²) with c' of a steel spur pair and r the roller
  // circle (the §4 drive: 2.3e-4 rad against cycloid-loads' 2.4e-4); step 1 turns it by a tenth
  // of that and the disc by half as much, which closes the loaded rollers and pins alike (the
  // disc and the member turning together close no pin).
  const double r = ring.roller_circle_radius;
  const double theta = output_torque / (single_pair_stiffness * spec.disc_width * r * r);
  AbaqusRigidBody output;
  output.name = "OUTPUT";
  output.boundary_id = cycloid_ids::output_pin_bores;
  output.torque = output_torque;
  output.closing_rotation = 0.1 * theta;
  AbaqusRigidBody bearing;
  bearing.name = "DISC_BEARING";
  bearing.boundary_id = scene_ids::first_bore;
  bearing.centre = info.first_centre;
  bearing.closing_rotation = 0.05 * theta;
  deck.rigid_bodies = {output, bearing};
  deck.print_contact_forces = true;
  deck.fixed_bores = {scene_ids::second_bore};
  deck.title = "gearstiff cycloid scene (disc rotation " + std::to_string(spec.disc_rotation) +
               " rad, output torque " + std::to_string(output_torque) + " N m), " +
               std::to_string(info.mesh.n_cells) + " cells";
  return deck;
}

AbaqusDeckSpec cylinders_deck_spec(const CylindersSceneSpec& spec, const SceneInfo& info,
                                   const double friction, const double penalty_factor)
{
  if (info.contacts.size() != 1)
    throw InputError("Abaqus deck", "the cylinders deck needs the scene's one contact");
  AbaqusDeckSpec deck =
      common_deck_spec(info, spec.young_modulus, spec.poisson_ratio, friction, penalty_factor);
  // The support of each cylinder: its bore, or without one the flat face through its centre.
  const int lower = spec.bore_radius_1 > 0. ? scene_ids::first_bore : scene_ids::first_cuts;
  const int upper = spec.bore_radius_2 > 0. ? scene_ids::second_bore : scene_ids::second_cuts;
  deck.fixed_bores = {lower};
  // Cylinder 2 on cylinder 1, as gearstiff's built-in case pairs the upper arc (slave) on the
  // lower one; both arcs are meshed alike in this scene.
  deck.contact_pairs = {{abaqus_name(info.boundary_names.at(scene_ids::second_contact)),
                         abaqus_name(info.boundary_names.at(scene_ids::first_contact))}};
  deck.print_contact_forces = true;
  // Elastically similar cylinders under a normal load carry no shear (Johnson 1985 §5.1), so the
  // stick slope only has to hold the surfaces together; as stiff as the normal penalty, ccx's
  // Newton iteration chattered between stick states at the few nodes closed in step 1 and did
  // not converge (h_c = 0.02 mm, μ = 0.1 or 0.01); a hundredth of it converges; the elastic
  // slip of a sticking node, μp/slope, is then 0.002 µm (μ = 0.01, p = 1 GPa, h_c = 0.02 mm).
  deck.stick_slope = 0.01 * deck.penalty;

  // The overlap of the undeformed profiles over the loaded half-width is a²/(2R*); the loaded
  // approach adds the bodies' compression (logarithmic in R/a, several times more). A tenth of
  // a²/R* closes the contact nodes within ~0.45 a and stays far below the loaded state.
  const SceneContact& contact = info.contacts.front();
  const double r1 = contact.first_curvature_radius, r2 = contact.second_curvature_radius;
  const double a = contact.hertz_half_width;
  AbaqusRigidBody pushed;
  pushed.name = "UPPER";
  pushed.boundary_id = upper;
  pushed.centre = info.second_centre;
  pushed.pushed = true;
  pushed.force = -spec.force_per_length * deck.slice_thickness; // towards cylinder 1
  pushed.closing_displacement = -0.1 * a * a * (r1 + r2) / (r1 * r2);
  deck.rigid_bodies = {pushed};
  std::ostringstream title;
  title << "gearstiff cylinders scene (R1 " << r1 * 1e3 << " mm, R2 " << r2 * 1e3 << " mm, "
        << spec.force_per_length * 1e-3 << " N/mm), " << info.mesh.n_cells << " cells";
  deck.title = title.str();
  return deck;
}

void write_abaqus_deck(const SceneInfo& info, const AbaqusDeckSpec& spec,
                       const std::string& inp_file)
{
  const SceneMesh mesh = read_scene_mesh(info.file, info.dimension);
  const DeckLayout layout = deck_layout(mesh, spec);
  if (mesh.dimension == 2 && !(spec.slice_thickness > 0.))
    throw InputError(field::deck("thickness"), "must be positive for a 2D scene");
  write_file(inp_file,
             [&](std::ostream& out)
             {
               out << std::setprecision(12);
               out << "*HEADING\n" << spec.title << "\n";
               out << "** Written by gearstiff (geometry/abaqus_deck.h). Units: m, N, Pa.\n";
               write_nodes(out, mesh, layout, spec.slice_thickness);
               write_elements(out, mesh, info, layout);
               write_groups(out, mesh, info, spec, layout);
               write_model(out, mesh, info, spec, layout);
               write_steps(out, info, spec, layout);
             });
}
} // namespace gearstiff::geometry
