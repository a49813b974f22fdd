#!/usr/bin/env python3
"""docs/accuracy.md's claims table is one-to-one with `ctest -L verification` (issue 43).

Every row of the table "Claims and the tests that check them" names exactly one test
(`verification.NAME` in its test column), every test labelled `verification` has exactly one row,
and no row names a test twice. A claim whose test was removed, or a verification test added
without its row, fails here, so the table a reader checks a figure against is the list ctest
runs. Python 3 standard library only.

usage: claims_table.py ACCURACY_MD CTEST BUILD_DIR
"""
import json
import re
import subprocess
import sys

HEADING = "## Claims and the tests that check them"


def table_tests(path):
    """The `verification.NAME` of each row of the claims table, in order."""
    text = open(path, encoding="utf-8").read()
    if HEADING not in text:
        sys.exit(f"claims_table: {path} has no section '{HEADING}'")
    section = text.split(HEADING, 1)[1].split("\n## ", 1)[0]
    rows = [line for line in section.splitlines() if line.startswith("|")]
    tests = []
    for row in rows[2:]:  # the header and its |---| line
        cells = [c.strip() for c in row.strip().strip("|").split("|")]
        if len(cells) < 4:
            sys.exit(f"claims_table: a row without claim, test, measured, tolerance: {row}")
        names = re.findall(r"`(verification\.[A-Za-z0-9_]+)`", cells[1])
        if len(names) != 1:
            sys.exit(f"claims_table: the test column names {len(names)} verification tests "
                     f"(one expected): {cells[1]}")
        tests.append(names[0])
    return tests


def ctest_tests(ctest, build):
    """The tests whose labels include `verification` (not the fixtures ctest adds to a -L
    selection that needs them: their label is `fixture`)."""
    run = subprocess.run([ctest, "--test-dir", build, "--show-only=json-v1"],
                         capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"claims_table: ctest --show-only failed ({run.returncode}):\n{run.stderr}")
    tests = []
    for test in json.loads(run.stdout)["tests"]:
        labels = [p["value"] for p in test.get("properties", []) if p["name"] == "LABELS"]
        if labels and "verification" in labels[0]:
            tests.append(test["name"])
    return tests


def main():
    path, ctest, build = sys.argv[1:4]
    rows, labelled = table_tests(path), ctest_tests(ctest, build)
    failed = []
    for name in sorted({t for t in rows if rows.count(t) > 1}):
        failed.append(f"{name}: {rows.count(name)} rows")
    for name in sorted(set(rows) - set(labelled)):
        failed.append(f"{name}: a row of the claims table, but no test labelled verification")
    for name in sorted(set(labelled) - set(rows)):
        failed.append(f"{name}: labelled verification, but no row in the claims table")
    print(f"claims table: {len(rows)} rows; ctest -L verification: {len(labelled)} tests")
    if failed:
        sys.exit("claims_table: docs/accuracy.md and ctest -L verification differ:\n  " +
                 "\n  ".join(failed))
    print("one row per verification test, one verification test per row")


if __name__ == "__main__":
    main()
