// Files the dynamics tests write and read back (hand-written `gearstiff stiffness`/`faults`
// summaries): <build>/tests/dynamics/work/<name>, so that a passing suite leaves nothing in the
// temporary folder (they were /tmp/gearstiff-test-*.json, never removed; issue 49).
#pragma once

#include <filesystem>
#include <string>

inline std::string dynamics_work_file(const std::string& name)
{
  const auto folder = std::filesystem::path(GEARSTIFF_BINARY_DIR) / "tests" / "dynamics" / "work";
  std::filesystem::create_directories(folder);
  return (folder / name).string();
}
