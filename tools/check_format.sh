#!/usr/bin/env bash
# Fails when a C++ file of the repository differs from clang-format (Debian's clang-format 14 with
# the checked-in .clang-format); prints the files. Fix with: clang-format -i <file>.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files '*.cc' '*.h')
if ! clang-format --dry-run --Werror "${files[@]}" 2>/dev/null; then
  echo "clang-format: these files need formatting (clang-format -i <file>):"
  for f in "${files[@]}"; do
    clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || echo "  $f"
  done
  exit 1
fi
echo "clang-format: ${#files[@]} files formatted"
