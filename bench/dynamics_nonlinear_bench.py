#!/usr/bin/env python3
"""Speed figures of the nonlinear mesh model (issue 29), through `gearstiff dynamics --json`.

    python3 bench/dynamics_nonlinear_bench.py [path/to/gearstiff]   (default: build/app/gearstiff)

Targets from the issue: a 100-speed up-and-down sweep of the split path with nonlinear meshes
in at most 30 s on one core; 200 000 RK4 steps with switching (separation and re-contact
located every mesh period) in at most 0.5 s. Each figure is the median of three runs of the
command's own measurement (sweep_time: wall clock of the sweep; integration_cpu_time: processor
time of the integration). On a shared machine run it when the cores are idle.
"""
import json
import os
import resource
import statistics
import subprocess
import sys

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
binary = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build", "app", "gearstiff")


def run(*settings):
    """The command's values, and the processor time (user + system) of the whole process."""
    args = [binary, "dynamics", "--json", "--set", "Simulation/mesh model=nonlinear"]
    for s in settings:
        args += ["--set", s]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    values = json.loads(out)["values"]
    values["process_cpu_time"] = {"value": cpu}
    return values


def value(values, key):
    return values[key]["value"] if key in values else float("nan")


# 200 000 steps with switching: the split path with its wheels in phase (placement 120°) at
# 27 000 rpm separates every mesh period (the linear model reports contact loss there);
# 1 s simulated at 5 µs.
cpu, wall = [], []
for _ in range(3):
    v = run("Train/input speed=27000", "Mesh 2/placement angle=120", "Speed sweep/points=0",
            "Simulation/simulated time=1", "Simulation/steady state start=0.99",
            "Simulation/output interval=1000000")
    cpu.append(value(v, "integration_cpu_time") / 1e3)
    wall.append(value(v, "integration_time") / 1e3)
print(f"200 000 steps with switching ({value(v, 'steps'):.0f} steps, "
      f"{value(v, 'located_switches'):.0f} located switches, mesh 1 separation fraction "
      f"{value(v, 'mesh1_separation_fraction'):.3f}): CPU median {statistics.median(cpu):.3f} s "
      f"(runs {', '.join(f'{c:.3f}' for c in cpu)}), wall median {statistics.median(wall):.3f} s;"
      f" target 0.5 s -> ratio {statistics.median(cpu) / 0.5:.2f}")

# 100-speed up-and-down sweep (200 runs) through the range where the in-phase meshes separate.
# The process is single-threaded, so its processor time is the one-core cost (the sweep's wall
# time is reported too; on a busy machine it is longer).
times, cpus = [], []
for _ in range(3):
    v = run("Speed sweep/points=100", "Speed sweep/direction=both", "Mesh 2/placement angle=120",
            "Speed sweep/minimum speed=500", "Speed sweep/maximum speed=45000")
    times.append(value(v, "sweep_time"))
    cpus.append(value(v, "process_cpu_time"))
print(f"100-speed up-and-down sweep ({value(v, 'sweep_steps'):.0f} steps in all, "
      f"{value(v, 'sweep_separating_speeds'):.0f} runs separating): process CPU median "
      f"{statistics.median(cpus):.2f} s (runs {', '.join(f'{t:.2f}' for t in cpus)}), sweep wall "
      f"median {statistics.median(times):.2f} s (runs {', '.join(f'{t:.2f}' for t in times)}); "
      f"target 30 s on one core -> ratio {statistics.median(cpus) / 30:.2f}")
print(f"  load average now: {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
