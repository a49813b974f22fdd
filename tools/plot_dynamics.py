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


def vibration_chart(path, window, png, title=""):
    """phi_i(t) in the steady-state window about each angle's straight-line fit: a free train's
    angles drift (a rigid rotation at a slightly different mean speed, the static wind-up), which
    on one axis hid the vibration; the removed drift rate is in the legend."""
    header, c = read(path)
    t = c[header[0]]
    start, end = (float(x) for x in window.split(",")[:2])
    rows = [i for i, time in enumerate(t) if start <= time <= end]
    fig, ax = plt.subplots(figsize=(9, 4.5))
    times = [t[i] for i in rows]
    for h in header[1:]:
        if not h.startswith("phi_") or len(rows) < 2:
            continue
        values = [c[h][i] for i in rows]
        tm, vm = sum(times) / len(times), sum(values) / len(values)
        sxx = sum((x - tm) ** 2 for x in times)
        rate = sum((x - tm) * (v - vm) for x, v in zip(times, values)) / sxx if sxx > 0 else 0.
        ax.plot(times, [v - vm - rate * (x - tm) for x, v in zip(times, values)], lw=0.7,
                label="%s (mean %.4g µrad, drift %.4g µrad/s removed)" % (h.split(" [")[0], vm,
                                                                           rate))
    ax.set_title("Torsional vibration in the steady-state window, about each angle's mean and "
                 "linear drift" + (" — " + title if title else ""), fontsize=9)
    finish(fig, ax, "time [s]", "angle about its mean and drift [µrad]", png, "upper right", 7)


def time_series(kind, path, window, png):
    if kind == "kv":
        kv_chart(path, window, png)
        return
    if kind == "vibration":
        vibration_chart(path, window, png)
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


def sweep_legs(speed):
    """The row ranges of each sweep direction: a sweep `both` runs up, then down from the top
    speed; drawn as one line it zig-zags back over the up sweep."""
    if len(speed) > 1 and speed[1] < speed[0]:
        return [("down", range(len(speed)))]
    turn = next((i for i in range(1, len(speed)) if speed[i] <= speed[i - 1]), len(speed))
    legs = [("up" if turn < len(speed) else "", range(0, turn))]
    if turn < len(speed):
        legs.append(("down", range(turn, len(speed))))
    return legs


def resonance(path, png, title=""):
    header, c = read(path)
    speed = c["input_speed [rpm]"]
    fig, ax = plt.subplots(figsize=(9, 4.5))
    for tag, rows in sweep_legs(speed):
        ax.plot([speed[i] for i in rows], [c["kv_max [-]"][i] for i in rows],
                "o-" if tag != "down" else "s--", ms=3, lw=1,
                color="C0" if tag != "down" else "C3",
                label="K_v max (simulated%s)" % (", sweep " + tag if tag else ""))
    first = sweep_legs(speed)[0][1]  # ISO K_v depends on the speed alone: one leg
    ax.plot([speed[i] for i in first], [c["kv_iso [-]"][i] for i in first], "--", lw=1,
            color="C1", label="K_v ISO 6336-1 method B")
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
    ax.set_title("Resonance chart: K_v max against input speed" + (" — " + title if title else ""),
                 fontsize=10)
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
