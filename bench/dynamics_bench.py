#!/usr/bin/env python3
"""Speed figures of the dynamics module (issue 6), measured through `gearstiff dynamics --json`.

    python3 bench/dynamics_bench.py [path/to/gearstiff]     (default: build/app/gearstiff)

Targets from the issue: 1 s of simulated time at a 5 µs step (200 000 RK4 steps, 3 DOF) in
under 50 ms; a 100-point speed sweep in seconds. Also compares the three integrators on the
built-in split-path case (the same K_v window). Prints each figure and its ratio to the target.
The integration time is the command's own wall-clock measurement of the integrator (with the
trajectory stored at every step); on a shared machine run it when the cores are idle.
"""
import json
import os
import subprocess
import sys

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
binary = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build", "app", "gearstiff")


def run(*settings):
    args = [binary, "dynamics", "--json"]
    for s in settings:
        args += ["--set", s]
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    return json.loads(out)["values"]


def value(values, key):
    return values[key]["value"]


# 1 s at 5 µs with RK4, three repetitions each (best of three: the machine may be busy).
# "core": the integrator with K_v statistics over the last 10 ms and no stored trajectory;
# "full": K_v over the last 0.5 s with the spectrum series and a 20 µs trajectory kept.
cases = {
    "core": ["Simulation/steady state start=0.99", "Simulation/output interval=1000000"],
    "full": ["Simulation/steady state start=0.5"],
}
for name, extra in cases.items():
    wall, cpu = [], []
    for _ in range(3):
        v = run("Simulation/simulated time=1", "Speed sweep/points=0", *extra)
        wall.append(value(v, "integration_time"))
        cpu.append(value(v, "integration_cpu_time"))
    steps = value(v, "steps")
    print(f"RK4 {name}, 1 s simulated at 5 us, {steps:.0f} steps: wall {min(wall):.1f} ms, "
          f"CPU {min(cpu):.1f} ms ({min(cpu) * 1e6 / steps:.0f} ns/step); target 50 ms -> "
          f"ratio wall {min(wall) / 50:.2f}, CPU {min(cpu) / 50:.2f}")
print(f"  load average now: {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")

# 100-point sweep.
v = run("Speed sweep/points=100")
print(f"speed sweep, 100 points ({value(v, 'sweep_steps'):.0f} steps in all): "
      f"{value(v, 'sweep_time'):.2f} s; target 'seconds' (10 s) -> ratio "
      f"{value(v, 'sweep_time') / 10:.2f}; unstable speeds {value(v, 'sweep_unstable'):.0f}, "
      f"with contact loss {value(v, 'sweep_contact_loss'):.0f}")

# The three integrators on the built-in case.
print("integrators on the built-in case (same window):")
for integrator, extra in (("RK4", []), ("adaptive RK", ["Simulation/relative tolerance=1e-7"]),
                          ("HHT-alpha", ["Simulation/HHT alpha=0"])):
    v = run(f"Simulation/integrator={integrator}", "Speed sweep/points=0", *extra)
    print(f"  {integrator:12s} K_v max {value(v, 'kv_max'):.4f}  steps {value(v, 'steps'):8.0f}  "
          f"evaluations {value(v, 'function_evaluations'):8.0f}  "
          f"time {value(v, 'integration_time'):7.1f} ms")
