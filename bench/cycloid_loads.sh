#!/usr/bin/env bash
# Cycloid drive under load (issue 13), measured on this machine:
#   - one crank position of the built-in case (20 rollers, 8 pins, 2D, nominal), one core:
#     target <= 10 s at <= 1% error in P_max (three runs, the wall time of each);
#   - refinement study: every mesh size scaled by 1, 0.7, 0.5, 0.35 (contact, body, rim and the
#     growth rate, so that the whole size field scales; the fine radius stays), P_max / Q_max;
#   - a 16-position crank-angle sweep on 1 and 2 ranks (target <= 2 min on 2).
# usage: bench/cycloid_loads.sh [path/to/gearstiff]   (default build/app/gearstiff)
set -euo pipefail
gearstiff=${1:-$(dirname "$0")/../build/app/gearstiff}
mpi=(mpirun --allow-run-as-root --oversubscribe)
export OMP_NUM_THREADS=1
one=(--set "Cycloid loads/profiles=nominal" --set "Cycloid loads/torsional curve=false")
seconds() { local start=$(date +%s.%N); "$@" >/dev/null 2>&1; echo "$(date +%s.%N) - $start" | bc; }

for run in 1 2 3; do
  echo "one position, nominal, 1 rank, run $run: $(seconds "$gearstiff" cycloid-loads "${one[@]}") s"
done
profile=(n_dofs max_roller_force max_pin_force solve_wall_time meshing_time meshing_attempts read_time
  setup_time factorization_time iteration_time evaluate_time active_set_iterations)
echo "profile of one position (${profile[*]}):"
"$gearstiff" cycloid-loads "${one[@]}" --json 2>/dev/null |
  python3 -c "import json,sys; v=json.load(sys.stdin)['values']; print(*(round(v[k]['value'], 4) for k in '${profile[*]}'.split()))"
echo "refinement (size factor, DoFs, P_max [N], Q_max [N], wall [s]):"
for f in 1 0.7 0.5 0.35; do
  sizes=$(python3 -c "f=$f; print(' '.join('%.6g' % (v*f) for v in (0.08, 2, 8, 0.4)))")
  read -r hc body rim growth <<<"$sizes"
  "$gearstiff" cycloid-loads "${one[@]}" --json --set "Mesh/contact size=$hc" \
    --set "Mesh/body size=$body" --set "Mesh/rim size=$rim" --set "Mesh/growth rate=$growth" \
    2>/dev/null |
    python3 -c "import json,sys; v=json.load(sys.stdin)['values']; print('$f', *(v[k]['value'] for k in ('n_dofs','max_roller_force','max_pin_force','solve_wall_time')))"
done
for ranks in 1 2; do
  echo "16-position sweep, nominal, $ranks rank(s): $(seconds "${mpi[@]}" -np $ranks "$gearstiff" \
    cycloid-loads "${one[@]}" --set "Cycloid loads/sweep positions=16") s"
done
