// Load distribution of a cycloid (Cyclo) drive at one crank angle from a frictional FE contact
// solve: the roller forces P_i, the output-pin forces Q_j and the eccentric-bearing force R of
// the drive of Chmurawa & Łokiec (docs/references.md §4), nominal or corrected
// disc profile.
//
// Load case — statically equivalent to the running drive at crank angle φ_h. In steady running
// the (slow) accelerations are negligible and every body is in equilibrium under its contact
// forces; freezing the mechanism at φ_h therefore needs only supports that transmit the same
// forces and leave the same freedoms:
//  - the eccentric is held at φ_h: the disc's bore sits on a bearing that fixes the bore centre
//    C = e·(cos φ_h, sin φ_h) and lets the disc turn about it (a torque-free rigid hub: the
//    bearing transmits a force, no moment — the input torque M_h = |C × R| is what holds the
//    crank, checked against M_c/|i|);
//  - the rollers turn freely on fixed pins: the disc–roller contact is frictionless, so the
//    roller's spin carries no load, and each roller is held at its pin bore (fixed);
//  - the output pins are one body each in their holes (frictionless, the pins roll in the holes
//    through their sleeves), their bores all held by ONE rigid output member turning about the
//    ring centre (one rigid hub over every pin bore) which carries the output torque M_c
//    (counter-clockwise > 0), the rotation θ of the member being the unknown.
// The disc's rotation β and the output rotation θ are solved for, so every force is at exactly
// M_c. The geometry's clearances (corrected profile's Δr_i, pin-hole play) are in the mesh:
// they enter the contact solve as initial gaps. Each roller and each pin is its own contact pair
// (slave: roller or pin surface, master: the disc faces nearest to it), so P_i and Q_j are
// exact sums of that pair's multipliers. 2D is plane stress of the disc width by default.
//
//   CycloidLoadSettings settings;                 // the §4 drive, M_c = 440 N·m, nominal
//   settings.scene_file = "/tmp/cycloid.msh";
//   const CycloidLoadResult r = CycloidLoads<2>(settings).run();   // r.max_roller_force in N
#pragma once

#include "contact/contact_problem.h"
#include "fem/fields.h"
#include "fem/parameters.h"
#include "geometry/scene_cycloid.h"
#include "stiffness/cycloid_analytic.h"

#include <memory>
#include <string>
#include <vector>

namespace gearstiff::stiffness
{
// The fields of CycloidLoadSettings an InputError names, "cycloid_loads.<member>" (an initial
// overlap names contact::field::contact("overlap_tolerance"), contact/fields.h); app/ maps them
// to the parameters the user writes (app/cycloid/cycloid_field_names.cc).
namespace field
{
inline std::string cycloid_loads(const std::string& member)
{
  return "cycloid_loads." + member;
}
inline const std::vector<std::string>& cycloid_loads_fields()
{
  static const std::vector<std::string> members = {"output_torque", "contact_arc_ratio",
                                                   "young_modulus", "roller_young_modulus",
                                                   "poisson_ratio"};
  return members;
}
} // namespace field

// The §4 drive with output pins in their holes and explicit mesh sizes.
geometry::CycloidSceneSpec default_cycloid_load_scene();
// Plane stress (the disc is thin), Q1, thickness = disc width.
fem::ElasticityParameters default_cycloid_elasticity();

contact::ContactParameters default_cycloid_contact();

struct CycloidLoadSettings
{
  // Ring, disc profile (nominal: disc.rollers = 0), bore, pins, widths and mesh sizes (SI);
  // disc_rotation is set from the crank angle.
  geometry::CycloidSceneSpec scene = default_cycloid_load_scene();
  double crank_angle = 0.;     // rad, φ_h: the disc centre at e·(cos φ_h, sin φ_h)
  double output_torque = 440.; // N·m, M_c on the output member (counter-clockwise > 0), ≠ 0
  fem::ElasticityParameters elasticity = default_cycloid_elasticity(); // thickness: disc width
  fem::LinearSolverParameters linear_solver;
  // Frictionless (see the load case); overlap tolerance 5 µm: the closing rotation of a corrected
  // profile closes its first roller by 1 µm (a fifth of it), more than the outline spline's and
  // the chords' deviations from the exact curves, so that roller starts in the active set.
  contact::ContactParameters contact = default_cycloid_contact();
  fem::Material material;              // disc and output pins (steel 210 GPa, 0.3)
  fem::Material roller_material;       // rollers (the same steel by default)
  std::string scene_file;              // path of the .msh to write
  std::string output_directory;        // VTU here; empty: none
  std::string output_base = "cycloid"; // VTU base name
};

// One roller or pin and what it carries.
struct CycloidContactLoad
{
  unsigned int index = 0;  // -, roller i (polar angle 2πi/z_k) or pin j
  double angle = 0.;       // rad, polar angle of its centre about the ring centre
  double initial_gap = 0.; // m, geometric clearance (roller Δr_i, pin play)
  double force = 0.;       // N, Σ of the pair's normal multipliers (P_i or Q_j); 0: no pair
  double force_x = 0., force_y = 0.; // N, resultant on the roller / pin
  double max_pressure = 0.;          // Pa
  double contact_length = 0.;        // m
  double analytic_force = 0.;        // N, the rigid-disc estimate (cycloid_analytic.h)
  bool candidate = false;            // modelled as a contact pair

