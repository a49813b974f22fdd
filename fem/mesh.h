// Meshes for fem/: reading a gmsh .msh with its physical-group names, and joining separately
// generated bodies into one triangulation without merging their coincident vertices (two bodies
// touching at a point must stay two bodies).
#pragma once

#include <deal.II/grid/tria.h>
#include <map>
#include <string>
#include <vector>

namespace gearstiff::fem
{
// Physical-group names of a mesh: name -> tag, per dimension of the group's entities.
struct PhysicalNames
{
  std::map<std::string, int> cells; // dim-dimensional groups: deal.II material ids
  std::map<std::string, int> faces; // (dim−1)-dimensional groups: deal.II boundary ids
};

// Reads a .msh file (gmsh 2.2 or 4.1) into `tria`, scaling coordinates by `scale` (e.g. 1e-3 for
// a mesh in mm) and returns its physical names. InputError(parameter) when the file is
// missing, unreadable or not of dimension dim.
template <int dim>
PhysicalNames read_msh(const std::string& file_name, double scale, dealii::Triangulation<dim>& tria,
                       const std::string& parameter);

// The coarse cells of all `parts` in one triangulation, keeping material and boundary ids;
// no vertices are shared between parts.
template <int dim>
void join_bodies(const std::vector<const dealii::Triangulation<dim>*>& parts,
                 dealii::Triangulation<dim>& result);

// The coarse cells of material `body` of `scene` as a triangulation of their own, keeping
// material and boundary ids (the vertices of other bodies dropped): one gear of a scene.
template <int dim>
void one_body(const dealii::Triangulation<dim>& scene, dealii::types::material_id body,
              dealii::Triangulation<dim>& result);
} // namespace gearstiff::fem
