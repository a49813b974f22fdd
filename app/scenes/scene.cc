#include "app/scenes/scene.h"

#include "errors/errors.h"

namespace gearstiff::app
{
std::map<std::string, SceneType>& scene_registry()
{
  static std::map<std::string, SceneType> registry;
  return registry;
}

SceneRegistration::SceneRegistration(SceneType type)
{
  const std::string name = type.name;
  if (!scene_registry().emplace(name, std::move(type)).second)
    throw std::logic_error("scene type registered twice: " + name);
}
} // namespace gearstiff::app
