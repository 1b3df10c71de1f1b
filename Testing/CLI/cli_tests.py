#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
# Copyright (c) 2026, the Overlay Stitch Meshing authors
"""Tests of osm-mesh, the command-line tool, run by CTest (label cli).

    cli_tests.py GROUP --cli osm-mesh --helper osm_cli_helper --data DIR
                 --shared DIR --out DIR

GROUP is one of: help, options, formats, inputs, errors, determinism,
reference, realdata, matrix (the bad-input matrix of issue 6). Every check prints "ok" or "FAIL"; the exit status is 1
if any check failed, 77 (CTest's skip) when the group's data is absent.
Plain Python 3, no third-party module.
"""
import argparse
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

ARGS = None
FAILURES = []


def check(condition, what, detail=""):
    if condition:
        print("ok   " + what)
    else:
        FAILURES.append(what)
        print("FAIL " + what + (": " + detail if detail else ""))
    return condition


def data(name):
    return os.path.join(ARGS.data, name)


def out(name):
    return os.path.join(ARGS.out, name)


def run(*args, timeout=600):
    p = subprocess.run([ARGS.cli] + [str(a) for a in args], capture_output=True,
                       text=True, timeout=timeout)
    return p


def mesh_ok(*args, what=None):
    """Runs osm-mesh, expecting success and no error line."""
    p = run(*args)
    what = what or "osm-mesh " + " ".join(str(a) for a in args)
    errors = [l for l in p.stderr.splitlines() if not l.startswith("osm-mesh: warning: ")]
    check(p.returncode == 0 and not errors, what + " succeeds",
          "status %d, stderr %r" % (p.returncode, p.stderr[-500:]))
    return p


def expect_error(args, status, fragments, what):
    """Runs osm-mesh, expecting failure with one line 'osm-mesh: <reason>'."""
    p = run(*args)
    lines = p.stderr.splitlines()
    check(p.returncode == status, what + ": exit status %d" % status,
          "got %d, stderr %r" % (p.returncode, p.stderr))
    errors = [l for l in lines if not l.startswith("osm-mesh: warning: ")]
    check(len(errors) == 1 and errors[0].startswith("osm-mesh: "),
          what + ": one line 'osm-mesh: ...' on stderr", repr(p.stderr))
    for fragment in fragments:
        check(fragment in p.stderr, what + ": message names %r" % fragment, repr(p.stderr))
    check(p.stdout == "", what + ": nothing on stdout", repr(p.stdout[:200]))
    return p


def validate(input_path, mesh_path, *extra, what=None):
    p = subprocess.run([ARGS.helper, "validate", input_path, mesh_path] + list(extra),
                       capture_output=True, text=True, timeout=600)
    check(p.returncode == 0, what or "validate %s against %s" % (
        os.path.basename(mesh_path), os.path.basename(input_path)),
          (p.stdout + p.stderr)[-800:])
    return p.stdout


def stats_of(*args):
    p = mesh_ok(*(list(args) + ["--stats"]))
    try:
        return json.loads(p.stdout)
    except ValueError as e:
        check(False, "--stats prints JSON", str(e) + ": " + p.stdout[:300])
        return {}


def read_triangle_files(base):
    """Parses base.node/.ele/.edge as osm-mesh writes them; checks the format.
    The files count from the input's first index (0 or 1, as Triangle's do);
    the indices returned count from 1."""
    def rows(path):
        with open(path) as f:
            return [l.split() for l in f if l.strip() and not l.lstrip().startswith("#")]

    name = os.path.basename(base)
    node = rows(base + ".node")
    n, dim, nattr, nmark = (int(x) for x in node[0])
    check(dim == 2 and nmark == 1 and len(node) == n + 1 and
          all(len(r) == 4 + nattr for r in node[1:]),
          "%s.node: header '%d 2 %d 1' and %d vertex lines" % (name, n, nattr, n))
    first = int(node[1][0]) if n else 1
    check(first in (0, 1) and [int(r[0]) for r in node[1:]] == list(range(first, n + first)),
          "%s.node: vertices numbered %d..%d" % (name, first, n + first - 1))
    vertices = [(float(r[1]), float(r[2])) for r in node[1:]]
    shift = 1 - first

    ele = rows(base + ".ele")
    t, corners, eattr = (int(x) for x in ele[0])
    check(corners == 3 and len(ele) == t + 1 and all(len(r) == 4 + eattr for r in ele[1:]),
          "%s.ele: header '%d 3 %d' and %d triangle lines" % (name, t, eattr, t))
    check([int(r[0]) for r in ele[1:]] == list(range(first, t + first)),
          "%s.ele: triangles numbered %d..%d" % (name, first, t + first - 1))
    triangles = [tuple(int(x) + shift for x in r[1:4]) for r in ele[1:]]
    check(all(1 <= v <= n for tri in triangles for v in tri),
          "%s.ele: corners are vertex numbers in %d..%d" % (name, first, n + first - 1))

    edge = rows(base + ".edge")
    e, emark = (int(x) for x in edge[0])
    check(emark == 1 and len(edge) == e + 1,
          "%s.edge: header '%d 1' and %d edge lines" % (name, e, e))
    check([int(r[0]) for r in edge[1:]] == list(range(first, e + first)),
          "%s.edge: edges numbered %d..%d" % (name, first, e + first - 1))
    edges = [(int(r[1]) + shift, int(r[2]) + shift, int(r[3])) for r in edge[1:]]
    check(all(1 <= a <= n and 1 <= b <= n for a, b, _ in edges),
          "%s.edge: endpoints are vertex numbers" % name)
    # Euler: every edge of the triangles is listed once.
    mesh_edges = set()
    for a, b, c in triangles:
        for u, v in ((a, b), (b, c), (c, a)):
            mesh_edges.add((min(u, v), max(u, v)))
    check(mesh_edges == set((min(a, b), max(a, b)) for a, b, _ in edges),
          "%s.edge: exactly the edges of the triangles" % os.path.basename(base))
    # (Not where base.poly is the input, which osm-mesh leaves as it is.)
    if os.path.exists(base + ".poly") and open(base + ".poly").readline().startswith(
            "# the mesh's input subsegments"):
        poly_segments_ok(base, first, triangles, edges)
    return vertices, triangles, edges


def poly_segments_ok(base, first, triangles, edges):
    """base.poly as Triangle's -p writes it: no vertices (base.node's), then
    the mesh's input subsegments and boundary edges with .edge's markers."""
    name = os.path.basename(base)
    with open(base + ".poly") as f:
        rows = [l.split() for l in f if l.strip() and not l.lstrip().startswith("#")]
    check(rows[0] == ["0", "2", "0", "1"], "%s.poly: header '0 2 0 1' (vertices in the .node)" % name)
    s = int(rows[1][0])
    segments = [(int(r[1]) + 1 - first, int(r[2]) + 1 - first, int(r[3])) for r in rows[2:2 + s]]
    check([int(r[0]) for r in rows[2:2 + s]] == list(range(first, s + first)),
          "%s.poly: segments numbered %d..%d" % (name, first, s + first - 1))
    marker = {(min(a, b), max(a, b)): m for a, b, m in edges}
    count = {}
    for tri in triangles:
        for u, v in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
            key = (min(u, v), max(u, v))
            count[key] = count.get(key, 0) + 1
    listed = set((min(a, b), max(a, b)) for a, b, _ in segments)
    check(all(marker.get((min(a, b), max(a, b))) == m for a, b, m in segments),
          "%s.poly: every segment is a mesh edge, with its .edge marker" % name)
    check(all(k in listed for k, c in count.items() if c == 1),
          "%s.poly: every boundary edge is a segment" % name)
    holes = int(rows[2 + s][0])
    check(len(rows) >= 3 + s + holes, "%s.poly: %d hole lines" % (name, holes))
    return segments


def array_names(path, section):
    """The names of the arrays in a VTK XML file's PointData or CellData."""
    header = read_bytes(path).split(b"<AppendedData")[0]
    part = header.split(b"<" + section.encode())[1].split(b"</" + section.encode() + b">")[0]
    return set(n.decode() for n in re.findall(b'Name="([^"]+)"', part))


def area(vertices, tri):
    (ax, ay), (bx, by), (cx, cy) = (vertices[v - 1] for v in tri)
    return 0.5 * ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))


def total_area(vertices, triangles):
    return sum(area(vertices, t) for t in triangles)


def read_bytes(path):
    with open(path, "rb") as f:
        return f.read()


# ---------------------------------------------------------------- groups

def group_help():
    for flag in ("--help", "-h"):
        p = run(flag)
        check(p.returncode == 0 and p.stdout.startswith("Usage: osm-mesh INPUT"),
              flag + " prints the usage on stdout, exit 0", p.stdout[:100] + p.stderr)
        for option in ("-o", "--domain", "--min-angle", "--gamma", "--max-edge", "--no-resolve",
                       "--merge-tolerance", "--max-steiner", "--project-xy", "--region-areas",
                       "--gap-ratio", "--no-point-data", "--stats", "--svg", "--version"):
            check(option in p.stdout, flag + " documents " + option)
    # The --gamma range it prints is accepted at both ends (found by a user
    # review: 0.8717 and 28.65 lay just outside it).
    ends = re.search(r"G from ([0-9.]+) to ([0-9.]+)", run("--help").stdout)
    check(ends is not None, "--help gives the --gamma range")
    for end in (ends.groups() if ends else ()):
        mesh_ok(data("square_hole.poly"), "--gamma", end, "-o", out("gamma-end.vtp"))
    p = run("--version")
    check(p.returncode == 0 and p.stdout.startswith("osm-mesh ") and
          p.stdout.strip().split()[1][0].isdigit(), "--version prints 'osm-mesh <version>'",
          p.stdout)


