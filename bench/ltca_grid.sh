#!/usr/bin/env bash
# Accuracy against cost of `Stiffness/contact model = influence coefficients` (issue 47,
# docs/ltca.md): the 2D default pair, 32 positions, frictionless, exact rolling sweep (sweep mesh
# once, h_c 0.03 mm: k within 0.08 % of h_c 0.015 mm, measured 2026-12-02) against the fast model
# at several `Stiffness/influence grid points` (below 40 the grid step exceeds the matching depth
# and the model refuses). Prints worst |Δk|, |ΔTE| and the sweep's wall time of each.
# usage: flock /tmp/gearstiff-build.lock bash bench/ltca_grid.sh [path/to/gearstiff]
set -euo pipefail
gearstiff=${1:-$(dirname "$0")/../build/app/gearstiff}
export OMP_NUM_THREADS=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sweep=(stiffness --quiet --set "Stiffness/mode=sweep" --set "Stiffness/sweep positions=32"
  --set "Contact/Friction coefficient=0" --json)
"$gearstiff" "${sweep[@]}" >"$work/exact.json"
for grid in ${LTCA_GRIDS:-40 64 128 256}; do
  "$gearstiff" "${sweep[@]}" --set "Stiffness/contact model=influence coefficients" \
    --set "Stiffness/influence grid points=$grid" >"$work/fast_$grid.json"
done
python3 - "$work" ${LTCA_GRIDS:-40 64 128 256} <<'PY'
import json, sys
work, grids = sys.argv[1], sys.argv[2:]
def load(name):
    text = open(f"{work}/{name}.json").read()
    d = json.loads(text[text.index("{"):])
    t = d["tables"]["stiffness_sweep"]
    cols = t["columns"]
    rows = [dict(zip(cols, r)) for r in t["rows"]]
    return d["values"], rows
ev, er = load("exact")
print(f"exact: sweep wall {ev['sweep_wall_time']['value']:.3f} s")
print("| grid points | step [mm] | worst |Δk| [%] | worst |ΔTE| [µm] | worst |Δp_max| vs exact [%] | sweep wall [s] |")
print("|---:|---:|---:|---:|---:|---:|")
for g in grids:
    fv, fr = load(f"fast_{g}")
    dk = max(abs(b["stiffness"] / a["stiffness"] - 1) for a, b in zip(er, fr)) * 100
    dte = max(abs(b["transmission_error"] - a["transmission_error"]) for a, b in zip(er, fr))
    dp = max(abs(b["max_pressure"] / a["max_pressure"] - 1) for a, b in zip(er, fr)) * 100
    print(f"| {g} | {fv['influence_grid_step']['value']:.3f} | {dk:.3f} | {dte:.4f} | {dp:.1f} | "
          f"{fv['sweep_wall_time']['value']:.3f} |")
PY
