#!/usr/bin/env python3
"""Design study, runnable today: the pinion shaft (bore) diameter that gives a target mesh stiffness.

In the FE scene the pinion sits on a rigid shaft through its bore (the torque acts there), so a
larger shaft leaves less elastic gear body under the teeth and stiffens the mesh. This finds, with
scipy.optimize.brentq on FE single-pair stiffness solves of `gearstiff.stiffness`, the bore at
which the single-pair mesh stiffness k'_j of the split-path pair (docs/references.md §1) reaches
a target — by default ISO 6336-1's c'·b for the same pair (from `gearstiff.gear_pair`), whose
blank assumption the FE model then matches — and draws k'_j(bore).

    PYTHONPATH=build/python /usr/bin/python3 examples/design_pinion_bore.py [--target 330] [--chart bore.png]

Each evaluation is one in-process FE contact solve (2D, Q2 elements by default; --coarse: Q1 on a
coarse mesh, for a quick look). Under `mpirun -np N` every rank runs the same script; only rank 0
prints and draws. (examples/optimise_tip_relief.py is the tip-relief study that needs issue 27.)
"""
import argparse

import gearstiff
from scipy.optimize import brentq

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("--target", type=float, default=None,
                    help="target k'_j [N/µm] (default: ISO 6336-1 c'·b of the pair)")
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


# From a thin shaft to a rim of 1.1 modules under the root circle (the scene needs one at least).
small = 0.3 * root_diameter
large = root_diameter - 2.2 * module
target = arguments.target or pair["values"]["iso_single_stiffness_times_width"]["value"]
if root:
    print(f"target k'_j = {target:.2f} N/µm")
k_small, k_large = stiffness(small), stiffness(large)
if not min(k_small, k_large) <= target <= max(k_small, k_large):
    bore = small if abs(k_small - target) < abs(k_large - target) else large
    if root:
        print(f"the target is outside k'_j({small:.1f} mm) .. k'_j({large:.1f} mm); nearest: {bore:.2f} mm")
else:
    bore = brentq(lambda d: stiffness(d) - target, small, large, xtol=0.05)
    if root:
        print(f"pinion bore for k'_j = {target:.2f} N/µm: {bore:.2f} mm (rim under the root: "
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
        ax.axhline(target, color="grey", ls="--", label=f"target {target:.1f} N/µm")
        ax.axvline(bore, color="C3", ls=":", label=f"bore {bore:.2f} mm")
        ax.set_xlabel("pinion bore diameter [mm]")
        ax.set_ylabel("single-pair mesh stiffness k'_j [N/µm]")
        ax.set_title("Split-path pair: pinion shaft diameter against mesh stiffness")
        ax.legend()
        fig.tight_layout()
        fig.savefig(arguments.chart, dpi=120)
        print(f"chart: {arguments.chart}")
