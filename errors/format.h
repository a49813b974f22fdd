// Numbers in the text of messages (InputError and SolverFailure reasons, progress lines, the
// numbers the commands write into parameter files and plot arguments). One definition, so that
// every module words a number the same way.
#pragma once

#include <sstream>
#include <string>

namespace gearstiff
{
// `value` with `precision` significant digits, in the default notation of std::ostream.
inline std::string format_number(double value, int precision)
{
  std::ostringstream s;
  s.precision(precision);
  s << value;
  return s.str();
}

// A length given in m, as the user writes it: "12.5 mm" (6 significant digits).
inline std::string format_mm(double length)
{
  return format_number(length * 1e3, 6) + " mm";
}
} // namespace gearstiff
