"""Unit tests of the benchmark suite's own logic (no benchmark is run): the
scaling pass backs each run's memory first (BENCHMARKS.md, item 48)."""
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_benchmarks as rb  # noqa: E402


def osm_entry(family, n, triangles, peak):
    first = {"status": "ok", "out_triangles": triangles}
    if peak is not None:
        first["process_maxrss"] = peak
    return {"tool": "osm", "class": family, "n": n, "input": "%s:%d:1" % (family, n),
            "name": "%s %d" % (family, n), "first": first, "seconds": [1.0], "cpu": [1.0]}


class Args:
    timeout = 10


class ScalingPassBacksMemory(unittest.TestCase):
    def setUp(self):
        self.saved = (rb.back_memory, rb.run_once, rb.SCALING_ROUNDS)
        self.calls = []

        def back(nbytes):
            self.calls.append(("back", nbytes))
            return nbytes

        def run(exe, spec, args, timeout):
            self.calls.append(("run", spec))
            return {"status": "ok", "out_triangles": self.triangles[spec],
                    "cpu_seconds": 2.0, "system_seconds": 0.1}

        rb.back_memory, rb.run_once, rb.SCALING_ROUNDS = back, run, 1

    def tearDown(self):
        rb.back_memory, rb.run_once, rb.SCALING_ROUNDS = self.saved

    def test_each_run_follows_touching_its_size_peak_times_the_factor(self):
        results = [osm_entry("points", 10000, 90000, 20 << 20),
                   osm_entry("points", 1000000, 9000000, 800 << 20)]
        self.triangles = {e["input"]: e["first"]["out_triangles"] for e in results}
        data = rb.run_scaling_pass("bench_osm", results, Args())
        self.assertEqual(self.calls, [
            ("back", rb.WARM_FACTOR * (20 << 20)), ("run", "points:10000:1"),
            ("back", rb.WARM_FACTOR * (800 << 20)), ("run", "points:1000000:1")])
        self.assertEqual([r["warmed"] for r in data["runs"]],
                         [[rb.WARM_FACTOR * (20 << 20)], [rb.WARM_FACTOR * (800 << 20)]])
        self.assertEqual(rb.warmed_text({"scaling_pass": data}),
                         "In this suite run: 2 of the pass's 2 runs, 3,200 MiB at most.")

    def test_a_size_without_a_recorded_peak_touches_nothing(self):
        results = [osm_entry("spread", 1000, 40000, None),
                   osm_entry("spread", 3000, 120000, None)]
        self.assertEqual([x[2] for x in rb.scaling_specs(results)["spread"]], [0, 0])


class BackMemory(unittest.TestCase):
    def setUp(self):
        self.saved = rb.available_bytes

    def tearDown(self):
        rb.available_bytes = self.saved

    def test_leaves_two_gibibytes_free(self):
        rb.available_bytes = lambda: (2 << 30) + (8 << 20)
        self.assertEqual(rb.back_memory(1 << 40), 8 << 20)
        rb.available_bytes = lambda: 1 << 30
        self.assertEqual(rb.back_memory(64 << 20), 0)

    def test_touches_what_is_asked_when_there_is_room(self):
        rb.available_bytes = lambda: 4 << 30
        self.assertEqual(rb.back_memory(4 << 20), 4 << 20)
        self.assertEqual(rb.back_memory(0), 0)


class WarmedText(unittest.TestCase):
    def test_older_results_say_they_predate_it(self):
        data = {"scaling_pass": {"runs": [{"cpu": [1.0]}]}}
        self.assertEqual(rb.warmed_text(data), "The runs of this report predate it.")
        self.assertEqual(rb.warmed_text({}), "The runs of this report predate it.")


if __name__ == "__main__":
    unittest.main()
