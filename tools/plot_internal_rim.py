#!/usr/bin/env python3
"""Chart of the ring rim study of bench/internal_rim_study.py: k against s_R/m per support.

usage: plot_internal_rim.py internal_rim_study.csv OUT.png
One line per way of holding the ring (whole outer circle, pads, bolt holes), single-pair mesh
stiffness k [N/µm] against the rim thickness under the root in modules.
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import chart_case  # noqa: E402,F401  (every figure names its case in a footer)
import matplotlib.pyplot as plt  # noqa: E402


def main():
    with open(sys.argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    series = defaultdict(list)
    for r in rows:
        series[r["support"]].append((float(r["rim_modules"]), float(r["stiffness"])))
    figure, axes = plt.subplots(figsize=(6.4, 4.4))
    for (support, points), marker in zip(series.items(), "osd^v"):
        points.sort()
        axes.plot([p[0] for p in points], [p[1] for p in points], marker=marker, label=support)
    axes.set_xlabel("rim thickness under the root s_R/m [-]")
    axes.set_ylabel("single-pair mesh stiffness k [N/µm]")
    axes.set_title("Ring 69 / planet 24, m = 2.5 mm: rim and ring support")
    axes.set_ylim(bottom=0)
    axes.grid(True, alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(sys.argv[2], dpi=120)


if __name__ == "__main__":
    sys.exit(main())
