#!/usr/bin/env python3
"""Charts of `gearstiff dynamics` with `Simulation/mesh model = nonlinear` (issue 29).

    plot_nonlinear_dynamics.py dte       SERIES.csv START,END OUT.png   DTE(t) and e(t) per mesh
    plot_nonlinear_dynamics.py sweep     SWEEP.csv OUT.png      DF against speed, up and down
    plot_nonlinear_dynamics.py waterfall WATERFALL.csv OUT.png  DTE spectrum (mesh orders)
                                                                against speed, up and down

CSV headers are "name [unit]" as written by the command; the PNG path is the last argument.
"""
import math
import sys

import matplotlib

from dynamics_charts import column, finish, plt, read, shade_window


def dte(path, window, png):
    header, c = read(path)
    t = c[header[0]]
    fig, ax = plt.subplots(figsize=(9, 4.5))
    for h in header[1:]:
        if h.startswith("dte_") or h.startswith("te_"):
            ax.plot(t, c[h], lw=0.7, label=h, ls="-" if h.startswith("dte_") else "--")
    shade_window(ax, window)
    finish(fig, ax, "time [s]", "transmission error along the line of action [µm]", png)


def sweep(path, png):
    header, c = read(path)
    speed = column(header, c, "input_speed")
    direction = column(header, c, "direction")
    df = column(header, c, "dynamic_factor")
    separation = column(header, c, "separation_fraction")
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True,
                                  gridspec_kw={"height_ratios": [3, 1]})
    for d, label, style in (("up", "up sweep", "o-"), ("down", "down sweep", "s--")):
        idx = [i for i, v in enumerate(direction) if v == d]
        if not idx:
            continue
        xs = [speed[i] for i in idx]
        ax.plot(xs, [df[i] for i in idx], style, ms=3, lw=1, label=label)
        ax2.plot(xs, [separation[i] for i in idx], style, ms=2, lw=0.8, label=label)
    ax.axhline(1.0, color="0.5", lw=0.5)
    ax.set_ylabel("DF = max dynamic / static mesh force [-]")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8)
    ax2.set_xlabel("input speed [rpm]")
    ax2.set_ylabel("separation\nfraction [-]")
    ax2.grid(True, lw=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def waterfall(path, png):
    """One row of panels per mesh (column "mesh"; older tables without it: mesh 1), one column
    per sweep direction, a shared logarithmic colour scale."""
    header, c = read(path)
    speed = column(header, c, "input_speed")
    direction = column(header, c, "direction")
    order = column(header, c, "order")
    amplitude = column(header, c, "amplitude")
    mesh = column(header, c, "mesh") if any(h.startswith("mesh") for h in header) \
        else [1.0] * len(speed)
    directions = [d for d in ("up", "down") if d in direction]
    meshes = sorted(set(mesh))
    fig, axes = plt.subplots(len(meshes), len(directions),
                             figsize=(5 * len(directions) + 1, 3.2 * len(meshes) + 1.3),
                             squeeze=False, sharex=True, sharey=True)
    top = max([a for a in amplitude if math.isfinite(a)] + [1e-12])
    norm = matplotlib.colors.LogNorm(vmin=top * 1e-4, vmax=top)
    for row, m in enumerate(meshes):
        for ax, d in zip(axes[row], directions):
            idx = [i for i, v in enumerate(direction) if v == d and mesh[i] == m]
            points = ax.scatter([speed[i] for i in idx], [order[i] for i in idx],
                                c=[max(amplitude[i], top * 1e-4) for i in idx], s=6,
                                cmap="viridis", norm=norm)
            ax.set_title(f"mesh {int(m)}, {d} sweep",
                         fontsize=9)
            ax.grid(True, lw=0.3)
        axes[row][0].set_ylabel("DTE frequency /\nmesh frequency [-]")
    for ax in axes[-1]:
        ax.set_xlabel("input speed [rpm]")
    fig.colorbar(points, ax=axes.ravel().tolist(), label="DTE amplitude [µm]")
    fig.savefig(png, dpi=120)


def main(argv):
    kind = argv[1]
    if kind == "dte":
        dte(argv[2], argv[3], argv[-1])
    elif kind == "sweep":
        sweep(argv[2], argv[-1])
    elif kind == "waterfall":
        waterfall(argv[2], argv[-1])
    else:
        raise SystemExit(f"unknown chart {kind}")


if __name__ == "__main__":
    main(sys.argv)
