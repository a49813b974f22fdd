#!/usr/bin/env bash
# Speed of the contact solver (issue 12): the Schur complement on the contact unknowns with one
# factorization (default) against the full re-solve of every active-set iteration (the reference,
# `Contact/Iteration solves=full re-solve`), on the split-path pair of docs/references.md §1 with the
# published μ = 0.01. Every figure is a median of three runs unless marked; the ratios compare
# runs taken in this one invocation (the machine is shared).
#
#   single pair, default 2D scene (Q2, 53k DoFs), 1 rank: process wall time and contact solve
#   32- and 128-position sweeps on 2 ranks (and 32 on 1 rank, alternating with 2: the 2-rank
#   speed-up of the process and of the sweep itself)
#   gearstiff run (the whole chain) on 1 rank
#   3D, Q1, 8 layers (187k DoFs) on 2 ranks: wall time and peak memory per rank
#
#   warm start (Contact/Warm start): active-set iterations summed over the 32-position sweep,
#   each position started from its neighbour's zone against every position started cold
#
#   --large: 3D, Q2, 6 layers (1.06 M DoFs) on 2 ranks, one run, each rank under an 11 GB
#   address-space limit (prlimit), MUMPS factors out of core (ICNTL(22) = 1, files in $TMPDIR or
#   /tmp, ~7.3 GB), PORD ordering (ICNTL(7) = 4: what METIS (5) falls back to in this Debian
#   build): wall time and peak memory per rank. In core, MUMPS estimates 11.1 GB for the
#   factors on top of the ~8 GB the ranks hold otherwise: ~19 GB, too close to the 23 GB machine.
#
# usage: bench/contact_speed.sh [path/to/gearstiff] [--quick|--large|--once|--once-3d]
#   (--quick: one run each, no 3D; --large: only the ~1 M DoF case; --once: only the rolling-sweep
#   rows, one run each)
# Results with before/after figures: bench/contact_speed.md.
set -euo pipefail
gearstiff=${1:-$(dirname "$0")/../build/app/gearstiff}
quick=${2:-}
runs=3
[ "$quick" = "--quick" ] && runs=1
mpi=(mpirun --allow-run-as-root --oversubscribe)
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
friction=(--set "Contact/Friction coefficient=0.01")

# The median of its arguments.
median() { printf '%s\n' "$@" | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }

# Median wall time (s) of `runs` runs of a command.
median_seconds() {
  local times=()
  for _ in $(seq "$runs"); do
    local start end
    start=$(date +%s.%N)
    "$@" >/dev/null 2>&1
    end=$(date +%s.%N)
    times+=("$(echo "$end - $start" | bc)")
  done
  median "${times[@]}"
}

# The value of a "<label>   <number>  s" line of a command's text report.
report_value() { grep -E "$1" | head -1 | awk '{for (i = NF; i > 0; --i) if ($i ~ /^[0-9.]+$/) {print $i; exit}}'; }

if [ "$quick" = "--large" ]; then
  dir=$(mktemp -d)
  MUMPS_OOC_TMPDIR=${TMPDIR:-/tmp} PETSC_OPTIONS="-mat_mumps_icntl_22 1 -mat_mumps_icntl_7 4" \
  "${mpi[@]}" -np 2 sh -c '/usr/bin/time -f "%e %M" -o "$0/rank$OMPI_COMM_WORLD_RANK.time" \
    prlimit --as=11000000000 "$@"' "$dir" "$gearstiff" stiffness --set "Mesh/dimension=3" \
    --set "Mesh/layers=6" --set "Finite elements/Element degree=2" "${friction[@]}" >"$dir/out"
  echo "| 3D Q2 6 layers ($(grep -oE '[0-9]+ DoFs' "$dir/out" | head -1)), 2 ranks [s], one run |" \
    "$(cat "$dir"/rank0.time) / $(cat "$dir"/rank1.time) (s, peak KB of rank 0 / rank 1) | | |"
  rm -rf "$dir"
  exit 0
