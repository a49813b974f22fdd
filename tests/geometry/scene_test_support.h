// Helpers of the scene tests (test_scene_*.cc): a scratch folder for the meshes they write, and
// the mesh read back with deal.II's GridIn::read_msh with its material and boundary ids.
#pragma once

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>
#include <filesystem>
#include <set>
#include <string>

namespace gearstiff::test_support
{
// `name` in the build tree's tests/geometry/scene-work (created on first use).
inline std::string work_file(const std::string& name)
{
  const std::filesystem::path folder =
      std::filesystem::path(GEARSTIFF_BINARY_DIR) / "tests" / "geometry" / "scene-work";
  std::filesystem::create_directories(folder);
  return (folder / name).string();
}

template <int dim>
void read_mesh(dealii::Triangulation<dim>& triangulation, const std::string& file)
{
  dealii::GridIn<dim> grid_in(triangulation);
  grid_in.read_msh(file);
}

struct Ids
{
  std::set<int> materials, boundaries;
};

// The material ids of the cells and the boundary ids of the boundary faces.
template <int dim>
Ids ids_of(const dealii::Triangulation<dim>& triangulation)
{
  Ids ids;
  for (const auto& cell : triangulation.active_cell_iterators())
  {
    ids.materials.insert(cell->material_id());
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        ids.boundaries.insert(cell->face(f)->boundary_id());
  }
  return ids;
}
} // namespace gearstiff::test_support
