// `gearstiff contact`: two-body frictional contact on any quadrilateral/hexahedral .msh, with
// the bodies, surfaces and supports named by their gmsh physical groups. Without a mesh file it
// runs the built-in Hertz case (two steel cylinders R1 = 10 mm, R2 = 15 mm pressed together in
// plane strain) and compares with Hertz's half-width and peak pressure.
//
//   gearstiff contact                         built-in Hertz case
//   gearstiff contact case.prm -o out         a user mesh; VTU, CSV, JSON into out/
#include "app/core/command.h"
#include "app/scenes/fe_contact_parameters.h"
#include "contact/contact_problem.h"
#include "contact/cylinder_pair.h"
#include "errors/errors.h"
#include "errors/format.h"
#include "errors/limits.h"
#include "fem/abaqus_reader.h"
#include "fem/mesh.h"
#include "fem/small_strain.h"
#include "kinematics/hertz.h"

#include <cmath>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_tools.h>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace dealii;
using namespace gearstiff;
using namespace gearstiff::app;

std::vector<std::string> split(const std::string& text, char separator)
{
  std::vector<std::string> parts;
  for (const auto& part : Utilities::split_string_list(text, separator))
    if (!part.empty())
      parts.push_back(part);
  return parts;
}

std::vector<double> numbers(const std::string& text, const std::string& parameter)
{
  std::vector<double> values;
  for (const auto& item : split(text, ','))
  {
    try
    {
      std::size_t used = 0;
      values.push_back(std::stod(item, &used));
      if (used != item.size())
        throw std::invalid_argument(item);
    }
    catch (const std::exception&)
    {
      throw InputError(parameter, "'" + item + "' is not a number");
    }
  }
  return values;
}

// "name: a, b, c" -> (name, {a, b, c}); entries separated by ';'.
std::vector<std::pair<std::string, std::vector<double>>> named_vectors(const std::string& text,
                                                                       const std::string& parameter)
{
  std::vector<std::pair<std::string, std::vector<double>>> entries;
  for (const auto& entry : split(text, ';'))
  {
    const auto colon = entry.find(':');
    if (colon == std::string::npos)
      throw InputError(parameter, "entry '" + entry + "' is not of the form 'group: values'");
    entries.emplace_back(Utilities::trim(entry.substr(0, colon)),
                         numbers(entry.substr(colon + 1), parameter));
  }
  return entries;
}

// The built-in case's mesh grows as 1/fine size²: refuse what could not finish.
void check_built_in_size(const contact::CylinderPairGeometry& geometry, const unsigned int dim)
{
  const double cells = contact::cylinder_pair_cells(geometry, dim);
  const double limit = dim == 3 ? limits::max_cells_3d : limits::max_cells_2d;
  if (cells > limit)
  {
    std::ostringstream reason;
    reason.precision(2);
    reason << "the built-in mesh would have about " << cells << " cells (limit " << limit
           << ", docs/limits.md); meshing and solving it could not finish: use a larger size "
              "(default 0.00625 mm)";
    throw InputError("Mesh/Built-in fine size", reason.str());
  }
}

// m, the range of body sizes a mesh in the right unit spans: from a watch gear to a wind-turbine
// stage. A mesh outside it by a factor of 1000 is almost surely in another length unit. Inside
// the wider range but outside the usual one (1 mm to 2 m), bad contact geometry is more likely
// a unit mistake than a modelling one, and its message says so.
constexpr double smallest_plausible_extent = 1e-4;
constexpr double largest_plausible_extent = 20.;
constexpr double smallest_usual_extent = 1e-3;
constexpr double largest_usual_extent = 2.;

std::string millimetres(const double metres)
{
  std::ostringstream s;
  s.precision(3);
  s << metres * 1e3 << " mm";
  return s.str();
}

template <int dim>
void check_mesh_extent(const Triangulation<dim>& tria, const double unit)
{
  const double extent = GridTools::diameter(tria);
  if (!(extent >= smallest_plausible_extent && extent <= largest_plausible_extent))
  {
    // The unit that gives machine-part sizes, if one does (a `gearstiff mesh` scene is in
    // metres: Length unit = 1).
    std::string suggestion;
    for (const auto& [candidate, name] : std::vector<std::pair<double, std::string>>{
             {1e-3, "mm"}, {1., "m"}, {0.0254, "inches"}, {1e-6, "µm"}})
      if (candidate != unit && suggestion.empty())
      {
        const double span = extent / unit * candidate;
        if (span >= smallest_usual_extent && span <= largest_usual_extent)
          suggestion = "; with Length unit = " + format_number(candidate, 4) + " (" + name +
                       ") it spans " + millimetres(span);
      }
    throw InputError("Mesh/Length unit",
                     "the mesh spans " + millimetres(extent) + " with " + format_number(unit, 4) +
                         " m per mesh unit, implausible for machine parts: check the length unit "
                         "of the mesh (mm expected, Length unit = 1e-3" +
                         suggestion + ")");
  }
}

