// Round trip through a CalculiX/Abaqus deck: a gear-pair (and a cylinders) scene is meshed (.msh,
// gmsh) and exported (.inp, geometry/abaqus_deck.h); deal.II reads the .msh (fem::read_msh, the
// exact oracle) and the deck (fem::read_abaqus). Both must give the same cells, vertices and
// groups: the same cell count per body, the same boundary faces per group, and the same geometry
// (sums of cell areas/volumes and of face measures per group).
#include "errors/errors.h"
#include "fem/abaqus_reader.h"
#include "fem/mesh.h"
#include "geometry/abaqus_deck.h"
#include "geometry/scene_cylinders.h"
#include "geometry/scene_gear_pair.h"
#include "tests/test_paths.h"

#include <deal.II/grid/tria.h>
#include <filesystem>
#include <gtest/gtest.h>
#include <map>

namespace
{
using namespace gearstiff;

std::string work_file(const std::string& name)
{
  const auto folder = test_support::build_work_folder("tests/contact/abaqus-work");
  return (folder / name).string();
}

// Per group name: element count and summed measure.
struct GroupSums
{
  std::map<std::string, std::pair<unsigned int, double>> cells, faces;
};

template <int dim>
GroupSums group_sums(const dealii::Triangulation<dim>& tria, const fem::PhysicalNames& names)
{
  std::map<int, std::string> material, boundary;
  for (const auto& [name, id] : names.cells)
    material[id] = name;
  for (const auto& [name, id] : names.faces)
    boundary[id] = name;
  GroupSums sums;
  for (const auto& cell : tria.active_cell_iterators())
  {
    auto& entry = sums.cells[material.at(cell->material_id())];
    ++entry.first;
    entry.second += cell->measure();
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() != 0)
      {
        auto& face = sums.faces[boundary.at(cell->face(f)->boundary_id())];
        ++face.first;
        face.second += cell->face(f)->measure();
      }
  }
  return sums;
}

// The .msh and the deck written from it (`base`.msh, `base`.inp) read as the same mesh.
template <int dim>
void expect_same_files(const std::string& base, const geometry::SceneInfo& info);

template <int dim>
void expect_same_mesh(const geometry::Element2D element_2d, const std::string& base)
{
  geometry::GearPairSceneSpec spec;
  spec.mesh.dimension = dim;
  spec.mesh.layers = 2;
  spec.mesh.contact_size = 0.1e-3; // coarse: the test is about the file, not the mechanics
  spec.mesh.body_size = 1.5e-3;
  spec.pinion_teeth_modelled = 3;
  spec.wheel_teeth_modelled = 3;
  const geometry::GearPairScene scene =
      geometry::write_gear_pair_scene(spec, work_file(base + ".msh"));
  const geometry::SceneInfo& info = scene.info;
  geometry::AbaqusDeckSpec deck = geometry::gear_pair_deck_spec(spec, scene, 0.01, 50.);
  deck.element_2d = element_2d;
  geometry::write_abaqus_deck(info, deck, work_file(base + ".inp"));
  expect_same_files<dim>(base, info);
}

template <int dim>
void expect_same_files(const std::string& base, const geometry::SceneInfo& info)
{
  dealii::Triangulation<dim> from_msh, from_inp;
  const fem::PhysicalNames msh_names =
      fem::read_msh(work_file(base + ".msh"), 1., from_msh, "Mesh/File");
  const fem::PhysicalNames inp_names =
      fem::read_abaqus(work_file(base + ".inp"), 1., from_inp, "Mesh/File");
  EXPECT_EQ(from_inp.n_active_cells(), from_msh.n_active_cells());
  EXPECT_EQ(from_inp.n_used_vertices(), from_msh.n_used_vertices());
  EXPECT_EQ(from_inp.n_active_cells(), info.mesh.n_cells);

  const GroupSums expected = group_sums(from_msh, msh_names);
  const GroupSums actual = group_sums(from_inp, inp_names);
  ASSERT_EQ(actual.cells.size(), expected.cells.size());
  ASSERT_EQ(actual.faces.size(), expected.faces.size());
  // The deck prints 12 significant digits: measures agree to ~1e-11 relative.
  const double tolerance = 1e-9;
  for (const auto& [name, count_measure] : expected.cells)
  {
    ASSERT_TRUE(actual.cells.count(name)) << name;
    EXPECT_EQ(actual.cells.at(name).first, count_measure.first) << name;
    EXPECT_NEAR(actual.cells.at(name).second / count_measure.second, 1., tolerance) << name;
  }
  for (const auto& [name, count_measure] : expected.faces)
  {
    ASSERT_TRUE(actual.faces.count(name)) << name;
    EXPECT_EQ(actual.faces.at(name).first, count_measure.first) << name;
    EXPECT_NEAR(actual.faces.at(name).second / count_measure.second, 1., tolerance) << name;
  }
}

TEST(AbaqusRoundTrip, GearPairPlaneStrainCPE4)
{
  expect_same_mesh<2>(geometry::Element2D::plane_strain, "gear_pair_2d");
}

TEST(AbaqusRoundTrip, GearPair3DC3D8)
{
  expect_same_mesh<3>(geometry::Element2D::slice, "gear_pair_3d");
}

// The Hertz cylinders' deck (half-discs: arcs and flat faces; CPE4) reads back as its .msh.
TEST(AbaqusRoundTrip, CylindersPlaneStrainCPE4)
{
  geometry::CylindersSceneSpec spec;
  spec.mesh.contact_size = 0.02e-3; // coarse: the test is about the file
  spec.mesh.body_size = 1e-3;
  spec.mesh.rim_size = 1e-3;
  const geometry::SceneInfo info =
      geometry::write_cylinders_scene(spec, work_file("cylinders_2d.msh"));
  geometry::AbaqusDeckSpec deck = geometry::cylinders_deck_spec(spec, info, 0.01, 50.);
  deck.element_2d = geometry::Element2D::plane_strain;
  geometry::write_abaqus_deck(info, deck, work_file("cylinders_2d.inp"));
  expect_same_files<2>("cylinders_2d", info);
}

// A slice deck (C3D8) is a 3D mesh: reading it as 2D names the keyword and line.
TEST(AbaqusRoundTrip, SliceIsNotA2DMesh)
{
  geometry::GearPairSceneSpec spec;
  spec.mesh.contact_size = 0.1e-3;
  spec.mesh.body_size = 1.5e-3;
  const geometry::GearPairScene scene =
      geometry::write_gear_pair_scene(spec, work_file("slice.msh"));
  geometry::write_abaqus_deck(scene.info, geometry::gear_pair_deck_spec(spec, scene, 0.01, 50.),
                              work_file("slice.inp"));
  dealii::Triangulation<2> tria;
  try
  {
    fem::read_abaqus(work_file("slice.inp"), 1., tria, "Mesh/File");
    FAIL() << "a C3D8 deck was read as 2D";
  }
  catch (const InputError& e)
  {
    EXPECT_EQ(e.parameter(), "Mesh/File");
    EXPECT_NE(std::string(e.reason()).find("*ELEMENT: TYPE=C3D8 is a 3D element"),
              std::string::npos)
        << e.reason();
  }
}
} // namespace
