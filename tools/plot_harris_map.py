#!/usr/bin/env python3
"""Harris map of `gearstiff stiffness` (Stiffness/torques, Stiffness/variants).

usage: plot_harris_map.py MAP.csv LABEL [MAP.csv LABEL ...] OUT.png
  MAP.csv   a te_map table (torque [N*m], te_peak_to_peak [um], te_harmonic_1 [um], ...)
  LABEL     the modification set of that table ("base" for the parameter file's own)
Top: TE peak-to-peak against torque, one line per modification set (Harris 1958: a relief has
its minimum near the torque whose deflection matches it), each minimum marked with its value and
torque; bottom: the first mesh harmonic.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import chart_case  # noqa: E402,F401  (every figure names its case in a footer)
import matplotlib.pyplot as plt  # noqa: E402

from report_csv import read_table  # noqa: E402


def main():
    png = sys.argv[-1]
    pairs = sys.argv[1:-1]
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    for k in range(0, len(pairs), 2):
        table = read_table(pairs[k])
        label = pairs[k + 1]
        line, = top.plot(table["torque"], table["te_peak_to_peak"], "o-", label=label)
        bottom.plot(table["torque"], table["te_harmonic_1"], "o-", label=label)
        # The map's point: the torque at which this modification set runs quietest.
        best = min(range(len(table["torque"])), key=lambda i: table["te_peak_to_peak"][i])
        torque, te = table["torque"][best], table["te_peak_to_peak"][best]
        top.plot([torque], [te], "*", ms=14, color=line.get_color())
        top.annotate(f"min {te:.3g} µm at {torque:.4g} N·m", (torque, te),
                     textcoords="offset points", xytext=(6, 8), fontsize=8,
                     color=line.get_color())
    top.set_ylabel("TE peak-to-peak [µm]")
    top.set_title("Harris map: loaded transmission error over one mesh cycle")
    top.legend(fontsize=8, loc="best")
    top.grid(alpha=0.3)
    bottom.set_ylabel("TE at 1× mesh frequency [µm]")
    bottom.set_xlabel("pinion torque T1 [N·m]")
    bottom.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    main()
