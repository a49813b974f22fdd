// Small-strain linear elasticity of one or several bodies on one deal.II mesh (bodies are told
// apart by material id), in 2D plane strain, 2D plane stress (times a thickness) or 3D, with FE_Q
// of degree 1 or 2 and PETSc linear algebra on a parallel::shared::Triangulation partitioned by
// METIS.
//
// The class integrates every cell once (setup_system) and keeps the element stiffness matrices
// and traction loads, so that any analysis can impose its own AffineConstraints (supports, rigid
// hubs, closed contacts) per solve without integrating again, and obtain the reactions
// consistently as the residual r = K u − f, evaluated cell by cell: the nodal force the
// constraints exert, rather than a value recovered from stresses.
//
// Every rank holds the whole mesh, so DoF-level data (support points, constraints, the returned
// solution and residual) are complete on every rank; only assembly and the solve are distributed.
#pragma once

#include "fem/parameters.h"

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>
#include <map>
#include <memory>
#include <mpi.h>
#include <string>
#include <vector>

namespace dealii
{
template <int dim, int spacedim>
class FiniteElement;
template <int dim, int spacedim>
class Mapping;
namespace PETScWrappers::MPI
{
class SparseMatrix;
class Vector;
} // namespace PETScWrappers::MPI
} // namespace dealii

namespace gearstiff::fem
{
// One FE node (support point) with its dim DoFs.
template <int dim>
struct Node
{
  std::array<dealii::types::global_dof_index, dim> dofs; // x, y(, z) components
  dealii::Point<dim> position;                           // m, reference configuration
};

// The nodes on the faces with any of the given boundary ids, sorted by DoF index.
template <int dim>
std::vector<Node<dim>> boundary_nodes(const dealii::DoFHandler<dim>& dof_handler,
                                      const std::vector<dealii::types::boundary_id>& boundaries);

// Cost of one linear solve, reported with every result.
struct LinearSolveStatistics
{
  dealii::types::global_dof_index n_dofs = 0;
  unsigned int iterations = 0; // Krylov iterations (0 for the direct solver)
  double assembly_time = 0.;   // s, wall
  double solve_time = 0.;      // s, wall
};

// A nodal scalar for output (contact pressure, gap, ...), indexed like the x-component DoF
// of each node; nodes not listed are written as 0.
struct NodalField
{
  std::string name;
  std::map<dealii::types::global_dof_index, double> values;
};

template <int dim>
class ElasticSystem
{
public:
  ElasticSystem(MPI_Comm mpi_communicator, const ElasticityParameters& elasticity,
                const LinearSolverParameters& linear_solver);
  ~ElasticSystem();

  // Fill this before setup_system() (GridIn, GridGenerator, ...).
  dealii::parallel::shared::Triangulation<dim>& triangulation() { return tria; }

  // Every material id of the mesh needs a material; a missing one is an InputError naming
  // `parameter`.
  void set_materials(const std::map<dealii::types::material_id, Material>& materials,
                     const std::string& parameter);
  // A constant surface traction (Pa) on a boundary, a dead load.
  void add_traction(dealii::types::boundary_id boundary, const dealii::Tensor<1, dim>& traction);

  // Scales the tractions (dead loads) in every later solve and residual; for load stepping.
  void set_load_factor(double factor) { load_factor = factor; }

  // Distributes DoFs and integrates the element stiffness matrices and loads (once).
  void setup_system();

  // Solves the system condensed with `constraints` (closed, identical on every rank), with
  // `point_loads` (N, complete vector, may be empty) added to f. Throws SolverFailure when the
  // constraints leave a body free to move or the solver fails. Returns the complete solution.
  dealii::Vector<double> solve(const dealii::AffineConstraints<double>& constraints,
                               const dealii::Vector<double>& point_loads,
                               LinearSolveStatistics& statistics) const;

  // r = K u − f (N): the forces the constraints exert on the bodies.
  dealii::Vector<double> residual(const dealii::Vector<double>& solution) const;

  // Throws SolverFailure naming the body when the homogeneous part of `constraints` leaves a
  // rigid-body motion of some body unrestrained (the stiffness matrix would be singular).
  void check_rigid_body_freedom(const dealii::AffineConstraints<double>& constraints,
                                const std::string& context) const;
  // The rigid-body motions the homogeneous part of `constraints` leaves free: an orthonormal
  // basis of complete DoF vectors (m per unit amplitude); empty when every body is held.
  std::vector<dealii::Vector<double>>
  free_rigid_modes(const dealii::AffineConstraints<double>& constraints) const;

  // K and f (tractions times the load factor, plus `point_loads`, N, complete, may be empty)
  // condensed with `constraints` into `matrix` and `rhs` (initialised here, compressed): the
  // system every solve factorizes.
  void condensed_system(const dealii::AffineConstraints<double>& constraints,
                        const dealii::Vector<double>& point_loads,
                        dealii::PETScWrappers::MPI::SparseMatrix& matrix,
                        dealii::PETScWrappers::MPI::Vector& rhs) const;
  const LinearSolverParameters& get_linear_solver() const { return linear_solver; }
  // Component (0..dim−1) of every DoF, complete.
  const std::vector<unsigned int>& dof_components() const;

  // Writes displacement, von Mises stress, material id, MPI subdomain and the nodal fields as
  // <directory>/<base>_<rank>.vtu plus <base>.pvtu; returns the file names (relative).
  std::vector<std::string> write_vtu(const dealii::Vector<double>& solution,
                                     const std::vector<NodalField>& nodal_fields,
                                     const std::string& directory, const std::string& base) const;

  const dealii::DoFHandler<dim>& get_dof_handler() const { return dof_handler; }
  const dealii::Mapping<dim, dim>& get_mapping() const;
  const dealii::FiniteElement<dim, dim>& get_fe() const;
  // Position (m) of the node each DoF belongs to.
  const std::vector<dealii::Point<dim>>& support_points() const { return dof_support_points; }
  const Material& material(dealii::types::material_id id) const;
  // Factor turning per-unit-depth integrals into forces: the thickness in 2D, 1 in 3D.
  double depth() const;
  // Smallest and largest Young's modulus of the bodies (Pa).
  double min_youngs_modulus() const;
  double max_youngs_modulus() const;
  MPI_Comm get_mpi_communicator() const { return mpi_communicator; }
  const ElasticityParameters& get_parameters() const { return elasticity; }

private:
  struct RigidModeAnalysis; // the Gram matrix of the rigid modes under the constraints
  RigidModeAnalysis rigid_mode_analysis(const dealii::AffineConstraints<double>& constraints) const;

  struct Implementation; // PETSc objects, kept out of this header
  MPI_Comm mpi_communicator;
  ElasticityParameters elasticity;
  LinearSolverParameters linear_solver;
  dealii::parallel::shared::Triangulation<dim> tria;
  dealii::DoFHandler<dim> dof_handler;
  std::map<dealii::types::material_id, Material> materials;
  std::vector<std::pair<dealii::types::boundary_id, dealii::Tensor<1, dim>>> tractions;
  std::vector<dealii::Point<dim>> dof_support_points;
  double load_factor = 1.;              // -, multiplies the tractions
  std::unique_ptr<Implementation> impl; // owned
};
} // namespace gearstiff::fem
