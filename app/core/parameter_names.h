// The names a user writes (--set section/key, `set key` in a .prm, keys of a .json) checked
// against the declared parameters before deal.II reads them, so a misspelt name is answered with
// its section and the nearest declared names instead of deal.II's "You can't ask for entry
// <teeht> you have not yet declared".
#pragma once

#include <deal.II/base/parameter_handler.h>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace gearstiff::app
{
// One subsection of the declared parameters: its entries and its subsections.
struct DeclaredSection
{
  std::set<std::string> entries;
  std::map<std::string, DeclaredSection> sections;
};

// Every declared entry and subsection of `prm` (read from its ShortJSON listing).
DeclaredSection declared_parameters(const dealii::ParameterHandler& prm);

// The declared names nearest to `name` (edit distance, case ignored), best first: at most
// `count`, each within a third of the name's length (at least 2 edits).
std::vector<std::string> nearest_names(const std::string& name,
                                       const std::vector<std::string>& candidates,
                                       unsigned int count = 3);

// InputError(`parameter`, ...) when the entry `sections`/`key` is not declared: the first
// missing subsection or the entry, the section it was looked for in, the nearest names.
void check_parameter_name(const DeclaredSection& declared, const std::vector<std::string>& sections,
                          const std::string& key, const std::string& parameter);

// The names a parameter file may hold although this command does not declare them: those another
// command declares, so that one pair file serves every command that reads a pair (gear-pair,
// stiffness, cai, faults, mesh, dynamics). check_parameter_file lists each one it meets in
// `ignored` ("section/key") instead of refusing it; a name no command declares is still refused
// with this command's nearest names.
struct OtherCommandNames
{
  DeclaredSection declared;         // the union of the other commands' parameters
  std::vector<std::string> ignored; // met in the file, in the file's order
  std::size_t own = 0;              // entries met in the file that this command declares
};
// `into` gains every entry and subsection of `from`.
void merge_declared(DeclaredSection& into, const DeclaredSection& from);

// Why an entry's pattern refuses `value`, in words. A Selection ("[Selection single|double|sweep
// ]") and a value it does not allow: "not one of 'single', 'double', 'sweep'; did you mean
// 'sweep'?" (the nearest allowed value, when one is near). For a number or a flag its pattern
// refuses, the pattern in words: "not a number of at least 0", "not a whole number from 1 to 2",
// "neither true nor false". "" for another pattern, or a number or flag that matches: its own
// message stands.
std::string pattern_mismatch(const dealii::ParameterHandler& prm,
                             const std::vector<std::string>& sections, const std::string& key,
                             const std::string& value);

// After deal.II refused parameter file `file`: InputError naming the parameter (and the file
// and line) for the first selection value (`set mode = swep`) its pattern does not allow, with
// the allowed values and the nearest one, or the first number or flag its pattern refuses;
// nothing when every such value is allowed.
void check_selection_values(const dealii::ParameterHandler& prm, const std::string& file);

// The same for every `set` of a .prm file or every key of a .json file; the InputError names
// the file and line (.prm) or the file and the key's path (.json). Lines it does not understand
// are left to deal.II's parser. With `others`, names only other commands declare are listed
// there, not refused. With `text`, that is the file's content (the file's text with renamed
// parameters under their new names, app/core/renamed_parameters.h); messages still name `file`.
void check_parameter_file(const DeclaredSection& declared, const std::string& file,
                          OtherCommandNames* others = nullptr, const std::string* text = nullptr);
} // namespace gearstiff::app
