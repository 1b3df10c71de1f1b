#!/usr/bin/env python3
"""Meshing with a maximum edge length: the OSM core against CGAL's Mesh_2 with
the same bound (its size criterion bounds the longest edge of every triangle),
on every .poly of ../shared/data/pslg, the bound a fixed fraction of each
input's extent. Writes Testing/Benchmarks/SIZE_BOUND.md.

    bash Testing/Benchmarks/run.sh --size-bound [size_bound.py options]

builds the drivers (build-bench/bench) and runs this script. The two tools
take turns on each input (one run of each per round), each run in its own
process with a time limit; the figure is the median CPU time of the meshing
call. Mesh_2 runs with its default shape bound (about 20.7 degrees), OSM with
its defaults (no angle above 170 degrees)."""
import argparse
import datetime
import glob
import json
import os
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_benchmarks as rb  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
from poly_rows import poly_rows  # noqa: E402

TOOLS = (("OSM", "bench_osm"), ("Mesh_2", "bench_cgal_mesh2"))


def extent(path):
    """The larger side of the bounding box of a .poly's points (or of the
    .node beside it when the .poly lists none)."""
    rows = poly_rows(path)
    count = int(rows[0][0])
    if count == 0:
        return extent(os.path.splitext(path)[0] + ".node")
    xs = [float(r[1]) for r in rows[1:count + 1]]
    ys = [float(r[2]) for r in rows[1:count + 1]]
    return max(max(xs) - min(xs), max(ys) - min(ys))


def run_once(exe, path, bound, timeout):
    """One driver run: its JSON line, or {"ok": False, "error": why}."""
    try:
        done = subprocess.run([exe, path, "--max-edge", repr(bound)], capture_output=True,
                              text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"ok": False, "error": "no mesh after %g s" % timeout}
    lines = done.stdout.strip().splitlines()
    if done.returncode != 0 or not lines:
        return {"ok": False, "error": (done.stderr.strip() or "exit %d" % done.returncode)[:200]}
    return json.loads(lines[-1])


def measure(bench, path, bound, runs, timeout, run=run_once):
    """Per tool: its runs, taking turns; a tool that fails is not run again."""
    results = {name: [] for name, _ in TOOLS}
    for _ in range(runs):
        for name, exe in TOOLS:
            if results[name] and not results[name][-1].get("ok"):
                continue
            results[name].append(run(os.path.join(bench, exe), path, bound, timeout))
    return results


def summary(runs):
    """Median CPU seconds and the first run's figures, or the failure."""
    if not runs or not all(r.get("ok") for r in runs):
        failed = [r for r in runs if not r.get("ok")]
        return {"error": failed[0].get("error", "failed") if failed else "not run"}
    first = runs[0]
    return {"cpu": statistics.median(r["cpu_seconds"] for r in runs),
            "triangles": first["out_triangles"], "max_angle": first.get("max_angle"),
            "missing": first.get("missing_segments")}


def fmt(s, key, form):
    return form.format(s[key]) if s.get(key) is not None else "—"


def row(name, osm, mesh2):
    """A table row: times, their ratio (or which tool failed, and why)."""
    if osm.get("cpu") and "cpu" in mesh2:
        ratio = "%.2f" % (mesh2["cpu"] / osm["cpu"])
    else:
        ratio = "; ".join(tool + ": " + s["error"]
                          for tool, s in (("OSM", osm), ("Mesh_2", mesh2)) if "error" in s) or "—"
    missing = "%s, %s" % (fmt(osm, "missing", "{}"), fmt(mesh2, "missing", "{}"))
    sizes = "%.2f" % (osm["triangles"] / mesh2["triangles"]) if (
        osm.get("triangles") and mesh2.get("triangles")) else "—"
    return "| " + " | ".join([
        name, fmt(osm, "cpu", "{:.3f}"), fmt(mesh2, "cpu", "{:.3f}"), ratio,
        fmt(osm, "triangles", "{:,}"), fmt(mesh2, "triangles", "{:,}"), sizes,
        fmt(osm, "max_angle", "{:.2f}"), fmt(mesh2, "max_angle", "{:.2f}"), missing]) + " |"


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--build", default=os.path.join(rb.ROOT, "build-bench"))
    p.add_argument("--data", default=os.path.join(rb.ROOT, "..", "shared", "data", "pslg"))
    p.add_argument("--fraction", type=float, default=250,
                   help="the bound is each input's extent over this (default 250)")
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--timeout", type=float, default=120)
    p.add_argument("--output", default=os.path.join(rb.HERE, "SIZE_BOUND.md"))
    args = p.parse_args()
    bench = os.path.join(args.build, "bench")
    for _, exe in TOOLS:
        if not os.access(os.path.join(bench, exe), os.X_OK):
            sys.exit("size_bound.py: %s is not built: run bash Testing/Benchmarks/run.sh "
                     "--size-bound" % os.path.join(bench, exe))
    inputs = sorted(glob.glob(os.path.join(args.data, "*.poly")))
    if not inputs:
        print("size_bound.py: no .poly in %s: nothing to measure" % args.data)
        return 0
    started = datetime.datetime.now(datetime.timezone.utc)
    rows, faster, both, no_mesh2 = [], 0, 0, []
    for path in inputs:
        bound = extent(path) / args.fraction
        res = measure(bench, path, bound, args.runs, args.timeout)
        osm, mesh2 = summary(res["OSM"]), summary(res["Mesh_2"])
        if "cpu" in osm and "cpu" in mesh2:
            both += 1
            faster += mesh2["cpu"] > osm["cpu"]
        elif "cpu" in osm:
            no_mesh2.append(os.path.basename(path))
        rows.append(row(os.path.basename(path), osm, mesh2))
        print(rows[-1], flush=True)
    minutes = (datetime.datetime.now(datetime.timezone.utc) - started).total_seconds() / 60
    lines = [
        "# Meshing with a maximum edge length: OSM and CGAL Mesh_2",
        "",
        "Generated by `bash Testing/Benchmarks/run.sh --size-bound` "
        "(`Testing/Benchmarks/size_bound.py`); do not edit by hand. Run on %s, commit `%s`, %s, "
        "in %.0f minutes." % (started.strftime("%Y-%m-%d %H:%M UTC"), rb.git_commit(),
                              rb.cpu_name(), minutes),
        "",
        "Each input meshed with no edge longer than its extent (the larger side of its "
        "bounding box) / %g: the OSM core with `Options::maxEdgeLength`, CGAL's Mesh_2 with "
        "`Delaunay_mesh_size_criteria_2(0.125, bound)` (its default shape bound, about 20.7 "
        "degrees, and the bound on the longest edge of every triangle), in the same domain. "
        "The tools take turns, %d runs each, every run its own process with a limit of %g s; "
        "*s*: median CPU seconds of the meshing call. *Mesh_2 / OSM* above 1 favours OSM." % (
            args.fraction, args.runs, args.timeout),
        "",
        "OSM is faster on %d of the %d inputs both meshed%s%s." % (
            faster, both,
            "; Mesh_2 gave no mesh of %s" % ", ".join(no_mesh2) if no_mesh2 else "",
            "; OSM gave none of %d (see the table)" % (len(inputs) - both - len(no_mesh2))
            if len(inputs) > both + len(no_mesh2) else ""),
        "",
        "| input | OSM s | Mesh_2 s | Mesh_2 / OSM | OSM triangles | Mesh_2 triangles "
        "| OSM / Mesh_2 triangles | OSM max angle | Mesh_2 max angle "
        "| missing segments: OSM, Mesh_2 |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|",
    ] + rows
    with open(args.output, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote %s" % args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
