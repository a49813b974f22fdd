#!/usr/bin/env python3
"""Every command's numeric parameters state their unit one way (issue 45, docs/developers.md
"Units are written one way"): the documentation string of each Integer, Double or list-of-Double
parameter carries its unit in brackets ("face width b [mm]", "[-]" for a pure number), and none
begins with a bare unit ("mm, ..."), the older spelling `--print-parameters` and the Python
module's `unit` do not read.

usage: parameter_units.py GEARSTIFF
"""
import json
import re
import subprocess
import sys

COMMANDS = ["cai", "contact", "cycloid", "cycloid-loads", "dynamics", "faults", "gear-pair",
            "kinematics", "mesh", "run", "stiffness"]
# A unit in brackets: no blank, comma or '=' inside (so "[0, 0.5)" or "[Double ...]" do not count).
BRACKETED = re.compile(r"\[[^\]\s,=]{1,16}\]")
LEADING_UNIT = re.compile(r"^(-|mm|m|s|N|deg|rpm|N·m|Pa|MPa|GPa|Hz|µm|µs|N/m|kg|rad)[,;] ")
NUMERIC = ("[Integer", "[Double", "[List of <[Double", "[List of <[Integer")


def entries(node, path=""):
    for key, value in node.items():
        if isinstance(value, dict) and "documentation" in value:
            yield path + key, value
        elif isinstance(value, dict):
            yield from entries(value, path + key + "/")


def main():
    binary = sys.argv[1]
    problems, checked = [], 0
    for command in COMMANDS:
        out = subprocess.run([binary, command, "--print-parameters", "--json"],
                             capture_output=True, text=True, check=True)
        for name, entry in entries(json.loads(out.stdout)):
            doc = entry["documentation"]
            if LEADING_UNIT.match(doc):
                problems.append(f"{command}: {name}: begins with a bare unit: {doc[:60]}")
            if entry["pattern_description"].startswith(NUMERIC):
                checked += 1
                if not BRACKETED.search(doc):
                    problems.append(f"{command}: {name}: no [unit]: {doc[:60]}")
    if problems:
        sys.exit("\n".join(problems))
    print(f"{checked} numeric parameters of {len(COMMANDS)} commands checked, each with [unit]")


if __name__ == "__main__":
    main()