  // Every member, once: serialisation (results cross MPI ranks, fem/parallel.h) and the
  // completeness check of tests/stiffness/test_result_fields.cc use this list.
  template <class Self, class Visit>
  static void for_each_field(Self& self, Visit&& visit)
  {
    visit("index", self.index);
    visit("angle", self.angle);
    visit("initial_gap", self.initial_gap);
    visit("force", self.force);
    visit("force_x", self.force_x);
    visit("force_y", self.force_y);
    visit("max_pressure", self.max_pressure);
    visit("contact_length", self.contact_length);
    visit("analytic_force", self.analytic_force);
    visit("candidate", self.candidate);
  }
  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    fem::serialize_fields(archive, *this);
  }
};

struct CycloidLoadResult
{
  double crank_angle = 0.;   // rad
  double disc_rotation = 0.; // rad, ψ of the scene (nominal kinematics)
  double output_torque = 0.; // N·m, M_c applied
  std::vector<CycloidContactLoad> rollers, pins;
  double max_roller_force = 0., max_pin_force = 0.; // N
  unsigned int loaded_rollers = 0, loaded_pins = 0; // -, carrying > 1e-6 of the largest
  double bearing_force = 0.;                        // N, R: the disc's force on the eccentric
  double bearing_angle = 0.;           // rad, α_R: M_h = R·e·cos α_R (from the crank's normal)
  double bearing_force_direction = 0.; // rad, polar angle of R
  double input_torque = 0.;            // N·m, M_h = |C × R| holding the eccentric
  double input_torque_ratio = 0.;      // -, M_h/(M_c/z_s): 1 for rigid kinematics
  // Balance checks (relative, solver precision expected for the first two).
  double disc_force_balance = 0.;    // -, |R_on_disc − Σ contact forces| / R
  double disc_moment_balance = 0.;   // -, |moments about C of P_i and Q_j| / M_c
  double output_moment_balance = 0.; // -, |Σ c_j × Q_j − M_c| / M_c (lines through pin centres)
  // rad, rigid rotation of disc and output member that closes the first roller clearance before
  // any load (the corrected profile's backlash in the torque's sense; 0 for nominal): the solve
  // starts from there (and 1 µm beyond, so that a roller touches); the rotations below include
  // it.
  double closing_rotation = 0.;
  double output_rotation = 0.;      // rad, θ of the output member under M_c
  double disc_rotation_load = 0.;   // rad, β of the disc about its bearing
  double max_contact_pressure = 0.; // Pa
  double disc_von_mises = 0.;       // Pa, largest von Mises stress in the disc
  CycloidAnalyticResult analytic;   // the rigid-disc estimate at the same position
  // Model and cost.
  unsigned int n_cells = 0, n_dofs = 0, active_set_iterations = 0;
  double contact_size = 0.;                                                  // m
  double scene_time = 0., setup_time = 0., solve_time = 0., total_time = 0.; // s, wall
  // Profile of one position (s, wall): gmsh meshing (all attempts) and its number of attempts,
  // reading the mesh and labelling the pairs, the factorization (contact assembly) and the
  // active-set iterations, the evaluation (forces, von Mises, analytic model).
  double meshing_time = 0., read_time = 0., factorization_time = 0., iteration_time = 0.,
         evaluate_time = 0.;
  unsigned int meshing_attempts = 0;
  std::vector<std::string> output_files;

