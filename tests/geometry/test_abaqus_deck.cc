// The CalculiX/Abaqus deck of a gear-pair scene (geometry/abaqus_deck.h), checked against the
// mesh it was written from (read_scene_mesh on the same .msh: exact counts): one node per mesh
// node and layer plus the rigid body's two nodes, one element per cell, one element set per
// body, an element-face surface and a node set per boundary group, the rigid pinion bore carrying
// the torque, the fixed wheel bore, and plane strain on every node but the rigid bore's.
// When `ccx` is installed the deck is also solved, as it is. The cycloid deck (the load case of
// stiffness/cycloid_loads.h) is checked for its sets, surfaces, pairs and rigid bodies.
#include "errors/errors.h"
#include "geometry/abaqus_deck.h"
#include "geometry/scene_cylinders.h"
#include "geometry/scene_gear_pair.h"
#include "tests/test_paths.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
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
  const auto folder = test_support::build_work_folder("tests/geometry/deck-work");
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

// The Gmsh scene a deck is written from, read back (the exact counts the deck is checked
// against), and the deck.
struct SceneDeck
{
  SceneInfo info;
  SceneMesh mesh;
  std::string file;
};

// Reads back the mesh of the scene written to deck.info and writes the deck `base`.inp.
void write_deck(SceneDeck& deck, unsigned int dimension, const AbaqusDeckSpec& spec,
                const std::string& base)
{
  deck.mesh = read_scene_mesh(deck.info.file, dimension);
  deck.file = work_file(base + ".inp");
  write_abaqus_deck(deck.info, spec, deck.file);
}

// The element sets, rigid bodies and reference nodes of a deck, by keyword.
struct DeckBodies
{
  std::set<std::string> element_sets;            // "*ELEMENT, TYPE=C3D8, ELSET=<set>"
  std::set<std::string> rigid_bodies;            // the *RIGID BODY keyword lines
  std::map<std::string, std::string> node_lines; // "*NODE, NSET=<name>" -> its node line
};

DeckBodies deck_bodies(const std::string& file)
{
  DeckBodies bodies;
  for (const auto& [keyword, lines] : blocks(file))
    if (keyword.rfind("*ELEMENT, TYPE=C3D8, ELSET=", 0) == 0)
      bodies.element_sets.insert(keyword.substr(27));
    else if (keyword.rfind("*RIGID BODY", 0) == 0)
      bodies.rigid_bodies.insert(keyword);
    else if (keyword.rfind("*NODE, NSET=", 0) == 0 && keyword != "*NODE, NSET=NALL")
      bodies.node_lines[keyword.substr(12)] = lines.at(0);
  return bodies;
}

// Solves the deck `file` with ccx as it is, in its folder (log: <job>.log); std::system's status.
int run_calculix(const std::string& file)
{
  const std::string job = file.substr(0, file.size() - 4);
  const std::string folder = job.substr(0, job.rfind('/'));
  const std::string name = job.substr(job.rfind('/') + 1);
  return std::system(
      ("cd " + folder + " && OMP_NUM_THREADS=1 ccx -i " + name + " > " + name + ".log 2>&1")
          .c_str());
}

