// Files the dynamics tests write and read back (hand-written `gearstiff stiffness`/`faults`
// summaries): <build>/tests/dynamics/work/<name>, so that a passing suite leaves nothing in the
// temporary folder (they were /tmp/gearstiff-test-*.json, never removed; issue 49).
#pragma once

#include "tests/test_paths.h"

#include <filesystem>
#include <string>

inline std::string dynamics_work_file(const std::string& name)
{
  const auto folder = gearstiff::test_support::build_work_folder("tests/dynamics/work");
  return (folder / name).string();
}
