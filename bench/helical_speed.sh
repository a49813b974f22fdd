#!/usr/bin/env bash
# Speed of the exact (FE contact) path on the default helical pair (issue 46 "Speed";
# docs/helical.md "Speed"): the built-in pair at β ±15° (ε_β ≈ 1), Q1, frictionless, its default
# layers and sizes, on 2 MPI ranks: one position (the default single-pair position) and a
# HELICAL_POSITIONS-position sweep over a base pitch (default 32) meshed HELICAL_SWEEP_MESH
# ("per position", the default: each position its own scene, mesh and factorization; or "once":
# one mesh per rank refined along the band the face sweeps, turned to each position).
# HELICAL_COARSE=1 runs the coarse sizes of tests/helical/sweep_once.py's built-in case (contact
# 0.1875, fine radius 0.5, body 0.9375, rim 3.125 mm). HELICAL_SINGLE=0 skips the single
# position. HELICAL_RANKS (default 2): MPI ranks; a `once` sweep factorizes the whole rolling
# mesh on every rank (the default sizes' estimate: ~12 GB a rank, docs/helical.md "Speed").
# HELICAL_SWEEP_START (deg, optional): Stiffness/sweep start. HELICAL_JSON (optional): a file
# that receives the JSON report of the last run (rank 0).
# Process wall time of mpirun and the larger peak RSS of the two ranks (/usr/bin/time -v on each
# rank), medians of HELICAL_RUNS runs (default 3).
# usage: bench/helical_speed.sh [path/to/gearstiff]   (default build/app/gearstiff); run it
# under the build lock (flock /tmp/gearstiff-build.lock bash bench/helical_speed.sh).
set -euo pipefail
gearstiff=$(realpath "${1:-$(dirname "$0")/../build/app/gearstiff}")
export OMP_NUM_THREADS=1 OMPI_MCA_rmaps_base_oversubscribe=1
runs=${HELICAL_RUNS:-3}
positions=${HELICAL_POSITIONS:-32}
sweep_mesh=${HELICAL_SWEEP_MESH:-per position}
ranks=${HELICAL_RANKS:-2}
helical=(--set "Mesh/dimension=3" --set "Finite elements/Element degree=1"
  --set "Contact/Friction coefficient=0"
  --set "Gear pair/Pinion/helix angle=15" --set "Gear pair/Wheel/helix angle=-15")
sizes="default sizes"
if [ "${HELICAL_COARSE:-0}" = 1 ]; then
  helical+=(--set "Mesh/contact size=0.1875" --set "Mesh/fine radius=0.5"
    --set "Mesh/body size=0.9375" --set "Mesh/rim size=3.125")
  sizes="coarse sizes"
fi
# wall seconds of mpirun and the largest peak RSS (MB) of its ranks
measure() {
  local folder
  folder=$(mktemp -d)
  local start end
  start=$(date +%s.%N)
  mpirun --allow-run-as-root -np "$ranks" bash -c \
    '/usr/bin/time -v "$@" >"'"$folder"'/out.$OMPI_COMM_WORLD_RANK" 2>"'"$folder"'/rank.$OMPI_COMM_WORLD_RANK"' _ "$@"
  end=$(date +%s.%N)
  local mem
  mem=$(awk -F': ' '/Maximum resident set size/ {m = ($2 > m ? $2 : m)} END {printf "%.0f", m / 1024}' \
    "$folder"/rank.*)
  if [ -n "${HELICAL_JSON:-}" ]; then cp "$folder/out.0" "$HELICAL_JSON"; fi
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
if [ "${HELICAL_SINGLE:-1}" != 0 ]; then
  median "helical default pair ($sizes), one position, $ranks ranks" "$gearstiff" stiffness --quiet --json \
    "${helical[@]}"
fi
start_set=()
if [ -n "${HELICAL_SWEEP_START:-}" ]; then start_set=(--set "Stiffness/sweep start=$HELICAL_SWEEP_START"); fi
median "helical default pair ($sizes), $positions-position sweep ($sweep_mesh), $ranks ranks" \
  "$gearstiff" stiffness --quiet --json "${helical[@]}" "${start_set[@]}" --set "Stiffness/mode=sweep" \
  --set "Stiffness/sweep positions=$positions" --set "Stiffness/sweep mesh=$sweep_mesh"