  // Every member, once: serialisation (results cross MPI ranks, fem/parallel.h) and the
  // completeness check of tests/stiffness/test_result_fields.cc use this list.
  template <class Self, class Visit>
  static void for_each_field(Self& self, Visit&& visit)
  {
    visit("crank_angle", self.crank_angle);
    visit("disc_rotation", self.disc_rotation);
    visit("output_torque", self.output_torque);
    visit("rollers", self.rollers);
    visit("pins", self.pins);
    visit("max_roller_force", self.max_roller_force);
    visit("max_pin_force", self.max_pin_force);
    visit("loaded_rollers", self.loaded_rollers);
    visit("loaded_pins", self.loaded_pins);
    visit("bearing_force", self.bearing_force);
    visit("bearing_angle", self.bearing_angle);
    visit("bearing_force_direction", self.bearing_force_direction);
    visit("input_torque", self.input_torque);
    visit("input_torque_ratio", self.input_torque_ratio);
    visit("disc_force_balance", self.disc_force_balance);
    visit("disc_moment_balance", self.disc_moment_balance);
    visit("output_moment_balance", self.output_moment_balance);
    visit("closing_rotation", self.closing_rotation);
    visit("output_rotation", self.output_rotation);
    visit("disc_rotation_load", self.disc_rotation_load);
    visit("max_contact_pressure", self.max_contact_pressure);
    visit("disc_von_mises", self.disc_von_mises);
    visit("analytic", self.analytic);
    visit("n_cells", self.n_cells);
    visit("n_dofs", self.n_dofs);
    visit("active_set_iterations", self.active_set_iterations);
    visit("contact_size", self.contact_size);
    visit("scene_time", self.scene_time);
    visit("setup_time", self.setup_time);
    visit("solve_time", self.solve_time);
    visit("total_time", self.total_time);
    visit("meshing_time", self.meshing_time);
    visit("read_time", self.read_time);
    visit("factorization_time", self.factorization_time);
    visit("iteration_time", self.iteration_time);
    visit("evaluate_time", self.evaluate_time);
    visit("meshing_attempts", self.meshing_attempts);
    visit("output_files", self.output_files);
  }
  template <class Archive>
  void serialize(Archive& archive, const unsigned int /*version*/)
  {
    fem::serialize_fields(archive, *this);
  }
};

// One solved point of a torque loop (cycloid_hysteresis).
struct LoopPoint
{
  double torque = 0.;   // N·m, the output member's torque on the pins (its reaction)
  double rotation = 0.; // rad, output rotation θ, closing rotation included
  int branch = 0;       // +1 torque rising, −1 falling, 0 the first loading before the loop
};

// A torque target of trace_loop and the branch its points belong to.
struct LoopTarget
{
  double torque = 0.; // N·m
  int branch = 0;
};

