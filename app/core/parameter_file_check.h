// Checks of a parameter file that deal.II's reader reports in its own words or not at all.
#pragma once

#include <string>

namespace gearstiff::app
{
// A JSON parameter file whose values are arrays or objects where a value belongs: InputError
// naming the key ("Gear pair/Pinion/teeth") — deal.II said "entry <> you have not yet declared".
// Files that are not JSON (or not valid JSON) are left to deal.II's reader.
void check_json_parameter_file(const std::string& file);
} // namespace gearstiff::app
