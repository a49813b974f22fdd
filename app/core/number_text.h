// One number written in a parameter's text, read the same way by every list and entry of app/
// that is not a Patterns::Double (modification amounts, torque lists, 'name: v ...' lists).
#pragma once

#include <exception>
#include <optional>
#include <string>

namespace gearstiff::app
{
// `text` as one number (std::stod's syntax, blanks and tabs around it allowed); nullopt when it
// is not one or has anything after it. "inf" and "nan" are numbers here: callers that need a
// finite value check it, so each keeps its own message.
inline std::optional<double> number_in(const std::string& text)
{
  std::size_t used = 0;
  double value = 0.;
  try
  {
    value = std::stod(text, &used);
  }
  catch (const std::exception&)
  {
    return std::nullopt;
  }
  if (used == 0 || text.find_first_not_of(" \t", used) != std::string::npos)
    return std::nullopt;
  return value;
}
} // namespace gearstiff::app
