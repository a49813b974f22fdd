// Parameters renamed for one name per physical input (issue 45). An old name stays accepted for
// one release: in --set, .prm and .json it is read as the new one, with one note on stderr naming
// both, so a parameter file written for the previous release runs unchanged. docs/parameters.md
// "Renamed parameters" lists them for users.
#pragma once

#include <string>
#include <vector>

namespace gearstiff::app
{
struct RenamedParameter
{
  const char* old_path; // "Train/tooth friction coefficient", as the previous release declared it
  const char* new_path; // its name now; same subsection
  const char* until;    // the release after which the old name is refused
};
// Every renamed parameter.
const std::vector<RenamedParameter>& renamed_parameters();

// `path` ("section/.../key") under its current name; `path` itself when it was not renamed.
std::string current_parameter_path(const std::string& path);

// The note a renamed name gets: "gearstiff: note: <where>: '<old>' is now '<new>' ...".
std::string renamed_note(const std::string& where, const std::string& old_path);

// The text of a parameter file (`json`: a .json file, else .prm) with every renamed name written
// under its new name (a .prm keeps its lines, so messages name the user's line); the old paths met
// are appended to `met`.
std::string with_current_names(const std::string& text, bool json, std::vector<std::string>& met);
} // namespace gearstiff::app
