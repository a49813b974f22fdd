#!/usr/bin/python3
"""Fuzz test of the gearstiff command-line contract (issues 11 and 26).

    fuzz.py GEARSTIFF WORKDIR [--seed N] [--cases-per-command N]

For every parameter of the fast commands (listed by `gearstiff <cmd> --print-parameters --json`)
and a few FE commands on a coarse scene (cycloid-loads and the train model of the dynamics
included), plus Abaqus decks mutated by the seed (duplicated, deleted, swapped lines, hostile
numbers, huge GENERATE sets, self-includes) read by `contact`, it runs the command with seeded random values at the
edges and beyond (0, negative, NaN, inf, huge, tiny, wrong types, empty, a 120 kB string) and
asserts only the contract, never a number:

  - the exit code is 0, 2 (bad input) or 3 (failed method), and the run ends within its timeout;
  - a failing run prints exactly one line on stderr and writes nothing: no -o folder, no
    staging folder;
  - a successful run with -o creates the folder.

Issue 42 adds cases drawn from the parameters of the newest paths (ISSUE42: fault indices,
torque and variant lists, sweep work, lateral stages and trains, stiffness files, `-o` names and
TMPDIR), with values aimed at their classes of defect (integers beyond int, inf in lists, empty
entries, names given twice, names too long for the file system).

Stdlib only. The seed makes a failure reproducible: every failing case is printed as a command
line, and the seed is printed first. The cases are counted, not timed: `--cases-per-command`
sets how many each command gets, so a seed always runs the same cases (a time budget cut the
plan wherever the machine's load put the end).
"""
import argparse
import json
import os
import random
import re
import shutil
import subprocess
import sys
import time
from itertools import zip_longest

# Commands, the overrides that keep a run short, the per-run timeout (s) and how many cases
# each gets. Fast commands first; the FE ones on a coarse scene with Q1 elements.
# A single planetary stage in the kinematics command's Train form (tests/dynamics/cli).
TRAIN = ["Train/gears=s: 20, p: 10, r: -40", "Train/modules=s: 2, p: 2, r: 2", "Train/carriers=c",
         "Train/planets=p: c*3", "Train/meshes=s-p/c, p-r/c", "Train/fixed=r", "Train/inputs=s: 1470",
         "Train/output=c", "Train/inertias=s: 2e-4, p: 5e-5, c: 4e-3, r: 1e-2", "Train/masses=p: 0.4"]

COARSE_SCENE = [
    "Mesh/contact size=0.2", "Mesh/fine radius=0.5", "Mesh/body size=1", "Mesh/rim size=3",
]
COARSE_FE = COARSE_SCENE + ["Finite elements/Element degree=1"]
COMMANDS = [
    ("kinematics", [], 15, 1.0),
    ("gear-pair", [], 15, 1.0),
    ("cycloid", [], 15, 1.0),
    ("dynamics", ["Simulation/simulated time=0.02"], 20, 1.0),
    ("mesh", COARSE_SCENE, 30, 0.6),
    ("stiffness", COARSE_FE + ["Stiffness/published reference=false"], 40, 0.25),
    ("contact", ["Mesh/Built-in fine size=0.05"], 40, 0.25),
    # issue 26: the newer paths. cycloid-loads with one profile and no torque ramp on Q1 (one solve,
    # ~3 s); the train model of the dynamics; Abaqus decks (DECK below, mutated by seed).
    ("cycloid-loads", ["Cycloid loads/profiles=nominal", "Cycloid loads/torsional curve=false",
                       "Finite elements/Element degree=1"], 40, 0.25),
    ("dynamics", ["Train/model=train", "Simulation/simulated time=0.02"] + TRAIN, 20, 0.5),
]

HUGE_TEXT = "9" * 120_000  # one argument may hold at most 128 kB
LONG_NAME = "n" * 300      # longer than NAME_MAX (255)

