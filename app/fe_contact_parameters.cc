#include "app/fe_contact_parameters.h"

#include "app/parameter_patterns.h"

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
                    "polynomial degree of the FE_Q displacement elements (1 or 2)");
  prm.declare_entry("Thickness", "1", Double(1e-9),
                    "mm; out-of-plane depth of a 2D model (face width): all forces and torques "
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
  prm.declare_entry("Relative tolerance", "1e-10", Double(1e-16, 1e-2),
                    "-, iterative methods: stop when |b - A x| <= tolerance |b|");
  prm.declare_entry("Max iterations", "5000", Integer(1),
                    "-, iterative methods: iteration limit (reaching it is a solver failure)");
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
  contact::ContactParameters::declare_parameters(prm);
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
  contact.parse_parameters(prm);
  prm.leave_subsection();
}
} // namespace gearstiff::app
