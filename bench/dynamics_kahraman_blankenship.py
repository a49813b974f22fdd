#!/usr/bin/env python3
"""Kahraman & Blankenship (1997)-style study (issue 29, dynamics/README.md "Nonlinear mesh"):
DF against speed through the main resonance of a unity-ratio spur pair, up and down sweeps
with continuation, contact ratio 1.5 and 2.0: the Cai curve (bench/dynamics_kahraman_blankenship.prm)
or, with --fe, the FE k(θ) and loaded TE tables of `gearstiff stiffness`
(bench/kahraman_blankenship_fe/: the same pair as a Train, tips set for each contact ratio).

    python3 bench/dynamics_kahraman_blankenship.py [path/to/gearstiff] [--fe] [-o DIR]

Prints, per contact ratio, the natural frequency, where each sweep jumps (the largest DF rise
of the up sweep, the largest drop of the down sweep, between neighbouring speeds), the DF and separation fraction on both sides, and the
speed range where the two sweeps differ (|ΔDF| > 0.05). With -o DIR the command's charts and
CSV of each case go to DIR/eps1.5 and DIR/eps2.0.
"""
import json
import os
import subprocess
import sys

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
fe = "--fe" in sys.argv
args = [a for a in sys.argv[1:] if a not in ("-o", "--fe")]
out_dir = sys.argv[sys.argv.index("-o") + 1] if "-o" in sys.argv else None
if out_dir:
    args.remove(out_dir)
binary = os.path.abspath(args[0]) if args else os.path.join(root, "build", "app", "gearstiff")
prm = os.path.join(root, "bench", "dynamics_kahraman_blankenship.prm")
fe_folder = os.path.join(root, "bench", "kahraman_blankenship_fe")

for contact_ratio, approach in ((1.5, 0.75), (2.0, 1.0)):
    if fe:
        table = f"stiffness_eps{contact_ratio}.json"
        command = [binary, "dynamics", "dynamics_fe.prm", "--json",
                   "--set", f"Train mesh 1/stiffness file={table}",
                   "--set", f"Train mesh 1/transmission error file={table}"]
    else:
        command = [binary, "dynamics", prm, "--json",
                   "--set", f"Mesh 1/contact ratio={contact_ratio}",
                   "--set", f"Mesh 1/approach ratio={approach}"]
    if out_dir:
        command += ["-o", os.path.abspath(os.path.join(out_dir, f"eps{contact_ratio}"))]
    result = json.loads(subprocess.run(command, check=True, capture_output=True, text=True,
                                       cwd=fe_folder if fe else None).stdout)
    natural = result["tables"]["dynamics_modes"]["rows"][0][1]
    rows = result["tables"]["dynamics_nonlinear_sweep"]["rows"]
    up = [r for r in rows if r[2] == 0]
    down = [r for r in rows if r[2] == 1]

    def jump(sweep):
        # up: the largest rise of DF; down (speeds falling): the largest drop
        pairs = list(zip(sweep, sweep[1:]))
        a, b = max(pairs, key=lambda p: p[1][3] - p[0][3] if p[1][0] > p[0][0] else
                   p[0][3] - p[1][3])
        return (f"{a[0]:.0f} -> {b[0]:.0f} rpm (f_mesh/f_n {a[1] / natural:.3f} -> "
                f"{b[1] / natural:.3f}): DF {a[3]:.2f} -> {b[3]:.2f}, separation fraction "
                f"{a[5]:.2f} -> {b[5]:.2f}")

    by_speed = {r[0]: r for r in down}
    differ = [r[0] for r in up if abs(r[3] - by_speed[r[0]][3]) > 0.05]
    print(f"eps_alpha {contact_ratio}: f_n {natural:.0f} Hz (resonance at "
          f"{natural * 60 / 50:.0f} rpm); sweep {result['values']['sweep_time']['value']:.2f} s")
    print(f"  up sweep jump:   {jump(up)}")
    print(f"  down sweep jump: {jump(down)}")
    print(f"  largest DF up {max(r[3] for r in up):.2f}, down {max(r[3] for r in down):.2f}; "
          f"sweeps differ (|dDF| > 0.05) from {min(differ, default=float('nan')):.0f} to "
          f"{max(differ, default=float('nan')):.0f} rpm")
