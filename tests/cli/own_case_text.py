#!/usr/bin/env python3
"""An own pair's output holds no text of the built-in case, names the torque of every TE figure
and prints the sizes it derived (a new user's walkthrough: z 23/61, m_n 4 mm, b 30 mm,
x 0.2/-0.1, a tip relief of 10 µm with its length `auto`, a Harris map at 100 and 300 N·m).

usage: own_case_text.py path/to/gearstiff WORKDIR

1. `gearstiff stiffness --help` quotes no published figure of the built-in pair (327.2, 497.5).
2. The sweep with -o, as text: no "ANSYS" anywhere (the files-written list said "with the ANSYS
   single/double-pair values"); the load case names both torques and the TE peak-to-peak the
   torque it was taken at (it printed T1 = 300 N·m beside the 100 N·m value).
3. The `auto` tip relief length is listed under "derived sizes" for both gears, equal to
   DE = AE − p_bt = (ε_α − 1)·p_bt (the long relief's definition, app/tooth_modification_
   parameters.cc) with ε_α and p_bt from `gearstiff gear-pair --json` of the same pair, to the
   6 digits the text prints.
"""
import json
import os
import re
import shutil
import subprocess
import sys

PAIR = ["--set", "Gear pair/Pinion/teeth=23", "--set", "Gear pair/Wheel/teeth=61",
        "--set", "Gear pair/Pinion/module=4", "--set", "Gear pair/Wheel/module=4",
        "--set", "Gear pair/Pinion/face width=30", "--set", "Gear pair/Wheel/face width=30",
        "--set", "Gear pair/Pinion/profile shift=0.2", "--set", "Gear pair/Wheel/profile shift=-0.1"]
COARSE = ["--set", "Mesh/contact size=0.3", "--set", "Mesh/fine radius=0.8",
          "--set", "Mesh/body size=1.5", "--set", "Mesh/rim size=5",
          "--set", "Finite elements/Element degree=1"]


def run(gearstiff, *args):
    done = subprocess.run([gearstiff, *args], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"FAILED: gearstiff {' '.join(args)} exited {done.returncode}:\n{done.stderr}")
    return done.stdout


def main():
    gearstiff, work = sys.argv[1:3]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    failures = []
    help_text = run(gearstiff, "stiffness", "--help")
    for figure in ("327.2", "497.5"):
        if figure in help_text:
            failures.append(f"stiffness --help quotes the built-in pair's {figure} N/µm")
    out = run(gearstiff, "stiffness", *PAIR, *COARSE, "--quiet",
              "--set", "Stiffness/mode=sweep", "--set", "Stiffness/sweep positions=3",
              "--set", "Gear pair scene/pinion torque=300", "--set", "Stiffness/torques=100, 300",
              "--set", "Gear pair/Pinion/tip relief=10", "--set", "Gear pair/Wheel/tip relief=10",
              "-o", os.path.join(work, "out"))
    for line in out.splitlines():
        if "ANSYS" in line:
            failures.append(f"built-in text in an own pair's output: '{line.strip()}'")
    if not re.search(r"load case +T1 = 100, 300 N·m on the pinion", out):
        failures.append("the load case does not name the torques of the sweep")
    if not re.search(r"peak-to-peak of the loaded TE over the sweep at T1 = 100 N·m", out):
        failures.append("the TE peak-to-peak does not name the torque it was taken at")
    pair = json.loads(run(gearstiff, "gear-pair", *PAIR, "--json"))["values"]
    expected = (pair["transverse_contact_ratio"]["value"] - 1.) * pair["transverse_base_pitch"]["value"]
    for gear in ("Pinion", "Wheel"):
        found = re.search(rf"Gear pair/{gear}/tip relief length = ([0-9.]+) mm \(auto", out)
        if not found:
            failures.append(f"no derived Gear pair/{gear}/tip relief length in the report")
        elif abs(float(found.group(1)) / expected - 1.) > 1e-5:
            failures.append(f"{gear} tip relief length {found.group(1)} mm, expected "
                            f"(ε_α − 1)·p_bt = {expected:.6g} mm")
        else:
            print(f"{gear} tip relief length {found.group(1)} mm = (ε_α − 1)·p_bt "
                  f"{expected:.6g} mm")
    for f in failures:
        print("FAIL " + f)
    if failures:
        print(out)
        return 1
    print("own case: no built-in text, torques named, auto relief lengths derived")
    return 0


if __name__ == "__main__":
    sys.exit(main())
