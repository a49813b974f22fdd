#!/usr/bin/env python3
"""Refinement study of the internal (ring-planet) single-pair mesh stiffness, 2D and 3D.

The pair of docs/internal-gears.md: planet 24 / ring 69, m = 2.5 mm, x = 0, ring tip 170 mm,
widths 26/24 mm, planet bore 20 mm, ring rim s_R = 5·m = 12.5 mm held on its whole outer circle,
T1 = 49.4 N·m, μ = 0, single-pair position. Each point is one `gearstiff stiffness --json` run on
one rank (3D: two ranks through mpirun).

Levels: the default stiffness scene's size field (contact 0.03 mm, body 0.7 mm, rim 2.8 mm,
growth rate 0.35; `contact::default_stiffness_scene()`) times f = √2, 1, 1/√2, 1/2, every size
scaled together (the fine radius kept), with element degree 2 (the default) and 1. The
reference is the Richardson extrapolation of the Q2 ladder's three finest levels when they
converge monotonically, else its finest level; the default's discretisation error is stated
against it. 3D: hexahedra extruded over the face width (free faces), Q1 on the coarse ×2 field
(contact 0.06 mm) with 2 layers, against plane strain and plane stress on the same transverse
mesh — the energy bound puts 3D between the two.

usage: bench/internal_refinement.py [--gearstiff build/app/gearstiff] [--out bench] [--no-3d]
Writes internal_refinement.csv into --out and prints the table of docs/internal-gears.md.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

# The planet-ring pair of docs/internal-gears.md as command-line settings (mm, degrees).
PLANET_RING = {
    "Gear pair/Pinion/teeth": 24,
    "Gear pair/Wheel/teeth": 69,
    "Gear pair/Wheel/internal": "true",
    "Gear pair/Pinion/profile shift": 0,
    "Gear pair/Wheel/profile shift": 0,
    "Gear pair/Pinion/tip diameter": 0,
    "Gear pair/Wheel/tip diameter": 170,
    "Gear pair/Wheel/bore diameter": 0,
    "Gear pair scene/wheel rim thickness": 12.5,
    "Contact/Friction coefficient": 0,
}
# The default stiffness scene's size field (mm; growth rate in mm/mm).
DEFAULT_SIZES = {"Mesh/contact size": 0.03, "Mesh/body size": 0.7, "Mesh/rim size": 2.8,
                 "Mesh/growth rate": 0.35}


def run_stiffness(binary, settings, ranks=1):
    args = [binary, "stiffness", "--json"]
    for key, value in settings.items():
        args += ["--set", f"{key}={value}"]
    if ranks > 1:
        args = ["mpirun", "--oversubscribe", "-np", str(ranks)] + args
    env = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    done = subprocess.run(args, capture_output=True, text=True, env=env)
    if done.returncode != 0:
        raise RuntimeError(f"exit {done.returncode}: {done.stderr.strip()}")
    values = json.loads(done.stdout)["values"]
    return {"stiffness": values["mesh_stiffness"]["value"], "dofs": values["dofs"]["value"],
            "solve_time": values["time_total"]["value"]}


def gearstiff_parser(doc):
    """The command-line parser of the internal_* benches with its --gearstiff option."""
    parser = argparse.ArgumentParser(description=doc,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--gearstiff", default=os.path.join(here, "..", "build", "app", "gearstiff"))
    return parser


def sized(factor):
    return {key: value * factor for key, value in DEFAULT_SIZES.items()}


def richardson(levels):
    """k at h -> 0 from the three finest (factor, k) levels of constant ratio; None when the
    differences change sign or do not shrink (not in the asymptotic range)."""
    (_, k0), (f1, k1), (f2, k2) = levels[-3:]
    d1, d2 = k1 - k0, k2 - k1
    if d1 * d2 <= 0 or abs(d2) >= abs(d1):
        return None, None
    ratio = f1 / f2
    order = math.log(d1 / d2) / math.log(ratio)
    return k2 + d2 / (ratio ** order - 1.0), order


def main():
    parser = gearstiff_parser(__doc__)
    parser.add_argument("--out", default=os.path.dirname(os.path.abspath(__file__)))
    parser.add_argument("--no-3d", action="store_true")
    options = parser.parse_args()

    root2 = math.sqrt(2.0)
    factors = [root2, 1.0, 1 / root2, 0.5]
    rows = []

    def record(variant, degree, model, factor, settings, ranks=1):
        try:
            result = run_stiffness(options.gearstiff, {**PLANET_RING, **settings}, ranks)
        except RuntimeError as error:
            print(f"{variant:22s} f {factor:5.3f}: FAILED ({error})", flush=True)
            return
        rows.append({"variant": variant, "degree": degree, "model": model, "size_factor": factor,
                     **result})
        print(f"{variant:22s} f {factor:5.3f}: k = {result['stiffness']:9.3f} N/um, "
              f"{int(result['dofs']):7d} DoFs, {result['solve_time']:6.2f} s", flush=True)

    for degree in (2, 1):
        for factor in factors:
            record(f"Q{degree} plane strain", degree, "plane strain", factor,
                   {"Finite elements/Element degree": degree, **sized(factor)})
    if not options.no_3d:
        coarse = {"Finite elements/Element degree": 1, **sized(2.0), "Mesh/layers": 2}
        for model in ("plane strain", "plane stress"):
            record(f"Q1 {model} (x2)", 1, model, 2.0,
                   {**coarse, "Finite elements/Planar model": model})
        record("Q1 3D extruded (x2)", 1, "3D", 2.0, {**coarse, "Mesh/dimension": 3}, ranks=2)

    q2 = [(r["size_factor"], r["stiffness"]) for r in rows if r["variant"] == "Q2 plane strain"]
    q1 = [(r["size_factor"], r["stiffness"]) for r in rows if r["variant"] == "Q1 plane strain"]
    extrapolated, order = richardson(q2) if len(q2) >= 3 else (None, None)
    q1_extrapolated, q1_order = richardson(q1) if len(q1) >= 3 else (None, None)
    reference = extrapolated if extrapolated is not None else q2[-1][1]
    print(f"Q2 Richardson: {extrapolated} (order {order}); Q1 Richardson: {q1_extrapolated} "
          f"(order {q1_order}); reference {reference:.3f} N/um")
    for r in rows:
        r["error_reference"] = r["stiffness"] / reference - 1
    default = [r for r in rows if r["variant"] == "Q2 plane strain" and r["size_factor"] == 1.0]
    if default:
        print(f"default (Q2, f = 1): {default[0]['stiffness']:.3f} N/um, "
              f"{default[0]['error_reference'] * 100:+.2f}% from the reference")

    print("\n| model | f | DoFs | time [s] | k [N/µm] | vs reference |\n|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['variant']} | {r['size_factor']:.3f} | {int(r['dofs'])} | "
              f"{r['solve_time']:.2f} | {r['stiffness']:.2f} | {r['error_reference'] * 100:+.2f}% |")
    os.makedirs(options.out, exist_ok=True)
    with open(os.path.join(options.out, "internal_refinement.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    sys.exit(main())
