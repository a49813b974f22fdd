#!/usr/bin/env python3
"""Bi-planetary study (issue 15): ring 7 fastened to the frame (variant I) against ring 7 hung on
a torsional spring and damper (variant II), with the train model of `gearstiff dynamics`.

    python3 bench/dynamics_biplanetary_study.py [gearstiff] [points]   (defaults: build, 40)
    python3 bench/dynamics_biplanetary_study.py --plot-only     (chart from the CSV again)

Input: bench/dynamics_biplanetary.prm (stated assumptions: steel blanks, FE k(θ) of every mesh
from bench/biplanetary_meshes/, c_g = 600 N·s/m). For each variant: natural frequencies, K_v max
of every mesh at 1470 rpm beside ISO 6336-1 method B, and a K_v speed sweep; the same at 1470 rpm
with the earlier Cai curves (280 N/µm single-pair peak) for comparison. Writes
docs/biplanetary_dynamics.csv (sweeps), docs/biplanetary_resonance.png (the resonance charts side
by side) and prints the Markdown tables used in docs/biplanetary_dynamics.md. Run it holding the
build lock.
"""
import csv
import json
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
binary = sys.argv[1] if len(sys.argv) > 1 and sys.argv[1] != "--plot-only" else os.path.join(root, "build", "app", "gearstiff")
points = int(sys.argv[2]) if len(sys.argv) > 2 else 40
prm = os.path.join(root, "bench", "dynamics_biplanetary.prm")
damping = 50.0  # N·m·s/rad of the suspension
variants = [("I: ring 7 fixed", None)] + [
    (f"II: k_s = {k:.0e} N·m/rad", k) for k in (1e5, 1e6, 1e7)]


def plot_sweeps(sweeps):
    """Ring fixed against the middle suspension stiffness: the linear model's K_v max in grey,
    valid points in colour, the rest marked by status."""
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
    for ax, (label, rows) in zip(axes, (sweeps[0], sweeps[2])):
        speed = [r["input_speed"] for r in rows]
        ax.plot(speed, [r["kv_max_linear"] for r in rows], "-", color="0.6", lw=1,
                label="K_v max of the linear model")
        for status, marker in (("valid", "o"), ("contact loss", "x"), ("not steady", "+")):
            pts = [(r["input_speed"], r["kv_max_linear"]) for r in rows if r["status"] == status]
            if pts:
                ax.plot([p[0] for p in pts], [p[1] for p in pts], marker, ms=5, label=status)
        ax.set_title(label)
        ax.set_xlabel("input speed n1 [rpm]")
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=8)
    axes[0].set_ylabel("K_v max over all meshes [-]")
    fig.tight_layout()
    fig.savefig(os.path.join(root, "docs", "biplanetary_resonance.png"), dpi=110)


if len(sys.argv) > 1 and sys.argv[1] == "--plot-only":
    sweeps = {}
    with open(os.path.join(root, "docs", "biplanetary_dynamics.csv"), newline="") as f:
        for r in csv.DictReader(f):
            sweeps.setdefault(r["variant"], []).append(
                {"input_speed": float(r["input_speed [rpm]"]), "status": r["status [-]"],
                 "kv_max_linear": float(r["kv_max_linear [-]"])})
    plot_sweeps(list(sweeps.items()))
    sys.exit(0)


def run(*settings):
    args = [binary, "dynamics", prm, "--json"]
    for s in settings:
        args += ["--set", s]
    out = subprocess.run(args, check=True, capture_output=True, text=True, cwd=root).stdout
    return json.loads(out[out.index("{"):])


def table(result, name):
    t = result["tables"][name]
    return [dict(zip(t["columns"], row)) for row in t["rows"]]


meshes = ("1-2", "3-4", "4-5", "6-7")
cai = [f"Train mesh {n}/stiffness source=cai" for n in range(1, 5)]


def by_mesh(result, key):
    """Per Train mesh: the largest of `key` over its copies (dynamics_meshes table)."""
    rows = table(result, "dynamics_meshes")
    names = [t for t in result["text"] if t.endswith(" stiffness")]
    out = {}
    for name, row in zip(names, rows):
        base = name.split("#")[0].replace(" stiffness", "")
        out[base] = max(out.get(base, 0.0), row[key] or 0.0)
    return out


def mean_stiffness(result):
    return {m: result["values"][k]["value"] for m in meshes
            for k in result["values"] if k.endswith("_mean_stiffness")
            and result["values"][k]["description"].startswith(m + "#1 ")}


results = []
for label, k in variants:
    extra = [] if k is None else [f"Train/suspended members=7: {k} {damping}"]
    single = run(*extra)
    sweep = run(*extra, f"Speed sweep/points={points}", "Speed sweep/minimum speed=100",
                "Speed sweep/maximum speed=6000")
    results.append((label, single, sweep))

print("| variant | natural frequencies [Hz] |")
print("|---|---|")
for label, single, _ in results:
    f = [r["frequency"] for r in table(single, "dynamics_modes")]
    print(f"| {label} | " + ", ".join(f"{x:.0f}" for x in f) + " |")

print("\n| variant | stiffness | mean k 1-2 / 3-4 / 4-5 / 6-7 [N/µm] | lowest 4 natural frequencies [Hz] "
      "| K_v max 1-2 / 3-4 / 4-5 / 6-7 at 1470 rpm |")
print("|---|---|---|---|---|")
for (label, k), (_, fe, _) in zip(variants, results):
    if k not in (None, 1e6):
        continue
    extra = [] if k is None else [f"Train/suspended members=7: {k} {damping}"]
    for source, result in (("Cai 280 N/µm", run(*extra, *cai)), ("FE", fe)):
        f = [r["frequency"] for r in table(result, "dynamics_modes")][:4]
        kv, km = by_mesh(result, "kv_max"), mean_stiffness(result)
        print(f"| {label} | {source} | " + " / ".join(f"{km[m]:.0f}" for m in meshes) + " | "
              + ", ".join(f"{x:.0f}" for x in f) + " | "
              + " / ".join(f"{kv[m]:.3f}" for m in meshes) + " |")

print("\n| variant | " + " | ".join(
    f"K_v max {m} (ISO)" for m in meshes) + " | sweep: diverged / contact loss / not steady |")
print("|---|---|---|---|---|---|")
for label, single, sweep in results:
    kv, iso = by_mesh(single, "kv_max"), by_mesh(single, "kv_iso")
    s = sweep["values"]
    print(f"| {label} | " + " | ".join(f"{kv.get(m, float('nan')):.3f} ({iso.get(m, float('nan')):.3f})"
                                        for m in meshes)
          + f" | {s['sweep_unstable']['value']:.0f} / {s['sweep_contact_loss']['value']:.0f} / "
            f"{s['sweep_not_steady']['value']:.0f} |")

os.makedirs(os.path.join(root, "docs"), exist_ok=True)
with open(os.path.join(root, "docs", "biplanetary_dynamics.csv"), "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["variant", "input_speed [rpm]", "kv_max [-]", "status [-]", "kv_max_linear [-]"])
    for label, _, sweep in results:
        for r in table(sweep, "dynamics_speed_sweep"):
            w.writerow([label, r["input_speed"], r["kv_max"], r["status"], r["kv_max_linear"]])

plot_sweeps([(label, table(sweep, "dynamics_speed_sweep")) for label, _, sweep in results])
print("\nwrote docs/biplanetary_dynamics.csv, docs/biplanetary_resonance.png")
