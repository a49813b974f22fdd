// The two-cylinder Hertz scene, read back with deal.II's GridIn: ids, contact size, and the
// half-width estimate against Johnson, Contact Mechanics (1985) eq. 4.43 evaluated by hand.
#include "errors/errors.h"
#include "geometry/scene_cylinders.h"
#include "tests/geometry/scene_test_support.h"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <set>

namespace
{
using namespace gearstiff;
using namespace gearstiff::geometry;
using namespace gearstiff::test_support;

TEST(CylindersScene, HalfDiscsReadWithIdsAndContactSize)
{
  CylindersSceneSpec spec; // R1 = R2 = 10 mm, F' = 1e5 N/m, steel
  const SceneInfo info = write_cylinders_scene(spec, work_file("cylinders.msh"));

  // Johnson eq. 4.43 by hand: R = 5 mm, E* = 210 GPa / (2·(1 − 0.09)) = 115.38 GPa,
  // a = sqrt(4·1e5·5e-3 / (π·115.38e9)) = 74.28 µm. The inputs are exact, so only rounding
  // of the hand value (4 digits) limits the tolerance.
  ASSERT_EQ(info.contacts.size(), 1u);
  EXPECT_NEAR(info.contacts[0].hertz_half_width, 74.28e-6, 0.01e-6);
  EXPECT_NEAR(info.contact_size, 7.428e-6, 0.001e-6);

  dealii::Triangulation<2> triangulation;
  read_mesh(triangulation, info.file);
  double largest_edge = 0.;
  for (const auto& cell : triangulation.active_cell_iterators())
  {
    bool at_contact = false;
    for (const auto v : cell->vertex_indices())
      at_contact |= cell->vertex(v).norm() < 0.5 * info.contact_size;
    if (at_contact)
      for (const auto f : cell->face_indices())
        largest_edge = std::max(largest_edge, cell->face(f)->measure());
  }
  const Ids ids = ids_of(triangulation);
  EXPECT_EQ(ids.materials, (std::set<int>{scene_ids::first_body, scene_ids::second_body}));
  EXPECT_EQ(ids.boundaries, (std::set<int>{scene_ids::first_contact, scene_ids::second_contact,
                                           scene_ids::first_cuts, scene_ids::second_cuts}));
  // The scene starts its arcs at the contact point, so both bodies have a vertex there and
  // the cells around it are no larger than h_c.
  EXPECT_GT(largest_edge, 0.);
  EXPECT_LE(largest_edge, info.contact_size);
}

TEST(CylindersScene, AnnuliWithBores)
{
  CylindersSceneSpec spec;
  spec.radius_2 = 20e-3;
  spec.bore_radius_1 = 4e-3;
  spec.bore_radius_2 = 8e-3;
  const SceneInfo info = write_cylinders_scene(spec, work_file("annuli.msh"));
  dealii::Triangulation<2> triangulation;
  read_mesh(triangulation, info.file);
  EXPECT_EQ(ids_of(triangulation).boundaries,
            (std::set<int>{scene_ids::first_bore, scene_ids::second_bore, scene_ids::first_contact,
                           scene_ids::second_contact}));
  EXPECT_EQ(triangulation.n_active_cells(), info.mesh.n_cells);
}

TEST(CylindersScene, RejectsBadInput)
{
  CylindersSceneSpec spec;
  spec.bore_radius_1 = 9e-3; // leaves 1 mm of ring
  EXPECT_THROW(write_cylinders_scene(spec, work_file("bad.msh")), InputError);
  spec = CylindersSceneSpec();
  spec.force_per_length = 1e9; // a ≈ 7 mm on 10 mm radii: outside Hertz theory
  EXPECT_THROW(write_cylinders_scene(spec, work_file("bad.msh")), InputError);
  EXPECT_FALSE(std::filesystem::exists(work_file("bad.msh")));
}
} // namespace
