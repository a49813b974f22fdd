"""Shared helpers of the verification tests (ctest -L verification, docs/accuracy.md).

Each test script runs `gearstiff` (and, for the CalculiX comparisons, `ccx` through the bench
scripts' helpers in bench/), computes the claim's figure and its independent reference, and
checks them with `Checks.near`, which prints the measured deviation beside the tolerance: the
test's log carries the figure docs/accuracy.md quotes.
"""
import json
import os
import shutil
import subprocess
import sys

SOURCE = os.path.realpath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE, "bench"))


def work_folder(path):
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    return path


def run_json(gearstiff, command, settings=(), extra=(), cwd=None):
    """`gearstiff command --json --set s ...` -> the JSON summary (exits the test on failure)."""
    args = [gearstiff, command, "--json"] + list(extra)
    for s in settings:
        args += ["--set", s]
    run = subprocess.run(args, capture_output=True, text=True, cwd=cwd,
                         env=dict(os.environ, OMP_NUM_THREADS="1"))
    if run.returncode != 0:
        sys.exit(f"{' '.join(args)} failed ({run.returncode}):\n{run.stderr[-3000:]}")
    return json.loads(run.stdout[run.stdout.index("{"):])


def value(summary, key):
    entry = summary["values"][key]
    return entry["value"] if isinstance(entry, dict) else entry


def column(summary, table, name):
    data = summary["tables"][table]
    index = data["columns"].index(name)
    return [row[index] for row in data["rows"]]


def require_ccx():
    if shutil.which("ccx") is None:
        sys.exit("ccx (CalculiX) not found: install it with `bash .ci/install-deps` "
                 "(Debian package calculix-ccx)")


class Checks:
    """Collects checks; `done()` exits non-zero when one failed."""

    def __init__(self, name):
        self.name, self.failed, self.count = name, 0, 0

    def near(self, label, measured, reference, tolerance, relative=True):
        self.count += 1
        if relative:
            deviation = measured / reference - 1.
            text = f"{deviation * 100:+.4f} % (tolerance ±{tolerance * 100:.4g} %)"
        else:
            deviation = measured - reference
            text = f"{deviation:+.5g} (tolerance ±{tolerance:.4g})"
        ok = abs(deviation) <= tolerance
        self.failed += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {label}: {measured:.8g} against {reference:.8g}: {text}")
        return deviation

    def holds(self, label, condition):
        self.count += 1
        self.failed += not condition
        print(f"{'ok  ' if condition else 'FAIL'} {label}")

    def done(self):
        if self.failed:
            sys.exit(f"{self.name}: {self.failed} of {self.count} checks failed")
        print(f"{self.name}: all {self.count} checks passed")
