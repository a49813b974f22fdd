#!/usr/bin/env python3
"""Bi-planetary study on the planar lateral-torsional model (issue 30): ring 7 fastened to the
frame (variant I) against ring 7 hung on a torsional spring and damper (variant II), with its
radial support soft (an elastic ring of that torsional stiffness) or stiff.

    python3 bench/dynamics_biplanetary_lateral.py [gearstiff] [points]   (defaults: build, 30)
    python3 bench/dynamics_biplanetary_lateral.py --plot-only   (charts from the CSVs again)

Input: bench/dynamics_biplanetary_lateral.prm (assumptions in its header). For each variant:
modes with their classes, static mesh and bearing forces, the response at 1470 rpm (K_v per
Train mesh, orbit and bearing force of sun 1, carrier h and ring 7) and a speed sweep
100-6000 rpm. Writes docs/biplanetary_lateral.csv (sweeps), docs/biplanetary_lateral_orbit.csv
(ring 7's orbit at 1470 rpm), docs/biplanetary_ring_orbit.png (its chart) and
docs/biplanetary_lateral_sweep.png, and prints the Markdown tables of docs/biplanetary_dynamics.md.
Run it holding the build lock.
"""
import csv
import json
import os
import subprocess
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
plot_only = len(sys.argv) > 1 and sys.argv[1] == "--plot-only"
binary = sys.argv[1] if len(sys.argv) > 1 and not plot_only else os.path.join(
    root, "build", "app", "gearstiff")
points = int(sys.argv[2]) if len(sys.argv) > 2 else 30
prm = os.path.join(root, "bench", "dynamics_biplanetary_lateral.prm")
suspended = "Train/suspended members=7: 1e6 50"
variants = [
    ("I: ring 7 fixed", []),
    ("II: k_s = 1e6 N·m/rad, radial 4.1e7 N/m", [
        suspended, "Train/bearing stiffness=1: 1e8, h: 1e9, 7: 4.1e7",
        "Train/bearing damping=1: 457, h: 12321, 7: 854"]),
    ("II': k_s = 1e6 N·m/rad, radial 1e9 N/m", [suspended]),
]
sweep_csv = os.path.join(root, "docs", "biplanetary_lateral.csv")
orbit_csv = os.path.join(root, "docs", "biplanetary_lateral_orbit.csv")


def plot(sweeps, orbits):
    fig, axes = plt.subplots(1, 2, figsize=(12, 6))
    for (label, rows), style in zip(orbits.items(), ("-", "--", ":")):
        x, y = [r[0] for r in rows], [r[1] for r in rows]
        mx, my = sum(x) / len(x), sum(y) / len(y)
        axes[0].plot(x, y, style, lw=1.0, label=label)
        axes[1].plot([v - mx for v in x], [v - my for v in y], style, lw=1.0, label=label)
    for ax, title in zip(axes, ("Ring 7 at 1470 rpm: static offset and orbit",
                                "the orbit about its mean")):
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_title(title)
        ax.set_xlabel("x [µm]")
        ax.set_ylabel("y [µm]")
        ax.grid(True, lw=0.3)
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(root, "docs", "biplanetary_ring_orbit.png"), dpi=110)
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    for label, rows in sweeps.items():
        speed = [r["input_speed"] for r in rows]
        kv = [max(r[f"kv_mesh{m}"] for m in range(1, 5)) for r in rows]
        axes[0].plot(speed, kv, "o-", ms=3, lw=0.8, label=label)
        axes[1].plot(speed, [r["orbit_7"] for r in rows], "o-", ms=3, lw=0.8, label=label)
        axes[2].plot(speed, [r["bearing_force_7"] for r in rows], "o-", ms=3, lw=0.8, label=label)
    for ax, title in zip(axes, ("K_v max over all meshes [-]", "ring 7 orbit amplitude [µm]",
                                "ring 7 largest bearing force [N]")):
        ax.set_title(title)
        ax.set_xlabel("input speed n1 [rpm]")
        ax.grid(True, lw=0.3)
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(root, "docs", "biplanetary_lateral_sweep.png"), dpi=110)


def read_back():
    sweeps, orbits = {}, {}
    with open(sweep_csv, newline="") as f:
        for r in csv.DictReader(f):
            sweeps.setdefault(r["variant"], []).append(
                {k: v if k == "status" else float(v) for k, v in r.items() if k != "variant"})
    with open(orbit_csv, newline="") as f:
        for r in csv.DictReader(f):
            orbits.setdefault(r["variant"], []).append((float(r["x"]), float(r["y"])))
    return sweeps, orbits


if plot_only:
    plot(*read_back())
    sys.exit(0)


def run(*settings):
    args = [binary, "dynamics", prm, "--json"]
    for s in settings:
        args += ["--set", s]
    start = time.perf_counter()
    out = subprocess.run(args, check=True, capture_output=True, text=True, cwd=root).stdout
    return json.loads(out[out.index("{"):]), time.perf_counter() - start


def table(result, name):
    t = result["tables"][name]
    return [dict(zip([c.split(" [")[0] for c in t["columns"]], row)) for row in t["rows"]]