# Issue 42: (command, base overrides, timeout [s], {parameter: values}). Each case sets one or two
# of the parameters to values aimed at the classes of the issue; the bases keep a valid case
# short (faults: Q1 on the coarse scene, one position per pitch).
LIN_PARKER = "@SRC@/tests/dynamics/cli/lateral_lin_parker.prm"
BIPLANETARY = ["@SRC@/bench/dynamics_biplanetary_lateral.prm"] + [
    f"Train mesh {n}/stiffness source=constant" for n in range(1, 5)]
SUN_PLANET = "@SRC@/tests/dynamics/cli/stiffness_sun_planet.json"
INTEGER_EDGES = ["1e20", "-2147483648", "2147483648", "3e9", "4294967297", str(10 ** 30), "-0",
                 "1.5", "99", "100", "-99"]
ISSUE42 = [
    ("faults", COARSE_FE + ["Stiffness/sweep positions=1"], 60, {
        "Gear pair/Pinion/faulty tooth": INTEGER_EDGES,
        "Gear pair/Wheel/faulty tooth": INTEGER_EDGES,
        "Stiffness/torques": ["10, 20", "10", "10, inf", "inf", "1e9"],
        "Stiffness/variants": ["tip relief = 5", ";;", "tip relief = 5;;"],
        "Gear pair/Pinion/crack depth": ["1e-9", "1e-300", "0.001", "inf", "1e9"],
        "Gear pair/Pinion/tip relief": ["800", "1e9", "-1", "nan"],
    }),
    ("stiffness", COARSE_FE + ["Stiffness/mode=sweep", "Stiffness/sweep positions=2",
                               "Stiffness/published reference=false"], 60, {
        "Stiffness/torques": ["10, inf", "10, nan", "10, 1e9", "10;20", "10,,20", "20, 10",
                              ", ".join(str(t) for t in range(1, 2000))],
        "Stiffness/variants": [";;", "tip relief = 5;;tip relief = 6", ";", "tip relief = 5;",
                               "; ".join(f"tip relief = {v}" for v in range(1, 1000))],
        "Stiffness/sweep start": ["inf", "1e9", "-inf", "1e-300", "0"],
        "Stiffness/sweep positions": ["5000", "2147483648", "0"],
        "Stiffness/mode": ["single", "double", "roll angle"],
        "Stiffness/sweep mesh": ["once", "per position"],
        "Linear solver/Method": ["cg-gamg", "direct"],
        "Mesh/dimension": ["3"],
        "Mesh/layers": ["1000", "1", "0"],
        "Stiffness/pinion roll angle": ["10.9091", "36.6", "1e9", "-1"],
    }),
    ("dynamics", [LIN_PARKER], 30, {
        "Train/carrier radii": ["c: 1", "c: -5", "c: 0", "c: 1e9", "c: 88.4, c: 88.4", "x: 5"],
        "Train/planet pin errors": ["p#2: 1 0, 2: 1 0", "4294967297: 1 0", "0: 1 0", "-1: 1 0",
                                    "p#5: 1 0", "p#1: inf 0", "2: 1 0, 2: 1 0"],
        "Train/backlash": ["1e12", "1e308", "inf", "0", "-1"],
        "Train/suspended members": ["r: 1e6 10, r: 1e5 1", "x: 1 1", "r: -1 0"],
        "Train/bearing stiffness": ["s: 1e8, x: 1e8", "s: 1e8, s: 1e8", "p: 1e8", "s: inf"],
        "Train/planet pin stiffness": ["p: 1e8, s: 1e8", "x: 1e8", ""],
        "Train/gears": ["s: 1e20, p: 40, r: -111", "s: 3e9, p: 40, r: -111",
                        "s: -2147483648, p: 40, r: -111"],
        "Train/planets": ["p: c*1000", "p: c*1e20", "p: c*4294967297"],
        "Simulation/mesh model": ["nonlinear"],
    }),
    ("dynamics", BIPLANETARY, 40, {
        "Simulation/mesh model": ["nonlinear"],
        "Train/carrier radii": ["h: 0", "h: -5", "H: 1e9"],
        "Train/backlash": ["10", "1e12"],
        "Train/gyroscopic": ["true"],
        "Train/suspended members": ["7: 1e6 10, 7: 1e5 1"],
        "Train/bearing stiffness": ["x: 1e8"],
    }),
    ("dynamics", ["@SRC@/tests/dynamics/cli/planetary_train.prm",
                  "Train/gears=s: 30, p: 18, r: -66", "Train mesh 1/stiffness source=file",
                  f"Train mesh 1/stiffness file={SUN_PLANET}"], 30, {
        "Train mesh 1/stiffness file": [LONG_NAME, "@WORK@/" + LONG_NAME + ".json", "",
                                        "@SRC@/README.md", "/dev/null", "@SRC@"],
        "Train mesh 1/back flank file": [LONG_NAME, SUN_PLANET, "/dev/null"],
        "Simulation/mesh model": ["nonlinear"],
    }),
]
# `-o` names and TMPDIR (issue 42): a case of gear-pair with one of these.
OUTPUT_NAMES = ["", LONG_NAME, "@SRC@/README.md/out", "@WORK@/" + LONG_NAME + "/x",
                "@WORK@/a/../out"]
