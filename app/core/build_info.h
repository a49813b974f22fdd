// What built this gearstiff: its version, the source revision and the libraries it was compiled
// against — printed by `gearstiff --version` and written into every summary.json (and the
// Python result's "gearstiff"), so a result file says which code produced it.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace gearstiff::app
{
// The project's version (CMake's PROJECT_VERSION), e.g. "0.1.0".
std::string version();
// `git describe --always --dirty` of the source tree at build time ("unknown" outside git).
std::string source_revision();
// The libraries compiled against, name and version: deal.II, PETSc, gmsh, Eigen.
std::vector<std::pair<std::string, std::string>> library_versions();
// "gearstiff 0.1.0 (revision abc)": the line `--version` starts with and parameters.prm names.
std::string version_line();
// "deal.II 9.4.1, PETSc 3.18.5, gmsh 4.8.0, Eigen 3.4.0".
std::string library_line();
} // namespace gearstiff::app
