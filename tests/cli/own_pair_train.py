#!/usr/bin/env python3
"""An own modified pair's Harris-map sweep drives its own train: at the torque its k(x) was solved
at, and with its micro-geometry's TE in the nonlinear model.

usage: own_pair_train.py path/to/gearstiff WORK_FOLDER

Two defects found by running the features together on an own pair (session 19):
1. `Stiffness/torques = 100, 300` with tip relief on both gears wrote a stiffness_table.prm whose
   k(x) was the first torque's (100 N·m: the sweep's positions are the first torque's) but whose
   train ran at `Gear pair scene/pinion torque` (300 N·m), so `gearstiff dynamics` applied
   300 N·m to the stiffness of 100 N·m — 12 % softer than the FE's at 300 N·m on the pair below.
   Tip relief makes k depend on the load (the relieved pair carries more of it as the load
   grows), which is why the torque and its k must travel together.
2. The nonlinear model refused the same sweep's summary.json as `transmission error file` ("k·s
   differs between rows: the table is not one load case"): it split the loaded TE s assuming
   k = W/s, which holds for unmodified teeth only; `gearstiff stiffness` writes k = W/(s − e)
   with the modifications' unloaded TE e beside it. The split now takes e from the table, so a
   relief's TE excites the train.
3. (session 20) Nothing warned when a file's k(x) was solved at another load than the train's:
   the sweep's summary.json now states `pinion_torque` (the torque of k(x)), and `gearstiff
   dynamics` reports the file's tooth force beside the mesh's nominal force, with a warning
   when they differ by more than 10 %.

Asserts, on the own pair z 23/61, m_n 4 mm with 12 µm tip relief on both gears (coarse 2D Q1,
16 positions, 2 torques, ~8 s):
- the table's T1 is the first torque's (exact: the number typed), and the table says so;
- `gearstiff dynamics` on it reports as mean mesh stiffness the first torque's FE mean of te_map
  (1e-6 relative: the mean of a periodic linear interpolation of uniform samples is their mean,
  and the table carries 10 digits); the two torques' means differ by more than 5 % (they do by
  14 %), so that the check tells the torques apart;
- the nonlinear model with the sweep's summary.json as TE file, μ = 0, at a quasi-static 50 rpm
  (0.5 % of n_E1: K_v − 1 ≈ 2e-4): its mean dynamic TE equals the FE's mean loaded TE at
  100 N·m within 0.3 % (measured −0.085 % here, −0.42 % with 8 positions, −0.041 % on the
  default mesh of the same pair at 16 positions: the dynamics interpolates k(x) linearly, and
  W/k of the interpolated k lies below the interpolated W/k, 1/k being convex; 0.3 % is about
  3× the measured);
- the summary's pinion_torque is 100 (the number typed); the summary as `Train mesh 1/stiffness
  file` of the pair as a two-gear Train reports mesh1_table_force = 100 N·m / r_b1 (1e-9: the
  value and r_b1 travel with 10+ digits), no load warning at 100 N·m and "1-2 load warning" at
  Train/input torque = 300.
"""
import csv
import json
import os
import re
import shutil
import subprocess
import sys

PAIR = ["--set", "Gear pair/Pinion/teeth=23", "--set", "Gear pair/Wheel/teeth=61",
        "--set", "Gear pair/Pinion/module=4", "--set", "Gear pair/Wheel/module=4",
        "--set", "Gear pair/Pinion/tip relief=12", "--set", "Gear pair/Wheel/tip relief=12",
        "--set", "Gear pair scene/pinion torque=300",
        "--set", "Mesh/contact size=0.3", "--set", "Mesh/fine radius=0.8",
        "--set", "Mesh/body size=1.5", "--set", "Mesh/rim size=5",
        "--set", "Finite elements/Element degree=1",
        "--set", "Stiffness/mode=sweep", "--set", "Stiffness/sweep positions=16",
        "--set", "Stiffness/torques=100, 300"]


def run(args):
    process = subprocess.run(args, capture_output=True, text=True)
    if process.returncode != 0:
        sys.exit(f"own_pair_train: {' '.join(args[:2])} exited {process.returncode}: "
                 f"{process.stderr.strip()[-600:]}")
    return process.stdout


def number(report, key):
    entry = report["values"][key]
    return entry["value"] if isinstance(entry, dict) else entry


