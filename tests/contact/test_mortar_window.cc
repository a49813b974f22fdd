// The pairing window of the dual-mortar coupling (contact/mortar.h, PairingWindow; issue 28:
// rolling sweeps pair only the flanks near each position's contact). The window must drop
// nodes, never change one: every node it couples carries exactly (bit for bit) the mortar data
// of the whole surfaces, every node whose faces all lie inside it is coupled, and no node
// outside it is. Two Q2 blocks with non-matching meshes; the upper one's contact face is bent
// into a parabola (gap = x²/2ρ about its middle, ρ = 2 mm), so the gaps, normals and master
// weights vary from node to node and a search distance of 0.03 mm pairs only part of it.
#include "contact/mortar.h"
#include "fem/mesh.h"

#include <algorithm>
#include <cmath>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <gtest/gtest.h>
#include <map>

using namespace dealii;
using namespace gearstiff;
using namespace gearstiff::contact;

namespace
{
constexpr double width = 4e-3, height = 1e-3, radius_of_curvature = 2e-3; // m

// Boundary ids: upper contact 1, lower contact 4 (others 0).
void make_bent_blocks(Triangulation<2>& tria)
{
  Triangulation<2> upper, lower;
  GridGenerator::subdivided_hyper_rectangle(upper, {37, 4}, Point<2>(0, 0), Point<2>(width, height),
                                            true);
  GridGenerator::subdivided_hyper_rectangle(lower, {23, 3}, Point<2>(0, -height),
                                            Point<2>(width, 0), true);
  // The upper block's bottom face bent up, fading out towards its top.
  GridTools::transform(
      [](const Point<2>& p)
      {
        const double x = p[0] - 0.5 * width;
        return Point<2>(p[0], p[1] + (1. - p[1] / height) * x * x / (2. * radius_of_curvature));
      },
      upper);
  for (auto& [tria_part, contact_id] : {std::pair{&upper, 1}, std::pair{&lower, 4}})
    for (auto& cell : tria_part->active_cell_iterators())
    {
      cell->set_material_id(contact_id);
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          cell->face(f)->set_boundary_id(
              cell->face(f)->boundary_id() == (contact_id == 1 ? 2 : 3) ? contact_id : 0);
    }
  fem::join_bodies<2>({&upper, &lower}, tria);
}

// The bent blocks with their Q2 DoFs, as every test here pairs them.
struct BentBlocks
{
  BentBlocks()
  {
    make_bent_blocks(tria);
    dof_handler.distribute_dofs(fe);
  }
  Triangulation<2> tria;
  const FESystem<2> fe{FE_Q<2>(2), 2};
  DoFHandler<2> dof_handler{tria};
};
} // namespace

