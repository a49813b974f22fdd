#!/usr/bin/env python3
"""compare.py's own contract (issue 41): round-off of a zero result never fails a comparison, a
real change always does, and only the listed wall-clock fields are ignored.

The case: the stored regression output of `gearstiff contact` (tests/regression/contact.json),
whose reactions x and the tangential force are round-off of zero (~1e-11 N beside a 128.7 N
load; a fresh machine measured -2.27e-11 against the stored -2.37e-11 N, 1.79e-11 against
1.51e-11 N) and whose reaction torques are round-off of force x arm."""
import copy
import json
import os
import sys
import unittest

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
import compare  # noqa: E402


def load(case):
    with open(os.path.join(here, case + ".json")) as f:
        return json.load(f)


class Compare(unittest.TestCase):
    def setUp(self):
        self.stored = load("contact")
        self.actual = copy.deepcopy(self.stored)

    def set_value(self, key, value):
        self.actual["values"][key]["value"] = value

    def test_identical_agrees(self):
        self.assertEqual(compare.compare(self.stored, self.actual), [])

    def test_round_off_of_zero_forces_agrees(self):
        # The fresh machine's figures (issue 41), and round-off 100x larger still.
        self.set_value("support_lower bottom_force_x", -2.27e-11)
        self.set_value("tangential_force", 1.79e-11)
        self.set_value("support_upper top_force_x", 5e-9)
        self.set_value("support_lower bottom_torque", 3e-12)
        self.assertEqual(compare.compare(self.stored, self.actual), [])

    def test_real_change_fails(self):
        # A reaction of 1e-5 of the load is no round-off (the solver's relative scatter is
        # ~1e-12): the comparison must see it, and a 1e-5 relative change of the load itself.
        for key, value in (("support_lower bottom_force_x", 128.7e-5),
                           ("normal_force", 128.72918429 * (1 + 1e-5)),
                           ("max_pressure", 887.828739542 * (1 - 1e-5))):
            actual = copy.deepcopy(self.stored)
            actual["values"][key]["value"] = value
            diffs = compare.compare(self.stored, actual)
            self.assertEqual(len(diffs), 1, key)
            self.assertIn(key, diffs[0])

    def test_wall_clock_ignored_by_name_only(self):
        self.set_value("time_total", 123.)
        self.set_value("mpi_ranks", 4)
        self.assertEqual(compare.compare(self.stored, self.actual), [])

    def test_results_named_like_timings_are_compared(self):
        # `decay_time`, `time_step`, `kv_max_time`, `..._times_width` are results.
        for case, key in (("dynamics", "decay_time"), ("dynamics", "time_step"),
                          ("gear_pair", "iso_single_stiffness_times_width"),
                          ("gear_pair", "iso_mesh_stiffness_alpha_times_width")):
            stored = load(case)
            actual = copy.deepcopy(stored)
            actual["values"][key]["value"] *= 1.001
            diffs = compare.compare(stored, actual)
            self.assertEqual(len(diffs), 1, f"{case}: {key}")
        stored = load("dynamics")
        actual = copy.deepcopy(stored)
        table = actual["tables"]["dynamics_meshes"]
        column = table["columns"].index("kv_max_time")
        table["rows"][0][column] = table["rows"][0][column] * 1.001 + 1e-3
        self.assertEqual(len(compare.compare(stored, actual)), 1)

    def test_every_stored_case_agrees_with_itself(self):
        for name in sorted(os.listdir(here)):
            if name.endswith(".json"):
                case = load(name[:-5])
                self.assertEqual(compare.compare(case, copy.deepcopy(case)), [], name)


if __name__ == "__main__":
    unittest.main()
