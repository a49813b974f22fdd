// `gearstiff cycloid-loads [case.prm]`: the load distribution of a cycloid (Cyclo) drive from the
// FE contact solver — roller forces P_i, output-pin forces Q_j, eccentric-bearing force R, torque
// balances, loaded counts, contact pressures, disc stress, output rotation — for the nominal and
// the corrected disc profile, beside the analytic rigid-disc estimate and the published values of
// docs/references.md §4 (Chmurawa & Łokiec); torsional stiffness and lost motion from a torque
// ramp; optionally a crank-angle sweep. Load case and its static equivalence:
// stiffness/cycloid_loads.h.
//
//   gearstiff cycloid-loads                                  §4 drive, nominal + ε = 0.27
//   gearstiff cycloid-loads --json                           the figures as JSON
//   mpirun -np 2 gearstiff cycloid-loads --set "Cycloid loads/sweep positions=16" -o out
//
// Files with -o: the tables (CSV), the distribution chart, the sweep traces and the torsion
// curve (PNG), VTU with "Cycloid loads/write vtu=true".
#include "app/core/command.h"
#include "app/core/units.h"
#include "app/cycloid/cycloid_loads_parameters.h"
#include "app/scenes/geometry_parameters.h"
#include "errors/errors.h"
#include "errors/limits.h"
#include "geometry/fields.h"
#include "stiffness/cycloid_sweep.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <unistd.h>

