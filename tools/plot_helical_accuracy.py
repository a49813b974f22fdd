#!/usr/bin/env python3
"""Accuracy against cost of a helical pair's layers (docs/helical.md "Layer extrapolation").

usage: plot_helical_accuracy.py bench/helical_layers_accuracy.csv REFERENCE_N_PER_UM OUT.png

The built-in pair at β ±15°, default sizes and single position, Q1, frictionless, 2 ranks: k on
L layers (chords: the default flanks), the helicoid flanks, the layer extrapolation and the
influence-coefficient model (one position as a one-position sweep, its whole model built for
it), each point's |k/k_ref − 1| against its wall time. The reference is the layers' limit estimated from
20 and 26 layers (Richardson in the rotation); the times come from the sittings the CSV names
(the machine is shared: ±20 % at best, 3× between a loaded and a quiet day), so the chart
compares orders of magnitude.
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    path, reference, out = sys.argv[1], float(sys.argv[2]), sys.argv[3]
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    variants = defaultdict(list)
    for r in rows:
        variants[r["variant"]].append(r)
    fig, ax = plt.subplots(figsize=(7.5, 5))
    for name, points in variants.items():
        time = [float(p["wall_time"]) for p in points]
        error = [abs(float(p["stiffness"]) / reference - 1.) * 100. for p in points]
        style = "o-" if len(points) > 1 else ("s" if "helicoid" in name else "D")
        ax.plot(time, error, style, ms=7, label=name)
        for p, t, e in zip(points, time, error):
            sign = "+" if float(p["stiffness"]) > reference else "−"
            ax.annotate(f"{p['layers']} ({sign})", (t, e), fontsize=7,
                        textcoords="offset points", xytext=(4, 3))
    ax.axhline(1.0, color="k", ls=":", lw=1, label="1 % (issue 46)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time of one position, 2 ranks [s]")
    ax.set_ylabel(f"|k / k_limit − 1| [%], k_limit = {reference:.1f} N/µm")
    ax.set_title("Helical pair β ±15°, default sizes: the layers' error against cost\n"
                 "(labels: layers L, sign of the error; extrapolation: L and 2L)", fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
