#!/usr/bin/env bash
# Speed of the 3D influence-coefficient model (issue 47, docs/ltca.md §3) beside the exact 3D
# rolling sweep (`sweep mesh = once`), default spur pair, Q1, 4 layers, 32 positions, 1 rank:
# process wall time and peak memory (/usr/bin/time -v); the fast model as the median of 3, the
# exact sweep LTCA_EXACT_RUNS times (default 1: it takes minutes). Run it under the build lock
# (flock /tmp/gearstiff-build.lock bash bench/ltca_speed_3d.sh) on a quiet machine.
# usage: bench/ltca_speed_3d.sh [path/to/gearstiff]   (default build/app/gearstiff)
set -euo pipefail
gearstiff=${1:-$(dirname "$0")/../build/app/gearstiff}
export OMP_NUM_THREADS=1
positions=${LTCA_POSITIONS:-32}
measure() { # wall seconds and peak RSS (MB) of one run
  local log
  log=$(mktemp)
  /usr/bin/time -v "$@" >/dev/null 2>"$log"
  awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, t, ":"); s = 0;
               for (i = 1; i <= n; ++i) s = s * 60 + t[i]; w = s}
              /Maximum resident set size/ {m = $2 / 1024}
              END {printf "%.3f %.0f\n", w, m}' "$log"
  rm -f "$log"
}
runs() { # label, count, command...
  local label=$1 count=$2
  shift 2
  local all=()
  for _ in $(seq "$count"); do all+=("$(measure "$@")"); done
  printf '%s\n' "${all[@]}" | sort -n | sed -n "$(((count + 1) / 2))p" | {
    read -r wall mem
    echo "$label: wall $wall s (median of $count: $(printf '%s ' "${all[@]%% *}")), peak RSS $mem MB"
  }
}
sweep=(stiffness --quiet --set "Stiffness/mode=sweep" --set "Stiffness/sweep positions=$positions"
  --set "Mesh/dimension=3" --set "Mesh/layers=4" --set "Finite elements/Element degree=1")
runs "influence coefficients 3D, $positions positions, 1 rank" 3 \
  "$gearstiff" "${sweep[@]}" --set "Stiffness/contact model=influence coefficients"
runs "finite element 3D (exact, once, h_c 0.06 mm, μ 0), $positions positions, 1 rank" \
  "${LTCA_EXACT_RUNS:-1}" "$gearstiff" "${sweep[@]}" --set "Contact/Friction coefficient=0" \
  --set "Mesh/contact size=0.06" --set "Stiffness/sweep mesh=once"
