#include "app/core/renamed_parameters.h"

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <sstream>

namespace gearstiff::app
{
namespace
{
std::string trimmed(const std::string& text)
{
  const auto begin = text.find_first_not_of(" \t\r");
  if (begin == std::string::npos)
    return "";
  return text.substr(begin, text.find_last_not_of(" \t\r") - begin + 1);
}

std::string last_name(const std::string& path)
{
  return path.substr(path.rfind('/') + 1);
}

// `tree` with its keys under their current names (same order); `sections` is the path of `tree`.
boost::property_tree::ptree renamed_json_keys(const boost::property_tree::ptree& tree,
                                              const std::string& sections,
                                              std::vector<std::string>& met)
{
  boost::property_tree::ptree renamed(tree.data());
  for (const auto& [name, child] : tree)
  {
    const std::string path = sections.empty() ? name : sections + "/" + name;
    const std::string current = current_parameter_path(path);
    if (current != path)
      met.push_back(path);
    renamed.push_back(
        {current == path ? name : last_name(current), renamed_json_keys(child, path, met)});
  }
  return renamed;
}
} // namespace

const std::vector<RenamedParameter>& renamed_parameters()
{
  // One name and one range for every Coulomb friction coefficient (app/core/parameter_patterns.h).
  static const std::vector<RenamedParameter> renamed = {
      {"Train/tooth friction coefficient", "Train/friction coefficient",
       "the release after 2026-12"},
      // One name for Poisson's ratio (the other commands' "Poisson's ratio").
      {"Bodies/Poisson ratios", "Bodies/Poisson's ratios", "the release after 2026-12"},
  };
  return renamed;
}

std::string current_parameter_path(const std::string& path)
{
  for (const RenamedParameter& renamed : renamed_parameters())
    if (path == renamed.old_path)
      return renamed.new_path;
  return path;
}

std::string renamed_note(const std::string& where, const std::string& old_path)
{
  for (const RenamedParameter& renamed : renamed_parameters())
    if (old_path == renamed.old_path)
      return "gearstiff: note: " + where + ": '" + old_path + "' is now '" + renamed.new_path +
             "' (the old name is read as the new one until " + renamed.until + ")";
  return "";
}

std::string with_current_names(const std::string& text, bool json, std::vector<std::string>& met)
{
  if (json)
  {
    std::istringstream in(text);
    boost::property_tree::ptree tree;
    try
    {
      boost::property_tree::read_json(in, tree);
    }
    catch (const std::exception&)
    {
      return text; // not valid JSON: the checks that follow say where
    }
    const std::size_t before = met.size();
    const boost::property_tree::ptree renamed = renamed_json_keys(tree, "", met);
    if (met.size() == before)
      return text;
    std::ostringstream out;
    boost::property_tree::write_json(out, renamed);
    return out.str();
  }
  std::istringstream in(text);
  std::ostringstream out;
  std::vector<std::string> sections;
  for (std::string line; std::getline(in, line);)
  {
    const std::string stripped = trimmed(line.substr(0, line.find('#')));
    if (stripped.rfind("subsection ", 0) == 0)
      sections.push_back(trimmed(stripped.substr(11)));
    else if (stripped == "end" && !sections.empty())
      sections.pop_back();
    else if (stripped.rfind("set ", 0) == 0 && stripped.find('=') != std::string::npos)
    {
      const std::string key = trimmed(stripped.substr(4, stripped.find('=') - 4));
      std::string path;
      for (const std::string& section : sections)
        path += section + "/";
      path += key;
      const std::string current = current_parameter_path(path);
      if (current != path)
      {
        met.push_back(path);
        const std::size_t at = line.find(key, line.find("set") + 3);
        line.replace(at, key.size(), last_name(current));
      }
    }
    out << line << '\n';
  }
  return out.str();
}
} // namespace gearstiff::app
