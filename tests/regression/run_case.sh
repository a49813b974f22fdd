#!/usr/bin/env bash
# run_case.sh [--bless] STORED WORKDIR command args...
# Runs a gearstiff command with `-o WORKDIR/out` and compares WORKDIR/out/summary.json with the
# stored whole output STORED (compare.py: numbers to a relative 1e-6, timings ignored). With
# --bless, STORED is replaced by the new output instead (after an intended change).
set -u
bless=()
if [ "${1:-}" = "--bless" ]; then bless=(--bless); shift; fi
stored=$1; work=$2; shift 2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work" || exit 99
if ! "$@" -o "$work/out" >"$work/stdout.txt" 2>"$work/stderr.txt"; then
  echo "the command failed: $*"; tail -5 "$work/stderr.txt"; exit 1
fi
python3 "$here/compare.py" "${bless[@]}" "$stored" "$work/out/summary.json"
