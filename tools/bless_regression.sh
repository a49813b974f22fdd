#!/usr/bin/env bash
# Re-writes the stored whole outputs of the regression tests (tests/regression/<case>.json) from
# the current build, after an intended change: `bash tools/bless_regression.sh [CASE ...]`
# (default: every case; BUILD=build-dir to use another build). Review `git diff tests/regression`
# before committing: every number that moved should be one the change meant to move.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD:-build}
regex="^regression\\."
if [ $# -gt 0 ]; then regex="^regression\\.($(IFS='|'; echo "$*"))\$"; fi
# ctest knows each case's command line; run it with --bless inserted after run_case.sh.
ctest --test-dir "$build" -R "$regex" --show-only=json-v1 |
python3 -c '
import json, os, subprocess, sys
failed = 0
for test in json.load(sys.stdin)["tests"]:
    command = test["command"]
    i = next(k for k, a in enumerate(command) if a.endswith("run_case.sh"))
    env = os.environ.copy()
    for p in test.get("properties", []):
        if p["name"] == "ENVIRONMENT":
            env.update(v.split("=", 1) for v in p["value"])
    failed |= subprocess.run(command[:i + 1] + ["--bless"] + command[i + 1:], env=env).returncode != 0
sys.exit(failed)
'
