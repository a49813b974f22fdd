#include "app/units.h"

namespace gearstiff::app
{
std::string shortened(const std::string& text, const unsigned int length)
{
  if (text.size() <= length)
    return text;
  // Cut at a character boundary of UTF-8 (never inside a multi-byte sequence).
  std::size_t end = length;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80)
    --end;
  return text.substr(0, end) + "… (" + std::to_string(text.size()) + " characters)";
}
} // namespace gearstiff::app
