#include "app/core/parameter_names.h"

#include "errors/errors.h"

#include <algorithm>
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cctype>
#include <climits>
#include <deal.II/base/patterns.h>
#include <fstream>
#include <memory>
#include <regex>
#include <sstream>

namespace gearstiff::app
{
namespace
{
DeclaredSection from_tree(const boost::property_tree::ptree& tree)
{
  DeclaredSection section;
  for (const auto& [name, child] : tree)
    if (child.empty())
      section.entries.insert(name);
    else
      section.sections.emplace(name, from_tree(child));
  return section;
}

std::string lower(std::string text)
{
  for (char& c : text)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::size_t edit_distance(const std::string& a, const std::string& b)
{
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
  {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
    {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string joined_path(const std::vector<std::string>& sections, std::size_t count)
{
  std::string path;
  for (std::size_t i = 0; i < count; ++i)
    path += (i == 0 ? "" : "/") + sections[i];
  return path;
}

// "nearest: 'teeth', 'tip diameter'", or the names declared there when none is near.
std::string suggestion(const std::string& name, const std::vector<std::string>& candidates)
{
  if (candidates.empty())
    return "none is declared there";
  const std::vector<std::string> near = nearest_names(name, candidates);
  const std::vector<std::string>& listed = near.empty() ? candidates : near;
  std::string text = near.empty() ? "declared there: " : "nearest: ";
  for (std::size_t i = 0; i < listed.size() && i < 8; ++i)
    text += (i == 0 ? "'" : ", '") + listed[i] + "'";
  if (near.empty() && listed.size() > 8)
    text += ", ... (--print-parameters lists them all)";
  return text;
}

// The reason a name is not declared, or "" when it is. `key` empty: only the sections.
std::string missing_reason(const DeclaredSection& declared,
                           const std::vector<std::string>& sections, const std::string& key)
{
  const DeclaredSection* current = &declared;
  for (std::size_t i = 0; i < sections.size(); ++i)
  {
    const auto found = current->sections.find(sections[i]);
    if (found == current->sections.end())
    {
      std::vector<std::string> names;
      for (const auto& [name, section] : current->sections)
        names.push_back(name);
      return "no subsection '" + sections[i] + "' " +
             (i == 0 ? std::string("at the top level") : "in '" + joined_path(sections, i) + "'") +
             "; " + suggestion(sections[i], names);
    }
    current = &found->second;
  }
  if (key.empty() || current->entries.count(key) > 0)
    return "";
  std::vector<std::string> names(current->entries.begin(), current->entries.end());
  std::vector<std::string> subsections;
  for (const auto& [name, section] : current->sections)
    subsections.push_back(name);
  const std::string where = sections.empty()
                                ? std::string("the top level")
                                : "section '" + joined_path(sections, sections.size()) + "'";
  if (current->sections.count(key) > 0)
    return "'" + key + "' is a subsection of " + where +
           ", not a parameter: name an entry inside it";
  return where + " has no parameter '" + key + "'; " + suggestion(key, names);
}

std::string trimmed(const std::string& text)
{
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos)
    return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

// For an unknown subsection (the last of `sections`) that is declared one level further out:
// the `end` of the subsection opened before it is probably missing. "" otherwise.
std::string unclosed_hint(const DeclaredSection& declared, const std::vector<std::string>& sections,
                          const std::vector<unsigned int>& opened_at)
{
  if (sections.size() < 2)
    return "";
  std::vector<std::string> outer(sections.begin(), sections.end() - 2);
  outer.push_back(sections.back());
  if (!missing_reason(declared, outer, "").empty())
    return "";
  return " (is the `end` of subsection '" + sections[sections.size() - 2] + "', opened at line " +
         std::to_string(opened_at[opened_at.size() - 2]) + ", missing?)";
}

// Whether `sections`/`key` is declared by another command (then listed as ignored); `key` empty:
// only the sections.
bool elsewhere(OtherCommandNames* others, const std::vector<std::string>& sections,
               const std::string& key)
{
  if (others == nullptr || !missing_reason(others->declared, sections, key).empty())
    return false;
  if (!key.empty())
    others->ignored.push_back(joined_path(sections, sections.size()) +
                              (sections.empty() ? "" : "/") + key);
  return true;
}

// Why a name no command declares is refused: with `others` (every command's names) the nearest
// names of any command, so that a misspelt section of another command is found too.
std::string any_command_reason(const OtherCommandNames* others,
                               const std::vector<std::string>& sections, const std::string& key,
                               const std::string& reason)
{
  return others == nullptr ? reason : missing_reason(others->declared, sections, key);
}

void check_prm_file(const DeclaredSection& declared, const std::string& file,
                    OtherCommandNames* others, std::istream& in)
{
  std::vector<std::string> sections;
  std::vector<unsigned int> opened_at; // the line of each open subsection
  // Depth of the outermost open subsection only other commands declare (npos: none).
  std::size_t foreign = std::string::npos;
  std::string line, logical;
  unsigned int number = 0, first_line = 0;
  while (std::getline(in, line))
  {
    ++number;
    if (logical.empty())
      first_line = number;
    // deal.II's continuation: a line ending in a backslash goes on on the next line.
    const std::string stripped = trimmed(line);
    if (!stripped.empty() && stripped.back() == '\\')
    {
      logical += stripped.substr(0, stripped.size() - 1) + " ";
      continue;
    }
    logical += line;
    std::string text = logical;
    logical.clear();
    const auto comment = text.find('#');
    if (comment != std::string::npos)
      text.erase(comment);
    text = trimmed(text);
    const std::string where = file + ":" + std::to_string(first_line);
    if (text.rfind("subsection ", 0) == 0)
    {
      sections.push_back(trimmed(text.substr(11)));
      opened_at.push_back(first_line);
      const std::string reason = foreign != std::string::npos
                                     ? missing_reason(others->declared, sections, "")
                                     : missing_reason(declared, sections, "");
      if (reason.empty())
        continue;
      if (foreign == std::string::npos && elsewhere(others, sections, ""))
        foreign = sections.size() - 1;
      else
        throw InputError(where, any_command_reason(others, sections, "", reason) +
                                    unclosed_hint(declared, sections, opened_at));
    }
    else if (text == "end")
    {
      if (sections.empty())
        return; // deal.II reports the unbalanced end
      sections.pop_back();
      opened_at.pop_back();
      if (foreign != std::string::npos && sections.size() <= foreign)
        foreign = std::string::npos;
    }
    else if (text.rfind("set ", 0) == 0)
    {
      const auto equals = text.find('=');
      if (equals == std::string::npos)
        continue;
      const std::string key = trimmed(text.substr(4, equals - 4));
      const std::string reason = foreign != std::string::npos
                                     ? missing_reason(others->declared, sections, key)
                                     : missing_reason(declared, sections, key);
      if (!reason.empty() || foreign != std::string::npos)
      {
        if (!elsewhere(others, sections, key))
          throw InputError(where, any_command_reason(others, sections, key, reason));
      }
      else if (others != nullptr)
        ++others->own;
    }
  }
  // deal.II's own message for an unclosed subsection names no line.
  if (!sections.empty())
    throw InputError(file + ":" + std::to_string(opened_at.back()),
                     "subsection '" + joined_path(sections, sections.size()) +
                         "' opened here is never closed: an `end` is missing");
}

// `foreign`: the tree lies inside a section only other commands declare (checked against
// theirs).
void check_json_tree(const DeclaredSection& declared, const boost::property_tree::ptree& tree,
                     std::vector<std::string>& sections, const std::string& file,
                     OtherCommandNames* others, bool foreign)
{
  const DeclaredSection& names = foreign ? others->declared : declared;
  for (const auto& [name, child] : tree)
  {
    // deal.II's full JSON writes an entry as an object with its "value".
    const bool entry = child.empty() || child.count("value") > 0;
    if (entry)
    {
      const std::string reason = missing_reason(names, sections, name);
      if ((!reason.empty() || foreign) && !elsewhere(others, sections, name))
        throw InputError(file + ": " + joined_path(sections, sections.size()) +
                             (sections.empty() ? "" : "/") + name,
                         any_command_reason(others, sections, name, reason));
      if (reason.empty() && !foreign && others != nullptr)
        ++others->own;
      continue;
    }
    sections.push_back(name);
    const std::string reason = missing_reason(names, sections, "");
    const bool other = !foreign && !reason.empty() && elsewhere(others, sections, "");
    if (!reason.empty() && !other)
      throw InputError(file + ": " + joined_path(sections, sections.size()),
                       any_command_reason(others, sections, "", reason));
    check_json_tree(declared, child, sections, file, others, foreign || other);
    sections.pop_back();
  }
}
} // namespace

DeclaredSection declared_parameters(const dealii::ParameterHandler& prm)
{
  std::stringstream listing;
  prm.print_parameters(listing, dealii::ParameterHandler::ShortJSON);
  boost::property_tree::ptree tree;
  boost::property_tree::read_json(listing, tree);
  return from_tree(tree);
}

std::vector<std::string> nearest_names(const std::string& name,
                                       const std::vector<std::string>& candidates,
                                       unsigned int count)
{
  const std::string wanted = lower(name);
  const std::size_t limit = std::max<std::size_t>(2, wanted.size() / 3);
  std::vector<std::pair<std::size_t, std::string>> scored;
  for (const std::string& candidate : candidates)
  {
    const std::string other = lower(candidate);
    std::size_t distance = edit_distance(wanted, other);
    // A name written in part ("tip" for "tip diameter") is near too.
    if (wanted.size() >= 3 && other.find(wanted) != std::string::npos)
      distance = std::min(distance, std::size_t(1));
    if (distance <= limit)
      scored.emplace_back(distance, candidate);
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> names;
  for (std::size_t i = 0; i < scored.size() && i < count; ++i)
    names.push_back(scored[i].second);
  return names;
}

// A number or a flag its pattern refuses, in words: deal.II's own text named the limits as C++
// spells them ("does not match the given pattern <[Double 0...MAX_DOUBLE (inclusive)]>" for a
// negative face width). "" when `value` matches or the pattern is none of these.
std::string number_mismatch(const std::string& pattern, const std::string& value)
{
  // Only these: pattern_factory throws for a description it does not know.
  if (pattern != "[Bool]" && pattern.rfind("[Integer", 0) != 0 && pattern.rfind("[Double", 0) != 0)
    return "";
  const std::unique_ptr<dealii::Patterns::PatternBase> parsed =
      dealii::Patterns::pattern_factory(pattern);
  if (!parsed || parsed->match(value))
    return "";
  if (pattern == "[Bool]")
    return "neither true nor false";
  if (pattern == "[Integer]")
    return "not a whole number";
  static const std::regex range(R"(\[(Integer range|Double) (\S+)\.\.\.(\S+) \(inclusive\)\])");
  std::smatch parts;
  if (!std::regex_match(pattern, parts, range))
    return "";
  const std::string kind = parts[1] == "Integer range" ? "not a whole number" : "not a number";
  const std::string low = parts[2], high = parts[3];
  const bool below = low != "-MAX_DOUBLE" && low != std::to_string(INT_MIN);
  const bool above = high != "MAX_DOUBLE" && high != std::to_string(INT_MAX);
  if (below && above)
    return kind + " from " + low + " to " + high;
  if (below)
    return kind + " of at least " + low;
  return above ? kind + " of at most " + high : kind;
}

std::string pattern_mismatch(const dealii::ParameterHandler& prm,
                             const std::vector<std::string>& sections, const std::string& key,
                             const std::string& value)
{
  // The full JSON listing carries each entry's pattern description (names demangled).
  std::stringstream listing;
  prm.print_parameters(listing, dealii::ParameterHandler::JSON);
  boost::property_tree::ptree tree;
  boost::property_tree::read_json(listing, tree);
  const boost::property_tree::ptree* node = &tree;
  for (const std::string& name : sections)
  {
    const auto found = node->find(name);
    if (found == node->not_found())
      return "";
    node = &found->second;
  }
  const auto entry = node->find(key);
  if (entry == node->not_found())
    return "";
  const std::string pattern = entry->second.get<std::string>("pattern_description", "");
  if (const std::string number = number_mismatch(pattern, value); !number.empty())
    return number;
  const std::string head = "[Selection ";
  if (pattern.rfind(head, 0) != 0 || pattern.size() < head.size() + 2)
    return "";
  std::vector<std::string> allowed;
  std::istringstream options(pattern.substr(head.size(), pattern.size() - head.size() - 2));
  std::string text = "not one of ";
  for (std::string option; std::getline(options, option, '|');)
  {
    text += (allowed.empty() ? "'" : ", '") + option + "'";
    allowed.push_back(option);
  }
  const std::vector<std::string> near = nearest_names(value, allowed, 1);
  return near.empty() ? text : text + "; did you mean '" + near.front() + "'?";
}

void check_parameter_name(const DeclaredSection& declared, const std::vector<std::string>& sections,
                          const std::string& key, const std::string& parameter)
{
  const std::string reason = missing_reason(declared, sections, key);
  if (!reason.empty())
    throw InputError(parameter, reason);
}

void merge_declared(DeclaredSection& into, const DeclaredSection& from)
{
  into.entries.insert(from.entries.begin(), from.entries.end());
  for (const auto& [name, section] : from.sections)
    merge_declared(into.sections[name], section);
}

void check_parameter_file(const DeclaredSection& declared, const std::string& file,
                          OtherCommandNames* others, const std::string* text)
{
  const bool json = file.size() > 5 && file.substr(file.size() - 5) == ".json";
  std::ifstream from_file;
  std::istringstream from_text;
  if (text != nullptr)
    from_text.str(*text);
  else
    from_file.open(file);
  std::istream& in = text != nullptr ? static_cast<std::istream&>(from_text) : from_file;
  if (!json)
  {
    check_prm_file(declared, file, others, in);
    return;
  }
  boost::property_tree::ptree tree;
  try
  {
    boost::property_tree::read_json(in, tree);
  }
  catch (const std::exception&)
  {
    return; // not valid JSON: deal.II's parser says where
  }
  std::vector<std::string> sections;
  check_json_tree(declared, tree, sections, file, others, false);
}
namespace
{
// The selection value at `path` that its pattern refuses, as an InputError naming the parameter
// (`where`: the file and line, or the file).
void check_selection(const dealii::ParameterHandler& prm, const std::vector<std::string>& sections,
                     const std::string& key, const std::string& value, const std::string& where)
{
  const std::string reason = pattern_mismatch(prm, sections, key, value);
  if (!reason.empty() && reason.find("'" + value + "'") == std::string::npos)
    throw InputError(joined_path(sections, sections.size()) + (sections.empty() ? "" : "/") + key,
                     "'" + value + "' (" + where + ") is " + reason);
}

void check_json_selections(const dealii::ParameterHandler& prm,
                           const boost::property_tree::ptree& tree,
                           std::vector<std::string>& sections, const std::string& file)
{
  for (const auto& [name, child] : tree)
  {
    if (child.empty() || child.count("value") > 0)
    {
      check_selection(prm, sections, name, child.empty() ? child.data() : child.get("value", ""),
                      file);
      continue;
    }
    sections.push_back(name);
    check_json_selections(prm, child, sections, file);
    sections.pop_back();
  }
}
} // namespace

void check_selection_values(const dealii::ParameterHandler& prm, const std::string& file)
{
  if (file.size() > 5 && file.substr(file.size() - 5) == ".json")
  {
    boost::property_tree::ptree tree;
    try
    {
      boost::property_tree::read_json(file, tree);
    }
    catch (const std::exception&)
    {
      return;
    }
    std::vector<std::string> sections;
    check_json_selections(prm, tree, sections, file);
    return;
  }
  std::ifstream in(file);
  std::vector<std::string> sections;
  std::string line;
  for (unsigned int number = 1; std::getline(in, line); ++number)
  {
    std::string text = line.substr(0, line.find('#'));
    text = trimmed(text);
    if (text.rfind("subsection ", 0) == 0)
      sections.push_back(trimmed(text.substr(11)));
    else if (text == "end" && !sections.empty())
      sections.pop_back();
    else if (text.rfind("set ", 0) == 0 && text.find('=') != std::string::npos)
    {
      const std::size_t equals = text.find('=');
      check_selection(prm, sections, trimmed(text.substr(4, equals - 4)),
                      trimmed(text.substr(equals + 1)), file + " line " + std::to_string(number));
    }
  }
}
} // namespace gearstiff::app
