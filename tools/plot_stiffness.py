#!/usr/bin/env python3
"""k(θ) chart of `gearstiff stiffness` (mode sweep).

usage: plot_stiffness.py SWEEP.csv ANSYS_SINGLE ANSYS_DOUBLE ISO_MEAN FE_MEAN OUT.png
  SWEEP.csv     the stiffness_sweep table (roll_angle [deg], stiffness [N/um], share_pair_* [-])
  ANSYS_*       published single/double-pair stiffness [N/um] (0: not drawn)
  ISO_MEAN      ISO 6336-1 c_gamma_alpha * b [N/um]
  FE_MEAN       mean of the FE sweep [N/um]
Top: mesh stiffness against the pinion roll angle with the reference lines; bottom: load share.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import chart_case  # noqa: E402,F401  (every figure names its case in a footer)
import matplotlib.pyplot as plt  # noqa: E402

from report_csv import read_table  # noqa: E402


def main():
    table = read_table(sys.argv[1])
    single, double, iso, mean = (float(v) for v in sys.argv[2:6])
    png = sys.argv[-1]
    angle = table["roll_angle"]
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), sharex=True,
                                      gridspec_kw={"height_ratios": [2, 1]})
    top.plot(angle, table["stiffness"], "o-", color="C0", label="FE k(θ) (this model)")
    top.axhline(mean, color="C0", ls=":", label=f"FE mean {mean:.1f} N/µm")
    if single > 0:
        top.axhline(single, color="C3", ls="--", label=f"ANSYS single pair {single:.1f} N/µm")
    if double > 0:
        top.axhline(double, color="C1", ls="--", label=f"ANSYS double pair {double:.1f} N/µm")
    top.axhline(iso, color="C2", ls="-.", label=f"ISO 6336-1 c_γα·b {iso:.1f} N/µm")
    top.set_ylabel("mesh stiffness k = T1/(r_b1²·Δφ) [N/µm]")
    top.legend(fontsize=8, loc="best")
    top.grid(alpha=0.3)
    for key, label in (("share_pair_0", "reference pair"), ("share_pair_p1", "next pair (+1)"),
                       ("share_pair_m1", "previous pair (−1)")):
        if key in table and max(table[key]) > 0:
            bottom.plot(angle, table[key], ".-", label=label)
    bottom.set_xlabel("pinion roll angle of the reference pair [deg]")
    bottom.set_ylabel("load share [-]")
    bottom.set_ylim(-0.05, 1.05)
    bottom.legend(fontsize=8)
    bottom.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    main()
