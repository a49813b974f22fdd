// `gearstiff mesh [scene.prm]`: writes the FE mesh of one scene (ASCII .msh 4.1, all quadrilateral
// in 2D, hexahedra extruded over the face width in 3D) and reports its ids, extent, predicted
// contacts, cell counts, quality and timings. Default: the split-path pair of docs/references.md §1
// at the single-pair position (pitch point).
//
//   gearstiff mesh -o out                                        out/scene.msh, 2D, single pair
//   gearstiff mesh --set "Gear pair scene/position=double" -o out
//   gearstiff mesh --set "Mesh/dimension=3" --set "Mesh/layers=6" -o out
//   gearstiff mesh --set "Scene/type=cylinders" -o out          Hertz verification scene
//   gearstiff mesh --set "Scene/type=cycloid" -o out            Cyclo disc and rollers (§4)
//   gearstiff mesh --set "Mesh/format=inp" -o out               out/scene.inp, a CalculiX/Abaqus
//                                                               deck (geometry/abaqus_deck.h)
//
// Without -o the mesh is generated (all checks run, the report is complete) but not kept.
#include "app/core/command.h"
#include "app/core/parameter_patterns.h"
#include "app/core/units.h"
#include "app/scenes/geometry_parameters.h"
#include "app/scenes/scene.h"
#include "app/scenes/tooth_modification_parameters.h"
#include "errors/errors.h"
#include "errors/format.h"
#include "geometry/abaqus_deck.h"
#include "geometry/scene_gear_pair.h"
#include "kinematics/gear_pair.h"

#include <cmath>
#include <deal.II/base/parameter_handler.h>
#include <filesystem>
#include <unistd.h>

namespace
{
using namespace gearstiff;
using namespace gearstiff::app;

// The file format and the CalculiX/Abaqus deck's own choices (the scene supplies the rest).
void declare_deck_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Mesh");
  prm.declare_entry("format", "msh", Selection("msh|inp|msh and inp"),
                    "msh: the gmsh mesh (Scene/mesh file); inp: a CalculiX/Abaqus input deck of "
                    "the scene (cycloid: with its output pins meshed) of the same name ending in "
                    ".inp, solvable by `ccx -i` as it is (docs/calculix.md); msh and inp: both");
  prm.leave_subsection();
  prm.enter_subsection("Abaqus deck");
  prm.declare_entry("2D elements", "slice", Selection("slice|CPE4|CPS4"),
                    "slice: one-element-thick C3D8 with u_z = 0 (plane strain, what ccx solves "
                    "best); CPE4/CPS4: plane strain/stress quadrilaterals");
  prm.declare_entry(
      "friction coefficient", format_number(kinematics::split_path_published::tooth_friction, 10),
      friction_coefficient_pattern(),
      "Coulomb μ between the flanks or the cylinders [-] (docs/references.md §1: 0.01; "
      "the cycloid deck is frictionless, as cycloid-loads)");
  prm.declare_entry("output torque", "440", Double(),
                    "cycloid scene: M_c on the rigid output member, counter-clockwise > 0 [N·m] "
                    "(docs/references.md §4: 440)");
  prm.declare_entry("penalty factor", "50", Double(1e-3),
                    "contact penalty slope K = factor · E / h_c [-]");
  prm.leave_subsection();
}

void declare_parameters(ParameterHandler& prm)
{
  // Scene/type offers every registered scene type (app/scenes/scene.h), each declaring its
  // sections.
  std::string names, descriptions;
  for (const auto& [name, type] : scene_registry())
  {
    names += (names.empty() ? "" : "|") + name;
    descriptions += (descriptions.empty() ? "" : "; ") + name + ": " + type.description;
  }
  prm.enter_subsection("Scene");
  prm.declare_entry("type", default_scene_type, Selection(names), "what to mesh — " + descriptions);
  prm.declare_entry("mesh file", "scene.msh", Anything(),
                    "name of the .msh file written into the -o folder");
  prm.leave_subsection();
  for (const auto& [name, type] : scene_registry())
    type.declare_parameters(prm);

  // The mesh sizes of every scene type.
  declare_scene_mesh_parameters(prm, geometry::GearPairSceneSpec().mesh, true);
  declare_deck_parameters(prm);
}

// SI quantities of the scene in the units of the parameter files.
void add_quantity(Report& report, const geometry::SceneQuantity& q)
{
  if (q.unit == "m")
    report.add_value(q.key, q.value / mm, "mm", q.description);
  else if (q.unit == "Pa")
    report.add_value(q.key, q.value / 1e6, "MPa", q.description);
  else if (q.unit == "rad")
    report.add_value(q.key, q.value / degree, "deg", q.description);
  else
    report.add_value(q.key, q.value, q.unit, q.description);
}

