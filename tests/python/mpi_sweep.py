"""`mpirun -np 2 python3 mpi_sweep.py`: a stiffness sweep called from Python on two ranks.

Every rank calls gearstiff.stiffness with the same parameters (as every rank of
`mpirun -np 2 gearstiff stiffness` runs the command); the sweep's positions are shared by the
ranks (fem::distribute_items) and every rank returns the whole result. Checks: both ranks took
positions (the table's `rank` column, `sweep_ranks` = 2), both return the same table, and the
stiffness of every position equals the serial command line's (expected.json, written by the same
script started without mpirun, which then launches itself under mpirun). Tolerance 1e-9
relative: each position is the same one-rank solve on either path, so only the summation order
inside MUMPS could differ.
"""
import json
import os
import subprocess
import sys
import tempfile

PARAMETERS = {
    "Mesh": {"contact size": 0.2, "fine radius": 0.5, "body size": 1, "rim size": 3},
    "Finite elements": {"Element degree": 1},
    "Stiffness": {"mode": "sweep", "sweep positions": 5, "published reference": False},
}


def settings(tree, prefix=""):
    for key, value in tree.items():
        if isinstance(value, dict):
            yield from settings(value, prefix + key + "/")
        elif isinstance(value, bool):
            yield f"{prefix}{key}={'true' if value else 'false'}"
        else:
            yield f"{prefix}{key}={value}"


def driver():
    """Without mpirun: the serial command line's result, then this script on two ranks."""
    executable = os.environ["GEARSTIFF_EXECUTABLE"]
    arguments = [executable, "stiffness", "--json"]
    for s in settings(PARAMETERS):
        arguments += ["--set", s]
    serial = subprocess.run(arguments, capture_output=True, text=True, check=True).stdout
    with tempfile.TemporaryDirectory() as work:
        expected = os.path.join(work, "expected.json")
        with open(expected, "w") as f:
            f.write(serial)
        mpirun = [os.environ.get("GEARSTIFF_MPIEXEC", "mpirun"), "--allow-run-as-root", "--oversubscribe", "--bind-to", "none",
                  "-np", "2", sys.executable, __file__, expected]
        return subprocess.run(mpirun).returncode


def rank_part(expected_file):
    import numpy as np
    import gearstiff

    rank, size = gearstiff.mpi_rank(), gearstiff.mpi_size()
    assert size == 2, f"expected 2 ranks, got {size}"
    result = gearstiff.stiffness(PARAMETERS)
    table = result["tables"]["stiffness_sweep"]["data"]
    assert result["values"]["sweep_ranks"]["value"] == 2
    assert set(table["rank"]) == {0.0, 1.0}, f"positions per rank: {table['rank']}"

    with open(expected_file) as f:
        serial = json.load(f)["tables"]["stiffness_sweep"]
    column = serial["columns"].index("stiffness")
    expected = np.array([row[column] for row in serial["rows"]])
    np.testing.assert_allclose(table["stiffness"], expected, rtol=1e-9)
    print(f"rank {rank}: {len(expected)} positions, ranks {sorted(set(table['rank']))}: "
          "same as the serial command line", flush=True)
    return 0


if __name__ == "__main__":
    if "OMPI_COMM_WORLD_SIZE" in os.environ:
        sys.exit(rank_part(sys.argv[1]))
    sys.exit(driver())
