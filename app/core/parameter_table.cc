#include "app/core/parameter_table.h"

namespace gearstiff::app
{
void declare_text_entries(dealii::ParameterHandler& prm, const std::vector<TextEntry>& entries)
{
  for (const TextEntry& entry : entries)
    prm.declare_entry(entry.name, entry.default_value, dealii::Patterns::Anything(),
                      entry.documentation);
}

void read_text_entries(dealii::ParameterHandler& prm, const std::vector<TextEntry>& entries,
                       std::map<std::string, std::string>& text)
{
  for (const TextEntry& entry : entries)
  {
    const std::string value = prm.get(entry.name);
    const auto first = value.find_first_not_of(" \t");
    text[entry.name] = first == std::string::npos
                           ? ""
                           : value.substr(first, value.find_last_not_of(" \t") - first + 1);
  }
}
} // namespace gearstiff::app