TMPDIRS = ["@SRC@/README.md", "@WORK@/" + LONG_NAME, "/nonexistent/tmp", "", "@WORK@"]

# Two touching one-cell squares (tests/contact/data/touching_mesh.inp, nodes inline): the deck
# the reader cases mutate, one hostile edit or more per case (deck_mutation).
DECK = """*HEADING
two touching unit squares
*NODE
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
5, 0, 1.0
6, 1, 1.0
7, 1, 2.0
8, 0, 2.0
*ELEMENT, TYPE=CPE4, ELSET=LOWER
1, 1, 2, 3, 4
*ELEMENT, TYPE=CPE4
2, 5, 6, 7, 8
*ELSET, ELSET=UPPER
2
*SURFACE, NAME=LOWER_CONTACT, TYPE=ELEMENT
1, S3
*SURFACE, NAME=LOWER_BOTTOM
LOWER, S1
*SURFACE, NAME=UPPER_CONTACT
2, S1
*SURFACE, NAME=UPPER_TOP
UPPER, S3
"""
HOSTILE_NUMBERS = ["nan", "inf", "-inf", "1e300", "-1e300", "0", "-1", "1e-300", "2.5", "abc", "",
                   "9223372036854775807", "-9223372036854775808", "99999999999999999999"]


def deck_mutation(rng, deck_path):
    """A mutated DECK: duplicated, deleted or swapped lines, hostile numbers, huge GENERATE sets,
    self-includes and fan-out, unknown keywords."""
    lines = DECK.splitlines()
    for _ in range(rng.choice((1, 1, 2, 3))):
        kind = rng.randrange(8)
        i = rng.randrange(len(lines))
        if kind == 0:
            lines.insert(i, lines[i])
        elif kind == 1:
            del lines[i]
        elif kind == 2 and not lines[i].startswith("*"):
            parts = lines[i].split(",")
            parts[rng.randrange(len(parts))] = " " + rng.choice(HOSTILE_NUMBERS)
            lines[i] = ",".join(parts)
        elif kind == 3:
            first = rng.choice(["1", "-5", "0", "2"])
            last = rng.choice(["4000000000000000000", "9223372036854775807", "2", "1", "-3"])
            step = rng.choice(["", ", 1000000000000000000", ", 1", ", 0", ", -1"])
            lines.insert(i, f"*ELSET, ELSET=G, GENERATE\n{first}, {last}{step}")
        elif kind == 4:
            lines.insert(i, "*INCLUDE, INPUT=" + os.path.basename(deck_path))
        elif kind == 5:
            j = rng.randrange(len(lines))
            lines[i], lines[j] = lines[j], lines[i]
        elif kind == 6:
            lines.insert(i, rng.choice(["*ELEMENT, TYPE=CPE8", "*SURFACE, NAME=X", "*ELSET",
                                        "*NODE", "UPPER, S9", "*ELSET, ELSET=UPPER\nUPPER, UPPER"]))
        else:
            lines.insert(i, ",".join(["1"] * rng.choice((1, 5, 50, 5000))))
    return "\n".join(lines) + "\n"


