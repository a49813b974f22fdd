#!/usr/bin/env python3
"""Speed of the train model (issue 15) on the bi-planetary train, through `gearstiff dynamics`.

    python3 bench/dynamics_train_bench.py [path/to/gearstiff]   (default: build/app/gearstiff)

Targets: 200 000 RK4 steps of the bi-planetary train (bench/dynamics_biplanetary.prm, 17 DOF,
24 mesh copies) in at most 0.2 s; a 100-point speed sweep in at most 20 s on one core. Prints
the median of three runs of each (processor time of the integration / of the sweep) and its
ratio to the target. Run it holding the build lock on a shared machine.
"""
import os

from gearstiff_cli import median_value, root

prm = os.path.join(root, "bench", "dynamics_biplanetary.prm")


def median_of_three(key, *settings):
    return median_value(3, key, "dynamics", prm, *settings)


# 200 000 steps at 1 µs (below the RK4 limit printed with it); K_v over the last 10 ms only.
steps = ["Simulation/time step=1", "Simulation/simulated time=0.2",
         "Simulation/steady state start=0.19", "Simulation/output interval=1000000"]
cpu, values = median_of_three("integration_cpu_time", *steps)
print(f"RK4 200000 steps, {values['steps']['value']:.0f} steps: {cpu:.1f} ms "
      f"(target 200 ms, ratio {cpu / 200:.2f}); RK4 limit {values['rk4_step_limit']['value']:.3g} µs")

sweep = ["Speed sweep/points=100", "Speed sweep/minimum speed=100",
         "Speed sweep/maximum speed=3000"]
seconds, values = median_of_three("sweep_time", *sweep)
print(f"100-point sweep: {seconds:.2f} s wall (target 20 s, ratio {seconds / 20:.2f}), "
      f"{values['sweep_steps']['value']:.0f} steps, "
      f"{values['sweep_unstable']['value']:.0f} diverged, "
      f"{values['sweep_contact_loss']['value']:.0f} contact loss")
