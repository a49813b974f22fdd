#!/usr/bin/env python3
"""Progress lines (issue 25): on stderr, from the rank that did the work, silenced by --quiet,
never on stdout of a --json run.

usage: progress.py path/to/gearstiff "MPIEXEC"

1. `stiffness --json` (one position): stderr shows the four stages with the elapsed time, stdout
   is exactly one JSON object.
2. `stiffness --quiet`: stderr is empty.
3. `MPIEXEC -np 2 stiffness --json`, a 4-position sweep: each rank reports the positions it
   solved ("[rank 0]" and "[rank 1]", each with "done here", elapsed and "left"), stdout is JSON.
4. `contact --json` (the Hertz case): the set-up and each active-set iteration on stderr.
5. `dynamics --json`, a 3-speed up-and-down sweep: one line per speed run ("speed sweep i/6",
   the speed, elapsed and "left"), stdout is JSON; with --quiet stderr is empty.
6. `stiffness` without --json: the progress lines ("solving the single position", "k = …") on
   stderr only, stdout the report alone; k in the report's unit N/µm, in the sweep's lines too.
"""
import json
import re
import shlex
import subprocess
import sys


def run(command):
    process = subprocess.run(command, capture_output=True, text=True)
    if process.returncode != 0:
        sys.exit(f"progress: {' '.join(command)} exited {process.returncode}: {process.stderr}")
    return process


def main():
    gearstiff, mpiexec = sys.argv[1], shlex.split(sys.argv[2])
    one = run([gearstiff, "stiffness", "--json"])
    json.loads(one.stdout)  # stdout holds the JSON alone
    for stage in range(1, 5):
        if not re.search(rf"stiffness: stage {stage}/4 .* s elapsed", one.stderr):
            sys.exit(f"progress: no stage {stage}/4 line on stderr:\n{one.stderr}")
    quiet = run([gearstiff, "stiffness", "--quiet"])
    if quiet.stderr.strip():
        sys.exit(f"progress: --quiet printed on stderr:\n{quiet.stderr}")
    text = run([gearstiff, "stiffness"])
    for pattern in (r"stiffness: solving the single position", r"stiffness: k = [0-9.]+ N/µm",
                    r"stiffness: stage 1/4"):
        if not re.search(pattern, text.stderr):
            sys.exit(f"progress: no line like {pattern} on stderr:\n{text.stderr}")
    leaked = [line for line in text.stdout.splitlines() if line.startswith("stiffness:")]
    if leaked:
        sys.exit(f"progress: progress lines on stdout of a text run: {leaked}")
    sweep = run(mpiexec + ["-np", "2", gearstiff, "stiffness", "--json", "--set",
                           "Stiffness/mode=sweep", "--set", "Stiffness/sweep positions=4"])
    json.loads(sweep.stdout)
    if not re.search(r"stiffness: position \d/4 .*: k = [0-9.]+ N/µm, ", sweep.stderr):
        sys.exit(f"progress: the sweep's lines give k in another unit than N/µm:\n{sweep.stderr}")
    for rank in (0, 1):
        pattern = rf"stiffness: position \d/4 .*done here of ~2, .* s elapsed, ~.* s left\) \[rank {rank}\]"
        if not re.search(pattern, sweep.stderr):
            sys.exit(f"progress: rank {rank} reported no position:\n{sweep.stderr}")
    contact = run([gearstiff, "contact", "--json"])
    json.loads(contact.stdout)
    for pattern in (r"contact: set-up done: \d+ DoFs, \d+ slave nodes",
                    r"contact: load step 1/1, iteration \d+: \d+ closed, 0 changed"):
        if not re.search(pattern, contact.stderr):
            sys.exit(f"progress: contact printed no line like {pattern}:\n{contact.stderr}")
    sweep_args = ["--set", "Speed sweep/points=3", "--set", "Speed sweep/direction=both"]
    dynamics = run([gearstiff, "dynamics", "--json"] + sweep_args)
    json.loads(dynamics.stdout)
    for i in range(1, 7):
        pattern = rf"dynamics: speed sweep {i}/6, [0-9.]+ rpm.*\({i} done here of ~6, .* s elapsed, ~.* s left\)"
        if not re.search(pattern, dynamics.stderr):
            sys.exit(f"progress: no dynamics sweep line {i}/6 on stderr:\n{dynamics.stderr}")
    quiet = run([gearstiff, "dynamics", "--quiet"] + sweep_args)
    if quiet.stderr.strip():
        sys.exit(f"progress: dynamics --quiet printed on stderr:\n{quiet.stderr}")
    print("progress: stages, per-rank sweep lines, contact iterations, dynamics sweep lines, "
          "--quiet and --json stdout as expected")


if __name__ == "__main__":
    main()
