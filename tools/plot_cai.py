#!/usr/bin/env python3
"""Cai calibration chart of `gearstiff cai`.

usage: plot_cai.py SAMPLES.csv CURVES.csv OUT.png
  SAMPLES.csv  cai_samples table: roll_position [base pitches], fe_pair_stiffness [N/um], ...
  CURVES.csv   cai_curves table: roll_position, calibrated_cai, paper_cai [N/um]
FE single-pair stiffness points with the calibrated and the paper-scaled Cai curves.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import chart_case  # noqa: E402,F401  (every figure names its case in a footer)
import matplotlib.pyplot as plt  # noqa: E402

from report_csv import read_table  # noqa: E402


def main():
    samples, curves = read_table(sys.argv[1]), read_table(sys.argv[2])
    fig, ax = plt.subplots(figsize=(8, 5))
    ax.plot(samples["roll_position"], samples["fe_pair_stiffness"], "o", color="C0",
            label="FE: pair stiffness share·k")
    ax.plot(curves["roll_position"], curves["calibrated_cai"], "-", color="C1",
            label="Cai curve, calibrated (least squares)")
    ax.plot(curves["roll_position"], curves["paper_cai"], "--", color="C2",
            label="Cai curve, paper scaling (peak = ANSYS k'_j)")
    ax.set_xlabel("roll position of the pair from the start of contact A [base pitches]")
    ax.set_ylabel("single-pair stiffness [N/µm]")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=9)
    fig.tight_layout()
    fig.savefig(sys.argv[-1], dpi=110)


if __name__ == "__main__":
    main()
