#!/usr/bin/env bash
# Speed of `Stiffness/contact model = influence coefficients` (issue 47, docs/ltca.md) beside the
# exact rolling sweep (`sweep mesh = once`, μ 0), default pair, 1 rank: process wall time and peak
# memory (/usr/bin/time -v); the fast model as the median of 3, the exact sweep as the median of
# LTCA_EXACT_RUNS (default 3 in 2D, 1 in 3D: it takes minutes there).
# - 2D (default): 32 and 128 positions (target: ≤ 2 s for the fast model at 128), then how the
#   fast model's time splits (scene, factorization, coefficients, contact problems) from its report.
# - LTCA_DIMENSION=3: 32 positions, Q1, LTCA_LAYERS layers (default 4; docs/ltca.md §3); the exact
#   sweep at h_c 0.06 mm; then the fast model's time split from its report.
# LTCA_POSITIONS overrides the position counts; LTCA_EXACT_RUNS=0 leaves the exact sweep out.
# usage: bench/ltca_speed.sh [path/to/gearstiff]   (default build/app/gearstiff); run it under
# the build lock (flock /tmp/gearstiff-build.lock bash bench/ltca_speed.sh) on a quiet machine.
set -euo pipefail
gearstiff=${1:-$(dirname "$0")/../build/app/gearstiff}
export OMP_NUM_THREADS=1
dimension=${LTCA_DIMENSION:-2}
if [ "$dimension" = 3 ]; then
  positions_list=${LTCA_POSITIONS:-32}
  exact_runs=${LTCA_EXACT_RUNS:-1}
  model=(--set "Mesh/dimension=3" --set "Mesh/layers=${LTCA_LAYERS:-4}"
    --set "Finite elements/Element degree=1")
  exact=(--set "Mesh/contact size=0.06")
else
  positions_list=${LTCA_POSITIONS:-32 128}
  exact_runs=${LTCA_EXACT_RUNS:-3}
  model=()
  exact=()
fi
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
median() { # label, count, command...
  local label=$1 count=$2
  shift 2
  local runs=()
  for _ in $(seq "$count"); do runs+=("$(measure "$@")"); done
  printf '%s\n' "${runs[@]}" | sort -n | sed -n "$(((count + 1) / 2))p" | {
    read -r wall mem
    echo "$label: wall $wall s (median of $count: $(printf '%s ' "${runs[@]%% *}")), peak RSS $mem MB"
  }
}
for positions in $positions_list; do
  sweep=(stiffness --quiet --set "Stiffness/mode=sweep" --set "Stiffness/sweep positions=$positions"
    "${model[@]}")
  median "influence coefficients ${dimension}D, $positions positions, 1 rank" 3 \
    "$gearstiff" "${sweep[@]}" --set "Stiffness/contact model=influence coefficients"
  [ "$exact_runs" = 0 ] && continue
  median "finite element ${dimension}D (exact, sweep mesh once, μ 0), $positions positions, 1 rank" \
    "$exact_runs" "$gearstiff" "${sweep[@]}" --set "Contact/Friction coefficient=0" \
    --set "Stiffness/sweep mesh=once" "${exact[@]}"
done
split_positions=$([ "$dimension" = 3 ] && echo 32 || echo 128)
echo "time split of the fast model (its report, $split_positions positions):"
sweep=(stiffness --quiet --set "Stiffness/mode=sweep" --set "Stiffness/sweep positions=$split_positions"
  "${model[@]}")
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
