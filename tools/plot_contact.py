"""Contact pressure and shear along the contact surface(s) from gearstiff contact's CSV.

usage: python3 plot_contact.py contact_surface.csv out.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import chart_case  # noqa: E402,F401  (every figure names its case in a footer)
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    pairs = {}
    with open(csv_path) as f:
        for row in csv.DictReader(f):
            pairs.setdefault(row["pair"], []).append(row)
    fig, ax = plt.subplots(figsize=(7, 4))
    for pair, rows in pairs.items():
        s = [float(r["coordinate_mm"]) for r in rows]
        ax.plot(s, [float(r["pressure_MPa"]) for r in rows], ".-", label=f"pressure, pair {pair}")
        ax.plot(s, [float(r["shear_MPa"]) for r in rows], "x--", label=f"|shear|, pair {pair}")
    ax.set_xlabel("coordinate along the surface [mm]")
    ax.set_ylabel("traction [MPa]")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
