#!/usr/bin/env python3
"""Accuracy-against-cost chart of bench/accuracy_cost.py.

usage: plot_accuracy.py accuracy.csv [more.csv ...] REFERENCE_N_PER_UM OUT.png
Left: error against the converged reference value; right: error against ANSYS k'_j; both
against wall time (one rank), one line per model variant (gearstiff's and, from
bench/calculix_ladder.csv, CalculiX's on the same meshes), the ISO 6336 value as a star. Errors
are computed here from each row's stiffness, so every ladder meets one reference; the point that
is the reference itself (error 0) is left out of the left panel.
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    rows = []
    for path in sys.argv[1:-2]:
        with open(path, newline="") as f:
            rows += list(csv.DictReader(f))
    reference = float(sys.argv[-2])
    ansys = 327.222  # N/um, docs/references.md §1 k'_j
    for r in rows:
        k = float(r["stiffness"])
        r["error_reference"] = abs(k / reference - 1)
        r["error_ansys"] = abs(k / ansys - 1)
    variants = defaultdict(list)
    for r in rows:
        variants[r["variant"]].append(r)
    fig, axes = plt.subplots(1, 2, figsize=(12, 5), sharey=False)
    for ax, key, title in ((axes[0], "error_reference",
                            f"against the converged value {reference:.1f} N/µm"),
                           (axes[1], "error_ansys", "against ANSYS k'_j = 327.2 N/µm")):
        for name, points in variants.items():
            points = [p for p in points if float(p[key]) > 1e-9]
            if not points:
                continue
            time = [float(p["solve_time"]) for p in points]
            error = [float(p[key]) * 100 for p in points]
            if name.startswith("ISO"):
                ax.plot(time, error, "*", ms=14, label=name)
                continue
            ax.plot(time, error, "s--" if name.startswith("CalculiX") else "o-", label=name)
            for p, t, e in zip(points, time, error):
                ax.annotate(f"×{float(p['size_factor']):.2g}", (t, e), fontsize=6,
                            textcoords="offset points", xytext=(3, 3))
        ax.set_xscale("log")
        ax.set_yscale("log")
        if key == "error_reference":
            ax.axhline(1.0, color="k", ls=":", lw=1, label="1% target")
        ax.set_xlabel("wall time of the solve, one rank [s]")
        ax.set_ylabel("|k / k_ref − 1| [%]")
        ax.set_title(title, fontsize=10)
        ax.grid(alpha=0.3, which="both")
    axes[0].legend(fontsize=7)
    fig.suptitle("Single-pair mesh stiffness of the split-path pair: accuracy against cost "
                 "(×f: size field × f)", fontsize=10)
    fig.tight_layout()
    fig.savefig(sys.argv[-1], dpi=110)


if __name__ == "__main__":
    main()
