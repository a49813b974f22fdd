#include "app/stiffness/stiffness_parameters.h"

#include "app/core/number_text.h"
#include "app/core/parameter_patterns.h"
#include "app/core/units.h"
#include "app/kinematics/kinematics_parameters.h"
#include "app/scenes/fe_contact_parameters.h"
#include "app/scenes/geometry_parameters.h"
#include "dynamics/train_model.h"
#include "errors/errors.h"
#include "errors/format.h"
#include "errors/limits.h"
#include "geometry/tooth_fault.h"
#include "kinematics/gear_pair.h"
#include "kinematics/hertz.h"
#include "stiffness/influence_sweep.h"
#include "stiffness/transmission_error.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <sstream>
#include <unistd.h>

namespace gearstiff::app
{
void declare_stiffness_parameters(ParameterHandler& prm)
{
  declare_gear_pair_parameters(prm);
  declare_tooth_modification_parameters(prm);
  const geometry::GearPairSceneSpec scene = stiffness::default_stiffness_scene();
  // The sector cut faces are left free by the stiffness analysis.
  declare_gear_scene_parameters(prm, scene, true);
  declare_scene_mesh_parameters(prm, scene.mesh, true);
  prm.enter_subsection("Mesh");
  prm.declare_entry("helical flanks", "chords", Selection("chords|helicoid"),
                    "what a helical pair's contact measures its gaps between [-]: chords = the "
                    "meshed surfaces, whose hexahedron edges between two layers are chords of "
                    "the helices, up to r·Δφ²/8 inside (the model CalculiX solves on the "
                    "exported deck); helicoid = the flanks' involute helicoids. Their errors in "
                    "the layers have opposite signs and both fall as the layer height squared "
                    "(docs/helical.md \"Layers and the helicoids\")");
  prm.declare_entry("layer extrapolation", "none", Selection("none|richardson"),
                    "3D [-]: none = the result on Mesh/layers; richardson = every position solved "
                    "on Mesh/layers (L) and on 2L layers, and k, TE, load shares and the mesh "
                    "forces extrapolated to zero layer height, x∞ = x(2L) + (x(2L) − x(L))/3 (the "
                    "layers' error falls as their height squared); pressures, line loads, K_Hβ "
                    "and root stresses are the 2L solve's. About 4.5× the time of L layers "
                    "alone; a correction above 5 % fails (exit 3): more layers. docs/helical.md "
                    "\"Layer extrapolation\"");
  prm.leave_subsection();

  declare_fe_contact_parameters(prm);
  prm.enter_subsection("Finite elements");
  // Q2 on the default scene: docs/accuracy.md.
  prm.set("Element degree", std::to_string(stiffness::default_stiffness_elasticity().degree));
  prm.leave_subsection();
  prm.enter_subsection("Contact");
  // docs/references.md §1: the ANSYS model used μ = 0.01 between the teeth.
  prm.set("Friction coefficient",
          format_number(kinematics::split_path_published::tooth_friction, 10));
  prm.leave_subsection();

  // The load has one name in every command that builds the scene (mesh, stiffness, cai, run).
  prm.enter_subsection("Gear pair scene");
  prm.declare_entry("pinion torque", "49.4", Double(),
                    "T1 on the pinion [N·m], > 0 (drives the loaded flanks into contact); "
                    "docs/references.md §1: 7.5 kW at 1450 rpm");
  prm.leave_subsection();

  prm.enter_subsection("Stiffness");
  prm.declare_entry("mode", "single", Selection("single|double|roll angle|sweep"),
                    "single: the pitch point if it lies in the single-contact zone, else that "
                    "zone's middle; double: middle of the first double-contact zone; roll "
                    "angle: the 'pinion roll angle' below; sweep: k(θ) at 'sweep positions' "
                    "positions over 'sweep base pitches'");
  prm.declare_entry("pinion roll angle", "20", Double(),
                    "mode roll angle: pinion roll angle ℓ/r_b1 of the reference pair, ℓ from "
                    "T1 along the line of action [deg]; must lie on the path of contact");
  declare_elastic_constants(prm, "both gears");
  prm.declare_entry("sweep start", "-1", Double(),
                    "pinion roll angle of the first sweep interval's start [deg]; negative: "
                    "the start of active contact A");
  prm.declare_entry("sweep base pitches", "1", Double(),
                    "span of the sweep in transverse base pitches [-] (1: one mesh period)");
  prm.declare_entry("sweep positions", "32", Integer(),
                    "positions N of the sweep [-], at the middles of N equal intervals");
  // Micro-geometry studies (issue 27): a list of torques, further modification sets.
  prm.declare_entry(
      "torques", "", Anything(),
      "pinion torques [N·m], comma-separated, ascending, each > 0; empty = 'Gear pair "
      "scene/pinion torque' alone. A sweep then gives TE(θ), k(θ), load sharing and pressure "
      "per torque and the Harris-map table te_map (one scene and factorization "
      "per position for all torques)");
  prm.declare_entry("variants", "", Anything(),
                    "further modification sets swept like the base one, ';'-separated, each "
                    "'name = value, ...' of Gear pair/Pinion and Wheel entries ('tip relief = "
                    "10' both gears, 'Pinion/tip relief = 10' one), e.g. 'tip relief = 5; tip "
                    "relief = 10'; empty = none");
  prm.declare_entry(
      "sweep mesh", "automatic", Selection("automatic|per position|once"),
      "per position: every sweep position builds, meshes and factorizes its own scene (the "
      "reference); once: each rank meshes one scene, refined along every flank contact of the "
      "sweep, factorizes it once and turns the bodies rigidly to each position (the contact "
      "paired afresh there, warm-started from the neighbour; what a position reports is "
      "completed from the kept unit responses in 2D, by one back-substitution in 3D; needs "
      "the direct solver's Schur complement); automatic (the default): once in 2D, per "
      "position in 3D and for scenes with a broken, chipped or spalled tooth (root cracks "
      "roll: every flank stays whole) or without the direct solver's Schur complement. "
      "In 2D once meets the accuracy of per position (k within 0.3 %, TE 0.05 µm, load share "
      "0.5 %: external and internal pairs, μ = 0.01, a torque list, 2 MPI ranks) at ~0.04 s a "
      "position after ~3-4 s once (default pair, 128 positions, 1 rank: ~9 s, 16x faster than "
      "per position); in 3D once is within 0.5 % of per position, nearer the converged k, but "
      "only ~1.6x faster for 2.5x the memory (docs: bench/contact_speed.md), so 3D stays per "
      "position");
  prm.declare_entry(
      "contact model", "finite element", Selection("finite element|influence coefficients"),
      "finite element: mortar contact on a mesh that resolves the Hertz zone (the reference); "
      "influence coefficients (mode sweep, Coulomb friction in 2D, profile modifications, rounded "
      "tips, "
      "no "
      "tooth faults; 2D plane strain; 3D: spur and helical pairs, lead crowning with at least 16 "
      "layers, lead slope and end relief on spur pairs with at least 16): a FE body "
      "of both gears that does not resolve the Hertz zone (flank cells h_f = "
      "0.04·m_n; 3D 0.08·m_n with the band of swept contacts meshed at 1.5·h_f = 0.12·m_n; the "
      "rims coarse beyond the modelled teeth) factored once, the influence coefficients of a grid "
      "on every meshing flank (3D: on every node plane) read 3·h_f under the surface (0.12·m_n; "
      "3D 0.24·m_n), the analytic plane-strain Hertz layer above that depth, one small contact "
      "problem per position (docs/ltca.md); the root stresses from the FE body's fillets under "
      "the solved loads in 2D, not evaluated in 3D (nan in the tables, null in JSON)");
  prm.declare_entry("influence grid points", "64", Integer(8, 10000),
                    "contact model influence coefficients: grid points per flank over the path "
                    "of contact [-]; the step must not exceed the matching depth 3·h_f (0.12·m_n; "
                    "3D 0.24·m_n) nor half the shortest relief length");
  prm.declare_entry("write vtu", "false", Bool(),
                    "write VTU/PVTU of every solved position into the -o folder");
  prm.declare_entry("published reference", "true", Bool(),
                    "print the ANSYS values of docs/references.md §1 (Reszuta & Drewniak 2015) "
                    "beside ours when the pair is that case (decided from the geometry: teeth, "
                    "face widths, tip diameters); false: never");
  prm.leave_subsection();
}

void declare_stiffness_sweep_parameters(ParameterHandler& prm, unsigned int positions)
{
  declare_stiffness_parameters(prm);
  prm.enter_subsection("Stiffness");
  prm.set("mode", "sweep");
  prm.set("sweep positions", std::to_string(positions));
  prm.leave_subsection();
}

std::string mode_name(StiffnessMode mode)
{
  switch (mode)
  {
  case StiffnessMode::single:
    return "single";
  case StiffnessMode::double_pair:
    return "double";
  case StiffnessMode::roll_angle:
    return "roll angle";
  case StiffnessMode::sweep:
    break;
  }
  return "sweep";
}

ParameterNames stiffness_parameter_names()
{
  ParameterNames names = gear_scene_parameter_names();
  names[geometry::scene_field::position] = "Stiffness/mode";
  names[geometry::scene_field::pinion_roll_angle] = "Stiffness/pinion roll angle";
  names[geometry::scene_field::young_modulus] = "Stiffness/Young's modulus";
  names[geometry::scene_field::poisson_ratio] = "Stiffness/Poisson's ratio";
  names[stiffness::stiffness_parameter::torque] = "Gear pair scene/pinion torque";
  names[stiffness::stiffness_parameter::torques] = "Stiffness/torques";
  names[stiffness::stiffness_parameter::positions] = "Stiffness/sweep positions";
  names[stiffness::stiffness_parameter::pitches] = "Stiffness/sweep base pitches";
  names[stiffness::stiffness_parameter::start] = "Stiffness/sweep start";
  names[stiffness::stiffness_parameter::sweep_mesh] = "Stiffness/sweep mesh";
  names[geometry::scene_field::swept_positions] = "Stiffness/sweep mesh";
  names[stiffness::stiffness_parameter::contact_model] = "Stiffness/contact model";
  names[stiffness::stiffness_parameter::influence_grid_points] = "Stiffness/influence grid points";
  return names;
}

namespace
{
StiffnessMode parse_mode(const std::string& text)
{
  for (const StiffnessMode mode : {StiffnessMode::single, StiffnessMode::double_pair,
                                   StiffnessMode::roll_angle, StiffnessMode::sweep})
    if (text == mode_name(mode))
      return mode;
  throw InputError("Stiffness/mode",
                   "'" + text + "' is not one of single, double, roll angle, sweep");
}

// "Stiffness/torques": comma-separated numbers (N·m); empty: none. The analysis checks sign and
// order (stiffness::check_torque_list).
std::vector<double> parse_torque_list(const std::string& text)
{
  std::vector<double> torques;
  if (text.find_first_not_of(" \t") == std::string::npos)
    return torques;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
  {
    const std::optional<double> value = number_in(item);
    if (!value)
      throw InputError("Stiffness/torques", "'" + item + "' is not a torque [N·m]");
    torques.push_back(*value);
  }
  with_parameter_names(stiffness_parameter_names(), [&] { stiffness::check_torque_list(torques); });
  return torques;
}

// The micro-geometry of both gears (Gear pair/Pinion, Gear pair/Wheel) and the variants of
// "Stiffness/variants", each checked against the generated teeth before anything is meshed.
void parse_modification_stage(ParameterHandler& prm, const std::string& variants,
                              StiffnessParameters& p)
{
  geometry::GearPairSceneSpec& scene = p.settings.scene;
  const PairModificationText text = read_tooth_modification_text(prm);
  const unsigned int dimension = scene.mesh.dimension;
  scene.pinion_modifications = parse_gear_modifications(text.pinion, false, dimension);
  scene.wheel_modifications = parse_gear_modifications(text.wheel, true, dimension);
  geometry::check_tooth_modifications(scene);
  for (const ModificationVariant& v :
       parse_modification_variants(variants, text, "Stiffness/variants"))
  {
    StiffnessVariant variant{v.label, parse_gear_modifications(v.text.pinion, false, dimension),
                             parse_gear_modifications(v.text.wheel, true, dimension)};
    geometry::GearPairSceneSpec checked = scene;
    checked.pinion_modifications = variant.pinion;
    checked.wheel_modifications = variant.wheel;
    geometry::check_tooth_modifications(checked);
    p.variants.push_back(variant);
  }
  if (!p.variants.empty() && p.mode != StiffnessMode::sweep)
    throw InputError("Stiffness/variants", "applies to mode sweep only");
  // One position solves at 'Gear pair scene/pinion torque': a list there was ignored.
  if (!p.settings.torques.empty() && p.mode != StiffnessMode::sweep)
    throw InputError("Stiffness/torques", "applies to mode sweep only (one position runs at "
                                          "Gear pair scene/pinion torque)");
}

// The work of an influence-coefficient sweep (s): its FE body once (scene, factorization,
// coefficients; on two or more ranks a gear a rank, so at most half of it — measured 46.4 → 27.4 s
// on the helical built-in pair, 7.0 → 5.4 s on the spur 3D one, 2026-12-04), then a small contact
// problem a position and torque on rank 0 (stiffness::influence_sweep). The exact path's seconds a
// position do not apply: they refused a 3D sweep of 200 positions as 1.3 h (its 23.3 s a position)
// that the fast model runs in ~8 s (found 2026-12-04). Measured on one rank (docs/ltca.md "Cost",
// the sweep's own times): 2D Q2 default pair 1.84 s once (59.4k DoFs); 3D Q1 8 layers 6.40 s once
// (75.7k DoFs); the contact problems ≤ 0.25 ms a position and torque (the helical built-in pair at
// β 15°, 32 positions 8 ms, 8 torques × 32 positions 20 ms, 2026-12-04; spur 3D 0.8 ms for 32).
// Another degree scales the body by (p / p_measured)^dim, more layers by layers / 8; each variant
// is a sweep of its own.
double check_influence_sweep_work(const StiffnessParameters& p)
{
  const stiffness::GearMeshStiffnessSettings& s = p.settings;
  const unsigned int dim = s.scene.mesh.dimension;
  const bool gear_a_rank = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1;
  const double body = (dim == 3 ? 6.40 * s.scene.mesh.layers / 8. : 1.84) *
                      std::pow(s.elasticity.degree / (dim == 3 ? 1. : 2.), double(dim)) /
                      (gear_a_rank ? 2. : 1.);
  const double solves = double(p.sweep.positions) * std::max<std::size_t>(1, s.torques.size());
  constexpr double seconds_a_solve = 0.25e-3;
  const double seconds = (body + solves * seconds_a_solve) * (1. + double(p.variants.size()));
  if (seconds <= limits::max_run_seconds)
    return seconds;
  // Only the contact problems can push it there (~1.4·10⁷ positions × torques).
  throw InputError(s.torques.size() > 1 ? "Stiffness/torques" : "Stiffness/sweep positions",
                   std::to_string(p.sweep.positions) + " positions" +
                       (s.torques.size() > 1 ? " × " + std::to_string(s.torques.size()) + " torques"
                                             : std::string()) +
                       " would take at least " + format_number(seconds / 3600., 3) +
                       " h with influence coefficients (" +
                       format_number(seconds_a_solve * 1e3, 2) + " ms a contact problem; limit " +
                       format_number(limits::max_run_seconds / 3600., 2) +
                       " h, docs/limits.md): fewer positions or torques");
}

// The work of a sweep (s, on the ranks of MPI_COMM_WORLD), estimated from what it will solve
// before the positions are allocated, and refused above limits::max_run_seconds naming the
// parameter that pushed it there (2·10⁹ positions were allocated; a 3D sweep of 5000
// positions announced 35 h at 25.5 s a position; 10⁵ torques and 10³ variants were not
// counted). Seconds a position, measured on one rank (bench/contact_speed.md): 2D Q2 per
// position 18.7 s / 32 = 0.58 s, once 0.07 s (0.08–0.1 s measured 2026-11-26, 128 positions);
// 3D Q1 8 layers per position 373.0 s / 16 = 23.3 s, once 228.5 s / 16 = 14.3 s (32 positions
// on 2 ranks, 2026-12-01). Another degree scales them by the unknowns, (p / p_measured)^dim,
// and more layers in 3D by layers / 8: a lower bound, as the factorization grows faster than
// the unknowns. Each further torque of a list costs at least 0.15 of a position (8 torques ×
// 32 positions 21.9 s against 10.5 s, once), each variant at least half the base sweep (15.7 s
// against 10.5 s). So this is a lower bound: finer meshes take longer.
double check_sweep_work(const StiffnessParameters& p)
{
  const stiffness::GearMeshStiffnessSettings& s = p.settings;
  if (s.contact_model == stiffness::ContactModel::influence_coefficients)
    return check_influence_sweep_work(p);
  const bool once = p.sweep.mesh == stiffness::SweepMesh::once;
  const unsigned int dim = s.scene.mesh.dimension;
  const double measured =
      dim == 3 ? (once ? 228.5 / 16. : 373.0 / 16.) : (once ? 0.07 : 18.7 / 32.);
  const unsigned int ranks = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  const double positions = std::ceil(double(p.sweep.positions) / ranks) * measured;
  // The factors beyond the measured case, each with the parameter that sets it.
  const std::vector<std::pair<double, std::string>> factors{
      {std::pow(s.elasticity.degree / (dim == 3 ? 1. : 2.), double(dim)),
       "Finite elements/Element degree"},
      {dim == 3 ? std::max(1., s.scene.mesh.layers / 8.) : 1., "Mesh/layers"},
      {1. + 0.15 * (s.torques.empty() ? 0. : double(s.torques.size()) - 1.), "Stiffness/torques"},
      {1. + 0.5 * double(p.variants.size()), "Stiffness/variants"},
      // L and 2L layers: at least 1 + 2 solves of L.
      {p.layer_extrapolation ? 3. : 1., "Mesh/layer extrapolation"}};
  double seconds = positions;
  for (const auto& [factor, name] : factors)
    seconds *= factor;
  if (seconds <= limits::max_run_seconds)
    return seconds;
  // The positions alone beyond the limit, or else the largest factor, pushed it over.
  const auto largest = std::max_element(factors.begin(), factors.end());
  const std::string parameter =
      positions > limits::max_run_seconds ? "Stiffness/sweep positions" : largest->second;
  throw InputError(
      parameter,
      std::to_string(p.sweep.positions) + " positions" +
          (s.torques.size() > 1 ? " × " + std::to_string(s.torques.size()) + " torques"
                                : std::string()) +
          (p.variants.empty()
               ? std::string()
               : " × " + std::to_string(p.variants.size() + 1) + " modification sets") +
          " would take at least " + format_number(seconds / 3600., 3) + " h on " +
          std::to_string(ranks) + " rank(s) at " +
          format_number(measured * factors[0].first * factors[1].first, 3) + " s a position (" +
          std::to_string(dim) + "D, Q" + std::to_string(s.elasticity.degree) +
          (dim == 3 ? ", " + std::to_string(s.scene.mesh.layers) + " layers" : std::string()) +
          (once ? ", once" : ", per position") + "; limit " +
          format_number(limits::max_run_seconds / 3600., 2) +
          " h, docs/limits.md): fewer positions, torques, variants or layers, a lower degree, "
          "or more MPI ranks");
}

// The relief lengths that read `auto` (the long relief: from the tip to the start of
// single-tooth contact, (ε_α − 1)·p_bt along the path of contact for either gear) as derived
// sizes, and a note for a relief amount that looks like a unit slip: below 0.1 µm (a
// relief typed in mm) or from 5 % of m_n up (more than any relief removes: mm, or a relief
// meant for a larger gear). The run goes on: such a value is possible, only unlikely.
void note_relief_sizes(const kinematics::GearPairGeometry& pair, StiffnessParameters& p)
{
  const geometry::GearPairSceneSpec& scene = p.settings.scene;
  const double tip_side[2] = {pair.contact_end - pair.single_contact_end(),
                              pair.single_contact_start() - pair.contact_start};
  for (const bool wheel : {false, true})
  {
    const std::string gear = wheel ? "Gear pair/Wheel/" : "Gear pair/Pinion/";
    const geometry::GearModifications& m =
        wheel ? scene.wheel_modifications : scene.pinion_modifications;
    const double module = (wheel ? scene.pair.wheel : scene.pair.pinion).normal_module;
    for (const geometry::ToothModification& t : m.all_teeth)
    {
      const bool tip = t.kind == geometry::ModificationKind::tip_relief;
      if (!(tip || t.kind == geometry::ModificationKind::root_relief) || !(t.amount > 0.))
        continue;
      const std::string name = gear + (tip ? "tip relief" : "root relief");
      if (tip && t.length < 0.)
        p.derived_sizes.push_back({name + " length", tip_side[wheel ? 1 : 0],
                                   "auto: from the tip to the start of single-tooth contact, "
                                   "(ε_α − 1)·p_bt along the path of contact"});
      if (t.amount < 0.1e-6)
        p.input_notes.push_back(name + " = " + format_number(t.amount * 1e6, 4) +
                                " µm is below 0.1 µm, far less than any relief removes: was it "
                                "given in mm? (the unit is µm)");
      else if (t.amount >= 0.05 * module * (1. - 1e-12)) // 200 µm on 4 mm: from µm and mm
        p.input_notes.push_back(name + " = " + format_number(t.amount * 1e6, 4) +
                                " µm is 5 % of m_n = " + format_number(module * 1e3, 4) +
                                " mm or more, more than a relief removes: check the unit (µm)");
    }
  }
}

// Influence coefficients (docs/ltca.md): a sweep model; what it cannot carry is refused here,
// before anything is meshed. Friction is not applied (a note in the report).
void check_influence_parameters(StiffnessParameters& p)
{
  if (p.mode != StiffnessMode::sweep)
    throw InputError("Stiffness/contact model", "influence coefficients runs in Stiffness/mode = "
                                                "sweep only (a single position: finite element)");
  if (p.write_vtu)
    throw InputError("Stiffness/write vtu",
                     "influence coefficients solve no FE field per position: nothing to write");
  stiffness::check_influence_settings(p.settings);
  for (const StiffnessVariant& variant : p.variants)
  {
    if (!variant.pinion.by_tooth.empty() || !variant.wheel.by_tooth.empty())
      throw InputError("Stiffness/contact model", "influence coefficients cannot carry a tooth "
                                                  "fault of Stiffness/variants");
    // Each variant's own checks too, before the base set is swept: a lead crowning only a variant
    // carries, on 8 layers, was refused after the base sweep had run (found 2026-12-06).
    try
    {
      stiffness::check_influence_settings(with_variant(p.settings, variant));
    }
    catch (const InputError& error)
    {
      throw InputError(error.parameter(),
                       error.reason() + " (Stiffness/variants: '" + variant.label + "')");
    }
  }
  if (p.settings.contact.friction_coefficient > 0. && p.settings.scene.mesh.dimension == 3)
    p.input_notes.push_back(
        "Contact/Friction coefficient = " +
        format_number(p.settings.contact.friction_coefficient, 4) +
        " is not applied by Stiffness/contact model = influence coefficients in 3D: its 3D "
        "contact problem is frictionless (friction is verified in 2D only, docs/ltca.md §4)");
}

// The checks the analysis makes before it meshes, run at parse time: the library's own (one
// copy each), their field names mapped to the parameters by the caller.
void check_stiffness_parameters(StiffnessParameters& p, const kinematics::GearPairGeometry& pair)
{
  stiffness::GearMeshStiffnessSettings& s = p.settings;
  stiffness::check_stiffness_settings(s);
  // The pattern admits the closed interval; ν = 0.5 makes λ infinite (incompressible) and
  // E = 0 no material at all. One range for E and for ν in every command: kinematics' checks.
  kinematics::check_young_modulus(s.material.youngs_modulus, geometry::scene_field::young_modulus);
  kinematics::check_poisson_ratio(s.material.poisson_ratio, geometry::scene_field::poisson_ratio);
  // `once` rolls one factorization: the direct solver's Schur complement. With an iterative
  // solver the contact module refused it naming Contact/Iteration solves, which the user had
  // not set; full re-solve is refused there under its own name.
  if (p.mode == StiffnessMode::sweep && p.sweep.mesh == stiffness::SweepMesh::once &&
      s.linear_solver.method != fem::LinearSolverMethod::direct_mumps)
    throw InputError("Linear solver/Method", "Stiffness/sweep mesh = once needs the direct "
                                             "solver (an iterative one sweeps per position)");
  if (s.contact_model == stiffness::ContactModel::influence_coefficients)
    check_influence_parameters(p);
  if (p.layer_extrapolation && s.scene.mesh.dimension != 3)
    throw InputError("Mesh/layer extrapolation",
                     "richardson needs Mesh/dimension = 3 (a 2D scene has no layers)");
  if (p.layer_extrapolation && s.contact_model != stiffness::ContactModel::finite_element)
    throw InputError("Mesh/layer extrapolation", "richardson runs with Stiffness/contact model = "
                                                 "finite element only");
  if (p.layer_extrapolation)
  {
    // The helical default count (16 per unit of ε_β; a spur mesh of one layer as the floor):
    // below it the layers' error is not yet the Δz² term Richardson removes. The built-in pair's
    // ladder (docs/helical.md "Mesh convergence"): 13, 14, 20 and 26 layers follow one 1/L²
    // curve to 0.06 %, 7 and 10 layers lie 12 % and 2.8 % off it (the mortar artifact of the
    // contact lines starts a pair closed), and 7/14 would extrapolate 3.9 % low.
    geometry::SceneMeshSettings one_layer = s.scene.mesh;
    one_layer.layers = 1;
    const unsigned int least = geometry::helical_mesh_defaults(one_layer, pair).layers;
    // A fault narrower than the face is meshed to whole layers (a cell is removed by its
    // centroid's z): unless its extent is a whole number of layers on L (and so on 2L), the two
    // levels carry different faults, and the extrapolation would mix that change into the
    // layers' error (a crack over half the face of the small helical pair: 5 layers keep 2 of
    // them cracked, 10 layers 5; k 98.31 → 97.89 N/µm, extrapolated 97.75, against 96.34 → 96.85
    // → 97.02 for a crack over 0.6 = 3/5 of the face; measured 2026-12-03).
    std::vector<const geometry::ToothModification*> faults;
    const auto collect = [&faults](const geometry::GearModifications& m)
    {
      for (const auto& t : m.all_teeth)
        faults.push_back(&t);
      for (const auto& [tooth, list] : m.by_tooth)
        for (const auto& t : list)
          faults.push_back(&t);
    };
    collect(s.scene.pinion_modifications);
    collect(s.scene.wheel_modifications);
    for (const StiffnessVariant& variant : p.variants)
    {
      collect(variant.pinion);
      collect(variant.wheel);
    }
    for (const geometry::ToothModification* fault : faults)
    {
      if (!geometry::is_partial_width(*fault))
        continue;
      const double layers = fault->width_fraction * s.scene.mesh.layers;
      const bool whole_layers = fault->kind == geometry::ModificationKind::root_crack &&
                                !fault->parabolic_front &&
                                std::abs(layers - std::round(layers)) <= 1e-9 * layers;
      if (!whole_layers)
        throw InputError(
            "Mesh/layer extrapolation",
            "a fault narrower than the face is meshed to whole layers, so on " +
                std::to_string(s.scene.mesh.layers) + " and " +
                std::to_string(2 * s.scene.mesh.layers) +
                " layers it would differ and the extrapolation would mix that change into the "
                "layers' error: extrapolate a root crack with a straight front whose crack width "
                "fraction is a multiple of 1/Mesh/layers, or a fault across the whole face");
    }
    if (s.scene.mesh.layers < least)
      throw InputError("Mesh/layers",
                       std::to_string(s.scene.mesh.layers) +
                           " layers are too few for Mesh/layer extrapolation: at least " +
                           std::to_string(least) +
                           " (16 per unit of ε_β = " + format_number(pair.overlap_ratio, 4) +
                           "), where the layers' error falls as their height squared "
                           "(docs/helical.md \"Layer extrapolation\")");
  }
  if (p.mode == StiffnessMode::sweep)
  {
    p.estimated_seconds = check_sweep_work(p);
    stiffness::sweep_positions(pair, p.sweep);
  }
  // Off the path of contact A..E no tooth pair touches: there is no mesh to be stiff.
  const double r_b1 = 0.5 * pair.pinion.base_diameter;
  // The ends as printed below (6 decimals of a degree) must be accepted: a roll angle within
  // half a unit of the last printed digit of an end is that end.
  const double printed = 0.5e-6 * degree;
  const double start_angle = pair.contact_start / r_b1, end_angle = pair.contact_end / r_b1;
  if (p.mode == StiffnessMode::roll_angle)
  {
    if (std::abs(s.scene.pinion_roll_angle - start_angle) <= printed)
      s.scene.pinion_roll_angle = start_angle;
    if (std::abs(s.scene.pinion_roll_angle - end_angle) <= printed)
      s.scene.pinion_roll_angle = end_angle;
  }
  const double position = s.scene.pinion_roll_angle * r_b1;
  if (p.mode == StiffnessMode::roll_angle &&
      (position < pair.contact_start - 1e-12 || position > pair.contact_end + 1e-12))
    throw InputError(
        geometry::scene_field::pinion_roll_angle,
        "no tooth pair is in contact at " + std::to_string(s.scene.pinion_roll_angle / degree) +
            "°: the path of contact spans " + std::to_string(pair.contact_start / r_b1 / degree) +
            "° to " + std::to_string(pair.contact_end / r_b1 / degree) + "°");
}
} // namespace

namespace
{

// The variants' modification sets as stiffness::once_sweep_valid takes them.
std::vector<std::pair<geometry::GearModifications, geometry::GearModifications>>
variant_modifications(const StiffnessParameters& p)
{
  std::vector<std::pair<geometry::GearModifications, geometry::GearModifications>> sets;
  for (const StiffnessVariant& variant : p.variants)
    sets.emplace_back(variant.pinion, variant.wheel);
  return sets;
}

// `Mesh/layers = auto` with influence coefficients in 3D: at least the count that model accepts
// for the face (a helical face's node planes at most 0.74·m_n apart, 16 layers with lead
// crowning, on the base set or any variant; stiffness::influence_least_layers), so that a user
// who leaves the layers to the program is not refused for them. The automatic count is the exact
// path's (16 per unit of ε_β), which on a narrow or small-module helical face lies below the
// model's spacing (z 27/41, m_n 2 mm, β 12°, b 16 mm: 9 layers, 1.78 mm apart, where 11 are
// needed) and gives a spur pair 8 where lead crowning needs 16.
void raise_automatic_layers(ParameterHandler& prm, StiffnessParameters& p)
{
  stiffness::GearMeshStiffnessSettings& s = p.settings;
  prm.enter_subsection("Mesh");
  const bool automatic = prm.get("layers") == "auto";
  prm.leave_subsection();
  if (!automatic || s.contact_model != stiffness::ContactModel::influence_coefficients ||
      s.scene.mesh.dimension != 3)
    return;
  unsigned int least = stiffness::influence_least_layers(s);
  for (const StiffnessVariant& variant : p.variants)
    least = std::max(least, stiffness::influence_least_layers(with_variant(s, variant)));
  if (least <= s.scene.mesh.layers)
    return;
  p.input_notes.push_back("Mesh/layers = auto takes " + std::to_string(least) + " layers (" +
                          std::to_string(s.scene.mesh.layers) +
                          " for the exact path): the fewest influence coefficients are verified "
                          "on for this face (docs/ltca.md §3)");
  s.scene.mesh.layers = least;
}
} // namespace

stiffness::GearMeshStiffnessSettings with_variant(const stiffness::GearMeshStiffnessSettings& base,
                                                  const StiffnessVariant& variant)
{
  stiffness::GearMeshStiffnessSettings with = base;
  with.scene.pinion_modifications = variant.pinion;
  with.scene.wheel_modifications = variant.wheel;
  return with;
}

StiffnessParameters parse_stiffness_parameters(ParameterHandler& prm)
{
  StiffnessParameters p;
  stiffness::GearMeshStiffnessSettings& s = p.settings;
  s.scene = stiffness::default_stiffness_scene();
  s.scene.pair = parse_gear_pair_parameters(prm, p.derived_sizes);
  parse_gear_scene_parameters(prm, s.scene);
  prm.enter_subsection("Gear pair scene");
  s.pinion_torque = prm.get_double("pinion torque");
  prm.leave_subsection();
  s.scene.mesh =
      parse_scene_mesh_parameters(prm, gear_pair_mesh_defaults(s.scene.mesh, s.scene.pair),
                                  mesh_module_scale(s.scene.pair), &p.derived_sizes);
  prm.enter_subsection("Mesh");
  s.helicoid_flanks = prm.get("helical flanks") == "helicoid";
  p.layer_extrapolation = prm.get("layer extrapolation") == "richardson";
  prm.leave_subsection();
  parse_fe_contact_parameters(prm, s.elasticity, s.linear_solver, s.contact);

  prm.enter_subsection("Stiffness");
  p.mode = parse_mode(prm.get("mode"));
  s.scene.pinion_roll_angle = prm.get_double("pinion roll angle") * degree;
  parse_elastic_constants(prm, s.material.youngs_modulus, s.material.poisson_ratio);
  const double start = prm.get_double("sweep start");
  p.sweep.base_pitches = prm.get_double("sweep base pitches");
  const long positions = prm.get_integer("sweep positions");
  const std::string sweep_mesh = prm.get("sweep mesh");
  s.contact_model = prm.get("contact model") == "influence coefficients"
                        ? stiffness::ContactModel::influence_coefficients
                        : stiffness::ContactModel::finite_element;
  s.influence_grid_points = prm.get_integer("influence grid points");
  p.write_vtu = prm.get_bool("write vtu");
  p.published_reference =
      prm.get_bool("published reference") && kinematics::is_split_path_pair(s.scene.pair);
  const std::string torques = prm.get("torques");
  const std::string variants = prm.get("variants");
  prm.leave_subsection();
  s.torques = parse_torque_list(torques);
  parse_modification_stage(prm, variants, p);
  p.sweep.mesh = sweep_mesh == "once" || (sweep_mesh == "automatic" &&
                                          stiffness::once_sweep_valid(s, variant_modifications(p)))
                     ? stiffness::SweepMesh::once
                     : stiffness::SweepMesh::per_position;

  raise_automatic_layers(prm, p);

  // A count below one becomes 0, which the sweep's own check (stiffness::sweep_positions)
  // refuses in mode sweep; the other modes do not use it.
  p.sweep.positions = static_cast<unsigned int>(std::clamp<long>(positions, 0, UINT_MAX));
  const kinematics::GearPairGeometry pair = kinematics::compute_gear_pair(s.scene.pair);
  note_relief_sizes(pair, p);
  if (start >= 0.)
    p.sweep.start_position = start * degree * 0.5 * pair.pinion.base_diameter;
  switch (p.mode)
  {
  case StiffnessMode::single:
    s.scene.position = geometry::PairPosition::single;
    break;
  case StiffnessMode::double_pair:
    s.scene.position = geometry::PairPosition::double_pair;
    break;
  case StiffnessMode::roll_angle:
  case StiffnessMode::sweep:
    s.scene.position = geometry::PairPosition::roll_angle;
    break;
  }
  with_parameter_names(stiffness_parameter_names(), [&] { check_stiffness_parameters(p, pair); });
  return p;
}
} // namespace gearstiff::app
