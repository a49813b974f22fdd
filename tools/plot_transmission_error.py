#!/usr/bin/env python3
"""Loaded transmission error of a `gearstiff stiffness` sweep.

usage: plot_transmission_error.py SWEEP.csv TITLE OUT.png
  SWEEP.csv  the stiffness_sweep table (roll_angle [deg], transmission_error [um])
  TITLE      the case and its torque, e.g. "z 21/57, m_n 2.5 mm, T1 = 49.4 N·m"
TE(θ) along the line of action with its peak-to-peak and mean marked.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import chart_case  # noqa: E402,F401  (every figure names its case in a footer)
import matplotlib.pyplot as plt  # noqa: E402

from report_csv import read_table  # noqa: E402


def main():
    table = read_table(sys.argv[1])
    title, png = sys.argv[2], sys.argv[-1]
    angle, te = table["roll_angle"], table["transmission_error"]
    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.plot(angle, te, "o-", color="C0", label="loaded TE (FE)")
    mean = sum(te) / len(te)
    ax.axhline(mean, color="C0", ls=":", label=f"mean {mean:.3f} µm")
    low, high = min(te), max(te)
    ax.axhspan(low, high, color="C0", alpha=0.08,
               label=f"peak-to-peak {high - low:.3f} µm")
    ax.set_xlabel("pinion roll angle of the reference pair [deg]")
    ax.set_ylabel("transmission error along the line of action [µm]")
    ax.set_title("Transmission error, " + title)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="best")
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    main()
