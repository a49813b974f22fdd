#!/usr/bin/env python3
"""Where the suite's time goes (issue 43): the last `ctest` run's time of every test, weighted by
the processors it holds, summed by label, and the costliest tests.

usage: python3 tools/test_times.py [BUILD_DIR] [--top N] [--cores C]

Reads BUILD_DIR/Testing/Temporary/CTestCostData.txt (ctest's own record: per test the number of
runs and the mean time in s, which after one run in a fresh build folder is that run's time) and
`ctest --show-only=json-v1` (labels, PROCESSORS). A test counts under each of its labels. The
"ideal wall" is Σ(time × processors)/C: what the run would take on C cores packed without a gap,
a lower bound to compare with the measured `Total Test time (real)`.
"""
import argparse
import collections
import json
import os
import subprocess
import sys


def cost_data(build):
    """{test name: mean time [s]} of CTestCostData.txt (the part before its '---' line)."""
    path = os.path.join(build, "Testing", "Temporary", "CTestCostData.txt")
    times = {}
    try:
        with open(path) as f:
            for line in f:
                if line.startswith("---"):
                    break
                name, _, seconds = line.rsplit(None, 2)
                times[name] = float(seconds)
    except OSError as error:
        sys.exit(f"test_times: {error} (run ctest in {build} first)")
    return times


def test_properties(build):
    """{test name: (labels, processors)} as ctest knows them."""
    listing = subprocess.run(["ctest", "--test-dir", build, "--show-only=json-v1"],
                             capture_output=True, text=True, check=True)
    tests = {}
    for test in json.loads(listing.stdout)["tests"]:
        labels, processors = [], 1
        for p in test.get("properties", []):
            if p["name"] == "LABELS":
                labels = p["value"]
            elif p["name"] == "PROCESSORS":
                processors = int(p["value"])
        tests[test["name"]] = (labels, processors)
    return tests


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("build", nargs="?", default="build")
    parser.add_argument("--top", type=int, default=25)
    parser.add_argument("--cores", type=int, default=os.cpu_count() or 1)
    args = parser.parse_args()
    times, tests = cost_data(args.build), test_properties(args.build)
    weighted = {name: seconds * tests.get(name, ([], 1))[1] for name, seconds in times.items()
                if name in tests}
    by_label, count = collections.Counter(), collections.Counter()
    for name, seconds in weighted.items():
        for label in tests[name][0] or ["(none)"]:
            by_label[label] += seconds
            count[label] += 1
    total = sum(weighted.values())
    print(f"{len(weighted)} of {len(tests)} tests timed; Σ time × processors {total:.0f} s; "
          f"ideal wall on {args.cores} cores {total / args.cores:.0f} s")
    print("by label (s, tests):")
    for label, seconds in by_label.most_common():
        print(f"  {label:14s} {seconds:8.0f} {count[label]:5d}")
    print(f"costliest {args.top} (s × processors):")
    for name, seconds in sorted(weighted.items(), key=lambda item: -item[1])[:args.top]:
        processors = tests[name][1]
        print(f"  {seconds:7.1f}  {name}" + (f"  ({processors} processors)"
                                             if processors > 1 else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
