#!/usr/bin/env python3
"""Charts of `gearstiff dynamics`.

    plot_dynamics.py vibration SERIES.csv START,END OUT.png   torsional vibration phi_i(t)
    plot_dynamics.py kv        SERIES.csv START,END[,PERIOD] OUT.png
                                      K_v(t): above, its envelope (max and min over each mesh
                                      period PERIOD [s]) over the whole run with the window;
                                      below, the last four mesh periods of the window
    plot_dynamics.py stiffness SERIES.csv START,END OUT.png   mesh stiffness k(t)
    plot_dynamics.py resonance SWEEP.csv OUT.png              K_v max and ISO K_v against speed
    plot_dynamics.py campbell  CAMPBELL.csv MODES.csv MIN,MAX OUT.png
                                      mesh-frequency orders against the natural frequencies

CSV headers are "name [unit]" as written by the command; the PNG path is the last argument.
"""
import sys

from dynamics_charts import finish, plt, read, shade_window


def envelope(t, values, period):
    """Per mesh period: the period's middle time, the smallest and the largest value."""
    mids, lows, highs, bucket, start = [], [], [], [], t[0]
    for time, v in zip(t, values):
        if time >= start + period and bucket:
            mids.append(start + 0.5 * period)
            lows.append(min(bucket))
            highs.append(max(bucket))
            bucket, start = [], start + period * int((time - start) / period)
        bucket.append(v)
    return mids, lows, highs


def kv_chart(path, window, png):
    header, c = read(path)
    t = c[header[0]]
    numbers = [float(x) for x in window.split(",")]
    start, end = numbers[0], numbers[1]
    period = numbers[2] if len(numbers) > 2 else (end - start) / 40.
    fig, (whole, detail) = plt.subplots(2, 1, figsize=(9, 6.5))
    columns = [h for h in header[1:] if h.startswith("kv_")]
    for n, h in enumerate(columns):
        mids, lows, highs = envelope(t, c[h], period)
        whole.fill_between(mids, lows, highs, color=f"C{n}", alpha=0.35, lw=0)
        whole.plot(mids, highs, color=f"C{n}", lw=0.8, label=f"{h}: max/min per mesh period")
        rows = [i for i, time in enumerate(t) if end - 4. * period <= time <= end]
        detail.plot([t[i] for i in rows], [c[h][i] for i in rows], color=f"C{n}", lw=1., label=h)
    whole.axvspan(start, end, color="0.9", zorder=0, label="steady-state window")
    whole.set_title("K_v(t) envelope over the run", fontsize=10)
    detail.set_title(f"the last four mesh periods of the window (period {period * 1e3:.3g} ms)",
                     fontsize=10)
    for ax in (whole, detail):
        ax.set_xlabel("time [s]")
        ax.set_ylabel("K_v = F / F_nominal [-]")
        ax.grid(True, lw=0.3)
        ax.legend(loc="best", fontsize=7)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def time_series(kind, path, window, png):
    if kind == "kv":
        kv_chart(path, window, png)
        return
    header, c = read(path)
    t = c[header[0]]
    fig, ax = plt.subplots(figsize=(9, 4.5))
    prefix = {"vibration": "phi_", "kv": "kv_", "stiffness": "stiffness_"}[kind]
    for h in header[1:]:
        if h.startswith(prefix):
            ax.plot(t, c[h], lw=0.7, label=h)
    shade_window(ax, window)
    if kind == "stiffness":
        # Stiffness repeats every mesh period: show the last few periods of the window.
        start, end = (float(x) for x in window.split(","))
        ax.set_xlim(max(start, end - (end - start) / 8), end)
    finish(fig, ax, "time [s]",
           {"vibration": "angle relative to nominal rotation [µrad]",
            "kv": "K_v = F / F_nominal [-]",
            "stiffness": "mesh stiffness [N/µm]"}[kind], png)


def resonance(path, png):
    header, c = read(path)
    speed = c["input_speed [rpm]"]
    fig, ax = plt.subplots(figsize=(9, 4.5))
    ax.plot(speed, c["kv_max [-]"], "o-", ms=3, lw=1, label="K_v max (simulated)")
    ax.plot(speed, c["kv_iso [-]"], "--", lw=1, label="K_v ISO 6336-1 method B")
    status = c["status [-]"]
    unstable = [s for s, u in zip(speed, status) if u == "diverged"]
    if unstable:
        ax.plot(unstable, [1.0] * len(unstable), "rx", label="linear model diverges")
    # The linear model's K_v exists but is not a valid result; shown apart.
    invalid = [(s, k) for s, u, k in zip(speed, status, c["kv_max_linear [-]"])
               if u in ("contact loss", "not steady")]
    if invalid:
        ax.plot([s for s, _ in invalid], [1.0] * len(invalid), "m+",
                label="contact loss / not steady (no valid K_v)")
    # Near a parametric instability K_v can reach tens; clip so the chart stays readable and
    # mark the clipped points at the top edge.
    finite = sorted(k for k in c["kv_max [-]"] if k == k)
    if finite:
        top = min(finite[-1] * 1.05, max(6.0, 2.0 * finite[len(finite) // 2]))
        ax.set_ylim(0, top)
        clipped = [s for s, k in zip(speed, c["kv_max [-]"]) if k == k and k > top]
        if clipped:
            ax.plot(clipped, [top * 0.98] * len(clipped), "^", color="C0",
                    label="K_v max beyond the scale")
    finish(fig, ax, "input speed n1 [rpm]", "dynamic factor K_v [-]", png)


def campbell(path, modes_path, speeds, png):
    """Orders 1-3 of every mesh frequency over the input speed, natural frequencies as
    horizontal lines; a crossing is a speed where a mesh harmonic can excite a mode."""
    _, c = read(path)
    _, modes = read(modes_path)
    low, high = (float(x) for x in speeds.split(","))
    fig, ax = plt.subplots(figsize=(9, 5))
    top = 0.0
    for i, (mesh, rate) in enumerate(zip(c["mesh [-]"], c["mesh_frequency_per_rpm [Hz/rpm]"])):
        for order, style in ((1, "-"), (2, "--"), (3, ":")):
            ax.plot([low, high], [order * rate * low, order * rate * high], style,
                    color=f"C{i % 10}", lw=1,
                    label=f"mesh {int(mesh)} x{order}" if order == 1 else None)
            top = max(top, order * rate * high)
    frequencies = [f for f in modes["frequency [Hz]"] if f == f and f > 0]
    for f in frequencies:
        ax.axhline(f, color="0.5", lw=0.6)
    if frequencies:
        top = 1.1 * max(frequencies)
    ax.set_xlim(low, high)
    ax.set_ylim(0, top)
    ax.set_title("Campbell chart: mesh orders 1 (solid), 2 (dashed), 3 (dotted); modes (grey)")
    finish(fig, ax, "input speed [rpm]", "frequency [Hz]", png, "upper left", 7)


def main(argv):
    kind = argv[1]
    if kind == "resonance":
        resonance(argv[2], argv[-1])
    elif kind == "campbell":
        campbell(argv[2], argv[3], argv[4], argv[-1])
    else:
        time_series(kind, argv[2], argv[3], argv[-1])


if __name__ == "__main__":
    main(sys.argv)
