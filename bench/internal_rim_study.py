#!/usr/bin/env python3
"""Rim study of the internal (ring-planet) single-pair mesh stiffness: k against s_R/m.

The pair of docs/internal-gears.md (planet 24 / ring 69, m = 2.5 mm, T1 = 49.4 N·m, μ = 0, default
stiffness scene, single-pair position) with the ring held three ways:
  - whole circle: its whole outer circle clamped (the default);
  - pads: 6 pads of 10 mm on its outer circle, the mesh midway between two;
  - bolts: 6 bolt holes of 4.5 mm (M4 clearance, ISO 273) on the rim's middle circle, the holes
    clamped and the outer circle free, the mesh midway between two. A hole keeps one module of
    material on each side, so bolts need s_R ≥ 2·m + 4.5 mm = 3.8·m.
Writes internal_rim_study.csv into --out and the chart (tools/plot_internal_rim.py) to --png.

usage: bench/internal_rim_study.py [--gearstiff build/app/gearstiff] [--out bench]
                                   [--png docs/internal_rim.png]
"""
import csv
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from internal_refinement import PLANET_RING, gearstiff_parser, run_stiffness  # noqa: E402

MODULE = 2.5  # mm
RIMS = [1, 2, 3, 4, 5, 6, 8]  # s_R/m
SUPPORTS = {
    "whole circle": ({}, RIMS),
    "6 pads of 10 mm": ({"Gear pair scene/wheel supports": 6,
                         "Gear pair scene/wheel support width": 10}, RIMS),
    "6 bolt holes of 4.5 mm": ({"Gear pair scene/wheel bolt holes": 6,
                                "Gear pair scene/bolt hole diameter": 4.5}, [4, 5, 6, 8]),
}


def main():
    parser = gearstiff_parser(__doc__)
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--out", default=here)
    parser.add_argument("--png", default=os.path.join(here, "..", "docs", "internal_rim.png"))
    options = parser.parse_args()

    rows = []
    for support, (settings, rims) in SUPPORTS.items():
        for rim in rims:
            run = {**PLANET_RING, **settings, "Gear pair scene/wheel rim thickness": rim * MODULE}
            result = run_stiffness(options.gearstiff, run)
            rows.append({"support": support, "rim_modules": rim, **result})
            print(f"{support:24s} s_R/m = {rim}: k = {result['stiffness']:8.2f} N/um, "
                  f"{result['solve_time']:.2f} s", flush=True)
    csv_path = os.path.join(options.out, "internal_rim_study.csv")
    with open(csv_path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    print("\n| s_R/m | " + " | ".join(SUPPORTS) + " |\n|---|" + "---|" * len(SUPPORTS))
    for rim in RIMS:
        cells = []
        for support in SUPPORTS:
            k = [r["stiffness"] for r in rows if r["support"] == support and r["rim_modules"] == rim]
            cells.append(f"{k[0]:.1f}" if k else "–")
        print(f"| {rim} | " + " | ".join(cells) + " |")
    plot = os.path.join(here, "..", "tools", "plot_internal_rim.py")
    subprocess.run(["/usr/bin/python3", plot, csv_path, options.png], check=True)


if __name__ == "__main__":
    sys.exit(main())