def group_options():
    square = data("square_hole.poly")
    # --domain: auto is enclosed here; hull and box cover more.
    areas = {}
    for domain in ("auto", "enclosed", "hull", "box"):
        mesh_ok(square, "-o", out("d-%s.node" % domain), "--domain", domain)
        v, t, _ = read_triangle_files(out("d-" + domain))
        areas[domain] = total_area(v, t)
        validate(square, out("d-%s.node" % domain), "--allow-missing",
                 "--domain", "enclosed" if domain == "auto" else domain,
                 what="--domain %s mesh is valid, its boundary and hole too" % domain)
    # The domain check can fail: the same square meshed without its hole
    # (a review: a seed on the filling's diagonal passed).
    with open(square) as f:
        text = f.read()
    filled = out("filled.poly")
    with open(filled, "w") as f:
        f.write(text.replace("1\n1 5 5\n", "0\n"))
    mesh_ok(filled, "-o", out("filled.node"))
    p = subprocess.run([ARGS.helper, "validate", square, out("filled.node"), "--allow-missing",
                        "--domain", "enclosed"], capture_output=True, text=True, timeout=600)
    check(p.returncode == 1 and "hole seed 0 (5, 5) lies in triangle" in p.stdout,
          "the square meshed without its hole fails the domain check", p.stdout[-500:])
    check(abs(areas["enclosed"] - 96.0) < 1e-9, "--domain enclosed: area 100 - 4 (hole)",
          str(areas["enclosed"]))
    check(read_bytes(out("d-auto.node")) == read_bytes(out("d-enclosed.node")) and
          read_bytes(out("d-auto.ele")) == read_bytes(out("d-enclosed.ele")),
          "--domain auto gives the enclosed mesh on a closed outline")
    check(areas["hull"] >= areas["enclosed"] - 1e-9, "--domain hull covers at least the enclosed area",
          str(areas))
    check(areas["box"] > 100.0 + 1e-9, "--domain box covers more than the square", str(areas))

    # --min-angle and --gamma reach the overlay (statistics Theta1Deg, Gamma).
    s = stats_of(square, "--min-angle", "20")
    check(abs(s.get("Theta1Deg", 0) - 20.0) < 1e-9, "--min-angle 20: Theta1Deg = 20", str(s.get("Theta1Deg")))
    s = stats_of(square, "--gamma", "2")
    expected = math.degrees(math.asin(1.0 / 4.0))
    check(abs(s.get("Theta1Deg", 0) - expected) < 1e-9,
          "--gamma 2: Theta1Deg = asin(1/4) = %.6f" % expected, str(s.get("Theta1Deg")))
    check(abs(s.get("Gamma", 0) - 2.0) < 1e-9, "--gamma 2: Gamma = 2", str(s.get("Gamma")))
    default = stats_of(square)
    check(abs(default.get("Theta1Deg", 0) - 30.0) < 1e-9, "default Theta1Deg = 30")
    # Above 30 degrees refinement has no guarantee: a warning, and a clear error
    # where it does not end (4 points, one close to a corner, at 35 degrees).
    p = mesh_ok(square, "--min-angle", "31", "-o", out("angle31.vtp"))
    check("osm-mesh: warning: a minimum angle above 30 degrees (here 31) has no guarantee" in p.stderr,
          "--min-angle 31 warns that nothing is guaranteed", p.stderr[-300:])
    check("above 30" not in run(square, "-o", out("angle30.vtp")).stderr,
          "the default angle gives no such warning")
    corner = out("close-to-corner.poly")
    with open(corner, "w") as f:
        f.write(poly_text([(0, 0), (1, 0), (0, 1), (0.02, 0.01)], []))
    expect_error([corner, "--min-angle", "35", "-o", out("angle35.vtp")], 1,
                 ["Steiner points without ending", "above 30 degrees it need not end"],
                 "--min-angle 35 on points where refinement does not end")
    check(default.get("MaxAngleDeg", 999) <= default.get("PredictedMaxAngleDeg", 0) + 1e-9,
          "default run within its predicted angle bound")

    # --max-edge refines, and no edge is longer (at 0.4 completion makes one
    # longer diagonal, which is split).
    fine = stats_of(square, "--max-edge", "0.4")
    check(fine.get("OutputTriangles", 0) > default.get("OutputTriangles", 0),
          "--max-edge 0.4 gives more triangles (%s > %s)" % (
              fine.get("OutputTriangles"), default.get("OutputTriangles")))
    check(fine.get("LongEdgesSplit", 0) >= 1,
          "--max-edge 0.4 splits a long completed edge (LongEdgesSplit %s)" % (
              fine.get("LongEdgesSplit")))
    mesh_ok(square, "-o", out("fine.node"), "--max-edge", "0.4")
    validate(square, out("fine.node"), "--allow-missing", "--max-edge", "0.4",
             what="--max-edge mesh is valid, no edge longer than 0.4")

    # --no-resolve: same mesh as the default on an input without crossings.
    mesh_ok(square, "-o", out("noresolve.vtp"), "--no-resolve")
    mesh_ok(square, "-o", out("resolve.vtp"))
    check(read_bytes(out("noresolve.vtp")) == read_bytes(out("resolve.vtp")),
          "--no-resolve changes nothing without crossings")
    # ... and crossings are split by default.
    crossing = stats_of(data("crossing.poly"))
    check(crossing.get("CrossingsSplit", 0) >= 1, "crossings split by default",
          str(crossing.get("CrossingsSplit")))

    # --merge-tolerance merges near points.
    near = out("near.poly")
    with open(near, "w") as f:
        f.write("6 2 0 0\n0 0 0\n1 4 0\n2 4 4\n3 0 4\n4 2 2\n5 2.0000001 2\n"
                "4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n0\n")
    exact = stats_of(near)
    merged = stats_of(near, "--merge-tolerance", "0.001")
    check(exact.get("DuplicatePointsMerged", -1) == 0, "no merge with the default tolerance 0")
    check(merged.get("DuplicatePointsMerged", -1) == 1,
          "--merge-tolerance 0.001 merges the two near points",
          str(merged.get("DuplicatePointsMerged")))
    check(merged.get("OutputVertices", 0) < exact.get("OutputVertices", 0),
          "--merge-tolerance: fewer output vertices")

    # --max-steiner: a generous cap is fine, a tiny one is an error.
    s = stats_of(square, "--max-steiner", "1000000")
    check(s.get("OutputTriangles", 0) == default.get("OutputTriangles"),
          "--max-steiner 1000000 does not change the mesh")
    expect_error([square, "--max-steiner", "3"], 1, ["Steiner"], "--max-steiner 3")

    # --stats: JSON with the filter's statistic names, matching the files.
    mesh_ok(square, "-o", out("stats.node"))
    v, t, e = read_triangle_files(out("stats"))
    for name in ("InputPoints", "InputSegments", "OutputTriangles", "OutputVertices",
                 "MaxAngleDeg", "MinAngleDeg", "DiscardedEdges", "SecondsTotal", "Warnings"):
        check(name in default, "--stats has " + name)
    check(default.get("ok") is True, "--stats: ok is true")
    check(default.get("OutputTriangles") == len(t) and default.get("OutputVertices") == len(v),
          "--stats counts match the written .ele/.node (%d, %d)" % (len(t), len(v)))
    check(default.get("InputPoints") == 9 and default.get("InputSegments") == 8,
          "--stats: 9 input points, 8 segments")

    # --svg: a drawing with the mesh, the discarded edges (dashed) and the input (bold).
    for name, source in (("square", square), ("crossing", data("crossing.poly"))):
        svg = out(name + ".svg")
        s = stats_of(source, "--svg", svg, "-o", out(name + "-svg.node"))
        v_of, _, edges = read_triangle_files(out(name + "-svg"))
        try:
            root = ET.parse(svg).getroot()
        except ET.ParseError as e:
            check(False, "--svg writes well-formed XML", str(e))
            continue
        ns = "{http://www.w3.org/2000/svg}"
        check(root.tag == ns + "svg", "--svg: an <svg> document")
        groups = {g.get("id"): g for g in root.iter(ns + "g")}
        check(set(groups) >= {"mesh", "discarded", "input"},
              "--svg: groups mesh, discarded, input", str(sorted(groups)))
        if set(groups) >= {"mesh", "discarded", "input"}:
            dashed = [l for l in groups["discarded"].iter(ns + "line")]
            check(len(dashed) == s.get("DiscardedEdges") and
                  all(l.get("stroke-dasharray") for l in dashed),
                  "--svg %s: %d dashed discarded edges" % (name, s.get("DiscardedEdges", -1)),
                  str(len(dashed)))
            bold = list(groups["input"].iter(ns + "line"))
            # The input subsegments: the mesh edges along the file's segments.
            input_edges = sum(1 for a, b, _ in edges
                              if on_segments(source, v_of[a - 1], v_of[b - 1]))
            check(len(bold) == input_edges and
                  all(float(l.get("stroke-width")) > 1 for l in bold),
                  "--svg %s: %d bold input subsegments" % (name, input_edges), str(len(bold)))
            thin = list(groups["mesh"].iter(ns + "line"))
            check(len(thin) + len(bold) == len(edges),
                  "--svg %s: every mesh edge drawn" % name, "%d + %d vs %d" % (
                      len(thin), len(bold), len(edges)))
    # No -o: nothing written, still a success.
    p = mesh_ok(square)
    check(p.stdout == "", "no -o and no --stats: nothing on stdout")
    # Warnings: one line each, prefixed, no VTK formatting; also in --stats.
    outside = out("outside.poly")
    with open(outside, "w") as f:
        f.write("5 2 0 0\n0 0 0\n1 4 0\n2 4 4\n3 0 4\n4 10 10\n"
                "4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n0\n")
    p = run(outside, "--stats", "-o", out("outside.node"))
    lines = p.stderr.splitlines()
    check(p.returncode == 0 and lines and
          all(l.startswith("osm-mesh: warning: ") for l in lines),
          "a point outside the enclosed domain: warnings only, each 'osm-mesh: warning: ...'",
          repr(p.stderr))
    check("outside the meshed domain" in p.stderr, "the warning says the point is left out",
          repr(p.stderr))
    check(not any(noise in p.stderr for noise in ("Warning: In ", "(0x", ".cxx", "WARN|")),
          "no VTK formatting noise in warnings", repr(p.stderr))
    try:
        w = json.loads(p.stdout).get("Warnings", [])
    except ValueError:
        w = []
    check(len(w) == len(lines) and all(("osm-mesh: warning: " + x) in lines for x in w),
          "--stats lists the same warnings", repr(w))
    validate(outside, out("outside.node"), "--allow-missing",
             what="mesh without the outside point is valid")
    # --option=value spelling.
    a = stats_of(square, "--min-angle=25", "--domain=hull")
    check(abs(a.get("Theta1Deg", 0) - 25) < 1e-9, "--min-angle=25 spelling accepted")


def node_data_ok(path, vertices):
    """square_hole.poly's vertex attribute and markers in the .node written:
    its own at input vertices, linear along the bottom edge (0.5 to 1.5), and
    Triangle's markers: the segment's on a segment, 0 elsewhere."""
    with open(path) as f:
        rows = [l.split() for l in f if l.strip() and not l.lstrip().startswith("#")]
    given = {(0, 0): (0.5, 1), (10, 0): (1.5, 1), (10, 10): (2.5, 1), (0, 10): (3.5, 1),
             (4, 4): (4.5, 2), (6, 4): (5.5, 2), (6, 6): (6.5, 2), (4, 6): (7.5, 2),
             (2, 8): (8.5, 0)}
    wrong = []
    for (x, y), r in zip(vertices, rows[1:]):
        a, m = float(r[3]), int(r[4])
        outer = x in (0.0, 10.0) or y in (0.0, 10.0)
        hole = (x in (4.0, 6.0) and 4 <= y <= 6) or (y in (4.0, 6.0) and 4 <= x <= 6)
        expected = given.get((x, y), (0.5 + x / 10 if y == 0.0 else a,
                                      1 if outer else 2 if hole else 0))
        if abs(a - expected[0]) > 1e-12 or m != expected[1]:
            wrong.append((x, y, a, m, expected))
    check(rows[0][2] == "1" and not wrong,
          ".node: the file's vertex attribute and markers carried to %d vertices" % len(vertices),
          wrong[:3])


