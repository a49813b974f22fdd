#include "app/dynamics/train_parameter_entries.h"

#include "errors/errors.h"

#include <cmath>
#include <sstream>

namespace gearstiff::app
{
namespace
{
std::string trimmed(std::string text)
{
  text.erase(0, text.find_first_not_of(" \t"));
  text.erase(text.find_last_not_of(" \t") + 1);
  return text;
}

// The numbers of `text`, each a whole word; false at the first that is not a finite number.
bool read_numbers(const std::string& text, std::vector<double>& numbers)
{
  std::istringstream in(text);
  std::string word;
  while (in >> word)
  {
    try
    {
      std::size_t used = 0;
      numbers.push_back(std::stod(word, &used));
      if (used != word.size() || !std::isfinite(numbers.back()))
        return false;
    }
    catch (const std::exception&)
    {
      return false;
    }
  }
  return true;
}
} // namespace

std::vector<std::pair<std::string, std::vector<double>>>
parse_named_numbers(const std::string& text, unsigned int count, const std::string& parameter,
                    const std::string& units, NumberSign sign)
{
  std::vector<std::pair<std::string, std::vector<double>>> entries_read;
  std::istringstream in(text);
  std::string entry;
  while (std::getline(in, entry, ','))
  {
    if (trimmed(entry).empty())
      continue;
    const auto colon = entry.find(':');
    const std::string name = colon == std::string::npos ? "" : trimmed(entry.substr(0, colon));
    std::vector<double> numbers;
    bool good = !name.empty() && read_numbers(entry.substr(colon + 1), numbers) &&
                !numbers.empty() && (count == 0 || numbers.size() == count);
    for (const double v : numbers)
      good = good && (sign == NumberSign::any || v >= 0.);
    if (!good)
      throw InputError(parameter,
                       "entry '" + trimmed(entry) + "' is not 'name: " + units + "'" +
                           (sign == NumberSign::any ? "" : " with non-negative numbers"));
    // A name twice ("7: 1e6 10, 7: 1e5 1") would keep one entry, or add both, silently.
    for (const auto& [earlier, values] : entries_read)
      if (earlier == name)
        throw InputError(parameter, "entry '" + name + "' is given twice");
    entries_read.emplace_back(name, numbers);
  }
  return entries_read;
}
} // namespace gearstiff::app