// Runs the contact problem of a user mesh. Bad geometry (bodies that overlap, or lie beyond the
// search distance) in a mesh of unusual size usually means a mesh in another unit than the one
// declared, so the message says so.
template <int dim>
const contact::ContactResults<dim>& run_with_unit_hint(contact::ContactProblem<dim>& problem,
                                                       const double unit)
{
  try
  {
    return problem.run();
  }
  catch (const InputError& e)
  {
    const double extent = GridTools::diameter(problem.system().triangulation());
    if (extent >= smallest_usual_extent && extent <= largest_usual_extent)
      throw;
    throw InputError(e.parameter(), e.reason() + "; the mesh spans " + millimetres(extent) +
                                        " at Mesh/Length unit = " + format_number(unit, 4) +
                                        " m: check the length unit of the mesh (mm expected)");
  }
}

void declare_parameters(ParameterHandler& prm)
{
  prm.enter_subsection("Mesh");
  prm.declare_entry("File", "", Patterns::Anything(),
                    "gmsh .msh of quadrilaterals (2D) or hexahedra (3D) with physical groups, or a "
                    "CalculiX/Abaqus .inp (element sets and surfaces as the groups); "
                    "empty: the built-in Hertz case (groups 'upper', 'lower', 'upper contact', "
                    "'upper top', 'lower contact', 'lower bottom')");
  prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3),
                    "space dimension of the mesh [-] (3: the built-in case is extruded by the "
                    "thickness into hexahedra)");
  prm.declare_entry("Length unit", "1e-3", Patterns::Double(1e-12),
                    "metres per mesh length unit [m] (1e-3: the mesh is in mm)");
  prm.declare_entry("Built-in fine size", "0.00625", Patterns::Double(1e-6),
                    "cell size at the contact point of the built-in Hertz case [mm]");
  prm.leave_subsection();

  declare_fe_contact_parameters(prm);
  prm.enter_subsection("Contact");
  prm.declare_entry("Slave surfaces", "upper contact", Patterns::Anything(),
                    "physical groups (comma-separated) of the slave surface; mesh it at least as "
                    "finely as the master");
  prm.declare_entry("Master surfaces", "lower contact", Patterns::Anything(),
                    "physical groups (comma-separated) of the master surface");
  prm.leave_subsection();

  prm.enter_subsection("Bodies");
  prm.declare_entry("Names", "upper, lower", Patterns::Anything(),
                    "physical groups of the bodies (comma-separated)");
  prm.declare_entry("Young's moduli", "210, 210", Patterns::Anything(),
                    "Young's modulus of each body, one per name [GPa]");
  prm.declare_entry("Poisson's ratios", "0.3, 0.3", Patterns::Anything(),
                    "Poisson's ratio of each body, one per name [-]");
  prm.leave_subsection();

  prm.enter_subsection("Supports");
  prm.declare_entry("Fixed", "lower bottom", Patterns::Anything(),
                    "physical groups (comma-separated) held fixed");
  prm.declare_entry("Displacements", "upper top: 0, -0.004", Patterns::Anything(),
                    "prescribed displacements 'group: ux, uy[, uz]' in mm, ';'-separated");
  prm.declare_entry("Tractions", "", Patterns::Anything(),
                    "surface tractions 'group: tx, ty[, tz]' in MPa, ';'-separated");
  prm.declare_entry("Hub rotations", "", Patterns::Anything(),
                    "rigid hubs with a prescribed rotation 'group: angle, x0, y0' (angle in "
                    "degrees, axis point in mm), ';'-separated");
  prm.declare_entry("Hub torques", "", Patterns::Anything(),
                    "rigid hubs driven by a torque 'group: torque, x0, y0' (N·m about +z, axis "
                    "point in mm), the rotation is solved for; ';'-separated");
  prm.leave_subsection();

  prm.enter_subsection("Output");
  prm.declare_entry("VTU", "true", Patterns::Bool(), "write the fields as VTU/PVTU (with -o only)");
  prm.leave_subsection();
}

