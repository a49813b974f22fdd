#include "app/units.h"

#include <sstream>

namespace gearstiff::app
{
std::string format_number(double value, int precision)
{
  std::ostringstream s;
  s.precision(precision);
  s << value;
  return s.str();
}
} // namespace gearstiff::app
