#!/usr/bin/env bash
# Speed of `Stiffness/contact model = influence coefficients` (issue 47, docs/ltca.md) beside the
# exact rolling sweep, 2D default pair, 32 and 128 positions, 1 rank (target: ≤ 2 s for the fast
# model at 128):
# process wall time and peak memory (/usr/bin/time -v), medians of 3, and how the fast model's
# time splits (scene, factorization, coefficients, contact problems) from its report.
# usage: bench/ltca_speed.sh [path/to/gearstiff]   (default build/app/gearstiff); run it under
# the build lock (flock /tmp/gearstiff-build.lock bash bench/ltca_speed.sh) on a quiet machine.
set -euo pipefail
gearstiff=${1:-$(dirname "$0")/../build/app/gearstiff}
export OMP_NUM_THREADS=1
positions_list=${LTCA_POSITIONS:-32 128}
# wall seconds and peak RSS (MB) of one run
measure() {
  local log
  log=$(mktemp)
  /usr/bin/time -v "$@" >/dev/null 2>"$log"
  awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, t, ":"); s = 0;
               for (i = 1; i <= n; ++i) s = s * 60 + t[i]; w = s}
              /Maximum resident set size/ {m = $2 / 1024}
              END {printf "%.3f %.0f\n", w, m}' "$log"
  rm -f "$log"
}
median3() { # label, command...
  local label=$1
  shift
  local runs=()
  for _ in 1 2 3; do runs+=("$(measure "$@")"); done
  printf '%s\n' "${runs[@]}" | sort -n | sed -n 2p | {
    read -r wall mem
    echo "$label: wall $wall s (median of 3: $(printf '%s ' "${runs[@]%% *}")), peak RSS $mem MB"
  }
}
for positions in $positions_list; do
  sweep=(stiffness --quiet --set "Stiffness/mode=sweep" --set "Stiffness/sweep positions=$positions")
  median3 "influence coefficients, $positions positions, 1 rank" \
    "$gearstiff" "${sweep[@]}" --set "Stiffness/contact model=influence coefficients"
  median3 "finite element (exact, sweep mesh once), $positions positions, 1 rank" \
    "$gearstiff" "${sweep[@]}" --set "Contact/Friction coefficient=0"
done
echo "time split of the fast model (its report, 128 positions):"
sweep=(stiffness --quiet --set "Stiffness/mode=sweep" --set "Stiffness/sweep positions=128")
"$gearstiff" "${sweep[@]}" --set "Stiffness/contact model=influence coefficients" --json |
  python3 -c '
import json, sys
values = json.load(sys.stdin)["values"]
for key in ("influence_fe_dofs", "influence_grid_points", "influence_grid_step",
            "influence_scene_time", "influence_factorization_time",
            "influence_coefficient_time", "influence_contact_time", "sweep_wall_time"):
    v = values[key]
    print("  %s: %s" % (key, v["value"] if isinstance(v, dict) else v))
'
