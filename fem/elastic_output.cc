// VTU/PVTU output of ElasticSystem: displacement, von Mises stress, material id, MPI subdomain
// and analysis-specific nodal scalars.
#include "errors/io.h"
#include "fem/elastic_system.h"
#include "fem/parallel.h"
#include "fem/stress.h"

#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

namespace gearstiff::fem
{
using namespace dealii;

namespace
{
// von Mises stress from the displacement gradient at each output point, with the material
// of the cell; σ_zz of plane strain (ν·(σ_xx + σ_yy)) is included.
template <int dim>
class VonMises : public DataPostprocessorScalar<dim>
{
public:
  explicit VonMises(const ElasticSystem<dim>& system)
      : DataPostprocessorScalar<dim>("von_mises_stress", update_gradients), system(system)
  {
  }

  void evaluate_vector_field(const DataPostprocessorInputs::Vector<dim>& inputs,
                             std::vector<Vector<double>>& computed) const override
  {
    const auto cell = inputs.template get_cell<dim>();
    const Material& m = system.material(cell->material_id());
    const PlanarModel model = system.get_parameters().model;
    for (unsigned int p = 0; p < computed.size(); ++p)
    {
      Tensor<2, dim> gradient;
      for (unsigned int i = 0; i < dim; ++i)
        gradient[i] = inputs.solution_gradients[p][i];
      computed[p](0) = von_mises_stress(m, model, gradient);
    }
  }

private:
  const ElasticSystem<dim>& system;
};
} // namespace

template <int dim>
std::vector<std::string> ElasticSystem<dim>::write_vtu(const Vector<double>& solution,
                                                       const std::vector<NodalField>& nodal_fields,
                                                       const std::string& directory,
                                                       const std::string& base) const
{
  const unsigned int rank = Utilities::MPI::this_mpi_process(mpi_communicator);
  const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);

  // Nodal scalars live on a scalar FE_Q of the same degree, whose DoF i of a cell sits at the
  // node of the vector element's x-component DoF of the same base index.
  DoFHandler<dim> scalar_dof_handler(tria);
  scalar_dof_handler.distribute_dofs(FE_Q<dim>(elasticity.degree));
  std::vector<Vector<double>> scalar_fields(nodal_fields.size(),
                                            Vector<double>(scalar_dof_handler.n_dofs()));
  {
    const FiniteElement<dim>& fe = get_fe();
    std::vector<types::global_dof_index> vector_dofs(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> scalar_dofs(scalar_dof_handler.get_fe().n_dofs_per_cell());
    auto scalar_cell = scalar_dof_handler.begin_active();
    for (const auto& cell : dof_handler.active_cell_iterators())
    {
      cell->get_dof_indices(vector_dofs);
      scalar_cell->get_dof_indices(scalar_dofs);
      for (unsigned int i = 0; i < scalar_dofs.size(); ++i)
        for (unsigned int k = 0; k < nodal_fields.size(); ++k)
        {
          const auto found =
              nodal_fields[k].values.find(vector_dofs[fe.component_to_system_index(0, i)]);
          if (found != nodal_fields[k].values.end())
            scalar_fields[k][scalar_dofs[i]] = found->second;
        }
      ++scalar_cell;
    }
  }

  Vector<float> material_id(tria.n_active_cells()), subdomain(tria.n_active_cells());
  for (const auto& cell : tria.active_cell_iterators())
  {
    material_id[cell->active_cell_index()] = cell->material_id();
    subdomain[cell->active_cell_index()] = cell->subdomain_id();
  }

  DataOut<dim> data_out;
  data_out.attach_triangulation(tria);
  const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector_field(
      dim, DataComponentInterpretation::component_is_part_of_vector);
  data_out.add_data_vector(dof_handler, solution, std::vector<std::string>(dim, "displacement"),
                           vector_field);
  const VonMises<dim> von_mises(*this);
  data_out.add_data_vector(dof_handler, solution, von_mises);
  for (unsigned int k = 0; k < nodal_fields.size(); ++k)
    data_out.add_data_vector(scalar_dof_handler, scalar_fields[k], nodal_fields[k].name);
  data_out.add_data_vector(material_id, "material_id", DataOut<dim>::type_cell_data);
  data_out.add_data_vector(subdomain, "subdomain", DataOut<dim>::type_cell_data);
  data_out.build_patches(get_mapping(), elasticity.degree);

  std::vector<std::string> names;
  for (unsigned int r = 0; r < n_ranks; ++r)
    names.push_back(base + "_" + Utilities::int_to_string(r, 4) + ".vtu");
  // Each rank writes its piece; a rank whose write fails (a full disk) makes every rank throw the
  // same IoError, so none is left waiting in the next collective call.
  const Failure failure = catch_failure(
      [&]()
      {
        write_file(directory + "/" + names[rank],
                   [&](std::ostream& out) { data_out.write_vtu(out); });
        if (rank == 0)
          write_file(directory + "/" + base + ".pvtu",
                     [&](std::ostream& out) { data_out.write_pvtu_record(out, names); });
      });
  first_failure(mpi_communicator, failure).rethrow();
  names.push_back(base + ".pvtu");
  scalar_dof_handler.clear();
  return names;
}

template std::vector<std::string> ElasticSystem<2>::write_vtu(const Vector<double>&,
                                                              const std::vector<NodalField>&,
                                                              const std::string&,
                                                              const std::string&) const;
template std::vector<std::string> ElasticSystem<3>::write_vtu(const Vector<double>&,
                                                              const std::vector<NodalField>&,
                                                              const std::string&,
                                                              const std::string&) const;
} // namespace gearstiff::fem
