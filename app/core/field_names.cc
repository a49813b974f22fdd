#include "app/core/field_names.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace gearstiff::app
{
namespace
{
std::map<std::string, std::function<ParameterNames()>>& registered_tables()
{
  static std::map<std::string, std::function<ParameterNames()>> tables;
  return tables;
}
} // namespace

FieldNamesRegistration::FieldNamesRegistration(const std::string& family,
                                               std::function<ParameterNames()> table)
{
  if (!registered_tables().emplace(family, std::move(table)).second)
    throw std::logic_error("field-name family '" + family + "' registered twice");
}

ParameterNames field_family(const std::string& section, const std::vector<std::string>& members,
                            const std::function<std::string(const std::string&)>& field_of,
                            const ParameterNames& keys)
{
  ParameterNames names;
  for (const std::string& member : members)
  {
    std::string key = member;
    std::replace(key.begin(), key.end(), '_', ' ');
    if (const auto found = keys.find(member); found != keys.end())
      key = found->second;
    names[field_of(member)] = section + "/" + key;
  }
  return names;
}

const std::map<std::string, ParameterNames>& registered_field_names()
{
  // Built at first use, after every static registration: the tables read the libraries' field
  // lists, which are themselves built on first use.
  static const std::map<std::string, ParameterNames> tables = []
  {
    std::map<std::string, ParameterNames> built;
    for (const auto& [family, table] : registered_tables())
      built.emplace(family, table());
    return built;
  }();
  return tables;
}

std::string parameter_of_field(const std::string& field)
{
  for (const auto& [family, names] : registered_field_names())
    if (const auto found = names.find(field); found != names.end())
      return found->second;
  return field;
}
} // namespace gearstiff::app
