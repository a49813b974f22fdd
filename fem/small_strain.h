// The small-strain check every solve's results pass through: linear elasticity with linearised
// rigid rotations is only valid for displacements far below the size of the bodies. A load that
// turns a pinion by hundreds of turns still "solves" and returns a number; this check refuses
// it instead (limits::small_strain, errors/limits.h, docs/limits.md).
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>
#include <string>

namespace gearstiff::fem
{
// -, the largest displacement component of `u` over the diameter of the mesh of `dofs`.
template <int dim>
double displacement_ratio(const dealii::DoFHandler<dim>& dofs, const dealii::Vector<double>& u);

// InputError naming `load_parameter` (the load that caused it, as the user writes it) when
// displacement_ratio exceeds limits::small_strain.
template <int dim>
void check_small_strain(const dealii::DoFHandler<dim>& dofs, const dealii::Vector<double>& u,
                        const std::string& load_parameter);
// The same for a mesh of the given diameter (m, dealii::GridTools::diameter, whose cost grows
// with the square of the vertex count): analyses that solve one mesh many times (rolling sweeps)
// compute it once.
void check_small_strain(double diameter, const dealii::Vector<double>& u,
                        const std::string& load_parameter);
} // namespace gearstiff::fem
