#!/usr/bin/env python3
"""Design study, runnable today: the pinion shaft (bore) diameter that gives a target mesh stiffness.

In the FE scene the pinion sits on a rigid shaft through its bore (the torque acts there), so a
larger shaft leaves less elastic gear body under the teeth and stiffens the mesh. This finds, with
scipy.optimize.brentq on FE single-pair stiffness solves of `gearstiff.stiffness`, the bore at
which the single-pair mesh stiffness k'_j of the split-path pair (docs/references.md §1) reaches
a target — by default ISO 6336-1's c'·b for the same pair (from `gearstiff.gear_pair`), whose
blank assumption the FE model then matches — and draws k'_j(bore).

    PYTHONPATH=build/python /usr/bin/python3 examples/design_pinion_bore.py [PAIR.prm] [--target 330] [--chart bore.png]

PAIR.prm is your own pair (a .prm file as `gearstiff stiffness --print-parameters` writes it);
without it, the built-in split-path pair. Each evaluation's settings are appended to a copy of
it (the last `set` wins).

Each evaluation is one in-process FE contact solve (2D, Q2 elements by default; --coarse: Q1 on a
coarse mesh, for a quick look). Under `mpirun -np N` every rank runs the same script; only rank 0
prints and draws. (examples/optimise_tip_relief.py is a tip-relief study of the same kind.)
"""
import argparse
import os
import sys
import tempfile

import gearstiff
from scipy.optimize import brentq

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.ArgumentDefaultsHelpFormatter)
parser.add_argument("pair", nargs="?", default=None,
                    help="your pair's .prm file; None: the built-in split-path pair")
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

if arguments.pair and not (arguments.pair.endswith(".prm") and os.path.isfile(arguments.pair)):
    sys.exit(f"{arguments.pair}: give your pair as an existing .prm file")
PAIR_TEXT = open(arguments.pair).read() if arguments.pair else ""
CASE = f"pair of {os.path.basename(arguments.pair)}" if arguments.pair else "split-path pair"


def prm_text(settings, indent=""):
    """A settings dict as .prm subsections."""
    lines = []
    for name, value in settings.items():
        if isinstance(value, dict):
            lines += [f"{indent}subsection {name}", prm_text(value, indent + "  "), f"{indent}end"]
        else:
            text = str(value).lower() if isinstance(value, bool) else str(value)
            lines.append(f"{indent}set {name} = {text}")
    return "\n".join(lines)


def run(command, settings):
    """gearstiff.<command> on the pair file (settings appended) or the built-in pair."""
    if not arguments.pair:
        return command(settings)
    with tempfile.NamedTemporaryFile("w", suffix=".prm", delete=False) as f:
        f.write(PAIR_TEXT + "\n" + prm_text(settings) + "\n")
    try:
        return command(f.name)
    finally:
        os.unlink(f.name)


pair = run(gearstiff.gear_pair, {})
root_diameter = pair["values"]["pinion_root_diameter"]["value"]  # mm
module = float(pair["parameters"]["Gear pair"]["Pinion"]["module"])  # mm
evaluations = []  # (bore [mm], k'_j [N/µm])


def stiffness(bore):
    """Single-pair mesh stiffness k'_j [N/µm] with a pinion bore of `bore` mm."""
    params = {**base, "Gear pair": {"Pinion": {"bore diameter": bore}}}
    k = run(gearstiff.stiffness, params)["values"]["mesh_stiffness"]["value"]
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
        ax.set_title(f"{CASE}: pinion shaft diameter against mesh stiffness", fontsize=9)
        ax.legend()
        fig.tight_layout()
        fig.savefig(arguments.chart, dpi=120)
        print(f"chart: {arguments.chart}")
