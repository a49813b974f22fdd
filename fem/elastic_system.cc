#include "fem/elastic_system.h"

#include "errors/errors.h"
#include "fem/linear_solver.h"

#include <Eigen/Dense>
#include <algorithm>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <set>
#include <sstream>

namespace gearstiff::fem
{
using namespace dealii;

template <int dim>
std::vector<Node<dim>> boundary_nodes(const DoFHandler<dim>& dof_handler,
                                      const std::vector<types::boundary_id>& boundaries)
{
  const FiniteElement<dim>& fe = dof_handler.get_fe();
  const FiniteElement<dim>& base = fe.base_element(0);
  const MappingQ<dim> mapping(1);
  const std::vector<Point<dim>>& unit_points = base.get_unit_support_points();
  std::map<types::global_dof_index, Node<dim>> nodes;
  std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
  for (const auto& cell : dof_handler.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
    {
      if (!cell->face(f)->at_boundary() ||
          std::find(boundaries.begin(), boundaries.end(), cell->face(f)->boundary_id()) ==
              boundaries.end())
        continue;
      cell->get_dof_indices(dofs);
      for (unsigned int i = 0; i < base.n_dofs_per_cell(); ++i)
      {
        if (!base.has_support_on_face(i, f))
          continue;
        Node<dim> node;
        for (unsigned int c = 0; c < dim; ++c)
          node.dofs[c] = dofs[fe.component_to_system_index(c, i)];
        if (nodes.count(node.dofs[0]))
          continue;
        node.position = mapping.transform_unit_to_real_cell(cell, unit_points[i]);
        nodes.emplace(node.dofs[0], node);
      }
    }
  std::vector<Node<dim>> result;
  for (const auto& [dof, node] : nodes)
    result.push_back(node);
  return result;
}

template <int dim>
struct ElasticSystem<dim>::Implementation
{
  explicit Implementation(unsigned int degree) : fe(FE_Q<dim>(degree), dim), mapping(1) {}

  FESystem<dim> fe;
  MappingQ<dim> mapping;
  IndexSet locally_owned;
  std::vector<types::material_id> dof_body; // material id of each DoF's body
  std::vector<unsigned int> dof_component;  // 0..dim-1

  // The element work, done once by setup_system(): for every locally owned cell (in the
  // iteration order of the DoF handler) its DoF indices, its stiffness matrix (N/m, row-major)
  // and its traction load at unit load factor (N). Every condensed system and every residual
  // is built from these, so no cell is integrated twice.
  std::vector<types::global_dof_index> cell_dofs;
  std::vector<double> cell_matrices;
  std::vector<double> cell_loads;

  // Integrates the stiffness and tractions of the locally owned cells into the cache.
  void integrate_cells(const ElasticSystem<dim>& system);
  // The cached cells condensed with `constraints` into matrix and rhs (loads times
  // `load_factor`; not compressed).
  void assemble(const AffineConstraints<double>& constraints, double load_factor,
                PETScWrappers::MPI::SparseMatrix& matrix, PETScWrappers::MPI::Vector& rhs) const;
};

namespace
{
// Cell stiffness of isotropic elasticity, ∫ (λ div v div u + 2μ ε(v):ε(u)) · depth.
template <int dim>
void cell_stiffness(const FEValues<dim>& fe_values, double lambda, double mu, double depth,
                    FullMatrix<double>& cell_matrix)
{
  const FiniteElement<dim>& fe = fe_values.get_fe();
  const unsigned int n = fe.n_dofs_per_cell();
  cell_matrix = 0;
  for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
  {
    const double JxW = fe_values.JxW(q) * depth;
    for (unsigned int i = 0; i < n; ++i)
    {
      const unsigned int ci = fe.system_to_component_index(i).first;
      const Tensor<1, dim> grad_i = fe_values.shape_grad(i, q);
      for (unsigned int j = i; j < n; ++j)
      {
        const unsigned int cj = fe.system_to_component_index(j).first;
        const Tensor<1, dim> grad_j = fe_values.shape_grad(j, q);
        double value = lambda * grad_i[ci] * grad_j[cj] + mu * grad_i[cj] * grad_j[ci];
        if (ci == cj)
          value += mu * (grad_i * grad_j);
        cell_matrix(i, j) += value * JxW;
      }
    }
  }
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < i; ++j)
      cell_matrix(i, j) = cell_matrix(j, i);
}
} // namespace

template <int dim>
void ElasticSystem<dim>::Implementation::integrate_cells(const ElasticSystem<dim>& system)
{
  const QGauss<dim> quadrature(fe.degree + 1);
  const QGauss<dim - 1> face_quadrature(fe.degree + 1);
  FEValues<dim> fe_values(mapping, fe, quadrature, update_gradients | update_JxW_values);
  FEFaceValues<dim> fe_face_values(mapping, fe, face_quadrature, update_values | update_JxW_values);
  const unsigned int n = fe.n_dofs_per_cell();
  FullMatrix<double> cell_matrix(n, n);
  std::vector<types::global_dof_index> dofs(n);
  const double depth = system.depth();
  // Reserved up front: growing the arrays cell by cell copied them about as long as the
  // integration took.
  std::size_t n_cells = 0;
  for (const auto& cell : system.dof_handler.active_cell_iterators())
    n_cells += cell->is_locally_owned() ? 1 : 0;
  cell_dofs.clear();
  cell_matrices.clear();
  cell_loads.clear();
  cell_dofs.reserve(n_cells * n);
  cell_matrices.reserve(n_cells * n * n);
  cell_loads.reserve(n_cells * n);
  for (const auto& cell : system.dof_handler.active_cell_iterators())
    if (cell->is_locally_owned())
    {
      fe_values.reinit(cell);
      const Material& m = system.material(cell->material_id());
      cell_stiffness(fe_values, m.lame_lambda(dim, system.elasticity.model), m.lame_mu(), depth,
                     cell_matrix);
      cell_matrices.insert(cell_matrices.end(), &cell_matrix(0, 0), &cell_matrix(0, 0) + n * n);
      const std::size_t load = cell_loads.size();
      cell_loads.resize(load + n, 0.);
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          for (const auto& [boundary, traction] : system.tractions)
            if (cell->face(f)->boundary_id() == boundary)
            {
              fe_face_values.reinit(cell, f);
              for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                for (unsigned int i = 0; i < n; ++i)
                  cell_loads[load + i] += fe_face_values.shape_value(i, q) *
                                          traction[fe.system_to_component_index(i).first] *
                                          fe_face_values.JxW(q) * depth;
            }
      cell->get_dof_indices(dofs);
      cell_dofs.insert(cell_dofs.end(), dofs.begin(), dofs.end());
    }
}

template <int dim>
void ElasticSystem<dim>::Implementation::assemble(const AffineConstraints<double>& constraints,
                                                  double load_factor,
                                                  PETScWrappers::MPI::SparseMatrix& matrix,
                                                  PETScWrappers::MPI::Vector& rhs) const
{
  const unsigned int n = fe.n_dofs_per_cell();
  FullMatrix<double> cell_matrix(n, n);
  Vector<double> cell_rhs(n);
  std::vector<types::global_dof_index> dofs(n);
  for (std::size_t cell = 0; cell * n < cell_dofs.size(); ++cell)
  {
    std::copy_n(cell_matrices.begin() + cell * n * n, n * n, &cell_matrix(0, 0));
    for (unsigned int i = 0; i < n; ++i)
      cell_rhs[i] = load_factor * cell_loads[cell * n + i];
    std::copy_n(cell_dofs.begin() + cell * n, n, dofs.begin());
    constraints.distribute_local_to_global(cell_matrix, cell_rhs, dofs, matrix, rhs);
  }
}

template <int dim>
ElasticSystem<dim>::ElasticSystem(MPI_Comm mpi_communicator, const ElasticityParameters& elasticity,
                                  const LinearSolverParameters& linear_solver)
    : mpi_communicator(mpi_communicator), elasticity(elasticity), linear_solver(linear_solver),
      tria(mpi_communicator, Triangulation<dim>::none, false,
           parallel::shared::Triangulation<dim>::partition_metis),
      dof_handler(tria), impl(std::make_unique<Implementation>(elasticity.degree))
{
  Assert(elasticity.degree >= 1 && elasticity.degree <= 2,
         ExcMessage("element degree must be 1 or 2"));
}

template <int dim>
ElasticSystem<dim>::~ElasticSystem()
{
  dof_handler.clear();
}

template <int dim>
const Mapping<dim, dim>& ElasticSystem<dim>::get_mapping() const
{
  return impl->mapping;
}

template <int dim>
const FiniteElement<dim, dim>& ElasticSystem<dim>::get_fe() const
{
  return impl->fe;
}

template <int dim>
double ElasticSystem<dim>::depth() const
{
  return dim == 2 ? elasticity.thickness : 1.;
}

template <int dim>
void ElasticSystem<dim>::set_materials(const std::map<types::material_id, Material>& given,
                                       const std::string& parameter)
{
  std::set<types::material_id> present;
  for (const auto& cell : tria.active_cell_iterators())
    present.insert(cell->material_id());
  for (const auto id : present)
    if (given.count(id) == 0)
      throw InputError(parameter, "the mesh has cells with material id " + std::to_string(id) +
                                      " (physical tag) but no material was given for them");
  materials = given;
}

template <int dim>
const Material& ElasticSystem<dim>::material(types::material_id id) const
{
  const auto found = materials.find(id);
  AssertThrow(found != materials.end(), ExcMessage("no material for id " + std::to_string(id)));
  return found->second;
}

template <int dim>
double ElasticSystem<dim>::min_youngs_modulus() const
{
  double e = std::numeric_limits<double>::max();
  for (const auto& [id, m] : materials)
    e = std::min(e, m.youngs_modulus);
  return e;
}

template <int dim>
double ElasticSystem<dim>::max_youngs_modulus() const
{
  double e = 0;
  for (const auto& [id, m] : materials)
    e = std::max(e, m.youngs_modulus);
  return e;
}

template <int dim>
void ElasticSystem<dim>::add_traction(types::boundary_id boundary, const Tensor<1, dim>& traction)
{
  tractions.emplace_back(boundary, traction);
}

template <int dim>
void ElasticSystem<dim>::setup_system()
{
  if (tria.n_active_cells() == 0)
    throw InputError("mesh", "the mesh has no cells");
  for (const auto& cell : tria.active_cell_iterators())
    if (!cell->reference_cell().is_hyper_cube())
      throw InputError("mesh", "has non-quadrilateral/hexahedral cells; FE_Q needs quads "
                               "(recombine the mesh in gmsh)");
  if (materials.empty())
    throw InputError("materials", "none given");
  for (const auto& cell : tria.active_cell_iterators())
    material(cell->material_id());

  const FESystem<dim>& fe = impl->fe;
  dof_handler.distribute_dofs(fe);
  impl->locally_owned = dof_handler.locally_owned_dofs();

  // Node data of every DoF, on every rank (the mesh is shared).
  const unsigned int n_dofs = dof_handler.n_dofs();
  dof_support_points.assign(n_dofs, Point<dim>());
  impl->dof_body.assign(n_dofs, 0);
  impl->dof_component.assign(n_dofs, 0);
  const std::vector<Point<dim>>& unit_points = fe.get_unit_support_points();
  std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    cell->get_dof_indices(dofs);
    for (unsigned int i = 0; i < dofs.size(); ++i)
    {
      dof_support_points[dofs[i]] = impl->mapping.transform_unit_to_real_cell(cell, unit_points[i]);
      impl->dof_body[dofs[i]] = cell->material_id();
      impl->dof_component[dofs[i]] = fe.system_to_component_index(i).first;
    }
  }

