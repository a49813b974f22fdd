#!/usr/bin/env python3
"""Charts that say what they show (issue 44.4), checked on the figures the plot scripts draw
from small CSV files written here (each chart's input as the command writes it).

usage: charts44.py TOOLS_DIR WORKDIR

1. Resonance chart of a sweep `both` (up 1000..3000 rpm, down 3000..1000): two K_v lines, one
   per direction, each monotone in speed (drawn as one line it zig-zagged back), and a title.
2. Vibration chart: angles phi(t) = 50 + 2000·t + 3·cos(2π·500·t) µrad; the drawn curve in the
   window is the vibration alone (its mean and slope ~0; its amplitude 3 µrad
   within 2 %: the cosine is even about the window middle, so the fit takes the drift alone),
   the legend states the removed drift 2000 µrad/s.
3. Lateral Campbell chart: the unstable speeds shaded, the crossings circled (their count in
   the legend), the axes with units.
4. Faults chart: the healthy and the faulty pass, the fault restated in the title, the crack tip's
   K_I/K_II panel, axes with units.
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def write(path, header, rows):
    with open(path, "w") as f:
        f.write(",".join(header) + "\n")
        for row in rows:
            f.write(",".join(str(v) for v in row) + "\n")
    return path


def check(condition, message):
    if not condition:
        sys.exit("FAILED: " + message)
    print("ok:", message)


def resonance(tools, work):
    import plot_dynamics
    speeds = [1000, 1500, 2000, 2500, 3000, 3000, 2500, 2000, 1500, 1000]
    rows = [[s, s / 60 * 21, 0.5, 1 + s / 1e4, 0.9, 1.1, "valid", 5, 1 + s / 1e4] for s in speeds]
    csv = write(os.path.join(work, "sweep.csv"),
                ["input_speed [rpm]", "mesh_frequency [Hz]", "resonance_ratio [-]", "kv_max [-]",
                 "kv_min [-]", "kv_iso [-]", "status [-]", "time_step [µs]",
                 "kv_max_linear [-]"], rows)
    plot_dynamics.resonance(csv, os.path.join(work, "resonance.png"))
    ax = plt.gcf().axes[0]
    kv = [line for line in ax.lines if (line.get_label() or "").startswith("K_v max")]
    check(len(kv) == 2, "resonance: one K_v line per sweep direction (found %d)" % len(kv))
    up = list(kv[0].get_xdata())
    down = list(kv[1].get_xdata())
    check(up == sorted(up) and down == sorted(down, reverse=True),
          "resonance: the up line rises in speed, the down line falls (no zig-zag)")
    check("Resonance chart" in ax.get_title() and "[rpm]" in ax.get_xlabel(),
          "resonance: title and speed axis with its unit")
    plt.close("all")


def vibration(tools, work):
    import plot_dynamics
    rows = []
    for i in range(4001):
        t = i * 1e-5  # 0 … 0.04 s
        rows.append([t, 50 + 2000 * t + 3 * math.cos(2 * math.pi * 500 * t)])
    csv = write(os.path.join(work, "series.csv"), ["time [s]", "phi_1 [µrad]"], rows)
    plot_dynamics.time_series("vibration", csv, "0.02,0.04", os.path.join(work, "vib.png"))
    ax = plt.gcf().axes[0]
    line = ax.lines[0]
    t, y = list(line.get_xdata()), list(line.get_ydata())
    mean = sum(y) / len(y)
    tm = sum(t) / len(t)
    slope = sum((a - tm) * b for a, b in zip(t, y)) / sum((a - tm) ** 2 for a in t)
    check(abs(mean) < 1e-6 and abs(slope) < 1e-3,
          "vibration: drawn about its mean and drift (mean %.2g µrad, slope %.2g µrad/s)"
          % (mean, slope))
    amplitude = 0.5 * (max(y) - min(y))
    check(abs(amplitude - 3.0) < 0.06, "vibration: amplitude %.4f µrad (3 µrad drawn)" % amplitude)
    check("drift 2000 µrad/s removed" in line.get_label(),
          "vibration: the legend states the removed drift (%s)" % line.get_label())
    check("[µrad]" in ax.get_ylabel() and "[s]" in ax.get_xlabel(), "vibration: axes with units")
    plt.close("all")


def campbell(tools, work):
    import plot_lateral
    header = ["carrier_speed [rpm]", "f1 [Hz]", "f2 [Hz]", "mesh_order_1 [Hz]", "stability [-]",
              "growth_rate [1/s]"]
    rows = []
    for i in range(11):
        s = 100.0 * i
        rows.append([s, 300 - 0.1 * s, 500 + 0.1 * s, 0.6 * s,
                     "stable" if s < 800 else "divergence", 0 if s < 800 else 5.0])
    csv = write(os.path.join(work, "campbell.csv"), header, rows)
    crossings = write(os.path.join(work, "crossings.csv"),
                      ["order [-]", "mode [-]", "carrier_speed [rpm]", "input_speed [rpm]",
                       "frequency [Hz]"], [[1, 1, 428.57, 1800, 257.14], [1, 2, 1000, 4200, 600]])
    plot_lateral.campbell(csv, os.path.join(work, "campbell.png"), crossings)
    ax = plt.gcf().axes[0]
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    check(any(label.startswith("unstable") for label in labels) and len(ax.patches) == 3,
          "campbell: the 3 unstable speeds shaded (%d spans)" % len(ax.patches))
    check("crossing (2)" in labels, "campbell: the 2 crossings circled (%s)" % labels)
    check("[rpm]" in ax.get_xlabel() and "[Hz]" in ax.get_ylabel() and ax.get_title(),
          "campbell: title and axes with units")
    plt.close("all")


def faults(tools, work):
    import plot_faults
    sweep = write(os.path.join(work, "fault_sweep.csv"),
                  ["mesh_position [-]", "healthy_stiffness [N/um]", "faulty_stiffness [N/um]",
                   "lost_contact [-]"],
                  [[0.0, 400, 380, 0], [0.5, 420, 390, 0], [1.0, 410, 0, 1]])
    tip = write(os.path.join(work, "crack_tip.csv"),
                ["mesh_position [-]", "K_I [MPa*m^0.5]", "K_II [MPa*m^0.5]"],
                [[0.0, 5, 1], [0.5, 7, 2], [1.0, 0, 0]])
    fault = "pinion tooth 0: root crack 1 mm deep at 45° to the centre line"
    plot_faults.main(["plot_faults.py", sweep, fault, tip, os.path.join(work, "faults.png")])
    axes = plt.gcf().axes
    check(len(axes) == 2, "faults: stiffness and crack tip panels")
    labels = [line.get_label() for line in axes[0].lines]
    check("healthy pass" in labels and "faulty pass" in labels,
          "faults: the healthy and the faulty pass (%s)" % labels)
    check(fault in axes[0].get_title(), "faults: the title restates the fault")
    check("[N/µm]" in axes[0].get_ylabel() and "[base pitches]" in axes[1].get_xlabel()
          and "√m" in axes[1].get_ylabel(), "faults: axes with units")
    plt.close("all")


def main():
    tools, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    sys.path.insert(0, tools)
    resonance(tools, work)
    vibration(tools, work)
    campbell(tools, work)
    faults(tools, work)


if __name__ == "__main__":
    main()
