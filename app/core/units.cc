#include "app/core/units.h"

#include "errors/errors.h"

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

bool read_whole_number(const std::string& text, double& number)
{
  std::size_t used = 0;
  try
  {
    number = std::stod(text, &used);
  }
  catch (const std::exception&)
  {
    return false;
  }
  return text.find_first_not_of(" \t", used) == std::string::npos;
}

bool read_length_or_auto(const std::string& text, const std::string& parameter,
                         const std::string& what, double& value)
{
  if (text == "auto")
    return true;
  double number = -1.;
  if (!read_whole_number(text, number) || !(number >= 0.))
    throw InputError(parameter,
                     "'" + shortened(text) + "' is neither a " + what + " >= 0 [mm] nor auto");
  value = number * mm;
  return false;
}
std::string table_unit(const std::string& unit)
{
  static const std::pair<const char*, const char*> ascii[] = {
      {"µ", "u"}, {"·", "*"}, {"²", "^2"}, {"³", "^3"}, {"°", "deg"}};
  std::string text = unit;
  for (const auto& [symbol, replacement] : ascii)
    for (auto at = text.find(symbol); at != std::string::npos; at = text.find(symbol, at))
    {
      text.replace(at, std::string(symbol).size(), replacement);
      at += std::string(replacement).size();
    }
  return text;
}
} // namespace gearstiff::app
