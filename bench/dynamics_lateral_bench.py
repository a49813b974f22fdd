#!/usr/bin/env python3
"""Speed of the lateral-torsional stage model (issue 30) through `gearstiff dynamics`.

    python3 bench/dynamics_lateral_bench.py [path/to/gearstiff]   (default: build/app/gearstiff)

Targets: the modes (with their classification and energies) of a 6-planet stage in at most
10 ms; 200 000 RK4 steps of the 3-planet stage in at most 0.5 s. Also timed (no target): a
20-speed sweep up and down of the 4-planet stage with the nonlinear mesh law and Cai k(x). The stage is Lin & Parker's
example system (tests/dynamics/cli/lateral_lin_parker.prm). Prints the median of five runs of
each (wall time reported by the command) and its ratio to the target. Run it holding the build
lock on a shared machine.
"""
import os

from gearstiff_cli import median_value, root

prm = os.path.join(root, "tests", "dynamics", "cli", "lateral_lin_parker.prm")


def median_of_five(key, *settings):
    return median_value(5, key, "dynamics", prm, *settings)


short = ["Simulation/simulated time=0.0001", "Simulation/time step=1", "Train/carrier radii=c: 120"]
ms, _ = median_of_five("modes_time", "Train/planets=p: c*6", *short)
print(f"modes of the 6-planet stage: {ms:.3f} ms (target 10 ms, ratio {ms / 10:.3f})")

steps = ["Train/planets=p: c*3", "Simulation/time step=1", "Simulation/simulated time=0.2"]
ms, values = median_of_five("integration_time", *steps)
print(f"RK4 {values['steps']['value']:.0f} steps of the 3-planet stage: {ms:.1f} ms "
      f"(target 500 ms, ratio {ms / 500:.3f}); RK4 limit {values['rk4_step_limit']['value']:.3g} µs")

# Speed sweep (issue 30): 20 speeds up and down, nonlinear meshes with Cai k(x), damped.
sweep = ["Speed sweep/points=20", "Speed sweep/minimum speed=200", "Speed sweep/maximum speed=4000",
         "Speed sweep/direction=both", "Simulation/mesh model=nonlinear",
         "Simulation/steady state start=0.02", "Simulation/time step=5",
         "Simulation/simulated time=0.001", "Train/bearing damping=s: 2000, r: 2000, c: 2000",
         "Train mesh 1/damping=1000", "Train mesh 2/damping=1000",
         "Train mesh 1/stiffness source=cai", "Train mesh 2/stiffness source=cai"]
seconds, values = median_value(3, "lateral_sweep_time", "dynamics", prm, *sweep)
print(f"sweep of 40 runs ({values['lateral_sweep_steps']['value']:.0f} RK4 steps) of the 4-planet "
      f"stage, nonlinear meshes: {seconds:.2f} s (median of 3, no target)")