void report_scene(const geometry::SceneInfo& info, const Scene& scene, Report& report)
{
  std::string ids;
  for (const auto& [id, name] : info.material_names)
    ids += (ids.empty() ? "" : ", ") + std::to_string(id) + " " + name;
  report.add_text("material_ids", ids);
  ids = "0 free surface";
  for (const auto& [id, name] : info.boundary_names)
    ids += ", " + std::to_string(id) + " " + name;
  report.add_text("boundary_ids", ids);

  for (const auto& q : info.quantities)
    add_quantity(report, q);
  scene.report(info, report);

  report.add_value("contact_size", info.contact_size / mm, "mm",
                   "h_c, cell size at the contacts (smallest)");
  report.add_value("largest_edge_ratio_at_contact", info.mesh.largest_edge_ratio_at_focus, "-",
                   "longest cell edge at a contact point / its h_c (≤ 1)");
  report.add_value("fine_radius", info.fine_radius / mm, "mm", "radius meshed at h_c (largest)");
  report.add_value("body_size", info.body_size / mm, "mm", "cell size in the bodies");
  report.add_value("rim_size", info.rim_size / mm, "mm", "largest cell size (rims)");
  report.add_value("cells", info.mesh.n_cells, "-",
                   info.dimension == 2 ? "quadrilaterals" : "hexahedra");
  // The count a 3D scene was extruded with (Mesh/layers, or what `auto` chose: a helical pair's
  // follows ε_β), which the cell count multiplies.
  if (info.dimension == 3)
    report.add_value("layers", info.mesh.layers, "-", "hexahedron layers across the face width");
  if (info.mesh.removed_cells > 0)
    report.add_value(
        "cells_removed", info.mesh.removed_cells, "-",
        "hexahedra of partial-width faults left out (counted neither above nor below)");
  for (const auto& [id, count] : info.mesh.cells_per_body)
    report.add_value("cells_material_" + std::to_string(id), count, "-",
                     "cells of " + info.material_names.at(id));
  report.add_value("vertices", info.mesh.n_vertices, "-", "mesh vertices");
  report.add_value("min_scaled_jacobian", info.mesh.min_scaled_jacobian, "-",
                   "minimum scaled Jacobian (1: square)");
  report.add_value("mean_scaled_jacobian", info.mesh.mean_scaled_jacobian, "-",
                   "mean scaled Jacobian");
  report.add_value("meshing_attempts", info.mesh.meshing_attempts, "-",
                   "mesh generations until the contact size was met");
  report.add_value("time_geometry", info.mesh.time_geometry, "s", "building the gmsh model");
  report.add_value("time_meshing", info.mesh.time_meshing, "s", "mesh generation");
  report.add_value("time_checking", info.mesh.time_checking, "s", "cell type and quality checks");
  report.add_value("time_writing", info.mesh.time_writing, "s", "writing the .msh file");
  report.add_value("time_total", info.time_total, "s", "the whole scene");

  auto& table = report.add_table(
      "contacts",
      {"x", "y", "normal_x", "normal_y", "radius_1", "radius_2", "normal_force", "hertz_half_width",
       "gap", "contact_size", "fine_radius", "feature_1", "feature_2"},
      {"mm", "mm", "-", "-", "mm", "mm", "N", "mm", "mm", "mm", "mm", "-", "-"});
  for (const auto& c : info.contacts)
    table.add_row({c.point.x() / mm, c.point.y() / mm, c.normal.x(), c.normal.y(),
                   c.first_curvature_radius / mm, c.second_curvature_radius / mm, c.normal_force,
                   c.hertz_half_width / mm, c.gap / mm, c.contact_size / mm, c.fine_radius / mm,
                   double(c.first_feature), double(c.second_feature)});
}

struct DeckRequest
{
  bool write = false;   // write the CalculiX/Abaqus deck
  bool keep_msh = true; // keep the .msh in the output folder
  DeckOptions options;
};

DeckRequest parse_deck_request(ParameterHandler& prm)
{
  DeckRequest request;
  prm.enter_subsection("Mesh");
  const std::string format = prm.get("format");
  prm.leave_subsection();
  request.write = format != "msh";
  request.keep_msh = format != "inp";
  prm.enter_subsection("Abaqus deck");
  request.options.element_2d =
      geometry::parse_element_2d(prm.get("2D elements"), "Abaqus deck/2D elements");
  request.options.friction = prm.get_double("friction coefficient");
  request.options.penalty_factor = prm.get_double("penalty factor");
  request.options.output_torque = prm.get_double("output torque");
  prm.leave_subsection();
  return request;
}

