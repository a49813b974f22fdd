// Helpers of the scene tests (test_scene_*.cc): a scratch folder for the meshes they write, and
// the mesh read back with deal.II's GridIn::read_msh with its material and boundary ids.
#pragma once

#include "kinematics/gear_pair.h"
#include "tests/test_paths.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/tria.h>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gearstiff::test_support
{
// `name` in the build tree's tests/geometry/scene-work (created on first use).
inline std::string work_file(const std::string& name)
{
  const auto folder = build_work_folder("tests/geometry/scene-work");
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
// Where the segment a–b (b excluded) crosses the line t1–t2: the distance from t1 along it, or
// nothing when they do not meet between t1 and t2 (or are parallel).
inline std::optional<double> segment_crossing(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                              const Eigen::Vector2d& t1, const Eigen::Vector2d& t2)
{
  const Eigen::Vector2d u = (t2 - t1).normalized();
  Eigen::Matrix2d m;
  m << u, a - b;
  if (std::abs(m.determinant()) < 1e-30)
    return std::nullopt;
  const Eigen::Vector2d ts = m.inverse() * (a - t1);
  if (ts(1) >= 0. && ts(1) < 1. && ts(0) >= 0. && ts(0) <= (t2 - t1).norm())
    return ts(0);
  return std::nullopt;
}

// Distances along the line of action (from T1) where it crosses boundary faces with an id of
// `ids`.
inline std::vector<double> crossings(const dealii::Triangulation<2>& triangulation,
                                     const std::set<int>& ids, const Eigen::Vector2d& t1,
                                     const Eigen::Vector2d& t2)
{
  std::vector<double> result;
  for (const auto& cell : triangulation.active_cell_iterators())
    for (const auto f : cell->face_indices())
      if (cell->face(f)->at_boundary() && ids.count(cell->face(f)->boundary_id()) > 0)
      {
        const auto v0 = cell->face(f)->vertex(0), v1 = cell->face(f)->vertex(1);
        if (const auto t = segment_crossing({v0[0], v0[1]}, {v1[0], v1[1]}, t1, t2))
          result.push_back(*t);
      }
  return result;
}

// The gap between the two flanks (boundary ids `pinion_flank`, `wheel_flank`) of one tooth pair
// along the line t1–t2 on a mesh read back [m]: the pinion and wheel crossings closest to each
// other, wheel minus pinion (1e300 when a flank does not cross the line).
inline double flank_gap(const dealii::Triangulation<2>& triangulation, int pinion_flank,
                        int wheel_flank, const Eigen::Vector2d& t1, const Eigen::Vector2d& t2)
{
  double gap = 1e300;
  for (const double p : crossings(triangulation, {pinion_flank}, t1, t2))
    for (const double w : crossings(triangulation, {wheel_flank}, t1, t2))
      if (std::abs(p - w) < std::abs(gap))
        gap = w - p;
  return gap;
}

// Where the two flanks of one tooth pair touch when brought together along the line t1–t2: the
// smallest flank_gap over lines parallel to it, offset across it by up to ±`reach` (m) in 201
// steps — the rigid flanks' smallest gap (geometry::touching_point), measured on the mesh.
inline double smallest_flank_gap(const dealii::Triangulation<2>& triangulation, int pinion_flank,
                                 int wheel_flank, const Eigen::Vector2d& t1,
                                 const Eigen::Vector2d& t2, double reach)
{
  const Eigen::Vector2d u = (t2 - t1).normalized(), across(-u.y(), u.x());
  double smallest = 1e300;
  for (int i = -100; i <= 100; ++i)
  {
    const Eigen::Vector2d offset = reach * i / 100. * across;
    const double gap =
        flank_gap(triangulation, pinion_flank, wheel_flank, t1 + offset, t2 + offset);
    if (std::abs(gap) < 1e299)
      smallest = std::min(smallest, std::abs(gap));
  }
  return smallest;
}

// The unloaded TE with equal linear long reliefs C on both gears at s = (ℓ − A)/(B − A) of the
// first double zone (test_tooth_modification.cc's tent): the entering pair at ℓ relieved by the
// wheel's tip, C·(1 − s), its slope C/(B − A) a unit of ℓ, the leaving one at ℓ + p_bt by the
// pinion's, C·s, slope C/(E − D); each lowered by β²R/2 where its flanks touch (β the slope
// across the contact, r_b/ρ a unit of ℓ; R the relative radius, a ring's flank concave).
inline double relieved_tent(const kinematics::GearPairGeometry& pair, double s, double c)
{
  const double a = pair.contact_start, b = pair.single_contact_start();
  const double d = pair.single_contact_end(), e = pair.contact_end;
  const double r_b1 = 0.5 * std::abs(pair.pinion.base_diameter);
  const double r_b2 = 0.5 * std::abs(pair.wheel.base_diameter);
  const bool ring = pair.spec.wheel.internal;
  const auto touching = [&](double at, double removal, double slope, bool of_wheel)
  {
    const double rho_1 = at;
    const double rho_2 = ring ? at + pair.line_of_action_length : pair.line_of_action_length - at;
    const double beta = slope * (of_wheel ? r_b2 / rho_2 : r_b1 / rho_1);
    const double radius = 1. / (1. / rho_1 + (ring ? -1. : 1.) / rho_2);
    return removal - 0.5 * beta * beta * radius;
  };
  const double at = a + s * (b - a);
  return std::min(touching(at, c * (1. - s), c / (b - a), true),
                  touching(at + pair.transverse_base_pitch, c * s, c / (e - d), false));
}
} // namespace gearstiff::test_support
