#include "app/scenes/geometry_parameters.h"

#include "app/core/parameter_patterns.h"
#include "app/core/units.h"

#include <cmath>

namespace gearstiff::app
{
void declare_cycloid_disc_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Cycloid disc");
  prm.declare_entry("rollers", "20", Integer(3, 1000),
                    "z_k, rollers in the ring [-]; the disc has z_k - 1 lobes");
  prm.declare_entry("roller circle radius", "96", Double(0.),
                    "r, radius of the circle through the roller centres [mm]");
  prm.declare_entry("eccentricity", "3", Double(0.), "e, eccentricity of the disc [mm]");
  prm.declare_entry("roller radius", "8.5", Double(0.), "q, roller radius [mm]");
  prm.leave_subsection();
}

geometry::CycloidDiscSpec parse_cycloid_disc_parameters(ParameterHandler& prm)
{
  geometry::CycloidDiscSpec spec;
  prm.enter_subsection("Cycloid disc");
  spec.rollers = prm.get_integer("rollers");
  spec.roller_circle_radius = prm.get_double("roller circle radius") * mm;
  spec.eccentricity = prm.get_double("eccentricity") * mm;
  spec.roller_radius = prm.get_double("roller radius") * mm;
  prm.leave_subsection();
  return spec;
}

namespace
{
// The four cell sizes of "Mesh" [mm]: name, its documentation, the member.
struct MeshSizeEntry
{
  const char* name;
  const char* documentation;
  double geometry::SceneMeshSettings::*member;
};

const std::vector<MeshSizeEntry>& mesh_size_entries()
{
  static const std::vector<MeshSizeEntry> entries = {
      {"contact size",
       "h_c, cell size at the contact points [mm]; 0 = a tenth of the smallest Hertz half-width",
       &geometry::SceneMeshSettings::contact_size},
      {"fine radius",
       "radius meshed at h_c around each contact point [mm]; 0 = 1.5 × the largest Hertz "
       "half-width",
       &geometry::SceneMeshSettings::fine_radius},
      {"body size", "cell size in the teeth away from contact [mm]",
       &geometry::SceneMeshSettings::body_size},
      {"rim size", "largest cell size, reached deep in the gear rims [mm]; 0 = 4 × body size",
       &geometry::SceneMeshSettings::rim_size}};
  return entries;
}

// -, Mesh/layers: `auto` takes `automatic`; else a count from 1 to 1000.
unsigned int read_layers(const std::string& text, unsigned int automatic)
{
  if (text == "auto")
    return automatic;
  double count = 0.;
  if (!read_whole_number(text, count) || !(count >= 1. && count <= 1000.) ||
      count != std::floor(count))
    throw InputError("Mesh/layers",
                     "'" + shortened(text) + "' is neither a count from 1 to 1000 nor auto");
  return static_cast<unsigned int>(count);
}

// The built-in pair's normal module [m], the reference of the `auto` mesh sizes.
constexpr double reference_module = 2.5e-3;
} // namespace

void declare_scene_mesh_parameters(ParameterHandler& prm,
                                   const geometry::SceneMeshSettings& defaults,
                                   bool sizes_follow_module)
{
  prm.enter_subsection("Mesh");
  prm.declare_entry("dimension", std::to_string(defaults.dimension), Integer(2, 3),
                    "space dimension [-]; 2: quadrilaterals in the transverse plane, 3: "
                    "hexahedra over the face width");
  if (sizes_follow_module)
    prm.declare_entry("layers", "auto", Anything(),
                      "hexahedron layers across the face width [-] (3D, 1 to 1000); auto = " +
                          std::to_string(defaults.layers) +
                          ", for a helical pair 16 per unit of overlap ratio ε_β (at least " +
                          std::to_string(defaults.layers) +
                          ") with twice the automatic body size (docs/helical.md); the stiffness "
                          "command's influence coefficients take at least the count they are "
                          "verified on (docs/ltca.md §3)");
  else
    prm.declare_entry("layers", std::to_string(defaults.layers), Integer(1, 1000),
                      "hexahedron layers across the face width [-] (3D)");
  prm.declare_entry("growth rate", format_number(defaults.growth_rate, 10), Double(0.01, 1.),
                    "cell size increase per unit distance beyond the fine radius [-]");
  // The 3D limit is the machine's, not the method's: the estimate (docs/limits.md) is held to
  // what one process may take, and a user with more memory than the 16 GB the default assumes
  // raises it. Not `auto` from the machine's memory: the automatic body size coarsens to fit
  // this limit, so the mesh, and every result, would change from one machine to the next.
  prm.declare_entry("memory limit", format_number(defaults.memory_limit / 1e9, 10),
                    Double(0.1, 1e6),
                    "the most memory one 3D contact solve may take on one process [GB], "
                    "estimated from the hexahedra before meshing (docs/limits.md): a larger "
                    "estimate is refused naming the size to change, and an automatic body size "
                    "coarsens to fit; raise it on a machine with more memory (a rolling sweep "
                    "holds one such solve per rank)");
  for (const MeshSizeEntry& entry : mesh_size_entries())
  {
    const std::string value = format_number(defaults.*entry.member / mm, 10);
    // A default of 0 is a rule (the Hertz zone, 4 × body size), not a length to scale: `auto`
    // takes that rule at any module (the mesh command reported "Mesh/contact size = 0 mm (the
    // built-in pair's 0 mm × m_n / 2.5 mm)" among its derived sizes until 2026-12-06).
    if (sizes_follow_module && defaults.*entry.member == 0.)
      prm.declare_entry(entry.name, "auto", Anything(),
                        std::string(entry.documentation) + "; auto = 0 (that rule, at any module)");
    else if (sizes_follow_module)
      prm.declare_entry(entry.name, "auto", Anything(),
                        std::string(entry.documentation) + "; auto = " + value +
                            " mm for the built-in pair's module 2.5 mm, scaled by m_n / 2.5 mm");
    else
      prm.declare_entry(entry.name, value, Anything(),
                        std::string(entry.documentation) + "; auto = " + value + " mm");
  }
  prm.leave_subsection();
}

