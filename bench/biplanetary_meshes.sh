#!/usr/bin/env bash
# FE stiffness of the four meshes of the bi-planetary train (docs/references.md §2; issue 14's last
# deliverable, the inputs of docs/biplanetary_dynamics.md): for each mesh 1-2, 3-4, 4-5, 6-7 the
# k(θ) sweep over one base pitch (24 positions), the single- and double-contact positions, all
# with bench/biplanetary_meshes/<pair>.prm (assumptions stated there), on 2 ranks.
# Keeps bench/biplanetary_meshes/<pair>/{sweep,single,double}.json (summary.json of -o) and the
# sweep's CSV table; prints the wall time per mesh. Run it holding the build lock:
#   flock /tmp/gearstiff-build.lock bench/biplanetary_meshes.sh [path/to/gearstiff [pairs...]]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
gearstiff=${1:-$here/../build/app/gearstiff}
pairs=("${@:2}")
[ ${#pairs[@]} -gt 0 ] || pairs=(1-2 3-4 4-5 6-7)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
mpi=(mpirun --oversubscribe -np 2)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for pair in "${pairs[@]}"; do
  dir=$here/biplanetary_meshes/$pair
  mkdir -p "$dir"
  start=$(date +%s.%N)
  for mode in sweep single double; do
    rm -rf "$work/$mode"
    "${mpi[@]}" "$gearstiff" stiffness "$here/biplanetary_meshes/$pair.prm" \
      --set "Stiffness/mode=$mode" -o "$work/$mode" >/dev/null
    cp "$work/$mode/summary.json" "$dir/$mode.json"
  done
  cp "$work/sweep/"*stiffness_sweep*.csv "$dir/" 2>/dev/null || true
  python3 - "$dir" "$(echo "$(date +%s.%N) - $start" | bc)" <<'PY'
import json, sys
d = sys.argv[1]
v = lambda name, key: json.load(open(f"{d}/{name}.json"))["values"][key]["value"]
print(f"{d.rsplit('/', 1)[1]}: eps_alpha {v('sweep', 'contact_ratio'):.4f}, "
      f"k single {v('single', 'mesh_stiffness'):.1f}, double {v('double', 'mesh_stiffness'):.1f}, "
      f"sweep mean {v('sweep', 'mean_stiffness'):.1f} N/um; wall {float(sys.argv[2]):.1f} s")
PY
done