// The mesh of Mesh/File by its extension: ".inp" a CalculiX/Abaqus deck, anything else gmsh.
template <int dim>
fem::PhysicalNames read_mesh_file(const std::string& file, double unit, Triangulation<dim>& tria)
{
  if (std::filesystem::path(file).extension() == ".inp")
    return fem::read_abaqus(file, unit, tria, "Mesh/File");
  return fem::read_msh(file, unit, tria, "Mesh/File");
}

// The boundary id of the physical group `name` (a surface in 3D, a curve in 2D).
template <int dim>
types::boundary_id face_id(const fem::PhysicalNames& names, const std::string& name,
                           const std::string& parameter)
{
  const auto found = names.faces.find(name);
  if (found == names.faces.end())
    throw InputError(parameter, "the mesh has no " + std::to_string(dim - 1) +
                                    "D physical group named '" + name + "'");
  return static_cast<types::boundary_id>(found->second);
}

// The mesh of the problem and what the rest of the command needs to know about it.
struct ContactMesh
{
  fem::PhysicalNames names;
  std::string file;                       // Mesh/File; empty: the built-in cylinder pair
  double unit = 1.;                       // m per mesh length unit
  contact::CylinderPairGeometry geometry; // the built-in pair's (for the Hertz comparison)
};

// The bodies and surfaces: the built-in cylinder pair without Mesh/File, else the named mesh.
template <int dim>
ContactMesh make_or_read_mesh(ParameterHandler& prm, const fem::ElasticityParameters& elasticity,
                              contact::ContactProblem<dim>& problem)
{
  ContactMesh mesh;
  prm.enter_subsection("Mesh");
  mesh.file = prm.get("File");
  mesh.unit = prm.get_double("Length unit");
  mesh.geometry.fine_size = prm.get_double("Built-in fine size") * 1e-3;
  prm.leave_subsection();
  if (!mesh.file.empty())
  {
    mesh.names = read_mesh_file<dim>(mesh.file, mesh.unit, problem.system().triangulation());
    check_mesh_extent(problem.system().triangulation(), mesh.unit);
    return mesh;
  }
  if (dim == 3)
    mesh.geometry.depth = elasticity.thickness;
  check_built_in_size(mesh.geometry, dim);
  contact::make_cylinder_pair(mesh.geometry, problem.system().triangulation());
  mesh.names.cells = {{"upper", contact::upper_body}, {"lower", contact::lower_body}};
  mesh.names.faces = {{"upper contact", contact::upper_contact},
                      {"upper top", contact::upper_top},
                      {"lower contact", contact::lower_contact},
                      {"lower bottom", contact::lower_bottom}};
  if (dim == 3)
    mesh.names.faces["extrusion faces"] = contact::extrusion_faces;
  return mesh;
}

// Bodies/: one material per named body, in SI units.
template <int dim>
std::map<types::material_id, fem::Material> parse_bodies(ParameterHandler& prm,
                                                         const fem::PhysicalNames& names)
{
  prm.enter_subsection("Bodies");
  const auto body_names = split(prm.get("Names"), ',');
  const auto moduli = numbers(prm.get("Young's moduli"), "Bodies/Young's moduli");
  const auto ratios = numbers(prm.get("Poisson's ratios"), "Bodies/Poisson's ratios");
  prm.leave_subsection();
  if (moduli.size() != body_names.size())
    throw InputError("Bodies/Young's moduli", "give one value per body name");
  if (ratios.size() != body_names.size())
    throw InputError("Bodies/Poisson's ratios", "give one value per body name");
  std::map<types::material_id, fem::Material> materials;
  for (unsigned int b = 0; b < body_names.size(); ++b)
  {
    const auto found = names.cells.find(body_names[b]);
    if (found == names.cells.end())
      throw InputError("Bodies/Names", "the mesh has no " + std::to_string(dim) +
                                           "D physical group named '" + body_names[b] + "'");
    kinematics::check_young_modulus(moduli[b] * 1e9, "Bodies/Young's moduli");
    kinematics::check_poisson_ratio(ratios[b], "Bodies/Poisson's ratios");
    materials[found->second] = fem::Material{moduli[b] * 1e9, ratios[b]};
  }
  return materials;
}

