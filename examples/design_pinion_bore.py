#!/usr/bin/env python3
"""Design study, runnable today: the largest pinion bore that keeps a target single-pair stiffness.

A lighter pinion (a larger bore, a thinner rim under the teeth) is softer; how much softer only
an FE model says (ISO 6336-1's C_R covers webbed blanks, not a plain bore). This finds, with
scipy.optimize.brentq on FE single-pair stiffness solves of `gearstiff.stiffness`, the bore
diameter at which the single-pair mesh stiffness k'_j of the split-path pair (docs/references.md
§1) has dropped by a chosen fraction from its value with a small bore, and draws k'_j(bore).

    PYTHONPATH=build/python /usr/bin/python3 examples/design_pinion_bore.py [--drop 0.03] [--chart bore.png]

Each evaluation is one in-process FE contact solve (2D, Q2 elements by default; --coarse: Q1 on a
coarse mesh, for a quick look). Under `mpirun -np N` every rank runs the same script; only rank 0
prints and draws.
"""
import argparse

import gearstiff
from scipy.optimize import brentq

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("--drop", type=float, default=0.03,
                    help="allowed relative drop of k'_j from the small-bore value (default 0.03)")
parser.add_argument("--chart", default="pinion_bore.png", help="PNG of k'_j(bore)")
parser.add_argument("--coarse", action="store_true", help="Q1 elements on a coarse mesh")
arguments = parser.parse_args()
root = gearstiff.mpi_rank() == 0

base = {"Stiffness": {"mode": "single", "published reference": False}}
if arguments.coarse:
    base["Mesh"] = {"contact size": 0.2, "fine radius": 0.5, "body size": 1, "rim size": 3}
    base["Finite elements"] = {"Element degree": 1}

pair = gearstiff.gear_pair()
root_diameter = pair["values"]["pinion_root_diameter"]["value"]  # mm
module = float(pair["parameters"]["Gear pair"]["Pinion"]["module"])  # mm
evaluations = []  # (bore [mm], k'_j [N/µm])


def stiffness(bore):
    """Single-pair mesh stiffness k'_j [N/µm] with a pinion bore of `bore` mm."""
    params = {**base, "Gear pair": {"Pinion": {"bore diameter": bore}}}
    k = gearstiff.stiffness(params)["values"]["mesh_stiffness"]["value"]
    evaluations.append((bore, k))
    if root:
        print(f"  bore {bore:7.3f} mm: k'_j = {k:.4f} N/µm", flush=True)
    return k


# The bore may grow until about one module of rim remains under the root circle.
small = 0.3 * root_diameter
large = root_diameter - 2 * module
k_small = stiffness(small)
target = (1 - arguments.drop) * k_small
if root:
    print(f"target k'_j = {target:.4f} N/µm ({100 * arguments.drop:g} % below the {small:.1f} mm bore)")
if stiffness(large) > target:
    bore = large
    if root:
        print(f"even the largest bore ({large:.2f} mm, one module of rim) keeps k'_j above target")
else:
    bore = brentq(lambda d: stiffness(d) - target, small, large, xtol=0.05)
    if root:
        print(f"largest bore for the target: {bore:.2f} mm (rim under the root: "
              f"{(root_diameter - bore) / 2:.2f} mm), {len(evaluations)} FE solves")

if root and arguments.chart:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib missing: no chart")
    else:
        points = sorted(evaluations)
        fig, ax = plt.subplots(figsize=(6, 4))
        ax.plot([p[0] for p in points], [p[1] for p in points], "o-", label="FE k'_j (gearstiff)")
        ax.axhline(target, color="grey", ls="--", label=f"target ({100 * arguments.drop:g} % drop)")
        ax.axvline(bore, color="C3", ls=":", label=f"bore {bore:.2f} mm")
        ax.set_xlabel("pinion bore diameter [mm]")
        ax.set_ylabel("single-pair mesh stiffness k'_j [N/µm]")
        ax.set_title("Split-path pair: pinion bore against mesh stiffness")
        ax.legend()
        fig.tight_layout()
        fig.savefig(arguments.chart, dpi=120)
        print(f"chart: {arguments.chart}")