def value(result, key):
    return result["values"][key]["value"]


def carrier_force(result):
    """Largest bearing force on carrier h (the body of h and its rings 5)."""
    return value(result, "bearing_force_max_h")


# Every copy of every mesh is in phase (z/N whole for 1, 3, 5 and 7), so the mesh excitation
# alone is cyclic-symmetric and the central members do not orbit: a tangential pin error of
# planet 2#1 (10 µm) breaks the symmetry, as a real train's errors do.
error = "Train/planet pin errors=2#1: 10 0"
perfect = []
for label, extra in variants:
    single, wall = run(*extra)
    perfect.append((label, single, wall))
results = []
for label, extra in variants:
    single, wall = run(*extra, error)
    sweep, sweep_wall = run(*extra, error, f"Speed sweep/points={points}",
                            "Speed sweep/minimum speed=100", "Speed sweep/maximum speed=6000")
    results.append((label, single, sweep, wall, sweep_wall))

print("| variant (no error) | K_v 1-2 / 3-4 / 4-5 / 6-7 at 1470 rpm | ring 7 orbit [µm] |"
      " static inner-set shares 3-4 | run wall [s] |")
print("|---|---|---|---|---|")
for label, single, wall in perfect:
    kv = " / ".join(f"{value(single, f'kv_max_train_mesh{m}'):.3f}" for m in range(1, 5))
    shares = [r["share"] for r in table(single, "lateral_train_mesh_forces")
              if round(r["train_mesh"]) == 2][:3]
    print(f"| {label} | {kv} | {value(single, 'orbit_7'):.2e} | "
          + " / ".join(f"{x:.3f}" for x in shares) + f" | {wall:.1f} |")
print()

print("| variant | lowest natural frequencies [Hz] (class: r rotational ×1, t translational ×2) |"
      " rotational / translational / planet / mixed groups |")
print("|---|---|---|")
names = {"rotational": "r", "translational": "t", "planet": "p", "mixed": "m"}
for label, single, *_ in perfect:
    groups = {}
    for r in table(single, "lateral_train_modes"):
        groups.setdefault(r["group"], (r["frequency"], names[r["class"]]))
    low = [f"{f:.0f} {c}" for f, c in list(groups.values())[:12]]
    counts = " / ".join(f"{value(single, k):.0f}" for k in (
        "rotational_groups", "translational_groups", "planet_groups", "mixed_groups"))
    print(f"| {label} | " + ", ".join(low) + f" | {counts} |")

print("\n| variant (pin error 2#1 10 µm) | K_v 1-2 / 3-4 / 4-5 / 6-7 at 1470 rpm | ring 7 orbit [µm] | bearing force"
      " ring 7 / carrier h / sun 1 [N] | static bearing force ring 7 [N] | run wall [s] |")
print("|---|---|---|---|---|---|")
sweeps, orbits = {}, {}
for label, single, sweep, wall, sweep_wall in results:
    kv = " / ".join(f"{value(single, f'kv_max_train_mesh{m}'):.3f}" for m in range(1, 5))
    static = {round(r["body"]): r["force"] for r in table(single, "lateral_train_bearing_forces")}
    bodies = {b: n for b, n in enumerate(single["text"]["bodies"].split(", "), 1)}
    ring = [b for b, n in bodies.items() if n.endswith(" 7")][0]
    print(f"| {label} | {kv} | {value(single, 'orbit_7'):.3f} | "
          f"{value(single, 'bearing_force_max_7'):.1f} / {carrier_force(single):.1f}"
          f" / {value(single, 'bearing_force_max_1'):.1f} | {static[ring]:.2e} | {wall:.1f} |")
    sweeps[label] = table(sweep, "lateral_train_speed_sweep")
    orbits[label] = [(r["7_x"], r["7_y"]) for r in table(single, "lateral_train_orbit")]
    s = sweeps[label]
    valid = [r for r in s if r["status"] == "valid"]
    top = max(valid, key=lambda r: max(r[f"kv_mesh{m}"] for m in range(1, 5))) if valid else None
    orbit_top = max(s, key=lambda r: r["orbit_7"])
    print(f"|   sweep | {len(valid)}/{len(s)} valid; largest K_v "
          + (f"{max(top[f'kv_mesh{m}'] for m in range(1, 5)):.3f} at {top['input_speed']:.0f} rpm"
             if top else "-")
          + f" | largest orbit {orbit_top['orbit_7']:.3f} at {orbit_top['input_speed']:.0f} rpm"
          f" | largest ring force {max(r['bearing_force_7'] for r in s):.1f} N | | "
          f"{sweep_wall:.1f} |")

with open(sweep_csv, "w", newline="") as f:
    columns = list(next(iter(sweeps.values()))[0].keys())
    w = csv.writer(f)
    w.writerow(["variant"] + columns)
    for label, rows in sweeps.items():
        for r in rows:
            w.writerow([label] + [r[c] for c in columns])
with open(orbit_csv, "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["variant", "x", "y"])
    for label, rows in orbits.items():
        for x, y in rows[::4]:
            w.writerow([label, f"{x:.5g}", f"{y:.5g}"])
plot(*read_back())
