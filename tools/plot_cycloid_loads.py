#!/usr/bin/env python3
"""Charts of `gearstiff cycloid-loads`.

usage: plot_cycloid_loads.py MODE TABLE.csv OUT.png
  rollers  cycloid_rollers table: P_i against the roller angle, FE bars and analytic markers,
           one colour per profile (nominal, corrected)
  pins     cycloid_pins table: Q_j the same way
  torsion  cycloid_torsion table: output rotation [arcmin] against the output torque [N·m] along
           the ramp -M_c -> +M_c -> -M_c (column branch: loading, unloading)
  hysteresis  cycloid_hysteresis table: the loops with friction, rotation [arcmin] against
           torque [N·m], one colour per profile (column profile), rising solid, falling dashed
  sweep    cycloid_sweep_<profile> table: P_i(φ_h) and Q_j(φ_h) traces
"""
import sys

import matplotlib

matplotlib.use("Agg")
import chart_case  # noqa: E402,F401  (every figure names its case in a footer)
import matplotlib.pyplot as plt  # noqa: E402

from report_csv import read_table  # noqa: E402


def profiles(table):
    return [k[len("force_"):] for k in table if k.startswith("force_")]


def distribution(table, index, symbol, png):
    fig, ax = plt.subplots(figsize=(9, 4.5))
    names = profiles(table)
    width = 0.8 / max(len(names), 1)
    for n, name in enumerate(names):
        x = [i + (n - (len(names) - 1) / 2) * width for i in table[index]]
        ax.bar(x, table["force_" + name], width, color=f"C{n}", label=f"FE, {name}")
        ax.plot(x, table["analytic_force_" + name], "k^" if n == 0 else "kv", ms=5,
                mfc=f"C{n}", label=f"analytic (rigid disc), {name}")
    ax.set_xticks(table[index])
    ax.set_xticklabels([f"{int(i)}\n{a:.0f}°" for i, a in zip(table[index], table["angle"])],
                       fontsize=7)
    ax.set_xlabel(f"{index} (index, polar angle)")
    ax.set_ylabel(f"{symbol} [N]")
    ax.grid(alpha=0.3, axis="y")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def finish_torque_rotation(fig, ax, png):
    """Axes, grid and legend of a torque-against-rotation chart (ramp and hysteresis loop)."""
    ax.axhline(0, color="k", lw=0.5)
    ax.axvline(0, color="k", lw=0.5)
    ax.set_xlabel("output rotation θ [arcmin]")
    ax.set_ylabel("output torque [N·m]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def torsion(table, png):
    """The ramp -M_c -> +M_c -> -M_c: loading branch solid, unloading branch dashed (they
    coincide without friction); a profile with play jumps across zero torque by its backlash."""
    fig, ax = plt.subplots(figsize=(7, 5))
    for n, key in enumerate(k for k in table if k.startswith("rotation_")):
        for branch, style in (("loading", "o-"), ("unloading", "x--")):
            rows = [i for i, b in enumerate(table["branch"]) if b == branch]
            ax.plot([table[key][i] for i in rows], [table["torque"][i] for i in rows], style,
                    color=f"C{n}", label=f"{key[len('rotation_'):]}, {branch}")
    finish_torque_rotation(fig, ax, png)


def hysteresis(table, png):
    """The loops -M_c -> +M_c -> -M_c with friction: rising branch solid, falling dashed, the
    first loading dotted; a profile with play jumps across zero torque by its backlash."""
    fig, ax = plt.subplots(figsize=(7, 5))
    for n, name in enumerate(("nominal", "corrected")):
        for branch, style in (("rising", "o-"), ("falling", "x--"), ("first loading", ".:")):
            rows = [i for i in range(len(table["torque"]))
                    if table["profile"][i] == name and table["branch"][i] == branch]
            rows.sort(key=lambda i: table["torque"][i])
            if rows:
                ax.plot([table["rotation"][i] for i in rows], [table["torque"][i] for i in rows],
                        style, ms=3, color=f"C{n}", label=f"{name}, {branch}")
    finish_torque_rotation(fig, ax, png)


def sweep(table, png):
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    angle = table["crank_angle"]
    for key in (k for k in table if k.startswith("P_")):
        if max(table[key]) > 0:
            top.plot(angle, table[key], ".-", lw=1, label=key)
    for key in (k for k in table if k.startswith("Q_")):
        if max(table[key]) > 0:
            bottom.plot(angle, table[key], ".-", lw=1, label=key)
    top.set_ylabel("roller force P_i [N]")
    bottom.set_ylabel("pin force Q_j [N]")
    bottom.set_xlabel("crank angle φ_h [deg]")
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=6, ncol=4)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def main():
    mode, csv, png = sys.argv[1], sys.argv[2], sys.argv[-1]
    table = read_table(csv)
    if mode == "rollers":
        distribution(table, "roller", "roller force P_i", png)
    elif mode == "pins":
        distribution(table, "pin", "pin force Q_j", png)
    elif mode == "torsion":
        torsion(table, png)
    elif mode == "hysteresis":
        hysteresis(table, png)
    else:
        sweep(table, png)


if __name__ == "__main__":
    main()
