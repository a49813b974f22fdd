#!/usr/bin/env python3
"""In-process Python calls against one process per call (issue 32).

100 `gearstiff.gear_pair(params)` evaluations in one Python process against 100
`gearstiff gear-pair --json --set ...` processes (the way a Python optimisation loop reached
gearstiff before the module), each evaluation with a different face width (both gears) so no result
is reused. Three rounds, alternating the two ways; the figures are the medians over the rounds and
the ratio is taken within each round (the machine is shared). Target: in-process >= 20x faster.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_api.py [build/app/gearstiff] [--rounds N]

The process side includes what every process pays: MPI singleton start, library loading, parameter
parsing and the JSON (fem/mpi_start.h keeps Open MPI's singleton start near 0.08 s).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

ENVIRONMENT = dict(os.environ)  # before MPI starts (see tests/python/test_api.py)
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "build", "python"))
import gearstiff  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("executable", nargs="?", default=os.path.join(HERE, "..", "build", "app",
                                                                   "gearstiff"))
parser.add_argument("--rounds", type=int, default=3)
parser.add_argument("--evaluations", type=int, default=100)
arguments = parser.parse_args()

widths = [20 + 20 * i / (arguments.evaluations - 1) for i in range(arguments.evaluations)]  # mm


def in_process():
    start = time.perf_counter()
    results = [gearstiff.gear_pair({"Gear pair": {"Pinion": {"face width": b},
                                                  "Wheel": {"face width": b}}})
               ["values"]["iso_single_stiffness_times_width"]["value"] for b in widths]
    return time.perf_counter() - start, results


def processes():
    start = time.perf_counter()
    results = []
    for b in widths:
        out = subprocess.run([arguments.executable, "gear-pair", "--json",
                              "--set", f"Gear pair/Pinion/face width={b!r}",
                              "--set", f"Gear pair/Wheel/face width={b!r}"],
                             capture_output=True, text=True, check=True, env=ENVIRONMENT).stdout
        results.append(json.loads(out)["values"]["iso_single_stiffness_times_width"]["value"])
    return time.perf_counter() - start, results


inside, outside, ratios = [], [], []
for round_number in range(arguments.rounds):
    t_in, r_in = in_process()
    t_out, r_out = processes()
    # Same numbers both ways (the CLI prints 12 significant digits).
    assert all(abs(a - b) <= 1e-11 * abs(b) for a, b in zip(r_in, r_out))
    inside.append(t_in)
    outside.append(t_out)
    ratios.append(t_out / t_in)
    print(f"round {round_number + 1}: {arguments.evaluations} in-process {t_in:.4f} s "
          f"({1e3 * t_in / arguments.evaluations:.3f} ms each), {arguments.evaluations} processes "
          f"{t_out:.2f} s ({1e3 * t_out / arguments.evaluations:.1f} ms each), ratio {t_out / t_in:.0f}",
          flush=True)

print(f"median of {arguments.rounds} rounds: in-process {statistics.median(inside):.4f} s, "
      f"processes {statistics.median(outside):.2f} s, ratio {statistics.median(ratios):.0f}x "
      f"(target >= 20x)")
