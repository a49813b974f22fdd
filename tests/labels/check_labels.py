#!/usr/bin/env python3
"""Every ctest entry carries a category label and one tier (issue 43).

    check_labels.py CTEST BUILD_DIR

Lists the suite (`ctest --show-only=json-v1` in BUILD_DIR) and fails, naming each test, when a
test has none of the category labels (plain, unit, cli, regression, verification, python,
readme, invariants) or not exactly one of the tiers `quick` and `slow` (tests/CMakeLists.txt adds
the tier: `slow` for the listed tests, `quick` for the others). So `ctest -L quick` and
`ctest -L <category>` select every test they should, and a new test without a label fails here.
Python 3 standard library only.
"""
import json
import subprocess
import sys

CATEGORIES = {"plain", "unit", "cli", "regression", "verification", "python", "readme", "invariants"}
TIERS = {"quick", "slow"}


def property_of(test, name):
    for prop in test.get("properties", []):
        if prop["name"] == name:
            return prop["value"] if isinstance(prop["value"], list) else [prop["value"]]
    return []


def labels_of(test):
    return set(property_of(test, "LABELS"))


def main():
    ctest, build = sys.argv[1], sys.argv[2]
    listing = subprocess.run([ctest, "--show-only=json-v1"], cwd=build, capture_output=True,
                             text=True, check=True)
    tests = json.loads(listing.stdout)["tests"]
    problems = []
    for test in tests:
        labels = labels_of(test)
        if not labels & CATEGORIES:
            problems.append(f"{test['name']}: no category label (has {sorted(labels)}; one of "
                            f"{sorted(CATEGORIES)})")
        if len(labels & TIERS) != 1:
            problems.append(f"{test['name']}: tiers {sorted(labels & TIERS)}, not exactly one of "
                            "quick/slow")
    # `ctest -L quick` runs the set-up of every fixture a quick test requires: it must be quick.
    slow_fixtures = {}
    for test in tests:
        if "slow" in labels_of(test):
            for fixture in property_of(test, "FIXTURES_SETUP"):
                slow_fixtures[fixture] = test["name"]
    for test in tests:
        if "quick" in labels_of(test):
            for fixture in property_of(test, "FIXTURES_REQUIRED"):
                if fixture in slow_fixtures:
                    problems.append(f"{test['name']}: quick, but needs fixture {fixture} of the "
                                    f"slow {slow_fixtures[fixture]}: make it slow too")
    quick = sum(1 for t in tests if "quick" in labels_of(t))
    print(f"{len(tests)} tests: {quick} quick, {len(tests) - quick} slow")
    for problem in problems:
        print(problem)
    if problems:
        sys.exit(f"{len(problems)} label problem(s): label each test (tests/CMakeLists.txt)")
    if len(tests) < 100:
        sys.exit(f"only {len(tests)} tests listed: the listing failed")


if __name__ == "__main__":
    main()