def group_formats():
    square = data("square_hole.poly")
    for ext in ("vtp", "vtu", "vtk", "node"):
        path = out("square." + ext)
        mesh_ok(square, "-o", path)
        check(os.path.isfile(path) and os.path.getsize(path) > 0, "." + ext + " written")
        report = validate(square, path, "--allow-missing", what="." + ext + " read back and valid")
        check(" 9 of 9 input points" in report,
              ".%s: all 9 input points are mesh vertices (the isolated one too)" % ext, report)
    # Triangle's files: the three side by side, parsed back.
    v, t, e = read_triangle_files(out("square"))
    node_data_ok(out("square.node"), v)
    # --no-point-data: no attribute, and Triangle's markers for input without
    # any: 1 on the mesh's boundary (the outer square's and the hole's), else 0.
    mesh_ok(square, "-o", out("bare.node"), "--no-point-data")
    with open(out("bare.node")) as f:
        rows = [l.split() for l in f if l.strip() and not l.lstrip().startswith("#")]
    wrong = []
    for r in rows[1:]:
        x, y, m = float(r[1]), float(r[2]), int(r[3])
        boundary = (x in (0.0, 10.0) or y in (0.0, 10.0) or
                    (x in (4.0, 6.0) and 4 <= y <= 6) or (y in (4.0, 6.0) and 4 <= x <= 6))
        if m != (1 if boundary else 0):
            wrong.append((x, y, m))
    check(rows[0][2] == "0" and not wrong,
          "--no-point-data: no vertex attribute, marker 1 on the boundary's vertices, 0 inside",
          str((rows[0], wrong[:3])))
    check(abs(total_area(v, t) - 96.0) < 1e-9, ".node/.ele: area 96 (the hole is left out)")
    # --no-holes, Triangle's -O (a Triangle user's review: no way to ignore them).
    mesh_ok(square, "-o", out("noholes.node"), "--no-holes")
    nv, nt, _ = read_triangle_files(out("noholes"))
    check(abs(total_area(nv, nt) - 100.0) < 1e-9, "--no-holes: area 100, the hole filled")
    with open(out("noholes.poly")) as f:
        rows = [l.split() for l in f if l.strip() and not l.startswith("#")]
    check(rows[2 + int(rows[1][0])] == ["0"],
          "--no-holes: the .poly lists no hole, so meshing it again fills it too (a review)")
    # Seeds moved with the points (SeedReferencePoints: square_hole scaled by
    # 2 after reading) are written where the filter used them (a review: the
    # .poly kept (5, 5), and meshing it again removed the ring).
    with open(out("moved.vtk"), "w") as f:
        f.write("# vtk DataFile Version 3.0\nscaled\nASCII\nDATASET POLYDATA\n"
                "FIELD FieldData 2\nHolePoints 2 1 double\n5 5\n"
                "SeedReferencePoints 4 5 double\n0 0 0 0\n1 10 0 0\n2 10 10 0\n4 4 4 0\n8 0 0 0\n"
                "POINTS 8 double\n0 0 0  20 0 0  20 20 0  0 20 0\n8 8 0  12 8 0  12 12 0  8 12 0\n"
                "LINES 8 24\n2 0 1\n2 1 2\n2 2 3\n2 3 0\n2 4 5\n2 5 6\n2 6 7\n2 7 4\n")
    mesh_ok(out("moved.vtk"), "-o", out("moved.node"))
    mesh_ok(out("moved.poly"), "-o", out("moved-again.node"))
    mv, mt, _ = read_triangle_files(out("moved"))
    av, at, _ = read_triangle_files(out("moved-again"))
    check(abs(total_area(mv, mt) - 384.0) < 1e-9 and abs(total_area(av, at) - 384.0) < 1e-9,
          "seeds moved with the points: the written .poly meshes the same 384 again",
          "%g, %g" % (total_area(mv, mt), total_area(av, at)))
    check(all(area(v, tri) > 0 for tri in t), ".ele: every triangle counter-clockwise")
    inside_hole = [tri for tri in t if
                   4 < sum(v[i - 1][0] for i in tri) / 3 < 6 and 4 < sum(v[i - 1][1] for i in tri) / 3 < 6]
    check(not inside_hole, "the file's hole is honoured: no triangle in (4,6)x(4,6)")
    # Triangle's .edge markers: each input subsegment its segment's (1 outside,
    # 2 around the hole), the other edges 0.
    outer = sum(math.dist(v[a - 1], v[b - 1]) for a, b, m in e if m == 1)
    hole = sum(math.dist(v[a - 1], v[b - 1]) for a, b, m in e if m == 2)
    check(abs(outer - 40.0) < 1e-9 and abs(hole - 8.0) < 1e-9 and
          all(m in (0, 1, 2) for _, _, m in e),
          ".edge: the segments' markers on their subsegments, 40 long with 1, 8 with 2",
          (outer, hole))
    # The .poly beside them (Triangle's -p; a Triangle user's review: an
    # interior segment's edges could not be told from the others): the 48
    # long of segments with their markers, and the file's hole.
    with open(out("square.poly")) as f:
        rows = [l.split() for l in f if l.strip() and not l.startswith("#")]
    segments = [(int(r[1]), int(r[2]), int(r[3])) for r in rows[2:2 + int(rows[1][0])]]
    lengths = {m: sum(math.dist(v[a - 1], v[b - 1]) for a, b, k in segments if k == m) for m in (1, 2)}
    check(abs(lengths[1] - 40.0) < 1e-9 and abs(lengths[2] - 8.0) < 1e-9 and
          len(segments) == sum(1 for _, _, m in e if m) and
          rows[2 + len(segments)] == ["1"] and rows[3 + len(segments)][1:] == ["5", "5"],
          ".poly: the segments' subsegments, 40 long with 1, 8 with 2, and the hole at (5, 5)",
          str(lengths))
    # It is not written over the input ("osm-mesh square.poly -o square.node").
    shutil.copy(square, out("self.poly"))
    p = mesh_ok(out("self.poly"), "-o", out("self.node"))
    check(read_bytes(out("self.poly")) == read_bytes(square) and
          "segments are not written to %s, which is the input" % out("self.poly") in p.stderr,
          "a .node output beside its input .poly keeps it, and says so", p.stderr[-300:])
    _, _, bare_edges = read_triangle_files(out("bare"))
    check(abs(sum(math.dist(v[a - 1], v[b - 1]) for a, b, m in bare_edges if m == 1) - 48.0) < 1e-9,
          "--no-point-data: .edge marks every input subsegment 1 (40 + 8 long)")
    # Triangle's marker rules (triangle.markers.html) on cases a review found:
    # an input vertex inside a marked segment, a crossing of a 0 and a 7
    # segment (either order), a vertex given twice, a segment given twice
    # with 0 and 7, and a file with segment markers but none on its vertices.
    rules = out("rules.poly")
    with open(rules, "w") as f:
        f.write("\n".join([
            "14 2 0 1",
            "0 0 0 0", "1 4 0 0", "2 4 4 0", "3 0 4 0",
            "4 2 0 0",                          # inside the bottom segment (marker 5)
            "5 0.5 1 0", "6 1.5 3 0",           # a diagonal, marker 0
            "7 0.5 3 0", "8 1.5 1 0",           # the other, marker 7: they cross at (1, 2)
            "9 3 1 0", "10 3 3 0",              # a slit given twice, with 0 and 3
            "11 3.5 2 0", "12 3.5 2 0", "13 3.8 2 0",  # 12 repeats 11; 12-13 has marker 9
            "9 1",
            "0 0 1 5", "1 1 2 0", "2 2 3 0", "3 3 0 0",
            "4 5 6 0", "5 7 8 7", "6 9 10 0", "7 10 9 3", "8 12 13 9",
            "0", ""]))
    mesh_ok(rules, "-o", out("rules.node"))
    v, t, e = read_triangle_files(out("rules"))
    with open(out("rules.node")) as f:
        node_rows = [l.split() for l in f if l.strip() and not l.lstrip().startswith("#")][1:]
    # The vertices of triangles: the point given twice is also listed unused,
    # with its own marker, as Triangle lists it.
    used = set(i for tri in t for i in tri)
    marker_at = {(float(r[1]), float(r[2])): int(r[3])
                 for k, r in enumerate(node_rows) if k + 1 in used}
    expected_points = {(2.0, 0.0): 5, (0.0, 0.0): 5, (4.0, 0.0): 5, (0.0, 4.0): 1, (4.0, 4.0): 1,
                       (1.0, 2.0): 7, (0.5, 1.0): 0, (1.5, 3.0): 0, (0.5, 3.0): 7, (1.5, 1.0): 7,
                       (3.0, 1.0): 3, (3.0, 3.0): 3, (3.5, 2.0): 9, (3.8, 2.0): 9}
    wrong = [(p, marker_at.get(p), m) for p, m in expected_points.items() if marker_at.get(p) != m]
    check(not wrong, "Triangle's vertex markers: inside a marked segment, at a crossing, on a "
          "segment given twice, at a point given twice, on the boundary", str(wrong))
    slit = [m for a, b, m in e if all(v[i - 1][0] == 3.0 and 1 <= v[i - 1][1] <= 3 for i in (a, b))]
    check(slit and all(m == 3 for m in slit),
          "Triangle's edge markers: a segment given with 0 and 3 is marked 3", str(slit))
    # No vertex markers, segment markers only: vertices take their segments'.
    seg_only = out("segonly.poly")
    with open(seg_only, "w") as f:
        f.write("4 2 0 0\n0 0 0\n1 2 0\n2 2 2\n3 0 2\n"
                "4 1\n0 0 1 5\n1 1 2 0\n2 2 3 0\n3 3 0 0\n0\n")
    mesh_ok(seg_only, "-o", out("segonly.node"))
    with open(out("segonly.node")) as f:
        node_rows = [l.split() for l in f if l.strip() and not l.lstrip().startswith("#")][1:]
    bottom = [int(r[3]) for r in node_rows if float(r[2]) == 0.0]
    check(bottom and all(m == 5 for m in bottom),
          "a file without vertex markers: the bottom segment's vertices take its marker 5",
          str(bottom))
    # .vtu and .vtp hold the same mesh: validated above; the .vtk too.
    # Sizes agree between formats (validator summaries).
    summaries = {}
    for ext in ("vtp", "vtu", "vtk", "node"):
        line = validate(square, out("square." + ext), "--allow-missing", what="." + ext + " again")
        summaries[ext] = line.split(",")[0:2]
    check(len(set(tuple(x) for x in summaries.values())) == 1,
          "all four formats hold the same number of triangles and vertices", str(summaries))
    # Coordinates that need all 17 significant digits keep every bit in each
    # format (legacy .vtk files included: they are written in binary).
    odd = out("odd-digits.poly")
    with open(odd, "w") as f:
        f.write(poly_text([(0.1, 0.2), (10.123456789012345, 0.30000000000000004),
                           (9.87654321098765, 7.777777777777777), (0.3333333333333333, 9.1)],
                          [(0, 1), (1, 2), (2, 3), (3, 0)]))
    for ext in ("vtp", "vtu", "vtk", "node"):
        path = out("odd-digits." + ext)
        mesh_ok(odd, "-o", path)
        report = validate(odd, path, what="." + ext + ": 17-digit coordinates read back and valid")
        check(" 4 of 4 input points" in report,
              ".%s: the 4 input points keep their coordinates bit for bit" % ext, report)
    # Regional attributes (a .poly's region lines, as Triangle's -A uses them):
    # the .ele's first attribute, per triangle of each region; the area limit
    # bounds every triangle of its region, as Triangle's -a does.
    regions = out("regions.poly")
    with open(regions, "w") as f:
        f.write(poly_text([(0, 0), (10, 0), (10, 10), (0, 10), (3, 3), (7, 3), (7, 7), (3, 7)],
                          [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4)]) +
                "2\n0 1 1 -2.5\n1 5 5 0.125 0.05\n")
    text = mesh_ok(regions, "-o", out("regions-default.node")).stderr
    check("1 region(s) set a maximum triangle area, which is not applied" in text and
          "--region-areas" in text,
          "regions: by default (as Triangle without -a) the area limit is said not applied", text)
    text = mesh_ok(regions, "-o", out("regions.node"), "--region-areas").stderr
    check("area" not in text, "regions: --region-areas applies the area limit, no warning", text)
    # --gap-ratio: the paper's overlay quality at once, more triangles.
    fast = stats_of(data("wedge.vtk"))
    strict = stats_of(data("wedge.vtk"), "--gap-ratio")
    check(fast.get("GapRatioOverlay") == 0 and strict.get("GapRatioOverlay") == 1 and
          strict.get("OutputTriangles", 0) > fast.get("OutputTriangles", 0),
          "--gap-ratio makes the gap-ratio overlay (%s triangles, %s without)" % (
              strict.get("OutputTriangles"), fast.get("OutputTriangles")))
    with open(out("regions.ele")) as f:
        rows = [l.split() for l in f if l.strip()]
    rv, rt, _ = read_triangle_files(out("regions"))
    check(rows[0][2] == "2", "regions: .ele has 2 attributes (regional attribute, region id)",
          " ".join(rows[0]))

    def inner(tri):
        cx, cy = (sum(rv[i - 1][k] for i in tri) / 3 for k in (0, 1))
        return 3 < cx < 7 and 3 < cy < 7
    wrong = [r for r, tri in zip(rows[1:], rt) if float(r[4]) != (0.125 if inner(tri) else -2.5)]
    check(any(inner(tri) for tri in rt) and not wrong,
          "regions: every triangle has its region's attribute (-2.5 outside, 0.125 inside)",
          str(wrong[:3]))

    def tri_area(tri):
        (ax, ay), (bx, by), (cx, cy) = (rv[i - 1] for i in tri)
        return 0.5 * ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))
    inner_areas = [tri_area(tri) for tri in rt if inner(tri)]
    outer_areas = [tri_area(tri) for tri in rt if not inner(tri)]
    check(len(inner_areas) >= 16 / 0.05 and max(inner_areas) <= 0.05 and max(outer_areas) > 0.05,
          "regions: every inner triangle within the region's maximum area 0.05, the outer "
          "region coarser (%d inner, largest %g; largest outer %g)" % (
              len(inner_areas), max(inner_areas), max(outer_areas)))
    # Triangle's numbering (found by a user review: the nodes came in the
    # mesh's order, so no input vertex kept its number): node i is input
    # point i, counted from the input's first index; a point given twice and
    # a point in a hole are listed too, used by no triangle, with their own
    # attribute and marker, as Triangle lists them unless -j.
    for first in (0, 1):
        numbered = out("numbered%d.poly" % first)
        rows = [(0, 0, 10, 1), (6, 0, 11, 1), (6, 6, 12, 1), (0, 6, 13, 1),
                (2, 2, 14, 0), (4, 2, 15, 0), (4, 4, 16, 0), (2, 4, 17, 0),
                (6, 6, 18, 4),   # point 2 again
                (3, 3, 19, 6),   # inside the hole
                (1, 5, 20, 0)]   # a free point
        with open(numbered, "w") as f:
            f.write("%d 2 1 1\n" % len(rows))
            for k, (x, y, a, m) in enumerate(rows):
                f.write("%d %g %g %g %d\n" % (k + first, x, y, a, m))
            f.write("8 0\n")
            for k, (a, b) in enumerate([(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4)]):
                f.write("%d %d %d\n" % (k + first, a + first, b + first))
            f.write("1\n%d 3 3\n" % first)
        mesh_ok(numbered, "-o", out("numbered%d.node" % first))
        v, t, _ = read_triangle_files(out("numbered%d" % first))
        with open(out("numbered%d.node" % first)) as f:
            node_rows = [l.split() for l in f if l.strip() and not l.lstrip().startswith("#")][1:]
        used = set(i for tri in t for i in tri)
        listed = [(float(r[1]), float(r[2]), float(r[3]), int(r[4])) for r in node_rows[:len(rows)]]
        # (The hole's corners are on the boundary: Triangle marks them 1.)
        expected = [(float(x), float(y), float(a), 1 if 4 <= k <= 7 else m)
                    for k, (x, y, a, m) in enumerate(rows)]
        check(int(node_rows[0][0]) == first and listed == expected,
              "Triangle's numbering, input counting from %d: node i is input point i, numbered "
              "from %d, with its attribute and marker" % (first, first), str(listed[:4]))
        check(9 not in used and 10 not in used and all(k + 1 in used for k in (0, 1, 2, 3, 4, 5, 6, 7, 10)),
              "Triangle's numbering, input counting from %d: the repeated point and the point in "
              "the hole are used by no triangle, every other input point is" % first, str(sorted(used)[:12]))
    # Uppercase extension and a .node output base in a sub-directory.
    os.makedirs(out("sub"), exist_ok=True)
    mesh_ok(square, "-o", out("sub/UPPER.VTP"))
    validate(square, out("sub/UPPER.VTP"), "--allow-missing", what="an upper-case .VTP")