fi

# --once-3d (issue 28): the rolling sweep in 3D, default pair, Q1, 8 layers (the default 3D
# mesh sizes), 32 positions, μ = 0.01, 2 ranks: median wall time of 3 runs and the peak memory
# of each rank (/usr/bin/time %M per rank) of the last run; then the same sweep per position, one run.
# Target ≤ 60 s. Max iterations 500: next to the pitch point, where the sliding direction reverses
# in the contact zone, the friction bounds' fixed point needs more than the default 40 in 3D; at
# 32 positions once, position 14 (next to the pitch point) took 207 iterations and position 17
# (the first single-pair one, warm-started from position 8) 285, so 150 stopped the sweep there.
# Body size 0.8 mm (default 0.7): with the default the cell estimate (2.3e5 hexahedra, about twice
# the real count: it does not credit the coarse rims) exceeds the 3D limit of 2e5 (docs/limits.md).
if [ "$quick" = "--once-3d" ]; then
  dir=$(mktemp -d)
  times=()
  for _ in $(seq "$runs"); do
    start=$(date +%s.%N)
    "${mpi[@]}" --bind-to none -np 2 sh -c '/usr/bin/time -f "%M" -o "$0/rank$OMPI_COMM_WORLD_RANK.kb" "$@"' \
      "$dir" "$gearstiff" stiffness --set "Stiffness/mode=sweep" --set "Stiffness/sweep positions=32" \
      --set "Mesh/dimension=3" --set "Finite elements/Element degree=1" "${friction[@]}" \
      --set "Stiffness/sweep mesh=once" --set "Contact/Max iterations=500" --set "Mesh/body size=0.8" \
      --json >"$dir/out.json" 2>/dev/null
    end=$(date +%s.%N)
    times+=("$(echo "$end - $start" | bc)")
  done
  dofs=$(python3 -c "import json,sys; t=json.load(open(sys.argv[1]))['tables']['stiffness_sweep']; print(int(t['rows'][0][t['columns'].index('dofs')]))" "$dir/out.json")
  echo "| load average | $(cut -d' ' -f1-3 /proc/loadavg) |"
  echo "| 32-position sweep 3D Q1 8 layers once ($dofs DoFs), 2 ranks [s], median of $runs (${times[*]}) | $(median "${times[@]}") |"
  echo "| peak memory rank 0 / rank 1 [MB] | $(( $(cat "$dir/rank0.kb") / 1024 )) / $(( $(cat "$dir/rank1.kb") / 1024 )) |"
  # The same sweep per position (the reference, and `automatic` in 3D), one run.
  start=$(date +%s.%N)
  "${mpi[@]}" --bind-to none -np 2 sh -c '/usr/bin/time -f "%M" -o "$0/rank$OMPI_COMM_WORLD_RANK.kb" "$@"' \
    "$dir" "$gearstiff" stiffness --set "Stiffness/mode=sweep" --set "Stiffness/sweep positions=32" \
    --set "Mesh/dimension=3" --set "Finite elements/Element degree=1" "${friction[@]}" \
    --set "Stiffness/sweep mesh=per position" --set "Contact/Max iterations=500" \
    --set "Mesh/body size=0.8" >/dev/null 2>&1
  end=$(date +%s.%N)
  echo "| 32-position sweep 3D Q1 8 layers per position, 2 ranks [s], one run | $(echo "$end - $start" | bc) |"
  echo "| peak memory rank 0 / rank 1 [MB] | $(( $(cat "$dir/rank0.kb") / 1024 )) / $(( $(cat "$dir/rank1.kb") / 1024 )) |"
  rm -rf "$dir"
  exit 0
fi