  // The element work, once: every later system and residual reuses it.
  impl->integrate_cells(*this);
}

template <int dim>
const std::vector<unsigned int>& ElasticSystem<dim>::dof_components() const
{
  return impl->dof_component;
}

template <int dim>
void ElasticSystem<dim>::condensed_system(const AffineConstraints<double>& constraints,
                                          const Vector<double>& point_loads,
                                          PETScWrappers::MPI::SparseMatrix& matrix,
                                          PETScWrappers::MPI::Vector& rhs) const
{
  const FESystem<dim>& fe = impl->fe;
  const unsigned int n_dofs = dof_handler.n_dofs();
  std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());

  // Every rank holds all constraints, so the whole pattern is built locally; rows not owned are
  // simply ignored by reinit.
  DynamicSparsityPattern dsp(n_dofs, n_dofs);
  for (const auto& cell : dof_handler.active_cell_iterators())
  {
    cell->get_dof_indices(dofs);
    constraints.add_entries_local_to_global(dofs, dsp, false);
  }
  matrix.reinit(impl->locally_owned, impl->locally_owned, dsp, mpi_communicator);
  rhs.reinit(impl->locally_owned, mpi_communicator);

  impl->assemble(constraints, load_factor, matrix, rhs);
  // Point loads enter once (on rank 0); loads on constrained DoFs are passed to their masters
  // as virtual work requires.
  if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0 && point_loads.size() > 0)
    for (types::global_dof_index i = 0; i < point_loads.size(); ++i)
      if (point_loads[i] != 0.)
      {
        Vector<double> load(1);
        load[0] = point_loads[i];
        const std::vector<types::global_dof_index> index{i};
        constraints.distribute_local_to_global(load, index, rhs);
      }
  matrix.compress(VectorOperation::add);
  rhs.compress(VectorOperation::add);
}