// The deck next to (or instead of) the .msh; without -o it is written to scratch and removed,
// so every check of the export still runs.
void write_deck(const geometry::SceneInfo& info, geometry::AbaqusDeckSpec deck,
                const DeckRequest& request, const std::string& msh_name, CommandContext& context)
{
  deck.element_2d = request.options.element_2d;
  const std::string name = std::filesystem::path(msh_name).replace_extension(".inp").string();
  if (context.writes_files())
  {
    geometry::write_abaqus_deck(info, deck,
                                context.output_file(name, "CalculiX/Abaqus input deck (ccx -i)"));
    context.report.add_value("deck_penalty", deck.penalty, "Pa/m",
                             "contact penalty slope of the deck");
    for (const auto& body : deck.rigid_bodies)
      if (body.pushed)
        context.report.add_value(
            "deck_closing_displacement_" + body.name, body.closing_displacement / mm, "mm",
            "displacement prescribed in the deck's first step (" + body.name + ")");
      else
        context.report.add_value(
            "deck_closing_rotation_" + body.name, body.closing_rotation * 1e6, "µrad",
            "rotation prescribed in the deck's first step (" + body.name + ")");
    return;
  }
  const std::filesystem::path scratch = std::filesystem::path(scratch_directory()) / "deck.inp";
  try
  {
    geometry::write_abaqus_deck(info, deck, scratch.string());
  }
  catch (...)
  {
    std::filesystem::remove(scratch);
    throw;
  }
  std::filesystem::remove(scratch);
}

void run(ParameterHandler& prm, CommandContext& context)
{
  prm.enter_subsection("Scene");
  const std::string type = prm.get("type");
  const std::string file_name = prm.get("mesh file");
  prm.leave_subsection();
  if (file_name.empty() || file_name.find('/') != std::string::npos ||
      std::filesystem::path(file_name).extension() != ".msh")
    throw InputError("Scene/mesh file", "must be a plain file name ending in .msh");
  const DeckRequest deck = parse_deck_request(prm);

  // Parse everything first: a bad parameter must stop the command before gmsh runs.
  if (type != default_scene_type)
  {
    // Micro-geometry is defined on involute flanks: refuse it on other scene types.
    const std::string modified = first_modified_entry(read_tooth_modification_text(prm));
    if (!modified.empty())
      throw InputError(modified, "tooth modifications apply to the involute teeth of the "
                                 "gear-pair scene only, not to a " +
                                     type + " scene (set it to 0)");
  }
  const std::unique_ptr<Scene> scene = scene_registry().at(type).parse(prm);
  if (deck.write)
    scene->prepare_for_deck();

  std::string path;
  std::filesystem::path scratch;
  if (context.writes_files() && deck.keep_msh)
    path =
        context.output_file(file_name, "scene mesh (ASCII .msh 4.1, coordinates in metres, ids in "
                                       "summary.json)");
  else
  {
    scratch = std::filesystem::path(scratch_directory()) / "mesh.msh";
    path = scratch.string();
  }
  geometry::SceneInfo info;
  try
  {
    info = scene->write_mesh(path);
    if (deck.write)
      write_deck(info, scene->deck_spec(info, deck.options), deck, file_name, context);
    // The geometry and mesh as a picture (from the .msh, before a scratch copy is removed).
    if (context.writes_files() && context.is_root())
      context.plot("plot_mesh.py", {path}, "scene_mesh.png",
                   "the scene's geometry and mesh, with a zoom on the contact zones");
  }
  catch (...)
  {
    if (!scratch.empty())
      std::filesystem::remove(scratch);
    throw;
  }
  if (!scratch.empty())
    std::filesystem::remove(scratch);

  context.pcout << "mesh: " << info.kind << ", " << info.mesh.n_cells << " cells in "
                << info.time_total << " s" << std::endl;
  report_scene(info, *scene, context.report);
}

const CommandRegistration registration(
    {"mesh", "FE mesh of a scene (gear pair at one position, cylinders, cycloid) with gmsh",
     "Writes the mesh of one FE scene as ASCII .msh 4.1 (deal.II GridIn::read_msh): for a gear\n"
     "pair a few teeth of each gear around the contacts predicted along the line of action, with\n"
     "rim and bore, the wheel placed in mesh; all quadrilateral (2D) or hexahedra extruded over\n"
     "the face width (3D), sizes graded from h_c at the contacts (default a tenth of the Hertz\n"
     "half-width) to the body size. Physical groups: material ids 1 (pinion, disc, cylinder 1),\n"
     "2 (wheel, rollers, cylinder 2); boundary ids 1/2 bores (roller pins), 3/4 candidate\n"
     "contact surfaces (gear pair: one id per loaded flank, 200 + j on pinion tooth j and\n"
     "400 + j on the wheel tooth meshing it), 5/6 sector cuts (flat faces), 7 side faces (3D),\n"
     "8 output-pin holes, 0 free. Leftover triangles or inverted cells are an error.\n"
     "Coordinates in metres: `gearstiff contact` reads the file with Mesh/Length unit = 1.",
     declare_parameters, run});
} // namespace
