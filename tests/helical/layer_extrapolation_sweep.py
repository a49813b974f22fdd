#!/usr/bin/env python3
"""`Mesh/layer extrapolation = richardson` on a helical sweep (issue 46, stiffness/
layer_extrapolation.h): the command's two levels are the plain sweeps on L and 2L layers, and
every position's extrapolated k is Richardson's in the pinion rotation from them.

usage: layer_extrapolation_sweep.py path/to/gearstiff WORK_FOLDER [MPIEXEC]

The small coarse pair of tests/helical/small_pair.py (z 19/29, m_n 2 mm, β ±10°, b 8 mm, Q1,
frictionless; 5 layers), a 4-position rolling (`once`) sweep on 2 ranks (1 without MPIEXEC),
run three times: with the extrapolation, and plainly on 5 and on 10 layers. Checked, at every
position (exact oracles of the construction, not measured values):
- the command's 5- and 10-layer columns are the plain sweeps' k (1e-9: each level is the plain
  sweep — the same scene, body size and rank split; the JSON prints 12 digits);
- its k is 1/k∞ = 1/k(2L) + (1/k(2L) − 1/k(L))/3 (1e-9), and the stiffness_sweep table carries it;
- its TE is the 10-layer TE plus r_b1·(Δφ∞ − Δφ(2L)), i.e. TE∞ − TE(2L) = T1/r_b1·(1/k∞ −
  1/k(2L)) (1e-6 µm; T1 = 20 N·m, r_b1 from the report);
- the load shares still sum to 1 (1e-9: a linear combination of two sets that do).
Measured 2026-12-03 (2 ranks): corrections +0.17 … +0.36 %, the command 17 s.
"""
import json
import os
import shlex
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from small_pair import MESH, PAIR  # noqa: E402

SWEEP = ["Stiffness/mode=sweep", "Stiffness/sweep positions=4", "Stiffness/sweep mesh=once",
         "Finite elements/Element degree=1", "Contact/Friction coefficient=0",
         "Stiffness/published reference=false"]
TORQUE = 20.  # N·m, small_pair.PAIR's


def run(gearstiff, launcher, work, layers, extrapolate):
    args = launcher + [gearstiff, "stiffness", "--json", "--quiet"]
    entries = PAIR + [m for m in MESH if not m.startswith("Mesh/layers=")] + SWEEP + [
        f"Mesh/layers={layers}"]
    if extrapolate:
        entries.append("Mesh/layer extrapolation=richardson")
    for entry in entries:
        args += ["--set", entry]
    out = subprocess.run(args, cwd=work, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"layer_extrapolation_sweep: {layers} layers exited {out.returncode}: "
                 f"{out.stderr[-800:]}")
    return json.loads(out.stdout)


def rows(report, name):
    t = report["tables"][name]
    return [dict(zip(t["columns"], row)) for row in t["rows"]]


def main():
    gearstiff, work = sys.argv[1], sys.argv[2]
    launcher = (shlex.split(sys.argv[3].replace(";", " ")) + ["-np", "2"]
                if len(sys.argv) > 3 and sys.argv[3] else [])
    os.makedirs(work, exist_ok=True)
    extrapolated = run(gearstiff, launcher, work, 5, True)
    plain = {n: rows(run(gearstiff, launcher, work, n, False), "stiffness_sweep") for n in (5, 10)}
    levels = rows(extrapolated, "layer_extrapolation")
    sweep = rows(extrapolated, "stiffness_sweep")
    r_b1 = extrapolated["values"]["pinion_base_radius"]["value"] * 1e-3  # m
    failures = []

    def close(what, a, b, tolerance):
        if not abs(a - b) <= tolerance * max(1., abs(b)):
            failures.append(f"{what}: {a!r} against {b!r} (tolerance {tolerance})")

    for i, (level, row) in enumerate(zip(levels, sweep)):
        k1, k2, k = level["stiffness_5_layers"], level["stiffness_10_layers"], level["stiffness"]
        close(f"position {i + 1}: 5-layer level", k1 / plain[5][i]["stiffness"], 1., 1e-9)
        close(f"position {i + 1}: 10-layer level", k2 / plain[10][i]["stiffness"], 1., 1e-9)
        close(f"position {i + 1}: Richardson in the rotation",
              k * (1. / k2 + (1. / k2 - 1. / k1) / 3.), 1., 1e-9)
        close(f"position {i + 1}: stiffness_sweep's k", row["stiffness"] / k, 1., 1e-9)
        # µm: T1/r_b1 (N) · (1/k) (µm/N, k in N/µm).
        expected_te = plain[10][i]["transmission_error"] + TORQUE / r_b1 * (1. / k - 1. / k2)
        close(f"position {i + 1}: TE", row["transmission_error"], expected_te, 1e-6)
        close(f"position {i + 1}: load shares",
              sum(row.get(c, 0.) for c in ("share_pair_m1", "share_pair_0", "share_pair_p1")),
              1., 1e-9)
        print(f"position {i + 1}: k {k1:.4f} (5 layers), {k2:.4f} (10) -> {k:.4f} N/um "
              f"({level['correction']:+.3f} %)")
    for failure in failures:
        print("  fails: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
