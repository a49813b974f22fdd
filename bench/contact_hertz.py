#!/usr/bin/env python3
"""Speed of the contact solver (issue 4) on the built-in Hertz case of `gearstiff contact`:
two steel cylinders R1 = 10 mm, R2 = 15 mm pressed by 4 µm in plane strain (≈129 N/mm,
a ≈ 0.09 mm). For three cell sizes at the contact it prints DoFs, active-set (semismooth Newton)
steps, time per step and the deviation from Hertz (half-width by profile fit, peak pressure).

    python3 bench/contact_hertz.py [path/to/gearstiff] [--ranks N] [--degree 1|2]
"""
import argparse
import json
import subprocess
import sys
import time


def run(gearstiff, size_mm, ranks, degree, dimension):
    command = [gearstiff, "contact", "--json",
               "--set", f"Mesh/Built-in fine size={size_mm}",
               "--set", f"Mesh/Dimension={dimension}",
               "--set", f"Finite elements/Element degree={degree}"]
    if ranks > 1:
        command = ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + command
    start = time.time()
    out = subprocess.run(command, capture_output=True, text=True)
    wall = time.time() - start
    if out.returncode != 0:
        sys.exit(f"gearstiff failed ({out.returncode}): {out.stderr.strip()}")
    summary = json.loads(out.stdout)
    return summary["values"], wall


def number(values, key):
    return values[key]["value"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("gearstiff", nargs="?", default="build/app/gearstiff")
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--degree", type=int, default=1)
    parser.add_argument("--dimension", type=int, default=2)
    args = parser.parse_args()
    print(f"Hertz line contact, plane strain, FE_Q({args.degree}), {args.ranks} rank(s)")
    print(f"{'h [um]':>8} {'DoFs':>8} {'steps':>6} {'s/step':>8} {'total s':>8} "
          f"{'a err %':>8} {'p0 err %':>9}")
    for size in (0.0125, 0.00625, 0.003125):
        values, wall = run(args.gearstiff, size, args.ranks, args.degree, args.dimension)
        steps = number(values, "active_set_iterations")
        width = values.get("half_width", {})
        peak = values.get("peak_pressure", {})

        def deviation(entry):
            if not isinstance(entry, dict) or not entry.get("published"):
                return float("nan")
            return 100.0 * (entry["value"] / entry["published"] - 1.0)

        print(f"{size * 1e3:8.3f} {int(number(values, 'dofs')):8d} {int(steps):6d} "
              f"{number(values, 'time_per_iteration'):8.3f} {number(values, 'time_total'):8.2f} "
              f"{deviation(width):8.2f} {deviation(peak):9.3f}")


if __name__ == "__main__":
    main()
