#!/usr/bin/env python3
"""tools/run.sh, the README's first command, builds only what the run needs: the `gearstiff`
command (the chart scripts are Python; the tests and the Python module are tools/test.sh's).

usage: run_script_targets.py SOURCE_DIR WORK_DIR

Runs a copy of tools/run.sh in WORK_DIR with stand-ins: .ci/install-deps does nothing, `cmake`
on PATH records its arguments, build/app/gearstiff records its own. Passes when every
`cmake --build` names --target gearstiff and nothing else (before: a bare `cmake --build build`
built all 56 test executables and the module too), and the run is `gearstiff run -o results`.
"""
import os
import shutil
import stat
import subprocess
import sys


def executable(path, text):
    with open(path, "w") as f:
        f.write(text)
    os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)


def main():
    source, work = sys.argv[1:3]
    shutil.rmtree(work, ignore_errors=True)
    for folder in ("tools", ".ci", "bin", "build/app"):
        os.makedirs(os.path.join(work, folder))
    shutil.copy(os.path.join(source, "tools", "run.sh"), os.path.join(work, "tools", "run.sh"))
    log = os.path.join(work, "calls.log")
    executable(os.path.join(work, ".ci", "install-deps"), "#!/bin/sh\nexit 0\n")
    executable(os.path.join(work, "bin", "cmake"), f'#!/bin/sh\necho "cmake $*" >> {log}\n')
    executable(os.path.join(work, "build", "app", "gearstiff"),
               f'#!/bin/sh\necho "gearstiff $*" >> {log}\n')
    environment = dict(os.environ, PATH=os.path.join(work, "bin") + ":" + os.environ["PATH"])
    done = subprocess.run(["bash", os.path.join(work, "tools", "run.sh")], env=environment,
                          capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"FAILED: tools/run.sh exited {done.returncode}: {done.stderr}")
    with open(log) as f:
        calls = f.read().splitlines()
    builds = [c for c in calls if c.startswith("cmake --build")]
    failures = []
    if not builds:
        failures.append("tools/run.sh builds nothing")
    for call in builds:
        words = call.split()
        targets = [words[i + 1] for i, w in enumerate(words) if w == "--target"]
        if targets != ["gearstiff"]:
            failures.append(f"'{call}' builds {targets or 'every target'}, not only gearstiff")
    if "gearstiff run -o results" not in calls:
        failures.append(f"the run is not `gearstiff run -o results`: {calls}")
    for f in failures:
        print("FAIL " + f)
    if not failures:
        print("tools/run.sh: " + "; ".join(calls))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
