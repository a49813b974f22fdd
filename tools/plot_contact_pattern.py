#!/usr/bin/env python3
"""Contact pattern of a 3D `gearstiff stiffness` run (issue 27: lead modifications).

usage: plot_contact_pattern.py FACE_LOAD.csv OUT.png
  FACE_LOAD.csv  the face_load table (pinion_roll_angle [deg], z [mm], line_load [N/mm]): the line
                 load w(z) = integral of the contact pressure across the profile, summed over the
                 pairs in contact, at every solved position
One position: w(z) across the face width with its mean (K_Hbeta = peak/mean in the title).
Several (a sweep): the contact pattern, w over the face width (x) and the roll angle (y).
"""
import sys

import matplotlib

matplotlib.use("Agg")
import chart_case  # noqa: E402,F401  (every figure names its case in a footer)
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from report_csv import read_table  # noqa: E402


def main():
    table = read_table(sys.argv[1])
    png = sys.argv[2]
    angle = np.asarray(table["pinion_roll_angle"], dtype=float)
    z = np.asarray(table["z"], dtype=float)
    load = np.asarray(table["line_load"], dtype=float)
    angles = sorted(set(angle))
    fig, ax = plt.subplots(figsize=(8, 5))
    if len(angles) == 1:
        order = np.argsort(z)
        mean = np.trapz(load[order], z[order]) / (z.max() - z.min())
        ax.plot(z[order], load[order], "o-", label="line load")
        ax.axhline(mean, color="grey", ls="--", label="mean")
        ax.set_title("Load across the face width at %.3f°: K_Hβ = %.3f"
                     % (angles[0], load.max() / mean))
        ax.set_ylabel("line load w(z) [N/mm]")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    else:
        zs = sorted(set(z))
        grid = np.full((len(angles), len(zs)), np.nan)
        for a, x, w in zip(angle, z, load):
            grid[angles.index(a), zs.index(x)] = w
        mesh = ax.pcolormesh(zs, angles, grid, shading="nearest", cmap="viridis")
        fig.colorbar(mesh, ax=ax, label="line load w(z) [N/mm]")
        ax.set_ylabel("pinion roll angle [°]")
        ax.set_title("Contact pattern: line load over the face width and the mesh cycle")
    ax.set_xlabel("face width z [mm]")
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    main()