geometry::SceneMeshSettings gear_pair_mesh_defaults(const geometry::SceneMeshSettings& spur,
                                                    const kinematics::GearPairSpec& pair)
{
  if (pair.pinion.helix_angle == 0.)
    return spur;
  return geometry::helical_mesh_defaults(spur, kinematics::compute_gear_pair(pair));
}

double mesh_module_scale(const kinematics::GearPairSpec& pair)
{
  return kinematics::has_split_path_teeth(pair) ? 1. : pair.pinion.normal_module / reference_module;
}

geometry::SceneMeshSettings
parse_scene_mesh_parameters(ParameterHandler& prm, const geometry::SceneMeshSettings& defaults,
                            double module_scale, std::vector<kinematics::DerivedSize>* derived)
{
  geometry::SceneMeshSettings mesh;
  prm.enter_subsection("Mesh");
  mesh.dimension = prm.get_integer("dimension");
  mesh.layers = read_layers(prm.get("layers"), defaults.layers);
  mesh.growth_rate = prm.get_double("growth rate");
  mesh.memory_limit = prm.get_double("memory limit") * 1e9;
  for (const MeshSizeEntry& entry : mesh_size_entries())
  {
    const std::string name = std::string("Mesh/") + entry.name;
    double& size = mesh.*entry.member;
    if (!read_length_or_auto(prm.get(entry.name), name, "size", size))
      continue;
    size = defaults.*entry.member * module_scale;
    mesh.body_size_fits_cell_limit |= entry.member == &geometry::SceneMeshSettings::body_size;
    if (derived && module_scale != 1. && size != 0.)
      derived->push_back({name, size,
                          "the built-in pair's " + format_number(defaults.*entry.member / mm, 6) +
                              " mm × m_n / 2.5 mm"});
  }
  prm.leave_subsection();
  return mesh;
}

void declare_gear_scene_parameters(ParameterHandler& prm,
                                   const geometry::GearPairSceneSpec& defaults,
                                   bool sector_cuts_free)
{
  prm.enter_subsection("Gear pair scene");
  for (const auto& [gear, count] : {std::pair{"pinion", defaults.pinion_teeth_modelled},
                                    std::pair{"wheel", defaults.wheel_teeth_modelled}})
    prm.declare_entry(std::string(gear) + " teeth modelled", "auto", Anything(),
                      std::string(gear) +
                          " teeth in the scene, centred on the contacts [-] (a count of at least "
                          "1, or auto); auto = " +
                          std::to_string(count) +
                          ", or every tooth pair that can touch when they are more (a helical "
                          "pair: across the face at any position of the mesh cycle, so ε_α + ε_β "
                          "decides; a rolling sweep: at every position it turns to)");
  prm.declare_entry("pinion bore radius", format_number(defaults.pinion_bore_radius / mm, 10),
                    Double(0.),
                    "pinion bore radius [mm]; 0 = half of Gear pair/Pinion/bore diameter");
  prm.declare_entry("wheel bore radius", format_number(defaults.wheel_bore_radius / mm, 10),
                    Double(0.),
                    "wheel bore radius [mm]; 0 = half of Gear pair/Wheel/bore diameter");
  prm.declare_entry(
      "wheel rim thickness", format_number(defaults.wheel_rim_thickness / mm, 10), Double(0.),
      "internal wheel (ring): rim thickness under the root circle [mm], the rim's "
      "outer circle held (see wheel supports); 0 = outer radius from 'wheel bore radius' or Gear "
      "pair/Wheel/bore diameter (the ring's outer diameter); at least one module");
  prm.declare_entry("wheel supports", std::to_string(defaults.wheel_supports), Integer(0),
                    "internal wheel with a full rim: 0 = the whole outer circle held; N >= 2 = "
                    "held only on N evenly spaced pads (bolted or splined into a rigid housing), "
                    "the mesh midway between two [-]");
  prm.declare_entry("wheel support width", format_number(defaults.wheel_support_width / mm, 10),
                    Double(0.), "arc length of one support pad on the ring's outer circle [mm]");
  prm.declare_entry("wheel bolt holes", std::to_string(defaults.wheel_bolt_holes), Integer(0),
                    "internal wheel with a full rim: 0 = no holes; N >= 2 = the ring bolted at N "
                    "evenly spaced holes in its rim (the holes clamped, the outer circle free; "
                    "instead of wheel supports), the mesh midway between two [-]");
  prm.declare_entry("bolt hole diameter", format_number(defaults.wheel_bolt_hole_diameter / mm, 10),
                    Double(0.),
                    "diameter of one bolt hole in the ring's rim [mm]; each hole keeps one module "
                    "of material to the root circle, the outer circle and its neighbours");
  prm.declare_entry("bolt circle diameter",
                    format_number(defaults.wheel_bolt_circle_diameter / mm, 10), Double(0.),
                    "diameter of the circle of the bolt-hole centres [mm]; 0 = the middle of the "
                    "rim");
  prm.declare_entry("rim", defaults.rim == geometry::RimModel::full ? "full" : "sector",
                    Selection("sector|full"),
                    std::string("sector: rim of the modelled teeth only, cut radially (cut faces "
                                "get ids 5/6") +
                        (sector_cuts_free ? ", free" : "") +
                        "); full: whole rim and bore, the other teeth removed");
  prm.leave_subsection();
}

