#!/usr/bin/env python3
"""Every table a command writes names its categories (a sweep's direction, a run's status, a
stiffness source) in the CSV, and summary.json states each table's columns, units and the names
a categorical column allows: a table opened alone (a spreadsheet, pandas.read_csv) says what its
entries mean. Reads the CSVs back with the csv module.

usage: tables_by_name.py GEARSTIFF SOURCE_DIR WORK_DIR [--case OUTPUT_DIR command args...]...

Each --case names the `-o` folder a regression case wrote (the default commands) and its command
line; a folder without summary.json (this test run alone) is written again by running the
command. The script adds its own runs for the columns no default command writes (a dynamics sweep
up and down with nonlinear meshes, the lateral stage's sweep).
"""
import csv
import json
import os
import shutil
import subprocess
import sys

STATUS = ["valid", "diverged", "contact loss", "not steady"]
# The categorical columns by name, with the names each must allow (None: not fixed here).
EXPECTED = {
    "source": ["calibrated Cai", "FE k(θ) table", "paper-scaled Cai"],
    "direction": ["up", "down"],
    "status": STATUS,
    "branch": None,
    "profile": ["nominal", "corrected"],
    "class": ["rotational", "translational", "planet", "mixed"],
}
# Tables of the default commands and of the runs below that must show up with their categories.
REQUIRED = {("run_kv", "source"), ("dynamics_speed_sweep", "status"),
            ("cycloid_torsion", "branch"), ("dynamics_nonlinear_sweep", "direction"),
            ("dynamics_nonlinear_sweep", "status"), ("dynamics_dte_waterfall", "direction"),
            ("lateral_speed_sweep", "direction"), ("lateral_speed_sweep", "status"),
            ("lateral_modes", "class")}


def is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def check_folder(folder, seen, errors):
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    for name, table in summary["tables"].items():
        case = os.path.basename(folder)
        where = f"{os.path.basename(os.path.dirname(folder)) if case == 'out' else case}/{name}"
        categories = table.get("categories", {})
        with open(os.path.join(folder, name + ".csv"), newline="") as f:
            rows = list(csv.reader(f))
        header = [f"{c} [{u}]" for c, u in zip(table["columns"], table["units"])]
        if rows[0] != header:
            errors.append(f"{where}: CSV header {rows[0]} != {header}")
            continue
        for c, column in enumerate(table["columns"]):
            cells = [r[c] for r in rows[1:]]
            if column in EXPECTED and column not in categories:
                errors.append(f"{where}: column {column} holds {sorted(set(cells))[:4]}, "
                              "not declared categorical in summary.json")
                continue
            if column not in categories:
                text = [v for v in cells if not is_number(v)]
                if text:
                    errors.append(f"{where}: numeric column {column} holds text {text[:3]}")
                continue
            allowed = categories[column]
            expected = EXPECTED.get(column)
            if expected is not None and allowed != expected:
                errors.append(f"{where}: {column} allows {allowed}, expected {expected}")
            json_cells = [r[c] for r in table["rows"]]
            for label, values in (("CSV", cells), ("JSON", json_cells)):
                wrong = [v for v in values if v not in allowed]
                if wrong:
                    errors.append(f"{where}: {label} column {column} holds {wrong[:3]}, "
                                  f"not one of {allowed}")
            seen.add((name, column))
            print(f"{where}: {column} by name: {sorted(set(cells))}")


def run(gearstiff, work, name, args):
    folder = os.path.join(work, name)
    shutil.rmtree(folder, ignore_errors=True)
    result = subprocess.run([gearstiff] + args + ["--quiet", "-o", folder], capture_output=True,
                            text=True)
    if result.returncode != 0:
        sys.exit(f"FAILED: gearstiff {' '.join(args)}: exit {result.returncode}\n"
                 f"{result.stderr[-2000:]}")
    return folder


def main(argv):
    gearstiff, source, work = argv[1:4]
    os.makedirs(work, exist_ok=True)
    folders, cases = [], []
    for word in argv[4:]:
        if word == "--case":
            cases.append([])
        else:
            cases[-1].append(word)
    for folder, *command in cases:
        if not os.path.isfile(os.path.join(folder, "summary.json")):
            folder = run(gearstiff, work, os.path.basename(os.path.dirname(folder)), command)
        folders.append(folder)
    sweep = ["--set", "Speed sweep/points=3", "--set", "Speed sweep/direction=both"]
    folders.append(run(gearstiff, work, "dynamics_up_down", [
        "dynamics", "--set", "Simulation/mesh model=nonlinear"] + sweep))
    folders.append(run(gearstiff, work, "lateral_up_down", [
        "dynamics", os.path.join(source, "tests/dynamics/cli/lateral_lin_parker.prm"),
        "--set", "Speed sweep/points=2", "--set", "Speed sweep/minimum speed=200",
        "--set", "Speed sweep/maximum speed=4000", "--set", "Speed sweep/direction=both",
        "--set", "Simulation/steady state start=0.02", "--set", "Simulation/time step=5",
        "--set", "Simulation/simulated time=0.001", "--set", "Simulation/mesh model=nonlinear",
        "--set", "Train/bearing damping=s: 2000, r: 2000, c: 2000",
        "--set", "Train mesh 1/damping=1000", "--set", "Train mesh 2/damping=1000",
        "--set", "Train mesh 1/stiffness source=cai",
        "--set", "Train mesh 2/stiffness source=cai"]))
    seen, errors = set(), []
    for folder in folders:
        check_folder(folder, seen, errors)
    for table, column in sorted(REQUIRED - seen):
        errors.append(f"{table}/{column}: not written by name (summary.json 'categories')")
    for e in errors:
        print("FAIL " + e)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
