#!/usr/bin/env bash
# gearstiff cycloid-loads against CalculiX on the same mesh (issue 16, docs/calculix.md): the
# nominal Cyclo drive of docs/references.md §4 at one crank angle, by `gearstiff cycloid-loads` and by
# `ccx` on the deck `gearstiff mesh --set "Scene/type=cycloid" --set "Mesh/format=inp"` writes
# (two contact penalties, extrapolated). Prints every roller force P_i, pin force Q_j, the
# bearing force, the output rotation, wall times and peak memory of both; the last line is
#   calculix_cycloid: P_max gearstiff X N, CalculiX Y N (Z %), Q_max ..., theta ..., time ratio Rx
# Installs Debian's calculix-ccx if ccx is missing. Not run by CI (minutes).
# usage: bench/calculix_cycloid.sh [path/to/gearstiff] [calculix_cycloid.py options]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
gearstiff=${1:-$here/../build/app/gearstiff}
shift || true
source "$here/ensure_ccx.sh" calculix_cycloid
exec python3 "$here/calculix_cycloid.py" "$(realpath "$gearstiff")" "$@"