template <int dim>
Vector<double> ElasticSystem<dim>::solve(const AffineConstraints<double>& constraints,
                                         const Vector<double>& point_loads,
                                         LinearSolveStatistics& statistics) const
{
  check_rigid_body_freedom(constraints, "linear solve");
  Timer timer(mpi_communicator, true);
  PETScWrappers::MPI::SparseMatrix matrix;
  PETScWrappers::MPI::Vector rhs;
  condensed_system(constraints, point_loads, matrix, rhs);
  statistics.n_dofs = dof_handler.n_dofs();
  statistics.assembly_time = timer.wall_time();

  timer.restart();
  PETScWrappers::MPI::Vector solution(impl->locally_owned, mpi_communicator);
  statistics.iterations =
      solve_linear_system(matrix, solution, rhs, linear_solver, dof_support_points,
                          impl->dof_component, mpi_communicator);
  Vector<double> complete(solution);
  constraints.distribute(complete);
  statistics.solve_time = timer.wall_time();
  return complete;
}

template <int dim>
Vector<double> ElasticSystem<dim>::residual(const Vector<double>& solution) const
{
  // Cell by cell from the cached element matrices (no global K is kept); each rank sums its
  // own cells, the ranks then add up the complete vector.
  const unsigned int n = impl->fe.n_dofs_per_cell();
  Vector<double> r(dof_handler.n_dofs());
  std::vector<double> local(n);
  for (std::size_t cell = 0; cell * n < impl->cell_dofs.size(); ++cell)
  {
    const types::global_dof_index* dofs = &impl->cell_dofs[cell * n];
    const double* matrix = &impl->cell_matrices[cell * n * n];
    bool zero = true; // a cell without displacement or load adds nothing (a solution known
                      // only at a few cells, e.g. a rolling sweep's kept rows, skips most)
    for (unsigned int i = 0; i < n; ++i)
    {
      local[i] = solution[dofs[i]];
      zero = zero && local[i] == 0. && impl->cell_loads[cell * n + i] == 0.;
    }
    if (zero)
      continue;
    for (unsigned int i = 0; i < n; ++i)
    {
      double value = -load_factor * impl->cell_loads[cell * n + i];
      for (unsigned int j = 0; j < n; ++j)
        value += matrix[i * n + j] * local[j];
      r[dofs[i]] += value;
    }
  }
  if (Utilities::MPI::n_mpi_processes(mpi_communicator) > 1)
    Utilities::MPI::sum(ArrayView<const double>(r.begin(), r.size()), mpi_communicator,
                        make_array_view(r));
  return r;
}

