#!/usr/bin/env python3
"""A helical pair's k(θ) sweep over a mesh cycle drives `gearstiff dynamics` (issue 46,
docs/helical.md "Sweeps and the dynamics", dynamics/README.md "Helical meshes").

usage: sweep_dynamics.py path/to/gearstiff WORK_FOLDER

A small coarse helical pair (CASE below: 3D Q1, per-position sweep of POSITIONS positions over
one transverse base pitch, frictionless) is swept with -o; its stiffness_table.prm (the pair
alone with its FE k(x) table) is then run by `gearstiff dynamics`. Checked:
  - the sweep: the torques balance at every position, |T_wheel/T1| = r_b2/r_b1 (6.3e-4, the
    faceted helicoid's bound of tests/invariants/invariants.py, docs/helical.md "Results"), and
    its k values (regression);
  - the table: the dynamics' mean mesh stiffness is the sweep's mean (the periodic linear
    interpolation of equally spaced samples has their mean: 1e-6, the file's 10 digits), its
    mesh frequency z1·n1/60 (exact), K_v at the file's own speed (regression), and K_v = 1 at a
    quasi-static speed (0.5 % of the resonance speed, no tooth friction: the static mesh force,
    within 0.5 % as tests/invariants/invariants.py's own-train identity).
"""
import json
import os
import shutil
import subprocess
import sys

# tools/report_csv.py: value() and column() of a JSON report, as the tools read them.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from report_csv import column, value  # noqa: E402

# z 19/29, m_n 2 mm, β 10° (ε_β = b·sin β/(π·m_n) = 0.221, so 2 layers by the twist rule; 5
# layers so that the contact lines do not refuse them, docs/helical.md "Layers and the contact
# lines"), b 8 mm, cell sizes coarse (the own_pair_coarse set of tests/cli scaled to m_n 2 mm).
CASE = ["--set", "Gear pair/Pinion/teeth=19", "--set", "Gear pair/Wheel/teeth=29",
        "--set", "Gear pair/Pinion/module=2", "--set", "Gear pair/Wheel/module=2",
        "--set", "Gear pair/Pinion/profile shift=0", "--set", "Gear pair/Wheel/profile shift=0",
        "--set", "Gear pair/Pinion/face width=8", "--set", "Gear pair/Wheel/face width=8",
        "--set", "Gear pair/Pinion/helix angle=10", "--set", "Gear pair/Wheel/helix angle=-10",
        "--set", "Gear pair scene/pinion torque=20", "--set", "Stiffness/published reference=false",
        "--set", "Mesh/dimension=3", "--set", "Mesh/layers=5",
        "--set", "Finite elements/Element degree=1", "--set", "Contact/Friction coefficient=0",
        "--set", "Mesh/contact size=0.15", "--set", "Mesh/fine radius=0.4",
        "--set", "Mesh/body size=0.75", "--set", "Mesh/rim size=2.5"]
POSITIONS = 4

# Regression: measured 2026-12-02 (k in N/µm per position, K_v at the file's speed, 0.3 of the
# resonance speed); re-measured the same day when a helical scene's negative mortar gap stopped
# being taken out as a turn (stiffness/mesh_stiffness.cc, docs/helical.md "CalculiX"). Held to 1e-6 relative, the whole-output regression cases' own tolerance
# (tests/regression/compare.py): the mesh, the direct solver and the integrator are
# deterministic, so any change beyond round-off is a change of the method.
EXPECTED_K = [144.1176849, 144.8440239, 122.9585631, 100.8041498]
EXPECTED_KV = 1.126422032
K_TOLERANCE = 1e-6
KV_TOLERANCE = 1e-6


def run(args, cwd):
    out = subprocess.run(args, cwd=cwd, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"sweep_dynamics: {' '.join(args[1:3])} exited {out.returncode}: "
                 f"{out.stderr.strip()[-1500:]}")
    return json.loads(out.stdout)



class Checks:
    def __init__(self):
        self.failed = 0

    def near(self, label, measured, reference, tolerance, relative=True):
        deviation = measured / reference - 1. if relative else measured - reference
        ok = abs(deviation) <= tolerance
        self.failed += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {label}: {measured:.10g} against {reference:.10g}: "
              f"{deviation:+.3g}{' relative' if relative else ''} (tolerance {tolerance:.3g})")


def main():
    gearstiff, work = os.path.realpath(sys.argv[1]), sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    out = os.path.join(work, "sweep")
    sweep = run([gearstiff, "stiffness", "--json", "--quiet", "--set", "Stiffness/mode=sweep",
                 "--set", f"Stiffness/sweep positions={POSITIONS}", "-o", out] + CASE, work)
    checks = Checks()
    k = column(sweep, "stiffness_sweep", "stiffness")
    print(f"sweep: {len(k)} positions, k = {', '.join(f'{x:.9g}' for x in k)} N/um, "
          f"{value(sweep, 'sweep_wall_time'):.1f} s")
    if len(k) != POSITIONS:
        sys.exit(f"sweep_dynamics: {len(k)} positions, expected {POSITIONS}")
    checks.near("largest torque-balance deviation of the positions",
                value(sweep, "torque_ratio_deviation"), 0., 6.3e-4, relative=False)
    if EXPECTED_K is not None:
        for i, (measured, expected) in enumerate(zip(k, EXPECTED_K)):
            checks.near(f"k at position {i} [N/um] (regression)", measured, expected, K_TOLERANCE)
    table_file = os.path.join(out, "stiffness_table.prm")
    with open(table_file) as f:
        text = f.read()
    resonance = float(text.split("resonance speed n_E1 = ")[1].split()[0])
    # The header says what the table's k is for a helical mesh (dynamics/README.md "Helical
    # meshes"): beta_b of the small pair, tan(beta_b) = tan(beta)*cos(alpha_t).
    header = [line for line in text.splitlines() if line.startswith("# Helical, beta ")]
    checks.near("the table's header names the transverse line of action", len(header), 1, 0.,
                relative=False)
    if header:
        print(header[0])
    dynamics = run([gearstiff, "dynamics", table_file, "--json", "--quiet"], work)
    speed = float(text.split("set input speed = ")[1].split()[0])
    checks.near("mesh frequency [Hz] = z1 n1 / 60", value(dynamics, "mesh_frequency"),
                19 * speed / 60., 1e-9)
    checks.near("dynamics mean k = sweep mean [N/um]", value(dynamics, "mesh1_mean_stiffness"),
                sum(k) / len(k), 1e-6)
    kv = value(dynamics, "mesh1_kv_max")
    print(f"dynamics at {speed:.6g} rpm (0.3 of n_E1 = {resonance:.6g} rpm): K_v max {kv:.9g}")
    if EXPECTED_KV is not None:
        checks.near("K_v max at the file's speed (regression)", kv, EXPECTED_KV, KV_TOLERANCE)
    slow = run([gearstiff, "dynamics", table_file, "--json", "--quiet",
                "--set", f"Train/input speed={0.005 * resonance:.8g}"], work)
    checks.near("K_v max at 0.5 % of n_E1 (quasi-static: 1)", value(slow, "mesh1_kv_max"), 1.,
                5e-3, relative=False)
    return 1 if checks.failed else 0


if __name__ == "__main__":
    sys.exit(main())