def check_load_warning(gearstiff, table, out):
    """The file's load beside the train's: silent at the file's torque, a warning at 3x."""
    summary_path = os.path.join(out, "summary.json")
    with open(summary_path) as f:
        summary = json.load(f)
    torque, radius = number(summary, "pinion_torque"), number(summary, "pinion_base_radius")
    if torque != 100.:
        sys.exit(f"own_pair_train: summary pinion_torque {torque}, expected 100 (the first "
                 f"torque, whose k(x) the table holds)")
    # The pair as a two-gear Train (the split path takes tables inline, a Train takes files).
    train = [gearstiff, "dynamics", "--json", "--quiet"]
    for key, value in (("model", "train"), ("gears", "1: 23, 2: 61"), ("meshes", "1-2"),
                       ("modules", "1: 4, 2: 4"), ("fixed", ""), ("carriers", ""),
                       ("connections", ""), ("planets", ""), ("inputs", "1: 1000"),
                       ("output", "2"), ("inertias", "1: 0.01, 2: 0.05")):
        train += ["--set", f"Train/{key}={value}"]
    train += ["--set", "Train mesh 1/stiffness source=file",
              "--set", "Train mesh 1/stiffness file=" + summary_path,
              "--set", "Speed sweep/points=0"]
    for gear_torque, warned in ((100., False), (300., True)):
        report = json.loads(run(train + ["--set", f"Train/input torque={gear_torque:g}"]))
        force = number(report, "mesh1_table_force")
        expected = torque / (radius * 1e-3)
        if not abs(force / expected - 1.) <= 1e-9:
            sys.exit(f"own_pair_train: mesh1_table_force {force:.10g} N, expected T1/r_b1 = "
                     f"{expected:.10g} N")
        texts = report.get("text", {})
        if ("1-2 load warning" in texts) != warned:
            sys.exit(f"own_pair_train: at Gear 1/torque = {gear_torque:g} N·m the load warning "
                     f"is {'missing' if warned else 'given'}: {json.dumps(texts)[:800]}")
    print(f"own_pair_train: table force {force:.8g} N stated; warned at 300 N·m, not at 100")


def main():
    gearstiff, work = sys.argv[1:3]
    shutil.rmtree(work, ignore_errors=True)
    out = os.path.join(work, "sweep")
    run([gearstiff, "stiffness", "--quiet", "-o", out] + PAIR)
    with open(os.path.join(out, "te_map.csv")) as f:
        rows = list(csv.DictReader(f))
    means = {float(r["torque [N*m]"]): float(r["stiffness_mean [N/um]"]) for r in rows}
    if sorted(means) != [100., 300.]:
        sys.exit(f"own_pair_train: te_map.csv torques {sorted(means)}, expected 100, 300")
    if not abs(means[300.] / means[100.] - 1.) > 0.05:
        sys.exit(f"own_pair_train: mean k at 100 and 300 N·m differ by less than 5 % "
                 f"({means}): the check would not tell the torques apart")
    table = os.path.join(out, "stiffness_table.prm")
    with open(table) as f:
        text = f.read()
    gear1 = re.search(r"subsection Gear 1\n(?:.*\n)*?\s*set torque = ([-+0-9.eE]+)", text)
    if gear1 is None or float(gear1.group(1)) != 100.:
        sys.exit(f"own_pair_train: stiffness_table.prm's Gear 1 torque is "
                 f"{gear1.group(1) if gear1 else 'missing'}, expected 100 (the torque of its k)")
    if "T1 100 N·m" not in text or "first torque's of Stiffness/torques" not in text:
        sys.exit("own_pair_train: stiffness_table.prm does not say which torque it holds:\n"
                 + text[:600])
    dynamics = json.loads(run([gearstiff, "dynamics", table, "--json", "--quiet"]))
    mean = dynamics["values"]["mesh1_mean_stiffness"]
    mean = mean["value"] if isinstance(mean, dict) else mean
    deviation = mean / means[100.] - 1.
    if not abs(deviation) <= 1e-6:
        sys.exit(f"own_pair_train: dynamics' mean k {mean:.10g} N/µm against the FE's "
                 f"{means[100.]:.10g} at 100 N·m ({deviation:+.3g})")
    nonlinear = json.loads(run(
        [gearstiff, "dynamics", table, "--json", "--quiet",
         "--set", "Simulation/mesh model=nonlinear",
         "--set", "Mesh 1/transmission error file=" + os.path.join(out, "summary.json"),
         "--set", "Mesh 1/backlash=100", "--set", "Mesh 1/friction coefficient=0",
         "--set", "Train/input speed=50", "--set", "Speed sweep/points=0"]))
    with open(os.path.join(out, "summary.json")) as f:
        sweep = json.load(f)["tables"]["stiffness_sweep"]
    column = sweep["columns"].index("transmission_error")
    fe_mean = sum(row[column] for row in sweep["rows"]) / len(sweep["rows"])
    dte = nonlinear["values"]["mesh1_mean_dte"]
    dte = dte["value"] if isinstance(dte, dict) else dte
    if not abs(dte / fe_mean - 1.) <= 3e-3:
        sys.exit(f"own_pair_train: quasi-static mean DTE {dte:.8g} µm against the FE's mean "
                 f"loaded TE {fe_mean:.8g} µm ({dte / fe_mean - 1.:+.3g}, tolerance 0.3 %)")
    check_load_warning(gearstiff, table, out)
    print(f"own_pair_train: nonlinear, quasi-static: mean DTE {dte:.8g} µm = FE mean loaded TE "
          f"{fe_mean:.8g} µm ({dte / fe_mean - 1.:+.2g})")
    print(f"own_pair_train: table at T1 = 100 N·m, dynamics mean k {mean:.8g} N/µm = FE "
          f"{means[100.]:.8g} ({deviation:+.2g}); at 300 N·m the FE mean is {means[300.]:.8g}")


if __name__ == "__main__":
    main()