namespace
{
using namespace gearstiff;
using namespace gearstiff::app;

const std::string paper = "docs/references.md §4 (Chmurawa & Łokiec, analytic)";
// docs/references.md §4: analytic P_max = 1711 N, Q_max = 3776 N, eccentric reaction R = 10.3 kN;
// rigid-body ADAMS ≈ 2200 N and ≈ 3800 N.
constexpr double paper_max_roller_force = 1711.; // N
constexpr double paper_max_pin_force = 3776.;    // N
constexpr double paper_bearing_force = 10.3e3;   // N
constexpr double arcmin = M_PI / (180. * 60.);   // rad

// One profile's cases: the position, the torque levels, the sweep.
struct ProfileCases
{
  std::string name; // "nominal" or "corrected"
  unsigned int position = 0, first_level = 0, levels = 0, first_sweep = 0, sweep = 0;
};

std::vector<stiffness::CycloidLoadSettings> profile_settings(const CycloidLoadsParameters& p,
                                                             CommandContext& context)
{
  std::vector<stiffness::CycloidLoadSettings> profiles;
  if (p.nominal)
    profiles.push_back(p.settings);
  if (p.corrected)
  {
    // The correction's own names for its inputs are those of `gearstiff cycloid`.
    const ParameterNames names{
        {geometry::field::correction("contact_arc_ratios"),
         stiffness::field::cycloid_loads("contact_arc_ratio")},
        {geometry::field::correction("clearance_limit"), "Cycloid loads/clearance limit"}};
    const geometry::CycloidCorrection c =
        with_parameter_names(names,
                             [&]
                             {
                               return geometry::solve_cycloid_correction(
                                   p.settings.scene.ring, p.contact_arc_ratio, p.clearance_limit);
                             });
    stiffness::CycloidLoadSettings s = p.settings;
    s.scene.disc = c.corrected_disc(s.scene.ring);
    try
    {
      geometry::roller_clearances(s.scene.ring, s.scene.disc, 0.); // checks the corrected disc
    }
    catch (const InputError& e)
    {
      throw InputError("Cycloid loads/clearance limit",
                       "gives an impossible corrected profile (q_k = " +
                           format_number(c.roller_radius / mm, 6) + " mm): " + e.reason());
    }
    profiles.push_back(s);
    context.report.add_text("correction",
                            "ε = " + format_number(p.contact_arc_ratio, 4) +
                                ": r_k = " + format_number(c.roller_circle_radius / mm, 7) +
                                " mm, q_k = " + format_number(c.roller_radius / mm, 7) +
                                " mm, δ = " + format_number(c.rotation / degree, 6) +
                                "° (gearstiff cycloid)");
  }
  return profiles;
}

// Each rank's scene meshes, in its own scratch folder (removed at exit and on signals).
std::string scratch_stem(MPI_Comm communicator)
{
  const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(communicator);
  return (std::filesystem::path(scratch_directory()) / ("cycloid-" + std::to_string(rank)))
      .string();
}

// Cells of h_c across a contact below which its peak pressure is not resolved: four cells put
// at least three nodes inside the loaded width.
constexpr double contact_resolution_cells = 4.;

// Closed length / h_c of the contact (roller or pin) with the largest pressure.
double peak_contact_cells(const stiffness::CycloidLoadResult& r)
{
  const stiffness::CycloidContactLoad* peak = nullptr;
  for (const auto* list : {&r.rollers, &r.pins})
    for (const auto& load : *list)
      if (load.force > 0. && (peak == nullptr || load.max_pressure > peak->max_pressure))
        peak = &load;
  return peak == nullptr || !(r.contact_size > 0.) ? 0. : peak->contact_length / r.contact_size;
}

// The position's figures, keys prefixed (empty for the first profile).
void report_position(Report& report, const stiffness::CycloidLoadResult& r,
                     const std::string& prefix, const std::string& label, bool compare)
{
  const auto value =
      [&](const std::string& key, double v, const std::string& unit, const std::string& what)
  { report.add_value(prefix + key, v, unit, label + ": " + what); };
  if (compare)
  {
    report.add_compared_value(prefix + "max_roller_force", r.max_roller_force,
                              paper_max_roller_force, "N", label + ": P_max (FE)", paper);
    report.add_compared_value(prefix + "max_pin_force", r.max_pin_force, paper_max_pin_force, "N",
                              label + ": Q_max (FE)", paper);
    report.add_compared_value(prefix + "bearing_force", r.bearing_force, paper_bearing_force, "N",
                              label + ": eccentric-bearing force R (FE)", "docs/references.md §4");
  }
  else
  {
    value("max_roller_force", r.max_roller_force, "N", "P_max (FE)");
    value("max_pin_force", r.max_pin_force, "N", "Q_max (FE)");
    value("bearing_force", r.bearing_force, "N", "eccentric-bearing force R (FE)");
  }
  value("analytic_max_roller_force", r.analytic.max_roller_force, "N",
        "P_max, rigid disc + line-contact compliance");
  value("analytic_max_pin_force", r.analytic.max_pin_force, "N", "Q_max, the same model");
  value("analytic_bearing_force", r.analytic.bearing_force.norm(), "N", "R, the same model");
  value("analytic_output_rotation", r.analytic.output_rotation / arcmin, "arcmin",
        "output rotation θ, the same model (rigid bodies: a lower bound of the FE's)");
  value("bearing_angle", r.bearing_angle / degree, "deg", "α_R in M_h = R·e·cos α_R");
  value("bearing_force_direction", r.bearing_force_direction / degree, "deg",
        "polar angle of R (force on the eccentric)");
  value("input_torque", r.input_torque, "N·m", "M_h = R·e·cos α_R holding the eccentric");
  value("input_torque_ratio", r.input_torque_ratio, "-", "M_h / (M_c/z_s) (1: rigid kinematics)");
  value("loaded_rollers", r.loaded_rollers, "-", "rollers carrying load");
  value("loaded_pins", r.loaded_pins, "-", "output pins carrying load");
  value("disc_force_balance", r.disc_force_balance, "-", "|R + Σ contact forces on the disc|/R");
  value("disc_moment_balance", r.disc_moment_balance, "-",
        "|Σ moments of P_i and Q_j about the disc centre|/M_c");
  value("output_moment_balance", r.output_moment_balance, "-", "|Σ c_j × Q_j − M_c|/M_c");
  value("output_rotation", r.output_rotation / arcmin, "arcmin", "output rotation θ under M_c");
  value("max_contact_pressure", r.max_contact_pressure / 1e6, "MPa", "peak contact pressure");
  // The peak pressure is a converged number only when its contact spans several cells: a Hertz
  // line contact's pressure is an ellipse over 2a (Johnson 1985 eq. 4.43, docs/references.md
  // §6), which a few closed nodes cannot draw. Below contact_resolution_cells cells the value
  // depends on where the nodes fall (790 N gave 515 MPa, 741 N 855 MPa at h_c = 0.08 mm).
  const double cells = peak_contact_cells(r);
  value("peak_contact_cells", cells, "-",
        "closed contact length / h_c at the peak-pressure contact (resolved: >= " +
            format_number(contact_resolution_cells, 2) + ")");
  if (cells < contact_resolution_cells)
    report.add_text(prefix + "pressure unresolved",
                    label + ": the peak-pressure contact spans " + format_number(cells, 2) +
                        " cells of h_c = " + format_number(r.contact_size / mm, 3) + " mm (< " +
                        format_number(contact_resolution_cells, 2) +
                        "): max_contact_pressure is not resolved; forces are. Set Mesh/contact "
                        "size to at most " +
                        format_number(r.contact_size / mm * cells / contact_resolution_cells, 2) +
                        " mm for the pressure");
  value("disc_von_mises", r.disc_von_mises / 1e6, "MPa", "largest von Mises stress in the disc");
  value("n_dofs", r.n_dofs, "-", "DoFs");
  value("active_set_iterations", r.active_set_iterations, "-", "contact active-set iterations");
  value("solve_wall_time", r.total_time, "s", "wall time of the position (scene + solve)");
  value("scene_time", r.scene_time, "s", "gmsh scene: geometry, meshing, checks, writing");
  value("meshing_time", r.meshing_time, "s", "gmsh mesh generation (all attempts)");
  value("meshing_attempts", r.meshing_attempts, "-", "gmsh mesh generations");
  value("read_time", r.read_time, "s", "reading the mesh, contact pairs, supports");
  value("setup_time", r.setup_time, "s", "DoFs, stiffness matrix, mortar coupling");
  value("factorization_time", r.factorization_time, "s", "contact assembly (factorization)");
  value("iteration_time", r.iteration_time, "s", "active-set iterations (linear solves)");
  value("evaluate_time", r.evaluate_time, "s", "forces, von Mises, analytic model");
}

void add_contact_table(Report& report, const std::string& name,
                       const std::vector<ProfileCases>& profiles,
                       const std::vector<stiffness::CycloidLoadResult>& results, bool rollers)
{
  std::vector<std::string> columns{rollers ? "roller" : "pin", "angle"}, units{"-", "deg"};
  for (const auto& pc : profiles)
    for (const std::string c : {"gap", "force", "analytic_force", "max_pressure", "contact_cells"})
    {
      columns.push_back(c + "_" + pc.name);
      units.push_back(c == "gap"             ? "mm"
                      : c == "max_pressure"  ? "MPa"
                      : c == "contact_cells" ? "-"
                                             : "N");
    }
  ReportTable& table = report.add_table(name, columns, units);
  const auto& first = results[profiles[0].position];
  const unsigned int n = rollers ? first.rollers.size() : first.pins.size();
  for (unsigned int k = 0; k < n; ++k)
  {
    std::vector<double> row{double(k), (rollers ? first.rollers : first.pins)[k].angle / degree};
    for (const auto& pc : profiles)
    {
      const auto& l = (rollers ? results[pc.position].rollers : results[pc.position].pins)[k];
      const double h_c = results[pc.position].contact_size;
      // contact_cells: closed length / h_c, below 4 the pressure is unresolved (report text).
      row.insert(row.end(), {l.initial_gap / mm, l.force, l.analytic_force, l.max_pressure / 1e6,
                             h_c > 0. ? l.contact_length / h_c : 0.});
    }
    table.add_row(row);
  }
}

void add_sweep_table(Report& report, const ProfileCases& pc,
                     const std::vector<stiffness::CycloidLoadResult>& results)
{
  const auto& first = results[pc.first_sweep];
  std::vector<std::string> columns{"crank_angle", "max_roller_force", "max_pin_force",
                                   "bearing_force", "output_rotation"};
  std::vector<std::string> units{"deg", "N", "N", "N", "arcmin"};
  for (unsigned int i = 0; i < first.rollers.size(); ++i)
    columns.push_back("P_" + std::to_string(i)), units.push_back("N");
  for (unsigned int j = 0; j < first.pins.size(); ++j)
    columns.push_back("Q_" + std::to_string(j)), units.push_back("N");
  ReportTable& table = report.add_table("cycloid_sweep_" + pc.name, columns, units);
  for (unsigned int k = pc.first_sweep; k < pc.first_sweep + pc.sweep; ++k)
  {
    const auto& r = results[k];
    std::vector<double> row{r.crank_angle / degree, r.max_roller_force, r.max_pin_force,
                            r.bearing_force, r.output_rotation / arcmin};
    for (const auto& l : r.rollers)
      row.push_back(l.force);
    for (const auto& l : r.pins)
      row.push_back(l.force);
    table.add_row(row);
  }
}

// The ramp −M_c → +M_c → −M_c as solved: each level once (frictionless, so path independent:
// the unloading branch repeats the loading one), rows in the order of the ramp.
void add_torsion_table(Report& report, const std::vector<double>& levels,
                       const std::vector<ProfileCases>& profiles,
                       const std::vector<stiffness::CycloidLoadResult>& results)
{
  std::vector<std::string> columns{"torque", "branch"}, units{"N*m", "-"};
  for (const auto& pc : profiles)
    columns.push_back("rotation_" + pc.name), units.push_back("arcmin");
  ReportTable& table = report.add_table("cycloid_torsion", columns, units);
  table.set_categories("branch", {{-1, "unloading"}, {1, "loading"}});
  const unsigned int n = levels.size();
  for (unsigned int step = 0; step + 1 < 2 * n; ++step)
  {
    // Loading branch (+1) up to +M_c, then unloading (−1) back down.
    const bool loading = step < n;
    const unsigned int k = loading ? step : 2 * n - 2 - step;
    std::vector<double> row{levels[k], loading ? 1. : -1.};
    for (const auto& pc : profiles)
      row.push_back(results[pc.first_level + k].output_rotation / arcmin);
    table.add_row(row);
  }
}

// The loops with friction (stiffness::cycloid_hysteresis), one per profile, in the order solved:
// columns profile and branch (rising, falling, the first loading) by name.
void add_hysteresis_table(Report& report, const std::vector<ProfileCases>& profiles,
                          const std::vector<stiffness::CycloidHysteresis>& loops)
{
  ReportTable& table =
      report.add_table("cycloid_hysteresis", {"profile", "torque", "rotation", "branch"},
                       {"-", "N*m", "arcmin", "-"});
  table.set_categories("profile", {{0, "nominal"}, {1, "corrected"}});
  table.set_categories("branch", {{-1, "falling"}, {0, "first loading"}, {1, "rising"}});
  for (unsigned int b = 0; b < profiles.size(); ++b)
    for (const auto& point : loops[b].points)
      table.add_row({profiles[b].name == "nominal" ? 0. : 1., point.torque, point.rotation / arcmin,
                     double(point.branch)});
}

// The work of the run before the first solve: the solves (torque levels and crank angles of
// every profile, spread over the ranks) at the measured time of one solve on the default mesh
// (12 solves in 38.5 s on one rank, docs/cycloid.md), scaled by the cells of the mesh against the
// default as 1/h² of the contact and body sizes. Refused above limits::max_run_seconds, naming the
// parameter that contributes the most solves.
void check_work(const CycloidLoadsParameters& p, std::size_t solves, std::size_t level_solves,
                unsigned int ranks)
{
  constexpr double seconds_per_solve = 38.5 / 12.; // s, default mesh, one rank
  const geometry::CycloidSceneSpec defaults = stiffness::default_cycloid_load_scene();
  const auto& mesh = p.settings.scene.mesh;
  // The contact part dominates the default mesh: cells grow as 1/h_c²; never credited below 1.
  const double contact =
      mesh.contact_size > 0. ? defaults.mesh.contact_size / mesh.contact_size : 1.;
  const double scale = std::max(1., contact * contact);
  const double rounds = std::ceil(double(solves) / std::max(1u, ranks));
  const double seconds = rounds * seconds_per_solve * (std::isfinite(scale) ? scale : 1e300);
  if (seconds <= limits::max_run_seconds)
    return;
  const bool sweep = solves - level_solves > level_solves;
  throw InputError(
      sweep ? "Cycloid loads/sweep positions" : "Cycloid loads/torque steps",
      "the run would take " + std::to_string(solves) + " solves (" + std::to_string(level_solves) +
          " torque levels, " + std::to_string(solves - level_solves) +
          " crank angles, over the profiles), about " + format_number(seconds / 3600., 3) +
          " h on " + std::to_string(ranks) + " rank(s) at " +
          format_number(seconds_per_solve * scale, 3) + " s per solve (limit " +
          format_number(limits::max_run_seconds / 3600., 2) + " h, docs/limits.md): use fewer " +
          (sweep ? "sweep positions" : "torque steps") + ", more MPI ranks or a coarser mesh");
}

void plot(CommandContext& context, const std::string& table, const std::string& mode,
          const std::string& png, const std::string& description)
{
  const TemporaryCsv csv(context.report, table);
  context.plot("plot_cycloid_loads.py", {mode, csv.path()}, png, description);
}

void report_load_case(Report& report, const CycloidLoadsParameters& p)
{
  report.add_text("load case",
                  "crank angle φ_h = " + format_number(p.settings.crank_angle / degree, 5) +
                      "°, eccentric held, disc bore on a bearing free to turn, rollers on fixed "
                      "pins (frictionless), output pins tied to one rigid output member carrying "
                      "M_c = " +
                      format_number(p.settings.output_torque, 5) +
                      " N·m (stiffness/cycloid_loads.h: the static equivalent of running)");
  report.add_text("model",
                  fem::to_string(p.settings.elasticity.model) + " 2D, Q" +
                      std::to_string(p.settings.elasticity.degree) +
                      ", thickness = disc "
                      "width " +
                      format_number(p.settings.scene.disc_width / mm, 4) +
                      " mm, E = " + format_number(p.settings.material.youngs_modulus / 1e9, 4) +
                      " GPa, μ = " + format_number(p.settings.contact.friction_coefficient, 3));
}

// Every case of every profile in one list (to be spread over the ranks), and where each
// profile's cases lie in it.
struct CaseList
{
  std::vector<stiffness::CycloidLoadSettings> cases;
  std::vector<ProfileCases> profiles;
};

CaseList list_cases(const std::vector<stiffness::CycloidLoadSettings>& bases,
                    const std::vector<double>& levels, const std::vector<double>& angles)
{
  CaseList list;
  auto& cases = list.cases;
  for (unsigned int b = 0; b < bases.size(); ++b)
  {
    ProfileCases pc;
    pc.name = bases[b].scene.disc.rollers == 0 ? "nominal" : "corrected";
    // The position is the ramp's +M_c level when there is a ramp. Each level of either sign
    // starts from the flank its torque closes (stiffness/cycloid_sweep.h), so a corrected
    // profile's backlash lies between its −3% and +3% levels.
    pc.first_level = cases.size();
    pc.levels = levels.size();
    pc.position = levels.empty() ? cases.size() : pc.first_level + levels.size() - 1;
    for (const double t : levels)
    {
      cases.push_back(bases[b]);
      cases.back().output_torque = t;
    }
    if (levels.empty())
      cases.push_back(bases[b]);
    pc.first_sweep = cases.size();
    pc.sweep = angles.size();
    for (const double a : angles)
    {
      cases.push_back(bases[b]);
      cases.back().crank_angle = a;
    }
    list.profiles.push_back(pc);
  }
  return list;
}

// VTU of each profile's position, when asked for and files are written.
void request_vtu(const CycloidLoadsParameters& p, CommandContext& context, CaseList& list)
{
  if (!(p.write_vtu && context.writes_files()))
    return;
  for (const auto& pc : list.profiles)
  {
    auto& c = list.cases[pc.position];
    c.output_base = "cycloid_" + pc.name;
    c.output_directory =
        std::filesystem::path(context.output_file("vtu/" + c.output_base + ".pvtu",
                                                  "displacement, stress, contact (VTU)"))
            .parent_path()
            .string();
  }
}

std::vector<stiffness::CycloidLoadResult>
solve_cases(CommandContext& context, const std::vector<stiffness::CycloidLoadSettings>& cases)
{
  const unsigned int ranks = dealii::Utilities::MPI::n_mpi_processes(context.mpi_communicator);
  context.pcout << "cycloid-loads: " << cases.size() << " solves on " << ranks << " rank(s)"
                << std::endl;
  // From the rank that solved the case (each takes its own, fem::distribute_items).
  const auto progress = context.progress_counter("cycloid-loads", double(cases.size()) / ranks);
  return stiffness::solve_cycloid_cases(context.mpi_communicator, cases,
                                        scratch_stem(context.mpi_communicator), progress);
}

// The drive and load of docs/references.md §4, whose published values the FE is compared with.
bool is_published_case(const stiffness::CycloidLoadSettings& s)
{
  return s.scene.ring.rollers == 20 &&
         std::abs(s.scene.ring.roller_circle_radius - 96e-3) < 1e-12 &&
         std::abs(s.scene.ring.eccentricity - 3e-3) < 1e-12 &&
         std::abs(s.output_torque - 440.) < 1e-9;
}

// With friction the ramp is path dependent: each profile's loop runs on one contact problem
// that keeps the stick/slip history (serial; every rank solves it, the answer is the same).
std::vector<stiffness::CycloidHysteresis>
friction_loops(CommandContext& context, const std::vector<stiffness::CycloidLoadSettings>& bases,
               const std::vector<ProfileCases>& profiles)
{
  std::vector<stiffness::CycloidHysteresis> loops;
  for (unsigned int b = 0; b < bases.size(); ++b)
  {
    stiffness::CycloidLoadSettings s = bases[b];
    s.scene_file = scratch_stem(context.mpi_communicator) + "_loop_" + profiles[b].name + ".msh";
    loops.push_back(stiffness::cycloid_hysteresis(s));
    if (context.is_root()) // every rank solves the same loop
      context.progress("cycloid-loads", "friction loop " + std::to_string(b + 1) + "/" +
                                            std::to_string(bases.size()) + ", " + profiles[b].name +
                                            ": " + std::to_string(loops.back().steps) + " steps, " +
                                            format_number(loops.back().time, 3) + " s");
  }
  return loops;
}

void report_friction_loop(Report& report, const std::string& prefix, const std::string& name,
                          const stiffness::CycloidHysteresis& loop)
{
  report.add_value(prefix + "torsional_stiffness", loop.stiffness * arcmin, "N·m/arcmin",
                   name + ": friction loop, secant between 50% and 100% of M_c, both "
                          "loading branches");
  report.add_value(prefix + "lost_motion", loop.lost_motion / arcmin, "arcmin",
                   name + ": friction loop, mid-width rotation between ±3% of M_c");
  const bool resolved = loop.hysteresis > loop.hysteresis_resolution;
  report.add_value(
      prefix + "hysteresis", loop.hysteresis / arcmin, "arcmin",
      name + ": friction loop width at ±3% of M_c (falling − rising)" +
          (resolved ? std::string() : std::string(", BELOW RESOLUTION: no measurable loop")));
  report.add_value(prefix + "hysteresis_resolution", loop.hysteresis_resolution / arcmin, "arcmin",
                   name + ": what the loop width is known to (half the difference of its "
                          "+3% and −3% estimates)");
  if (!resolved)
    report.add_text(prefix + "hysteresis below resolution",
                    name + ": loop width " + format_number(loop.hysteresis / arcmin, 2) +
                        " arcmin is below its resolution " +
                        format_number(loop.hysteresis_resolution / arcmin, 2) +
                        " arcmin: no measurable friction loop at this μ and mesh");
  report.add_value(prefix + "loop_wall_time", loop.time, "s",
                   name + ": wall time of the friction loop (" + std::to_string(loop.steps) +
                       " load steps)");
}

// The frictionless ramp's torsion figures (with friction only the backlash: the loop gives the
// rest).
void report_torque_ramp(Report& report, const std::string& prefix, const ProfileCases& pc,
                        const std::vector<stiffness::CycloidLoadResult>& results, double torque,
                        bool friction)
{
  const std::vector<stiffness::CycloidLoadResult> ramp(
      results.begin() + pc.first_level, results.begin() + pc.first_level + pc.levels);
  const stiffness::TorsionalCurve curve = stiffness::torsional_curve(torque, ramp);
  if (!friction)
  {
    report.add_value(prefix + "torsional_stiffness", curve.stiffness * arcmin, "N·m/arcmin",
                     pc.name + ": secant between 50% and 100% of M_c, both directions");
    report.add_value(prefix + "lost_motion", curve.lost_motion / arcmin, "arcmin",
                     pc.name + ": rotation between ±3% of M_c");
    report.add_value(prefix + "hysteresis", curve.hysteresis / arcmin, "arcmin",
                     pc.name + ": loading/unloading difference (frictionless: 0)");
  }
  report.add_value(prefix + "backlash", curve.backlash / arcmin, "arcmin",
                   pc.name + ": rigid rotation between the flanks (closing rotations ±)");
}

void add_tables(Report& report, const CycloidLoadsParameters& p, const std::vector<double>& levels,
                const std::vector<ProfileCases>& profiles,
                const std::vector<stiffness::CycloidLoadResult>& results,
                const std::vector<stiffness::CycloidHysteresis>& loops)
{
  add_contact_table(report, "cycloid_rollers", profiles, results, true);
  report.add_text("roller gaps",
                  "gap_* of cycloid_rollers: the roller clearance Δr_i of `gearstiff cycloid` "
                  "(distance from the roller centre to the disc profile minus q, nominal "
                  "kinematics) at this position's disc rotation ψ = " +
                      format_number(results[profiles[0].position].disc_rotation / degree, 6) +
                      "° (`gearstiff cycloid --set \"Cycloid correction/disc rotation=...\"` gives "
                      "the same table at that ψ)");
  add_contact_table(report, "cycloid_pins", profiles, results, false);
  if (p.torsional)
    add_torsion_table(report, levels, profiles, results);
  if (!loops.empty())
    add_hysteresis_table(report, profiles, loops);
  if (p.sweep_positions > 0)
    for (const auto& pc : profiles)
      add_sweep_table(report, pc, results);
}

void plot_charts(CommandContext& context, const CycloidLoadsParameters& p,
                 const std::vector<ProfileCases>& profiles, bool friction)
{
  if (!(context.writes_files() && context.is_root()))
    return;
  plot(context, "cycloid_rollers", "rollers", "cycloid_rollers.png",
       "roller forces P_i, FE and analytic, per profile");
  plot(context, "cycloid_pins", "pins", "cycloid_pins.png", "output-pin forces Q_j");
  if (p.torsional)
    plot(context, "cycloid_torsion", "torsion", "cycloid_torsion.png",
         "output rotation against torque (torsional stiffness, lost motion)");
  if (friction)
    plot(context, "cycloid_hysteresis", "hysteresis", "cycloid_hysteresis.png",
         "hysteresis loop with friction: output rotation against torque, per profile");
  for (const auto& pc : profiles)
    if (p.sweep_positions > 0)
      plot(context, "cycloid_sweep_" + pc.name, "sweep", "cycloid_sweep_" + pc.name + ".png",
           "P_i(φ_h) and Q_j(φ_h) traces, " + pc.name);
}

void run(dealii::ParameterHandler& prm, CommandContext& context)
{
  const CycloidLoadsParameters p = parse_cycloid_loads_parameters(prm);
  Report& report = context.report;
  const double torque = p.settings.output_torque;
  const geometry::CycloidDiscSpec& ring = p.settings.scene.ring;
  context.chart_case = "cycloid drive, z_k " + std::to_string(ring.rollers) + " rollers, e " +
                       format_number(ring.eccentricity * 1e3, 4) +
                       " mm, M_c = " + format_number(torque, 5) + " N·m";
  report_load_case(report, p);
  if (p.settings.scene.mesh.dimension != 2)
    throw InputError("Mesh/dimension", "the cycloid load analysis runs in 2D (3D: not yet)");

  const std::vector<stiffness::CycloidLoadSettings> bases = profile_settings(p, context);
  const std::vector<double> levels =
      p.torsional ? stiffness::torsional_levels(torque, p.torque_steps) : std::vector<double>{};
  CaseList list =
      list_cases(bases, levels,
                 stiffness::crank_angles(p.settings.crank_angle, p.sweep_span, p.sweep_positions));
  check_work(p, list.cases.size(), levels.size() * bases.size(),
             dealii::Utilities::MPI::n_mpi_processes(context.mpi_communicator));
  request_vtu(p, context, list);
  const std::vector<stiffness::CycloidLoadResult> results = solve_cases(context, list.cases);
  const bool friction = p.torsional && p.settings.contact.friction_coefficient > 0.;
  const std::vector<stiffness::CycloidHysteresis> loops =
      friction ? friction_loops(context, bases, list.profiles)
               : std::vector<stiffness::CycloidHysteresis>{};

  const bool published = is_published_case(bases[0]);
  for (unsigned int b = 0; b < list.profiles.size(); ++b)
  {
    const ProfileCases& pc = list.profiles[b];
    const std::string prefix = b == 0 ? "" : pc.name + "_";
    report_position(report, results[pc.position], prefix, pc.name, published && b == 0);
    if (friction)
      report_friction_loop(report, prefix, pc.name, loops[b]);
    if (pc.levels > 0)
      report_torque_ramp(report, prefix, pc, results, torque, friction);
  }
  add_tables(report, p, levels, list.profiles, results, loops);
  plot_charts(context, p, list.profiles, friction);
}

const CommandRegistration registration(Command{
    "cycloid-loads",
    "cycloid drive under load (FE contact): roller and pin forces, bearing force, stiffness",
    "Solves the cycloid (Cyclo) drive of docs/references.md §4 at one crank angle with the FE "
    "contact\n"
    "solver: disc on its eccentric bearing (free to turn), rollers on fixed pins, output pins\n"
    "tied to one rigid output member carrying M_c; one contact pair per roller and per pin.\n"
    "Reports P_i, Q_j, the bearing force R and its angle, torque balances, loaded counts, peak\n"
    "pressures, disc von Mises stress and output rotation, for the nominal and the corrected\n"
    "profile, beside the analytic rigid-disc model and the paper (P_max 1711 N, Q_max 3776 N);\n"
    "torsional stiffness, lost motion and backlash from torque levels ±3%, ±50%, ±100% M_c (the\n"
    "ramp -M_c -> +M_c -> -M_c; with Contact/Friction coefficient > 0 the loop is traced on one\n"
    "contact problem keeping the stick/slip history: hysteresis, chart); optionally a\n"
    "crank-angle sweep spread over the MPI ranks.",
    declare_cycloid_loads_parameters, run});
} // namespace
