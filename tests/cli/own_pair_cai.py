#!/usr/bin/env python3
"""An own pair's Cai calibration drives its own train, as its stiffness table does (issue 41).

usage: own_pair_cai.py path/to/gearstiff WORK_FOLDER

Found by running `gearstiff cai` on an own pair (session 49): its cai_calibrated.prm put the
fitted curve on Mesh 1 and Mesh 2 of the built-in split-path gearbox, so `gearstiff dynamics
cai_calibrated.prm` ran the published gearbox (its base radii, ε_α, inertias and torque) with
the own pair's curve — `gearstiff stiffness` had written an own pair's train since issue 41, the
Cai path had not. And a helical pair ran its 3D sweep before anything said that the curve (one
spur pair's stiffness over ε_α) does not describe it.

Asserts, on the own pair z 23/57, m 3 mm, x 0.2 (coarse 2D Q1, 8 positions, ~3 s):
- cai_calibrated.prm is a two-gear train of this pair: no Mesh 2, Mesh 1 with `stiffness source =
  cai`, the pair's r_b1 = z1·m·cos α/2 (1e-9), its ε_α (cai's summary, 1e-9) and the typed torque;
- `gearstiff dynamics` on it reports the mean mesh stiffness the cai command reports for its
  curve, cai_mean_mesh_stiffness (1e-6: both are the curve's mean over this ε_α, the scale carried
  with 10 digits), and the nominal mesh force T1/r_b1 (1e-9);
- a helical pair is refused before any work: exit 2, one line naming Gear pair/Pinion/helix
  angle, nothing written.
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys

PAIR = ["--set", "Gear pair/Pinion/teeth=23", "--set", "Gear pair/Wheel/teeth=57",
        "--set", "Gear pair/Pinion/module=3", "--set", "Gear pair/Wheel/module=3",
        "--set", "Gear pair/Pinion/profile shift=0.2",
        "--set", "Gear pair scene/pinion torque=80",
        "--set", "Mesh/contact size=0.3", "--set", "Mesh/fine radius=0.8",
        "--set", "Mesh/body size=1.5", "--set", "Mesh/rim size=5",
        "--set", "Finite elements/Element degree=1",
        "--set", "Stiffness/sweep positions=8"]


def run(args, expect=0):
    process = subprocess.run(args, capture_output=True, text=True)
    if process.returncode != expect:
        sys.exit(f"own_pair_cai: {' '.join(args[:2])} exited {process.returncode} (expected "
                 f"{expect}): {process.stderr.strip()[-600:]}")
    return process


def number(report, key):
    entry = report["values"][key]
    return entry["value"] if isinstance(entry, dict) else entry


def main():
    gearstiff, work = sys.argv[1:3]
    shutil.rmtree(work, ignore_errors=True)
    out = os.path.join(work, "cai")
    run([gearstiff, "cai", "--quiet", "-o", out] + PAIR)
    with open(os.path.join(out, "summary.json")) as f:
        cai = json.load(f)
    with open(os.path.join(out, "cai_calibrated.prm")) as f:
        text = f.read()
    if "subsection Mesh 2" in text or "set stiffness source = cai" not in text:
        sys.exit("own_pair_cai: cai_calibrated.prm is not this pair's one-mesh train:\n" + text)
    # Spur: r_b1 = z1·m·cos α / 2 (α 20°, the default rack).
    radius = 23 * 3. * math.cos(math.radians(20.)) / 2.
    written = re.search(r"set driver base radius = ([-+0-9.eE]+)", text)
    if written is None or not abs(float(written.group(1)) / radius - 1.) <= 1e-9:
        sys.exit(f"own_pair_cai: Mesh 1's driver base radius "
                 f"{written.group(1) if written else 'missing'} mm, the pair's is {radius} mm")
    ratio = re.search(r"set contact ratio = ([-+0-9.eE]+)", text)
    if ratio is None or not abs(float(ratio.group(1)) / number(cai, "contact_ratio") - 1.) <= 1e-9:
        sys.exit(f"own_pair_cai: Mesh 1's contact ratio {ratio.group(1) if ratio else 'missing'}, "
                 f"the pair's {number(cai, 'contact_ratio')}")
    torque = re.search(r"subsection Gear 1\n(?:.*\n)*?\s*set torque = ([-+0-9.eE]+)", text)
    if torque is None or float(torque.group(1)) != 80.:
        sys.exit(f"own_pair_cai: Gear 1's torque {torque.group(1) if torque else 'missing'}, "
                 f"typed 80 N·m")
    dynamics = json.loads(run([gearstiff, "dynamics", os.path.join(out, "cai_calibrated.prm"),
                               "--json", "--quiet", "--set", "Speed sweep/points=0"]).stdout)
    mean, expected = (number(dynamics, "mesh1_mean_stiffness"),
                      number(cai, "cai_mean_mesh_stiffness"))
    if not abs(mean / expected - 1.) <= 1e-6:
        sys.exit(f"own_pair_cai: dynamics' mean k {mean:.10g} N/µm, the curve's "
                 f"{expected:.10g} (cai_mean_mesh_stiffness)")
    force = number(dynamics, "mesh1_nominal_force")
    if not abs(force / (80. / (radius * 1e-3)) - 1.) <= 1e-9:
        sys.exit(f"own_pair_cai: nominal force {force:.10g} N, T1/r_b1 = "
                 f"{80. / (radius * 1e-3):.10g} N")
    helical = os.path.join(work, "helical")
    process = run([gearstiff, "cai", "-o", helical] + PAIR +
                  ["--set", "Gear pair/Pinion/helix angle=12",
                   "--set", "Gear pair/Wheel/helix angle=-12", "--set", "Mesh/dimension=3"],
                  expect=2)
    lines = process.stderr.strip().splitlines()
    if len(lines) != 1 or "Gear pair/Pinion/helix angle" not in lines[0] or os.path.exists(helical):
        sys.exit(f"own_pair_cai: the helical pair's refusal: {process.stderr.strip()!r}, "
                 f"folder written: {os.path.exists(helical)}")
    print(f"own_pair_cai: the train's mean k {mean:.8g} N/µm = the curve's {expected:.8g}; "
          f"nominal force {force:.8g} N = T1/r_b1; helical refused: {lines[0]}")


if __name__ == "__main__":
    main()
