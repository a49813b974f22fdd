#!/usr/bin/env bash
# Speed target of issue 31: a faulty-tooth pass (the positions where the faulty tooth meshes,
# from A over ε_α = 1.5 base pitches of the split-path pair) at most 1.5 times a healthy sweep of
# the same positions. Both are `gearstiff stiffness` sweeps per position (a new scene each), the
# faulty one with a 1 mm root crack on pinion tooth 0 (the reference pair, in mesh throughout;
# its slit is meshed with 10 µm cells at the tip) or a broken tooth (its single-contact positions
# are refused: run with the crack only). One rank; run under flock (both cores are shared).
# usage: bench/fault_speed.sh [positions (64)] [path/to/gearstiff]
set -euo pipefail
positions=${1:-64}
gearstiff=${2:-$(dirname "$0")/../build/app/gearstiff}
export OMP_NUM_THREADS=1
seconds() { local start=$(date +%s.%N); "$@" >/dev/null; echo "$(date +%s.%N) - $start" | bc; }
sweep=(stiffness --set "Stiffness/mode=sweep" --set "Stiffness/sweep positions=$positions"
  --set "Stiffness/sweep base pitches=1.5" --quiet)
healthy=$(seconds "$gearstiff" "${sweep[@]}")
cracked=$(seconds "$gearstiff" "${sweep[@]}" --set "Gear pair/Pinion/crack depth=1")
echo "healthy sweep, $positions positions over 1.5 base pitches: $healthy s"
echo "1 mm root crack on the reference tooth, same positions:  $cracked s"
echo "ratio: $(echo "scale=3; $cracked / $healthy" | bc) (target <= 1.5)"
