"""Unit tests of the benchmark suite's own logic (no benchmark is run): the
scaling pass backs each run's memory first (BENCHMARKS.md, item 48); the
repeated-calls pass times the core and Mesh_2 after unmeasured calls in one
process (item 49)."""
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


def real_entry(tool, name, cpu, status="ok"):
    return {"tool": tool, "class": "real", "n": None, "input": "/data/%s.poly" % name,
            "name": "%s.poly" % name, "first": {"status": status, "out_triangles": 100},
            "seconds": [cpu] * 3, "cpu": [cpu] * 3}


class PairedRatios(unittest.TestCase):
    def test_each_long_run_against_the_runs_on_both_sides(self):
        v = {"cpu": [40.0, 60.0], "paired_bracketed": True,
             "paired_osm_runs": [[1.0, 1.0], [0.6, 0.6], [1.4, None]]}
        # Run 0 lies between the sets 0 and 1 (mean 0.8); run 1 between 1
        # and 2, which has a failed run: not counted.
        self.assertEqual(rb.paired_ratios(v), [50.0])

    def test_older_results_pair_the_runs_right_after(self):
        v = {"cpu": [40.0, 60.0], "paired_osm_cpu": [0.8, 1.2]}
        self.assertEqual(rb.paired_ratios(v), [50.0, 50.0])


class RepeatPass(unittest.TestCase):
    def setUp(self):
        self.saved = rb.run_once
        self.calls = []

        def run(exe, spec, args, timeout):
            self.calls.append((exe, spec, list(args)))
            # Calls this short are timed by their wall time (the CPU clock is coarse).
            wall = {"bench_osm": 0.002, "bench_cgal_mesh2": 0.001}[exe]
            return {"status": "ok", "cpu_seconds": 1e-6, "seconds": wall,
                    "warm_calls": int(args[args.index("--warm") + 1])}

        rb.run_once = run
        self.results = [
            real_entry("osm", "small", 0.004), real_entry("cgal-mesh2", "small", 0.002),
            real_entry("osm", "large", 0.5), real_entry("cgal-mesh2", "large", 0.9),
            real_entry("osm", "nomesh2", 0.004), real_entry("cgal-mesh2", "nomesh2", 120,
                                                             "timeout"),
            osm_entry("points", 1000, 9000, None)]

    def tearDown(self):
        rb.run_once = self.saved

    def test_only_real_inputs_both_tools_mesh_quickly(self):
        self.assertEqual(rb.repeat_specs(self.results), [("/data/small.poly", "small.poly")])

    def test_alternates_the_tools_each_warmed_up_in_its_process(self):
        found = {"osm": "bench_osm", "cgal-mesh2": "bench_cgal_mesh2"}
        data = rb.run_repeat_pass(found, self.results, Args())
        warm = ["--no-check", "--warm", str(rb.REPEAT_WARMUP)]
        self.assertEqual(self.calls, [("bench_osm", "/data/small.poly", warm),
                                      ("bench_cgal_mesh2", "/data/small.poly", warm)]
                         * rb.REPEAT_RUNS)
        self.assertEqual(data["runs"][0]["seconds"]["osm"], [0.002] * rb.REPEAT_RUNS)

    def test_reports_the_repeated_and_the_fresh_ratios(self):
        found = {"osm": "bench_osm", "cgal-mesh2": "bench_cgal_mesh2"}
        data = {"results": self.results,
                "repeat_pass": rb.run_repeat_pass(found, self.results, Args())}
        self.assertEqual(rb.repeat_rows(data), [("small.poly", 0.002, 0.001, 0.5, 0.5)])
        self.assertEqual(rb.repeat_summary(data),
                         "in one process after 10 calls, on the 1 inputs both mesh in under "
                         "0.1 s: faster on 0 of 1 (0 of 1 as fresh processes)")
        self.assertIn("| small.poly | 2 | 1 | 0.5 | 0.5 |", rb.repeat_text(data))

    def test_a_run_that_did_not_warm_up_is_not_counted(self):
        rb.run_once = lambda exe, spec, args, timeout: {"status": "ok", "cpu_seconds": 1.0,
                                                        "seconds": 1.0}
        data = rb.run_repeat_pass({"osm": "a", "cgal-mesh2": "b"}, self.results, Args())
        self.assertEqual(data["runs"][0]["cpu"], {"osm": [], "cgal-mesh2": []})
        self.assertEqual(rb.repeat_rows({"results": self.results, "repeat_pass": data}), [])

    def test_long_calls_are_timed_by_their_median_cpu_time(self):
        data = {"results": self.results, "repeat_pass": {"warmup": 10, "runs": [
            {"input": "/data/small.poly", "name": "small.poly",
             "cpu": {"osm": [0.2, 0.3, 0.4], "cgal-mesh2": [0.6, 0.6, 0.6]},
             "seconds": {"osm": [0.1, 0.5, 0.5], "cgal-mesh2": [0.7, 0.7, 0.7]}}]}}
        self.assertEqual(rb.repeat_rows(data), [("small.poly", 0.3, 0.6, 2.0, 0.5)])

    def test_without_mesh2_or_older_results_it_says_so(self):
        self.assertIsNone(rb.run_repeat_pass({"osm": "bench_osm"}, self.results, Args()))
        self.assertEqual(self.calls, [])
        self.assertIsNone(rb.repeat_summary({"results": self.results}))
        self.assertTrue(rb.repeat_text({"results": self.results}).startswith("Not run"))


if __name__ == "__main__":
    unittest.main()
