#!/usr/bin/env python3
"""The parameters written beside a result run it again: `gearstiff CMD DIR/parameters.json` (and
.prm) gives the same values as the run that wrote them.

usage: parameters_round_trip.py path/to/gearstiff WORK_FOLDER

Found by a user's first round trip (session 49): every command that declares ISO 6336/C_M
(gear-pair, stiffness, faults, cai, run, ...) refused its own parameters.json with "You can't ask
for entry <C" — deal.II 9.4 writes JSON names plain but reads them as mangled ("_XX" a hex-coded
character), so the '_' of C_M was read as a code. Names are now mangled for its reader, and JSON
numbers read as the text they are.

Asserts, for gear-pair on an own pair and for dynamics (the two cheap commands, one with C_M):
every reported value except costs and times equal (exactly: the same inputs, the same code),
from parameters.json and from parameters.prm; a hand-written JSON file with numeric values and
C_M gives the --set run's values.
"""
import json
import os
import shutil
import subprocess
import sys

OWN = ["--set", "Gear pair/Pinion/teeth=19", "--set", "Gear pair/Wheel/teeth=47",
       "--set", "Gear pair/Pinion/module=3", "--set", "Gear pair/Wheel/module=3",
       "--set", "ISO 6336/C_M=0.75"]


def run(args):
    process = subprocess.run(args, capture_output=True, text=True)
    if process.returncode != 0:
        sys.exit(f"parameters_round_trip: {' '.join(args[1:3])} exited {process.returncode}: "
                 f"{process.stderr.strip()[-400:]}")
    return json.loads(process.stdout)


def values(report):
    return {k: v for k, v in report["values"].items()
            if "time" not in k and k not in ("cost",)}


def same(label, a, b):
    va, vb = values(a), values(b)
    if va != vb:
        differ = [k for k in va if va.get(k) != vb.get(k)][:5]
        sys.exit(f"parameters_round_trip: {label}: values differ ({differ})")
    return len(va)


def main():
    gearstiff, work = sys.argv[1:3]
    shutil.rmtree(work, ignore_errors=True)
    for command, sets in (("gear-pair", OWN), ("dynamics", ["--set", "Speed sweep/points=0"])):
        out = os.path.join(work, command)
        first = run([gearstiff, command, "--json", "--quiet", "-o", out] + sets)
        for written in ("parameters.json", "parameters.prm"):
            again = run([gearstiff, command, os.path.join(out, written), "--json", "--quiet"])
            count = same(f"{command} from {written}", first, again)
        print(f"parameters_round_trip: {command}: {count} values equal from parameters.json "
              f"and parameters.prm")
    typed = os.path.join(work, "typed.json")
    with open(typed, "w") as f:
        json.dump({"Gear pair": {"Pinion": {"teeth": 19, "module": 3},
                                 "Wheel": {"teeth": 47, "module": 3.0}},
                   "ISO 6336": {"C_M": 0.75}}, f)
    same("hand-written JSON, numeric values", run([gearstiff, "gear-pair", "--json", "--quiet"] + OWN),
         run([gearstiff, "gear-pair", typed, "--json", "--quiet"]))
    print("parameters_round_trip: a hand-written JSON file with numbers and C_M reads as typed")


if __name__ == "__main__":
    main()
