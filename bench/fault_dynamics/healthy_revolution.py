#!/usr/bin/python3
"""The healthy counterpart of a `gearstiff faults` summary (docs/faults.md "Dynamics with the
faulty table"): the same revolution table with every row replaced by the healthy pitch of the
same run (fault_sweep's healthy_stiffness at the same offset, which `faults` repeats over the
healthy pitches) and no row without contact. So the healthy and the faulty dynamics run the same
table format, period and window.

    /usr/bin/python3 bench/fault_dynamics/healthy_revolution.py faults.json healthy.json
"""
import json
import sys


def main(source, target):
    with open(source) as f:
        summary = json.load(f)
    sweep = summary["tables"]["fault_sweep"]
    healthy = [row[sweep["columns"].index("healthy_stiffness")] for row in sweep["rows"]]
    table = summary["tables"]["revolution_stiffness"]
    columns = table["columns"]
    per_pitch = round(1.0 / (2.0 * table["rows"][0][columns.index("mesh_position")]))
    for i, row in enumerate(table["rows"]):
        row[columns.index("stiffness")] = healthy[i % per_pitch]
        row[columns.index("lost_contact")] = 0
    summary["text"]["healthy revolution"] = (
        "made by bench/fault_dynamics/healthy_revolution.py from " + source +
        ": the healthy pitch repeated over the revolution")
    with open(target, "w") as f:
        json.dump(summary, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