# Rolling sweeps (issue 28, `Stiffness/sweep mesh = once`: each rank meshes one scene refined
# along every flank contact of the sweep, factorizes it once and turns the bodies rigidly to each
# position) against `per position` (a scene, mesh and factorization per position), default 2D
# pair, μ = 0.01, 1 rank; medians of `runs`, the ratio from medians taken in this one sitting.
# Peak memory (KB, /usr/bin/time %M) of one run each. The report's sweep_once_time and
# sweep_per_position_time split the once sweep into what was done once and per position.
# The load average is printed with the rows (the machine is shared).
once=(--set "Stiffness/sweep mesh=once")
peak_kb() { /usr/bin/time -f "%M" -o "$1" "${@:2}" >/dev/null 2>&1; cat "$1"; }
rolling_rows() {
  echo "| load average before the rolling rows | $(cut -d' ' -f1-3 /proc/loadavg) | | |"
  mem=$(mktemp)
  r128_once=$(median_seconds "$gearstiff" stiffness --set "Stiffness/mode=sweep" \
    --set "Stiffness/sweep positions=128" "${friction[@]}" "${once[@]}")
  r256_once=$(median_seconds "$gearstiff" stiffness --set "Stiffness/mode=sweep" \
    --set "Stiffness/sweep positions=256" "${friction[@]}" "${once[@]}")
  r128_per=$(median_seconds "$gearstiff" stiffness --set "Stiffness/mode=sweep" \
    --set "Stiffness/sweep positions=128" "${friction[@]}")
  m128_once=$(peak_kb "$mem" "$gearstiff" stiffness --set "Stiffness/mode=sweep" \
    --set "Stiffness/sweep positions=128" "${friction[@]}" "${once[@]}")
  m128_per=$(peak_kb "$mem" "$gearstiff" stiffness --set "Stiffness/mode=sweep" \
    --set "Stiffness/sweep positions=128" "${friction[@]}")
  echo "| 128-position sweep 2D, 1 rank [s]: once / per position; peak MB | $r128_once ($((m128_once / 1024)) MB) | $r128_per ($((m128_per / 1024)) MB) | $(echo "scale=2; $r128_per / $r128_once" | bc) |"
  echo "| 256-position sweep 2D once, 1 rank [s]; / 128 positions | $r256_once | | $(echo "scale=2; $r256_once / $r128_once" | bc) |"
  if [ "$quick" != "--quick" ]; then
    /usr/bin/time -f "%e %M" -o "$mem" "${mpi[@]}" -np 2 "$gearstiff" stiffness \
      --set "Stiffness/mode=sweep" --set "Stiffness/sweep positions=32" --set "Mesh/dimension=3" \
      --set "Finite elements/Element degree=1" "${friction[@]}" "${once[@]}" >/dev/null 2>&1
    read -r seconds kilobytes <"$mem"
    echo "| 32-position sweep 3D Q1 8 layers once, 2 ranks [s], one run | $seconds (peak $((kilobytes / 1024)) MB on the launcher's largest rank) | | |"
  fi
  rm -f "$mem"
  echo "| load average after the rolling rows | $(cut -d' ' -f1-3 /proc/loadavg) | | |"
}

# --once: only the rolling-sweep rows (one run each: ratios in one sitting).
if [ "$quick" = "--once" ]; then
  runs=1
  echo "| case | once | per position | ratio |"
  echo "|---|---|---|---|"
  rolling_rows
  exit 0
fi

