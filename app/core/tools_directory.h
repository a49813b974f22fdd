// Where the chart scripts are: a header of its own so that tools_directory.cc, the one app file
// compiled with an absolute path, includes no deal.II header and recompiles in a second.
#pragma once

#include <string>

namespace gearstiff::app
{
// Directory holding tools/ (plot scripts), set at configure time; overridable by
// GEARSTIFF_TOOLS_DIR in the environment.
std::string tools_directory();
} // namespace gearstiff::app
