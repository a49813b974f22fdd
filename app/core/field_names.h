// The naming contract of errors: library code names its own fields in an InputError
// ("pinion.tip_diameter", "train.output", "simulation.time_step": kinematics/fields.h,
// dynamics/fields.h, geometry::scene_field); app/ maps each field to the parameter path the user
// wrote ("Gear pair/Pinion/tip diameter"), so the user still reads one line naming the
// parameter of the .prm or .json file (the same section/key spelling in both).
//
// One table per parameter family (gear pair, train, simulation, ...), each in the wing that
// declares the family's parameters and registered there by a static FieldNamesRegistration;
// run_loaded_command maps every InputError a command throws through all of them. A field whose
// parameter differs between commands (the gear-pair scene's fields: "Gear pair scene/..." in
// `mesh`, "Stiffness/..." in `stiffness`) is mapped at the call with with_parameter_names
// instead, before the registered tables see it.
#pragma once

#include "errors/errors.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace gearstiff::app
{
// Library field -> parameter path of one family or one command.
using ParameterNames = std::map<std::string, std::string>;

// Runs `work`; an InputError naming a field of `names` is thrown again under its parameter
// path, any other error passes unchanged.
template <typename Work>
auto with_parameter_names(const ParameterNames& names, Work&& work) -> decltype(work())
{
  try
  {
    return work();
  }
  catch (const InputError& e)
  {
    const auto found = names.find(e.parameter());
    if (found == names.end())
      throw;
    throw InputError(found->second, e.reason());
  }
}

// The table of one family: the field field_of(member) of each member -> `section`/key, the
// key the member's words ("time_step" -> "time step") unless `keys` gives it ("hht_alpha" ->
// "HHT alpha").
ParameterNames field_family(const std::string& section, const std::vector<std::string>& members,
                            const std::function<std::string(const std::string&)>& field_of,
                            const ParameterNames& keys = {});

// A family's table, registered once at start-up (static object in the family's wing file).
struct FieldNamesRegistration
{
  FieldNamesRegistration(const std::string& family, std::function<ParameterNames()> table);
};

// Every registered family's table: family -> its table (built on first use).
const std::map<std::string, ParameterNames>& registered_field_names();

// The parameter path of library field `field` in the registered tables; `field` itself when no
// table has it (a name that already is a parameter path, or a field mapped at its call).
std::string parameter_of_field(const std::string& field);

// Runs `work` with every InputError's field mapped by the registered tables.
template <typename Work>
auto with_registered_field_names(Work&& work) -> decltype(work())
{
  try
  {
    return work();
  }
  catch (const InputError& e)
  {
    const std::string parameter = parameter_of_field(e.parameter());
    if (parameter == e.parameter())
      throw;
    throw InputError(parameter, e.reason());
  }
}
} // namespace gearstiff::app
