#!/usr/bin/env bash
# The Hertz cylinders scene on the same mesh: ccx on the deck `gearstiff mesh` writes (two
# penalties, approach extrapolated in 1/K), `gearstiff contact` at ccx's approach, and Hertz's
# half-width and peak pressure (issue 16, docs/calculix.md). Last line:
#   calculix_hertz: F gearstiff X N at ccx's approach, CalculiX Y N (Z %), a ..., p0 ..., time ratio Rx
# Installs Debian's calculix-ccx if ccx is missing. Not run by CI (about a minute).
# usage: bench/calculix_hertz.sh [path/to/gearstiff] [calculix_hertz.py options]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
gearstiff=${1:-$here/../build/app/gearstiff}
shift || true
source "$here/ensure_ccx.sh" calculix_hertz
exec python3 "$here/calculix_hertz.py" "$(realpath "$gearstiff")" "$@"
