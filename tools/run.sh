#!/usr/bin/env bash
# The README's main command: install what is missing, build the `gearstiff` command only (the
# run loads nothing else: the chart scripts are Python, the tests and the Python module are built
# by tools/test.sh), and run the whole chain on the built-in split-path case; results in
# ./results (or the folder given as $1).
set -euo pipefail
cd "$(dirname "$0")/.."
bash .ci/install-deps
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target gearstiff
./build/app/gearstiff run -o "${1:-results}"
