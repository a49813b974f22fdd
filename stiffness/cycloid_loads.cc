#include "stiffness/cycloid_loads.h"

#include "contact/fields.h"
#include "errors/errors.h"
#include "fem/mesh.h"
#include "fem/stress.h"
#include "geometry/fields.h"
#include "kinematics/hertz.h"
#include "stiffness/contact_solve.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/fe/fe_values.h>
#include <filesystem>
#include <limits>
#include <tuple>

namespace gearstiff::stiffness
{
using namespace dealii;

namespace
{
// Every roller and pin is its own contact pair: faces relabelled per roller / pin.
constexpr types::boundary_id roller_surface_base = 1000; // + i
constexpr types::boundary_id disc_lobe_base = 2000;      // + i: lobe faces nearest roller i
constexpr types::boundary_id pin_surface_base = 3000;    // + j
constexpr types::boundary_id pin_hole_base = 4000;       // + j

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  return a.x() * b.y() - a.y() * b.x();
}

template <int dim>
Eigen::Vector2d planar(const Point<dim>& p)
{
  return Eigen::Vector2d(p[0], p[1]);
}

template <int dim>
Eigen::Vector2d planar(const Tensor<1, dim>& t)
{
  return Eigen::Vector2d(t[0], t[1]);
}

// Index of the point of `centres` nearest to `x`.
unsigned int nearest(const std::vector<Eigen::Vector2d>& centres, const Eigen::Vector2d& x)
{
  unsigned int best = 0;
  for (unsigned int k = 1; k < centres.size(); ++k)
    if ((centres[k] - x).norm() < (centres[best] - x).norm())
      best = k;
  return best;
}

Eigen::Vector2d disc_centre(const CycloidLoadSettings& s)
{
  return s.scene.ring.eccentricity *
         Eigen::Vector2d(std::cos(s.crank_angle), std::sin(s.crank_angle));
}

std::vector<Eigen::Vector2d> roller_centres(const geometry::CycloidDiscSpec& ring)
{
  std::vector<Eigen::Vector2d> centres;
  for (unsigned int i = 0; i < ring.rollers; ++i)
  {
    const double angle = 2. * M_PI * i / ring.rollers;
    centres.push_back(ring.roller_circle_radius *
                      Eigen::Vector2d(std::cos(angle), std::sin(angle)));
  }
  return centres;
}

// Play between the flanks: a corrected disc profile, or output pins with play in their holes
// (hole − pin − e above a nanometre, as pin_closing_rotation counts it). The loop is then traced
// flank by flank: crossing the play no torque-controlled step can do.
bool has_play(const geometry::CycloidSceneSpec& scene)
{
  return scene.disc.rollers != 0 || geometry::has_output_pin_play(scene);
}

std::vector<Eigen::Vector2d> pin_centres(const geometry::CycloidSceneSpec& scene)
{
  std::vector<Eigen::Vector2d> centres;
  for (unsigned int j = 0; j < scene.output_pins; ++j)
    centres.push_back(geometry::output_pin_centre(scene, j));
  return centres;
}

// Largest von Mises stress (Pa) over the Gauss points of the cells of `material`; 2D plane
// stress has σ_zz = 0, plane strain σ_zz = ν(σ_xx + σ_yy).
template <int dim>
double max_von_mises(const fem::ElasticSystem<dim>& system, const Vector<double>& u,
                     types::material_id material)
{
  const auto& fe = system.get_fe();
  const QGauss<dim> quadrature(fe.degree + 1);
  FEValues<dim> fe_values(system.get_mapping(), fe, quadrature, update_gradients);
  std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
  const fem::PlanarModel model = system.get_parameters().model;
  const fem::Material& m = system.material(material);
  double largest = 0.;
  for (const auto& cell : system.get_dof_handler().active_cell_iterators())
  {
    if (cell->material_id() != material)
      continue;
    fe_values.reinit(cell);
    cell->get_dof_indices(dofs);
    for (const unsigned int q : fe_values.quadrature_point_indices())
    {
      Tensor<2, dim> gradient;
      for (unsigned int i = 0; i < dofs.size(); ++i)
      {
        const unsigned int c = fe.system_to_component_index(i).first;
        gradient[c] += u[dofs[i]] * fe_values.shape_grad_component(i, q, c);
      }
      largest = std::max(largest, fem::von_mises_stress(m, model, gradient));
    }
  }
  return largest;
}

// Faces of every roller and pin, and the disc faces nearest to each, get their own ids.
template <int dim>
void relabel_contact_faces(Triangulation<dim>& tria, const std::vector<Eigen::Vector2d>& rollers,
                           const std::vector<Eigen::Vector2d>& pins, const Eigen::Vector2d& centre)
{
  std::vector<Eigen::Vector2d> holes;
  for (const auto& c : pins)
    holes.push_back(centre + c);
  for (const auto& cell : tria.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
    {
      const auto face = cell->face(f);
      if (!face->at_boundary())
        continue;
      const Eigen::Vector2d x = planar(face->center());
      switch (face->boundary_id())
      {
      case geometry::scene_ids::second_contact:
        face->set_boundary_id(roller_surface_base + nearest(rollers, x));
        break;
      case geometry::scene_ids::first_contact:
        face->set_boundary_id(disc_lobe_base + nearest(rollers, x));
        break;
      case geometry::cycloid_ids::output_pin_surfaces:
        face->set_boundary_id(pin_surface_base + nearest(pins, x));
        break;
      case geometry::scene_ids::output_pin_holes:
        face->set_boundary_id(pin_hole_base + nearest(holes, x));
        break;
      default:
        break;
      }
    }
}

// Contact pairs of the rollers the scene refined (clearance within the contact clearance); the
// others keep P_i = 0 (documented in the result as not candidate). Fills `loads` (one per
// roller) and returns each roller's pair index (invalid_unsigned_int: none); `pair` counts on.
template <int dim>
std::vector<unsigned int>
add_roller_pairs(contact::ContactProblem<dim>& problem, const CycloidLoadSettings& settings,
                 const geometry::CycloidSceneSpec& closed_scene, unsigned int& pair,
                 std::vector<CycloidContactLoad>& loads)
{
  const geometry::CycloidDiscSpec& ring = settings.scene.ring;
  const geometry::CycloidDiscSpec disc = closed_scene.disc.rollers == 0 ? ring : closed_scene.disc;
  const std::vector<geometry::RollerContact> contacts =
      geometry::roller_contacts(ring, disc, closed_scene.disc_rotation);
  const std::vector<double> clearances = geometry::roller_clearances(
      ring, settings.scene.disc.rollers == 0 ? ring : settings.scene.disc,
      settings.scene.disc_rotation);
  std::vector<unsigned int> pairs;
  loads.clear();
  for (unsigned int i = 0; i < ring.rollers; ++i)
  {
    CycloidContactLoad load;
    load.index = i;
    load.angle = 2. * M_PI * i / ring.rollers;
    load.initial_gap = clearances[i];
    load.candidate = contacts[i].clearance <= settings.scene.contact_clearance;
    if (!(contacts[i].clearance > -settings.contact.overlap_tolerance))
      throw InputError(geometry::field::disc("roller_radius"),
                       "roller " + std::to_string(i) + " overlaps the disc by " +
                           std::to_string(-contacts[i].clearance * 1e3) + " mm");
    loads.push_back(load);
    pairs.push_back(load.candidate ? pair++ : numbers::invalid_unsigned_int);
    if (load.candidate)
      problem.add_contact_pair({types::boundary_id(roller_surface_base + i)},
                               {types::boundary_id(disc_lobe_base + i)},
                               "roller " + std::to_string(i));
  }
  return pairs;
}

// A contact pair for every output pin in its hole; fills `loads`, returns the pair indices.
template <int dim>
std::vector<unsigned int> add_pin_pairs(contact::ContactProblem<dim>& problem,
                                        const CycloidLoadSettings& settings,
                                        const std::vector<Eigen::Vector2d>& pins,
                                        unsigned int& pair, std::vector<CycloidContactLoad>& loads)
{
  const double play = settings.scene.output_pin_hole_radius - settings.scene.output_pin_radius -
                      settings.scene.ring.eccentricity;
  std::vector<unsigned int> pairs;
  loads.clear();
  for (unsigned int j = 0; j < pins.size(); ++j)
  {
    CycloidContactLoad load;
    load.index = j;
    load.angle = std::atan2(pins[j].y(), pins[j].x());
    load.initial_gap = play;
    load.candidate = true;
    loads.push_back(load);
    pairs.push_back(pair++);
    problem.add_contact_pair({types::boundary_id(pin_surface_base + j)},
                             {types::boundary_id(pin_hole_base + j)}, "pin " + std::to_string(j));
  }
  return pairs;
}

// The largest force of `loads` (N); `loaded` counts those above 1e-6 of it.
double largest_force(const std::vector<CycloidContactLoad>& loads, unsigned int& loaded)
{
  double top = 0.;
  for (const auto& l : loads)
    top = std::max(top, l.force);
  loaded = 0;
  for (const auto& l : loads)
    loaded += l.force > 1e-6 * top;
  return top;
}

// The rigid-disc model of the same case beside the FE (cycloid_analytic.h).
void add_analytic_loads(const CycloidLoadSettings& settings, CycloidLoadResult& result)
{
  result.analytic = analytic_cycloid_loads(settings.scene, settings.output_torque,
                                           settings.roller_material.youngs_modulus);
  for (unsigned int i = 0; i < result.rollers.size(); ++i)
    result.rollers[i].analytic_force = result.analytic.roller_forces[i];
  for (unsigned int j = 0; j < result.pins.size(); ++j)
    result.pins[j].analytic_force = result.analytic.pin_forces[j];
}
} // namespace

geometry::CycloidSceneSpec default_cycloid_load_scene()
{
  geometry::CycloidSceneSpec scene;
  scene.output_pin_bodies = true;
  // Rollers this close to the disc are contact pairs (and meshed finely): the corrected
  // profiles of the correction table open at most a few hundredths of a millimetre near
  // the loaded flanks; farther rollers cannot close under M_c (their clearance exceeds the
  // disc's elastic rotation times their lever).
  scene.contact_clearance = 0.1e-3;
  // Sizes from the refinement study (docs/cycloid.md): with Q2 elements P_max within 1 % of the
  // finest level (all sizes × 0.35), Q_max within 0.1 %, one position in about 5 s.
  scene.points_per_lobe = 61;
  auto& mesh = scene.mesh;
  std::tie(mesh.contact_size, mesh.fine_radius, mesh.body_size, mesh.rim_size) =
      std::tuple{80e-6, 0.3e-3, 2e-3, 8e-3}; // m
  mesh.growth_rate = 0.4;
  return scene;
}

contact::ContactParameters default_cycloid_contact()
{
  contact::ContactParameters contact;
  contact.overlap_tolerance = 5e-6;
  return contact;
}

fem::ElasticityParameters default_cycloid_elasticity()
{
  fem::ElasticityParameters elasticity;
  elasticity.model = fem::PlanarModel::plane_stress;
  // Q2: P_max is set by the bending of the lobes and of the ring between lobes and bore, which
  // Q1 cells overstiffen. On the default mesh Q2 gives P_max 0.5 % below the finest level of
  // the study (Q2, all sizes × 0.35, 1.22 M DoFs) in about 5 s; Q1 needs all sizes × 0.7 for
  // 0.8 % at about the same cost (docs/cycloid.md, "Speed and discretisation").
  elasticity.degree = 2;
  return elasticity;
}

void check_cycloid_load_settings(const CycloidLoadSettings& s)
{
  if (!(std::abs(s.output_torque) > 0.) || !std::isfinite(s.output_torque))
    throw InputError(field::cycloid_loads("output_torque"),
                     "must not be zero: without a torque nothing is loaded (M_c per disc, N·m)");
  if (s.scene.output_pins == 0)
    throw InputError(geometry::field::cycloid_scene("output_pins"),
                     "the output torque needs at least one pin");
  if (s.scene_file.empty())
    throw InputError("scene file", "no path given for the scene mesh");
  check_cycloid_materials(s);
}

void check_cycloid_materials(const CycloidLoadSettings& s)
{
  // Material constants before any solver: E = 0 or ν = 0.5 reached MUMPS as a singular matrix
  // ("INFOG(1) = -10", exit 3), a failure of the input, not of the method.
  for (const auto& [material, name] :
       {std::pair{&s.material, field::cycloid_loads("young_modulus")},
        std::pair{&s.roller_material, field::cycloid_loads("roller_young_modulus")}})
  {
    kinematics::check_young_modulus(material->youngs_modulus, name);
    kinematics::check_poisson_ratio(material->poisson_ratio, field::cycloid_loads("poisson_ratio"));
  }
}

template <int dim>
CycloidLoads<dim>::CycloidLoads(const CycloidLoadSettings& given) : settings(given)
{
  check_cycloid_load_settings(settings);
  settings.scene.output_pin_bodies = true;
  settings.scene.mesh.dimension = dim;
  settings.scene.disc_rotation =
      geometry::disc_rotation_at_crank_angle(settings.scene.ring, settings.crank_angle);
  settings.scene.young_modulus = settings.material.youngs_modulus;
  settings.scene.poisson_ratio = settings.material.poisson_ratio;
  settings.elasticity.thickness = settings.scene.disc_width;
  // The Hertz estimate that sizes automatic contact cells (Mesh/contact size or fine radius 0)
  // takes the case's own forces: P_max and Q_max of the rigid-disc model under this torque
  // (cycloid_analytic.h), not the published case's.
  const CycloidAnalyticResult estimate = analytic_cycloid_loads(
      settings.scene, settings.output_torque, settings.roller_material.youngs_modulus);
  settings.scene.roller_force = estimate.max_roller_force;
  settings.scene.pin_force = estimate.max_pin_force;
  // A corrected profile touches no roller at the nominal placement, and the contact solve
  // starts from the touching nodes (the pins'): the disc would be free to turn. Turning disc and
  // output member rigidly through the clearance first is the same rigid motion the drive makes
  // when the load comes on.
  closed_scene = settings.scene;
  const double sign = settings.output_torque > 0. ? 1. : -1.;
  if (settings.scene.disc.rollers != 0)
  {
    // The closest roller is closed by a fifth of the overlap tolerance beyond touching: the
    // meshed outlines differ from the exact ones by fractions of a micrometre, and a roller left
    // at a tiny positive gap would not be in the solver's initial active set.
    scene_rotation =
        sign * closing_rotation(settings.scene, sign, 0.2 * settings.contact.overlap_tolerance);
    closed_scene.disc.rotation += scene_rotation;
    closed_scene.output_pin_phase += scene_rotation;
    // The backlash in this sense is the rotation to touching, without the pre-closure (which
    // the solve undoes: the overlap is a gap of −1 µm that the contact pushes open).
    result.closing_rotation = sign * closing_rotation(settings.scene, sign);
  }
  // Output pins with play (hole − pin − e > 0, which the scene parameters allow) touch no hole at
  // the nominal placement either, and the output member was free ("the body with material id 3
  // is free to move", exit 3, on any play until 2026-12-07): the pins alone are turned through
  // their play as well (from the rollers' closed placement), against holes that stay with the
  // disc, and that turn is backlash too.
  pin_turn =
      sign * pin_closing_rotation(closed_scene, sign, 0.2 * settings.contact.overlap_tolerance);
  closed_scene.output_pin_turn = pin_turn;
  result.closing_rotation += sign * pin_closing_rotation(closed_scene, sign);
}

template <int dim>
CycloidLoads<dim>::~CycloidLoads() = default;

template <int dim>
CycloidLoadResult CycloidLoads<dim>::run()
{
  Timer timer(MPI_COMM_SELF, true);
  const double closing = result.closing_rotation;
  result = CycloidLoadResult();
  result.closing_rotation = closing;
  result.crank_angle = settings.crank_angle;
  result.disc_rotation = settings.scene.disc_rotation;
  result.output_torque = settings.output_torque;
  make_scene();
  Timer step(MPI_COMM_SELF, true);
  setup_problem();
  result.read_time = step.wall_time();
  solve();
  step.restart();
  evaluate();
  result.evaluate_time = step.wall_time();
  if (!settings.output_directory.empty())
    result.output_files = problem->output_results(settings.output_directory, settings.output_base);
  result.total_time = timer.wall_time();
  return result;
}

template <int dim>
void CycloidLoads<dim>::make_scene()
{
  const geometry::SceneInfo info = geometry::write_cycloid_scene(closed_scene, settings.scene_file);
  result.contact_size = info.contact_size;
  result.scene_time = info.time_total;
  result.meshing_time = info.mesh.time_meshing;
  result.meshing_attempts = info.mesh.meshing_attempts;
}

template <int dim>
void CycloidLoads<dim>::setup_problem()
{
  problem = std::make_unique<contact::ContactProblem<dim>>(
      MPI_COMM_SELF, settings.elasticity, settings.linear_solver, settings.contact);
  Triangulation<dim>& tria = problem->system().triangulation();
  fem::read_msh<dim>(settings.scene_file, 1., tria, "scene file");
  problem->system().set_materials({{geometry::scene_ids::first_body, settings.material},
                                   {geometry::scene_ids::second_body, settings.roller_material},
                                   {geometry::cycloid_ids::output_pin_body, settings.material}},
                                  "material");
  const Eigen::Vector2d centre = disc_centre(settings);
  const std::vector<Eigen::Vector2d> pins = pin_centres(closed_scene);
  relabel_contact_faces(tria, roller_centres(settings.scene.ring), pins, centre);

  unsigned int pair = 0;
  roller_pairs = add_roller_pairs(*problem, settings, closed_scene, pair, result.rollers);
  pin_pairs = add_pin_pairs(*problem, settings, pins, pair, result.pins);

  // Supports (see the header): bearing (free to turn), fixed roller pins, rigid output member.
  Point<dim> bearing_axis, ring_axis;
  bearing_axis[0] = centre.x();
  bearing_axis[1] = centre.y();
  problem->add_rigid_hub(geometry::scene_ids::first_bore, bearing_axis,
                         fem::RigidHub<dim>::Control::torque, 0., "disc bearing");
  problem->add_displacement(geometry::scene_ids::second_bore, Tensor<1, dim>(), "roller pins");
  if (rotation_control)
    problem->add_rigid_hub(geometry::cycloid_ids::output_pin_bores, ring_axis,
                           fem::RigidHub<dim>::Control::rotation, start_rotation, "output member");
  else
    problem->add_rigid_hub(geometry::cycloid_ids::output_pin_bores, ring_axis,
                           fem::RigidHub<dim>::Control::torque, settings.output_torque,
                           "output member");
  result.n_cells = tria.n_active_cells();
}

template <int dim>
void CycloidLoads<dim>::solve()
{
  // Only the setup checks the initial overlap of the pairs.
  try
  {
    problem->setup_system();
  }
  catch (const InputError& e)
  {
    // The engine names the pair ("roller 3") of an initial overlap; what the user can change is
    // the tolerance (or the mesh: the chords of the meshed outlines overlap the other body by
    // h²/8ρ).
    throw InputError(contact::field::contact("overlap_tolerance"),
                     e.parameter() + ": " + e.reason());
  }
  solve_set_up_contact_problem(*problem, result);
  result.factorization_time = problem->results().assembly_time;
  result.iteration_time = problem->results().solve_time;
}

template <int dim>
void CycloidLoads<dim>::evaluate()
{
  const contact::ContactResults<dim>& contact = problem->results();
  const auto support = [&contact](const std::string& name) -> const contact::SupportResult<dim>&
  {
    for (const auto& s : contact.supports)
      if (s.name == name)
        return s;
    throw SolverFailure("cycloid loads", "no support named " + name);
  };
  const contact::SupportResult<dim>& bearing = support("disc bearing");
  const contact::SupportResult<dim>& output = support("output member");
  const Eigen::Vector2d centre = disc_centre(settings);
  const std::vector<Eigen::Vector2d> rollers = roller_centres(settings.scene.ring),
                                     pins = pin_centres(closed_scene);
  const double torque = settings.output_torque;

  // Contact forces on the rollers and pins; their lines of action run through the roller and
  // pin centres (frictionless contact on circles), which gives their moments.
  Eigen::Vector2d on_disc = Eigen::Vector2d::Zero();
  double disc_moment = bearing.torque, output_moment = 0.;
  const auto collect =
      [&](CycloidContactLoad& load, unsigned int pair, const Eigen::Vector2d& line_point)
  {
    if (pair == numbers::invalid_unsigned_int)
      return;
    const contact::PairResult<dim>& p = contact.pairs[pair];
    const Eigen::Vector2d force = planar(p.force_on_slave);
    load.force = p.normal_force;
    load.force_x = force.x();
    load.force_y = force.y();
    load.max_pressure = p.max_pressure;
    load.contact_length = p.contact_length;
    on_disc -= force;
    disc_moment += cross(line_point - centre, -force);
    result.max_contact_pressure = std::max(result.max_contact_pressure, p.max_pressure);
  };
  for (unsigned int i = 0; i < rollers.size(); ++i)
    collect(result.rollers[i], roller_pairs[i], rollers[i]);
  for (unsigned int j = 0; j < pins.size(); ++j)
  {
    collect(result.pins[j], pin_pairs[j], pins[j]);
    output_moment +=
        cross(pins[j], Eigen::Vector2d(result.pins[j].force_x, result.pins[j].force_y));
  }

  result.max_roller_force = largest_force(result.rollers, result.loaded_rollers);
  result.max_pin_force = largest_force(result.pins, result.loaded_pins);

  // Bearing: the support's force on the disc; the disc pushes the eccentric with its opposite.
  const Eigen::Vector2d support_force = planar(bearing.force);
  const Eigen::Vector2d on_eccentric = -support_force;
  result.bearing_force = on_eccentric.norm();
  result.bearing_force_direction = std::atan2(on_eccentric.y(), on_eccentric.x());
  result.input_torque = std::abs(cross(centre, on_eccentric));
  const double e = settings.scene.ring.eccentricity;
  result.bearing_angle = std::acos(std::min(1., result.input_torque / (e * result.bearing_force)));
  const double lobes = settings.scene.ring.rollers - 1.;
  result.input_torque_ratio = result.input_torque / (std::abs(torque) / lobes);

  result.disc_force_balance = (support_force + on_disc).norm() / result.bearing_force;
  result.disc_moment_balance = std::abs(disc_moment) / std::abs(torque);
  result.output_moment_balance = std::abs(output_moment + torque) / std::abs(torque);
  result.output_rotation = scene_rotation + pin_turn + output.rotation;
  result.disc_rotation_load = scene_rotation + bearing.rotation;
  result.disc_von_mises =
      max_von_mises(problem->system(), problem->solution(), geometry::scene_ids::first_body);

  add_analytic_loads(settings, result);
}

template <int dim>
std::vector<LoopPoint> CycloidLoads<dim>::trace_loop(const std::vector<LoopTarget>& targets)
{
  const double m = std::abs(settings.output_torque);
  const double sign = settings.output_torque > 0. ? 1. : -1.;
  // First guess of the stiffness: the nominal rigid-disc model's, stiffer than the FE, so the
  // first step falls short rather than beyond.
  geometry::CycloidSceneSpec nominal = settings.scene;
  nominal.disc.rollers = 0;
  double stiffness = // N·m/rad
      m / std::abs(analytic_cycloid_loads(nominal, m, settings.roller_material.youngs_modulus)
                       .output_rotation);
  // A drive with play starts closed by the pre-closure (a small torque); without play it
  // touches every roller and pin at no load, so it starts a tenth of M_c into its sense.
  rotation_control = true;
  start_rotation = has_play(settings.scene) ? 0. : sign * 0.1 * m / stiffness;
  make_scene();
  setup_problem();
  solve();
  const auto output_torque = [this]()
  {
    for (const auto& support : problem->results().supports)
      if (support.name == "output member")
        return support.torque;
    throw SolverFailure("cycloid loop", "no output member");
  };
  double theta = start_rotation, torque = output_torque();
  std::vector<LoopPoint> points{
      {torque, scene_rotation + pin_turn + theta, targets.empty() ? 0 : targets[0].branch}};
  int previous_direction = 0;
  for (const LoopTarget& target : targets)
  {
    const int direction = target.torque > torque ? 1 : -1;
    // Sticking contacts make the first steps after a reversal stiffer than the secant of the
    // last branch: half a step first, so it does not overshoot.
    double scale = previous_direction != 0 && direction != previous_direction ? 0.5 : 1.;
    previous_direction = direction;
    for (unsigned int attempt = 0; attempt < 8 && direction * (torque - target.torque) < -0.01 * m;
         ++attempt)
    {
      const double step = scale * (target.torque - torque) / stiffness; // rad
      scale = 1.;
      theta += step;
      problem->set_hub_target("output member", theta);
      problem->solve_next_step();
      const double now = output_torque();
      if ((now - torque) * direction > 0.)
        stiffness = (now - torque) / step;
      torque = now;
      points.push_back({torque, scene_rotation + pin_turn + theta, target.branch});
    }
  }
  return points;
}

template <int dim>
unsigned int CycloidLoads<dim>::loop_iterations() const
{
  return problem ? problem->results().active_set_iterations : 0;
}

namespace
{
// θ (rad) of a branch at torque t (N·m): linear between the neighbouring points of the same
// sense of torque, extrapolated from the two nearest ends outside. (A profile with play has a
// jump across zero torque that no interpolation may bridge.)
double branch_rotation(const std::vector<LoopPoint>& points, int branch, double t)
{
  std::vector<std::pair<double, double>> curve;
  for (const auto& p : points)
    if (p.branch == branch && p.torque * t > 0.)
      curve.emplace_back(p.torque, p.rotation);
  std::sort(curve.begin(), curve.end());
  if (curve.size() < 2)
    throw SolverFailure("cycloid loop", "a branch of the loop has fewer than two points");
  unsigned int k = 1;
  while (k + 1 < curve.size() && curve[k].first < t)
    ++k;
  const auto& [t0, r0] = curve[k - 1];
  const auto& [t1, r1] = curve[k];
  return r0 + (r1 - r0) * (t - t0) / (t1 - t0);
}
} // namespace

CycloidHysteresis cycloid_hysteresis(const CycloidLoadSettings& base)
{
  Timer timer(MPI_COMM_SELF, true);
  const double m = std::abs(base.output_torque);
  const std::vector<double> levels{0.03, 0.25, 0.5, 0.75, 1.};
  CycloidHysteresis h;
  const auto trace = [&](double sign, const std::vector<LoopTarget>& targets)
  {
    CycloidLoadSettings s = base;
    s.output_torque = sign * m;
    CycloidLoads<2> loads(s);
    const std::vector<LoopPoint> points = loads.trace_loop(targets);
    std::filesystem::remove(s.scene_file);
    h.points.insert(h.points.end(), points.begin(), points.end());
    h.steps += points.size();
    h.active_set_iterations += loads.loop_iterations();
  };
  // Targets from sign_from·M_c down the levels (and up the levels of sign_to when through
  // zero), the first left out: it is where the previous targets ended.
  const auto sweep = [&](std::vector<LoopTarget>& targets, double sign_from, double sign_to,
                         int branch, bool through_zero)
  {
    std::vector<double> path;
    for (auto it = levels.rbegin(); it != levels.rend(); ++it)
      path.push_back(sign_from * *it);
    if (through_zero)
      for (const double l : levels)
        path.push_back(sign_to * l);
    for (unsigned int k = 1; k < path.size(); ++k)
      targets.push_back({path[k] * m, branch});
  };
  if (!has_play(base.scene))
  {
    std::vector<LoopTarget> targets;
    for (const double l : levels)
      if (l > 0.1)
        targets.push_back({-l * m, 0});
    sweep(targets, -1., 1., 1, true);
    sweep(targets, 1., -1., -1, true);
    trace(-1., targets);
  }
  else
    for (const double sign : {1., -1.})
    {
      // Loading on this flank is the rising branch for +M_c and the falling one for −M_c.
      const int loading = sign > 0. ? 1 : -1;
      std::vector<LoopTarget> targets;
      for (const double l : levels)
        targets.push_back({sign * l * m, loading});
      sweep(targets, sign, sign, -loading, false);
      trace(sign, targets); // the start point belongs to the first target's branch: loading
    }
  const auto up = [&](double f) { return branch_rotation(h.points, 1, f * m); };
  const auto down = [&](double f) { return branch_rotation(h.points, -1, f * m); };
  h.stiffness = 0.5 * (0.5 * m / (up(1.) - up(0.5)) + 0.5 * m / (down(-0.5) - down(-1.)));
  h.lost_motion = 0.5 * (up(0.03) + down(0.03)) - 0.5 * (up(-0.03) + down(-0.03));
  h.hysteresis = 0.5 * ((down(0.03) - up(0.03)) + (down(-0.03) - up(-0.03)));
  double lowest = 0., highest = 0.;
  for (const LoopPoint& point : h.points)
  {
    lowest = std::min(lowest, point.rotation);
    highest = std::max(highest, point.rotation);
  }
  h.hysteresis_resolution =
      std::max(0.5 * std::abs((down(0.03) - up(0.03)) - (down(-0.03) - up(-0.03))),
               1e-9 * (highest - lowest));
  h.time = timer.wall_time();
  return h;
}

template class CycloidLoads<2>;
template class CycloidLoads<3>;
} // namespace gearstiff::stiffness
