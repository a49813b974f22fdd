#!/usr/bin/env bash
# The README's test command: install what is missing, check the formatting, build the
# deal.II-free modules in Debug and run their tests (so that their assertions execute
# somewhere), then build everything in Release and run every test. Warnings in gearstiff's own
# code are errors.
set -euo pipefail
cd "$(dirname "$0")/.."
bash .ci/install-deps
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
bash tools/check_format.sh
cmake -S . -B build-debug -DCMAKE_BUILD_TYPE=Debug -DGEARSTIFF_WERROR=ON >/dev/null
cmake --build build-debug -j"$(nproc)" --target gearstiff_plain_tests
# The compiled ones only (labels plain and unit): the plain scripts (tools/*.py checks, the
# labels and counts) do not depend on the build type and run in the Release step below; in the
# fresh clone of 329c91b two of them were 106 + 20 s of this step's 120 s, run twice.
ctest --test-dir build-debug --output-on-failure -j"$(nproc)" -L plain -L unit
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGEARSTIFF_WERROR=ON >/dev/null
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
# Where the time went (issue 43): Σ by label and the costliest tests of this run.
python3 tools/test_times.py build --top 25
