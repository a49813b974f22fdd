#include "app/core/parameter_file_check.h"

#include "app/core/units.h"
#include "errors/errors.h"

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cctype>
#include <sstream>

namespace gearstiff::app
{
namespace
{
using boost::property_tree::ptree;

// deal.II's JSON keys encode characters as _XX (hex): "Gear_20pair" is "Gear pair".
std::string unmangled(const std::string& key)
{
  std::string name;
  for (std::size_t i = 0; i < key.size(); ++i)
    if (key[i] == '_' && i + 2 < key.size() &&
        std::isxdigit(static_cast<unsigned char>(key[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(key[i + 2])))
    {
      name += static_cast<char>(std::stoi(key.substr(i + 1, 2), nullptr, 16));
      i += 2;
    }
    else
      name += key[i];
  return name;
}

void check_node(const ptree& node, const std::string& path)
{
  for (const auto& [key, child] : node)
  {
    const std::string name = path.empty() ? unmangled(key) : path + "/" + unmangled(key);
    if (key.empty())
      throw InputError(path.empty() ? "parameter file" : path,
                       "a JSON array is not a parameter value: give the value as one string "
                       "(e.g. \"s: 20, p: 10\")");
    // deal.II's JSON form: a subsection is an object, an entry an object with a "value" (the
    // long form) or a string.
    if (!child.empty() && child.count("value") == 0)
      check_node(child, name);
    else if (const auto value = child.get_child_optional("value"); value && !value->empty())
      throw InputError(name, "a JSON array or object is not a parameter value: give the value "
                             "as one string");
  }
}
} // namespace

void check_json_parameter_file(const std::string& file)
{
  if (file.size() < 5 || file.compare(file.size() - 5, 5, ".json") != 0)
    return;
  ptree tree;
  try
  {
    boost::property_tree::read_json(file, tree);
  }
  catch (const boost::property_tree::json_parser_error& e)
  {
    // deal.II's reader wrapped this in "Boost aborted with the following assert message".
    throw InputError(shortened(file),
                     "is not JSON (line " + std::to_string(e.line()) + ": " + e.message() + ")");
  }
  catch (const std::exception&)
  {
    return; // deal.II's reader reports what it finds
  }
  // A run's result summary (summary.json, or what --json printed) read as parameters: told as
  // such, not as its first array ("tables/stiffness_sweep/columns: a JSON array is not a
  // parameter value", found 2026-12-06 giving a sweep's summary.json to `dynamics`).
  if (const auto command = tree.get_optional<std::string>("command");
      command && (tree.count("values") > 0 || tree.count("tables") > 0))
    throw InputError(shortened(file),
                     "is the result summary of `gearstiff " + shortened(*command) +
                         "`, not a parameter file: that run's parameters are the "
                         "parameters.prm of its -o folder (a sweep's k(x) reaches `gearstiff "
                         "dynamics` as that folder's stiffness_table.prm, or through Train mesh "
                         "n/stiffness file)");
  check_node(tree, "");
}
namespace
{
std::string mangled_underscores(const std::string& name)
{
  std::string out;
  for (const char c : name)
    out += c == '_' ? std::string("_5f") : std::string(1, c);
  return out;
}

ptree with_mangled_names(const ptree& tree)
{
  ptree out(tree.data());
  for (const auto& [name, child] : tree)
    out.push_back({mangled_underscores(name), with_mangled_names(child)});
  return out;
}
} // namespace

std::string json_names_for_deal_ii(const std::string& text)
{
  ptree tree;
  try
  {
    std::istringstream in(text);
    boost::property_tree::read_json(in, tree);
  }
  catch (const boost::property_tree::json_parser_error&)
  {
    return text;
  }
  std::ostringstream out;
  boost::property_tree::write_json(out, with_mangled_names(tree));
  return out.str();
}
} // namespace gearstiff::app
