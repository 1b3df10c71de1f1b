"""Unit tests of size_bound.py's own logic (no benchmark is run): the extent
of a .poly, the tools taking turns, and the table row of a failed tool."""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import size_bound as sb  # noqa: E402


class Extent(unittest.TestCase):
    def test_poly_with_comments_and_a_node_beside_it(self):
        with tempfile.TemporaryDirectory() as d:
            poly = os.path.join(d, "a.poly")
            with open(poly, "w") as f:
                f.write("# a comment\n3 2 0 0\n1 0 0 # first\n2 4 1\n3 1 -2\n0 0\n0\n")
            self.assertEqual(sb.extent(poly), 4.0)
            with open(poly, "w") as f:
                f.write("0 2 0 0\n0 0\n0\n")
            with open(os.path.join(d, "a.node"), "w") as f:
                f.write("2 2 0 0\n1 0 0\n2 1 7\n")
            self.assertEqual(sb.extent(poly), 7.0)


class Turns(unittest.TestCase):
    def test_tools_alternate_and_a_failed_one_is_not_run_again(self):
        calls = []

        def run(exe, path, bound, timeout):
            calls.append(os.path.basename(exe))
            if exe.endswith("mesh2"):
                return {"ok": False, "error": "no mesh after 1 s"}
            return {"ok": True, "cpu_seconds": 0.5, "out_triangles": 10, "max_angle": 150.0,
                    "missing_segments": 0}

        res = sb.measure("/b", "x.poly", 0.1, 3, 1, run)
        self.assertEqual(calls, ["bench_osm", "bench_cgal_mesh2", "bench_osm", "bench_osm"])
        osm, mesh2 = sb.summary(res["OSM"]), sb.summary(res["Mesh_2"])
        self.assertEqual(osm["cpu"], 0.5)
        self.assertEqual(mesh2, {"error": "no mesh after 1 s"})
        row = sb.row("x.poly", osm, mesh2)
        self.assertIn("| Mesh_2: no mesh after 1 s |", row)
        self.assertIn("| 10 | — | — |", row)
        self.assertIn("| 0, — |", row)

    def test_both_failures_are_shown(self):
        row = sb.row("z", {"error": "crash"}, {"error": "no mesh after 1 s"})
        self.assertIn("| OSM: crash; Mesh_2: no mesh after 1 s |", row)

    def test_ratio_favours_the_faster(self):
        osm = {"cpu": 0.5, "triangles": 1000, "max_angle": 140.0, "missing": 0}
        mesh2 = {"cpu": 2.0, "triangles": 900, "max_angle": 120.0, "missing": 0}
        self.assertIn("| 0.500 | 2.000 | 4.00 | 1,000 | 900 | 1.11 |", sb.row("y", osm, mesh2))


if __name__ == "__main__":
    unittest.main()
