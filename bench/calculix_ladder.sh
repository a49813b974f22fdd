#!/usr/bin/env bash
# The CalculiX ladder of docs/accuracy.md's accuracy-against-cost chart (issue 16): the single-pair
# scene of bench/accuracy_cost.py (its size field times 1, 1/√2, 1/2; μ = 0) solved on the same
# mesh by gearstiff (FE_Q(1)) and by ccx (C3D8 slice, K = 10 and 100 E/h_c, extrapolated to
# K -> ∞). Writes bench/calculix_ladder.csv in bench/accuracy_results.csv's columns; errors are
# against the converged reference of that file (Q2, finest level: 281.264607442 N/µm). The cost
# of a CalculiX point is both penalty solves (process wall time, one core, the deck's export not
# included); of a gearstiff point the `gearstiff stiffness` process wall time (meshing included).
# About 3 minutes. usage: bench/calculix_ladder.sh [path/to/gearstiff]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
gearstiff=${1:-$here/../build/app/gearstiff}
out=$here/calculix_ladder.csv
work=$(mktemp -d)
rm -f "$out"
for factor in 1 0.7071067811865475 0.5; do
  "$here/calculix_compare.sh" "$gearstiff" --ladder --positions single --size-scale "$factor" \
    --work "$work/$factor" --accuracy-csv "$out" --reference 281.264607442 | tail -1
done
rm -rf "$work"
echo "calculix_ladder: $out"
