#!/usr/bin/env python3
"""Charts of `gearstiff dynamics` with Train/model = lateral.

    plot_lateral.py sharing  LOAD_SHARING.csv OUT.png   load sharing factor per planet
    plot_lateral.py campbell CAMPBELL.csv [CROSSINGS.csv] OUT.png
                                                        natural frequencies over carrier speed,
                                                        crossings circled, unstable speeds shaded
    plot_lateral.py orbit    ORBIT.csv [FLOOR] OUT.png  orbit of a central member (x, y); an
                                                        orbit smaller than FLOOR [µm] (1e-9 of
                                                        the sun's base radius) is round-off:
                                                        said in words, not drawn
    plot_lateral.py sweep    SWEEP.csv OUT.png          K_v, bearing forces, orbits over speed

CSV headers are "name [unit]" as written by the command; the PNG path is the last argument.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import chart_case  # noqa: E402,F401  (every figure names its case in a footer)
import matplotlib.pyplot as plt  # noqa: E402

from plot_dynamics import finish, read  # noqa: E402


def sharing(path, png):
    """Bars of N·F_sn/ΣF_s (sun meshes) and the ring meshes' factor per planet; 1 is equal."""
    _, c = read(path)
    planets = [int(p) for p in c["planet [-]"]]
    fig, ax = plt.subplots(figsize=(7, 4))
    width = 0.38
    ax.bar([p - width / 2 for p in planets], c["lsf_sun [-]"], width, label="sun meshes")
    ax.bar([p + width / 2 for p in planets], c["lsf_ring [-]"], width, label="ring meshes")
    ax.axhline(1.0, color="0.3", lw=0.8, ls="--", label="equal sharing")
    ax.set_xticks(planets)
    low = min(min(c["lsf_sun [-]"]), min(c["lsf_ring [-]"]))
    high = max(max(c["lsf_sun [-]"]), max(c["lsf_ring [-]"]))
    margin = max(0.02, 0.2 * (high - low))
    ax.set_ylim(min(low, 1.0) - margin, max(high, 1.0) + margin)
    ax.set_title("Planet load sharing factor")
    finish(fig, ax, "planet", "load sharing factor [-]", png)


def campbell(path, png, crossings_path=None):
    """Every natural frequency against carrier speed (rotating carrier frame); the mesh orders'
    crossings with them circled, the speeds where the undamped stage is unstable shaded (there
    a "frequency" is |Im λ| of a growing root)."""
    header, c = read(path)
    speed = c[header[0]]
    fig, ax = plt.subplots(figsize=(8, 5))
    extra = ("mesh_order_", "stability", "growth_rate")
    modes = [n for n in header[1:] if not n.startswith(extra)]
    orders = [n for n in header[1:] if n.startswith("mesh_order_")]
    for name in modes:
        ax.plot(speed, c[name], color="C0", lw=0.8)
    top = max(max(c[name]) for name in modes)
    for i, name in enumerate(orders):
        ax.plot(speed, c[name], color="C%d" % (i + 1), lw=1.0, ls="--",
                label="mesh order %s" % name.split("_")[-1].split(" ")[0])
    stability = c.get("stability [-]", [])
    step = (speed[1] - speed[0]) if len(speed) > 1 else 0.0
    shaded = False
    for s, state in zip(speed, stability):
        if state != "stable":
            ax.axvspan(s - step / 2, s + step / 2, color="C3", alpha=0.2, lw=0,
                       label=None if shaded else "unstable (divergence or flutter)")
            shaded = True
    if crossings_path:
        _, x = read(crossings_path)
        if x.get("carrier_speed [rpm]"):
            ax.plot(x["carrier_speed [rpm]"], x["frequency [Hz]"], "o", mfc="none", color="k",
                    ms=6, label="crossing (%d)" % len(x["carrier_speed [rpm]"]))
    ax.set_ylim(0, 1.05 * top)
    ax.set_title("Campbell chart of the lateral stage: natural frequencies with gyroscopic and "
                 "centripetal terms", fontsize=9)
    ax.plot([], [], color="C0", lw=0.8, label="natural frequencies")
    finish(fig, ax, "carrier speed [rpm]", "frequency [Hz]", png)


def orbit(path, png, floor=0.0):
    """x against y of the central members over the steady-state window; no picture of
    round-off: when every member's orbit spans less than `floor` [µm], a sentence instead."""
    header, c = read(path)
    spans = [max(c[h]) - min(c[h]) for h in header[1:]]
    if max(spans, default=0.0) < floor:
        fig, ax = plt.subplots(figsize=(6, 3))
        ax.axis("off")
        ax.text(0.5, 0.5, "no orbit: every central member moves less than %.3g µm\n"
                "(1e-9 of the sun's base radius), round-off of a motionless centre"
                % floor, ha="center", va="center", fontsize=10)
        ax.set_title("Orbits of the central members")
        fig.savefig(png, dpi=120)
        return
    fig, ax = plt.subplots(figsize=(6, 6))
    for i in range(1, len(header) - 1, 2):
        label = header[i].split("_x")[0]
        ax.plot(c[header[i]], c[header[i + 1]], lw=0.7, label=label)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_title("Orbits of the central members")
    finish(fig, ax, "x [µm]", "y [µm]", png)


def sweep(path, png):
    """K_v, largest bearing forces and orbit amplitudes against input speed; the down sweep
    dashed, invalid points (status not valid) marked x."""
    _, c = read(path)
    fig, axes = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    for tag, style in (("up", "-o"), ("down", "--s")):
        rows = [i for i, d in enumerate(c["direction [-]"]) if d == tag]
        if not rows:
            continue
        speed = [c["input_speed [rpm]"][i] for i in rows]
        axes[0].plot(speed, [c["kv_max [-]"][i] for i in rows], style, ms=3, color="C0",
                     label="K_v " + tag)
        bad = [i for i in rows if c["status [-]"][i] != "valid"]
        axes[0].plot([c["input_speed [rpm]"][i] for i in bad], [c["kv_max [-]"][i] for i in bad],
                     "x", color="k")
        for j, member in enumerate(("carrier", "ring", "sun")):
            axes[1].plot(speed, [c["bearing_force_%s [N]" % member][i] for i in rows], style,
                         ms=3, color="C%d" % j, label="%s %s" % (member, tag))
            axes[2].plot(speed, [c["orbit_%s [um]" % member][i] for i in rows], style, ms=3,
                         color="C%d" % j, label="%s %s" % (member, tag))
    axes[0].set_ylabel("K_v max [-]")
    axes[1].set_ylabel("largest bearing force [N]")
    axes[0].set_title("Lateral stage: speed sweep")
    for ax in axes[:2]:
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=7)
    finish(fig, axes[2], "input speed [rpm]", "orbit amplitude [µm]", png)


def main(argv):
    kind = argv[1]
    if kind == "sharing":
        sharing(argv[2], argv[-1])
    elif kind == "campbell":
        campbell(argv[2], argv[-1], argv[3] if len(argv) > 4 else None)
    elif kind == "sweep":
        sweep(argv[2], argv[-1])
    else:
        orbit(argv[2], argv[-1], float(argv[3]) if len(argv) > 4 else 0.0)


if __name__ == "__main__":
    main(sys.argv)
