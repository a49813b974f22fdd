// The one parameter-table type of app/ (issue 45): a section whose entries are free text
// (Patterns::Anything) that the section's own parser checks — the Train lists, the tooth
// modification and fault entries — is a table of TextEntry, declared and read by one loop each.
#pragma once

#include <deal.II/base/parameter_handler.h>
#include <map>
#include <string>
#include <vector>

namespace gearstiff::app
{
// A free-text entry (Patterns::Anything) of a parameter table.
struct TextEntry
{
  const char* name;
  const char* default_value;
  const char* documentation; // with the unit the file writes the value in
};
// Declares every entry in the current subsection.
void declare_text_entries(dealii::ParameterHandler& prm, const std::vector<TextEntry>& entries);
// Every entry's value of the current subsection as written, without leading and trailing blanks
// and tabs, into `text` (name → value).
void read_text_entries(dealii::ParameterHandler& prm, const std::vector<TextEntry>& entries,
                       std::map<std::string, std::string>& text);
} // namespace gearstiff::app
