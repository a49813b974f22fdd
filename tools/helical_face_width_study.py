#!/usr/bin/env python3
"""The face-width (overlap ratio ε_β) study of a helical pair (issue 46, docs/helical.md
"Face width and ε_β").

usage: helical_face_width_study.py path/to/gearstiff OUT_FOLDER [EPS_BETA ...]

One unmodified frictionless pair (CASE below) is swept over one transverse base pitch at face
widths b = ε_β·π·m_n / sin β for each requested ε_β (default STUDY), under the same load per
unit face width. Each sweep gives k(θ) and the loaded TE over the mesh cycle; the script writes
  OUT_FOLDER/face_width_study.csv      one row per width: ε_β, b, layers, k mean/min/max, the
                                       stiffness fluctuation (max − min)/mean, TE peak-to-peak,
                                       ISO 6336-1 c_γβ·b and the FE mean's difference from it
  OUT_FOLDER/face_width_curves.csv     k and TE at every position of every width
  OUT_FOLDER/face_width_study.md       the table as docs/helical.md shows it
  OUT_FOLDER/face_width_study.png      the chart: k(θ)/mean and TE(θ) over the cycle per width,
                                       and the fluctuation and TE peak-to-peak against ε_β
and prints the table. Why the trend: the total length of the contact lines, ε_α·b/cos β_b on
average, varies over the cycle by a part that vanishes when ε_β is an integer (each line that
leaves the zone of action at one end is replaced at the other), so k and TE fluctuate least at
ε_β = 1, 2 (ISO 6336-1 §9 uses the same argument for c_γβ; docs/references.md §18).
"""
import csv
import json
import math
import os
import re
import subprocess
import sys

from report_csv import column, value

# The small coarse pair of tests/helical (z 19/29, m_n 2 mm, x 0, the own_pair_coarse cell sizes
# scaled to m_n 2 mm, Q1, frictionless) at β ±20°, so that ε_β 2.2 needs b 40 mm rather than
# 53 mm at 15° (the layers follow ε_β, not b, so β does not change the cost).
NORMAL_MODULE = 2.  # mm
HELIX = 20.  # deg
CASE = ["--set", "Gear pair/Pinion/teeth=19", "--set", "Gear pair/Wheel/teeth=29",
        "--set", f"Gear pair/Pinion/module={NORMAL_MODULE}",
        "--set", f"Gear pair/Wheel/module={NORMAL_MODULE}",
        "--set", "Gear pair/Pinion/profile shift=0", "--set", "Gear pair/Wheel/profile shift=0",
        "--set", f"Gear pair/Pinion/helix angle={HELIX}",
        "--set", f"Gear pair/Wheel/helix angle={-HELIX}",
        "--set", "Stiffness/published reference=false",
        "--set", "Mesh/dimension=3", "--set", "Finite elements/Element degree=1",
        "--set", "Contact/Friction coefficient=0",
        "--set", "Mesh/contact size=0.15", "--set", "Mesh/fine radius=0.4",
        "--set", "Mesh/rim size=2.5"]
BODY_SIZE = 0.75  # mm, the own_pair_coarse body size scaled to m_n 2 mm
# The same load per unit face width at every width (the TE of a wider face under the same torque
# would fall by the width alone): 2.5 N·m/mm, the small pair's 20 N·m on 8 mm.
TORQUE_PER_WIDTH = 2.5  # N·m/mm
# Positions per transverse base pitch (the period of k for any ε_β). 6 put 2–3 samples in the
# single-contact zone ((2 − ε_α)·p_bt ≈ 0.45 p_bt at ε_β → 0) and resolve the fluctuation's
# first harmonic, which carries the trend; the sampled peak-to-peak is a lower bound of the
# curve's (the samples need not fall on the zone edges). Chosen for cost: the widest face runs
# 32 layers on this 2-core machine.
POSITIONS = 6
STUDY = [0.25, 0.5, 1.0, 1.5, 2.0, 2.2]


def face_width(eps_beta):
    """b = ε_β·π·m_n / sin β (ISO 21771), mm."""
    return eps_beta * math.pi * NORMAL_MODULE / math.sin(math.radians(HELIX))


