// tools_directory() alone in its file: the only app source compiled with an absolute path
// (GEARSTIFF_TOOLS_DIR, set in app/CMakeLists.txt for this file only), so a clone in another
// folder recompiles this small file and takes every other app object from ccache.
#include "app/core/tools_directory.h"

#include <cstdlib>

namespace gearstiff::app
{
std::string tools_directory()
{
  if (const char* dir = std::getenv("GEARSTIFF_TOOLS_DIR"))
    return dir;
  return GEARSTIFF_TOOLS_DIR;
}
} // namespace gearstiff::app
