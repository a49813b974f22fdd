"""What the dynamics bench scripts share: run `gearstiff dynamics PRM --json` with settings and
take the median of a value over several runs.

    from gearstiff_bench import Bench
    bench = Bench(binary, prm)
    value, first_run_values = bench.median(3, "integration_time", "Simulation/time step=1")
"""
import json
import statistics
import subprocess


class Bench:
    def __init__(self, binary, prm):
        self.binary, self.prm = binary, prm

    def run(self, *settings):
        """The `values` of one run with `--set` for each setting."""
        args = [self.binary, "dynamics", self.prm, "--json"]
        for s in settings:
            args += ["--set", s]
        out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
        return json.loads(out[out.index("{"):])["values"]

    def median(self, runs, key, *settings):
        """Median of value `key` over `runs` runs, and the first run's values."""
        results = [self.run(*settings) for _ in range(runs)]
        return statistics.median(r[key]["value"] for r in results), results[0]
