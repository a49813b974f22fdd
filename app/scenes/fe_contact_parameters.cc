#include "app/scenes/fe_contact_parameters.h"

#include "app/core/field_names.h"
#include "app/core/parameter_patterns.h"
#include "contact/fields.h"

namespace gearstiff::app
{
namespace
{
void declare_elasticity_parameters(ParameterHandler& prm)
{
  prm.declare_entry("Planar model", "plane strain", Selection("plane strain|plane stress"),
                    "2D meshes only: plane strain (thick gears, ε_zz = 0) or plane stress "
                    "(thin webs, σ_zz = 0)");
  prm.declare_entry("Element degree", "1", Integer(1, 2),
                    "polynomial degree of the FE_Q displacement elements [-], 1 or 2");
  prm.declare_entry("Thickness", "1", Double(1e-9),
                    "out-of-plane depth of a 2D model (face width) [mm]: all forces and torques "
                    "are totals over it");
}

fem::ElasticityParameters parse_elasticity_parameters(ParameterHandler& prm)
{
  fem::ElasticityParameters p;
  p.model = prm.get("Planar model") == "plane stress" ? fem::PlanarModel::plane_stress
                                                      : fem::PlanarModel::plane_strain;
  p.degree = prm.get_integer("Element degree");
  p.thickness = prm.get_double("Thickness") * 1e-3;
  return p;
}

void declare_linear_solver_parameters(ParameterHandler& prm)
{
  prm.declare_entry("Method", "direct", Selection("direct|cg-gamg|cg-boomeramg"),
                    "direct: MUMPS sparse Cholesky (default, robust in 2D); cg-gamg: CG with "
                    "PETSc GAMG and the rigid-body modes; cg-boomeramg: CG with hypre "
                    "BoomerAMG (nodal coarsening); the iterative ones for large 3D meshes");
  prm.declare_entry(
      "Relative tolerance", "1e-10", Double(1e-16, 1e-2),
      "relative residual of the iterative methods [-]: stop when |b - A x| <= tolerance |b|");
  prm.declare_entry(
      "Max iterations", "5000", Integer(1),
      "iteration limit of the iterative methods [-]; reaching it is a solver failure");
}

fem::LinearSolverParameters parse_linear_solver_parameters(ParameterHandler& prm)
{
  fem::LinearSolverParameters p;
  const std::string name = prm.get("Method");
  p.method = name == "cg-gamg"        ? fem::LinearSolverMethod::cg_gamg
             : name == "cg-boomeramg" ? fem::LinearSolverMethod::cg_boomeramg
                                      : fem::LinearSolverMethod::direct_mumps;
  p.relative_tolerance = prm.get_double("Relative tolerance");
  p.max_iterations = prm.get_integer("Max iterations");
  return p;
}
void declare_contact_parameters(ParameterHandler& prm)
{
  prm.declare_entry("Friction coefficient", "0", friction_coefficient_pattern(),
                    "Coulomb friction coefficient μ between the surfaces [-]; 0: frictionless");
  prm.declare_entry("Max iterations", "40", Integer(1, 1000),
                    "active-set iterations per load step [-]; reaching it is a solver failure");
  prm.declare_entry("Load steps", "1", Integer(1, 1000),
                    "equal load increments [-] (friction is path dependent)");
  prm.declare_entry(
      "Search distance", "1", Double(0.),
      "search distance [mm]: slave points farther than this from the master "
      "surface are never paired (small sliding: pairing is frozen in the reference configuration)");
  prm.declare_entry("Overlap tolerance", "1e-3", Double(0.),
                    "largest initial overlap of the bodies [mm]; more is an input error");
  prm.declare_entry("Friction tolerance", "1e-8", Double(1e-14, 1e-2),
                    "convergence of the slip forces relative to the largest normal force [-]");
  prm.declare_entry("Warm start", "true", Bool(),
                    "true: in a sweep, each position's active-set iteration starts from the "
                    "contact zone its neighbour converged to (mapped by initial gap, as the "
                    "meshes differ), and from the usual cold start should that fail; false: "
                    "every position starts cold (same results, more iterations)");
  prm.declare_entry("Iteration solves", "auto", Selection("auto|Schur complement|full re-solve"),
                    "how each active-set iteration is solved: 'Schur complement' factorizes the "
                    "stiffness once and solves for the contact forces only (needs the direct "
                    "solver); 'full re-solve' re-assembles and re-solves everything (the "
                    "reference); 'auto' takes the Schur complement with the direct solver");
}

contact::ContactParameters parse_contact_parameters(ParameterHandler& prm)
{
  contact::ContactParameters p;
  p.friction_coefficient = prm.get_double("Friction coefficient");
  p.max_iterations = prm.get_integer("Max iterations");
  p.load_steps = prm.get_integer("Load steps");
  p.search_distance = prm.get_double("Search distance") * 1e-3;
  p.overlap_tolerance = prm.get_double("Overlap tolerance") * 1e-3;
  p.friction_tolerance = prm.get_double("Friction tolerance");
  p.warm_start = prm.get_bool("Warm start");
  const std::string solves = prm.get("Iteration solves");
  p.iteration_solves = solves == "Schur complement" ? contact::IterationSolves::schur_complement
                       : solves == "full re-solve"  ? contact::IterationSolves::full_resolve
                                                    : contact::IterationSolves::automatic;
  return p;
}

// The contact library's fields (contact/fields.h) as the parameters of "Contact".
ParameterNames contact_field_names()
{
  return field_family(
      "Contact", contact::field::contact_fields(), contact::field::contact,
      {{"iteration_solves", "Iteration solves"}, {"overlap_tolerance", "Overlap tolerance"}});
}

const FieldNamesRegistration contact_fields("contact", contact_field_names);
} // namespace

void declare_fe_contact_parameters(dealii::ParameterHandler& prm)
{
  prm.enter_subsection("Finite elements");
  declare_elasticity_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("Linear solver");
  declare_linear_solver_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("Contact");
  declare_contact_parameters(prm);
  prm.leave_subsection();
}

void parse_fe_contact_parameters(dealii::ParameterHandler& prm,
                                 fem::ElasticityParameters& elasticity,
                                 fem::LinearSolverParameters& linear_solver,
                                 contact::ContactParameters& contact)
{
  prm.enter_subsection("Finite elements");
  elasticity = parse_elasticity_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("Linear solver");
  linear_solver = parse_linear_solver_parameters(prm);
  prm.leave_subsection();
  prm.enter_subsection("Contact");
  contact = parse_contact_parameters(prm);
  prm.leave_subsection();
}
} // namespace gearstiff::app