def layers(eps_beta):
    """16 per unit ε_β, at least 5. The twist rule's 8 per unit (docs/helical.md "Layers") leave
    this small pair's contact lines a mortar gap beyond the 1 µm overlap tolerance (ε_β 0.5 with
    5 layers: −2.13 µm at position 2, refused naming Mesh/layers with 11); the gap falls as the
    layer height squared, so 16 per unit bring it near 0.8 µm. A sweep still refused is rerun
    with the count the refusal names (sweep() below)."""
    return max(5, math.ceil(16. * eps_beta - 1e-9))



def sweep(gearstiff, eps_beta, positions=POSITIONS, extra=()):
    """One width's sweep: its summary row and its per-position k and TE."""
    b = face_width(eps_beta)
    count = layers(eps_beta)
    # The teeth modelled are the command's `auto`: from ε_β ≈ 2 it models a fourth tooth on each
    # gear (the pairs ±2 touch near the face ends; docs/helical.md "Teeth modelled").
    body = BODY_SIZE  # mm; a wide face with its extra tooth may need coarser bodies, below
    while True:
        args = [gearstiff, "stiffness", "--json", "--quiet", "--set", "Stiffness/mode=sweep",
                "--set", f"Stiffness/sweep positions={positions}",
                "--set", f"Gear pair/Pinion/face width={b:.6f}",
                "--set", f"Gear pair/Wheel/face width={b:.6f}",
                "--set", f"Mesh/layers={count}",
                "--set", f"Mesh/body size={body:.4g}",
                "--set", f"Gear pair scene/pinion torque={TORQUE_PER_WIDTH * b:.6f}"]
        out = subprocess.run(args + CASE + list(extra), capture_output=True, text=True)
        needed = re.search(r"Mesh/layers: .*too few for the contact lines.*use at least (\d+) layers",
                           out.stderr)
        # The 3D work limit (the estimated memory of the solve, 16 GB, docs/limits.md; until
        # 2026-12-02 2e5 hexahedra): the layers stay (the contact lines need them), the bodies
        # away from the flanks coarsen by 15 % a step; the row states it.
        too_many_cells = re.search(r"the mesh would have about .* hexahedra, .*\(limit", out.stderr)
        if out.returncode != 2 or not (needed or too_many_cells):
            break
        if too_many_cells:
            body *= 1.15
        else:
            count = int(needed.group(1))
    if out.returncode != 0:
        sys.exit(f"helical_face_width_study: ε_β {eps_beta}: gearstiff exited {out.returncode}: "
                 f"{out.stderr.strip()[-1500:]}")
    report = json.loads(out.stdout)
    teeth = int(re.search(r"(\d+)/\d+ teeth modelled", report["text"]["model"]).group(1))
    k = column(report, "stiffness_sweep", "stiffness")
    te = column(report, "stiffness_sweep", "transmission_error")
    mean = value(report, "mean_stiffness")
    row = {"eps_beta": eps_beta, "face_width_mm": b, "layers": count, "teeth_modelled": teeth,
           "body_size_mm": body,
           "torque_Nm": TORQUE_PER_WIDTH * b, "positions": len(k),
           "k_mean": mean, "k_min": min(k), "k_max": max(k),
           "k_fluctuation_percent": (max(k) - min(k)) / mean * 100.,
           "te_mean_um": sum(te) / len(te), "te_peak_to_peak_um": max(te) - min(te),
           "iso_c_gamma_beta_b": value(report, "iso_mesh_stiffness_beta"),
           "mean_vs_iso_beta_percent": value(report, "mean_vs_iso_beta"),
           "sweep_wall_s": value(report, "sweep_wall_time")}
    return row, k, te