template <int dim>
class CycloidLoads
{
public:
  // Checks the settings (InputError naming the parameter) before anything is meshed. Solves
  // serially (MPI_COMM_SELF): a 2D position takes seconds; sweeps spread positions over ranks.
  explicit CycloidLoads(const CycloidLoadSettings& settings);
  ~CycloidLoads();

  // Scene, contact solve, evaluation. InputError for an impossible scene, SolverFailure when the
  // contact iteration fails.
  CycloidLoadResult run();
  // The torque path of a hysteresis loop on ONE contact problem with the friction history
  // kept (ContactProblem::solve_next_step): the output member is rotation-controlled — its
  // torque is the reaction — and θ is stepped so that the torque reaches each target in turn
  // (secant on the measured stiffness, within 1% of M_c; a step may overshoot, never stops
  // short by more). The start is the flank the sign of settings.output_torque closes. Returns
  // every solved point; SolverFailure when a step does not converge.
  std::vector<LoopPoint> trace_loop(const std::vector<LoopTarget>& targets);
  unsigned int loop_iterations() const; // -, active-set iterations of trace_loop

private:
  void make_scene();
  void setup_problem();
  void solve();
  void evaluate();

  CycloidLoadSettings settings;
  // The scene solved: settings.scene turned rigidly (disc profile and pins) by the closing
  // rotation.
  geometry::CycloidSceneSpec closed_scene;
  double scene_rotation = 0.; // rad, the turn of closed_scene against settings.scene
  double pin_turn = 0.;       // rad, the output pins' further turn through their play
  std::unique_ptr<contact::ContactProblem<dim>> problem;
  std::vector<unsigned int> roller_pairs, pin_pairs; // contact pair index of each roller / pin
  CycloidLoadResult result;
  // trace_loop: the output member is rotation-controlled, starting at this rotation (rad,
  // relative to closed_scene).
  bool rotation_control = false;
  double start_rotation = 0.;
};

// The hysteresis loop −M_c → +M_c → −M_c with the contacts' friction (settings.contact; the
// robot-reducer catalogue curve) and the figures read from it:
//  - without play (nominal profile) one problem: a first loading to −M_c, then rising to +M_c
//    and falling to −M_c, every step from the converged stick/slip state of the last;
//  - with play (corrected profile) the two flanks separately: crossing the play opens every
//    roller contact (their friction history ends there) and is a large rigid rotation the
//    small-sliding contact cannot follow; each flank is loaded from touching to M_c and unloaded
//    to 3% of M_c, and the loop jumps across the backlash between them.
// Levels 3%, 25%, 50%, 75%, 100% of M_c in each sense; branches interpolated linearly.
struct CycloidHysteresis
{
  std::vector<LoopPoint> points; // in the order solved (flank by flank with play)
  double stiffness = 0.;         // N·m/rad, secant 50%–100% of M_c on each loading branch, mean
  double lost_motion = 0.;       // rad, mid-width rotation at +3% minus that at −3% of M_c
  double hysteresis = 0.;        // rad, width of the loop (falling − rising) at ±3% of M_c, mean
  // rad, what the width is known to: half the difference of its two estimates (at +3% and −3%
  // of M_c), at least 1e-9·(rotation span of the loop); a width below it (or below zero, which
  // friction cannot give) is no measurable loop.
  double hysteresis_resolution = 0.;
  unsigned int steps = 0, active_set_iterations = 0; // -, load steps, all flanks
  double time = 0.;                                  // s, wall, scene(s) and solves
};
CycloidHysteresis cycloid_hysteresis(const CycloidLoadSettings& settings);

// Checks what the scene cannot (torque, materials); throws InputError naming the parameter.
void check_cycloid_load_settings(const CycloidLoadSettings& settings);
// The material part of it (E and ν of disc, pins and rollers), which a caller can run as soon as
// the parameters are read, before it announces any solve.
void check_cycloid_materials(const CycloidLoadSettings& settings);
} // namespace gearstiff::stiffness
