#include "stiffness/mesh_stiffness.h"

#include "errors/errors.h"
#include "errors/format.h"
#include "fem/mesh.h"
#include "fem/parallel.h"
#include "fem/small_strain.h"
#include "fem/stress.h"
#include "geometry/fields.h"
#include "geometry/tooth_fault.h"
#include "stiffness/contact_solve.h"
#include "stiffness/root_stress.h"

#include <algorithm>
#include <boost/serialization/vector.hpp>
#include <cmath>
#include <cstring>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/grid_tools.h>
#include <limits>
#include <map>
#include <set>

namespace gearstiff::stiffness
{
using namespace dealii;

namespace
{
// x of the wheel axis in the scene frame (geometry/scene_gear_pair.h): an external wheel at
// +a_w, a ring at −a_w.
double wheel_axis_x(const kinematics::GearPairGeometry& pair)
{
  return pair.spec.wheel.internal ? -pair.centre_distance : pair.centre_distance;
}

// A helical pair's flanks on their involute helicoids (Mesh/helical flanks = helicoid), not on
// the chords the hexahedra's edges draw between two layers (BodyTwist::on_helix). The chords lie
// inside each body by r·Δφ²/8 at mid-layer — 0.4 µm normal to the pinion's flank at 13 layers on
// the built-in pair at 15° —, a gap that opens along every contact line between the layer planes
// and makes k rise with the layers; on the helicoids the dual mortar's own error is left, of the
// other sign, and both extrapolate to one limit (docs/helical.md "Layers and the helicoids").
// The layer planes are the distinct z of the mesh's vertices (lead modifications move nodes
// in-plane only).
template <int dim>
contact::SurfaceGeometry<dim> helical_flanks(const kinematics::GearPairGeometry& pair,
                                             const Triangulation<dim>& tria)
{
  if constexpr (dim == 2)
    return {};
  else
  {
    const std::map<int, geometry::BodyTwist> twists = geometry::gear_pair_twists(pair);
    if (twists.empty())
      return {};
    std::vector<double> planes;
    for (const Point<dim>& v : tria.get_vertices())
      planes.push_back(v[dim - 1]);
    std::sort(planes.begin(), planes.end());
    const double tolerance = 1e-9 * pair.common_face_width;
    planes.erase(std::unique(planes.begin(), planes.end(),
                             [tolerance](double a, double b) { return b - a < tolerance; }),
                 planes.end());
    return [twists, planes](const Point<dim>& p, const types::material_id material) -> Point<dim>
    {
      const auto twist = twists.find(material);
      if (twist == twists.end() || planes.size() < 2)
        return p;
      const auto above = std::clamp(std::upper_bound(planes.begin(), planes.end(), p[dim - 1]),
                                    planes.begin() + 1, planes.end() - 1);
      const Eigen::Vector3d x =
          twist->second.on_helix({p[0], p[1], p[dim - 1]}, *(above - 1), *above);
      return Point<dim>(x.x(), x.y(), x.z());
    };
  }
}

template <int dim>
double polar_radius(const Point<dim>& p, double centre_x)
{
  return std::hypot(p[0] - centre_x, p[1]);
}

// Where a point of the pinion's flank touches the wheel, on the path's scale (m from T1): the
// wheel's involute through the point (its distance from the wheel axis) meets the line of action
// there, ℓ₂ = T₂ − s₂·√(r₂² − r_b2²) with T₂ = (r_b1 + s₂·r_b2)·tan α_wt and s₂ = −1 for a ring
// (kinematics/gear_pair.cc set_line_of_action: the same formula gives A at the wheel's tip).
template <int dim>
double wheel_roll_on_path(const kinematics::GearPairGeometry& pair, const Point<dim>& p)
{
  const double s2 = pair.spec.wheel.internal ? -1. : 1.;
  const double rb1 = 0.5 * pair.pinion.base_diameter;
  const double rb2 = 0.5 * pair.wheel.base_diameter;
  const double t2 = (rb1 + s2 * rb2) * std::tan(pair.working_pressure_angle);
  const double r2 = polar_radius(p, wheel_axis_x(pair));
  return t2 - s2 * std::sqrt(std::max(0., r2 * r2 - rb2 * rb2));
}

// The pair's resultant against the line of action u = (sin α_wt, cos α_wt) (the ring pushes
// the pinion along −u) and the roll lengths of its closed pinion nodes (the pinion centre is
// the scene origin) and of its largest pressure, on the pinion and on the wheel (3D: across the
// face from its middle, at half the common width on the axis), ToothPairLoad.
template <int dim>
void locate_load(const contact::PairResult<dim>& contact, const kinematics::GearPairGeometry& pair,
                 ToothPairLoad& load)
{
  const double working_pressure_angle = pair.working_pressure_angle;
  const double pinion_base_radius = 0.5 * pair.pinion.base_diameter;
  const double mid_face = 0.5 * pair.common_face_width;
  const double along = -(contact.force_on_slave[0] * std::sin(working_pressure_angle) +
                         contact.force_on_slave[1] * std::cos(working_pressure_angle));
  const double across = -(contact.force_on_slave[1] * std::sin(working_pressure_angle) -
                          contact.force_on_slave[0] * std::cos(working_pressure_angle));
  load.resultant = std::hypot(along, across);
  load.force_deviation = std::atan2(across, along);
  load.closed_roll_min = std::numeric_limits<double>::max();
  load.closed_roll_max = 0.;
  double peak = -std::numeric_limits<double>::max();
  for (const auto& point : contact.points)
    if (point.state != contact::NodeState::open)
    {
      const double r = polar_radius(point.position, 0.);
      const double roll = std::sqrt(std::max(0., r * r - pinion_base_radius * pinion_base_radius));
      load.closed_roll_min = std::min(load.closed_roll_min, roll);
      load.closed_roll_max = std::max(load.closed_roll_max, roll);
      // Ties (a straight face's two ends carry the same peak to round-off) go to the smaller
      // face coordinate, then the smaller roll: the same node whatever order the scene numbered
      // them in (β = 0 reproduces the spur report, helical.beta_zero).
      const double face = dim == 3 ? point.position[dim - 1] - mid_face : 0.;
      const double tie = 1e-9 * std::abs(peak);
      if (point.pressure > peak + tie ||
          (point.pressure >= peak - tie &&
           (face < load.max_pressure_face ||
            (face == load.max_pressure_face && roll < load.max_pressure_roll))))
      {
        peak = std::max(peak, point.pressure);
        load.max_pressure_roll = roll;
        load.max_pressure_face = face;
        load.max_pressure_wheel_roll = wheel_roll_on_path(pair, point.position);
      }
    }
  if (load.closed_roll_min > load.closed_roll_max)
    load.closed_roll_min = load.closed_roll_max = load.max_pressure_roll =
        load.max_pressure_wheel_roll = load.position; // no closed node
}
// 3D: the mesh forces on the pinion and their tilting moment (GearMeshStiffnessResult).
template <int dim>
void mesh_forces(const contact::ContactResults<dim>& contact, unsigned int n_pairs,
                 double working_pressure_angle, double mid_face, GearMeshStiffnessResult& result)
{
  result.tangential_force = result.axial_force = 0.;
  double moment_x = 0., moment_y = 0.;
  for (unsigned int k = 0; k < n_pairs; ++k)
  {
    const contact::PairResult<dim>& pair = contact.pairs[k];
    const Tensor<1, dim>& f = pair.force_on_slave;
    result.tangential_force -=
        f[0] * std::sin(working_pressure_angle) + f[1] * std::cos(working_pressure_angle);
    result.axial_force += f[dim - 1];
    Point<dim> centre;
    double weight = 0.;
    for (const auto& point : pair.points)
      if (point.state != contact::NodeState::open && point.pressure > 0.)
      {
        centre += point.pressure * point.position;
        weight += point.pressure;
      }
    if (!(weight > 0.) || dim != 3)
      continue;
    centre /= weight;
    const double z = centre[dim - 1] - mid_face;
    moment_x += centre[1] * f[dim - 1] - z * f[1];
    moment_y += z * f[0] - centre[0] * f[dim - 1];
  }
  result.tilting_moment = std::hypot(moment_x, moment_y);
}
} // namespace

geometry::GearPairSceneSpec default_stiffness_scene()
{
  geometry::GearPairSceneSpec scene;
  // The ANSYS model removed the teeth that do not affect the stiffness but kept the gear
  // bodies (docs/references.md §1): full rims, three teeth per gear (one pair on either side of the
  // loaded ones). The sizes are explicit so that a refinement study scales one size field; with
  // Q2 elements (default_stiffness_elasticity) they are the cheapest scene within 1% of the
  // converged single-pair stiffness that meshes at every position of a sweep (docs/accuracy.md:
  // 0.2%; a √2 coarser field is 0.1% off but leaves triangles at some positions).
  scene.rim = geometry::RimModel::full;
  scene.pinion_teeth_modelled = 3;
  scene.wheel_teeth_modelled = 3;
  scene.mesh.contact_size = 0.03e-3;
  scene.mesh.fine_radius = 0.15e-3;
  scene.mesh.body_size = 0.7e-3;
  scene.mesh.rim_size = 2.8e-3;
  scene.mesh.growth_rate = 0.35;
  return scene;
}

fem::ElasticityParameters default_stiffness_elasticity()
{
  fem::ElasticityParameters elasticity;
  // Q2: the contact zone (Hertz half-width ≈ 2 h_c) is resolved far better than with Q1 on the
  // same cells, which converge pre-asymptotically (docs/accuracy.md).
  elasticity.degree = 2;
  return elasticity;
}

void check_stiffness_settings(const GearMeshStiffnessSettings& settings)
{
  if (!(settings.pinion_torque > 0.))
    throw InputError(stiffness_parameter::torque,
                     "must be positive: a torque <= 0 turns the pinion away from the wheel and "
                     "separates the loaded flanks (no contact, no stiffness)");
  if (settings.scene.both_flanks)
    throw InputError(geometry::scene_field::both_flanks,
                     "the stiffness analysis loads one flank per tooth; set it to false");
}

template <int dim>
GearMeshStiffness<dim>::GearMeshStiffness(MPI_Comm mpi_communicator,
                                          const GearMeshStiffnessSettings& given)
    : mpi_communicator(mpi_communicator), settings(given)
{
  check_stiffness_settings(settings);
  if (settings.scene_file.empty())
    throw InputError(stiffness_parameter::scene_file, "no path given for the scene mesh");
  pair = kinematics::compute_gear_pair(settings.scene.pair);
  settings.scene.mesh.dimension = dim;
  // The scene's Hertz estimate of the contact size uses the same load and material.
  settings.scene.pinion_torque = settings.pinion_torque;
  settings.scene.young_modulus = settings.material.youngs_modulus;
  settings.scene.poisson_ratio = settings.material.poisson_ratio;
  // A 2D model carries the common face width: the contact lines are that long.
  settings.elasticity.thickness = pair.common_face_width;
}

template <int dim>
GearMeshStiffnessResult GearMeshStiffness<dim>::run()
{
  Timer timer(mpi_communicator, true);
  result = GearMeshStiffnessResult();
  result.dimension = dim;
  const bool report = settings.progress && Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
  const auto stage = [&](unsigned int index, const std::string& text)
  {
    if (report)
      settings.progress("stage " + std::to_string(index) + "/4 " + text + ", " +
                        format_number(timer.wall_time(), 3) + " s elapsed");
  };
  stage(1, "meshing the scene");
  mesh_diameter = 0.;
  make_scene();
  stage(2, "setting up (reading the mesh, stiffness matrix, mortar coupling)");
  setup_problem();
  stage(3, "solving the contact (" +
               std::to_string(problem->system().triangulation().n_global_active_cells()) +
               " cells: factorization, then active-set iterations)");
  solve();
  stage(4, "evaluating (" + std::to_string(result.active_set_iterations) + " contact iterations)");
  evaluate();
  output_results();
  result.total_time = timer.wall_time();
  return result;
}

void check_torque_list(const std::vector<double>& torques)
{
  if (torques.empty())
    throw InputError(stiffness_parameter::torques, "must list at least one torque [N·m]");
  for (std::size_t i = 0; i < torques.size(); ++i)
  {
    if (!(torques[i] > 0.))
      throw InputError(stiffness_parameter::torques,
                       "every torque must be positive: a torque <= 0 separates the loaded "
                       "flanks (got " +
                           std::to_string(torques[i]) + " N·m)");
    // inf reached the contact solver and failed there (exit 3).
    if (!std::isfinite(torques[i]))
      throw InputError(stiffness_parameter::torques,
                       "every torque must be a finite number [N·m] (got " +
                           format_number(torques[i], 6) + ")");
    if (i > 0 && !(torques[i] > torques[i - 1]))
      throw InputError(stiffness_parameter::torques,
                       "the torques must ascend (one monotone loading path)");
  }
}

template <int dim>
std::vector<GearMeshStiffnessResult>
GearMeshStiffness<dim>::run_torques(const std::vector<double>& torques)
{
  check_torque_list(torques);
  std::vector<GearMeshStiffnessResult> results;
  settings.pinion_torque = torques.front();
  results.push_back(run());
  for (std::size_t t = 1; t < torques.size(); ++t)
    results.push_back(next_torque(torques[t]));
  return results;
}

template <int dim>
GearMeshStiffnessResult GearMeshStiffness<dim>::next_torque(const double torque)
{
  Timer timer(mpi_communicator, true);
  settings.pinion_torque = torque;
  const unsigned int iterations_before = problem->results().active_set_iterations;
  problem->set_hub_target("pinion bore", torque);
  const contact::ContactResults<dim>& contact = problem->solve_next_step();
  result.active_set_iterations = contact.active_set_iterations - iterations_before;
  result.setup_time = 0.; // the scene, the set-up and the factorization are the first torque's
  result.scene_time = 0.;
  result.factorization_time = 0.;
  evaluate();
  result.solve_time = timer.wall_time();
  result.total_time = result.solve_time;
  result.output_files.clear();
  return result;
}

namespace
{
// A root crack whose faces meet (geometry/tooth_fault.h), 2D: the boundary id of its first face
// (the other is + 1) and the cell size at its tip.
struct SceneCrack
{
  types::boundary_id face;
  double tip_size; // m
};

// Those of the mesh's teeth (a crack on a tooth outside the modelled window is not meshed).
template <int dim>
std::vector<SceneCrack> scene_cracks(const geometry::GearPairSceneSpec& scene,
                                     const Triangulation<dim>& triangulation)
{
  std::vector<SceneCrack> cracks;
  if (dim != 2)
    return cracks;
  const std::vector<types::boundary_id> ids = triangulation.get_boundary_ids();
  for (const bool wheel : {false, true})
    for (const auto& [tooth, list] :
         (wheel ? scene.wheel_modifications : scene.pinion_modifications).by_tooth)
    {
      const bool broken = std::any_of(
          list.begin(), list.end(),
          [](const auto& m) { return m.kind == geometry::ModificationKind::broken_tooth; });
      for (const geometry::ToothModification& m : list)
      {
        const auto face = static_cast<types::boundary_id>(geometry::crack_face_id(wheel, tooth));
        if (!broken && m.kind == geometry::ModificationKind::root_crack && m.crack_contact &&
            std::find(ids.begin(), ids.end(), face) != ids.end())
          cracks.push_back({face, geometry::crack_tip_cell_size(m)});
      }
    }
  return cracks;
}
} // namespace

template <int dim>
void GearMeshStiffness<dim>::make_scene()
{
  // Rank 0 writes the scene; every rank receives its numbers: ℓ_ref, h_c, the scene time and
  // the pairs j in contact (which are also modelled: the scene's windows cover them).
  const std::vector<double> scene = fem::run_on_root(
      mpi_communicator,
      [this]()
      {
        // The work limit of a 3D scene is the memory of its solve, which the degree sets.
        geometry::GearPairSceneSpec spec = settings.scene;
        spec.mesh.element_degree = settings.elasticity.degree;
        const geometry::GearPairScene written =
            geometry::write_gear_pair_scene(spec, settings.scene_file);
        std::vector<double> values{written.reference_position, written.info.contact_size,
                                   written.info.time_total, written.unloaded_transmission_error,
                                   written.info.body_size};
        for (const int j : written.contact_pairs)
          values.push_back(j);
        return values;
      });
  result.reference_position = scene[0];
  result.contact_size = scene[1];
  result.scene_time = scene[2];
  result.unloaded_transmission_error = scene[3];
  result.body_size = scene[4];
  candidate_pairs.clear();
  for (std::size_t i = 5; i < scene.size(); ++i)
  {
    ToothPairLoad load;
    load.pair = static_cast<int>(std::lround(scene[i]));
    load.position = result.reference_position + load.pair * pair.transverse_base_pitch;
    candidate_pairs.push_back(load);
  }
  result.kinematic_pairs = candidate_pairs.size();
  result.pinion_base_radius = 0.5 * pair.pinion.base_diameter;
  result.wheel_base_radius = 0.5 * pair.wheel.base_diameter;
  result.pinion_roll_angle = result.reference_position / result.pinion_base_radius;
  result.mesh_position =
      (result.reference_position - pair.contact_start) / pair.transverse_base_pitch;
}

template <int dim>
void GearMeshStiffness<dim>::setup_problem()
{
  fillets.clear(); // of the previous mesh
  problem = std::make_unique<contact::ContactProblem<dim>>(
      mpi_communicator, settings.elasticity, settings.linear_solver, settings.contact);
  Triangulation<dim>& tria = problem->system().triangulation();
  fem::read_msh<dim>(settings.scene_file, 1., tria, "scene file");
  if (settings.helicoid_flanks)
    problem->set_surface_geometry(helical_flanks(pair, tria));
  problem->system().set_materials({{geometry::scene_ids::pinion_body, settings.material},
                                   {geometry::scene_ids::wheel_body, settings.material}},
                                  "material");

  // Each pair in contact is its own contact pair: the scene wrote one boundary id per flank.
  // Pairs outside the path of contact could only touch by tip-corner contact under a
  // deflection larger than their gap, which the small-sliding mortar pairing (normal
  // projection onto the mate's flank, which ends at the tip) does not represent; they stay
  // free surfaces.
  for (const ToothPairLoad& load : candidate_pairs)
    problem->add_contact_pair(
        {static_cast<types::boundary_id>(geometry::pinion_flank_id(load.pair))},
        {static_cast<types::boundary_id>(geometry::wheel_flank_id(load.pair))},
        "tooth pair " + std::to_string(load.pair));
  add_crack_pairs();

  Point<dim> pinion_axis, wheel_axis;
  wheel_axis[0] = wheel_axis_x(pair);
  problem->add_rigid_hub(geometry::scene_ids::pinion_bore, pinion_axis,
                         fem::RigidHub<dim>::Control::torque, settings.pinion_torque,
                         "pinion bore");
  // The fixed wheel bore as a hub held at zero rotation: the same constraints as a fixed
  // support, and its reaction torque comes out about the wheel axis.
  problem->add_rigid_hub(geometry::scene_ids::wheel_bore, wheel_axis,
                         fem::RigidHub<dim>::Control::rotation, 0., "wheel bore");
  result.n_cells = tria.n_active_cells();
}

// A root crack whose faces meet: its faces are a contact pair of the gear with itself (with the
// contact's μ, 0 by default: frictionless), so they close where the root is compressed.
template <int dim>
void GearMeshStiffness<dim>::add_crack_pairs()
{
  for (const SceneCrack& crack : scene_cracks(settings.scene, problem->system().triangulation()))
    problem->add_contact_pair({crack.face}, {static_cast<types::boundary_id>(crack.face + 1)},
                              "crack faces " + std::to_string(crack.face), {}, true);
}

namespace
{
// A helical scene's contact lines cross its layers at β_b: within one layer a flank node's gap
// to its mate grows quadratically away from the line, and the mortar gap of a node near the
// line (the gap weighted by the dual basis, which is negative over part of each cell) comes out
// negative by a discretisation error that falls as the layer height squared. The flanks
// themselves do not overlap: their nodes lie on the involute helicoids (to 3 nm) and every
// facet lies inside its body. Case 24 of seed 20261201 (22/31 teeth, m_n 1.5 mm, β 8.2°,
// b 16.4 mm, Q1; measured 2026-12-02): 1.71 µm at 4 layers, 1.22 µm at 5, below 1 µm at 8.
// More layers cure it, so the overlap names them, with the count that brings it to half the
// tolerance by that scaling.
void refuse_helical_overlap(const InputError& error, const kinematics::GearPairGeometry& pair,
                            unsigned int layers, double overlap_tolerance)
{
  const std::string prefix = contact::overlap_reason;
  if (pair.spec.pinion.helix_angle == 0. || error.reason().rfind(prefix, 0) != 0)
    return;
  const double overlap = std::stod(error.reason().substr(prefix.size())) * 1e-3; // m
  const unsigned int needed =
      static_cast<unsigned int>(std::ceil(layers * std::sqrt(overlap / (0.5 * overlap_tolerance))));
  throw InputError(geometry::field::mesh("layers"),
                   "too few for the contact lines of this helical pair: " + error.parameter() +
                       ": " + error.reason() +
                       " (the lines cross the layers at the base helix angle; the mortar gap's "
                       "error falls as the layer height squared): use at least " +
                       std::to_string(std::max(needed, layers + 1)) + " layers, got " +
                       std::to_string(layers));
}
} // namespace

template <int dim>
void GearMeshStiffness<dim>::solve()
{
  try
  {
    problem->setup_system();
  }
  catch (const InputError& error)
  {
    refuse_helical_overlap(error, pair, settings.scene.mesh.layers,
                           settings.contact.overlap_tolerance);
    throw;
  }
  solve_set_up_contact_problem(*problem, result,
                               settings.contact.warm_start ? settings.warm_start.get() : nullptr);
}

template <int dim>
void GearMeshStiffness<dim>::evaluate()
{
  const contact::ContactResults<dim>& contact = problem->results();
  const contact::SupportResult<dim>& pinion_hub = contact.supports.at(0);
  const contact::SupportResult<dim>& wheel_hub = contact.supports.at(1);
  // A torque far beyond the linear model still returns a number; refuse it.
  if (!(mesh_diameter > 0.)) // one mesh for every position of a rolling sweep
    mesh_diameter = GridTools::diameter(problem->system().get_dof_handler().get_triangulation());
  // Under a torque list the load that broke the limit is the list's entry.
  fem::check_small_strain(mesh_diameter, problem->solution(),
                          settings.torques.empty() ? stiffness_parameter::torque
                                                   : stiffness_parameter::torques);
  result.pinion_torque = settings.pinion_torque;
  // Rotation from the unloaded touching configuration: every normal gap of an involute flank
  // closes by r_b1 per radian of pinion rotation (its normals are tangent to the base circle).
  // The meshed flanks are chords of the outlines and touch only after the pinion has turned by
  // g_min/r_b1 (g_min the smallest initial gap of the mortar nodes; the contact solve starts
  // with those nodes closed), which is no deflection and is taken out.
  double smallest_gap = std::numeric_limits<double>::max();
  for (unsigned int k = 0; k < candidate_pairs.size(); ++k) // the tooth pairs (not crack faces)
    for (const auto& point : contact.pairs[k].points)
      smallest_gap = std::min(smallest_gap, point.initial_gap);
  result.initial_gap = smallest_gap;
  // A helical scene's contact lines cross its layers at β_b: within a face the gap grows
  // quadratically away from the line and the dual basis (negative over part of the face) weights
  // it to a negative mortar gap, although the built flanks touch without overlapping (nodes on
  // the helicoids, facets inside the bodies): the turn to touching is then zero, not negative.
  // Taking the artifact out as a turn softened k by the double position's −0.20 µm (11 of
  // 431 µrad) in tests/verification/calculix_helical.py, −2.0 % against CalculiX, whose
  // rotation counts from the built position (measured 2026-12-02).
  const double touching_gap =
      pair.spec.pinion.helix_angle != 0. ? std::max(smallest_gap, 0.) : smallest_gap;
  result.pinion_rotation = pinion_hub.rotation - touching_gap / result.pinion_base_radius;
  result.pinion_hub_torque = pinion_hub.torque;
  result.wheel_torque = wheel_hub.torque;
  result.torque_ratio = std::abs(wheel_hub.torque / settings.pinion_torque);
  // A torque-driven hub that does not turn forward means the torque did not close the mesh;
  // a stiffness from it would be meaningless.
  if (!(result.pinion_rotation > 0.))
    throw SolverFailure("gear mesh stiffness",
                        "the pinion did not rotate forward under the torque (rotation " +
                            std::to_string(result.pinion_rotation) + " rad)");
  const double r_b1 = result.pinion_base_radius;
  result.mesh_stiffness = settings.pinion_torque / (r_b1 * r_b1 * result.pinion_rotation);
  // The pinion rolls the unloaded error (the modifications' gap) before the flanks touch; the
  // deflection from the touching position is what sets k.
  result.transmission_error = r_b1 * result.pinion_rotation + result.unloaded_transmission_error;
  evaluate_pairs(contact);
  evaluate_root_stress();
  evaluate_crack_tips();
}

template <int dim>
void GearMeshStiffness<dim>::evaluate_crack_tips()
{
  result.crack_tips.clear();
  if constexpr (dim == 2)
  {
    const fem::Material& m = settings.material;
    const double modulus = settings.elasticity.model == fem::PlanarModel::plane_strain
                               ? m.youngs_modulus / (1. - m.poisson_ratio * m.poisson_ratio)
                               : m.youngs_modulus;
    for (const SceneCrack& crack : scene_cracks(settings.scene, problem->system().triangulation()))
      result.crack_tips.push_back(
          crack_tip_factors(problem->system().get_dof_handler(), problem->system().get_mapping(),
                            problem->solution(), crack.face, crack.face + 1, modulus,
                            crack_fit_from * crack.tip_size, crack_fit_to * crack.tip_size));
  }
}

template <int dim>
void GearMeshStiffness<dim>::evaluate_pairs(const contact::ContactResults<dim>& contact)
{
  double total = 0.;
  for (unsigned int k = 0; k < candidate_pairs.size(); ++k)
    total += std::max(contact.pairs[k].normal_force, 0.);
  result.pairs = candidate_pairs;
  result.loaded_pairs = 0;
  result.max_contact_pressure = 0.;
  for (unsigned int k = 0; k < candidate_pairs.size(); ++k)
  {
    const contact::PairResult<dim>& pair_result = contact.pairs[k];
    ToothPairLoad& load = result.pairs[k];
    load.normal_force = pair_result.normal_force;
    load.load_share = total > 0. ? std::max(pair_result.normal_force, 0.) / total : 0.;
    load.max_pressure = pair_result.max_pressure;
    load.contact_length = pair_result.contact_length;
    load.closed_nodes = pair_result.n_closed;
    locate_load(pair_result, pair, load);
    result.loaded_pairs += load.load_share > 1e-6;
    result.max_contact_pressure = std::max(result.max_contact_pressure, load.max_pressure);
  }
  if constexpr (dim == 3) // the load across the face width (issue 27)
  {
    result.face_load.clear();
    for (unsigned int k = 0; k < candidate_pairs.size(); ++k)
      append_face_load(
          contact.pairs[k], candidate_pairs[k].pair,
          {pair.common_face_width, settings.scene.mesh.layers, settings.elasticity.degree},
          result.face_load);
    result.face_load_factor = summarise_face_load(result.face_load).factor;
    mesh_forces(contact, candidate_pairs.size(), pair.working_pressure_angle,
                0.5 * pair.common_face_width, result);
  }
}

template <int dim>
const std::vector<std::pair<typename DoFHandler<dim>::active_cell_iterator, unsigned int>>&
GearMeshStiffness<dim>::fillet_faces()
{
  // The fillets, as the influence-coefficient model reads them (stiffness/root_stress.h).
  if (fillets.empty())
    fillets = stiffness::fillet_faces(problem->system().get_dof_handler(), pair);
  return fillets;
}

template <int dim>
std::vector<types::global_dof_index> GearMeshStiffness<dim>::reported_dofs()
{
  std::vector<types::global_dof_index> dofs, cell_dofs;
  for (const auto& [cell, f] : fillet_faces())
  {
    cell_dofs.resize(cell->get_fe().n_dofs_per_cell());
    cell->get_dof_indices(cell_dofs);
    dofs.insert(dofs.end(), cell_dofs.begin(), cell_dofs.end());
  }
  // The crack tip's K comes from the displacements of both crack faces (evaluate_crack_tips).
  std::set<types::boundary_id> crack_faces;
  for (const SceneCrack& crack : scene_cracks(settings.scene, problem->system().triangulation()))
    crack_faces.insert({crack.face, static_cast<types::boundary_id>(crack.face + 1)});
  if (!crack_faces.empty())
    for (const auto& cell : problem->system().get_dof_handler().active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && crack_faces.count(cell->face(f)->boundary_id()) > 0)
        {
          cell_dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(cell_dofs);
          dofs.insert(dofs.end(), cell_dofs.begin(), cell_dofs.end());
        }
  return dofs;
}

template <int dim>
void GearMeshStiffness<dim>::evaluate_root_stress()
{
  // Root stress: the largest first principal stress on the fillets (fillet_faces), where tooth
  // root cracks start (ISO 6336-3 takes the tensile fillet stress); the influence-coefficient
  // model reads its FE body's fillets alike (stiffness/root_stress.h).
  const fem::ElasticSystem<dim>& system = problem->system();
  const Vector<double>& u = problem->solution();
  for (const bool pinion : {true, false})
  {
    std::vector<std::pair<typename DoFHandler<dim>::active_cell_iterator, unsigned int>> faces;
    for (const auto& face : fillet_faces())
      if ((face.first->material_id() == geometry::scene_ids::pinion_body) == pinion)
        faces.push_back(face);
    const FilletStressPoints points =
        fillet_stress_points(system.get_mapping(), system.get_dof_handler(), faces);
    std::vector<double> values;
    for (const types::global_dof_index dof : points.dofs)
      values.push_back(u[dof]);
    (pinion ? result.pinion_root_stress : result.wheel_root_stress) =
        largest_fillet_stress(points, values, settings.material, settings.elasticity.model);
  }
}

template <int dim>
void GearMeshStiffness<dim>::output_results()
{
  if (settings.output_directory.empty())
    return;
  problem->complete_field(); // a rolling sweep completed the field only where it reports
  result.output_files = problem->output_results(settings.output_directory, settings.output_base);
}

template class GearMeshStiffness<2>;
template class GearMeshStiffness<3>;
} // namespace gearstiff::stiffness
