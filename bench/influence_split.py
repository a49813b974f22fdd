"""How an influence-coefficient sweep's time splits, from its `--json` reports (the model's own
values): FE body DoFs, scene, read/assembly/factorization, coefficients, all contact problems,
the sweep. usage: python3 bench/influence_split.py REPORT.json ..."""
import json
import sys

for name in sys.argv[1:]:
    values = json.load(open(name))["values"]
    g = lambda key: values[key]["value"]
    print("%s: %d DoFs, scene %.2f s, factorization %.2f s, coefficients %.2f s, contact %.4f s, "
          "sweep %.2f s" % (name, g("influence_fe_dofs"), g("influence_scene_time"),
                            g("influence_factorization_time"), g("influence_coefficient_time"),
                            g("influence_contact_time"), g("sweep_wall_time")))