// Supports/: fixed faces, prescribed displacements [mm], tractions [MPa], rigid hubs turned by
// an angle [deg] or loaded by a torque [N·m] about an axis [mm].
template <int dim>
void add_supports(ParameterHandler& prm, const fem::PhysicalNames& names,
                  contact::ContactProblem<dim>& problem)
{
  prm.enter_subsection("Supports");
  for (const auto& name : split(prm.get("Fixed"), ','))
    problem.add_displacement(face_id<dim>(names, name, "Supports/Fixed"), Tensor<1, dim>(), name);
  for (const auto& [name, values] :
       named_vectors(prm.get("Displacements"), "Supports/Displacements"))
  {
    if (values.size() != dim)
      throw InputError("Supports/Displacements",
                       "'" + name + "' needs " + std::to_string(dim) + " components (mm)");
    Tensor<1, dim> u;
    for (unsigned int c = 0; c < dim; ++c)
      u[c] = values[c] * 1e-3;
    problem.add_displacement(face_id<dim>(names, name, "Supports/Displacements"), u, name);
  }
  for (const auto& [name, values] : named_vectors(prm.get("Tractions"), "Supports/Tractions"))
  {
    if (values.size() != dim)
      throw InputError("Supports/Tractions",
                       "'" + name + "' needs " + std::to_string(dim) + " components (MPa)");
    Tensor<1, dim> t;
    for (unsigned int c = 0; c < dim; ++c)
      t[c] = values[c] * 1e6;
    problem.system().add_traction(face_id<dim>(names, name, "Supports/Tractions"), t);
  }
  for (const auto& [key, control, scale] :
       {std::tuple{"Hub rotations", fem::RigidHub<dim>::Control::rotation, M_PI / 180.},
        std::tuple{"Hub torques", fem::RigidHub<dim>::Control::torque, 1.}})
  {
    const std::string parameter = std::string("Supports/") + key;
    for (const auto& [name, values] : named_vectors(prm.get(key), parameter))
    {
      if (values.size() != 3)
        throw InputError(parameter, "'" + name + "' needs 'value, x0, y0'");
      Point<dim> axis;
      axis[0] = values[1] * 1e-3;
      axis[1] = values[2] * 1e-3;
      problem.add_rigid_hub(face_id<dim>(names, name, parameter), axis, control, values[0] * scale,
                            name);
    }
  }
  prm.leave_subsection();
}

// Contact/: one pair of the named slave and master surfaces.
template <int dim>
void add_contact_pair(ParameterHandler& prm, const fem::PhysicalNames& names,
                      contact::ContactProblem<dim>& problem)
{
  prm.enter_subsection("Contact");
  const auto slave_names = split(prm.get("Slave surfaces"), ',');
  const auto master_names = split(prm.get("Master surfaces"), ',');
  prm.leave_subsection();
  std::vector<types::boundary_id> slave, master;
  for (const auto& name : slave_names)
    slave.push_back(face_id<dim>(names, name, "Contact/Slave surfaces"));
  for (const auto& name : master_names)
    master.push_back(face_id<dim>(names, name, "Contact/Master surfaces"));
  if (slave.empty() || master.empty())
    throw InputError("Contact/Slave surfaces", "name at least one slave and one master surface");
  auto joined = [](const std::vector<std::string>& parts)
  {
    std::string text;
    for (const auto& part : parts)
      text += (text.empty() ? "" : ",") + part;
    return text;
  };
  problem.add_contact_pair(slave, master, joined(slave_names) + " on " + joined(master_names));
}

