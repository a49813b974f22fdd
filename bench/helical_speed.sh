#!/usr/bin/env bash
# Speed of the exact (FE contact) path on the default helical pair (issue 46 "Speed";
# docs/helical.md "Speed"): the built-in pair at β ±15° (ε_β ≈ 1), Q1, frictionless, its default
# layers and sizes, on 2 MPI ranks: one position (the default single-pair position) and a
# HELICAL_POSITIONS-position sweep over a base pitch (default 32; each position its own scene,
# mesh and factorization, `sweep mesh = per position` being the only helical sweep).
# Process wall time of mpirun and the larger peak RSS of the two ranks (/usr/bin/time -v on each
# rank), medians of HELICAL_RUNS runs (default 3).
# usage: bench/helical_speed.sh [path/to/gearstiff]   (default build/app/gearstiff); run it
# under the build lock (flock /tmp/gearstiff-build.lock bash bench/helical_speed.sh).
set -euo pipefail
gearstiff=$(realpath "${1:-$(dirname "$0")/../build/app/gearstiff}")
export OMP_NUM_THREADS=1 OMPI_MCA_rmaps_base_oversubscribe=1
runs=${HELICAL_RUNS:-3}
positions=${HELICAL_POSITIONS:-32}
helical=(--set "Mesh/dimension=3" --set "Finite elements/Element degree=1"
  --set "Contact/Friction coefficient=0"
  --set "Gear pair/Pinion/helix angle=15" --set "Gear pair/Wheel/helix angle=-15")
# wall seconds of mpirun and the largest peak RSS (MB) of its ranks
measure() {
  local folder
  folder=$(mktemp -d)
  local start end
  start=$(date +%s.%N)
  mpirun --allow-run-as-root -np 2 bash -c \
    '/usr/bin/time -v "$@" >/dev/null 2>"'"$folder"'/rank.$OMPI_COMM_WORLD_RANK"' _ "$@"
  end=$(date +%s.%N)
  local mem
  mem=$(awk -F': ' '/Maximum resident set size/ {m = ($2 > m ? $2 : m)} END {printf "%.0f", m / 1024}' \
    "$folder"/rank.*)
  echo "$(echo "$end - $start" | bc) $mem"
  rm -rf "$folder"
}
median() { # label, command...
  local label=$1
  shift
  local results=()
  for _ in $(seq "$runs"); do results+=("$(measure "$@")"); done
  printf '%s\n' "${results[@]}" | sort -n | sed -n "$(((runs + 1) / 2))p" | {
    read -r wall mem
    echo "$label: wall $wall s (median of $runs: $(printf '%s ' "${results[@]%% *}")), peak RSS of a rank $mem MB"
  }
}
median "helical default pair, one position, 2 ranks" "$gearstiff" stiffness --quiet "${helical[@]}"
median "helical default pair, $positions-position sweep, 2 ranks" "$gearstiff" stiffness --quiet \
  "${helical[@]}" --set "Stiffness/mode=sweep" --set "Stiffness/sweep positions=$positions"
