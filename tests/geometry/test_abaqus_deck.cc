// The CalculiX/Abaqus deck of a gear-pair scene (geometry/abaqus_deck.h), checked against the
// mesh it was written from (read_scene_mesh on the same .msh: exact counts): one node per mesh
// node and layer plus the rigid body's two nodes, one element per cell, one element set per
// body, an element-face surface and a node set per boundary group, the rigid pinion bore carrying
// the torque, the fixed wheel bore, and plane strain on every node but the rigid bore's.
// When `ccx` is installed the deck is also solved, as it is.
#include "geometry/abaqus_deck.h"
#include "geometry/scene_gear_pair.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <set>
#include <sstream>

namespace
{
using namespace gearstiff;
using namespace gearstiff::geometry;

// `name` in the build tree's tests/geometry/deck-work (the deck test has no deal.II).
std::string work_file(const std::string& name)
{
  const std::filesystem::path folder =
      std::filesystem::path(GEARSTIFF_BINARY_DIR) / "tests" / "geometry" / "deck-work";
  std::filesystem::create_directories(folder);
  return (folder / name).string();
}

// Data lines per keyword line (the keyword line as written, e.g. "*ELEMENT, TYPE=C3D8, ...").
std::vector<std::pair<std::string, std::vector<std::string>>> blocks(const std::string& file)
{
  std::vector<std::pair<std::string, std::vector<std::string>>> result;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("**", 0) == 0)
      continue;
    else if (line.rfind("*", 0) == 0)
      result.push_back({line, {}});
    else if (!result.empty())
      result.back().second.push_back(line);
  return result;
}

std::size_t entries(const std::vector<std::string>& lines)
{
  std::size_t count = 0;
  for (const auto& line : lines)
    count += std::count(line.begin(), line.end(), ',') + 1;
  return count;
}

struct Deck
{
  GearPairSceneSpec spec;
  GearPairScene scene;
  SceneInfo info;
  SceneMesh mesh;
  std::string file;
};

Deck coarse_slice_deck(const std::string& base, unsigned int dimension = 2,
                       PairPosition position = PairPosition::single)
{
  Deck deck;
  deck.spec.position = position;
  deck.spec.mesh.dimension = dimension;
  deck.spec.mesh.layers = 2;
  deck.spec.rim = RimModel::full;
  deck.spec.pinion_teeth_modelled = 3;
  deck.spec.wheel_teeth_modelled = 3;
  deck.spec.mesh.contact_size = 0.1e-3; // coarse: ccx solves it in seconds
  deck.spec.mesh.body_size = 1.5e-3;
  deck.scene = write_gear_pair_scene(deck.spec, work_file(base + ".msh"));
  deck.info = deck.scene.info;
  deck.mesh = read_scene_mesh(deck.info.file, dimension);
  deck.file = work_file(base + ".inp");
  write_abaqus_deck(deck.info, gear_pair_deck_spec(deck.spec, deck.scene, 0.01, 50.), deck.file);
  return deck;
}

TEST(AbaqusDeck, SliceOfTheGearPair)
{
  const Deck deck = coarse_slice_deck("deck_slice");
  const std::size_t n = deck.mesh.nodes.size();
  std::size_t nodes = 0, elements = 0, plane_strain = 0, bore_nodes = 0;
  std::set<std::string> element_sets, surfaces;
  std::string rigid_body, cload;
  for (const auto& [keyword, lines] : blocks(deck.file))
  {
    if (keyword.rfind("*NODE,", 0) == 0)
      nodes += lines.size();
    else if (keyword.rfind("*ELEMENT, TYPE=C3D8, ELSET=", 0) == 0)
    {
      elements += lines.size();
      element_sets.insert(keyword.substr(27));
      for (const auto& line : lines)
        EXPECT_EQ(std::count(line.begin(), line.end(), ','), 8) << line;
    }
    else if (keyword.rfind("*SURFACE, NAME=", 0) == 0)
      surfaces.insert(keyword.substr(15, keyword.find(',', 15) - 15));
    else if (keyword == "*NSET, NSET=PLANE_STRAIN")
      plane_strain = entries(lines);
    else if (keyword == "*NSET, NSET=PINION_BORE_NODES")
      bore_nodes = entries(lines);
    else if (keyword.rfind("*RIGID BODY", 0) == 0)
      rigid_body = keyword;
    else if (keyword == "*CLOAD")
      cload = lines.at(0);
  }
  EXPECT_EQ(nodes, 2 * n + 2); // both layers, REF NODE and ROT NODE
  EXPECT_EQ(elements, deck.info.mesh.n_cells);
  EXPECT_EQ(element_sets, (std::set<std::string>{"PINION_BODY", "WHEEL_BODY"}));
  // One surface per modelled flank (geometry/scene_gear_pair.h: pinion tooth j, wheel tooth −j,
  // three teeth per gear in the default scene); only the pairs in contact are contact pairs.
  EXPECT_EQ(surfaces, (std::set<std::string>{"PINION_BORE", "WHEEL_BORE", "PINION_FLANK_-1",
                                             "PINION_FLANK_0", "PINION_FLANK_1", "WHEEL_FLANK_-1",
                                             "WHEEL_FLANK_0", "WHEEL_FLANK_1"}));
  EXPECT_GT(bore_nodes, 0u);
  EXPECT_EQ(plane_strain, 2 * n - bore_nodes);
  EXPECT_EQ(rigid_body, "*RIGID BODY, NSET=PINION_BORE_NODES, REF NODE=" +
                            std::to_string(2 * n + 1) + ", ROT NODE=" + std::to_string(2 * n + 2));
  EXPECT_EQ(cload, "DRIVEN_ROT, 3, 49.4"); // gear-data.md §1: T1 = 49.4 N·m
}

