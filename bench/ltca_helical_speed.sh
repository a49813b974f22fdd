#!/usr/bin/env bash
# Speed of the helical influence-coefficient model (issue 47's targets: 3D helical, 32 positions,
# 2 ranks ≤ 30 s; Harris map 8 torques × 32 positions ≤ 90 s): the built-in pair at β ±15°
# (ε_β 0.79) at the default sizes (13 layers), Q1, μ 0; three rounds of both, process wall and
# peak RSS of the larger rank (/usr/bin/time -v around mpirun). The model takes helical pairs since
# 2026-12-05 (docs/ltca.md §3 "Helical pairs accepted"); the measurements before that date
# (bench/ltca_helical_speed_2026-12-04.txt) ran binaries with the refusal lifted by hand.
# usage: flock /tmp/gearstiff-build.lock bash bench/ltca_helical_speed.sh path/to/gearstiff [work]
set -u
here=$(cd "$(dirname "$0")" && pwd)
gs=${1:?path to a gearstiff binary}
work=${2:-$(mktemp -d)}
mkdir -p "$work" && cd "$work" || exit 1
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
base=(stiffness --json --set "Mesh/dimension=3" --set "Finite elements/Element degree=1" --set "Contact/Friction coefficient=0"
  --set "Gear pair/Pinion/helix angle=15" --set "Gear pair/Wheel/helix angle=-15"
  --set "Stiffness/mode=sweep" --set "Stiffness/sweep positions=32" --set "Stiffness/contact model=influence coefficients")
torques="12.35, 24.7, 37.05, 49.4, 61.75, 74.1, 86.45, 98.8"
echo "load average $(cut -d' ' -f1-3 /proc/loadavg); $(date -u)"
for r in 1 2 3; do
  for kind in sweep map; do
    extra=()
    [ $kind = map ] && extra=(--set "Stiffness/torques=$torques")
    /usr/bin/time -v mpirun -np 2 --bind-to none $gs "${base[@]}" "${extra[@]}" > speed_${kind}_$r.json 2> speed_${kind}_$r.err
    w=$(awk -F': ' '/Elapsed \(wall clock\)/ {n = split($2, t, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + t[i]; print s}' speed_${kind}_$r.err)
    m=$(awk -F': ' '/Maximum resident set size/ {print $2/1024}' speed_${kind}_$r.err)
    echo "$kind run $r: wall $w s, peak RSS $m MB (the larger rank)"
  done
done
echo "load average $(cut -d' ' -f1-3 /proc/loadavg); $(date -u)"
# How the time splits (the model's report): FE body DoFs, scene, assembly and factorization,
# coefficients, all contact problems, the sweep.
python3 "$here/influence_split.py" speed_sweep_*.json speed_map_*.json