def write_outputs(folder, rows, curves):
    rows = sorted(rows, key=lambda r: r["eps_beta"])
    curves = dict(sorted(curves.items()))
    keys = list(rows[0].keys())
    with open(os.path.join(folder, "face_width_study.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(folder, "face_width_curves.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["eps_beta", "position", "stiffness_N_per_um", "transmission_error_um"])
        for eps_beta, (k, te) in curves.items():
            for i, (ki, ti) in enumerate(zip(k, te)):
                w.writerow([eps_beta, i + 1, f"{ki:.9g}", f"{ti:.9g}"])
    lines = ["| ε_β | b (mm) | layers | teeth | body (mm) | T1 (N·m) | k mean (N/µm) | k min–max (N/µm) | "
             "(max − min)/mean | TE p-p (µm) | TE mean (µm) | ISO c_γβ·b (N/µm) | "
             "FE mean − ISO | sweep (s) |",
             "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['eps_beta']:.2f} | {r['face_width_mm']:.2f} | {r['layers']} | "
                     f"{r['teeth_modelled']} | {r['body_size_mm']:.2f} | {r['torque_Nm']:.1f} | {r['k_mean']:.1f} | {r['k_min']:.1f}–{r['k_max']:.1f} "
                     f"| {r['k_fluctuation_percent']:.1f} % | {r['te_peak_to_peak_um']:.3f} | "
                     f"{r['te_mean_um']:.3f} | {r['iso_c_gamma_beta_b']:.1f} | "
                     f"{r['mean_vs_iso_beta_percent']:+.1f} % | {r['sweep_wall_s']:.0f} |")
    with open(os.path.join(folder, "face_width_study.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    plot(folder, rows, curves)


def plot(folder, rows, curves):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 3, figsize=(16, 4.8))
    for eps_beta, (k, te) in curves.items():
        mean = sum(k) / len(k)
        # Positions over one base pitch, closed periodically so that each curve shows a cycle.
        x = [i / len(k) for i in range(len(k) + 1)]
        axes[0].plot(x, [ki / mean for ki in k + k[:1]], marker="o", ms=3,
                     label=f"ε_β = {eps_beta:g}")
        te_mean = sum(te) / len(te)
        axes[1].plot(x, [t - te_mean for t in te + te[:1]], marker="o", ms=3,
                     label=f"ε_β = {eps_beta:g}")
    axes[0].set(xlabel="mesh position (transverse base pitches)", ylabel="k / mean k",
                title="k(θ) over a mesh cycle")
    axes[1].set(xlabel="mesh position (transverse base pitches)", ylabel="TE − mean TE (µm)",
                title="loaded TE over a mesh cycle (same load per mm)")
    eps = [r["eps_beta"] for r in rows]
    axes[2].plot(eps, [r["k_fluctuation_percent"] for r in rows], "o-",
                 label="stiffness fluctuation (max − min)/mean (%)")
    axes[2].plot(eps, [r["te_peak_to_peak_um"] * 100. for r in rows], "s-",
                 label="TE peak-to-peak (µm × 100)")
    for n in (1, 2):
        axes[2].axvline(n, color="grey", lw=0.8, ls=":")
    axes[2].set(xlabel="overlap ratio ε_β", ylim=(0, None),
                title="fluctuations against ε_β (integer ε_β: constant line length)")
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle(f"Helical pair z 19/29, m_n {NORMAL_MODULE:g} mm, β {HELIX:g}°, unmodified, "
                 f"frictionless, {TORQUE_PER_WIDTH:g} N·m per mm of face; Q1, {POSITIONS} "
                 "positions per base pitch, 16 layers per unit ε_β (at least 5)", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(folder, "face_width_study.png"), dpi=110)


def main():
    gearstiff, folder = os.path.realpath(sys.argv[1]), sys.argv[2]
    study = [float(a) for a in sys.argv[3:]] or STUDY
    os.makedirs(folder, exist_ok=True)
    rows, curves = [], {}
    for eps_beta in study:
        row, k, te = sweep(gearstiff, eps_beta)
        print(f"ε_β {eps_beta:g}: b {row['face_width_mm']:.2f} mm, {row['layers']} layers, "
              f"k {row['k_mean']:.2f} N/µm ± {row['k_fluctuation_percent']:.2f} %, "
              f"TE p-p {row['te_peak_to_peak_um']:.4f} µm, {row['sweep_wall_s']:.1f} s", flush=True)
        rows.append(row)
        curves[eps_beta] = (k, te)
        write_outputs(folder, rows, curves)
    return 0


if __name__ == "__main__":
    sys.exit(main())
