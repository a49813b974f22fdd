#!/usr/bin/env bash
# The influence-coefficient model a gear a rank (docs/ltca.md "Cost", "A gear a rank") against
# a build before it, in one sitting: three rounds of each case with each binary, process wall and
# peak RSS of the larger rank (/usr/bin/time -v around mpirun). Cases: the helical built-in pair
# at β ±15° (13 layers, Q1, μ 0) 32 positions and the Harris map 8 torques × 32 positions on 2
# ranks (issue 47's 30 s and 90 s; binaries before 2026-12-05 refuse helical pairs in this model
# and need that refusal lifted by hand, as bench/ltca_helical_speed.sh says);
# the spur 3D pair (8 layers, 32 positions) on 1 and 2 ranks; the 2D pair (128 positions) on 1.
# usage: flock /tmp/gearstiff-build.lock bash bench/ltca_ranks.sh OLD_BINARY NEW_BINARY [work]
set -u
here=$(cd "$(dirname "$0")" && pwd)
old=${1:?binary before}
new=${2:?binary after}
work=${3:-$(mktemp -d)}
mkdir -p "$work" && cd "$work" || exit 1
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
common=(stiffness --json --set "Stiffness/mode=sweep" --set "Stiffness/contact model=influence coefficients")
solid=(--set "Mesh/dimension=3" --set "Finite elements/Element degree=1" --set "Contact/Friction coefficient=0"
  --set "Stiffness/sweep positions=32")
helical=("${common[@]}" "${solid[@]}" --set "Gear pair/Pinion/helix angle=15" --set "Gear pair/Wheel/helix angle=-15")
spur=("${common[@]}" "${solid[@]}" --set "Mesh/layers=8")
plane=("${common[@]}" --set "Stiffness/sweep positions=128")
torques="12.35, 24.7, 37.05, 49.4, 61.75, 74.1, 86.45, 98.8"
one() { # name ranks command...
  local name=$1 ranks=$2
  shift 2
  /usr/bin/time -v mpirun -np "$ranks" --bind-to none "$@" > "$name.json" 2> "$name.err"
  w=$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, t, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + t[i]; print s}' "$name.err")
  m=$(awk -F': ' '/Maximum resident set size/ {print $2/1024}' "$name.err")
  echo "$name: wall $w s, peak RSS $m MB"
}
echo "load average $(cut -d' ' -f1-3 /proc/loadavg); $(date -u)"
for r in 1 2 3; do
  for build in old new; do
    gs=$new
    [ $build = old ] && gs=$old
    one "helical_sweep_np2_${build}_$r" 2 "$gs" "${helical[@]}"
    one "helical_map_np2_${build}_$r" 2 "$gs" "${helical[@]}" --set "Stiffness/torques=$torques"
    one "spur3d_np1_${build}_$r" 1 "$gs" "${spur[@]}"
    one "spur3d_np2_${build}_$r" 2 "$gs" "${spur[@]}"
    one "plane_np1_${build}_$r" 1 "$gs" "${plane[@]}"
  done
done
echo "load average $(cut -d' ' -f1-3 /proc/loadavg); $(date -u)"
# How the time splits (the model's report; factorization and coefficients: the slowest rank's).
python3 "$here/influence_split.py" helical_sweep_np2_*_1.json spur3d_np2_*_1.json