struct Deck : SceneDeck
{
  GearPairSceneSpec spec;
  GearPairScene scene;
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
  write_deck(deck, dimension, gear_pair_deck_spec(deck.spec, deck.scene, 0.01, 50.), base);
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
  EXPECT_EQ(cload, "DRIVEN_ROT, 3, 49.4"); // docs/references.md §1: T1 = 49.4 N·m
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
// (docs/references.md §1, ε_α < 2): one pair at the single position, two at the double one, three
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
  EXPECT_EQ(run_calculix(deck.file), 0);
  const std::string job = deck.file.substr(0, deck.file.size() - 4);
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
  EXPECT_GT(rotation, spec.rigid_bodies.at(0).closing_rotation);
  EXPECT_LT(rotation, 30. * spec.rigid_bodies.at(0).closing_rotation);
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

// A coarse cycloid scene (docs/references.md §4 drive, nominal disc) with its output pins meshed.
CycloidSceneSpec coarse_cycloid_spec()
{
  CycloidSceneSpec spec;
  spec.output_pin_bodies = true;
  spec.disc_rotation = M_PI / 19.; // crank angle 0 (disc_rotation_at_crank_angle)
  spec.contact_clearance = 0.1e-3; // as cycloid-loads: every roller of the nominal disc
  spec.points_per_lobe = 21;
  spec.mesh.contact_size = 0.2e-3; // coarse: the structure is checked, not solved
  spec.mesh.fine_radius = 0.4e-3;
  spec.mesh.body_size = 3e-3;
  spec.mesh.rim_size = 8e-3;
  spec.mesh.growth_rate = 0.4;
  return spec;
}

// Faces (data lines) of every *SURFACE, by name.
std::map<std::string, std::size_t> surface_faces(const std::string& file)
{
  std::map<std::string, std::size_t> faces;
  for (const auto& [keyword, lines] : blocks(file))
    if (keyword.rfind("*SURFACE, NAME=", 0) == 0)
      faces[keyword.substr(15, keyword.find(',', 15) - 15)] = lines.size();
  return faces;
}

// Every part of the cycloid deck's surfaces is a non-empty piece, and the parts of a group are
// the group (each facet in exactly one part).
void check_cycloid_surface_parts(const std::map<std::string, std::size_t>& faces)
{
  const auto parts_of = [&faces](const std::string& prefix, unsigned int count)
  {
    std::size_t total = 0;
    for (unsigned int k = 0; k < count; ++k)
    {
      const std::size_t part = faces.at(prefix + std::to_string(k));
      EXPECT_GT(part, 0u) << prefix << k;
      total += part;
    }
    return total;
  };
  EXPECT_EQ(parts_of("ROLLER_", 20), faces.at("ROLLER_SURFACES"));
  EXPECT_EQ(parts_of("LOBES_", 20), faces.at("DISC_LOBES"));
  EXPECT_EQ(parts_of("PIN_", 8), faces.at("OUTPUT_PIN_SURFACES"));
  EXPECT_EQ(parts_of("HOLE_", 8), faces.at("OUTPUT_PIN_HOLES"));
}

// The load-case keywords of a deck: its *CLOAD lines, the first *BOUNDARY's lines, the *ELASTIC
// line, the pairs whose contact force CF is printed, and whether any *FRICTION is given.
struct LoadKeywords
{
  std::vector<std::string> cloads, supports;
  std::string elastic;
  std::vector<std::string> contact_prints;
  bool friction = false;
};

LoadKeywords load_keywords(const std::string& file)
{
  LoadKeywords k;
  for (const auto& [keyword, lines] : blocks(file))
  {
    if (keyword == "*CLOAD")
      k.cloads = lines;
    else if (keyword == "*BOUNDARY" && k.supports.empty())
      k.supports = lines;
    else if (keyword == "*ELASTIC")
      k.elastic = lines.at(0);
    k.friction = k.friction || keyword == "*FRICTION";
    if (keyword.rfind("*CONTACT PRINT, SLAVE=", 0) == 0 && lines.at(0) == "CF")
      k.contact_prints.push_back(keyword.substr(22));
  }
  return k;
}

// The deck of the cycloid scene: one contact pair per roller (its surface on the lobe faces
// nearest to it) and per output pin (on its hole), the parts splitting each boundary group
// exactly; the disc bore a rigid body about the disc centre with no torque (the bearing), the
// output-pin bores one rigid body about the ring centre carrying M_c, the roller pins fixed;
// plane stress through the plane-strain-equivalent constants; contact forces printed per pair.
TEST(AbaqusDeck, CycloidSceneWithOutputMember)
{
  const CycloidSceneSpec spec = coarse_cycloid_spec();
  SceneDeck deck;
  deck.info = write_cycloid_scene(spec, work_file("deck_cycloid.msh"));
  const double torque = 440.; // N·m, docs/references.md §4 M_c
  write_deck(deck, 2, cycloid_deck_spec(spec, deck.info, torque, 50.), "deck_cycloid");
  const std::size_t n = deck.mesh.nodes.size();

  std::vector<std::string> expected_pairs;
  for (unsigned int i = 0; i < 20; ++i)
    expected_pairs.push_back("ROLLER_" + std::to_string(i) + ", LOBES_" + std::to_string(i));
  for (unsigned int j = 0; j < 8; ++j)
    expected_pairs.push_back("PIN_" + std::to_string(j) + ", HOLE_" + std::to_string(j));
  EXPECT_EQ(contact_pairs(deck.file), expected_pairs);

  check_cycloid_surface_parts(surface_faces(deck.file));

  const auto [element_sets, rigid_bodies, node_lines] = deck_bodies(deck.file);
  const auto [cloads, supports, elastic, contact_prints, friction] = load_keywords(deck.file);
  EXPECT_EQ(element_sets, (std::set<std::string>{"DISC", "ROLLERS", "OUTPUT_PINS"}));
  const auto id = [](std::size_t k) { return std::to_string(k); };
  EXPECT_EQ(rigid_bodies,
            (std::set<std::string>{"*RIGID BODY, NSET=OUTPUT_PIN_BORES_NODES, REF NODE=" +
                                       id(2 * n + 1) + ", ROT NODE=" + id(2 * n + 2),
                                   "*RIGID BODY, NSET=DISC_BORE_NODES, REF NODE=" + id(2 * n + 3) +
                                       ", ROT NODE=" + id(2 * n + 4)}));
  EXPECT_EQ(node_lines.at("OUTPUT_REF"), id(2 * n + 1) + ", 0, 0, 0"); // the ring centre
  // The disc centre: e = 3 mm off the ring centre at crank angle 0 (docs/references.md §4).
  EXPECT_NEAR(deck.info.first_centre.norm(), 3e-3, 1e-12);
  std::istringstream bearing(node_lines.at("DISC_BEARING_REF"));
  double x = 0., y = 0.;
  char comma = 0;
  long node = 0;
  bearing >> node >> comma >> x >> comma >> y;
  EXPECT_NEAR(x, deck.info.first_centre.x(), 1e-12);
  EXPECT_NEAR(y, deck.info.first_centre.y(), 1e-12);
  // The torque on the output member only: the bearing is torque-free.
  EXPECT_EQ(cloads, std::vector<std::string>{"OUTPUT_ROT, 3, 440"});
  EXPECT_EQ(supports, (std::vector<std::string>{"ROLLER_PINS_NODES, 1, 3", "OUTPUT_REF, 1, 3",
                                                "OUTPUT_ROT, 1, 2", "DISC_BEARING_REF, 1, 3",
                                                "DISC_BEARING_ROT, 1, 2", "PLANE_STRAIN, 3, 3"}));
  // Plane stress of (210 GPa, 0.3) = plane strain of (E(1 + 2ν)/(1 + ν)², ν/(1 + ν)), exact.
  std::istringstream constants(elastic);
  double e = 0., nu = 0.;
  constants >> e >> comma >> nu;
  EXPECT_NEAR(e, 210e9 * 1.6 / 1.69, 1e-9 * e);
  EXPECT_NEAR(nu, 0.3 / 1.3, 1e-11);
  EXPECT_FALSE(friction); // frictionless, as cycloid-loads
  // The contact force CF of every pair is printed (ccx names the pair by SLAVE and MASTER).
  ASSERT_EQ(contact_prints.size(), expected_pairs.size());
  for (std::size_t k = 0; k < expected_pairs.size(); ++k)
  {
    const std::string& pair = expected_pairs[k];
    EXPECT_EQ(contact_prints[k],
              pair.substr(0, pair.find(',')) + ", MASTER=" + pair.substr(pair.find(", ") + 2));
  }
}

TEST(AbaqusDeck, CycloidDeckRejectsBadInput)
{
  CycloidSceneSpec spec = coarse_cycloid_spec();
  spec.output_pin_bodies = false;
  EXPECT_THROW(cycloid_deck_spec(spec, SceneInfo(), 440., 50.), InputError); // before any mesh
  spec.output_pin_bodies = true; // a zero torque loads nothing
  EXPECT_THROW(cycloid_deck_spec(spec, SceneInfo(), 0., 50.), InputError);
}
// A coarse Hertz cylinders scene (R1 = R2 = 10 mm, F' = 100 N/mm, 10 mm long; h_c = 0.02 mm,
// coarser than the scene's default a/10: ccx solves it in about a second), half-discs or annuli.
struct CylindersDeck : SceneDeck
{
  CylindersSceneSpec spec;
};

CylindersDeck cylinders_deck(const std::string& base, double bore_radius = 0.)
{
  CylindersDeck deck;
  deck.spec.bore_radius_1 = bore_radius;
  deck.spec.bore_radius_2 = bore_radius;
  deck.spec.mesh.contact_size = 0.02e-3;
  deck.spec.mesh.body_size = 1e-3;
  deck.spec.mesh.rim_size = 1e-3;
  deck.info = write_cylinders_scene(deck.spec, work_file(base + ".msh"));
  write_deck(deck, 2, cylinders_deck_spec(deck.spec, deck.info, 0.1, 50.), base);
  return deck;
}

// The cylinders' deck: both bodies, cylinder 2's arc (slave) on cylinder 1's, cylinder 1's flat
// face fixed, cylinder 2's flat face one rigid body about its centre (0, R2) that only moves
// along y: closed by a tenth of a²/R* in step 1, then pushed by F = F'·L = 1000 N; plane strain
// on every other node; Coulomb friction; the contact force printed.
TEST(AbaqusDeck, CylindersPushedByTheirRigidFlatFace)
{
  const CylindersDeck deck = cylinders_deck("deck_cylinders");
  const std::size_t n = deck.mesh.nodes.size();
  const auto [element_sets, rigid_bodies, node_lines] = deck_bodies(deck.file);
  std::vector<std::vector<std::string>> boundaries;
  std::vector<std::string> cloads, friction, contact_prints;
  for (const auto& [keyword, lines] : blocks(deck.file))
  {
    if (keyword.rfind("*BOUNDARY", 0) == 0)
      boundaries.push_back(lines);
    else if (keyword == "*CLOAD")
      cloads = lines;
    else if (keyword == "*FRICTION")
      friction = lines;
    else if (keyword.rfind("*CONTACT PRINT, SLAVE=", 0) == 0)
      contact_prints.push_back(keyword.substr(22) + " " + lines.at(0));
  }
  EXPECT_EQ(element_sets, (std::set<std::string>{"CYLINDER_1", "CYLINDER_2"}));
  EXPECT_EQ(contact_pairs(deck.file),
            std::vector<std::string>{"CYLINDER_2_SURFACE, CYLINDER_1_SURFACE"});
  const auto id = [](std::size_t k) { return std::to_string(k); };
  EXPECT_EQ(rigid_bodies,
            (std::set<std::string>{"*RIGID BODY, NSET=CYLINDER_2_FLAT_FACE_NODES, REF NODE=" +
                                   id(2 * n + 1) + ", ROT NODE=" + id(2 * n + 2)}));
  EXPECT_EQ(node_lines.at("UPPER_REF"), id(2 * n + 1) + ", 0, 0.01, 0"); // (0, R2)
  const std::vector<std::string> supports = {"CYLINDER_1_FLAT_FACE_NODES, 1, 3", "UPPER_REF, 1, 1",
                                             "UPPER_REF, 3, 3", "UPPER_ROT, 1, 3",
                                             "PLANE_STRAIN, 3, 3"};
  ASSERT_EQ(boundaries.size(), 3u); // both steps' supports and step 1's closing displacement
  EXPECT_EQ(boundaries[0], supports);
  EXPECT_EQ(boundaries[2], supports);
  // Step 1: u_y = −a²/(10 R*), a the scene's Hertz half-width, R* = 5 mm (exact arithmetic of
  // the deck's own formula; 12 printed digits).
  const double a = deck.info.contacts.at(0).hertz_half_width;
  ASSERT_EQ(boundaries[1].size(), 1u);
  EXPECT_EQ(boundaries[1][0].rfind("UPPER_REF, 2, 2, ", 0), 0u);
  EXPECT_NEAR(std::stod(boundaries[1][0].substr(17)), -0.1 * a * a / 5e-3, 1e-11 * a * a / 5e-3);
  EXPECT_EQ(cloads, std::vector<std::string>{"UPPER_REF, 2, -1000"}); // F' = 1e5 N/m, L = 10 mm
  ASSERT_EQ(friction.size(), 1u);
  EXPECT_EQ(friction[0].substr(0, 5), "0.1, ");
  EXPECT_EQ(contact_prints,
            std::vector<std::string>{"CYLINDER_2_SURFACE, MASTER=CYLINDER_1_SURFACE CF"});

  // With bores the bores carry the support and the load (annuli).
  const CylindersDeck annuli = cylinders_deck("deck_annuli", 4e-3);
  std::set<std::string> annulus_bodies;
  std::string first_support;
  for (const auto& [keyword, lines] : blocks(annuli.file))
    if (keyword.rfind("*RIGID BODY", 0) == 0)
      annulus_bodies.insert(keyword.substr(0, keyword.find(',', 12)));
    else if (keyword == "*BOUNDARY" && first_support.empty())
      first_support = lines.at(0);
  EXPECT_EQ(first_support, "CYLINDER_1_BORE_NODES, 1, 3");
  EXPECT_EQ(annulus_bodies, std::set<std::string>{"*RIGID BODY, NSET=CYLINDER_2_BORE_NODES"});
}

// ccx solves the cylinders' deck as written: the contact carries the applied 1000 N (its printed
// total contact force; ccx stops its Newton iteration at 0.5 % of the mean force, *CONTROLS,
// hence 1 %), and the flat face moves down by more than the closing displacement and by about
// the approach of two cylinders under line load, per cylinder the classical approach of its
// centre F'(1 − ν²)/(πE)·(2 ln(4R/a) − 1) (Johnson 1985 ch. 5) = 1.6 µm, 3.2 µm for both (the
// flat-face support is not Johnson's: measured 2026-12-01 −3.4 % (the default-size deck gives
// 3.09 µm, docs/calculix.md), held to ±10 %, three times that; it was ±30 %). Skipped without ccx.
TEST(AbaqusDeck, CalculixPushesTheCylinders)
{
  if (std::system("command -v ccx > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "ccx is not installed";
  const CylindersDeck deck = cylinders_deck("deck_cylinders_ccx");
  ASSERT_EQ(run_calculix(deck.file), 0);
  const std::string job = deck.file.substr(0, deck.file.size() - 4);
  std::ifstream dat(job + ".dat");
  std::string line, block;
  double approach = 0., contact_force = 0.;
  while (std::getline(dat, line))
  {
    if (line.find(" for set ") != std::string::npos ||
        line.find("total surface force") != std::string::npos)
      block = line;
    std::istringstream values(line);
    if (block.find("displacements") != std::string::npos &&
        block.find("UPPER_REF") != std::string::npos)
    {
      long node = 0;
      double ux = 0., uy = 0.;
      if (values >> node >> ux >> uy)
        approach = -uy;
    }
    else if (block.find("total surface force") != std::string::npos)
    {
      double fx = 0., fy = 0.;
      if (values >> fx >> fy)
      {
        contact_force = fy; // the first line of numbers: the force (then the moment, ...)
        block.clear();
      }
    }
  }
  const double a = deck.info.contacts.at(0).hertz_half_width;
  const double e = deck.spec.young_modulus, nu = deck.spec.poisson_ratio;
  const double johnson =
      2. * 1e5 * (1. - nu * nu) / (M_PI * e) * (2. * std::log(4. * deck.spec.radius_1 / a) - 1.);
  std::cout << "ccx contact force " << contact_force << " N; approach " << approach * 1e6
            << " um against Johnson's " << johnson * 1e6 << " um ("
            << 100. * (approach / johnson - 1.) << " %)\n";
  EXPECT_NEAR(contact_force, 1000., 10.);
  EXPECT_GT(approach, 0.1 * a * a / 5e-3);
  EXPECT_NEAR(approach, johnson, 0.1 * johnson);
}
} // namespace
