#!/usr/bin/env python3
"""Design study: the tip relief that minimises the transmission error's peak-to-peak at a design torque.

Tip relief C_a (the same linear relief on pinion and wheel tips) shortens the load's entry and exit
of a tooth pair: too little and the pair takes its load abruptly, too much and the single-pair zone
carries alone for longer — the peak-to-peak transmission error (TE) has a minimum between, at a
relief that depends on the torque. This finds it with scipy.optimize.minimize_scalar (bounded) on
FE k(θ) sweeps of `gearstiff.stiffness`, and draws TE peak-to-peak against C_a.

    PYTHONPATH=build/python /usr/bin/python3 examples/optimise_tip_relief.py [PAIR.prm] [--torque 400] [--chart te.png]

PAIR.prm is your own pair (a .prm as `gearstiff stiffness --print-parameters` writes it, or the
pair file every command reads); without it, the built-in split-path pair. The relief and the
sweep settings are appended to a copy of it for each evaluation (the last `set` wins).

It uses `Gear pair/Pinion|Wheel/tip relief` [µm], `Stiffness/torques` and the sweep's table
`te_map` (column `te_peak_to_peak`). The TE peak-to-peak is taken from `--positions` samples of
the mesh cycle, so near the optimum it scatters by a few hundredths of a µm between neighbouring
reliefs (an own pair z 23/57, m 3 mm, 300 N·m, 8 positions: C_a 18.2 µm, 1.02 µm against 8.66 µm
unrelieved, 10 sweeps in 87 s; 2026-12-07): more positions sharpen it.
examples/design_pinion_bore.py is a design study of the same kind (the pinion bore that keeps a
target single-pair stiffness).

Every evaluation is one in-process sweep (positions over a base pitch); under `mpirun -np N` every
rank runs the script and each sweep's positions are shared by the ranks (only rank 0 prints).
"""
import argparse
import os
import sys
import tempfile

import gearstiff
from scipy.optimize import minimize_scalar

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.ArgumentDefaultsHelpFormatter)
parser.add_argument("pair", nargs="?", default=None,
                    help="your pair's .prm file; None: the built-in split-path pair")
parser.add_argument("--torque", type=float, default=400.0, help="design pinion torque [N·m]")
parser.add_argument("--max-relief", type=float, default=40.0, help="upper bound of C_a [µm]")
parser.add_argument("--positions", type=int, default=8, help="sweep positions per evaluation")
parser.add_argument("--chart", default="tip_relief.png", help="PNG of TE peak-to-peak against C_a")
arguments = parser.parse_args()
root = gearstiff.mpi_rank() == 0

declared = gearstiff.print_parameters("stiffness")
if "tip relief" not in declared["Gear pair"]["Pinion"] or "torques" not in declared["Stiffness"]:
    sys.exit("this build has no 'Gear pair/Pinion/tip relief' or 'Stiffness/torques' (issue 27); "
             "see examples/design_pinion_bore.py for a study that runs today")

evaluations = []  # (C_a [µm], TE peak-to-peak [µm])


if arguments.pair and not arguments.pair.endswith(".prm"):
    sys.exit(f"{arguments.pair}: give the pair as a .prm file (the settings are appended to it)")
if arguments.pair and not os.path.isfile(arguments.pair):
    sys.exit(f"{arguments.pair}: no such file")
PAIR_TEXT = open(arguments.pair).read() if arguments.pair else ""
CASE = (f"pair of {os.path.basename(arguments.pair)}" if arguments.pair
        else "built-in split-path pair")


def te_peak_to_peak(relief):
    settings = {
        "Gear pair": {"Pinion": {"tip relief": relief}, "Wheel": {"tip relief": relief}},
        "Stiffness": {"mode": "sweep", "sweep positions": arguments.positions,
                      "torques": [arguments.torque], "published reference": False},
    }
    if arguments.pair:
        # The user's pair with this evaluation's settings appended: deal.II keeps the last set.
        text = PAIR_TEXT + (
            f"\nsubsection Gear pair\n  subsection Pinion\n    set tip relief = {relief}\n  end\n"
            f"  subsection Wheel\n    set tip relief = {relief}\n  end\nend\n"
            f"subsection Stiffness\n  set mode = sweep\n"
            f"  set sweep positions = {arguments.positions}\n"
            f"  set torques = {arguments.torque}\n  set published reference = false\nend\n")
        with tempfile.NamedTemporaryFile("w", suffix=".prm", delete=False) as f:
            f.write(text)
        try:
            result = gearstiff.stiffness(f.name)
        finally:
            os.unlink(f.name)
    else:
        result = gearstiff.stiffness(settings)
    te = result["tables"]["te_map"]
    value = float(te["data"]["te_peak_to_peak"][0])
    evaluations.append((relief, value))
    if root:
        print(f"  C_a = {relief:6.2f} µm: TE peak-to-peak {value:.4f} {te['units']['te_peak_to_peak']}",
              flush=True)
    return value


try:
    best = minimize_scalar(te_peak_to_peak, bounds=(0.0, arguments.max_relief), method="bounded",
                           options={"xatol": 0.5})
except gearstiff.SolverFailure as failure:
    # No number from a failed FE solve: the search stops and says where, as the command line
    # does (exit 3).
    if root:
        print(f"{CASE}: the search stopped: {failure}", file=sys.stderr)
    sys.exit(3)
if root:
    print(f"{CASE}: tip relief minimising TE peak-to-peak at {arguments.torque:g} N·m: "
          f"C_a = {best.x:.1f} µm "
          f"(TE p-p {best.fun:.4f} µm; without relief {te_peak_to_peak(0.0):.4f} µm), "
          f"{len(evaluations)} FE sweeps")

if root and arguments.chart:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("matplotlib missing: no chart")
    points = sorted(evaluations)
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot([p[0] for p in points], [p[1] for p in points], "o-")
    ax.axvline(best.x, color="C3", ls=":", label=f"optimum C_a = {best.x:.1f} µm")
    ax.set_xlabel("tip relief C_a [µm]")
    ax.set_ylabel("TE peak-to-peak [µm]")
    ax.set_title(f"Tip relief against TE: {CASE} at {arguments.torque:g} N·m", fontsize=9)
    ax.legend()
    fig.tight_layout()
    fig.savefig(arguments.chart, dpi=120)
    print(f"chart: {arguments.chart}")