namespace
{
// -, "Gear pair scene/<gear> teeth modelled": `auto` keeps `count` (the command's) and lets the
// scene raise it to the pairs that can touch (`follows`); else a count of at least 1.
void read_teeth_modelled(const std::string& text, const std::string& gear, unsigned int& count,
                         bool& follows)
{
  follows = text == "auto";
  if (follows)
    return;
  double number = 0.;
  if (!read_whole_number(text, number) || !(number >= 1. && number <= 1e6) ||
      number != std::floor(number))
    throw InputError("Gear pair scene/" + gear + " teeth modelled",
                     "'" + shortened(text) + "' is neither a count of at least 1 nor auto");
  count = static_cast<unsigned int>(number);
}
} // namespace

void parse_gear_scene_parameters(ParameterHandler& prm, geometry::GearPairSceneSpec& spec)
{
  prm.enter_subsection("Gear pair scene");
  read_teeth_modelled(prm.get("pinion teeth modelled"), "pinion", spec.pinion_teeth_modelled,
                      spec.pinion_teeth_follow_pairs);
  read_teeth_modelled(prm.get("wheel teeth modelled"), "wheel", spec.wheel_teeth_modelled,
                      spec.wheel_teeth_follow_pairs);
  spec.pinion_bore_radius = prm.get_double("pinion bore radius") * mm;
  spec.wheel_bore_radius = prm.get_double("wheel bore radius") * mm;
  spec.wheel_rim_thickness = prm.get_double("wheel rim thickness") * mm;
  spec.wheel_supports = prm.get_integer("wheel supports");
  spec.wheel_support_width = prm.get_double("wheel support width") * mm;
  spec.wheel_bolt_holes = prm.get_integer("wheel bolt holes");
  spec.wheel_bolt_hole_diameter = prm.get_double("bolt hole diameter") * mm;
  spec.wheel_bolt_circle_diameter = prm.get_double("bolt circle diameter") * mm;
  spec.rim = geometry::parse_rim_model(prm.get("rim"), "Gear pair scene/rim");
  prm.leave_subsection();
}

void declare_elastic_constants(ParameterHandler& prm, const std::string& bodies)
{
  prm.declare_entry("Young's modulus", "210", Double(0.),
                    "Young's modulus of " + bodies + " [GPa] (default: steel)");
  prm.declare_entry("Poisson's ratio", "0.3", Double(0., 0.5),
                    "Poisson's ratio of " + bodies + " [-] (default: steel)");
}

void parse_elastic_constants(ParameterHandler& prm, double& young_modulus, double& poisson_ratio)
{
  young_modulus = prm.get_double("Young's modulus") * 1e9;
  poisson_ratio = prm.get_double("Poisson's ratio");
}

ParameterNames gear_scene_parameter_names()
{
  namespace field = geometry::scene_field;
  const std::string section = "Gear pair scene/";
  return {{field::position, section + "position"},
          {field::pinion_roll_angle, section + "pinion roll angle"},
          {field::pinion_teeth_modelled, section + "pinion teeth modelled"},
          {field::wheel_teeth_modelled, section + "wheel teeth modelled"},
          {field::pinion_bore_radius, section + "pinion bore radius"},
          {field::wheel_bore_radius, section + "wheel bore radius"},
          {field::wheel_rim_thickness, section + "wheel rim thickness"},
          {field::wheel_supports, section + "wheel supports"},
          {field::wheel_support_width, section + "wheel support width"},
          {field::wheel_bolt_holes, section + "wheel bolt holes"},
          {field::wheel_bolt_hole_diameter, section + "bolt hole diameter"},
          {field::wheel_bolt_circle_diameter, section + "bolt circle diameter"},
          {field::both_flanks, section + "both flanks"},
          {field::pinion_torque, section + "pinion torque"},
          {field::young_modulus, section + "Young's modulus"},
          {field::poisson_ratio, section + "Poisson's ratio"}};
}
} // namespace gearstiff::app
