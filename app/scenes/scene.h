// Scene types of `gearstiff mesh`, registered by name as commands are (app/core/command.h): each
// type supplies its parameters (declare/parse), its mesh, its CalculiX/Abaqus deck and the values
// it reports beyond the common ones, in its own app/scene_<type>.cc. Adding a drive type is adding
// files: geometry/scene_<type>.{h,cc} (the geometry and mesh, SI) and app/scene_<type>.cc (the
// parameters and the registration); `Scene/type` lists every registered name.
#pragma once

#include "app/core/report.h"
#include "geometry/abaqus_deck.h"
#include "geometry/scene_common.h"

#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <map>
#include <memory>
#include <string>

namespace gearstiff::app
{
// The deck's own choices, common to every scene (subsection Abaqus deck).
struct DeckOptions
{
  geometry::Element2D element_2d = geometry::Element2D::slice;
  double friction = 0.;       // -, Coulomb μ between the contact surfaces (scenes with friction)
  double penalty_factor = 0.; // -, K = factor · E / h_c
  double output_torque = 0.;  // N·m, scenes with an output member (cycloid: M_c)
};

// One parsed scene: everything it needs is known before gmsh runs.
class Scene
{
public:
  virtual ~Scene() = default;
  // Called before write_mesh when a deck will be written (a deck may need bodies the plain mesh
  // leaves out, as the cycloid's output pins).
  virtual void prepare_for_deck() {}
  // Meshes the scene into `path` (.msh); InputError naming the parameter for an impossible one.
  virtual geometry::SceneInfo write_mesh(const std::string& path) = 0;
  // The deck of the scene write_mesh wrote.
  virtual geometry::AbaqusDeckSpec deck_spec(const geometry::SceneInfo& info,
                                             const DeckOptions& options) const = 0;
  // Values beyond the ones every scene reports (ids, sizes, cells, contacts table).
  virtual void report(const geometry::SceneInfo& /*info*/, Report& /*report*/) const {}
};

// A scene whose mesh and deck are functions of its geometry spec alone
// (geometry/scene_<type>.h): `mesh` writes the .msh, `deck` gives the deck of what it wrote.
template <typename Spec>
class SpecScene : public Scene
{
public:
  using MeshFunction = geometry::SceneInfo (*)(const Spec&, const std::string&);
  using DeckFunction = geometry::AbaqusDeckSpec (*)(const Spec&, const geometry::SceneInfo&,
                                                    const DeckOptions&);
  SpecScene(const Spec& spec, MeshFunction mesh, DeckFunction deck)
      : spec(spec), mesh(mesh), deck(deck)
  {
  }
  geometry::SceneInfo write_mesh(const std::string& path) override { return mesh(spec, path); }
  geometry::AbaqusDeckSpec deck_spec(const geometry::SceneInfo& info,
                                     const DeckOptions& options) const override
  {
    return deck(spec, info, options);
  }

protected:
  Spec spec;

private:
  MeshFunction mesh;
  DeckFunction deck;
};

struct SceneType
{
  std::string name;        // the Scene/type value
  std::string description; // for the Scene/type documentation: what it meshes, which sections
  // Declares the scene's own subsections (Mesh and Abaqus deck are common: mesh_command.cc).
  std::function<void(dealii::ParameterHandler&)> declare_parameters;
  // Parses them (InputError naming the parameter) into a scene ready to mesh.
  std::function<std::unique_ptr<Scene>(dealii::ParameterHandler&)> parse;
};

// Scene types by name; `default_scene_type` is the one `Scene/type` starts with.
std::map<std::string, SceneType>& scene_registry();
inline const std::string default_scene_type = "gear pair";

struct SceneRegistration
{
  explicit SceneRegistration(SceneType type);
};
} // namespace gearstiff::app
