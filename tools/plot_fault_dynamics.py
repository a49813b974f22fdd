#!/usr/bin/env python3
"""Healthy against faulty `gearstiff dynamics` runs with whole-revolution stiffness tables
(issue 31, docs/faults.md "Dynamics with the faulty table"): the dynamic transmission error over
the window's revolutions, and the mesh-force spectrum around the first mesh harmonics with the
sidebands h·f_m ± s·f_r marked (f_r = the faulty gear's rotation frequency).

    plot_fault_dynamics.py HEALTHY_DIR FAULTY_DIR OUT.png

Each DIR is the -o folder of one `gearstiff dynamics` run (dynamics_time_series.csv,
dynamics_spectrum.csv, summary.json); f_m and f_r come from the faulty run's summary.json.
"""
import json
import os
import sys

from dynamics_charts import plt, read


def run(folder):
    with open(os.path.join(folder, "summary.json")) as f:
        values = {k: v["value"] for k, v in json.load(f)["values"].items()}
    series = read(os.path.join(folder, "dynamics_time_series.csv"))
    spectrum = read(os.path.join(folder, "dynamics_spectrum.csv"))
    return values, series, spectrum


def first(header, prefix):
    for h in header:
        if h.startswith(prefix):
            return h
    raise SystemExit(f"no column {prefix}*")


def main(healthy_dir, faulty_dir, png):
    runs = {"healthy": run(healthy_dir), "faulty": run(faulty_dir)}
    values = runs["faulty"][0]
    f_m = values["mesh_frequency"]
    f_r = values.get("revolution_frequency", f_m)
    fig, (trace, difference, spectrum) = plt.subplots(3, 1, figsize=(10, 10))
    colours = {"healthy": "tab:blue", "faulty": "tab:red"}
    traces = {}
    for name, (v, (header, c), (sheader, sc)) in runs.items():
        t = c[header[0]]
        dte = c[first(header, "dte_")]
        keep = [i for i, ti in enumerate(t) if v["window_start"] <= ti <= v["window_end"]]
        traces[name] = ([(t[i] - v["window_start"]) * f_r for i in keep], [dte[i] for i in keep])
        trace.plot(*traces[name], lw=0.6, color=colours[name], label=name)
        freq = sc[sheader[0]]
        amp = sc[first(sheader, "amplitude_")]
        band = [i for i, fi in enumerate(freq) if 0.5 * f_m <= fi <= 3.5 * f_m]
        spectrum.semilogy([freq[i] for i in band], [max(amp[i], 1e-9) for i in band],
                          lw=0.7, color=colours[name], label=name)
    (x, healthy), (_, faulty) = traces["healthy"], traces["faulty"]
    if len(healthy) == len(faulty):  # same step and window: the fault's share of the DTE
        difference.plot(x, [f - h for f, h in zip(faulty, healthy)], lw=0.6, color="tab:red",
                        label="faulty − healthy")
    difference.set_xlabel("revolutions of the faulty gear in the window [-]")
    difference.set_ylabel("DTE difference [µm]")
    for h in (1, 2, 3):
        spectrum.axvline(h * f_m, color="0.5", lw=0.8, ls="--")
        for s in (-3, -2, -1, 1, 2, 3):
            spectrum.axvline(h * f_m + s * f_r, color="0.8", lw=0.5, ls=":")
    trace.set_xlabel("revolutions of the faulty gear in the window [-]")
    trace.set_ylabel("dynamic transmission error δ [µm]")
    trace.set_title("DTE over the window: once-per-revolution impulse")
    spectrum.set_xlabel(f"frequency [Hz]   (f_m = {f_m:.4g} Hz, f_r = {f_r:.4g} Hz: "
                        "dashed h·f_m, dotted h·f_m ± s·f_r)")
    spectrum.set_ylabel("mesh-force amplitude [N]")
    spectrum.set_title("mesh-force spectrum: sidebands at the mesh harmonics ± f_r")
    for ax in (trace, difference, spectrum):
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        raise SystemExit(__doc__)
    main(*sys.argv[1:])
