// The names of the files and folders a user gives (`-o`, stiffness and back-flank files,
// TMPDIR), checked before anything touches them: a name the file system cannot hold reached
// std::filesystem and ended as its own text with exit 1 (issue 42). One check for every module.
#pragma once

#include "errors/errors.h"

#include <climits>
#include <string>

namespace gearstiff
{
// InputError naming `parameter` for an empty name, a name with a NUL, one longer than PATH_MAX
// or one with a component (between '/') longer than NAME_MAX: what POSIX file systems refuse.
inline void check_file_name(const std::string& name, const std::string& parameter)
{
  if (name.empty())
    throw InputError(parameter, "names no file or folder (empty)");
  if (name.find('\0') != std::string::npos)
    throw InputError(parameter, "contains a NUL character");
  if (name.size() >= PATH_MAX)
    throw InputError(parameter, "the path has " + std::to_string(name.size()) +
                                    " characters, more than the file system allows (" +
                                    std::to_string(PATH_MAX - 1) + ")");
  std::size_t start = 0;
  while (start <= name.size())
  {
    const std::size_t slash = name.find('/', start);
    const std::size_t end = slash == std::string::npos ? name.size() : slash;
    if (end - start > NAME_MAX)
      throw InputError(parameter, "a name in the path has " + std::to_string(end - start) +
                                      " characters, more than the file system allows (" +
                                      std::to_string(NAME_MAX) + ")");
    if (slash == std::string::npos)
      break;
    start = slash + 1;
  }
}
} // namespace gearstiff
