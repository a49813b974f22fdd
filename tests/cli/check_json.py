#!/usr/bin/env python3
"""Runs a `gearstiff` command with --json and compares numbers of its output with references.

usage: check_json.py WORKDIR [--check SPEC]... [--expect-file NAME]... [--text REGEX]...
                     [--stderr REGEX] -- command args...
       check_json.py WORKDIR --summary FILE [--check SPEC]... [--text REGEX]...

WORKDIR is emptied first and is the command's working directory; "@WORK@" and "@SRC@" in the
arguments expand to it and to the source tree. The command must exit 0 and print one JSON
object (app/core/report.cc). Each SPEC is

    KEY REFERENCE TOLERANCE        |value − REFERENCE| ≤ TOLERANCE (absolute, in KEY's unit)
    KEY REFERENCE TOLERANCE%       |value/REFERENCE − 1| ≤ TOLERANCE/100

with KEY a value name (`mesh_stiffness`), REFERENCE a number or @KEY (another value of the same
output), `table:COLUMN:ROW` (ROW an index, or max/min/sum/count
over the column), or `text:NAME` compared as a string with REFERENCE (no tolerance: "-").
The reference and where it comes from are the caller's business: every test that uses this
script states its source beside the SPEC (tests/*/CMakeLists.txt). Each check prints the
measured value and its deviation, so a test's log carries the figure its comment quotes.
--text REGEX must match one line "NAME: text" of the output's text entries (a note, a model
description: what a command says beside its numbers), --stderr REGEX the command's stderr.
--summary FILE checks the summary.json another test wrote (a ctest fixture, e.g. a regression
case's run) instead of running the same command again (issue 43: the suite's time).
"""
import json
import os
import re
import shutil
import subprocess
import sys


def parse_arguments(argv):
    work, checks, files = argv[1], [], []
    patterns = {"--text": [], "--stderr": [], "--summary": []}
    i = 2
    while i < len(argv) and argv[i] != "--":
        if argv[i] == "--check":
            checks.append(argv[i + 1].split())
            i += 2
        elif argv[i] == "--expect-file":
            files.append(argv[i + 1])
            i += 2
        elif argv[i] in patterns:
            patterns[argv[i]].append(argv[i + 1])
            i += 2
        else:
            sys.exit(f"check_json: unknown option {argv[i]}")
    return work, checks, files, patterns, argv[i + 1:]


def check_patterns(summary, stderr, patterns):
    """The --text and --stderr regular expressions; returns the number that failed."""
    lines = [f"{name}: {text}" for name, text in summary.get("text", {}).items()]
    failed = 0
    for pattern in patterns["--text"]:
        ok = any(re.search(pattern, line) for line in lines)
        print(f"{'ok  ' if ok else 'FAIL'} text /{pattern}/")
        failed += not ok
    for pattern in patterns["--stderr"]:
        ok = re.search(pattern, stderr) is not None
        print(f"{'ok  ' if ok else 'FAIL'} stderr /{pattern}/")
        failed += not ok
    if failed:
        print("--- text entries:\n" + "\n".join(lines) + "\n--- stderr:\n" + stderr[-2000:])
    return failed


def lookup(summary, key):
    if key.startswith("text:"):
        return summary["text"][key[5:]]
    if key.startswith("table:"):
        parts = key.split(":")
        table, column, row = parts[1], ":".join(parts[2:-1]), parts[-1]
        data = summary["tables"][table]
        values = [r[data["columns"].index(column)] for r in data["rows"]]
        if row == "max":
            return max(values)
        if row == "min":
            return min(values)
        if row == "sum":
            return sum(values)
        if row == "count":
            return len(values)
        return values[int(row)]
    entry = summary["values"][key]
    return entry["value"] if isinstance(entry, dict) else entry


def run_command(work, command):
    """Runs the command with --json in an emptied WORKDIR: its summary, stderr and command line."""
    src = os.path.realpath(os.path.join(os.path.dirname(__file__), "..", ".."))
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    command = [a.replace("@WORK@", work).replace("@SRC@", src) for a in command] + ["--json"]
    run = subprocess.run(command, cwd=work, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"check_json: exit code {run.returncode}\n--- command: {' '.join(command)}\n"
                 f"--- stderr:\n{run.stderr[-3000:]}")
    return json.loads(run.stdout[run.stdout.index("{"):]), run.stderr, command


def main():
    work, checks, files, patterns, command = parse_arguments(sys.argv)
    if patterns["--summary"]:
        command = [f"(summary {patterns['--summary'][0]})"]
        with open(patterns["--summary"][0], encoding="utf-8") as stored:
            summary, stderr = json.load(stored), ""
    else:
        summary, stderr, command = run_command(work, command)
    failed = check_patterns(summary, stderr, patterns)
    for spec in checks:
        key, reference, tolerance = spec[0], spec[1], spec[2]
        try:
            value = lookup(summary, key)
        except (KeyError, ValueError, IndexError) as error:
            print(f"FAIL {key}: not in the output ({error!r})")
            failed += 1
            continue
        if tolerance == "-":
            ok = str(value) == reference
            print(f"{'ok  ' if ok else 'FAIL'} {key} = {value!r} (expected {reference!r})")
        elif value is None:
            ok = False
            print(f"FAIL {key} = null (expected {reference})")
        else:
            ref = lookup(summary, reference[1:]) if reference.startswith("@") else float(reference)
            if tolerance.endswith("%"):
                deviation = value / ref - 1. if ref != 0. else float("inf")
                ok = abs(deviation) <= float(tolerance[:-1]) / 100.
                print(f"{'ok  ' if ok else 'FAIL'} {key} = {value:.10g} against {ref:.10g}: "
                      f"{deviation * 100:+.4g} % (tolerance ±{tolerance})")
            else:
                deviation = value - ref
                ok = abs(deviation) <= float(tolerance)
                print(f"{'ok  ' if ok else 'FAIL'} {key} = {value:.10g} against {ref:.10g}: "
                      f"{deviation:+.4g} (tolerance ±{tolerance})")
        failed += not ok
    for name in files:
        path = os.path.join(work, name.replace("@WORK@/", ""))
        ok = os.path.isfile(path) and os.path.getsize(path) > 0
        print(f"{'ok  ' if ok else 'FAIL'} file {name}")
        failed += not ok
    if failed:
        total = len(checks) + len(files) + len(patterns["--text"]) + len(patterns["--stderr"])
        sys.exit(f"check_json: {failed} of {total} checks failed\n"
                 f"--- command: {' '.join(command)}")


if __name__ == "__main__":
    main()
