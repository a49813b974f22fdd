// The cycloid (Cyclo) scene of docs/references.md §4 (Chmurawa & Łokiec): nominal disc r = 96 mm,
// e = 3 mm, q = 8.5 mm, z_k = 20, read back with deal.II's GridIn.
#include "errors/errors.h"
#include "geometry/scene_cycloid.h"
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

TEST(CycloidScene, NominalDiscTouchesEveryRoller)
{
  CycloidSceneSpec spec;
  spec.disc_rotation = 0.05; // rad, an arbitrary position
  // A coarse contact size keeps the test fast; the default (a/10 ≈ 8 µm) is benchmarked.
  spec.mesh.contact_size = 40e-6;
  const SceneInfo info = write_cycloid_scene(spec, work_file("cycloid.msh"));

  // The nominal equidistant is conjugate to the ring: every roller touches (clearance 0 to
  // the accuracy of prof's closest-point iteration, 1e-9·r).
  ASSERT_EQ(info.contacts.size(), 20u);
  for (const auto& contact : info.contacts)
  {
    EXPECT_LT(std::abs(contact.gap), 1e-9 * 96e-3);
    // The contact point is the exact closest point of the disc: it lies on the roller
    // (radius q = 8.5 mm) to the accuracy of the golden-section search (< 1 nm).
    const double angle = 2. * M_PI * contact.second_feature / 20.;
    const Eigen::Vector2d roller = 96e-3 * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    EXPECT_NEAR((contact.point - roller).norm(), 8.5e-3, 1e-9);
  }

  dealii::Triangulation<2> triangulation;
  read_mesh(triangulation, info.file);
  const Ids ids = ids_of(triangulation);
  EXPECT_EQ(ids.materials, (std::set<int>{scene_ids::first_body, scene_ids::second_body}));
  EXPECT_EQ(ids.boundaries,
            (std::set<int>{scene_ids::first_bore, scene_ids::second_bore, scene_ids::first_contact,
                           scene_ids::second_contact, scene_ids::output_pin_holes}));
  EXPECT_EQ(triangulation.n_active_cells(), info.mesh.n_cells);
  EXPECT_LE(info.mesh.largest_edge_ratio_at_focus, 1.);
}

TEST(CycloidScene, RejectsHolesThatDoNotFit)
{
  CycloidSceneSpec spec;
  spec.output_pin_circle_radius = 75e-3; // 75 + 12 mm reaches past the 84.5 mm lobe roots
  EXPECT_THROW(write_cycloid_scene(spec, work_file("bad_cycloid.msh")), InputError);
  spec = CycloidSceneSpec();
  spec.output_pins = 14; // 14 holes of 12 mm on a 55 mm circle overlap
  EXPECT_THROW(write_cycloid_scene(spec, work_file("bad_cycloid.msh")), InputError);
  EXPECT_FALSE(std::filesystem::exists(work_file("bad_cycloid.msh")));
}
} // namespace