// The built-in 2D case against Hertz with the computed load per length (Johnson 1985, eq.
// 4.43-4.45).
template <int dim>
void report_hertz(Report& report, const contact::ContactResults<dim>& result,
                  const contact::CylinderPairGeometry& geometry,
                  const std::map<types::material_id, fem::Material>& materials, double thickness)
{
  const double load = std::abs(result.supports.back().force[1]) / thickness;
  double inverse_modulus = 0;
  for (const auto& [id, m] : materials)
    inverse_modulus += (1. - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
  const kinematics::HertzLineContact hertz = kinematics::hertz_line_contact(
      load, geometry.upper_radius, geometry.lower_radius, 1. / inverse_modulus);
  const auto& pair = result.pairs.front();
  report.add_value("load_per_length", load * 1e-3, "N/mm", "Hertz load P");
  std::vector<double> x, p;
  for (const auto& point : pair.points)
    if (point.state != contact::NodeState::open)
    {
      x.push_back(point.position[0]);
      p.push_back(point.pressure);
    }
  const contact::HertzLineContact fitted = contact::fit_hertz_profile(x, p);
  report.add_value("closed_half_extent", 0.5 * pair.contact_length * 1e3, "mm",
                   "half the extent of the closed nodes");
  report.add_compared_value("half_width", fitted.half_width * 1e3, hertz.half_width * 1e3, "mm",
                            "contact half-width (fit of the Hertz profile)",
                            "Hertz, Johnson 1985 eq. 4.43");
  report.add_compared_value("peak_pressure", pair.max_pressure * 1e-6, hertz.peak_pressure * 1e-6,
                            "MPa", "peak pressure", "Hertz, Johnson 1985 eq. 4.45");
}

// Cost, pairs, supports and the active-set history of a solved problem.
template <int dim>
void report_contact(Report& report, const contact::ContactResults<dim>& result,
                    const fem::LinearSolverParameters& linear_solver)
{
  report.add_text("method", "dual mortar, primal-dual active set, Coulomb as successive "
                            "Tresca problems; " +
                                fem::to_string(linear_solver.method));
  report.add_value("dofs", result.n_dofs, "-", "degrees of freedom");
  report.add_value("mpi_ranks", result.n_mpi_ranks, "-", "MPI ranks");
  report.add_value("active_set_iterations", result.active_set_iterations, "-",
                   "active-set (semismooth Newton) iterations, all load steps");
  report.add_value("time_setup", result.setup_time, "s", "setup (DoFs, stiffness, mortar)");
  report.add_value("time_assembly", result.assembly_time, "s", "assembly, all iterations");
  report.add_value("time_solve", result.solve_time, "s", "linear solves, all iterations");
  report.add_value("time_per_iteration",
                   (result.assembly_time + result.solve_time) / result.active_set_iterations, "s",
                   "assembly + solve per iteration");
  report.add_value("time_total", result.total_time, "s", "total");
  for (const auto& pair : result.pairs)
  {
    report.add_text("contact_pair", pair.name);
    report.add_value("normal_force", pair.normal_force, "N", "sum of normal contact forces");
    report.add_value("tangential_force", pair.tangential_force, "N",
                     "resultant tangential contact force");
    report.add_value("max_pressure", pair.max_pressure * 1e-6, "MPa", "peak contact pressure");
    // What a rotation or displacement spends before the bodies touch (the chords of a meshed
    // curve lie inside it: a gear scene's flanks start nanometres apart).
    double smallest_gap = std::numeric_limits<double>::max();
    for (const auto& point : pair.points)
      smallest_gap = std::min(smallest_gap, point.initial_gap);
    if (!pair.points.empty())
      report.add_value("initial_gap", smallest_gap * 1e6, "µm",
                       "smallest initial normal gap of the slave nodes (negative: overlap)");
    report.add_value("contact_length", pair.contact_length * 1e3, "mm",
                     "extent of the closed nodes along the surface");
    report.add_value("closed_nodes", pair.n_closed, "-", "active-set size (closed nodes)");
    report.add_value("stick_nodes", pair.n_stick, "-", "sticking nodes");
    report.add_value("slip_nodes", pair.n_slip, "-", "slipping nodes");
  }
  for (const auto& support : result.supports)
  {
    const std::string key = "support_" + support.name;
    for (unsigned int c = 0; c < dim; ++c)
      report.add_value(key + "_force_" + std::string(1, "xyz"[c]), support.force[c], "N",
                       support.name + ": reaction force " + std::string(1, "xyz"[c]));
    report.add_value(key + "_torque", support.torque, "N·m",
                     support.name + ": reaction torque about +z through its axis");
    if (support.is_hub)
      report.add_value(key + "_rotation", support.rotation * 1e6, "µrad",
                       support.name + ": hub rotation");
  }
}

// The active-set history table, and with -o the surface CSV, the VTU fields and the chart.
template <int dim>
void write_contact_outputs(ParameterHandler& prm, CommandContext& context,
                           const contact::ContactProblem<dim>& problem,
                           const contact::ContactResults<dim>& result)
{
  ReportTable& history = context.report.add_table(
      "active_set_history",
      {"load_step", "iteration", "closed", "stick", "slip", "changed", "time"},
      {"-", "-", "-", "-", "-", "-", "s"});
  for (const auto& record : result.history)
    history.add_row({double(record.load_step), double(record.iteration), double(record.n_closed),
                     double(record.n_stick), double(record.n_slip), double(record.n_changed),
                     record.time});

  if (!context.writes_files())
    return;
  std::string csv;
  if (context.is_root())
  {
    csv = context.write_output(
        "contact_surface.csv", "pressure, shear, gap, slip along each contact surface",
        [&](std::ostream& out)
        {
          out << "pair,coordinate_mm,x_mm,y_mm,pressure_MPa,shear_MPa,gap_um,slip_um,state\n";
          for (unsigned int p = 0; p < result.pairs.size(); ++p)
            for (const auto& point : result.pairs[p].points)
              out << p << ',' << point.coordinate * 1e3 << ',' << point.position[0] * 1e3 << ','
                  << point.position[1] * 1e3 << ',' << point.pressure * 1e-6 << ','
                  << point.shear.norm() * 1e-6 << ',' << point.gap * 1e6 << ','
                  << point.slip.norm() * 1e6 << ',' << static_cast<int>(point.state) << '\n';
        });
  }
  prm.enter_subsection("Output");
  const bool vtu = prm.get_bool("VTU");
  prm.leave_subsection();
  if (vtu)
  {
    const std::string record = context.output_file("contact.pvtu", "fields (ParaView)");
    const auto files =
        problem.output_results(std::filesystem::path(record).parent_path().string(), "contact");
    for (const auto& file : files)
      if (file != "contact.pvtu")
        context.report.add_output_file(file, "fields of one MPI rank");
  }
  if (context.is_root())
    context.plot("plot_contact.py", {csv}, "contact_pressure.png",
                 "contact pressure along the surface");
}

template <int dim>
void run_contact(ParameterHandler& prm, CommandContext& context)
{
  fem::ElasticityParameters elasticity;
  fem::LinearSolverParameters linear_solver;
  contact::ContactParameters contact_parameters;
  parse_fe_contact_parameters(prm, elasticity, linear_solver, contact_parameters);
  contact::ContactProblem<dim> problem(context.mpi_communicator, elasticity, linear_solver,
                                       contact_parameters);
  const ContactMesh mesh = make_or_read_mesh(prm, elasticity, problem);
  const bool built_in = mesh.file.empty();
  const auto materials = parse_bodies<dim>(prm, mesh.names);
  problem.system().set_materials(materials, "Bodies/Names");
  add_supports(prm, mesh.names, problem);
  add_contact_pair(prm, mesh.names, problem);
  // The active set of a large 3D mesh takes minutes: one line per iteration from rank 0.
  problem.set_progress(
      [&context](const std::string& line)
      {
        if (context.is_root())
          context.progress("contact", line);
      });

  context.pcout << "contact: " << (built_in ? "built-in Hertz case" : mesh.file) << ", " << dim
                << "D, FE_Q(" << elasticity.degree << "), "
                << Utilities::MPI::n_mpi_processes(context.mpi_communicator) << " rank(s)\n";
  const contact::ContactResults<dim>& result =
      built_in ? problem.run() : run_with_unit_hint(problem, mesh.unit);
  // A load far beyond the linear model still returns numbers; refuse them.
  fem::check_small_strain(problem.system().get_dof_handler(), problem.solution(),
                          "Supports (the loads)");

  report_contact(context.report, result, linear_solver);
  if (built_in && dim == 2)
    report_hertz(context.report, result, mesh.geometry, materials, elasticity.thickness);
  write_contact_outputs(prm, context, problem, result);
}

void run(ParameterHandler& prm, CommandContext& context)
{
  prm.enter_subsection("Mesh");
  const int dim = prm.get_integer("Dimension");
  prm.leave_subsection();
  if (dim == 2)
    run_contact<2>(prm, context);
  else
    run_contact<3>(prm, context);
}

const CommandRegistration registration(Command{
    "contact", "two-body frictional contact (dual mortar, active set) on a gmsh mesh",
    "Solves small-sliding frictional contact between two elastic bodies of a mesh (plane "
    "strain, plane stress or 3D), named by physical groups: bodies with E and ν, supports "
    "(fixed, displacements, tractions, rigid hubs with a rotation or a torque), a slave and a "
    "master surface. Non-penetration is exact (dual mortar multipliers, primal-dual active "
    "set), friction is Coulomb. Reports reactions, hub rotations, contact forces and pressures, "
    "active-set iterations and timings; writes VTU/PVTU, CSV and JSON with -o. Without a mesh "
    "file it runs the Hertz case of two steel cylinders and compares with Hertz's formulas.",
    declare_parameters, run});
} // namespace