TEST(MortarWindow, CouplesTheWholeSurfacesNodesInsideUnchanged)
{
  const BentBlocks blocks;
  const DoFHandler<2>& dof_handler = blocks.dof_handler;
  const double search_distance = 0.03e-3, depth = 1e-3; // m
  const std::vector<SlaveNode<2>> whole =
      mortar_coupling<2>(dof_handler, {1}, {4}, search_distance, depth);
  // Without a window the search distance bounds the pairing: |x| ≲ √(2ρd) = 0.35 mm.
  ASSERT_GT(whole.size(), 10u);
  std::map<types::global_dof_index, const SlaveNode<2>*> by_dof;
  for (const auto& node : whole)
    by_dof[node.node.dofs[0]] = &node;

  PairingWindow<2> window;
  window.centre = Point<2>(0.5 * width + 0.1e-3, 0.02e-3);
  window.radius = 0.35e-3;
  const std::vector<SlaveNode<2>> windowed =
      mortar_coupling<2>(dof_handler, {1}, {4}, search_distance, depth, window);
  ASSERT_GT(windowed.size(), 5u);
  ASSERT_LT(windowed.size(), whole.size());
  const double cell = width / 37.; // upper face length (the bend lengthens it by < 2 %)
  for (const auto& node : windowed)
  {
    const auto it = by_dof.find(node.node.dofs[0]);
    ASSERT_NE(it, by_dof.end()) << "a node the whole surfaces do not couple";
    const SlaveNode<2>& reference = *it->second;
    // Exact equality: the same faces, candidates and quadrature in the same order.
    EXPECT_EQ(node.node.dofs[1], reference.node.dofs[1]);
    EXPECT_EQ(node.normal, reference.normal);
    EXPECT_EQ(node.area, reference.area);
    EXPECT_EQ(node.initial_gap, reference.initial_gap);
    EXPECT_EQ(node.initial_offset, reference.initial_offset);
    ASSERT_EQ(node.masters.size(), reference.masters.size());
    for (unsigned int m = 0; m < node.masters.size(); ++m)
    {
      EXPECT_EQ(node.masters[m].node.dofs[0], reference.masters[m].node.dofs[0]);
      EXPECT_EQ(node.masters[m].weight, reference.masters[m].weight);
    }
    // A coupled node's faces lie inside (centres within R): the node within R + h/2.
    EXPECT_LE(std::hypot(node.node.position[0] - window.centre[0],
                         node.node.position[1] - window.centre[1]),
              window.radius + 0.5 * cell * 1.02);
  }
  // Every node of the whole surfaces whose faces all lie inside is coupled: a node within
  // R − 1.5 h of the centre (its faces' centres within R − h, and no face of theirs touches a
  // face outside).
  unsigned int inside = 0;
  for (const auto& node : whole)
    if (std::hypot(node.node.position[0] - window.centre[0],
                   node.node.position[1] - window.centre[1]) < window.radius - 1.5 * cell * 1.02)
    {
      ++inside;
      EXPECT_TRUE(std::any_of(windowed.begin(), windowed.end(),
                              [&](const SlaveNode<2>& n)
                              { return n.node.dofs[0] == node.node.dofs[0]; }))
          << "x = " << node.node.position[0];
    }
  EXPECT_GT(inside, 5u);
}

// A SurfaceGeometry changes what the gap is measured between, nothing else: with the lower
// body's exact surface δ below its mesh, every node keeps its pairing, normal and master weights
// bit for bit and its gap grows by δ·(−n_y) (the slave normal points down, out of the upper
// block) — the gap integrated between the exact points.
TEST(MortarWindow, SurfaceGeometryMovesTheGapOnly)
{
  const BentBlocks blocks;
  const DoFHandler<2>& dof_handler = blocks.dof_handler;
  const double search_distance = 0.03e-3, depth = 1e-3, delta = 0.5e-6; // m
  const std::vector<SlaveNode<2>> meshed =
      mortar_coupling<2>(dof_handler, {1}, {4}, search_distance, depth);
  const SurfaceGeometry<2> lowered = [delta](const Point<2>& p, types::material_id body)
  { return body == 4 ? Point<2>(p[0], p[1] - delta) : p; };
  const std::vector<SlaveNode<2>> exact =
      mortar_coupling<2>(dof_handler, {1}, {4}, search_distance, depth, {}, lowered);
  ASSERT_GT(meshed.size(), 10u);
  ASSERT_EQ(exact.size(), meshed.size());
  for (std::size_t i = 0; i < meshed.size(); ++i)
  {
    EXPECT_EQ(exact[i].node.dofs[0], meshed[i].node.dofs[0]);
    EXPECT_EQ(exact[i].normal, meshed[i].normal);
    EXPECT_EQ(exact[i].area, meshed[i].area);
    ASSERT_EQ(exact[i].masters.size(), meshed[i].masters.size());
    for (std::size_t m = 0; m < meshed[i].masters.size(); ++m)
      EXPECT_EQ(exact[i].masters[m].weight, meshed[i].masters[m].weight);
    EXPECT_NEAR(exact[i].initial_gap - meshed[i].initial_gap, -delta * meshed[i].normal[1], 1e-18);
  }
}
