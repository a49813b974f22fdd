#!/usr/bin/env bash
# Meshing cost of the FE scenes (`gearstiff mesh`): cells, quality and wall time per scene,
# repeated to show the spread on a shared machine. Writes bench/results/mesh_scenes.csv.
#
#   bash bench/mesh_scenes.sh [path/to/gearstiff] [repeats]
#
# Target (issue 3): a 2D single-position gear scene meshes in under 1 s. The machine is shared
# (2 cores, load 6-9 while others compile), so wall times scatter by 2x; cpu_s (user + system
# time of the whole command, including MPI/deal.II start-up of ~0.2 s) is the stable figure.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
binary=${1:-$here/../build-scene/app/gearstiff}
repeats=${2:-3}
out=$here/results
mkdir -p "$out"
csv=$out/mesh_scenes.csv
echo "scene,repeat,cells,vertices,min_scaled_jacobian,contact_size_mm,largest_edge_over_h_c,attempts,time_meshing_s,time_total_s,cpu_s,load_average" > "$csv"

run() {
  local name=$1; shift
  for r in $(seq 1 "$repeats"); do
    local load
    load=$(cut -d' ' -f1 /proc/loadavg)
    /usr/bin/time -f "%U %S" -o "$out/.cpu" "$binary" mesh --json "$@" 2>/dev/null > "$out/.json"
    local cpu
    cpu=$(awk '{print $1 + $2}' "$out/.cpu")
    python3 -c "
import json, sys
v = {k: x['value'] for k, x in json.load(sys.stdin)['values'].items()}
print(','.join(str(s) for s in ['$name', $r, v['cells'], v['vertices'], v['min_scaled_jacobian'],
      v['contact_size'], v['largest_edge_ratio_at_contact'], v['meshing_attempts'],
      v['time_meshing'], v['time_total'], $cpu, $load]))" < "$out/.json" >> "$csv"
  done
}

run gear_2d_single
run gear_2d_double --set "Gear pair scene/position=double"
run gear_2d_single_full_rim --set "Gear pair scene/rim=full"
run gear_2d_single_3teeth --set "Gear pair scene/pinion teeth modelled=3" \
  --set "Gear pair scene/wheel teeth modelled=3"
run gear_3d_single_8layers --set "Mesh/dimension=3" --set "Mesh/layers=8"
run cylinders_2d --set "Scene/type=cylinders"
run cycloid_2d_nominal --set "Scene/type=cycloid"

rm -f "$out/.cpu" "$out/.json"
column -s, -t < "$csv"
