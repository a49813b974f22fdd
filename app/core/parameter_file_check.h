// Checks of a parameter file that deal.II's reader reports in its own words or not at all.
#pragma once

#include <string>

namespace gearstiff::app
{
// A JSON parameter file whose values are arrays or objects where a value belongs: InputError
// naming the key ("Gear pair/Pinion/teeth") — deal.II said "entry <> you have not yet declared".
// Files that are not JSON (or not valid JSON) are left to deal.II's reader.
void check_json_parameter_file(const std::string& file);

// The JSON text with its names as deal.II 9.4's JSON reader takes them. It reads names mangled
// ("_XX" a hex-coded character, its XML reader's rule) but its writer, the parameters.json next
// to every result, writes them plain: a name that holds '_' (ISO 6336/C_M) read back was refused
// as "You can't ask for entry <C". So each '_' of a name becomes "_5f" (the names are the plain
// ones gearstiff's checks have accepted); values are untouched. Text that is not valid JSON is
// returned as it is, for deal.II's reader to say where.
std::string json_names_for_deal_ii(const std::string& text);
} // namespace gearstiff::app
