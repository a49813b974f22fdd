#!/usr/bin/env python3
"""Cost of an internal (ring-planet) single position against the external default, one sitting.

Both at the default stiffness scene (Q2, contact size 0.03 mm, 3 teeth per gear, full rims, one
rank), which puts each within 0.3% of its own converged value (docs/accuracy.md for the external
split-path pair, bench/internal_refinement.py for the ring): the same accuracy. External: the
published load case of docs/references.md §1 (`gearstiff stiffness` with its defaults, μ = 0.01).
Internal: planet 24 / ring 69 of docs/internal-gears.md (rim 5·m held on its whole outer circle),
T1 = 49.4 N·m, the same μ = 0.01. The runs alternate (external, internal) three times; the
figure is the median of each model's solve time (scene, mesh, setup, contact iterations, as the
command reports it) and the ratio of the medians.

usage: bench/internal_speed.py [--gearstiff build/app/gearstiff] [--runs 3]
"""
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from internal_refinement import PLANET_RING, gearstiff_parser, run_stiffness  # noqa: E402


def main():
    parser = gearstiff_parser(__doc__)
    parser.add_argument("--runs", type=int, default=3)
    options = parser.parse_args()

    internal = {**PLANET_RING, "Contact/Friction coefficient": 0.01}
    times = {"external": [], "internal": []}
    last = {}
    for run in range(options.runs):
        for name, settings in (("external", {}), ("internal", internal)):
            result = run_stiffness(options.gearstiff, settings)
            times[name].append(result["solve_time"])
            last[name] = result
            print(f"run {run + 1} {name:8s}: {result['solve_time']:6.2f} s, "
                  f"k = {result['stiffness']:8.3f} N/um, {int(result['dofs'])} DoFs", flush=True)
    median = {name: statistics.median(values) for name, values in times.items()}
    for name in times:
        print(f"{name:8s}: median {median[name]:.2f} s of {options.runs} "
              f"({', '.join(f'{t:.2f}' for t in times[name])}), {int(last[name]['dofs'])} DoFs")
    print(f"ratio internal/external: {median['internal'] / median['external']:.2f} "
          f"(limit of issue 14: 2)")


if __name__ == "__main__":
    sys.exit(main())