template <int dim>
struct ElasticSystem<dim>::RigidModeAnalysis
{
  static constexpr unsigned int n_modes = dim == 2 ? 3 : 6; // per body
  std::map<types::material_id, unsigned int> body_index;
  std::vector<Point<dim>> centroid; // m, per body
  std::vector<double> radius;       // m, per body
  // Eigen-decomposition of the Gram matrix of the unit rigid modes of all bodies under the
  // constraint rows; zero eigenvalues are the free motions.
  Eigen::VectorXd eigenvalues;
  Eigen::MatrixXd eigenvectors;
  std::vector<unsigned int> free; // columns of eigenvectors that are free motions

  // Value of rigid mode k (0..n_modes−1) of DoF i's body at DoF i: dim translations and
  // dim(dim−1)/2 rotations about the body's centroid, scaled by its radius (unit size).
  double mode_value(const ElasticSystem<dim>& system, types::global_dof_index i,
                    unsigned int k) const
  {
    const unsigned int b = body_index.at(system.impl->dof_body[i]);
    const unsigned int c = system.impl->dof_component[i];
    if (k < dim)
      return c == k ? 1. : 0.;
    const Tensor<1, dim> x =
        (system.dof_support_points[i] - centroid[b]) / std::max(radius[b], 1e-300);
    // Rotations about z (2D, 3D), then about x and y (3D).
    const unsigned int axis = (dim == 2) ? 2 : (k == 3 ? 2 : k - 4);
    const unsigned int p = (axis + 1) % 3, q = (axis + 2) % 3;
    // ω × x with ω = e_axis: component p gets −x_q, component q gets x_p.
    if (c == p)
      return -(q < dim ? x[q] : 0.);
    if (c == q)
      return p < dim ? x[p] : 0.;
    return 0.;
  }
};