def write_ascii_vtp(path, points, lines, polys=(), cell_values=None):
    """Lines, or polygons (polys), and optionally a Float64 cell array Land."""
    cells, tag = (polys, "Polys") if polys else (lines, "Lines")
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" '
                'byte_order="LittleEndian">\n<PolyData>\n'
                '<Piece NumberOfPoints="%d" NumberOfVerts="0" NumberOfLines="%d" '
                'NumberOfStrips="0" NumberOfPolys="%d">\n' % (len(points), len(lines), len(polys)))
        f.write('<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">\n')
        f.write(" ".join("%r %r %r" % p for p in points) + "\n</DataArray></Points>\n")
        if cell_values is not None:
            f.write('<CellData><DataArray type="Float64" Name="Land" format="ascii">\n')
            f.write(" ".join("%r" % v for v in cell_values) + "\n</DataArray></CellData>\n")
        f.write('<%s><DataArray type="Int64" Name="connectivity" format="ascii">\n' % tag)
        f.write(" ".join(" ".join(str(i) for i in l) for l in cells) + "\n</DataArray>\n")
        offsets, o = [], 0
        for l in cells:
            o += len(l)
            offsets.append(o)
        f.write('<DataArray type="Int64" Name="offsets" format="ascii">\n')
        f.write(" ".join(str(x) for x in offsets) + "\n</DataArray></%s>\n" % tag)
        f.write("</Piece>\n</PolyData>\n</VTKFile>\n")


