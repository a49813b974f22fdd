#!/usr/bin/env bash
# check_cli.sh EXIT STDERR_REGEX STDOUT_REGEX WORKDIR command args...
# Runs the command in WORKDIR (emptied first). Passes when the exit code equals EXIT, stderr
# matches STDERR_REGEX and stdout STDOUT_REGEX (empty regex: not checked), and, for a failing
# run, WORKDIR holds no files afterwards: a failed command must leave nothing that looks like a
# result. Arguments "@WORK@" are replaced by WORKDIR and "@SRC@" by the source tree.
set -u
expected=$1; err_re=$2; out_re=$3; work=$4; shift 4
src=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 99
args=()
for a in "$@"; do a=${a//@WORK@/$work}; a=${a//@SRC@/$src}; args+=("$a"); done
"${args[@]}" >stdout.txt 2>stderr.txt
code=$?
fail=0
if [ "$code" != "$expected" ]; then echo "exit code $code, expected $expected"; fail=1; fi
if [ -n "$err_re" ] && ! grep -Eq -- "$err_re" stderr.txt; then
  echo "stderr does not match /$err_re/"; fail=1; fi
if [ -n "$out_re" ] && ! grep -Eq -- "$out_re" stdout.txt; then
  echo "stdout does not match /$out_re/"; fail=1; fi
if [ "$expected" != 0 ]; then
  left=$(find . -mindepth 1 ! -name stdout.txt ! -name stderr.txt ! -name '*.prm' ! -name '*.json.in' -type f | head -5)
  if [ -n "$left" ]; then echo "failed run left files behind: $left"; fail=1; fi
  # Progress lines (issue 25: "<stage>: stage i/N ...", "... done here of ~N ...", contact's
  # set-up and iterations, the influence-coefficient model's once-per-sweep steps) are not the
  # message; the error itself must stay one clear line.
  lines=$(grep -vE ': stage [0-9]+/[0-9]+ |done here of ~|^contact: (set-up done|load step)|^[a-z-]+: influence coefficients( \(3D\))?: ' stderr.txt | grep -c .)
  if [ "$lines" -gt 3 ]; then echo "error message is $lines lines, expected one clear line"; fail=1; fi
fi
if [ $fail != 0 ]; then
  echo "--- command: ${args[*]}"; echo "--- stdout:"; head -40 stdout.txt; echo "--- stderr:"; head -40 stderr.txt
  exit 1
fi
exit 0
