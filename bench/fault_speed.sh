#!/usr/bin/env bash
# Speed target of issue 31: a faulty-tooth pass (the positions where the faulty tooth meshes,
# from A over ε_α = 1.5 base pitches of the split-path pair) at most 1.5 times a healthy sweep of
# the same positions. Both are `gearstiff stiffness` sweeps, the faulty one with a 1 mm root crack
# on pinion tooth 0 (the reference pair, in mesh throughout; its slit meshed with 20 µm cells
# along the faces and 10 µm at the tip). `sweep mesh` (automatic | per position | once) applies to
# both: a cracked scene rolls like a healthy one (its flanks are whole), so `automatic` (the CLI
# default) rolls both in 2D; broken, chipped or spalled teeth are meshed per position. Each pair of runs is repeated `repeats` times in one sitting and the
# medians and the ratio of the medians printed. One rank; run under flock (both cores are shared).
# usage: bench/fault_speed.sh [positions (64)] [sweep mesh (automatic)] [repeats (3)] [gearstiff]
set -euo pipefail
positions=${1:-64}
mesh=${2:-automatic}
repeats=${3:-3}
gearstiff=${4:-$(dirname "$0")/../build/app/gearstiff}
export OMP_NUM_THREADS=1
seconds() { local start=$(date +%s.%N); "$@" >/dev/null; echo "$(date +%s.%N) - $start" | bc; }
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR + 1) / 2)]}'; }
sweep=(stiffness --set "Stiffness/mode=sweep" --set "Stiffness/sweep positions=$positions"
  --set "Stiffness/sweep base pitches=1.5" --set "Stiffness/sweep mesh=$mesh" --quiet)
healthy=() cracked=()
for ((i = 0; i < repeats; ++i)); do
  healthy+=("$(seconds "$gearstiff" "${sweep[@]}")")
  cracked+=("$(seconds "$gearstiff" "${sweep[@]}" --set "Gear pair/Pinion/crack depth=1")")
done
h=$(median "${healthy[@]}") c=$(median "${cracked[@]}")
echo "sweep mesh = $mesh, $positions positions over 1.5 base pitches, $repeats runs each"
echo "healthy sweep: ${healthy[*]} s (median $h s)"
echo "1 mm root crack on the reference tooth: ${cracked[*]} s (median $c s)"
echo "ratio of the medians: $(echo "scale=3; $c / $h" | bc) (target <= 1.5)"
