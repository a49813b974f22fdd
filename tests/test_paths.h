// The source and build folders a test reads data from and writes scratch files to. They come from
// the environment ctest gives every test (GEARSTIFF_SOURCE_DIR, GEARSTIFF_BINARY_DIR; set in
// tests/CMakeLists.txt), not from compile definitions: an absolute path compiled into a test
// object makes ccache miss it in every new clone folder (issue 43: ~58 test objects rebuilt).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace gearstiff::test_support
{
inline std::filesystem::path folder_from_environment(const char* variable)
{
  const char* value = std::getenv(variable);
  if (value == nullptr || *value == '\0')
    throw std::runtime_error(
        std::string(variable) +
        " is not set: run the test through ctest (tests/CMakeLists.txt sets it)");
  return value;
}

// The source tree's root.
inline std::filesystem::path source_dir()
{
  return folder_from_environment("GEARSTIFF_SOURCE_DIR");
}

// `<build>/<relative>`, created on first use.
inline std::filesystem::path build_work_folder(const std::filesystem::path& relative)
{
  const auto folder = folder_from_environment("GEARSTIFF_BINARY_DIR") / relative;
  std::filesystem::create_directories(folder);
  return folder;
}
} // namespace gearstiff::test_support