def unmangle(name):
    """deal.II's property-tree names encode characters as _XX (hex)."""
    return re.sub(r"_([0-9a-fA-F]{2})", lambda m: chr(int(m.group(1), 16)), name)


def leaves(tree, path=()):
    for key, value in tree.items():
        if not isinstance(value, dict):
            continue
        if "value" in value and not any(isinstance(v, dict) for v in value.values()):
            yield "/".join(path + (unmangle(key),)), value
        else:
            yield from leaves(value, path + (unmangle(key),))


def parameters(binary, command, cwd):
    out = subprocess.run([binary, command, "--print-parameters", "--json"], cwd=cwd,
                         capture_output=True, text=True, timeout=60)
    if out.returncode != 0:
        raise SystemExit(f"{command} --print-parameters failed: {out.stderr.strip()}")
    return list(leaves(json.loads(out.stdout)))


def candidate_values(entry, rng):
    """Edge and hostile values for one parameter, by its pattern."""
    pattern = entry.get("pattern_description", "")
    default = str(entry.get("default_value", entry.get("value", "")))
    generic = ["", " ", "nope", "1e", "0x10", "1,2", "nan", HUGE_TEXT if rng.random() < 0.05 else "-"]
    if "Selection" in pattern:
        options = re.sub(r"^\[Selection\s*|\s*\]$", "", pattern).split("|")
        return options + ["nope", ""]
    if "Bool" in pattern:
        return ["true", "false", "yes", "2", ""]
    if "Integer" in pattern:
        return ["0", "-1", "1", "2", "3", "1000000", "2147483648", "99999999999", "1.5",
                "abc", ""]
    if "Double" in pattern:
        try:
            d = float(default)
        except ValueError:
            d = 1.0
        scaled = [repr(d * f) for f in (1000.0, 1e-3, -1.0, 1e6, 1e-6)]
        return ["nan", "inf", "-inf", "1e308", "-1e308", "0", "-0", "-1", "1e-300", "1e9",
                "-1e9", "abc", ""] + scaled
    # Anything / lists: numbers in a list, wrong separators, empty entries.
    return generic + [default + "," + default, default + ";" + default, "a: nan, inf",
                      "x: 1e308, -1e308, 0", default.replace(",", ";")]


def expand(text, work):
    src = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    return text.replace("@SRC@", src).replace("@WORK@", work)


def run_case(binary, command, overrides, timeout, work, deck=None, output=None, tmpdir=None):
    """`output`: the -o name instead of <work>/out; `tmpdir`: TMPDIR for the run."""
    out_dir = os.path.join(work, "out") if output is None else expand(output, work)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    if deck is not None:
        # The deck lives beside the case folder: files in the folder count as left behind.
        path, text = deck
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)
    args = [binary, command]
    for o in overrides:
        if o.endswith((".prm", ".json")) and "=" not in o:
            args.append(expand(o, work))  # a parameter file
        else:
            args += ["--set", expand(o, work)]
    # --quiet: progress lines (stderr, e.g. "dynamics: simulating ...") are not the message; the
    # error line prints all the same, and it is what the contract counts.
    args += (["--output=" + out_dir] if out_dir == "" else ["-o", out_dir]) + ["--quiet"]
    environment = dict(os.environ)
    if tmpdir is not None:
        environment["TMPDIR"] = expand(tmpdir, work)
    start = time.monotonic()
    try:
        proc = subprocess.run(args, cwd=work, capture_output=True, text=True, timeout=timeout,
                              errors="replace", env=environment)
    except subprocess.TimeoutExpired:
        return args, f"no answer within {timeout} s (hang or unbounded work)", None
    elapsed = time.monotonic() - start
    problems = []
    if proc.returncode not in (0, 2, 3):
        problems.append(f"exit code {proc.returncode} (contract: 0, 2 or 3)")
    left = [n for n in os.listdir(work) if n != "out" or proc.returncode != 0]
    if proc.returncode != 0:
        lines = [l for l in proc.stderr.splitlines() if l.strip()]
        if len(lines) != 1:
            problems.append(f"{len(lines)} lines on stderr (contract: one)")
        elif len(lines[0]) > 2000:
            problems.append(f"error line of {len(lines[0])} characters")
        if left:
            problems.append(f"failed run left {left}")
    else:
        # The folder as the command names it: "a/../out" is "out" (the command normalises the
        # path; the file system cannot resolve "a/.." while "a" does not exist).
        if not os.path.isdir(os.path.normpath(os.path.join(work, out_dir))):
            problems.append("successful run with -o created no folder")
        stale = [n for n in os.listdir(work) if n.startswith(".gearstiff-staging")]
        if stale:
            problems.append(f"successful run left {stale}")
    return args, "; ".join(problems), (proc, elapsed)


