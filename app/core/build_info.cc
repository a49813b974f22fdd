// The version data alone in a light file: gearstiff_revision.h changes with every commit, and
// only this file includes it (no deal.II header beyond its configuration macros).
#include "app/core/build_info.h"

#include "gearstiff_revision.h"

#include <Eigen/Core>
#include <deal.II/base/config.h>
#include <gmsh.h>
#include <petscversion.h>

namespace gearstiff::app
{
std::string version()
{
  return GEARSTIFF_VERSION;
}

std::string source_revision()
{
  return GEARSTIFF_SOURCE_REVISION;
}

std::vector<std::pair<std::string, std::string>> library_versions()
{
  const auto dotted = [](int major, int minor, int patch)
  { return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch); };
  return {{"deal.II", DEAL_II_PACKAGE_VERSION},
          {"PETSc", dotted(PETSC_VERSION_MAJOR, PETSC_VERSION_MINOR, PETSC_VERSION_SUBMINOR)},
          {"gmsh", GMSH_API_VERSION},
          {"Eigen", dotted(EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)}};
}

std::string version_line()
{
  return "gearstiff " + version() + " (revision " + source_revision() + ")";
}

std::string library_line()
{
  std::string line;
  for (const auto& [name, library_version] : library_versions())
    line += (line.empty() ? "" : ", ") + name + " " + library_version;
  return line;
}
} // namespace gearstiff::app
