#!/usr/bin/env python3
"""Accuracy against cost of the single-pair mesh stiffness of the split-path pair.

What it runs (each FE point is one `gearstiff stiffness --json` on one rank, default load case of
docs/references.md §1: T1 = 49.4 N·m, μ = 0.01, pinion bore free to rotate, wheel bore
fixed, single-pair position = pitch point):
  - ISO 6336-1 method B c'·b (analytic, microseconds);
  - FE at four refinement levels (the default scene's size field times 1, 1/√2, 1/2, 1/(2√2):
    a coarser field no longer meshes the teeth with quadrilaterals) with element degree 1 and 2,
    plane strain, 3 teeth per gear (the default scene: Q2, factor 1);
  - three levels with 1 and 5 teeth modelled per gear (degree 2);
  - three levels in plane stress (degree 2).
The converged value of each model variant is the Richardson extrapolation of its three finest
levels (when they converge monotonically); the reference "converged answer" is that of the
degree-2 ladder (or its finest level), i.e. of the default model. Friction is left out of the
ladder (μ = 0): at μ = 0.01 it changes k by 0.01% and its fixed point costs iterations that
would blur the cost axis. A point whose solve fails is recorded as failed, not as a number. Writes accuracy.csv and accuracy.png (error against the converged value and
against ANSYS, versus wall time) into the output folder.

usage: bench/accuracy_cost.py [--gearstiff build/app/gearstiff] [--out docs] [--quick]
  --quick  three levels only: a smoke run of the script (~2 minutes)
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import time

ANSYS_SINGLE = 327.222  # N/um, docs/references.md §1 k'_j
# The cost of a point is the solve's own wall time (scene, setup, contact iterations) as the
# command reports it, on one rank; process start-up is excluded.


def run_stiffness(binary, settings):
    args = [binary, "stiffness", "--json"]
    for key, value in settings.items():
        args += ["--set", f"{key}={value}"]
    start = time.monotonic()
    done = subprocess.run(args, capture_output=True, text=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
    wall = time.monotonic() - start
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(args)} failed: {done.stderr.strip()}")
    values = json.loads(done.stdout)["values"]
    return {
        "stiffness": values["mesh_stiffness"]["value"],
        "iso": values["iso_single_stiffness"]["value"],
        "dofs": values["dofs"]["value"],
        "solve_time": values["time_total"]["value"],
        "wall_time": wall,
    }


def richardson(levels):
    """k at h -> 0 from the three finest (factor, k) levels of constant ratio; None if the
    differences change sign or do not shrink (not in the asymptotic range)."""
    (_, k0), (f1, k1), (f2, k2) = levels[-3:]
    ratio = f1 / f2
    d1, d2 = k1 - k0, k2 - k1
    if d1 * d2 <= 0 or abs(d2) >= abs(d1):
        return None, None
    order = math.log(d1 / d2) / math.log(ratio)
    return k2 + d2 / (ratio ** order - 1.0), order


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--gearstiff", default=os.path.join(here, "..", "build", "app", "gearstiff"))
    parser.add_argument("--out", default=os.path.join(here, "..", "docs"))
    parser.add_argument("--quick", action="store_true")
    options = parser.parse_args()

    # Default scene sizes (stiffness/mesh_stiffness.cc default_stiffness_scene), in mm.
    base = {"contact size": 0.04, "body size": 1.0, "rim size": 4.0, "growth rate": 0.5}
    root2 = math.sqrt(2.0)
    factors = [1, 1 / root2, 0.5] if options.quick else [1, 1 / root2, 0.5, 0.5 / root2]
    coarse = factors[:3]
    variants = [
        # name, teeth, degree, planar model, factors
        ("Q1 plane strain 3 teeth", 3, 1, "plane strain", factors),
        ("Q2 plane strain 3 teeth", 3, 2, "plane strain", factors),
        ("Q2 plane strain 1 tooth", 1, 2, "plane strain", coarse),
        ("Q2 plane strain 5 teeth", 5, 2, "plane strain", coarse),
        ("Q2 plane stress 3 teeth", 3, 2, "plane stress", coarse),
    ]
    rows = []
    iso_value = None
    for name, teeth, degree, model, levels in variants:
        for factor in levels:
            settings = {
                "Gear pair scene/pinion teeth modelled": teeth,
                "Gear pair scene/wheel teeth modelled": teeth,
                "Finite elements/Element degree": degree,
                "Finite elements/Planar model": model,
                "Contact/Friction coefficient": 0,
                "Mesh/contact size": base["contact size"] * factor,
                "Mesh/body size": base["body size"] * factor,
                "Mesh/rim size": base["rim size"] * factor,
                "Mesh/growth rate": base["growth rate"] * factor,
            }
            try:
                result = run_stiffness(options.gearstiff, settings)
            except RuntimeError as error:
                print(f"{name:26s} factor {factor:5.2f}: FAILED ({error})", flush=True)
                continue
            iso_value = result["iso"]
            rows.append({"variant": name, "teeth": teeth, "degree": degree, "model": model,
                         "size_factor": factor, **result})
            print(f"{name:26s} factor {factor:5.2f}: k = {result['stiffness']:8.3f} N/um, "
                  f"{int(result['dofs']):7d} DoFs, {result['solve_time']:6.2f} s", flush=True)

    converged = {}
    for name, *_ in variants:
        levels = [(r["size_factor"], r["stiffness"]) for r in rows if r["variant"] == name]
        converged[name] = richardson(levels) if len(levels) >= 3 else (None, None)
        value, order = converged[name]
        print(f"{name:26s} converged {value} (observed order {order})")
    reference_name = "Q2 plane strain 3 teeth"
    reference = converged[reference_name][0]
    if reference is None:
        reference = [r for r in rows if r["variant"] == reference_name][-1]["stiffness"]
    for r in rows:
        own = converged[r["variant"]][0]
        r["error_own_converged"] = abs(r["stiffness"] / own - 1) if own else float("nan")
        r["error_reference"] = abs(r["stiffness"] / reference - 1)
        r["error_ansys"] = abs(r["stiffness"] / ANSYS_SINGLE - 1)
    rows.append({"variant": "ISO 6336-1 method B", "teeth": 0, "degree": 0, "model": "analytic",
                 "size_factor": 0, "stiffness": iso_value, "iso": iso_value, "dofs": 0,
                 "solve_time": 1e-5, "wall_time": 1e-5,
                 "error_own_converged": 0.0, "error_reference": abs(iso_value / reference - 1),
                 "error_ansys": abs(iso_value / ANSYS_SINGLE - 1)})

    os.makedirs(options.out, exist_ok=True)
    csv_path = os.path.join(options.out, "accuracy.csv")
    with open(csv_path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    cheapest = min((r for r in rows if r["dofs"] > 0 and r["error_reference"] < 0.01),
                   key=lambda r: r["solve_time"], default=None)
    print(f"reference converged value ({reference_name}): {reference:.3f} N/um "
          f"({(reference / ANSYS_SINGLE - 1) * 100:+.2f}% from ANSYS)")
    if cheapest:
        print(f"cheapest within 1%: {cheapest['variant']} factor {cheapest['size_factor']} "
              f"({cheapest['solve_time']:.2f} s, {cheapest['error_reference'] * 100:.2f}%)")
    plot = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools", "plot_accuracy.py")
    # CalculiX's ladder on the same meshes (bench/calculix_ladder.sh), when it has been run.
    calculix = os.path.join(os.path.dirname(os.path.abspath(__file__)), "calculix_ladder.csv")
    extra = [calculix] if os.path.exists(calculix) else []
    subprocess.run(["/usr/bin/python3", plot, csv_path, *extra, f"{reference}",
                    os.path.join(options.out, "accuracy.png")], check=True)


if __name__ == "__main__":
    sys.exit(main())
