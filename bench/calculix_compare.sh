#!/usr/bin/env bash
# gearstiff against CalculiX on the same mesh (issue 16, docs/calculix.md): the single- and
# double-pair positions of the split-path pair solved by `gearstiff stiffness` (FE_Q(1)) and by
# `ccx` on the exported deck at two contact penalties (penalty-corrected by extrapolation in
# 1/K). Prints k, rotation, peak contact pressure, root stress, wall time and peak memory of
# both; the last line is
#   calculix_compare: k gearstiff X N/um, CalculiX Y N/um (Z %), time ratio Rx
# (single pair; Y penalty-corrected, Z = X/Y - 1, R = CalculiX time / gearstiff time: one ccx
# process against the gearstiff process without its meshing, both from a finished mesh).
# Installs Debian's calculix-ccx if ccx is missing. Not run by CI (minutes).
# usage: bench/calculix_compare.sh [path/to/gearstiff] [calculix_compare.py options]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
gearstiff=${1:-$here/../build/app/gearstiff}
shift || true
source "$here/ensure_ccx.sh" calculix_compare
exec python3 "$here/calculix_compare.py" "$(realpath "$gearstiff")" "$@"