template <int dim>
typename ElasticSystem<dim>::RigidModeAnalysis
ElasticSystem<dim>::rigid_mode_analysis(const AffineConstraints<double>& constraints) const
{
  RigidModeAnalysis analysis;
  constexpr unsigned int n_modes = RigidModeAnalysis::n_modes;
  for (const auto& [id, m] : materials)
    analysis.body_index.emplace(id, analysis.body_index.size());
  const unsigned int n_bodies = analysis.body_index.size();
  analysis.centroid.assign(n_bodies, Point<dim>());
  analysis.radius.assign(n_bodies, 0.);
  std::vector<double> count(n_bodies, 0.);
  for (unsigned int i = 0; i < dof_support_points.size(); ++i)
  {
    const unsigned int b = analysis.body_index.at(impl->dof_body[i]);
    analysis.centroid[b] += dof_support_points[i];
    count[b] += 1;
  }
  for (unsigned int b = 0; b < n_bodies; ++b)
    if (count[b] > 0)
      analysis.centroid[b] /= count[b];
  for (unsigned int i = 0; i < dof_support_points.size(); ++i)
  {
    const unsigned int b = analysis.body_index.at(impl->dof_body[i]);
    analysis.radius[b] =
        std::max(analysis.radius[b], analysis.centroid[b].distance(dof_support_points[i]));
  }
  const unsigned int n_columns = n_modes * n_bodies;
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(n_columns, n_columns);
  std::vector<double> row(n_columns);
  for (const auto& line : constraints.get_lines())
  {
    std::fill(row.begin(), row.end(), 0.);
    const unsigned int b = analysis.body_index.at(impl->dof_body[line.index]);
    for (unsigned int k = 0; k < n_modes; ++k)
      row[b * n_modes + k] += analysis.mode_value(*this, line.index, k);
    for (const auto& [j, a] : line.entries)
    {
      const unsigned int bj = analysis.body_index.at(impl->dof_body[j]);
      for (unsigned int k = 0; k < n_modes; ++k)
        row[bj * n_modes + k] -= a * analysis.mode_value(*this, j, k);
    }
    for (unsigned int p = 0; p < n_columns; ++p)
      if (row[p] != 0.)
        for (unsigned int q = 0; q < n_columns; ++q)
          gram(p, q) += row[p] * row[q];
  }
  // A body without any DoF (material without cells) is skipped.
  for (unsigned int b = 0; b < n_bodies; ++b)
    if (count[b] == 0)
      for (unsigned int k = 0; k < n_modes; ++k)
        gram(b * n_modes + k, b * n_modes + k) = 1.;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gram);
  analysis.eigenvalues = eigen.eigenvalues();
  analysis.eigenvectors = eigen.eigenvectors();
  // The Gram matrix of unit-size modes sums squares of constraint coefficients of order one;
  // an unrestrained mode gives exactly zero up to round-off.
  const double largest = std::max(analysis.eigenvalues.maxCoeff(), 1.);
  for (unsigned int k = 0; k < n_columns; ++k)
    if (analysis.eigenvalues[k] <= 1e-10 * largest)
      analysis.free.push_back(k);
  return analysis;
}

