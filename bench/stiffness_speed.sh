#!/usr/bin/env bash
# Speed targets of the mesh-stiffness solver (issue 5), measured on this machine:
#   - default single-pair 2D stiffness (< 1% discretization error) on one core: target < 10 s;
#   - a 32-position k(θ) sweep on 2 cores (mpirun -np 2): target < 2 min, about half of 1 rank;
#     with the published μ = 0.01 and, for the cost of friction, without it.
# usage: bench/stiffness_speed.sh [path/to/gearstiff]   (default build/app/gearstiff)
set -euo pipefail
gearstiff=${1:-$(dirname "$0")/../build/app/gearstiff}
mpi=(mpirun --allow-run-as-root --oversubscribe)
export OMP_NUM_THREADS=1
seconds() { local start=$(date +%s.%N); "$@" >/dev/null; echo "$(date +%s.%N) - $start" | bc; }

echo "single pair, default scene, 1 rank: $(seconds "$gearstiff" stiffness) s (process wall time)"
"$gearstiff" stiffness --json | grep -E '"(mesh_stiffness|time_total|dofs)"' | sed 's/, "description.*//'
for mu in 0.01 0; do
  for ranks in 1 2; do
    echo "32-position sweep, mu = $mu, $ranks rank(s): $(seconds "${mpi[@]}" -np $ranks \
      "$gearstiff" stiffness --set "Stiffness/mode=sweep" --set "Stiffness/sweep positions=32" \
      --set "Contact/Friction coefficient=$mu") s"
  done
done
echo "gearstiff run (whole chain), 2 ranks: $(seconds "${mpi[@]}" -np 2 "$gearstiff" run) s"
