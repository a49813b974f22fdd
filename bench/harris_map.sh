#!/usr/bin/env bash
# Speed of the loaded-TE studies (issue 27), 2D default scene, 2 ranks (mpirun -np 2):
#   - a Harris map of 8 torques × 32 positions: target ≤ 25 s (256 separate solves ≈ 70 s); one
#     scene and one factorization per position serve all 8 torques (GearMeshStiffness::run_torques);
#   - one modification variant more (Stiffness/variants) costs ≤ 1.2× a plain 32-position sweep.
# Each case runs `rounds` times (default 3); the median process wall time is printed.
# usage: bench/harris_map.sh [path/to/gearstiff] [rounds] [sweep mesh]
#   (default build/app/gearstiff, 3, "automatic" = the CLI default, once in 2D: each rank meshes
#   and factorizes one scene for all its positions and torques, issue 28; "per position": a scene
#   and factorization per position)
set -euo pipefail
gearstiff=${1:-$(dirname "$0")/../build/app/gearstiff}
rounds=${2:-3}
mesh=${3:-automatic}
mpi=(mpirun --allow-run-as-root --oversubscribe --bind-to none -np 2)
export OMP_NUM_THREADS=1
seconds() { local start=$(date +%s.%N); "$@" >/dev/null; echo "$(date +%s.%N) - $start" | bc; }
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
relief=(--set "Gear pair/Pinion/tip relief=6" --set "Gear pair/Wheel/tip relief=6")
sweep=(stiffness --set "Stiffness/mode=sweep" --set "Stiffness/sweep positions=32"
  --set "Stiffness/sweep mesh=$mesh")
torques="12.35, 24.7, 37.05, 49.4, 61.75, 74.1, 86.45, 98.8"
plain=() map=() variant=()
for ((r = 0; r < rounds; ++r)); do
  plain+=("$(seconds "${mpi[@]}" "$gearstiff" "${sweep[@]}" "${relief[@]}")")
  map+=("$(seconds "${mpi[@]}" "$gearstiff" "${sweep[@]}" "${relief[@]}" \
    --set "Stiffness/torques=$torques")")
  variant+=("$(seconds "${mpi[@]}" "$gearstiff" "${sweep[@]}" "${relief[@]}" \
    --set "Stiffness/variants=tip relief = 10")")
done
p=$(median "${plain[@]}") m=$(median "${map[@]}") v=$(median "${variant[@]}")
echo "sweep mesh = $mesh; load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo "plain 32-position sweep (relief 6 µm), 2 ranks: median $p s (${plain[*]})"
echo "Harris map 8 torques × 32 positions, 2 ranks: median $m s (${map[*]}), target ≤ 25 s"
echo "sweep + one variant, 2 ranks: median $v s (${variant[*]}): variant costs" \
  "$(echo "($v - $p) / $p" | bc -l | cut -c1-5)× a plain sweep, target ≤ 1.2"
