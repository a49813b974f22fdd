#!/usr/bin/env python3
"""Mesh stiffness k = T1/(r_b1²·Δφ) and transmission error of a gear-pair deck solved by CalculiX.

usage: tools/calculix_stiffness.py DECK_FOLDER [--json]

DECK_FOLDER is the -o folder of `gearstiff mesh --set "Mesh/format=inp"` after `ccx -i scene`
ran in it (docs/calculix.md): the pinion bore is a rigid body driven by the torque T1 on its
ROT NODE, whose rotation about z in the last increment of scene.dat is Δφ. T1 and r_b1 come from
the folder's summary.json (pinion_torque, pinion_base_radius), the ROT NODE from scene.inp.
`--set "Scene/gear pair defaults=stiffness"` makes the deck the scene `gearstiff stiffness`
solves, so the k printed here compares with `gearstiff stiffness --set "Finite
elements/Element degree=1"` (the element the deck's C3D8 slice reproduces).
The transmission error is r_b1·Δφ (the wheel held): the deck places the pair where unmodified
flanks touch, so with tooth modifications (issue 27; the deck carries the modified outline)
Δφ includes the roll that closes the designed separation, and r_b1·Δφ compares with the
`transmission_error` of `gearstiff stiffness` (r_b1·Δφ from first touch + the unloaded TE).
Prints `calculix k = X N/um, TE = Y um (T1 = ... N·m, r_b1 = ... mm, Δφ = ... µrad)`, or with
--json one object {"mesh_stiffness": N/µm, "transmission_error": µm, "pinion_rotation": rad,
"pinion_torque": N·m, "pinion_base_radius": mm}.
"""
import json
import os
import sys


def rotation_node(deck):
    """The ROT NODE of the deck's rigid body (the torque-driven pinion bore)."""
    node = None
    with open(deck) as f:
        for line in f:
            upper = line.strip().upper()
            if upper.startswith("*RIGID BODY") and "ROT NODE=" in upper:
                node = int(upper.split("ROT NODE=")[1].split(",")[0])
    if node is None:
        sys.exit(f"calculix_stiffness: {deck} has no *RIGID BODY with a ROT NODE")
    return node


def last_rotation(dat, rot):
    """Rotation about z of the ROT NODE in the last printed increment (rad)."""
    rotation, in_block = None, False
    with open(dat) as f:
        for line in f:
            if "displacements" in line:
                in_block = True
            elif in_block:
                parts = line.split()
                if len(parts) == 4 and parts[0].isdigit() and int(parts[0]) == rot:
                    rotation = float(parts[3])
    if rotation is None:
        sys.exit(f"calculix_stiffness: no rotation of node {rot} in {dat} (did ccx run?)")
    return rotation


def summary_value(summary, key):
    entry = summary.get("values", {}).get(key)
    if entry is not None:
        return entry["value"] if isinstance(entry, dict) else entry
    sys.exit(f"calculix_stiffness: summary.json has no '{key}' (a gear-pair deck of "
             "`gearstiff mesh`?)")


def main():
    arguments = [a for a in sys.argv[1:] if a != "--json"]
    if len(arguments) != 1:
        sys.exit(__doc__.strip().splitlines()[2])
    folder = arguments[0]
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    torque = summary_value(summary, "pinion_torque")  # N·m
    base_radius = summary_value(summary, "pinion_base_radius") * 1e-3  # m
    rotation = abs(last_rotation(os.path.join(folder, "scene.dat"),
                                 rotation_node(os.path.join(folder, "scene.inp"))))
    k = torque / (base_radius ** 2 * rotation) / 1e6  # N/µm
    te = base_radius * rotation * 1e6  # µm
    if "--json" in sys.argv[1:]:
        print(json.dumps({"mesh_stiffness": k, "transmission_error": te,
                          "pinion_rotation": rotation, "pinion_torque": torque,
                          "pinion_base_radius": base_radius * 1e3}))
    else:
        print(f"calculix k = {k:.6g} N/um, TE = {te:.6g} um (T1 = {torque:g} N·m, "
              f"r_b1 = {base_radius * 1e3:.6g} mm, Δφ = {rotation * 1e6:.6g} µrad)")


if __name__ == "__main__":
    main()