def issue42_cases(rng, count):
    """Issue 42: `count` cases per family of ISSUE42 (one or two of its parameters), and `count`
    gear-pair cases with a hostile -o name or TMPDIR."""
    families = []
    for command, base, timeout, choices in ISSUE42:
        cases = []
        for _ in range(count):
            chosen = rng.sample(sorted(choices), k=min(len(choices), rng.choice((1, 1, 2))))
            cases.append((command, list(base) + [f"{name}={rng.choice(choices[name])}"
                                                 for name in chosen], timeout, None))
        families.append(cases)
    names = []
    for _ in range(count):
        if rng.random() < 0.5:
            names.append(("gear-pair", [], 15, None, rng.choice(OUTPUT_NAMES), None))
        else:
            names.append(("gear-pair", [], 15, None, None, rng.choice(TMPDIRS)))
    families.append(names)
    return families


def shown(args):
    return " ".join(repr(a) if (" " in a or not a) else a for a in args)[:400]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("binary")
    parser.add_argument("work")
    parser.add_argument("--seed", type=int, default=20261123)
    parser.add_argument("--cases-per-command", type=int, default=10)
    options = parser.parse_args()
    print(f"fuzz: seed {options.seed}, {options.cases_per_command} cases per command", flush=True)
    rng = random.Random(options.seed)
    os.makedirs(options.work, exist_ok=True)

    per_command = []
    for command, base, timeout, weight in COMMANDS:
        entries = parameters(options.binary, command, options.work)
        cases = []
        for _ in range(max(1, round(options.cases_per_command * weight))):
            chosen = rng.sample(entries, k=min(len(entries), rng.choice((1, 1, 2, 3))))
            overrides = list(base) + [f"{path}={rng.choice(candidate_values(entry, rng))}"
                                      for path, entry in chosen]
            cases.append((command, overrides, timeout, None))
        per_command.append(cases)
    # Abaqus decks (issue 26), mutated by the seed, read by `contact` (serial).
    decks = []
    for k in range(max(1, options.cases_per_command)):
        path = os.path.join(options.work, "decks", f"deck{k}.inp")
        decks.append(("contact", [f"Mesh/File={path}"], 30, (path, deck_mutation(rng, path))))
    per_command.append(decks)
    per_command += issue42_cases(rng, options.cases_per_command)
    # Round-robin over the commands.
    plan = [case for batch in zip_longest(*per_command) for case in batch if case]

    failures, run, codes = [], 0, {}
    for i, (command, overrides, timeout, deck, *names) in enumerate(plan):
        output, tmpdir = names if names else (None, None)
        args, problem, result = run_case(options.binary, command, overrides, timeout,
                                         os.path.join(options.work, f"case{i}"), deck, output,
                                         tmpdir)
        run += 1
        if result:
            codes[result[0].returncode] = codes.get(result[0].returncode, 0) + 1
        if problem:
            stderr = result[0].stderr.strip()[:300] if result else ""
            failures.append(f"FAIL {shown(args)}\n     {problem}\n     stderr: {stderr}")
        else:
            shutil.rmtree(os.path.join(options.work, f"case{i}"), ignore_errors=True)
    print(f"fuzz: seed {options.seed}, {run} cases run, exit codes {codes}")
    for f in failures:
        print(f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