template <int dim>
void ElasticSystem<dim>::check_rigid_body_freedom(const AffineConstraints<double>& constraints,
                                                  const std::string& context) const
{
  const RigidModeAnalysis analysis = rigid_mode_analysis(constraints);
  if (analysis.free.empty())
    return;
  const Eigen::VectorXd free_mode = analysis.eigenvectors.col(analysis.free.front());
  std::ostringstream bodies;
  std::string separator;
  for (const auto& [id, b] : analysis.body_index)
  {
    double amplitude = 0;
    for (unsigned int k = 0; k < RigidModeAnalysis::n_modes; ++k)
      amplitude += free_mode[b * RigidModeAnalysis::n_modes + k] *
                   free_mode[b * RigidModeAnalysis::n_modes + k];
    if (amplitude > 1e-2)
    {
      bodies << separator << id;
      separator = ", ";
    }
  }
  throw SolverFailure(context, "the body with material id " + bodies.str() +
                                   " is free to move: supports, rigid hubs and closed contacts "
                                   "leave a rigid-body motion unrestrained (singular stiffness)");
}

template <int dim>
std::vector<Vector<double>>
ElasticSystem<dim>::free_rigid_modes(const AffineConstraints<double>& constraints) const
{
  const RigidModeAnalysis analysis = rigid_mode_analysis(constraints);
  std::vector<Vector<double>> modes;
  for (const unsigned int column : analysis.free)
  {
    Vector<double> mode(dof_handler.n_dofs());
    for (types::global_dof_index i = 0; i < mode.size(); ++i)
    {
      const unsigned int b = analysis.body_index.at(impl->dof_body[i]);
      for (unsigned int k = 0; k < RigidModeAnalysis::n_modes; ++k)
        mode[i] += analysis.eigenvectors(b * RigidModeAnalysis::n_modes + k, column) *
                   analysis.mode_value(*this, i, k);
    }
    // The constrained DoFs follow their masters exactly (the mode satisfies the homogeneous
    // constraints up to round-off); set them so.
    AffineConstraints<double> homogeneous;
    homogeneous.copy_from(constraints);
    for (const auto& line : constraints.get_lines())
      homogeneous.set_inhomogeneity(line.index, 0.);
    homogeneous.distribute(mode);
    for (const auto& other : modes) // orthonormal: Gram–Schmidt against the earlier ones
      mode.add(-(mode * other), other);
    mode /= mode.l2_norm();
    modes.push_back(std::move(mode));
  }
  return modes;
}

template std::vector<Node<2>> boundary_nodes(const DoFHandler<2>&,
                                             const std::vector<types::boundary_id>&);
template std::vector<Node<3>> boundary_nodes(const DoFHandler<3>&,
                                             const std::vector<types::boundary_id>&);
template class ElasticSystem<2>;
template class ElasticSystem<3>;
} // namespace gearstiff::fem