// The *CONTACT PAIR lines of a deck, "slave, master".
std::vector<std::string> contact_pairs(const std::string& file)
{
  std::vector<std::string> pairs;
  for (const auto& [keyword, lines] : blocks(file))
    if (keyword.rfind("*CONTACT PAIR", 0) == 0)
      pairs.insert(pairs.end(), lines.begin(), lines.end());
  return pairs;
}

// Regression (docs/calculix.md, "Internal and 24/69 pairs: the same contact model"): the deck pairs
// the flanks of exactly the tooth pairs `gearstiff stiffness` pairs, those inside the path of
// contact, not every modelled pair: pairing the neighbours let ccx carry load through a tip corner
// that the stiffness analysis leaves free (24/69: k +30 % external, +74 % ring). Split-path pair
// (gear-data.md §1, ε_α < 2): one pair at the single position, two at the double one, three
// modelled in both.
TEST(AbaqusDeck, PairsTheToothPairsInContactOnly)
{
  const Deck single = coarse_slice_deck("deck_pairs_single");
  ASSERT_EQ(single.scene.modelled_pairs.size(), 3u);
  ASSERT_EQ(single.scene.contact_pairs, std::vector<int>{0});
  EXPECT_EQ(contact_pairs(single.file), std::vector<std::string>{"PINION_FLANK_0, WHEEL_FLANK_0"});

  const Deck twice = coarse_slice_deck("deck_pairs_double", 2, PairPosition::double_pair);
  ASSERT_EQ(twice.scene.modelled_pairs.size(), 3u);
  ASSERT_EQ(twice.scene.contact_pairs.size(), 2u);
  std::vector<std::string> expected;
  for (const int j : twice.scene.contact_pairs)
    expected.push_back("PINION_FLANK_" + std::to_string(j) + ", WHEEL_FLANK_" + std::to_string(j));
  EXPECT_EQ(contact_pairs(twice.file), expected);
}

// Solves `deck` with ccx as written; returns the rotation of the ROT NODE (rad).
double calculix_rotation(const Deck& deck)
{
  const std::string job = deck.file.substr(0, deck.file.size() - 4);
  const std::string folder = job.substr(0, job.rfind('/'));
  const std::string name = job.substr(job.rfind('/') + 1);
  EXPECT_EQ(std::system(("cd " + folder + " && OMP_NUM_THREADS=1 ccx -i " + name + " > " + name +
                         ".log 2>&1")
                            .c_str()),
            0);
  // The last "displacements ... for set DRIVEN_ROT" block of the .dat: id, rx, ry, rz.
  std::ifstream dat(job + ".dat");
  std::string line;
  double rotation = 0.;
  bool in_block = false;
  while (std::getline(dat, line))
  {
    if (line.find(" for set ") != std::string::npos)
      in_block = line.find("displacements") != std::string::npos;
    else if (in_block)
    {
      std::istringstream values(line);
      long id = 0;
      double rx = 0., ry = 0., rz = 0.;
      if (values >> id >> rx >> ry >> rz)
        rotation = rz;
    }
  }
  return rotation;
}

// ccx solves the deck with no editing and turns the pinion forward: more than the closing
// rotation of step 1 and of the order of the deck's own estimate (ten times that rotation,
// from c' = 14 N/(mm·µm); the coarse Q1 scene is softer than that). Skipped without ccx.
TEST(AbaqusDeck, CalculixSolvesTheSlice)
{
  if (std::system("command -v ccx > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "ccx is not installed";
  const Deck deck = coarse_slice_deck("deck_ccx");
  const double rotation = calculix_rotation(deck);
  const AbaqusDeckSpec spec = gear_pair_deck_spec(deck.spec, deck.scene, 0.01, 50.);
  EXPECT_GT(rotation, spec.closing_rotation);
  EXPECT_LT(rotation, 30. * spec.closing_rotation);
}

// The 3D deck (C3D8 over the face width, two layers) solves too, and a plane-strain slice and
// 3D scene with free side faces differ by less than plane strain and plane stress do (docs/
// accuracy.md: 3D lies between them, within a few per cent).
TEST(AbaqusDeck, CalculixSolves3D)
{
  if (std::system("command -v ccx > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "ccx is not installed";
  const double slice = calculix_rotation(coarse_slice_deck("deck_ccx_2d"));
  const double solid = calculix_rotation(coarse_slice_deck("deck_ccx_3d", 3));
  EXPECT_GT(solid, slice);       // free side faces: softer than plane strain
  EXPECT_LT(solid, 1.2 * slice); // plane stress is ~ (1 − ν²)⁻¹ ≈ 10% softer
}
} // namespace