echo "| case | Schur complement | full re-solve | ratio |"
echo "|---|---|---|---|"
wall=()
contact=()
for method in "Schur complement" "full re-solve"; do
  wall[${#wall[@]}]=$(median_seconds "$gearstiff" stiffness "${friction[@]}" \
    --set "Contact/Iteration solves=$method")
  contact[${#contact[@]}]=$("$gearstiff" stiffness "${friction[@]}" \
    --set "Contact/Iteration solves=$method" | report_value "contact iterations")
done
echo "| single pair 2D, process wall [s] | ${wall[0]} | ${wall[1]} | $(echo "scale=2; ${wall[1]} / ${wall[0]}" | bc) |"
echo "| single pair 2D, contact solve [s] (one run) | ${contact[0]} | ${contact[1]} | $(echo "scale=2; ${contact[1]} / ${contact[0]}" | bc) |"

sweep() { "${mpi[@]}" -np "$1" "$gearstiff" stiffness --set "Stiffness/mode=sweep" \
  --set "Stiffness/sweep positions=$2" "${friction[@]}" "${@:3}"; }
# 1 rank and 2 ranks alternately, `runs` rounds: medians of the process wall time and of the
# sweep's own wall time (the report's "wall time of the sweep": first position to the results
# gathered on every rank, without the process start-up (mpirun, ~200 shared libraries, MPI) and
# the report, which no number of ranks shortens).
declare -A process own
for round in $(seq "$runs"); do
  for ranks in 1 2; do
    start=$(date +%s.%N)
    out=$(sweep "$ranks" 32 2>/dev/null)
    end=$(date +%s.%N)
    process[$ranks]+="$(echo "$end - $start" | bc) "
    own[$ranks]+="$(echo "$out" | report_value "wall time of the sweep") "
  done
done
# shellcheck disable=SC2086
s32_1=$(median ${process[1]}) s32_2=$(median ${process[2]}) own_1=$(median ${own[1]}) own_2=$(median ${own[2]})
s128_2=$(median_seconds sweep 2 128)
echo "| 32-position sweep, 2 ranks [s] | $s32_2 | (was 105-130) | |"
echo "| 32-position sweep, 1 rank [s]; 2-rank speed-up of the process | $s32_1 | | $(echo "scale=2; $s32_1 / $s32_2" | bc) |"
echo "| 32-position sweep, the sweep's own wall time, 1 / 2 ranks [s]; 2-rank speed-up | $own_1 / $own_2 | | $(echo "scale=3; $own_1 / $own_2" | bc) |"
echo "| 128-position sweep, 2 ranks [s]; cost / 32 positions | $s128_2 | | $(echo "scale=2; $s128_2 / $s32_2" | bc) |"
echo "| gearstiff run, 1 rank [s] | $(median_seconds "$gearstiff" run) | (was 94) | |"

# Σ of the per-position active-set iterations of a 32-position sweep (the JSON report's sweep
# table, column "iterations").
sweep_iterations() {
  sweep 2 32 --json "$@" 2>/dev/null | python3 -c '
import json, sys
def find(node):
    if isinstance(node, dict):
        for value in node.values():
            found = find(value)
            if found is not None:
                return found
        if "columns" in node and "rows" in node:
            columns = [c if isinstance(c, str) else c.get("name", "") for c in node["columns"]]
            for k, name in enumerate(columns):
                if "iteration" in name:
                    return sum(row[k] for row in node["rows"])
    elif isinstance(node, list):
        for value in node:
            found = find(value)
            if found is not None:
                return found
    return None
print(int(find(json.load(sys.stdin))))'
}
warm=$(sweep_iterations --set "Contact/Warm start=true")
cold=$(sweep_iterations --set "Contact/Warm start=false")
echo "| 32-position sweep, active-set iterations (Σ over positions), one run | $warm (warm start) | $cold (cold start) | $(echo "scale=2; $cold / $warm" | bc) |"

if [ "$quick" != "--quick" ]; then
  log=$(mktemp)
  /usr/bin/time -f "%e %M" -o "$log.time" "${mpi[@]}" -np 2 "$gearstiff" stiffness \
    --set "Mesh/dimension=3" --set "Finite elements/Element degree=1" "${friction[@]}" >"$log"
  read -r seconds kilobytes <"$log.time"
  echo "| 3D Q1 8 layers ($(grep -oE '[0-9]+ DoFs' "$log" | head -1)), 2 ranks [s], one run | $seconds (peak $((kilobytes / 1024)) MB on the launcher's largest rank) | (was 267) | |"
  rm -f "$log" "$log.time"
fi
rolling_rows
