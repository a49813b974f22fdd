// The names the contact library gives its own fields in an InputError: "contact.<member>" of
// ContactParameters (contact/contact_problem.h), as geometry/fields.h does for geometry. Library
// code names its fields, never the parameter paths users write ("Contact/Iteration solves"):
// app/scenes/fe_contact_parameters.cc maps every field of the list to its parameter, and
// tools/house_counts.py fails when contact/ spells a user parameter path.
#pragma once

#include <string>
#include <vector>

namespace gearstiff::contact::field
{
// A member of ContactParameters: "contact.iteration_solves".
inline std::string contact(const std::string& member)
{
  return "contact." + member;
}
inline const std::vector<std::string>& contact_fields()
{
  static const std::vector<std::string> members = {"iteration_solves", "overlap_tolerance"};
  return members;
}
} // namespace gearstiff::contact::field