def group_inputs():
    # .vtk polydata (the bundled wedge).
    wedge = data("wedge.vtk")
    mesh_ok(wedge, "-o", out("wedge.node"))
    validate(wedge, out("wedge.node"), "--allow-missing", what="wedge.vtk meshed and valid")
    # .vtp polydata, a polyline square with a slit.
    vtp = out("slit.vtp")
    write_ascii_vtp(vtp, [(0, 0, 0), (3, 0, 0), (3, 2, 0), (0, 2, 0), (0.5, 1, 0), (2.5, 1.2, 0)],
                    [[0, 1, 2, 3, 0], [4, 5]])
    mesh_ok(vtp, "-o", out("slit.vtu"))
    validate(vtp, out("slit.vtu"), what="a .vtp polyline input meshed, every point kept, valid")
    # The same as an unstructured grid, .vtu and legacy .vtk, with a tetra
    # (ignored, said) and the slit first: the same mesh.
    slit = stats_of(vtp, "-o", out("slit-again.vtp"))
    grid_points = [(0, 0, 0), (3, 0, 0), (3, 2, 0), (0, 2, 0), (0.5, 1, 0), (2.5, 1.2, 0)]
    grid_cells = [(10, [0, 1, 2, 3]), (3, [4, 5]), (4, [0, 1, 2, 3, 0])]  # tetra, line, polyline
    vtu = out("slit.vtu")
    with open(vtu, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="0.1" '
                'byte_order="LittleEndian">\n<UnstructuredGrid>\n<Piece NumberOfPoints="%d" '
                'NumberOfCells="%d">\n<Points><DataArray type="Float64" NumberOfComponents="3" '
                'format="ascii">%s</DataArray></Points>\n<Cells>\n'
                '<DataArray type="Int64" Name="connectivity" format="ascii">%s</DataArray>\n'
                '<DataArray type="Int64" Name="offsets" format="ascii">%s</DataArray>\n'
                '<DataArray type="UInt8" Name="types" format="ascii">%s</DataArray>\n'
                '</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n' % (
                    len(grid_points), len(grid_cells),
                    " ".join("%r %r %r" % p for p in grid_points),
                    " ".join(str(i) for _, c in grid_cells for i in c),
                    " ".join(str(sum(len(c) for _, c in grid_cells[:k + 1]))
                             for k in range(len(grid_cells))),
                    " ".join(str(t) for t, _ in grid_cells)))
    legacy = out("slit-grid.vtk")
    with open(legacy, "w") as f:
        f.write("# vtk DataFile Version 3.0\nslit\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                "POINTS %d double\n" % len(grid_points))
        f.write("".join("%r %r %r\n" % p for p in grid_points))
        f.write("CELLS %d %d\n" % (len(grid_cells), sum(len(c) + 1 for _, c in grid_cells)))
        f.write("".join("%d %s\n" % (len(c), " ".join(map(str, c))) for _, c in grid_cells))
        f.write("CELL_TYPES %d\n%s\n" % (len(grid_cells), "\n".join(str(t) for t, _ in grid_cells)))
    for grid in (vtu, legacy):
        p = mesh_ok(grid, "-o", out("slit-grid.vtp"), "--stats")
        s = json.loads(p.stdout) if p.returncode == 0 else {}
        check(all(s.get(k) == slit.get(k) and k in s
                  for k in ("InputPoints", "InputSegments", "OutputVertices", "OutputTriangles")) and
              "Ignored 1 cell(s) of the unstructured grid, the first cell 0 (vtkTetra)" in p.stderr,
              "an unstructured grid input (%s) meshes as the same lines in polydata, its tetra "
              "ignored with a warning" % os.path.basename(grid),
              str(s)[:300] + p.stderr[-300:])
        # Triangle's numbering: node i is input point i (found by a review:
        # a grid's nodes came in the mesh's order).
        mesh_ok(grid, "-o", out("slit-grid.node"))
        with open(out("slit-grid.node")) as f:
            rows = [l.split() for l in f.read().splitlines()[1:len(grid_points) + 1]]
        check([(float(r[1]), float(r[2])) for r in rows] == [p[:2] for p in grid_points] and
              rows[0][0] == "1",
              "a .node output of an unstructured grid (%s) numbers node i as input point i, from 1"
              % os.path.basename(grid), str(rows))
    # .vtp polygons with cell data: the mesh's triangles take their polygon's
    # (PassCellData; its values are checked by vtk.OverlayStitchMesher.Input.polygon-data).
    land = out("land.vtp")
    write_ascii_vtp(land, [(0, 0, 0), (4, 0, 0), (4, 4, 0), (0, 4, 0), (1, 1, 0), (1, 3, 0),
                           (3, 3, 0), (3, 1, 0)], [], polys=[[0, 1, 2, 3], [4, 5, 6, 7]],
                    cell_values=[1.5, 2.5])
    for extra, carried in (([], True), (["--no-point-data"], False)):
        mesh_ok(land, "-o", out("land.vtu"), *extra)
        validate(land, out("land.vtu"), what="a .vtp polygon input meshed, valid %r" % extra)
        names = array_names(out("land.vtu"), "CellData")
        check(({"InputCellId", "Land"} <= names) == carried and
              ({"InputCellId", "Land"} & names == set()) == (not carried),
              "polygon cell data on the mesh %s %r" % ("with" if carried else "without", extra),
              str(sorted(names)))
    # A .node output cannot hold them: it says so (found by a user review),
    # and of the point arrays it names those it does not write as Triangle's
    # attributes: Attribute0 is, Attribute2 (no Attribute1) and a 2-component
    # Attribute1... are not (found by a second review).
    p = mesh_ok(land, "-o", out("land.node"))
    check("not written to the .node/.ele files" in p.stderr and "cell data Land" in p.stderr,
          "a .node output names the cell data it leaves out", p.stderr[-300:])
    # Nor a plane z = 5 (found by a user review: z was dropped silently).
    raised = out("raised.vtk")
    with open(raised, "w") as f:
        f.write("# vtk DataFile Version 3.0\nz\nASCII\nDATASET POLYDATA\nPOINTS 4 double\n"
                "0 0 5\n1 0 5\n1 1 5\n0 1 5\nPOLYGONS 1 5\n4 0 1 2 3\n")
    p = mesh_ok(raised, "-o", out("raised.node"))
    check("the mesh lies in the plane z = 5, and a .node file holds x and y only" in p.stderr,
          "a .node output of a plane z = 5 says z is not written", p.stderr[-300:])
    p = mesh_ok(data("square_hole.poly"), "-o", out("flat.node"))
    check("plane z =" not in p.stderr, "nothing to say at z = 0", p.stderr[-300:])
    gaps = out("gaps.vtp")
    with open(gaps, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">'
                '<PolyData><Piece NumberOfPoints="4" NumberOfVerts="0" NumberOfLines="1" '
                'NumberOfStrips="0" NumberOfPolys="0"><PointData>'
                '<DataArray type="Float64" Name="Attribute0" format="ascii">1 2 3 4</DataArray>'
                '<DataArray type="Float64" Name="Attribute2" format="ascii">1 2 3 4</DataArray>'
                '</PointData><Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">'
                '0 0 0 1 0 0 1 1 0 0 1 0</DataArray></Points><Lines>'
                '<DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 3 0</DataArray>'
                '<DataArray type="Int64" Name="offsets" format="ascii">5</DataArray>'
                '</Lines></Piece></PolyData></VTKFile>\n')
    p = mesh_ok(gaps, "-o", out("gaps.node"))
    with open(out("gaps.node")) as f:
        header = f.readline().split()
    check(header[2] == "1" and "point data Attribute2" in p.stderr and
          "point data Attribute0" not in p.stderr,
          "a .node output writes Attribute0 and names Attribute2, which it leaves out",
          str(header) + p.stderr[-300:])
    # .node: points only, meshed over their hull.
    node = data("split_pslg.node")
    s = stats_of(node, "-o", out("points.node"))
    check(s.get("InputPoints") == 4 and s.get("InputSegments") == 0,
          ".node input: 4 points, no segment", str((s.get("InputPoints"), s.get("InputSegments"))))
    validate(node, out("points.node"), what=".node input meshed, valid")
    # A .poly listing zero vertices takes them from the .node beside it.
    s = stats_of(data("split_pslg.poly"), "-o", out("split.vtp"))
    check(s.get("InputPoints") == 4 and s.get("InputSegments") == 3,
          ".poly with 0 vertices reads split_pslg.node", str((s.get("InputPoints"), s.get("InputSegments"))))
    validate(data("split_pslg.poly"), out("split.vtp"), what="split .poly/.node meshed, valid")


def interrupted_write():
    """A signal during a long write leaves the old output whole and no
    temporary file (a review: SIGINT left a 0-byte file where a mesh was)."""
    import random
    import signal
    import time
    rng = random.Random(7)
    points = [(i + rng.uniform(-0.3, 0.3), j + rng.uniform(-0.3, 0.3))
              for i in range(320) for j in range(320)]
    source = out("many-points.node")
    with open(source, "w") as f:
        f.write("%d 2 0 0\n" % len(points))
        f.writelines("%d %.17g %.17g\n" % (k, x, y) for k, (x, y) in enumerate(points))
    target = out("interrupted.vtp")
    mesh_ok(data("square_hole.poly"), "-o", target)
    old = read_bytes(target)
    for sig in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
        p = subprocess.Popen([ARGS.cli, source, "-o", target],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        temp = []
        while p.poll() is None and not temp:
            temp = [f for f in os.listdir(ARGS.out) if f.startswith(".interrupted.vtp.osm-") and
                    os.path.getsize(out(f)) > 0]
            time.sleep(0.002)
        p.send_signal(sig)
        status = p.wait(timeout=600)
        check(temp and status == -sig, "signal %d arrived during the write" % sig,
              "status %d, temporary files %r" % (status, temp))
        check(read_bytes(target) == old, "signal %d during the write leaves the old file whole" % sig)
        left = [f for f in os.listdir(ARGS.out) if ".osm-" in f]
        check(not left, "signal %d during the write leaves no temporary file" % sig, str(left))


def group_errors():
    missing = out("does-not-exist.poly")
    expect_error([missing], 1, ["cannot open '%s'" % missing, "No such file or directory"],
                 "missing file")
    expect_error([out("missing.vtp")], 1, ["cannot open"], "missing .vtp")
    # A pipe or a device: the readers open the input more than once, so a
    # pipe's second open waited for ever (a review), and /dev/zero as .poly
    # was read for ever.
    fifo = out("fifo.poly")
    if os.path.lexists(fifo):
        os.remove(fifo)
    os.mkfifo(fifo)
    expect_error([fifo, "-o", out("fifo.vtp")], 1,
                 ["cannot read '%s'" % fifo, "not a regular file", "save it to a file first"],
                 "a named pipe as input")
    os.remove(fifo)
    zero = out("zero.poly")
    if os.path.lexists(zero):
        os.remove(zero)
    os.symlink("/dev/zero", zero)
    expect_error([zero, "-o", out("zero.vtp")], 1, ["not a regular file"], "a device as input")
    folder = out("folder.vtp")
    os.makedirs(folder, exist_ok=True)
    expect_error([folder], 1, ["cannot read '%s': it is a directory" % folder],
                 "a directory as input")

    def write(name, text):
        path = out(name)
        with open(path, "w") as f:
            f.write(text)
        return path

    truncated = write("truncated.poly", "4 2 0 0\n1 0 0\n2 1 0\n")
    expect_error([truncated], 1, ["truncated.poly:1:", "4 vertices"], "truncated .poly")
    text = write("text.poly", "3 2 0 0\n1 0 0\n2 abc 0\n3 0 1\n0 0\n0\n")
    expect_error([text], 1, ["text.poly:3:", "'abc'"], "text where a number belongs")
    ids = write("ids.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n2 0\n1 1 2\n2 2 40\n0\n")
    expect_error([ids], 1, ["ids.poly:7:", "40", "does not exist"], "segment id out of range")
    no_segments = write("nosegs.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n")
    expect_error([no_segments], 1, ["nosegs.poly:"], ".poly ending before its segments")
    # Crossing segments with --no-resolve name both segments (0-based, file order).
    expect_error([data("crossing.poly"), "--no-resolve"], 1,
                 ["input segment 4", "input segment 5", "cross"], "crossing segments with --no-resolve")
    # The same in a 1-based file: the message says how it numbers.
    one_based = write("crossing1.poly", "6 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 1 1\n6 3 3.5\n"
                      "6 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n6 2 4\n0\n")
    p = expect_error([one_based, "--no-resolve"], 1,
                     ["input segment 4", "input segment 5", "count from 0",
                      one_based + " counts from 1", "segment 4 runs from (1, 1, 0) to (3, 3.5, 0)"],
                     "crossing segments in a 1-based file")
    # A .poly's polydata holds its lone vertices' cells first: cell ids are no
    # numbers of the file's, so segments are placed by their ends' coordinates.
    check("is cell" not in p.stderr,
          "a 1-based file's segments are not named by VTK cell ids", repr(p.stderr))
    # Warnings that name points or segments say it too, and only those.
    for base in (0, 1):
        dup = write("duplicate%d.poly" % base,
                    "5 2 0 0\n{0} 0 0\n{1} 4 0\n{2} 4 4\n{3} 0 4\n{4} 0 0\n"
                    "4 0\n{0} {0} {1}\n{1} {1} {2}\n{2} {2} {3}\n{3} {3} {0}\n0\n"
                    .format(*range(base, base + 5)))
        p = mesh_ok(dup, what="a duplicate point in a %d-based file" % base)
        named = [l for l in p.stderr.splitlines() if "duplicate point" in l]
        check(len(named) == 1 and ("count from 0" in named[0]) == (base == 1) and
              ((dup + " counts from 1") in named[0]) == (base == 1),
              "the duplicate-point warning says how the file counts only if it counts from 1 "
              "(%d-based)" % base, repr(p.stderr))
    collinear = write("collinear1.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 2 0\n0 0\n0\n")
    p = mesh_ok(collinear, what="collinear points in a 1-based file")
    check("collinear" in p.stderr and "count from 0" not in p.stderr,
          "a warning that names no numbered item gets no numbering note", repr(p.stderr))
    # A legacy file's second SCALARS or VECTORS section is read as ParaView's
    # reader reads it (a review: only the first of each kind reached the mesh).
    sections = out("sections.vtk")
    with open(sections, "w") as f:
        f.write("# vtk DataFile Version 3.0\ntwo of a kind\nASCII\nDATASET POLYDATA\n"
                "POINTS 4 double\n0 0 0\n1 0 0\n1 1 0\n0 1 0\nLINES 1 6\n5 0 1 2 3 0\n"
                "POINT_DATA 4\nSCALARS temperature double 1\nLOOKUP_TABLE default\n1 2 3 4\n"
                "SCALARS pressure double 1\nLOOKUP_TABLE default\n10 20 30 40\n"
                "VECTORS wind double\n1 0 0 1 0 0 1 0 0 1 0 0\n"
                "VECTORS current double\n0 1 0 0 1 0 0 1 0 0 1 0\n")
    for ext in (".vtp", ".vtu"):
        mesh_ok(sections, "-o", out("sections" + ext))
        names = array_names(out("sections" + ext), "PointData")
        check({"temperature", "pressure", "wind", "current"} <= names,
              "every SCALARS and VECTORS section of a legacy input reaches the %s mesh" % ext,
              str(sorted(names)))
    # A NaN coordinate in a .vtk input.
    # Binary legacy file: VTK's ASCII parser would refuse the word "nan" itself.
    nan_vtk = out("nan.vtk")
    with open(nan_vtk, "wb") as f:
        f.write(b"# vtk DataFile Version 3.0\nNaN point\nBINARY\nDATASET POLYDATA\n"
                b"POINTS 3 double\n")
        f.write(struct.pack(">9d", 0, 0, 0, float("nan"), 1, 0, 1, 0, 0))
        f.write(b"\nLINES 1 4\n")
        f.write(struct.pack(">4i", 3, 0, 1, 2))
        f.write(b"\n")
    p = expect_error([nan_vtk], 1, ["point 1"], "NaN coordinate in a .vtk input")
    check("nan" in p.stderr.lower() and "unrecognized" not in p.stderr.lower(),
          "NaN coordinate: the mesher's message names the NaN", p.stderr)
    not_polydata = write("grid.vtk", "# vtk DataFile Version 3.0\ngrid\nASCII\n"
                         "DATASET STRUCTURED_POINTS\nDIMENSIONS 2 2 1\nORIGIN 0 0 0\nSPACING 1 1 1\n")
    expect_error([not_polydata], 1, ["not a legacy VTK polydata or unstructured grid"],
                 ".vtk that is neither polydata nor an unstructured grid")
    garbage = write("garbage.vtp", "this is not XML\n")
    expect_error([garbage], 1, ["cannot read '%s': " % garbage, "XML"], "malformed .vtp")
    # An unwritable output.
    expect_error([data("square_hole.poly"), "-o", out("no/such/dir/x.vtp")], 1,
                 ["cannot write '%s'" % out("no/such/dir/x.vtp")],
                 "unwritable .vtp output")
    expect_error([data("square_hole.poly"), "-o", out("no/such/dir/x.node")], 1, ["x"],
                 "unwritable .node output")
    expect_error([data("square_hole.poly"), "--svg", out("no/such/dir/x.svg")], 1, ["x.svg"],
                 "unwritable --svg output")
    # Said before meshing, so no output is left of a run that failed (the
    # .vtp was written, then the --svg failed).
    if os.path.exists(out("before-svg.vtp")):
        os.remove(out("before-svg.vtp"))
    expect_error([data("square_hole.poly"), "-o", out("before-svg.vtp"), "--svg",
                  out("no/such/dir/x.svg")], 1,
                 ["cannot write '%s': No such file or directory ('%s' does not exist" %
                  (out("no/such/dir/x.svg"), out("no/such/dir")), "nothing is meshed or written"],
                 "an --svg into a missing directory beside a good -o")
    check(not os.path.exists(out("before-svg.vtp")),
          "the good -o is not written when the --svg cannot be")
    # A folder or a file the user may not write to fails before meshing too
    # (it failed after). Root may write anywhere: it runs without the
    # capabilities that let it (as nobody, it could not load the build's
    # libraries from a clone under /root, which is 0700: a review), dropped
    # from the inheritable set too (some containers give them there).
    drop = "-dac_override,-dac_read_search"
    as_user = [] if os.geteuid() != 0 else (
        ["setpriv", "--inh-caps=" + drop, "--bounding-set=" + drop]
        if shutil.which("setpriv") else None)
    if as_user and subprocess.run(as_user + ["true"], capture_output=True).returncode != 0:
        as_user = None  # setpriv may not drop them here (no CAP_SETPCAP)
    if as_user is None:
        print("skip  unwritable folders: running as root without setpriv")
    else:
        locked = tempfile.mkdtemp(prefix="osm-locked-")
        os.chmod(locked, 0o755)
        readonly = os.path.join(locked, "readonly.vtp")
        open(readonly, "w").close()
        os.chmod(readonly, 0o444)
        inside = os.path.join(locked, "folder")
        os.mkdir(inside, 0o555)
        writable = tempfile.mkdtemp(prefix="osm-open-")
        os.chmod(writable, 0o777)
        good = os.path.join(writable, "good.vtp")
        for args, why in (
                (["-o", os.path.join(inside, "x.vtp")],
                 "Permission denied (in '%s'); nothing is meshed or written" % inside),
                (["-o", readonly], "cannot write '%s': Permission denied; nothing" % readonly),
                (["-o", good, "--svg", os.path.join(inside, "x.svg")],
                 "x.svg': Permission denied (in '%s'); nothing is meshed" % inside)):
            p = subprocess.run(as_user + [ARGS.cli, os.path.abspath(data("square_hole.poly"))] +
                               args, capture_output=True, text=True, timeout=600)
            check(p.returncode == 1 and why in p.stderr and not os.path.exists(good) and
                  os.listdir(inside) == [] and os.path.getsize(readonly) == 0,
                  "an output the user may not write fails before meshing: %s" % " ".join(args),
                  p.stderr[-400:])
        shutil.rmtree(locked)
        shutil.rmtree(writable)
    # As the system resolves the path (a review: "missing/../x" passed the
    # check, normalised), and a file where the directory should be.
    expect_error([data("square_hole.poly"), "-o", out("no-such/../x.vtp")], 1,
                 ["does not exist", "nothing is meshed or written"], "an output through missing/..")
    expect_error([data("square_hole.poly"), "-o", os.path.join(data("square_hole.poly"), "x.vtp")],
                 1, ["Not a directory", "is not a directory; nothing is meshed or written"],
                 "an output under a file")
    # Usage errors come first, with their own status (a review: status 1 for
    # the output's folder hid the wrong input extension).
    expect_error([out("input.txt"), "-o", out("no/such/dir/x.vtp")], 2,
                 ["the input must end in"], "a wrong input extension and a missing directory")
    # A write that fails half way (a full disk, here a file size limit) says
    # why in one line and leaves no partial file (a review: VTK's pipeline
    # report, and a partial file left behind).
    os.makedirs(out("dir.vtp"), exist_ok=True)
    expect_error([data("square_hole.poly"), "-o", out("dir.vtp")], 1,
                 ["cannot write '%s': Is a directory" % out("dir.vtp")], "a directory as output")
    check(os.path.isdir(out("dir.vtp")), "the directory is left as it was")

    # SIGXFSZ keeps its default action, as under a shell's `ulimit -f` (a
    # review: it killed osm-mesh mid-write, with no message and the partial
    # file left): osm-mesh ignores it itself.
    def small_files():
        import resource
        resource.setrlimit(resource.RLIMIT_FSIZE, (200, 200))
    full = ("File too large", "out of disk space, or over the file size limit")
    for ext, whys in ((".vtp", full), (".vtu", full), (".vtk", full),
                      (".node", ("limited.node: File too large", "limited.ele: File too large")),
                      (".svg", ("limited.svg': File too large (the partial file is removed",))):
        target = out("limited" + ext)
        option = "--svg" if ext == ".svg" else "-o"
        p = subprocess.run([ARGS.cli, data("square_hole.poly"), option, target],
                           capture_output=True, text=True, timeout=600, preexec_fn=small_files)
        errors = [l for l in p.stderr.splitlines() if not l.startswith("osm-mesh: warning: ")]
        check(p.returncode == 1 and len(errors) == 1 and any(w in errors[0] for w in whys),
              "a %s write over the file size limit fails in one line" % ext, p.stderr[-400:])
        left = [f for f in os.listdir(ARGS.out) if "limited" in f]
        check(not left, "no partial %s file is left, nor a hidden one" % ext, str(left))
    # An output written before is kept whole when the write over it fails (a
    # review: Ctrl-C or a file size limit left a partial file in its place),
    # with its permissions after one that succeeds.
    for ext in (".vtp", ".svg"):
        target = out("kept" + ext)
        with open(target, "w") as f:
            f.write("the old file\n")
        os.chmod(target, 0o640)
        option = "--svg" if ext == ".svg" else "-o"
        p = subprocess.run([ARGS.cli, data("square_hole.poly"), option, target],
                           capture_output=True, text=True, timeout=600, preexec_fn=small_files)
        check(p.returncode == 1 and "the old one is kept" in p.stderr,
              "a %s write over an old file that fails says the old one is kept" % ext,
              p.stderr[-300:])
        with open(target) as f:
            check(f.read() == "the old file\n", "the old %s file is kept whole" % ext)
        left = [f for f in os.listdir(ARGS.out) if "kept" + ext in f and f != "kept" + ext]
        check(not left, "no temporary file is left beside the old %s" % ext, str(left))
        mesh_ok(data("square_hole.poly"), option, target)
        check(os.stat(target).st_mode & 0o777 == 0o640 and os.path.getsize(target) > 1000,
              "a %s write over an old file keeps its permissions" % ext,
              oct(os.stat(target).st_mode))
    # Where a new file would lose what the old one has, it is written in place
    # (a review): a hard link keeps sharing it; a link loop is refused as
    # before, not replaced by a file.
    linked = out("hard.vtp")
    mesh_ok(data("square_hole.poly"), "-o", linked)
    os.link(linked, out("hard-too.vtp"))
    mesh_ok(data("square_hole.poly"), "--min-angle", "20", "-o", linked)
    check(os.stat(linked).st_nlink == 2 and
          read_bytes(linked) == read_bytes(out("hard-too.vtp")),
          "a file with another hard link is written in place, the link sharing the new mesh")
    # Another owner or group would be lost by a new file: root (who may write
    # over another's file) writes such a file in place.
    if os.geteuid() == 0:
        for owner, group, whose in ((65534, 65534, "another user's"), (0, 65534, "another group's")):
            theirs = out("theirs.vtp")
            with open(theirs, "w") as f:
                f.write("their old file\n")
            os.chown(theirs, owner, group)
            mesh_ok(data("square_hole.poly"), "-o", theirs)
            info = os.stat(theirs)
            check((info.st_uid, info.st_gid) == (owner, group) and info.st_size > 1000,
                  "%s file is written in place, keeping its owner and group" % whose,
                  "%d:%d, %d bytes" % (info.st_uid, info.st_gid, info.st_size))
            os.remove(theirs)
    else:
        print("skip  another owner's output: not running as root")
    os.symlink("loop-b.vtp", out("loop-a.vtp"))
    os.symlink("loop-a.vtp", out("loop-b.vtp"))
    expect_error([data("square_hole.poly"), "-o", out("loop-a.vtp")], 1,
                 ["Too many levels of symbolic links"], "an output through a link loop")
    check(os.path.islink(out("loop-a.vtp")), "a link loop stays a link")
    interrupted_write()
    p = subprocess.run([ARGS.cli, data("square_hole.poly"), "-o", out("limited.vtp"), "--stats"],
                       capture_output=True, text=True, timeout=600, preexec_fn=small_files)
    check(p.returncode == 1 and '"ok": false' in p.stdout and "file size limit" in p.stdout,
          "--stats prints its JSON when a write goes over the file size limit", p.stdout[-400:])
    # Through a symbolic link the partial file is the link's target: it goes,
    # the link stays (a review: the link went, the partial target stayed).
    for name in ("linked.vtp", "linked-target.vtp"):
        if os.path.lexists(out(name)):
            os.remove(out(name))
    os.symlink("linked-target.vtp", out("linked.vtp"))
    subprocess.run([ARGS.cli, data("square_hole.poly"), "-o", out("linked.vtp")],
                   capture_output=True, text=True, timeout=600, preexec_fn=small_files)
    check(os.path.islink(out("linked.vtp")) and not os.path.exists(out("linked-target.vtp")),
          "a write through a link that fails removes the partial target, not the link")
    # The same for .node files (a second review: the links went, their files
    # stayed rewritten), one of them a link to a file out of reach of the limit.
    for name in ("nlinked.node", "nlinked.ele", "nlinked.edge", "nlinked-target.node"):
        if os.path.lexists(out(name)):
            os.remove(out(name))
    os.symlink("nlinked-target.node", out("nlinked.node"))
    os.symlink("/dev/full", out("nlinked.ele"))
    p = subprocess.run([ARGS.cli, data("square_hole.poly"), "-o", out("nlinked.node")],
                       capture_output=True, text=True, timeout=600)
    check(p.returncode == 1 and "nlinked.ele: No space left on device" in p.stderr,
          ".node through a link to a full device: fails naming the file and why", p.stderr[-400:])
    check(os.path.islink(out("nlinked.node")) and os.path.islink(out("nlinked.ele")) and
          not os.path.exists(out("nlinked-target.node")) and
          not os.path.lexists(out("nlinked.edge")),
          "a failed .node write removes the files it wrote through the links, not the links")
    # An --svg that fails after a good -o says the mesh file is kept, and keeps it.
    for name in ("svgkept.vtp", "svgfull.svg"):
        if os.path.lexists(out(name)):
            os.remove(out(name))
    os.symlink("/dev/full", out("svgfull.svg"))
    p = subprocess.run([ARGS.cli, data("square_hole.poly"), "-o", out("svgkept.vtp"),
                        "--svg", out("svgfull.svg")], capture_output=True, text=True, timeout=600)
    check(p.returncode == 1 and "No space left on device" in p.stderr and
          "the mesh is written to '%s'" % out("svgkept.vtp") in p.stderr and
          os.path.getsize(out("svgkept.vtp")) > 0 and os.path.islink(out("svgfull.svg")),
          "an --svg failing after a good -o names the mesh file it kept, and keeps it",
          p.stderr[-400:])

    square = data("square_hole.poly")
    bad = [
        ([], ["no input file"]),
        ([square, square], ["more than one input"]),
        ([square, "-o", "a.vtp", "--output", "b.vtp"], ["more than one output file: 'a.vtp' and 'b.vtp'"]),
        ([square, "--frobnicate"], ["unknown option '--frobnicate'"]),
        ([square, "--min-angle"], ["--min-angle needs a value"]),
        # Found by a user review: this wrote an SVG file named --stats.
        ([square, "--svg", "--stats"], ["--svg needs a value, not the option --stats"]),
        ([square, "-o", "--max-edge", "1"], ["-o needs a value, not the option --max-edge"]),
        ([square, "--min-angle", "abc"], ["--min-angle", "'abc'"]),
        ([square, "--min-angle", "50"], ["--min-angle must be between 1 and 35"]),
        ([square, "--min-angle", "0.5"], ["--min-angle must be between 1 and 35"]),
        ([square, "--min-angle", "nan"], ["--min-angle"]),
        ([square, "--gamma", "0.5"], ["--gamma must be between"]),
        ([square, "--gamma", "100"], ["--gamma must be between"]),
        ([square, "--gamma", "-1"], ["--gamma must be between"]),
        ([square, "--min-angle", "30", "--gamma", "1"], ["--min-angle and --gamma"]),
        ([square, "--domain", "everywhere"], ["--domain", "'everywhere'"]),
        ([square, "--max-edge", "-1"], ["--max-edge"]),
        ([square, "--max-edge", "inf"], ["--max-edge"]),
        ([square, "--max-edge", "0x10"], ["--max-edge: expected a number, got '0x10'"]),
        ([square, "--merge-tolerance", "0X1p-3"], ["--merge-tolerance", "'0X1p-3'"]),
        ([square, "--merge-tolerance", "-0.1"], ["--merge-tolerance"]),
        ([square, "--max-steiner", "-3"], ["--max-steiner", "'-3'"]),
        ([square, "--max-steiner", "2.5"], ["--max-steiner"]),
        ([square, "--no-resolve=yes"], ["--no-resolve takes no value"]),
        ([square, "--region-areas=1"], ["--region-areas takes no value"]),
        ([square, "-o", out("mesh.txt")], ["mesh.txt", ".vtp, .vtu, .vtk or .node"]),
        ([out("input.txt")], ["input.txt", ".poly, .node, .vtp, .vtu or .vtk"]),
    ]
    for args, fragments in bad:
        expect_error(args, 2, fragments, "bad command line " + " ".join(
            os.path.basename(a) if os.sep in a else a for a in args))
    check(not os.path.exists(out("mesh.txt")), "a refused output is not created")
    check(not os.path.exists("--stats") and not os.path.exists(out("--stats")),
          "no file is named after the option that followed --svg")
    # A subnormal value is a number (it was refused as out of range), here too small.
    expect_error([square, "-o", out("tiny.vtp"), "--max-edge", "1e-310"], 1,
                 ["the maximum edge length is too small"], "a subnormal --max-edge")
    expect_error([square, "--max-edge", "1e-400"], 2, ["1e-400 is not a finite number in range"],
                 "a --max-edge that rounds to 0")
    # The input is never overwritten.
    points = out("points.node")
    shutil.copy(data("split_pslg.node"), points)
    before = read_bytes(points)
    expect_error([points, "-o", points], 2, ["is the input file"], "-o naming the input")
    expect_error([points, "--svg", points], 2, ["is the input file"], "--svg naming the input")
    check(read_bytes(points) == before, "the input file is left as it was")
    # Nor the .node file a .poly reads its vertices from (found by a user
    # review: the second run meshed the first run's output), nor one output
    # over another.
    poly = out("points.poly")
    shutil.copy(data("split_pslg.poly"), poly)
    expect_error([poly, "-o", points], 2, ["points.node", "the .node file the input reads its vertices from"],
                 "-o naming the .node file beside a .poly input")
    check(read_bytes(points) == before, "the .node file beside the input is left as it was")
    # Its zero written as the reader reads it, with CR line ends too (a review:
    # '.0' and a CR-only file had their .node overwritten).
    with open(data("split_pslg.poly"), "rb") as f:
        body = f.read()
    for name, text in (("dot-zero", re.sub(rb"(?m)^0 ", b".0 ", body, count=1)),
                       ("cr-only", body.replace(b"\r\n", b"\n").replace(b"\n", b"\r"))):
        shutil.copy(points, out(name + ".node"))
        with open(out(name + ".poly"), "wb") as f:
            f.write(text)
        expect_error([out(name + ".poly"), "-o", out(name + ".node")], 2,
                     ["the .node file the input reads its vertices from"],
                     "-o naming the .node beside a %s .poly" % name)
        check(read_bytes(out(name + ".node")) == before, "the %s .poly's .node is kept" % name)
    # A .poly that lists its vertices, after a UTF-8 byte order mark, reads
    # no .node: one of the same name is an output like any other (a user
    # review: it was refused as the input's vertices).
    bom = out("bom.poly")
    with open(bom, "wb") as f:
        f.write(b"\xef\xbb\xbf4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n")
    shutil.copy(data("split_pslg.node"), out("bom.node"))
    mesh_ok(bom, "-o", out("bom.node"), what="a .poly with a byte order mark, -o its own .node name")
    check(read_bytes(out("bom.node")).startswith(b"4 2 0 1\n"), "the .node written is the mesh's")
    expect_error([poly, "-o", out("twice.vtp"), "--svg", os.path.join(ARGS.out, ".", "twice.vtp")],
                 2, ["twice.vtp", "written twice"], "-o and --svg naming the same file")
    check(not os.path.exists(out("twice.vtp")), "a file named twice is not written")
    dangling = out("dangling.svg")
    if os.path.lexists(dangling):
        os.remove(dangling)
    os.symlink("twice.vtp", dangling)
    expect_error([poly, "-o", out("twice.vtp"), "--svg", dangling], 2, ["written twice"],
                 "-o and --svg naming one file through a dangling symbolic link")
    # --stats when meshing fails: JSON with "ok": false, the error and the
    # warnings (found by a user review: it printed nothing).
    all_hole = write("allhole.poly", "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n"
                                     "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n1\n1 0.5 0.5\n")
    p = run(all_hole, "--stats")
    try:
        failed = json.loads(p.stdout)
    except ValueError:
        failed = {}
    check(p.returncode == 1 and failed.get("ok") is False and "empty" in failed.get("Error", "") and
          any("removed every region" in w for w in failed.get("Warnings", [])),
          "--stats on a failure prints ok false, the error and the warnings", p.stdout[-300:])
    # ... the mesher's warnings too, from before it stopped (a second review).
    twice = write("twice-capped.poly", "5 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 1 0\n"
                                       "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n")
    p = run(twice, "--stats", "--max-steiner", "5")
    try:
        failed = json.loads(p.stdout)
    except ValueError:
        failed = {}
    check(p.returncode == 1 and failed.get("ok") is False and
          any("duplicate point" in w for w in failed.get("Warnings", [])),
          "--stats on a failure keeps the mesher's warnings from before it stopped",
          p.stdout[-300:])
    # ... and where the output cannot be written (a CLI review: none was printed).
    p = run(poly, "-o", out(os.path.join("no-such-folder", "x.vtp")), "--stats")
    try:
        failed = json.loads(p.stdout)
    except ValueError:
        failed = {}
    check(p.returncode == 1 and failed.get("ok") is False and
          "cannot write" in failed.get("Error", ""),
          "--stats with an output folder that does not exist prints ok false and the error",
          p.stdout[-300:])


def group_determinism():
    inputs = [data("square_hole.poly"), data("crossing.poly"), data("wedge.vtk")]
    for source in inputs:
        name = os.path.splitext(os.path.basename(source))[0]
        files = {}
        for run_no in (1, 2):
            d = out("run%d" % run_no)
            os.makedirs(d, exist_ok=True)
            for ext in ("vtp", "vtu", "vtk"):
                mesh_ok(source, "-o", os.path.join(d, name + "." + ext), what="%s run %d .%s" % (name, run_no, ext))
            mesh_ok(source, "-o", os.path.join(d, name + ".node"), "--svg",
                    os.path.join(d, name + ".svg"), what="%s run %d .node + .svg" % (name, run_no))
            files[run_no] = d
        for ext in ("vtp", "vtu", "vtk", "node", "ele", "edge", "svg"):
            a = os.path.join(files[1], name + "." + ext)
            b = os.path.join(files[2], name + "." + ext)
            check(read_bytes(a) == read_bytes(b), "%s.%s byte-identical over two runs" % (name, ext))


def group_reference():
    cases = [(data("square_hole.poly"), []), (data("crossing.poly"), []),
             (data("wedge.vtk"), []), (data("square_hole.poly"), ["--domain", "box"])]
    domain_number = {"auto": "0", "enclosed": "1", "hull": "2", "box": "3"}
    for i, (source, options) in enumerate(cases):
        name = "%s-%d" % (os.path.splitext(os.path.basename(source))[0], i)
        cli_out = out(name + "-cli.vtp")
        cxx_out = out(name + "-cxx.vtp")
        mesh_ok(source, "-o", cli_out, *options)
        helper_options = []
        if options:
            helper_options = ["--domain", domain_number[options[1]]]
        p = subprocess.run([ARGS.helper, "reference", source, cxx_out] + helper_options,
                           capture_output=True, text=True, timeout=600)
        check(p.returncode == 0, "C++ pipeline on " + name, p.stderr[-500:])
        check(read_bytes(cli_out) == read_bytes(cxx_out),
              "osm-mesh .vtp == C++ reader -> mesher -> vtkXMLPolyDataWriter (%s)" % name)


def group_realdata():
    if not os.path.isdir(ARGS.shared):
        print("skip: %s is absent" % ARGS.shared)
        sys.exit(77)
    names = sorted(n for n in os.listdir(ARGS.shared) if n.endswith(".poly"))
    # The big ones are meshed by the core's own real-data test; keep this one quick.
    small = [n for n in names if os.path.getsize(os.path.join(ARGS.shared, n)) < 400000]
    if not small:
        print("skip: no .poly in %s" % ARGS.shared)
        sys.exit(77)
    for n in small:
        source = os.path.join(ARGS.shared, n)
        base = out(os.path.splitext(n)[0])
        s = stats_of(source, "-o", base + ".node")
        if not s:
            continue
        v, t, _ = read_triangle_files(base)
        check(len(t) == s.get("OutputTriangles"), n + ": --stats matches the .ele")
        check(s.get("MaxAngleDeg", 999) <= 170.0, n + ": no angle above 170 degrees",
              str(s.get("MaxAngleDeg")))
        validate(source, base + ".node", "--allow-missing", what=n + ": mesh valid")
    # The adversarial review's case: a mesh made with a merge tolerance bends
    # segments within it, which the validator allows when told.
    img5 = os.path.join(ARGS.shared, "img5.poly")
    if os.path.exists(img5):
        mesh_ok(img5, "--merge-tolerance", "1e-3", "-o", out("img5-tol.node"))
        validate(img5, out("img5-tol.node"), "--merge-tolerance", "1e-3",
                 what="img5.poly with --merge-tolerance 1e-3: mesh valid within it")


def on_segments(poly, a, b):
    """Whether points a and b both lie on one segment of the .poly file poly."""
    rows = [l.split("#", 1)[0].split() for l in open(poly)]
    rows = [r for r in rows if r]
    n, first = int(rows[0][0]), int(rows[1][0])
    points = {int(r[0]) - first: (float(r[1]), float(r[2])) for r in rows[1:n + 1]}
    for r in rows[n + 2:n + 2 + int(rows[n + 1][0])]:
        p, q = points[int(r[1]) - first], points[int(r[2]) - first]
        length = math.dist(p, q)
        on = lambda x: (abs((q[0] - p[0]) * (x[1] - p[1]) - (q[1] - p[1]) * (x[0] - p[0]))
                        <= 1e-9 * length * length and
                        -1e-9 <= (x[0] - p[0]) * (q[0] - p[0]) + (x[1] - p[1]) * (q[1] - p[1])
                        <= length * length * (1 + 1e-9))
        if on(a) and on(b):
            return True
    return False


def poly_text(points, segments, holes=()):
    """A 0-based .poly file: points (x, y), segments (a, b), hole seeds (x, y)."""
    lines = ["%d 2 0 0" % len(points)]
    lines += ["%d %r %r" % (i, x, y) for i, (x, y) in enumerate(points)]
    lines += ["%d 0" % len(segments)]
    lines += ["%d %d %d" % (i, a, b) for i, (a, b) in enumerate(segments)]
    lines += ["%d" % len(holes)]
    lines += ["%d %r %r" % (i, x, y) for i, (x, y) in enumerate(holes)]
    return "\n".join(lines) + "\n"


def legacy_vtk(path, points, cells_keyword, cells):
    """An ASCII legacy polydata file with 3D points and one kind of cell."""
    with open(path, "w") as f:
        f.write("# vtk DataFile Version 3.0\nmatrix row\nASCII\nDATASET POLYDATA\n")
        f.write("POINTS %d double\n" % len(points))
        f.write("".join("%r %r %r\n" % p for p in points))
        f.write("%s %d %d\n" % (cells_keyword, len(cells), sum(len(c) + 1 for c in cells)))
        f.write("".join("%d %s\n" % (len(c), " ".join(str(i) for i in c)) for c in cells))
    return path


def matrix_row(name, source, *options, stats=None, warnings=(), validate_extra=("--allow-missing",)):
    """One row of the bad-input matrix that must mesh: exit 0, the expected
    warnings and statistics, and a mesh the independent validator accepts."""
    mesh = out("matrix-%s.node" % name)
    p = run(source, "-o", mesh, "--stats", *options)
    errors = [l for l in p.stderr.splitlines() if not l.startswith("osm-mesh: warning: ")]
    if not check(p.returncode == 0 and not errors, name + ": meshed",
                 "status %d, stderr %r" % (p.returncode, p.stderr[-400:])):
        return {}
    result = json.loads(p.stdout)
    for fragment in warnings:
        check(fragment in p.stderr, name + ": a warning says %r" % fragment, repr(p.stderr))
    for key, expected in (stats or {}).items():
        check(result.get(key) == expected, name + ": %s = %r" % (key, expected),
              repr(result.get(key)))
    check(result.get("OutputTriangles", 0) > 0 and result.get("MaxAngleDeg", 180) <= 170,
          name + ": triangles, none with an angle above 170 degrees",
          "%r triangles, max angle %r" % (result.get("OutputTriangles"), result.get("MaxAngleDeg")))
    validate(source, mesh, *validate_extra, what=name + ": the validator accepts the mesh")
    return result


def group_matrix():
    """The bad-input matrix of issue 6 through osm-mesh: every row meshes with
    its documented repair counted and said, or fails with one clear line."""
    def write(name, text):
        path = out(name)
        with open(path, "w") as f:
            f.write(text)
        return path

    square = [(0, 0), (10, 0), (10, 10), (0, 10)]
    ring = [(0, 1), (1, 2), (2, 3), (3, 0)]
    # NaN and infinity in a .poly are refused by the reader with the line.
    expect_error([write("m-nan.poly", poly_text(square, ring).replace("10 10", "nan 10", 1))], 1,
                 ["m-nan.poly:4:"], "NaN coordinate in a .poly")
    expect_error([write("m-inf.poly", poly_text(square, ring).replace("3 0 10", "3 0 inf", 1))], 1,
                 ["m-inf.poly:5:", "not a finite number"], "infinite coordinate in a .poly")
    # Exact duplicates are merged; near duplicates only within --merge-tolerance.
    matrix_row("exact-duplicate", write("m-dup.poly", poly_text(square + [(10, 10)], ring + [(1, 4)])),
               stats={"DuplicatePointsMerged": 1}, warnings=["merged 1 duplicate point"],
               validate_extra=())
    near = write("m-near.poly", poly_text(square + [(5, 5), (5, 5 + 1e-9)], ring))
    r = matrix_row("near-duplicate-kept", near, stats={"DuplicatePointsMerged": 0},
                   validate_extra=())
    matrix_row("near-duplicate-merged", near, "--merge-tolerance", "1e-6",
               stats={"DuplicatePointsMerged": 1}, warnings=["merged 1 duplicate point"])
    # A point within the merge tolerance of a segment bends the segment
    # through it: the validator told the tolerance accepts the bend, and
    # refuses it when not told (an adversarial review: meshes made with a
    # tolerance could not be validated).
    bent = write("m-bent.poly", poly_text(square + [(5, 1e-4), (5, 5)], ring + [(4, 5)]))
    matrix_row("point-bends-segment", bent, "--merge-tolerance", "1e-3",
               warnings=["split segments 1 time(s)"],
               validate_extra=("--merge-tolerance", "1e-3"))
    p = subprocess.run([ARGS.helper, "validate", bent, out("matrix-point-bends-segment.node")],
                       capture_output=True, text=True, timeout=600)
    check(p.returncode != 0 and "segment 0 (input points 0, 1) is not a chain" in p.stdout,
          "point-bends-segment: the validator without the tolerance refuses the bend",
          p.stdout[-400:])
    matrix_row("zero-length", write("m-zero.poly", poly_text(square, ring + [(2, 2)])),
               stats={"ZeroLengthSegmentsDropped": 1}, warnings=["zero-length segment"],
               validate_extra=())
    # Crossing segments: split (said and counted), or refused naming both.
    crossing = write("m-cross.poly", poly_text(square, ring + [(0, 2), (1, 3)]))
    matrix_row("crossing-split", crossing, stats={"CrossingsSplit": 1},
               warnings=["split 1 crossing", "input segment 4 and input segment 5"],
               validate_extra=())
    expect_error([crossing, "--no-resolve"], 1, ["input segment 4 and input segment 5 cross"],
                 "crossing segments refused with --no-resolve")
    # Collinear overlapping segments, and a vertex lying on a segment.
    overlap = square + [(2, 5), (6, 5), (4, 5), (8, 5)]
    matrix_row("collinear-overlap", write("m-overlap.poly", poly_text(overlap, ring + [(4, 5), (6, 7)])),
               validate_extra=())
    matrix_row("vertex-on-segment", write("m-tee.poly", poly_text(square + [(5, 0)], ring)),
               validate_extra=())
    # Degenerate point sets: the padded box is meshed instead of an empty hull.
    for name, pts, segs in (("one-point", [(1, 2)], []), ("two-points", [(1, 2), (4, -1)], [(0, 1)]),
                            ("collinear", [(0, 0), (1, 2), (2, 4), (3, 6)], [(0, 3)])):
        matrix_row(name, write("m-%s.poly" % name, poly_text(pts, segs)),
                   warnings=["one point", "padded box around it"] if len(pts) == 1 else
                   ["collinear", "bounding box"], validate_extra=())
    # Empty input (a .node file without points; a .poly without points takes
    # them from its .node, as in Triangle): the core returns an empty mesh with
    # a warning; osm-mesh says so and, having nothing to write, exits with 1.
    p = expect_error([write("m-empty.node", "0 2 0 0\n"), "-o", out("matrix-empty.vtp")], 1,
                     ["is empty"], "empty input")
    check("osm-mesh: warning: the input has no points" in p.stderr,
          "empty input: the warning says the input has no points", repr(p.stderr))
    # 10,000 segments through one vertex.
    n = 10000
    hub = [(0.0, 0.0)] + [(math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n))
                          for k in range(n)]
    matrix_row("10000-spokes", write("m-hub.poly", poly_text(hub, [(0, k) for k in range(1, n + 1)])),
               "--domain", "hull", validate_extra=())
    # Extreme magnitudes: meshed correctly at 1e300, a clear refusal for a 1e-300 spread.
    big = [(x * 1e300, y * 1e300) for x, y in ((0, 0), (1, 0), (1, 1), (0, 1), (0.3, 0.6))]
    matrix_row("magnitude-1e300", write("m-big.poly", poly_text(big, ring)), validate_extra=())
    expect_error([write("m-spread.poly", poly_text([(0, 0), (1, 0), (1e-300, 1e-300), (0, 1)], []))],
                 1, ["point 2", "exact arithmetic"], "a spread of 1e-300")
    # Cells that give no segment, and points off one plane (.vtk input).
    strips = legacy_vtk(out("m-strip.vtk"), [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)],
                        "TRIANGLE_STRIPS", [(0, 1, 2, 3)])
    matrix_row("triangle-strip", strips, warnings=["Ignored 1 input cell", "triangle strip"],
               validate_extra=())
    tilted = legacy_vtk(out("m-3d.vtk"), [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 1)],
                        "LINES", [(0, 1, 2, 3, 0)])
    expect_error([tilted], 1, ["not coplanar: point", "from their best-fitting plane",
                               "ProjectToXYPlane", "--project-xy"], "points off one plane")
    matrix_row("project-xy", tilted, "--project-xy",
               warnings=["projected onto the XY plane", "mean z"], validate_extra=())
    # Coplanar points in the plane x = 0: meshed in that plane, which the 2D
    # outputs (.node, --svg) cannot hold; the 3D formats can.
    wall = legacy_vtk(out("m-wall.vtk"), [(0, 0, 0), (0, 4, 0), (0, 4, 3), (0, 0, 3)],
                      "LINES", [(0, 1, 2, 3, 0)])
    for target in (["-o", out("m-wall.node")], ["--svg", out("m-wall.svg")]):
        expect_error([wall] + target, 1, ["not z = constant", "--project-xy", ".vtp"],
                     "a mesh in the plane x = 0 to " + target[1].rsplit(".", 1)[1])
        check(not os.path.exists(target[1]), "no %s written for it" % target[1])
    wall_stats = stats_of(wall, "-o", out("m-wall.vtp"))
    check(wall_stats.get("InputPlaneFitted") == 1 and wall_stats.get("OutputTriangles", 0) > 0,
          "the mesh in the plane x = 0 is written to .vtp", repr(wall_stats)[:300])



def main():
    global ARGS
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("group")
    parser.add_argument("--cli", required=True)
    parser.add_argument("--helper", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--shared", required=True)
    parser.add_argument("--out", required=True)
    ARGS = parser.parse_args()
    groups = {
        "help": group_help, "options": group_options, "formats": group_formats,
        "inputs": group_inputs, "errors": group_errors, "determinism": group_determinism,
        "reference": group_reference, "realdata": group_realdata, "matrix": group_matrix,
    }
    if ARGS.group not in groups:
        parser.error("unknown group " + ARGS.group)
    shutil.rmtree(ARGS.out, ignore_errors=True)
    os.makedirs(ARGS.out)
    groups[ARGS.group]()
    print("%d failure(s)" % len(FAILURES))
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
