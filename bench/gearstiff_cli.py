"""Runs the `gearstiff` command line for the bench scripts: one run's --json values, and the
median of a value over repeated runs.

    from gearstiff_cli import median_value
    seconds, values = median_value(3, "sweep_time", "dynamics", prm, "Speed sweep/points=100")

The binary is the script's first argument, else build/app/gearstiff of this checkout.
"""
import json
import os
import statistics
import subprocess
import sys

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
binary = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build", "app", "gearstiff")


def run_values(command, prm, *settings):
    """The "values" of `gearstiff command prm --json --set s ...` (prm None: the built-in case)."""
    args = [binary, command] + ([prm] if prm else []) + ["--json"]
    for s in settings:
        args += ["--set", s]
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    return json.loads(out)["values"]


def median_value(runs, key, command, prm, *settings):
    """The median of value `key` over `runs` runs, and the first run's values."""
    values = [run_values(command, prm, *settings) for _ in range(runs)]
    return statistics.median(v[key]["value"] for v in values), values[0]
