#!/usr/bin/python3
"""Run the OSM benchmark suite and write BENCHMARKS.md and benchmarks.png.

Builds nothing: it runs the drivers found in <build>/bench (see CMakeLists.txt
here; Testing/Benchmarks/run.sh configures and builds them). Every tool runs on
every input in its own child process with a time limit, so that a hang or a
crash of any tool is recorded as such and the suite goes on. The first run of a
(tool, input) pair inspects the output (angles, conformity); the repeats only
time it, and the table gives the median.

    run_benchmarks.py [--build DIR] [--data DIR] [--quick] [--report-only]

Python standard library only, plus matplotlib for the plot (skipped, with a
note, if it is missing).
"""

import argparse
import datetime
import json
import mmap
import os
import platform
import resource
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))

# name: (executable, extra arguments, label in tables and the plot)
TOOLS = {
    "osm": ("bench_osm", [], "OSM core"),
    "vtk-osm": ("bench_vtk_osm", [], "OSM VTK filter"),
    "cgal-mesh2": ("bench_cgal_mesh2", [], "CGAL Mesh_2 (0.125)"),
    "cgal-cdt": ("bench_cgal_cdt", [], "CGAL CDT alone"),
    "osm-delaunay": ("bench_osm_delaunay", [], "OSM Delaunay of points"),
    "vtk-delaunay2d": ("bench_vtk_delaunay2d", [], "vtkDelaunay2D"),
    "osm-mesh": ("osm-mesh", [], "osm-mesh CLI (end to end)"),
}
TOOL_ORDER = list(TOOLS)

# The generated families and their sizes (input vertices). Caps, so that the
# whole suite stays affordable on a shared 2-core machine (about 20 minutes):
# spread stops at 3e4 (at 1e5 OSM made 45 million triangles, 8.4 GB, 122 s,
# and Mesh_2 took 100 s); vtkDelaunay2D stops at 2e5 (1e5 segments, 40 s);
# the VTK filter at 1.4e6. The largest sizes make about 1e7 triangles.
FAMILIES = {
    "random-segments": [1000, 10000, 100000, 200000, 1400000],
    "points": [1000, 10000, 100000, 1300000],
    "spread": [1000, 3000, 10000],
}
QUICK_FAMILIES = {
    "random-segments": [1000, 10000],
    "points": [1000, 10000],
    "spread": [1000],
}
SEED = 1
CAPS = {  # tool: largest generated input (vertices) it runs on
    "vtk-delaunay2d": 200000,
    "vtk-osm": 1400000,
}
VTK_TARGET_N = 200000  # random segments of this many vertices: the vtkDelaunay2D target (1e5 segments)
PAIR_RUNS = 5  # OSM runs before the first and after each vtkDelaunay2D run of that target
VTK_OSM_FAMILIES = ("random-segments",)  # the filter's overhead needs one family only
CLI_FAMILIES = ("random-segments",)      # osm-mesh end to end: the same, plus the real inputs

TIMEOUT = 120.0        # CPU seconds per run (RLIMIT_CPU); the wall limit is WALL_FACTOR times it
WALL_FACTOR = 6.0      # the machine is shared: a run may wait for a core that long
RUNS_FAST = 5          # runs when one takes under FAST_SECONDS (CPU)
RUNS = 3               # otherwise: a median of several, even for the slowest runs
FAST_SECONDS = 1.0
REPEAT_BUDGET = 240.0  # no further repeat once runs so far + one more would exceed this (wall)
MEMORY_LIMIT = 12 << 30  # address-space limit of each child (the machine is shared)


# ----------------------------------------------------------------------------- running

CPU_LIMIT = int(TIMEOUT)


def limit_child():
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))
    # SIGXCPU at CPU_LIMIT seconds of CPU time; SIGKILL a little later.
    resource.setrlimit(resource.RLIMIT_CPU, (CPU_LIMIT, CPU_LIMIT + 5))
    os.setsid()  # its own process group, so a time-out kills all of it


GNU_TIME = "/usr/bin/time"


def spawn(cmd, timeout):
    """Runs cmd in its own process group under GNU time (when it is there) with a
    time limit. Returns (status, returncode, stdout, stderr, wall, maxrss bytes or None)."""
    rss_file = None
    if os.access(GNU_TIME, os.X_OK):
        fd, rss_file = tempfile.mkstemp(prefix="osm-bench-rss-")
        os.close(fd)
        cmd = [GNU_TIME, "-f", "%M %U %S", "-o", rss_file] + cmd
    t0 = time.monotonic()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            preexec_fn=limit_child, text=True)
    status = "done"
    try:
        out, err = proc.communicate(timeout=timeout * WALL_FACTOR)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
        status = "timeout"
    wall = time.monotonic() - t0
    maxrss = None
    cpu = None
    code = proc.returncode
    if rss_file:
        try:
            with open(rss_file) as f:
                text = f.read().split()
            os.unlink(rss_file)
            # GNU time reports "Command terminated by signal N" before the figures.
            if len(text) >= 3 and text[-3].isdigit():
                maxrss = int(text[-3]) * 1024
                cpu = float(text[-2]) + float(text[-1])
            if "signal" in text:
                code = -int(text[text.index("signal") + 1])
        except (OSError, ValueError, IndexError):
            pass
    if code == -signal.SIGXCPU or (code == -signal.SIGKILL and cpu and cpu >= CPU_LIMIT):
        status = "timeout"
    return status, code, out, err, wall, (maxrss, cpu)


# This virtual machine's host backs the guest's memory at its first touch and
# takes freed memory back within about 30 seconds (virtio_balloon's free page
# reporting; BENCHMARKS.md, item 47): a run that needs more memory than the runs
# just before it pays the host's first touches too, about 4.4 ms per 2 MiB page
# against 0.13 ms once backed. The scaling pass compares each size with the
# smallest one of its round, whose memory (freed a moment before) is mostly
# backed; so before each of its runs it touches WARM_FACTOR times the size's
# main-pass peak and frees it. The guest does not hand the freed pages out first,
# hence the factor (1.25 times the peak left most of the host's cost).
WARM_FACTOR = 4


def available_bytes():
    try:
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    return 0


def back_memory(nbytes):
    """Touches nbytes of fresh memory (in huge pages where the kernel gives them,
    leaving 2 GiB free), then frees it. Returns the bytes touched."""
    nbytes = min(nbytes, available_bytes() - (2 << 30))
    if nbytes <= 0:
        return 0
    m = mmap.mmap(-1, nbytes, flags=mmap.MAP_PRIVATE | mmap.MAP_ANONYMOUS)
    try:
        if hasattr(mmap, "MADV_HUGEPAGE"):
            m.madvise(mmap.MADV_HUGEPAGE)
        m[::mmap.PAGESIZE] = b"\x01" * len(range(0, nbytes, mmap.PAGESIZE))
    finally:
        m.close()
    return nbytes


def run_once(exe, spec, args, timeout):
    """One child process. Returns a dict: the driver's JSON plus status, wall."""
    if os.path.basename(exe) == "osm-mesh":
        return run_cli(exe, spec, args, timeout)
    load = os.getloadavg()[0]
    status, code, out, err, wall, (maxrss, _) = spawn([exe, spec] + args, timeout)
    if status == "timeout":
        return {"status": "timeout", "wall": wall, "load": load,
                "detail": "no result within %d CPU s (or %d s wall)" % (
                    timeout, timeout * WALL_FACTOR)}
    record = None
    for line in out.splitlines():
        line = line.strip()
        if line.startswith("{"):
            try:
                record = json.loads(line)
            except ValueError:
                pass
    if code < 0:
        name = signal.Signals(-code).name
        return {"status": "crash", "wall": wall, "load": load,
                "detail": "killed by %s; %s" % (name, tail(err))}
    if record is None:
        return {"status": "crash", "wall": wall, "load": load,
                "detail": "exit %d, no result; %s" % (code, tail(err))}
    record["status"] = "ok" if record.get("ok") else "error"
    if not record.get("ok"):
        record["detail"] = record.get("error", "")
    record["wall"] = wall
    record["load"] = load
    if maxrss is not None:
        record["process_maxrss"] = maxrss
    warnings = [l for l in err.splitlines() if "Warning" in l or "ERROR" in l]
    if warnings:
        record["stderr_warnings"] = len(warnings)
        record["stderr_example"] = warnings[0][:200]
    return record


# The osm-mesh command line, end to end: reading the .poly file, meshing, writing
# the mesh. It has no JSON line of its own: the wall time of the process, GNU
# time's peak RSS of the whole process, and the counts read back from what it wrote.
CLI_WORK = None  # folder for generated .poly inputs and the outputs (set by run_suite)


def cli_command(exe, poly, outdir):
    return [exe, poly, "-o", os.path.join(outdir, "mesh.vtp"), "--stats"]


def poly_for(spec):
    """The input as a .poly file: a real input as it is, a generated one written once."""
    if spec.lower().endswith(".poly"):
        return spec
    path = os.path.join(CLI_WORK, spec.replace(":", "_") + ".poly")
    if not os.path.exists(path):
        maker = os.path.join(os.path.dirname(CLI_WORK), "bench_make_poly")
        subprocess.run([maker, spec, path + ".tmp"], check=True)
        os.replace(path + ".tmp", path)
    return path


def cli_counts(outdir, stdout):
    """(vertices, triangles) from what osm-mesh wrote: its statistics JSON if it
    printed one, else the headers of .node/.ele or .vtp/.vtk files."""
    try:
        d = json.loads(stdout)
        if isinstance(d, dict) and "OutputTriangles" in d:
            return d.get("OutputVertices"), d["OutputTriangles"]
    except ValueError:
        pass
    for line in stdout.splitlines():
        line = line.strip()
        if line.startswith("{"):
            try:
                d = json.loads(line)
            except ValueError:
                continue
            for vk, tk in (("outputVertices", "outputTriangles"),
                           ("OutputVertices", "OutputTriangles"),
                           ("output_vertices", "output_triangles")):
                if tk in d:
                    return d.get(vk), d[tk]
    verts = tris = None
    for name in os.listdir(outdir):
        path = os.path.join(outdir, name)
        try:
            if name.endswith(".ele") or name.endswith(".node"):
                with open(path) as f:
                    for line in f:
                        if line.strip() and not line.lstrip().startswith("#"):
                            n = int(line.split()[0])
                            break
                if name.endswith(".ele"):
                    tris = n
                else:
                    verts = n
            elif name.endswith(".vtp"):
                with open(path, "rb") as f:
                    head = f.read(4096).decode("latin-1")
                import re
                m = re.search(r'NumberOfPoints="(\d+)"', head)
                k = re.search(r'NumberOfPolys="(\d+)"', head)
                if m and k:
                    verts, tris = int(m.group(1)), int(k.group(1))
        except (OSError, ValueError, IndexError):
            pass
    return verts, tris


def run_cli(exe, spec, args, timeout):
    load = os.getloadavg()[0]
    record = {"tool": "osm-mesh", "input": spec, "load": load}
    try:
        poly = poly_for(spec)
    except (OSError, subprocess.CalledProcessError) as e:
        record.update(status="error", wall=0.0, detail="writing the input: %s" % e)
        return record
    outdir = tempfile.mkdtemp(prefix="out-", dir=CLI_WORK)
    try:
        status, code, out, err, wall, (maxrss, cpu) = spawn(
            cli_command(exe, poly, outdir), timeout)
        record["wall"] = wall
        if status == "timeout":
            record.update(status="timeout", detail="no result within %d CPU s (or %d s wall)" % (
                timeout, timeout * WALL_FACTOR))
            return record
        if code < 0:
            record.update(status="crash", detail="killed by %s; %s" % (
                signal.Signals(-code).name, tail(err)))
            return record
        if code != 0:
            record.update(status="error", detail="exit %d; %s" % (code, tail(err)))
            return record
        verts, tris = cli_counts(outdir, out)
        if not tris:
            record.update(status="error", detail="no triangle count in its output")
            return record
        record.update(status="ok", ok=True, seconds=wall, cpu_seconds=cpu, out_vertices=verts,
                      out_triangles=tris, process_maxrss=maxrss,
                      input_bytes=os.path.getsize(poly))
        return record
    finally:
        shutil.rmtree(outdir, ignore_errors=True)


def tail(text, n=200):
    text = " ".join(text.split())
    return text[-n:] if text else "no error output"


def paired_ratios(v):
    """Each long run's CPU time over the mean CPU time of the OSM runs paired
    with it: the sets before and after it (paired_bracketed), or in older
    results the set right after it."""
    cpu = v.get("cpu", [])
    if v.get("paired_bracketed"):
        sets = v.get("paired_osm_runs", [])
        return [c / statistics.mean(sets[i] + sets[i + 1])
                for i, c in enumerate(cpu)
                if c and i + 1 < len(sets) and all(sets[i] + sets[i + 1])]
    return [c / p for c, p in zip(cpu, v.get("paired_osm_cpu", [])) if c and p]


class Measurement:
    """One tool's runs on one input: a first run with the output check, then
    timed repeats, one per call of repeat(), so that the tools meshing the same
    input can take turns (a slow phase of the machine, which lasts minutes,
    then falls on all of them alike).
    pair: a bench_osm to run PAIR_RUNS times before the first run and after
    each run, so that each long run is compared with the short runs on both
    sides of it, seconds apart, not minutes (see paired_ratios)."""

    def __init__(self, exe, spec, args, timeout, pair=None):
        self.exe, self.spec, self.args, self.timeout, self.pair = exe, spec, args, timeout, pair
        self.result = {"seconds": [], "cpu": [], "phases": []}
        self.done = False
        self.core = None

    def run_pair(self):
        # PAIR_RUNS runs, their mean: one run of a second samples this machine's
        # speed in that second, where the long run it is paired with averages
        # over a minute (a mean, so the median, lower on a skewed spread, would
        # favour OSM).
        if self.pair:
            cpu = []
            for _ in range(PAIR_RUNS):
                r = run_once(self.pair, self.spec, ["--no-check"], self.timeout)
                cpu.append(r.get("cpu_seconds") if r["status"] == "ok" else None)
            self.result.setdefault("paired_osm_runs", []).append(cpu)
            self.result.setdefault("paired_osm_cpu", []).append(
                statistics.mean(cpu) if all(cpu) else None)

    def add(self, record):
        self.result["seconds"].append(record["seconds"])
        self.result["cpu"].append(record.get("cpu_seconds"))
        self.result["phases"].append(phases_of(record))
        if self.core is not None:
            self.core.append(record["core_seconds"])

    def first(self):
        if self.pair:
            # A long run can meet a slow phase of this machine that the runs right
            # after it miss: bracket it, with runs before it as well.
            self.result["paired_bracketed"] = True
            self.run_pair()
        first = run_once(self.exe, self.spec, self.args, self.timeout)
        self.result["first"] = first
        if first["status"] != "ok":
            self.done = True
            return
        self.run_pair()
        self.core = [] if "core_seconds" in first else None
        self.add(first)
        c = first.get("cpu_seconds") or first["seconds"]
        self.target = RUNS_FAST if c < FAST_SECONDS else RUNS
        self.spent = self.last = first["wall"]
        self.update_done()

    def update_done(self):
        """Done once the target number of runs is reached, or one more would
        exceed the wall-time budget."""
        self.done = self.done or not (len(self.result["seconds"]) < self.target
                                      and self.spent + self.last <= REPEAT_BUDGET)

    def repeat(self):
        """One more timed run, unless the runs are complete."""
        if self.done:
            return
        again = run_once(self.exe, self.spec, self.args + ["--no-check"], self.timeout)
        self.spent += again["wall"]
        self.last = again["wall"]
        if again["status"] != "ok":
            self.result["repeat_failure"] = again
            self.done = True
            return
        self.run_pair()
        self.add(again)
        self.update_done()

    def finish(self):
        if self.core is not None:
            self.result["core_seconds"] = self.core
        return self.result


def measure_in_turns(measurements):
    """First runs tool after tool, then the repeats in rounds, one run of each
    tool per round, until every tool has its runs."""
    for m in measurements:
        m.first()
    while not all(m.done for m in measurements):
        for m in measurements:
            m.repeat()
    return [m.finish() for m in measurements]


def phases_of(record):
    keys = ["phase_clean", "phase_overlay", "phase_stitch", "phase_complete",
            "phase_domain", "phase_total"]
    return {k: record[k] for k in keys if k in record}


def inputs(data_dir, families):
    """(spec, class, display name, vertices or None) for every input."""
    real, generated = [], []
    if data_dir and os.path.isdir(data_dir):
        for name in sorted(os.listdir(data_dir)):
            if name.lower().endswith(".poly"):
                real.append((os.path.join(data_dir, name), "real", name, None))
    for family, sizes in families.items():
        for n in sizes:
            generated.append(("%s:%d:%d" % (family, n, SEED), family,
                              "%s %s" % (family, human(n)), n))
    # The first family (random segments: scaling, 1e5 segments, 1e7 triangles)
    # first, then the real inputs, then the rest: a suite cut short still has
    # the figures the targets need.
    first = [g for g in generated if g[1] == list(families)[0]] if families else []
    return first + real + [g for g in generated if g not in first]


def tool_applies(tool, cls, n):
    if tool == "vtk-osm" and cls not in ("real",) + VTK_OSM_FAMILIES:
        return False
    if tool == "osm-mesh" and cls not in ("real",) + CLI_FAMILIES:
        return False
    cap = CAPS.get(tool)
    if cap is not None and n is not None and n > cap:
        return False
    return True


def run_suite(args):
    bench = os.path.join(args.build, "bench")
    families = QUICK_FAMILIES if args.quick else FAMILIES
    global CLI_WORK, CPU_LIMIT
    CPU_LIMIT = int(args.timeout)
    found = {t: os.path.join(bench, TOOLS[t][0]) for t in TOOL_ORDER
             if os.access(os.path.join(bench, TOOLS[t][0]), os.X_OK)}
    cli = find_cli(args.build)
    if cli and os.access(os.path.join(bench, "bench_make_poly"), os.X_OK):
        found["osm-mesh"] = cli
        CLI_WORK = os.path.join(bench, "cli-work")
        os.makedirs(CLI_WORK, exist_ok=True)
    missing = [t for t in TOOL_ORDER if t not in found]
    if args.tools:
        wanted = args.tools.split(",")
        found = {t: x for t, x in found.items() if t in wanted}
    if "osm" not in found:
        sys.exit("no bench_osm in %s: build with -DOSM_BUILD_BENCHMARKS=ON first "
                 "(Testing/Benchmarks/run.sh)" % bench)
    data_dir = args.data if os.path.isdir(args.data) else None
    if data_dir is None:
        print("note: %s is absent: real inputs skipped" % args.data)
    results = []
    failed_at = {}  # (tool, class): size at which it timed out or crashed
    started = time.monotonic()
    load_start = os.getloadavg()
    print("load average at start: %.2f %.2f %.2f" % load_start, flush=True)
    meta = {
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        "commit": git_commit(),
        "dirty": git_dirty(),
        "load_start": load_start,
        "load_end": None,
        "cli": cli,
        "cli_commit": git_commit("Filters/CLI") if cli else None,
        "cpu": cpu_name(),
        "cores": os.cpu_count(),
        "memory_gib": round(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2**30),
        "python": platform.python_version(),
        "suite_seconds": 0.0,
        "quick": args.quick,
        "missing_tools": missing,
        "data_dir": args.data,
        "data_present": data_dir is not None,
        "timeout": args.timeout,
        "families": families,
        "caps": CAPS,
        "tools_take_turns": True,
    }
    for spec, cls, name, n in inputs(data_dir, families):
        # The tools take turns on each input (Measurement); the vtkDelaunay2D
        # target's runs, a minute each, are paired with OSM runs instead.
        turns, paired = [], []
        for tool in TOOL_ORDER:
            if tool not in found or not tool_applies(tool, cls, n):
                continue
            entry = {"tool": tool, "input": spec, "class": cls, "name": name, "n": n}
            results.append(entry)
            if (tool, cls) in failed_at and cls != "real":
                entry["skipped"] = "%s at %s input vertices" % (
                    failed_at[(tool, cls)][1], human(failed_at[(tool, cls)][0]))
                print("%-15s %-28s skipped (%s)" % (tool, name, entry["skipped"]), flush=True)
                continue
            if tool == "vtk-delaunay2d" and cls == "random-segments" and n == VTK_TARGET_N:
                paired.append((entry, Measurement(found[tool], spec, TOOLS[tool][1],
                                                  args.timeout, found["osm"])))
            else:
                turns.append((entry, Measurement(found[tool], spec, TOOLS[tool][1],
                                                 args.timeout)))
        measure_in_turns([m for _, m in turns])
        for entry, m in paired:
            measure_in_turns([m])
        for entry, m in turns + paired:
            tool = entry["tool"]
            r = m.finish()
            entry.update(r)
            status = r["first"]["status"]
            if status in ("timeout", "crash") and n is not None:
                failed_at[(tool, cls)] = (n, status)
            if status == "ok":
                print("%-15s %-28s %9.4f s CPU %9.4f s wall  x%d  %10d triangles" % (
                    tool, name, median_seconds(entry), median_wall(entry), len(r["seconds"]),
                    r["first"]["out_triangles"]), flush=True)
            else:
                print("%-15s %-28s %s: %s" % (tool, name, status,
                                               r["first"].get("detail", "")), flush=True)
        if args.partial:
            meta["suite_seconds"] = time.monotonic() - started
            meta["load_end"] = os.getloadavg()
            with open(args.partial, "w") as f:
                json.dump({"meta": meta, "results": results, "partial": True}, f)
    scaling = run_scaling_pass(found["osm"], results, args)
    repeated = run_repeat_pass(found, results, args)
    meta["suite_seconds"] = time.monotonic() - started
    meta["load_end"] = os.getloadavg()
    return {"meta": meta, "results": results, "scaling_pass": scaling, "repeat_pass": repeated}


# ----------------------------------------------------------------------------- scaling pass

# The main pass runs each input's repeats back to back, the small ones minutes
# before the large ones; on this shared virtual machine a slow phase lasts
# minutes, so a ratio of two sizes can be the machine's. This pass times the
# core alone on every size of a generated family in turn, in rounds (forward,
# then backward), so that each round's sizes share its conditions, and compares
# each size with the smallest one of the same round.
SCALING_ROUNDS = 5
SCALING_REPEATS_FAST = 3  # runs per size and round when one takes under FAST_SECONDS
SCALING_FAMILIES = ("random-segments", "points", "spread")


def scaling_specs(results):
    """Per family, the (spec, triangles, peak RSS or 0) of the core's runs with >= 1e4
    triangles."""
    specs = {}
    for e in results:
        if e["tool"] == "osm" and e["class"] in SCALING_FAMILIES and ok(e):
            t = e["first"]["out_triangles"]
            peak = e["first"].get("process_maxrss") or 0
            if 1e4 <= t <= 1.5e7:
                specs.setdefault(e["class"], []).append((e["n"], e["input"], t, peak))
    return {f: [x[1:] for x in sorted(v)] for f, v in specs.items() if len(v) >= 2}


def run_scaling_pass(exe, results, args):
    """Rounds of the core over each family's sizes. Returns {"rounds", "runs"}."""
    specs = scaling_specs(results)
    if not specs:
        return None
    order = [(fam, spec, t, peak) for fam, v in specs.items() for spec, t, peak in v]
    runs = []
    print("scaling pass: %d rounds over %d inputs" % (SCALING_ROUNDS, len(order)), flush=True)
    for rnd in range(SCALING_ROUNDS):
        for fam, spec, t, peak in (order if rnd % 2 == 0 else order[::-1]):
            cpu, system, warmed = [], [], []
            while True:
                warmed.append(back_memory(WARM_FACTOR * peak))
                r = run_once(exe, spec, ["--no-check"], args.timeout)
                if r["status"] != "ok" or r.get("out_triangles") != t:
                    warmed.pop()
                    break
                cpu.append(r["cpu_seconds"])
                system.append(r.get("system_seconds"))
                if len(cpu) >= SCALING_REPEATS_FAST or cpu[0] >= FAST_SECONDS:
                    break
            if cpu:
                runs.append({"round": rnd, "family": fam, "input": spec, "triangles": t,
                             "cpu": cpu, "system": system, "warmed": warmed})
        print("scaling pass: round %d done" % (rnd + 1), flush=True)
    return {"rounds": SCALING_ROUNDS, "runs": runs}


# ----------------------------------------------------------------------------- repeated calls

# Every run of the main pass is a fresh process, as an osm-mesh or pvbatch run
# is. ParaView and other long-lived applications call a mesher again and again
# in one process, its code, caches and heap warm. On inputs meshed in
# milliseconds the two differ by up to 8 times, and not alike for the two
# tools (BENCHMARKS.md, item 49): this pass times the core and Mesh_2 on
# those inputs after REPEAT_WARMUP unmeasured calls in the same process (the
# drivers' --warm), the two tools alternating, REPEAT_RUNS processes each.
REPEAT_WARMUP = 10
REPEAT_RUNS = 5
REPEAT_MAX_SECONDS = 0.1  # inputs on which both tools' main-pass medians are shorter


def repeat_specs(results):
    """The real inputs (spec, name) on which the core and Mesh_2 both meshed in their
    main-pass runs, each in under REPEAT_MAX_SECONDS of CPU (median)."""
    by = index_results(results)
    out = []
    for e in results:
        if e["tool"] != "osm" or e["class"] != "real" or not ok(e):
            continue
        m2 = by.get(("cgal-mesh2", e["input"]))
        if ok(m2) and max(median_seconds(e), median_seconds(m2)) < REPEAT_MAX_SECONDS:
            out.append((e["input"], e["name"]))
    return out


def run_repeat_pass(found, results, args):
    """Returns {"warmup", "runs": [{"input", "name", "cpu": {tool: [s, ...]},
    "seconds": {tool: [wall s, ...]}}]}, or None without Mesh_2 or such inputs."""
    specs = repeat_specs(results)
    if not specs or "cgal-mesh2" not in found:
        return None
    tools = ("osm", "cgal-mesh2")
    print("repeated calls: %d inputs, %d calls first" % (len(specs), REPEAT_WARMUP), flush=True)
    runs = []
    for spec, name in specs:
        cpu, wall = {t: [] for t in tools}, {t: [] for t in tools}
        for _ in range(REPEAT_RUNS):
            for tool in tools:
                r = run_once(found[tool], spec,
                             TOOLS[tool][1] + ["--no-check", "--warm", str(REPEAT_WARMUP)],
                             args.timeout)
                if r["status"] == "ok" and r.get("warm_calls") == REPEAT_WARMUP:
                    cpu[tool].append(r["cpu_seconds"])
                    wall[tool].append(r["seconds"])
        runs.append({"input": spec, "name": name, "cpu": cpu, "seconds": wall})
    return {"warmup": REPEAT_WARMUP, "runs": runs}


def repeat_rows(data):
    """[(name, OSM s, Mesh_2 s, Mesh_2 / OSM repeated, Mesh_2 / OSM fresh or None)] for the
    inputs on which both tools have repeated-call times, each taken as the main pass
    takes its times (median_seconds: the shortest wall time of runs under SHORT_RUN)."""
    rp = data.get("repeat_pass")
    if not rp:
        return []
    by = index_results(data["results"])
    rows = []
    for r in rp["runs"]:
        times = [median_seconds({"cpu": r["cpu"].get(t) or [],
                                 "seconds": r.get("seconds", {}).get(t) or []})
                 for t in ("osm", "cgal-mesh2")]
        if not all(times):
            continue
        mo, mm = times
        fo, fm = by.get(("osm", r["input"])), by.get(("cgal-mesh2", r["input"]))
        fresh = median_seconds(fm) / median_seconds(fo) if ok(fo) and ok(fm) else None
        rows.append((r["name"], mo, mm, mm / mo, fresh))
    return rows


def repeat_summary(data):
    """One sentence: on how many inputs the core is faster in repeated calls and in
    fresh processes; None if the pass did not run."""
    rows = repeat_rows(data)
    if not rows:
        return None
    faster = sum(1 for r in rows if r[3] > 1)
    fresh = [r for r in rows if r[4] is not None]
    return ("in one process after %d calls, on the %d inputs both mesh in under %s s: "
            "faster on %d of %d (%d of %d as fresh processes)" % (
                data["repeat_pass"]["warmup"], len(rows), fmt(REPEAT_MAX_SECONDS, 2), faster,
                len(rows), sum(1 for r in fresh if r[4] > 1), len(fresh)))


def repeat_text(data):
    rows = repeat_rows(data)
    if not rows:
        return ("Not run in this suite run (results from before the pass existed, or no "
                "Mesh_2 driver).")
    L = ["Each run of the main pass is a fresh process (as `osm-mesh` or a `pvbatch` script "
         "is); ParaView and other long-lived applications call the mesher again and again in "
         "one process. Here the core and Mesh_2 ran on the real inputs that both mesh in "
         "under %s s, each process making %d unmeasured calls first and timing the next "
         "(the drivers' `--warm`), the two tools alternating, %d processes each, the time "
         "taken as in the main pass (the median CPU time, or for calls under %s s the "
         "shortest wall time). "
         "Ratios above 1 favour OSM. In short, %s." % (
             fmt(REPEAT_MAX_SECONDS, 2), data["repeat_pass"]["warmup"], REPEAT_RUNS,
             fmt(SHORT_RUN, 2), repeat_summary(data)),
         "",
         "| input | OSM ms, repeated | Mesh_2 ms, repeated | Mesh_2 / OSM, repeated | "
         "Mesh_2 / OSM, fresh processes |",
         "|---|---:|---:|---:|---:|"]
    for name, mo, mm, rep, fresh in sorted(rows, key=lambda r: r[3]):
        L.append("| %s | %s | %s | %s | %s |" % (
            name, fmt(mo * 1e3), fmt(mm * 1e3), fmt(rep, 2),
            fmt(fresh, 2) if fresh is not None else "—"))
    return "\n".join(L)


def paired_scaling(data):
    """Per family: [(spec, triangles, median ns/tri, median ratio, min ratio, max ratio,
    kernel share, median user-time ratio)], each ratio a size's time per triangle over
    the family's smallest size in the same round (round medians of the repeats); the
    kernel share and the user-time ratio are None where the runs did not report it."""
    sp = data.get("scaling_pass")
    if not sp:
        return {}
    per, user, share = {}, {}, {}  # (family, spec) -> {round: value}
    tris = {}
    for r in sp["runs"]:
        k = (r["family"], r["input"])
        per.setdefault(k, {})[r["round"]] = statistics.median(r["cpu"]) / r["triangles"]
        tris[k] = r["triangles"]
        system = r.get("system") or []
        if system and all(x is not None for x in system):
            u = [c - x for c, x in zip(r["cpu"], system)]
            user.setdefault(k, {})[r["round"]] = statistics.median(u) / r["triangles"]
            share.setdefault(k, []).extend(x / c for c, x in zip(r["cpu"], system) if c > 0)
    out = {}
    for fam in SCALING_FAMILIES:
        keys = sorted((k for k in per if k[0] == fam), key=lambda k: tris[k])
        if len(keys) < 2:
            continue
        base, ubase = per[keys[0]], user.get(keys[0], {})
        rows = []
        for k in keys:
            ratios = [per[k][i] / base[i] for i in per[k] if i in base]
            if not ratios:
                continue
            uk = user.get(k, {})
            uratios = [uk[i] / ubase[i] for i in uk if i in ubase and ubase[i] > 0]
            rows.append((k[1], tris[k], statistics.median(per[k].values()) * 1e9,
                         statistics.median(ratios), min(ratios), max(ratios),
                         statistics.median(share[k]) if share.get(k) else None,
                         statistics.median(uratios) if uratios else None))
        out[fam] = rows
    return out


def paired_growth(rows):
    """The largest over the smallest of a family's median paired ratios."""
    med = [r[3] for r in rows]
    return max(med) / min(med)


def find_cli(build):
    """The osm-mesh executable of the build, if the tree has the command line tool."""
    for sub in ("bin", os.path.join("Filters", "CLI"), "."):
        path = os.path.join(build, sub, "osm-mesh")
        if os.access(path, os.X_OK) and os.path.isfile(path):
            return path
    for dirpath, _, files in os.walk(build):
        if "osm-mesh" in files and os.access(os.path.join(dirpath, "osm-mesh"), os.X_OK):
            return os.path.join(dirpath, "osm-mesh")
    return None


def git_dirty():
    """Uncommitted changes to the sources that the drivers compile (Filters/ and
    the drivers' own, Testing/Benchmarks/)."""
    try:
        out = subprocess.run(["git", "-C", ROOT, "status", "--short", "--", "Filters",
                              "Testing/Benchmarks/*.cxx", "Testing/Benchmarks/*.h"],
                             capture_output=True, text=True, check=True).stdout
        return [l[3:] + (" (new)" if l.startswith("??") else "")
                for l in out.splitlines() if l[:2].strip() in ("M", "MM", "A", "AM", "??")]
    except (OSError, subprocess.CalledProcessError):
        return []


def git_commit(path=None):
    """HEAD, or the last commit that touched path."""
    cmd = ["git", "-C", ROOT, "rev-parse", "--short", "HEAD"]
    if path:
        cmd = ["git", "-C", ROOT, "log", "-1", "--format=%h", "--", path]
    try:
        return subprocess.run(cmd, capture_output=True, text=True,
                              check=True).stdout.strip() or None
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def cpu_name():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


# ----------------------------------------------------------------------------- profile

PHASE_FUNCTIONS = [  # (phase, function whose inclusive cost is the phase's)
    ("clean", "osm::cleanPslg"),
    ("overlay", "osm::buildOverlay"),
    ("stitch: compact", "osm::compactOverlay"),
    ("stitch: walk", "osm::walkSegments"),
    ("stitch: split", "osm::stitch("),
    ("complete", "osm::complete("),
    ("domain", "osm::carveDomain"),
]
PROFILE_INPUT = "random-segments:30000:1"


def profiled_run(cmd, tool, note, timeout):
    """Runs a driver under a profiler: its JSON line in note["run"], or note["error"]."""
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    if p.returncode != 0:
        note["error"] = "%s failed: %s" % (tool, tail(p.stderr))
        return False
    for line in p.stdout.splitlines():
        if line.startswith("{"):
            note["run"] = json.loads(line)
    return True


def run_profile(args):
    """callgrind on a smaller run (perf has no hardware counters on this machine)."""
    exe = os.path.join(args.build, "bench", "bench_osm")
    note = {"input": PROFILE_INPUT}
    perf = shutil.which("perf")
    if perf:
        p = subprocess.run([perf, "stat", "-x,", "-e", "instructions", "true"],
                           capture_output=True, text=True)
        note["perf_instructions"] = "<not supported>" not in p.stderr and p.returncode == 0
    else:
        note["perf_instructions"] = False
    if not shutil.which("valgrind") or not shutil.which("callgrind_annotate"):
        note["error"] = "valgrind (callgrind) is not installed"
        return note
    out = os.path.join(args.build, "callgrind.bench_osm.out")
    t0 = time.monotonic()
    done = profiled_run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out,
                         exe, PROFILE_INPUT, "--no-check"], "callgrind", note, 1800)
    note["seconds"] = time.monotonic() - t0
    if not done:
        return note
    inclusive = annotate(out, True)
    exclusive = annotate(out, False)
    total = inclusive.get("__total__", 0)
    note["total_ir"] = total
    phases = []
    for phase, fn in PHASE_FUNCTIONS:
        cost = sum(c for name, c in inclusive.items() if name.startswith(fn))
        phases.append((phase, cost))
    note["phases"] = phases
    note["top_exclusive"] = sorted(
        ((n, c) for n, c in exclusive.items() if n != "__total__"),
        key=lambda x: -x[1])[:15]
    return note


# The sampled profile: perf samples the process's CPU time (its own and the
# kernel's on its behalf) where callgrind counts instructions, so it shows what
# instruction counts cannot: cache misses, and the kernel clearing fresh pages
# on their first touch.
SAMPLED_INPUT = "random-segments:120000:1"  # about 10^6 output triangles
SAMPLED_PHASES = [  # (phase, function-name prefixes after "osm::", anonymous namespaces dropped)
    ("clean", ("cleanPslg", "exactRepresentatives", "mergeDuplicates", "nearRepresentatives",
               "checkFinite", "mapSegments", "Mesher::mergeEqualPoints", "Mesher::splitCrossings")),
    ("overlay", ("Refiner::", "Triangulation::", "buildOverlay", "hilbertOrder", "incircle",
                 "orient", "SizeQueue")),
    ("stitch", ("compactOverlay", "walkSegments", "stitch", "OverlayEdges::", "Walker::")),
    ("complete", ("complete", "buildRotation", "triangulateMinMaxAngle")),
    ("domain", ("carveDomain", "adjacency", "convexHull", "hullBoundary", "hullCandidates",
                "components", "TriangleGrid", "segmentsEncloseRegion")),
    ("output", ("Mesher::buildOutput", "angleExtremes")),
]


def sampled_phase(sym):
    """The phase a sampled function belongs to, from its name (flat profile, no call graph).
    A library template (a sort) is placed by the first osm:: name in it, its comparator's."""
    if sym.startswith("[k]"):
        return "kernel"
    name = sym[3:].replace("(anonymous namespace)::", "")
    if "osm::" not in name:
        return "other"
    name = name[name.index("osm::") + len("osm::"):]
    for phase, prefixes in SAMPLED_PHASES:
        if name.startswith(prefixes):
            return phase
    return "other"


def run_sampled_profile(args):
    """perf record (cpu-clock samples) of one run of about 10^6 output triangles."""
    exe = os.path.join(args.build, "bench", "bench_osm")
    note = {"input": SAMPLED_INPUT}
    git = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                         capture_output=True, text=True)
    if git.returncode == 0:
        note["commit"] = git.stdout.strip()
    perf = shutil.which("perf")
    if not perf:
        note["error"] = "perf is not installed (Debian package linux-perf)"
        return note
    out = os.path.join(args.build, "perf.bench_osm.data")
    if not profiled_run([perf, "record", "-q", "-F", "4000", "-e", "cpu-clock", "-o", out, "--",
                         exe, SAMPLED_INPUT, "--no-check"], "perf record", note, 600):
        return note
    counts = subprocess.run([perf, "report", "-i", out, "--stdio", "-n", "--sort", "dso"],
                            capture_output=True, text=True, timeout=600)
    note["samples"] = sum(int(line.split()[1]) for line in counts.stdout.splitlines()
                          if not line.startswith("#") and len(line.split()) > 2
                          and line.split()[0].endswith("%") and line.split()[1].isdigit())
    r = subprocess.run([perf, "report", "-i", out, "--no-children", "--stdio", "--sort",
                        "dso,sym", "--percent-limit", "0.05"],
                       capture_output=True, text=True, timeout=600)
    rows = []  # (share in %, dso, "[.] symbol" or "[k] symbol")
    for line in r.stdout.splitlines():
        if line.startswith("#") or "%" not in line:
            continue
        parts = line.split(None, 2)
        if len(parts) == 3 and parts[0].endswith("%"):
            rows.append((float(parts[0].rstrip("%")), parts[1], parts[2].strip()))
    if not rows:
        note["error"] = "perf report gave no samples: " + tail(r.stderr)
        return note
    note["rows"] = rows
    return note


def sampled_profile_text(p):
    if not p:
        return ""
    if p.get("error"):
        return "Sampled profile not available: %s." % p["error"]
    rows = p["rows"]
    phases = {}
    for share, _, sym in rows:
        ph = sampled_phase(sym)
        phases[ph] = phases.get(ph, 0.0) + share
    kernel = [(share, sym[3:].strip()) for share, _, sym in rows if sym.startswith("[k]")]
    L = ["Sampled profile: `perf record -F 4000 -e cpu-clock` (samples of the process's CPU "
         "time, the kernel's on its behalf included, so cache misses and the kernel's work "
         "count, which callgrind's instructions do not) on `bench_osm %s` (%s output triangles, %s samples; the whole process, the "
         "generator included%s). Share of the samples by phase (each function assigned to "
         "its phase by name; *other*: library calls and sorts, whose callers a flat profile "
         "does not name):" % (p["input"], fmt_int(p.get("run", {}).get("out_triangles")),
                              fmt_int(p.get("samples")),
                              "; at commit %s" % p["commit"] if p.get("commit") else ""), "",
         "| phase | share of samples |", "|---|---:|"]
    order = [ph for ph, _ in SAMPLED_PHASES] + ["kernel", "other"]
    for ph in order:
        if ph in phases:
            label = ph
            if ph == "kernel" and kernel:
                label = "kernel (largest: `%s`, %.1f%%)" % (kernel[0][1], kernel[0][0])
            L.append("| %s | %.1f%% |" % (label, phases[ph]))
    if not kernel:
        L += ["", "No kernel samples: `perf_event_paranoid` withholds them from this user."]
    L += ["", "Its most sampled functions:", "", "| function | phase | share |", "|---|---|---:|"]
    for share, _, sym in rows[:12]:
        name = sym[3:].strip().replace("(anonymous namespace)", "anon")
        if len(name) > 70:
            name = name[:67] + "..."
        L.append("| `%s` | %s | %.1f%% |" % (name, sampled_phase(sym), share))
    if kernel and kernel[0][1].startswith("clear_page"):
        L += ["", "`%s` is the kernel clearing fresh memory at its first touch (huge pages "
              "included); on this virtual machine a first touch also waits for the host to "
              "back the page, which is why it is this large." % kernel[0][1]]
    return "\n".join(L)


def annotate(path, inclusive):
    """{function: instructions} from callgrind_annotate (symbols shortened)."""
    cmd = ["callgrind_annotate", "--threshold=100", "--inclusive=" + ("yes" if inclusive else "no"),
           path]
    p = subprocess.run(cmd, capture_output=True, text=True)
    costs = {}
    for line in p.stdout.splitlines():
        line = line.strip()
        parts = line.split(None, 1)
        if len(parts) != 2:
            continue
        number = parts[0].replace(",", "")
        if not number.isdigit():
            continue
        rest = parts[1]
        if rest.startswith("("):  # "(32.0%)" after the count in some versions
            rest = rest.split(None, 1)[1] if " " in rest else ""
        if rest.startswith("PROGRAM TOTALS"):
            costs["__total__"] = int(number)
            continue
        name = rest.split(" [", 1)[0]
        if ":" in name and not name.startswith("osm::") and "::" not in name.split(":", 1)[0]:
            name = name.split(":", 1)[1]  # drop "file:" prefix
        costs[name] = costs.get(name, 0) + int(number)
    return costs


# ----------------------------------------------------------------------------- report

def human(n):
    """1000 -> 1e3, 200000 -> 2e5; other numbers as they are."""
    if n is None:
        return ""
    for exp in range(9, 2, -1):
        if n % 10**exp == 0 and n // 10**exp < 10:
            return "%de%d" % (n // 10**exp, exp)
        if n % 10**(exp - 1) == 0 and n // 10**exp < 10 and n >= 10**exp:
            return "%.1fe%d" % (n / 10**exp, exp)
    return str(n)


SHORT_RUN = 0.05  # seconds: below it (wall), a run's CPU clock is too coarse here


def median_seconds(e):
    """The time every ratio uses: the median CPU time of the runs; for runs under
    SHORT_RUN, the shortest wall time (this machine's process CPU clock sometimes
    reads 0 for them, and the least disturbed run is the best estimate)."""
    cpu = [c for c in e.get("cpu", []) if c is not None]
    wall = median_wall(e)
    if cpu and wall is not None and wall >= SHORT_RUN:
        return statistics.median(cpu)
    return min(e["seconds"]) if e.get("seconds") else None


def median_wall(e):
    return statistics.median(e["seconds"]) if e.get("seconds") else None


def per_triangle(e):
    s = median_seconds(e)
    t = e["first"].get("out_triangles") if "first" in e else None
    return s / t if s is not None and t else None


def bytes_per_triangle(e):
    f = e.get("first", {})
    if f.get("status") != "ok" or not f.get("out_triangles"):
        return None
    if e.get("tool") == "osm-mesh":  # the whole process: GNU time's peak RSS
        return f["process_maxrss"] / f["out_triangles"] if f.get("process_maxrss") else None
    if f.get("peak_rss", -1) < 0 or f.get("base_rss", -1) < 0:
        return None
    return (f["peak_rss"] - f["base_rss"]) / f["out_triangles"]


def peak_bytes(f):
    if f.get("peak_rss", -1) > 0:
        return f["peak_rss"]
    return f.get("process_maxrss")


def fmt(x, digits=3):
    if x is None:
        return "—"
    if x == 0:
        return "0"
    if abs(x) >= 1000:
        return "{:,.0f}".format(x)
    return "%.*g" % (digits, x)


def fmt_int(x):
    return "—" if x is None else "{:,}".format(int(x))


def geomean(values):
    values = [v for v in values if v and v > 0]
    if not values:
        return None
    prod = 1.0
    for v in values:
        prod *= v ** (1.0 / len(values))
    return prod


def overlap_edges(e):
    """Edges of the tool's mesh that show overlapping triangles (in three or more
    triangles, or folded); None where the driver did not check (older results)."""
    f = e.get("first", {}) if e is not None else {}
    if "nonmanifold_edges" not in f:
        return None
    return f["nonmanifold_edges"] + f.get("folded_edges", 0)


def status_text(e):
    if "skipped" in e:
        return "skipped (%s)" % e["skipped"]
    f = e["first"]
    if f["status"] == "ok":
        if overlap_edges(e):
            return "ok, **overlapping**: %s edge(s) in 3+ triangles, %s folded" % (
                fmt_int(f["nonmanifold_edges"]), fmt_int(f.get("folded_edges", 0)))
        return "ok"
    if f["status"] == "timeout":
        return "**time-out**: %s" % f.get("detail", "")
    if f["status"] == "crash":
        return "**crash**: " + f.get("detail", "")[:80]
    return "**error**: " + f.get("detail", "")[:80]


def index_results(results):
    by = {}
    for e in results:
        by[(e["tool"], e["input"])] = e
    return by


def ok(e):
    return e is not None and e.get("first", {}).get("status") == "ok" and e.get("seconds")


CLASS_LABEL = {"real": "real inputs (../shared/data/pslg)", "random-segments": "random segments",
               "points": "random points", "spread": "high spread"}


def headline(data):
    results = data["results"]
    by = index_results(results)
    specs = []
    for e in results:
        if e["input"] not in [s for s, _ in specs]:
            specs.append((e["input"], e["class"]))
    rows = []
    for cls in ("real", "random-segments", "points", "spread"):
        members = [s for s, c in specs if c == cls]
        if not members:
            continue
        r_mesh2, r_cdt, r_mesh2_tri, r_vtk, r_tris = [], [], [], [], []
        vtk_timeouts = 0
        m2_failures = 0
        missing = {"osm": 0, "cgal-mesh2": 0, "vtk-delaunay2d": 0}
        overlapping = {"osm": 0, "cgal-mesh2": 0, "vtk-delaunay2d": 0}
        for s in members:
            for tool in missing:
                e = by.get((tool, s))
                if ok(e):
                    missing[tool] += e["first"].get("missing_segments", 0)
                    over = overlap_edges(e)
                    if over is None or overlapping[tool] is None:
                        overlapping[tool] = None  # results from before the check
                    else:
                        overlapping[tool] += 1 if over else 0
            o = by.get(("osm", s))
            if not ok(o):
                continue
            m2, cdt, vd = by.get(("cgal-mesh2", s)), by.get(("cgal-cdt", s)), by.get(("vtk-delaunay2d", s))
            if m2 is not None and m2.get("first", {}).get("status") in ("timeout", "crash"):
                m2_failures += 1
            if ok(m2):
                r_mesh2.append(median_seconds(m2) / median_seconds(o))
                r_mesh2_tri.append(per_triangle(o) / per_triangle(m2))
                r_tris.append(o["first"]["out_triangles"] / m2["first"]["out_triangles"])
            if ok(cdt):
                r_cdt.append(per_triangle(o) / per_triangle(cdt))
            if ok(vd):
                r_vtk.append(median_seconds(vd) / median_seconds(o))
            elif vd is not None and vd.get("first", {}).get("status") == "timeout":
                vtk_timeouts += 1
        rows.append((cls, len(members), r_mesh2, r_tris, r_mesh2_tri, r_cdt, r_vtk, vtk_timeouts,
                     missing, overlapping, m2_failures))
    return rows


def angle_rows(data):
    """Per input class, OSM's and Mesh_2's extreme angles on the inputs both
    meshed: (class, count, OSM's largest, Mesh_2's largest, inputs where
    OSM's largest angle is the larger, OSM's smallest, Mesh_2's smallest,
    inputs where OSM's smallest angle is the smaller)."""
    by = index_results(data["results"])
    rows = []
    for cls in ("real", "random-segments", "points", "spread"):
        pairs = []
        for e in data["results"]:
            if e["tool"] != "osm" or e["class"] != cls or not ok(e):
                continue
            m2 = by.get(("cgal-mesh2", e["input"]))
            if ok(m2):
                pairs.append((e["first"], m2["first"]))
        if pairs:
            rows.append((cls, len(pairs),
                         max(o["max_angle"] for o, _ in pairs), max(m["max_angle"] for _, m in pairs),
                         sum(1 for o, m in pairs if o["max_angle"] > m["max_angle"]),
                         min(o["min_angle"] for o, _ in pairs), min(m["min_angle"] for _, m in pairs),
                         sum(1 for o, m in pairs if o["min_angle"] < m["min_angle"])))
    return rows


def range_text(values):
    if not values:
        return "—"
    g = geomean(values)
    lo, hi = min(values), max(values)
    return "%s (%s – %s)" % (fmt(g, 2), fmt(lo, 2), fmt(hi, 2))


def targets(data, profile):
    results = data["results"]
    by = index_results(results)
    out = []
    osm_runs = [e for e in results if e["tool"] == "osm" and ok(e)]

    # 1a. faster than Mesh_2 on every input (a Mesh_2 time-out or crash counts for OSM)
    worse, failed, ratios = [], [], []
    for o in osm_runs:
        m2 = by.get(("cgal-mesh2", o["input"]))
        if ok(m2):
            ratios.append(median_seconds(m2) / median_seconds(o))
            if median_seconds(o) >= median_seconds(m2):
                worse.append((o["name"], median_seconds(o) / median_seconds(m2)))
        elif m2 is not None and m2.get("first", {}).get("status") in ("timeout", "crash"):
            failed.append("%s (%s)" % (o["name"], m2["first"]["status"]))
    compared = len(ratios) + len(failed)
    text = "faster on %d of %d inputs" % (compared - len(worse), compared)
    if failed:
        text += ", among them %d where Mesh_2 gave no mesh: %s" % (len(failed), ", ".join(failed))
    if ratios:
        text += "; where both finished, Mesh_2 time / OSM time from %s to %s (geometric mean %s)" % (
            fmt(min(ratios), 2), fmt(max(ratios), 2), fmt(geomean(ratios), 2))
    if worse:
        w_ = max(worse, key=lambda x: x[1])
        text += "; slowest relative: %s (OSM takes %s× Mesh_2's time)" % (w_[0], fmt(w_[1], 2))
    repeated = repeat_summary(data)
    if repeated:
        text += "; %s (see *Repeated calls*)" % repeated
    out.append(("Core faster than CGAL Mesh_2 on every input", text,
                not worse and compared > 0))

    # 1b. per triangle at most 1.5x CGAL CDT per triangle
    rel = []
    long_runs = set()
    for o in osm_runs:
        c = by.get(("cgal-cdt", o["input"]))
        if ok(c):
            rel.append((o["name"], per_triangle(o) / per_triangle(c)))
            if median_wall(c) >= SHORT_RUN:
                long_runs.add(o["name"])
    if rel:
        # The target holds on every input: the short runs count too (they are
        # timed by their shortest wall time, as in the Mesh_2 target).
        worst = max(rel, key=lambda r: r[1])
        best = min(rel, key=lambda r: r[1])
        over = sorted((r for r in rel if r[1] > 1.5), key=lambda r: -r[1])
        long_rel = [r[1] for r in rel if r[0] in long_runs]
        out.append(("Time per output triangle ≤ 1.5× CGAL CDT's per triangle",
                    "OSM / CDT per triangle on all %d inputs: geometric mean %s, from %s (%s) "
                    "to %s (%s); above 1.5 on %d: %s%s" % (
                        len(rel), fmt(geomean([r[1] for r in rel]), 2), fmt(best[1], 2),
                        best[0], fmt(worst[1], 2), worst[0], len(over),
                        ", ".join("%s %s" % (r[0], fmt(r[1], 2)) for r in over) or "none",
                        "; on the %d inputs on which the CDT takes at least %g s: at most %s" % (
                            len(long_rel), SHORT_RUN, fmt(max(long_rel), 2))
                        if long_rel else ""),
                    worst[1] <= 1.5))

    # 2. per triangle flat within 1.5x from 1e4 to 1e7 triangles (generated families)
    texts, met = [], True
    for fam in ("random-segments", "points", "spread"):
        pts = [(o["first"]["out_triangles"], per_triangle(o)) for o in osm_runs
               if o["class"] == fam and 1e4 <= o["first"]["out_triangles"] <= 1.5e7]
        if len(pts) < 2:
            continue
        pts.sort()
        hi = max(p[1] for p in pts)
        lo = min(p[1] for p in pts)
        met = met and hi / lo <= 1.5
        m2 = [per_triangle(by[("cgal-mesh2", o["input"])]) for o in osm_runs
              if o["class"] == fam and 1e4 <= o["first"]["out_triangles"] <= 1.5e7
              and ok(by.get(("cgal-mesh2", o["input"])))]
        m2text = ""
        if len(m2) >= 2:
            m2text = "; Mesh_2 on the same inputs: ×%s" % fmt(max(m2) / min(m2), 2)
        texts.append("%s: %s ns to %s ns over %s – %s triangles (×%s%s)" % (
            fam, fmt(lo * 1e9), fmt(hi * 1e9), fmt_int(pts[0][0]), fmt_int(pts[-1][0]),
            fmt(hi / lo, 2), m2text))
    largest = max((o["first"]["out_triangles"] for o in osm_runs), default=0)
    paired = paired_scaling(data)
    if paired:
        # The verdict is the interleaved pass's: sizes timed in the same rounds.
        met = all(paired_growth(rows) <= 1.5 for rows in paired.values())
        texts = ["interleaved pass (%d rounds; each size against the smallest in the same "
                 "round, median over the rounds): %s" % (
                     data["scaling_pass"]["rounds"], ", ".join(
                         "%s ×%s" % (fam, fmt(paired_growth(rows), 3))
                         for fam, rows in paired.items())) +
                 " (main pass, each size's median, sizes timed minutes apart: " +
                 "; ".join(texts) + ")"]
    if texts:
        out.append(("Time per output triangle within 1.5× from 1e4 to 1e7 triangles",
                    "; ".join(texts) + ("" if largest >= 1e7 else
                                        " (largest run: %s triangles)" % fmt_int(largest)),
                    met))

    # 3. memory at >= 1e7 triangles: osm-mesh (whole process) if it ran, else the core
    for tool, what in (("osm-mesh", "osm-mesh, whole process"),
                       ("osm", "core, increase during the call")):
        runs = [e for e in results if e["tool"] == tool and ok(e)]
        if not runs:
            continue
        big = [o for o in runs if o["first"]["out_triangles"] >= 0.95e7 and bytes_per_triangle(o)]
        qual = ""
        if not big:
            big = sorted(runs, key=lambda o: -o["first"]["out_triangles"])[:1]
            qual = "no run reached 1e7 triangles; largest: "
        if big and bytes_per_triangle(big[0]) is not None:
            worst = max(big, key=bytes_per_triangle)
            out.append(("Peak memory ≤ 200 bytes per triangle at ≥ 1e7 triangles (%s)" % what,
                        qual + "; ".join("%s: %s B/triangle (%s triangles, peak %s MB)" % (
                            o["name"], fmt(bytes_per_triangle(o)),
                            fmt_int(o["first"]["out_triangles"]),
                            fmt(peak_bytes(o["first"]) / 2**20)) for o in big),
                        bytes_per_triangle(worst) <= 200 and not qual))

    # 4. VTK filter overhead at ~1e6 triangles
    vt = [e for e in results if e["tool"] == "vtk-osm" and ok(e) and e.get("core_seconds")]
    if vt:
        near = min(vt, key=lambda e: abs(e["first"]["out_triangles"] - 1e6))
        over_same = statistics.median(
            [(s - c) / c for s, c in zip(near["seconds"], near["core_seconds"])])
        o = by.get(("osm", near["input"]))
        over_sep = median_seconds(near) / median_seconds(o) - 1 if ok(o) else None
        out.append(("VTK filter overhead ≤ 25% of core time at 1e6 triangles",
                    "%s (%s triangles): Update() vs the core inside it, same run: +%s%%; "
                    "vs bench_osm (separate processes): %s%%" % (
                        near["name"], fmt_int(near["first"]["out_triangles"]),
                        fmt(100 * over_same, 2),
                        "—" if over_sep is None else "%+.0f" % (100 * over_sep)),
                    over_same <= 0.25))

    # 5. vtkDelaunay2D at 1e5 segments
    cand = [e for e in results if e["tool"] == "vtk-delaunay2d" and
            e["class"] == "random-segments" and e.get("n") == VTK_TARGET_N and "first" in e]
    if cand:
        v = cand[0]
        o = by.get(("osm", v["input"]))
        if ok(o):
            om = o["first"].get("missing_segments")
            # Overlapping triangles break a mesh as surely as a missing segment.
            o_over, v_over = overlap_edges(o), overlap_edges(v)
            if ok(v):
                ratio = median_seconds(v) / median_seconds(o)
                vm = v["first"].get("missing_segments")
                text = "%s (1e5 segments): vtkDelaunay2D %s s, OSM %s s: %s× faster; missing " \
                       "segments: OSM %s, vtkDelaunay2D %s" % (
                           v["name"], fmt(median_seconds(v)), fmt(median_seconds(o)),
                           fmt(ratio, 2), om, vm)
                paired = paired_ratios(v)
                if paired:
                    # The verdict is the paired runs': each vtkDelaunay2D run
                    # against the OSM runs next to it.
                    ratio = statistics.median(paired)
                    runs = v.get("paired_osm_runs")
                    if v.get("paired_bracketed"):
                        against = ("the mean of the %d OSM runs around it (%d before, %d after)"
                                   % (2 * len(runs[0]), len(runs[0]), len(runs[0])))
                    else:
                        against = ("the mean of %d OSM runs right after it" % len(runs[0])
                                   if runs and len(runs[0]) > 1 else "an OSM run right after it")
                    text = "%s (1e5 segments), each vtkDelaunay2D run against %s: %s× faster " \
                           "(median of %d pairs, %s to %s); the two tools' " \
                           "medians, timed minutes apart: vtkDelaunay2D %s s, OSM %s s (%s×); " \
                           "missing segments: OSM %s, vtkDelaunay2D %s" % (
                               v["name"], against, fmt(ratio, 3), len(paired), fmt(min(paired), 3),
                               fmt(max(paired), 3), fmt(median_seconds(v)),
                               fmt(median_seconds(o)),
                               fmt(median_seconds(v) / median_seconds(o), 3), om, vm)
                if v_over is not None:
                    text += "; overlapping edges: OSM %s, vtkDelaunay2D %s" % (
                        fmt_int(o_over), fmt_int(v_over))
                good = ratio >= 50 and om == 0 and not o_over
            elif v["first"]["status"] == "timeout":
                ratio = args_timeout(data) / median_seconds(o)
                text = "vtkDelaunay2D timed out (> %d s): OSM at least %s× faster; OSM missing " \
                       "segments: %s" % (args_timeout(data), fmt(ratio, 2), om)
                good = ratio >= 50 and om == 0 and not o_over
            else:
                text = "vtkDelaunay2D: " + status_text(v)
                good = om == 0 and not o_over
            real_missing = sum(e["first"].get("missing_segments", 0) for e in results
                               if e["tool"] == "vtk-delaunay2d" and e["class"] == "real" and ok(e))
            real_inputs = sum(1 for e in results if e["tool"] == "vtk-delaunay2d"
                              and e["class"] == "real" and ok(e)
                              and e["first"].get("missing_segments", 0) > 0)
            real_overlapping = [e["name"] for e in results
                                if e["tool"] == "vtk-delaunay2d" and e["class"] == "real"
                                and ok(e) and overlap_edges(e)]
            if real_missing:
                text += " (on the real inputs vtkDelaunay2D misses %s segments on %d inputs, " \
                        "OSM none" % (fmt_int(real_missing), real_inputs)
                if real_overlapping:
                    text += "; its meshes overlap themselves on %d: %s" % (
                        len(real_overlapping), ", ".join(real_overlapping))
                text += ")"
            out.append(("≥ 50× faster than vtkDelaunay2D at 1e5 segments, zero missing segments",
                        text, good))
    return out


def args_timeout(data):
    return int(data["meta"]["timeout"])


def scaling_text(data):
    """OSM's time and memory per output triangle along the generated families."""
    results = data["results"]
    by = index_results(results)
    L = ["Time per output triangle of the OSM core along each generated family (CPU time "
         "of the median run; *vs smallest ≥ 1e4*: its ratio to the first size with at least "
         "10,000 output triangles), with CGAL's per-triangle times on the same inputs, and "
         "the memory per output triangle (core: peak RSS increase during the call; osm-mesh: "
         "peak RSS of the whole process).", "",
         "| family | input vertices | OSM triangles | OSM ns/tri | vs smallest ≥ 1e4 | "
         "Mesh_2 ns/tri | CDT ns/tri | filter ns/tri | osm-mesh ns/tri | core B/tri | "
         "osm-mesh B/tri |",
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for fam in ("random-segments", "points", "spread"):
        runs = sorted((e for e in results if e["tool"] == "osm" and e["class"] == fam and ok(e)),
                      key=lambda e: e["n"])
        base = None
        for o in runs:
            t = o["first"]["out_triangles"]
            pt = per_triangle(o)
            if base is None and t >= 1e4:
                base = pt
            def other(tool, what):
                x = by.get((tool, o["input"]))
                if not ok(x):
                    return "—" if x is None else status_text(x).split(":")[0]
                return fmt(what(x))
            L.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                fam, human(o["n"]), fmt_int(t), fmt(pt * 1e9),
                fmt(pt / base, 2) if base and t >= 1e4 else "—",
                other("cgal-mesh2", lambda x: per_triangle(x) * 1e9),
                other("cgal-cdt", lambda x: per_triangle(x) * 1e9),
                other("vtk-osm", lambda x: per_triangle(x) * 1e9),
                other("osm-mesh", lambda x: per_triangle(x) * 1e9),
                fmt(bytes_per_triangle(o)),
                other("osm-mesh", bytes_per_triangle)))
    paired = paired_scaling(data)
    if paired:
        L += ["", "The interleaved scaling pass: after the main pass, the core alone ran on "
              "every size of a family with at least 10^4 triangles in turn, %d rounds (forward, "
              "then backward; sizes under %g s of CPU %d times per round, the median taken), so "
              "that every size is timed under the same conditions as the others of its round. "
              "*vs smallest*: a size's time per triangle over the family's smallest size in the "
              "same round; the median over the rounds and their range. The target's verdict is "
              "this pass's: the main pass times each size minutes apart, and this machine's "
              "slow phases last minutes. *Kernel*: the share of the CPU time that the kernel "
              "spent on the process's behalf (nearly all of it first touches of fresh memory: "
              "page faults and clearing pages; the kernel splits user from system time by "
              "sampling at its tick, so the small runs' shares are coarse); *user time only*: "
              "the same paired ratio without it." % (
                  data["scaling_pass"]["rounds"], FAST_SECONDS, SCALING_REPEATS_FAST), "",
              "| family | OSM triangles | ns/tri (median over rounds) | vs smallest, same round "
              "(median) | range over rounds | kernel | user time only, vs smallest |",
              "|---|---:|---:|---:|---|---:|---:|"]
        for fam, rows in paired.items():
            for spec, t, ns, med, lo, hi, kshare, umed in rows:
                L.append("| %s | %s | %s | %s | %s – %s | %s | %s |" % (
                    fam, fmt_int(t), fmt(ns), fmt(med, 3), fmt(lo, 3), fmt(hi, 3),
                    "—" if kshare is None else "%.1f%%" % (100 * kshare),
                    fmt(umed, 3)))
    return "\n".join(L)


def phase_table(data):
    """Per-phase seconds of the OSM core runs whose output is nearest 1e6 triangles."""
    rows = []
    for e in data["results"]:
        if e["tool"] != "osm" or not ok(e):
            continue
        t = e["first"]["out_triangles"]
        if 5e5 <= t <= 2.5e6 and e.get("phases"):
            # the run whose total is the median one
            ph = sorted(e["phases"], key=lambda p: p.get("phase_total", 0))[len(e["phases"]) // 2]
            rows.append((e["name"], t, ph, e["input"]))
    return rows


def write_report(data, profile, md_path, png_path, plot_note):
    meta = data["meta"]
    results = data["results"]
    by = index_results(results)
    L = []
    w = L.append
    w("# Benchmarks")
    w("")
    w("Generated by `bash Testing/Benchmarks/run.sh` (which runs "
      "`Testing/Benchmarks/run_benchmarks.py`); do not edit by hand. "
      "Run on %s, commit `%s`, %s (%d cores, %d GiB), shared with other builds: "
      "timings are noisy, so ratios measured in the same suite run are what to read. "
      "The suite took %.0f minutes." % (
          meta["date"], meta["commit"], meta["cpu"], meta["cores"], meta["memory_gib"],
          meta["suite_seconds"] / 60.0))
    ls, le = meta.get("load_start"), meta.get("load_end")
    if ls and le:
        w("")
        w("Load average (1, 5, 15 min) at the start of the suite: %.2f, %.2f, %.2f; at its "
          "end: %.2f, %.2f, %.2f. On 2 cores, anything above about 1 means that other jobs "
          "(other builds in the same tree) competed with the benchmark; each figure is the "
          "median of several runs. " % (tuple(ls) + tuple(le)) + (
              "In the main pass the tools meshing an input take turns: their first runs one "
              "after another, then one repeat of each per round, so that a slow phase of the "
              "machine (it can last minutes) falls on all of them alike."
              if meta.get("tools_take_turns") else
              "In the main pass each tool's runs on an input follow one "
              "another, tool after tool (they are not interleaved run by run): a slow phase of "
              "the machine, which can last minutes, may fall on one tool's runs and not the "
              "other's, so a single ratio can be off by up to about 2 (us48.poly's Mesh_2 / OSM "
              "was 4.4 here and 1.4-2.5 in runs alternated by hand)."))
    if meta.get("dirty"):
        w("")
        w("The drivers were built from the working tree, which other sessions were editing: "
          "when the suite started it was at commit `%s` with uncommitted changes to: %s." % (
            meta["commit"], ", ".join("`%s`" % d for d in meta["dirty"])))
    if meta.get("quick"):
        w("")
        w("**Quick run (`--quick`): small sizes only; the targets need the full run.**")
    w("")
    w("![time per output triangle](Testing/Benchmarks/benchmarks.png)")
    w("")
    w("## Headline (ratios)")
    w("")
    w("Per input class: geometric mean over its inputs, with the range (min – max). "
      "*Mesh_2 time / OSM time* and *vtkDelaunay2D time / OSM time* above 1 favour OSM; "
      "the per-triangle columns are OSM's time per output triangle divided by the other "
      "tool's (below 1 favours OSM). Missing segments are summed over the class; "
      "*overlapping meshes* counts the inputs on which the tool's mesh has an edge in three "
      "or more triangles or two triangles on the same side of an edge (see *Results*).")
    w("")
    w("| inputs | count | Mesh_2 time / OSM time | OSM / Mesh_2 triangles | "
      "OSM / Mesh_2 per triangle | OSM / CGAL CDT per triangle | "
      "vtkDelaunay2D time / OSM time | missing segments: OSM, Mesh_2, vtkDelaunay2D | "
      "overlapping meshes: OSM, Mesh_2, vtkDelaunay2D |")
    w("|---|---:|---:|---:|---:|---:|---:|---|---|")
    for (cls, count, r_m2, r_tris, r_m2t, r_cdt, r_vtk, vto, missing, overlapping,
         m2f) in headline(data):
        m2text = range_text(r_m2)
        if m2f:
            m2text += " + %d Mesh_2 time-out(s)/crash(es)" % m2f
        vt = range_text(r_vtk)
        if vto:
            vt += " + %d time-out(s)" % vto
        if cls == "points":
            vt += " (no constraints)"
        tools = ("osm", "cgal-mesh2", "vtk-delaunay2d")
        w("| %s | %d | %s | %s | %s | %s | %s | %s | %s |" % (
            CLASS_LABEL.get(cls, cls), count, m2text, range_text(r_tris),
            range_text(r_m2t), range_text(r_cdt), vt,
            ", ".join(fmt_int(missing[t]) for t in tools),
            ", ".join("not checked" if overlapping[t] is None else fmt_int(overlapping[t])
                      for t in tools)))
    w("")
    layers = []
    for tool, label in (("vtk-osm", "VTK filter `Update()` / core"),
                        ("osm-mesh", "`osm-mesh` end to end (read, mesh, write .vtp) / core")):
        r = [median_seconds(by[(tool, o["input"])]) / median_seconds(o)
             for o in results if o["tool"] == "osm" and ok(o) and ok(by.get((tool, o["input"])))
             and median_wall(o) >= SHORT_RUN]
        if r:
            layers.append("%s: %s" % (label, range_text(r)))
    if layers:
        w("OSM's own layers, CPU time against the core's on the same inputs (geometric mean, "
          "range; runs of at least %g s): %s." % (SHORT_RUN, "; ".join(layers)))
        w("")
    w("OSM makes more triangles than Mesh_2 on the same input (the *OSM / Mesh_2 "
      "triangles* column): its phase-1 overlay is a quality mesh of the input points with "
      "every angle at least 30° (Mesh_2 refines to 20.7°), and stitching adds the points "
      "where segments cross it. The per-triangle columns compare work per triangle "
      "produced; they are no like-for-like measure of speed where the outputs differ (a "
      "tool that makes more triangles gains in them), so the plain time ratio is the one "
      "to read first.")
    w("")
    w("The two tools also make meshes of a different quality, and promise different things. "
      "OSM bounds the largest angle (170°) whatever the input angles and makes no promise on "
      "the smallest: stitching a segment across the overlay leaves thin triangles along it. "
      "Mesh_2 refines until every angle is at least 20.7°, which keeps the largest below "
      "about 138.6°, except near small input angles and where refinement stops, where "
      "neither is bounded. On the inputs both meshed:")
    w("")
    w("| inputs | both meshed | largest angle: OSM, Mesh_2 | OSM's largest the larger | "
      "smallest angle: OSM, Mesh_2 | OSM's smallest the smaller |")
    w("|---|---:|---|---:|---|---:|")
    for cls, n, omax, mmax, worse_max, omin, mmin, worse_min in angle_rows(data):
        w("| %s | %d | %.2f°, %.2f° | %d of %d | %.3g°, %.3g° | %d of %d |" % (
            CLASS_LABEL.get(cls, cls), n, omax, mmax, worse_max, n, omin, mmin, worse_min, n))
    w("")
    rows = angle_rows(data)
    both = sum(r[1] for r in rows)
    larger = sum(r[4] for r in rows)
    if both and 2 * larger > both:
        w("So on most inputs (%d of %d) Mesh_2's largest angle is the smaller: OSM's "
          "advantage is the bound, which holds on inputs where Mesh_2's does not (the "
          "largest angle column)." % (larger, both))
    elif both:
        w("OSM's largest angle is the smaller on %d of the %d inputs both meshed." % (
            both - larger, both))
    w("")
    w("## Targets (issue 5)")
    w("")
    w("| target | measured | met |")
    w("|---|---|---|")
    for name, text, good in targets(data, profile):
        w("| %s | %s | %s |" % (name, text, "**yes**" if good else "**no**"))
    w("")
    w("## Scaling")
    w("")
    w(scaling_text(data))
    w("")
    w("## Repeated calls in one process")
    w("")
    w(repeat_text(data))
    w("")
    w("## Where the time goes")
    w("")
    rows = phase_table(data)
    if rows:
        w("Per phase, from the core's own `Result::stats` (wall seconds of the median run, "
          "so inflated by the load like every wall time here; the shares are what to read), "
          "for the OSM runs with 0.5 to 2.5 million output triangles. *VTK conversion*: "
          "the VTK filter's `Update()` minus the core's own total inside that same call "
          "(median over its runs; vtkPolyData in, mesh with its arrays out), as a share of "
          "that core total:")
        w("")
        w("| input | triangles | clean | overlay | stitch | complete | domain | total | "
          "VTK conversion |")
        w("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
        by = index_results(results)
        for name, t, ph, spec in rows:
            tot = ph.get("phase_total", 0) or 1
            cells = []
            for k in ("phase_clean", "phase_overlay", "phase_stitch", "phase_complete",
                      "phase_domain"):
                cells.append("%s s (%.0f%%)" % (fmt(ph.get(k, 0)), 100 * ph.get(k, 0) / tot))
            v = by.get(("vtk-osm", spec))
            conv = "—"
            if ok(v) and v.get("core_seconds"):
                d = [(a - c, c) for a, c in zip(v["seconds"], v["core_seconds"])]
                mid = sorted(d, key=lambda x: x[0] / x[1])[len(d) // 2]
                conv = "%s s (%.0f%%)" % (fmt(mid[0]), 100 * mid[0] / mid[1])
            w("| %s | %s | %s | %s s | %s |" % (name, fmt_int(t), " | ".join(cells), fmt(tot),
                                                conv))
        w("")
    if profile:
        w(profile_text(profile))
        w("")
    if data.get("sampled_profile"):
        w(sampled_profile_text(data["sampled_profile"]))
        w("")
    w(CHANGES_FROM_PROFILES)
    w("")
    w("## Results")
    w("")
    w("*CPU s*: median process CPU time of the meshing call only (no reading, generating or "
      "converting), over the runs counted in *runs*, or for runs under %g s wall their "
      "shortest wall time (see *Method*); *wall s*: the median wall time of the "
      "same calls (inflated by the other jobs on the machine). Each run is a separate "
      "process with a limit of %d CPU seconds. "
      "*missing*: input segments that are not a chain of output edges (checked "
      "from exact input coordinates by the suite's own walk, the same for every tool); "
      "*out*: segments outside the domain the tool meshed (legitimately absent; which "
      "input points lie outside is taken from each tool's own output, so a tool that "
      "wrongly dropped a region would count its segments here, not as missing; OSM and "
      "Mesh_2 agree on every input). *status* says **overlapping** where a tool's mesh has an "
      "edge in three or more triangles or an edge whose two triangles' third vertices lie "
      "on the same side of it (exact orientation tests): the triangles then overlap. That "
      "check sees every overlap of triangles joined by edges, not two separate sheets "
      "lying over each other; the project's own validator checks OSM's meshes fully, in "
      "the tests. *peak*: peak RSS during "
      "the call (its increase over the RSS before it, per output triangle, in "
      "*B/tri*)." % (SHORT_RUN, args_timeout(data)))
    w("")
    w("| input | tool | runs | CPU s | wall s | ns / triangle | vertices | triangles | "
      "min angle | max angle | missing | out | peak MB | B/tri | status |")
    w("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    seen = []
    for e in results:
        if e["input"] not in seen:
            seen.append(e["input"])
    for spec in seen:
        entries = [by[(t, spec)] for t in TOOL_ORDER if (t, spec) in by]
        for e in entries:
            f = e.get("first", {})
            good = ok(e)
            missing = f.get("missing_segments") if good else None
            if e["tool"] == "osm-delaunay":
                missing_text, out_text = "n/a", "n/a"
            else:
                missing_text = "—" if missing is None else fmt_int(missing)
                out_text = "—" if not good else fmt_int(f.get("outside_segments", 0))
            w("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                e["name"], TOOLS[e["tool"]][2], len(e.get("seconds", [])) or "—",
                fmt(median_seconds(e), 4) if good else "—",
                fmt(median_wall(e), 4) if good else "—",
                fmt(per_triangle(e) * 1e9) if good else "—",
                fmt_int(f.get("out_vertices")) if good else "—",
                fmt_int(f.get("out_triangles")) if good else "—",
                fmt(f.get("min_angle"), 4) if good else "—",
                fmt(f.get("max_angle"), 5) if good else "—",
                missing_text, out_text,
                fmt(peak_bytes(f) / 2**20) if good and peak_bytes(f) else "—",
                fmt(bytes_per_triangle(e)) if good else "—",
                status_text(e)))
    w("")
    w("## What was run, and how")
    w("")
    w(notes_text(data, plot_note))
    with open(md_path, "w") as f:
        f.write("\n".join(L) + "\n")


# What the profiles above led to, in order; each step measured when it was made
# (the commit messages carry the same figures).
CHANGES_FROM_PROFILES = """### What was changed because of the profiles

1. **Edge pairing in linear time** (`complete`, `carveDomain`): sorting 2- and 3-int edge keys was 23% of the instructions; counting-sort rows by the smaller vertex replaced it. Instructions on random-segments 3e4: 3.05e9 -> 1.99e9 (callgrind), output bit-identical.
2. **Freeing the overlay early** (`Mesher`): the refinement's triangles are freed once compacted, the compact overlay and the walks once stitched. Core peak at 10.4 M triangles: 210 -> 114 bytes per triangle; output byte-identical.
3. **No repeated work in refinement** (`Overlay`, `Triangulation`, `Mesher`): a Steiner point reuses the cavity found for its circumcenter instead of searching it again, cavity insertion allocates nothing, the output's angle statistics call `atan2` only where a cosine filter cannot rule an angle out (it was 5% of the instructions), and a popped triangle is not tested for quality twice. Core instructions of `osm-mesh` on random-segments 2e4: 1.37e9 -> 1.12e9 (-18%), output byte-identical.
4. **Refinement order by size class** (`SizeQueue.h`): the exact heap of SVR's queue cost O(log n) cache misses per operation, and refined triangles in a spatially scattered order. SVR needs the order only within a constant factor: buckets of a factor 2 in circumradius, newest first within one, keep the refinement where the mesh was just touched. Overlay phase on random-segments 2e5 (1.74 M triangles): 3.5-3.9 s -> 1.4-2.0 s, for about 2% more triangles (aust.poly 1,325,333 -> 1,355,662; largest angle on the real inputs 149.91 degrees).
5. **Overlay renumbered along a Hilbert curve** (`renumberAlongHilbertCurve`, `compactOverlay`): vertices in spatial order and triangles by their lowest vertex, so stitch, complete and domain touch memory locally. On random-segments 2e5: complete 0.9-1.3 s -> 0.3-0.4 s, domain 0.4-0.5 s -> 0.1-0.2 s. With 4 and 5 together, the core's time per triangle on random segments stays flat from 1e4 to 3.5e6 triangles (1,553, 1,395, 1,588 ns) where it grew from 1,845 to 2,965 ns.
6. **The hull once per round** (`Mesher`): the hull domain's boundary was computed three times (3.7% of a 1e5-point run).
7. **osm-mesh writes with zlib level 1**: VTK's default level 5 compression was 65% of `osm-mesh`'s instructions; writing aust.poly's mesh 4.7 s -> 2.4 s for a 2% larger file.
8. **Uninserted input points in Hilbert order** (`Overlay`): the benchmark after steps 4-7 still showed the overlay's time per triangle growing with the number of input points (random-segments: 839 ns at 1e4, 1,280 ns at 1.2e6), from SVR's buckets of waiting points scattered in memory. Permuting them along a Hilbert curve (choices still made on the caller's indices, so the output is byte-identical): 1.2e6 overlay 1,280 -> 898 ns per triangle, core 2,197 -> 1,637.
9. **Hilbert order without branches or comparison sort** (`SpatialSort`): computing keys (branches on random bits) and sorting (key, index) pairs was 5.0% of a random-segments 2e5 run; branch-free keys (the same keys) and a stable radix sort: 3.2%.
10. **Fewer instructions per SVR insertion** (`Overlay`, `Triangulation`): a waiting input point finds its new triangle by the fan's rays (one orientation per fan triangle, shared rays tested once) instead of three orientations per triangle; the yield scan collects the waiting points so inserting the circumcenter does not walk the buckets again; the outside neighbour's back link is found by triangle id; per-slot arrays grow without an out-of-line `resize()` per insertion. Overlay instructions on random-segments 3e4: 1,050 M -> 942 M (-10%), output byte-identical. Wall time moved within the noise: the refinement is partly memory-bound (its time per insertion is 1.1 us at 2e3 points, 1.6 us from 2e4 up).
11. **Hilbert keys by table** (`SpatialSort`): 4 lookups in a 1,024-entry table (4 levels at a time) instead of 16 one-level steps, the same keys (checked on 7e8 cells): whole run 1,543 M -> 1,495 M instructions; scaling points back by a power of two with a multiplication instead of `ldexp` calls: 1,495 M -> 1,466 M.
12. **SVR yields to input points earlier** (`Overlay`, yield radius 0.5 -> 0.6 of the circumradius, any constant below 1 is SVR): fewer Steiner points, 3.5% fewer output triangles over the real and 3 generated inputs (random segments 6.4%, points 3.6%), largest angle 149.87 degrees; 1,466 M -> 1,391 M instructions. Tried and not kept: leaving the overlay coarse outside the input's bounding box (all but the Box domain discard it): small inputs 40-55% faster, but outputs 1.8% larger in geometric mean (up to 21%), for no change above 10^4 triangles; reserving the arrays for the expected overlay size (more page faults, not fewer); one struct per triangle slot for SVR's bucket and generation (0.7% fewer simulated D1 misses, no measurable time); a pseudo-angle pre-sort of the rotation system (more instructions).
13. **The cavity search lists the cavity's boundary** (`Triangulation`, output byte-identical): insertion no longer marks the cavity and scans its edges again. Overlay instructions on random-segments 3e4: 853 M -> 814 M (-4.6%), whole run 1,391 M -> 1,351 M.
14. **Completion traces only the faces that segments cross** (`Stitch`, `Complete`): the profile after 13 still spent 15% of the instructions in `complete`, which sorted the edges around every vertex and traced every face of the stitched graph, though an overlay triangle none of whose edges is crossed is a face as it stands. Stitch now lists those triangles as faces and marks the sides of the remaining edges that still need tracing. The same triangles on the 17 real inputs and 3 generated ones, both domains (compared as sets of exact coordinates; their order, and so the numbering of vertices and regions, changes): `complete` 205.5 M -> 21.6 M instructions, whole run 1,351 M -> 1,173 M (-13%); random-segments 2e5 1.99 -> 1.76 s, aust.poly 1.55 -> 1.24 s (minimum of 9 interleaved runs). Tried after it and not kept: allocating the output arrays once at their exact size (no measurable time).
15. **Domain carving reuses the overlay's adjacency** (`Stitch`, `Domain`): after 14, carving was 9% of the time, most of it matching the edges of every output triangle to find neighbours; the intact overlay triangles' neighbours among themselves are known from the overlay, so only the other edges are matched. Same triangles and region ids: domain phase on random-segments 2e5 0.154 -> 0.084 s, on points 1e6 1.00 -> 0.50 s (stitch +0.03 / +0.2 s for listing them). Measured and not changed: on points 1e6 the process spends about 2 s of its 10.7 s in the kernel, mostly first-touch page faults of freshly allocated arrays (859,000 faults); keeping freed memory in the heap (glibc tunables) cut that to 0.8 s for 8% more peak memory, but that is the host application's choice to make, not a library's, and huge pages (glibc.malloc.hugetlb=1) made it worse (3.5 s).
16. **Fewer comparison sorts of all the input points** (`Domain`, `Clean`; found with `perf record -e cpu-clock`, which samples wall time where callgrind counts instructions): the hull domain's convex hull sorted every point (2.2% of a random-segments 2e5 run), and finding exact duplicates sorted indices that each comparison followed into the point array (1.5%). The hull now sorts only the points outside the quadrilateral of the x and y extremes (Akl-Toussaint; the same hull, checked against gift wrapping on 200 random sets), and duplicates are found by sorting (point, index) pairs: random-segments 2e5 1.670 -> 1.637 s (minimum of 9), clean phase 0.049 -> 0.039 s (median of 9); the same meshes.
17. **The overlay's vertex-to-triangle links written in spatial order** (`compactOverlay`, found with `perf annotate`): a quarter of its samples were one scattered store per triangle corner, made in the refinement's slot order; made in the compact (spatial) order instead: stitch phase on random-segments 2e5 0.317 -> 0.286 s, on points 1e6 1.53 -> 1.42 s (minimum of 9), the same meshes.
18. **Arrays reserved instead of grown by doubling** (`Overlay`, `Stitch`, `Mesher`, found with `perf record -e page-faults`): a fifth of a points 3e5 run was system time, 240,435 first-touch page faults for a 386 MB peak. The refinement now reserves room for 6 overlay vertices per input point (random inputs need about 5; untouched room costs only address space), and stitching and the output reserve their upper bounds. Page faults 240,435 -> 138,203, system time 0.60 -> 0.45 s, peak 386 -> 371 MB; whole run, minimum of 9: random-segments 2e5 1.755 -> 1.550 s, points 3e5 2.832 -> 2.520 s, us48 1.278 -> 1.161 s (together with 19), the same meshes.
19. **One array of per-slot refinement state, one circumcenter per queued triangle** (`Overlay`, found with `perf annotate`): 16% of `insertVertex`'s samples were the store after a cache miss on the slot's generation, kept apart from its bucket; they now sit side by side. The quality test uses the circumcenter computed for the queue key, relative to a vertex so that tiny triangles far from the origin stay exact enough; the same meshes.
20. **No arrays over every overlay edge for a few crossings** (`Stitch`), **no copy of the overlay points to renumber them** (`Overlay`): 8,600 and 5,700 page faults on points 3e5; stitch phase 0.402 -> 0.364 s there (minimum of 9).
21. **Convex hull filtered by 8 extreme points, not 4** (`convexHull`, found with `perf record`): on uniform points the quadrilateral left about 40% of them to sort; the hull went from 2.34% to 0.36% of a points 1e6 run.
22. **Hole seeds located among the remaining triangles only** (`carveDomain`, found with callgrind on the small real inputs, where it was 18% of A.poly's instructions): the grid that finds the triangle under each hole point held the padded box's large triangles too, each covering a large share of its cells; it now holds only the triangles not yet removed. Instructions of the whole mesh call: A.poly 4.57 M -> 4.17 M, lake_superior.poly 23.8 M -> 22.5 M, face.poly 2.16 M -> 2.03 M; the same meshes.
23. **Hilbert table built at compile time** (`SpatialSort`, callgrind on A.poly): its construction was about 100,000 instructions per process, 2% of meshing A.poly.

Tried after 18-21 and not kept: telling cavity triangles apart by scanning the short lists of a cavity instead of stamps per slot (no measurable change); reserving for 16 overlay vertices per input point instead of 6 (overlay phase 6-9% faster on us48.poly and aust.poly, whole run within the noise, for 2.7 times the address space).

24. **The overlay's arrays reused in place** (`Stitch`, `Domain`, `Mesher`, found with `perf record -e page-faults`): after 18-23, points 1e6 still took 504,534 page faults, because every phase copied the previous one's large arrays: the compact overlay's triangles and neighbours into the intact triangles and their adjacency, that adjacency into carving's, carving's labels into region ids, the completed triangles into the output. Each now becomes the next in place (an intact triangle, a kept output triangle only moves down), and the overlay's points move into the stitched graph; only a kept overlay is copied. points 1e6 (alternating runs): page faults 504,534 -> 375,707, system time 1.65-2.08 -> 1.06 s, stitch phase 1.60-1.88 -> 1.32-1.34 s, domain 0.64-0.78 -> 0.47-0.50 s; the same meshes.
25. **One 32-byte slot per triangle** (`Triangulation`, found with `perf annotate`): a triangle's vertices, neighbours and cavity-search stamp were three arrays, a cache miss each when the refinement touches a triangle; they now share half a cache line. points 1e6, 5 alternating runs: overlay phase minimum 6.05 -> 5.82 s; 4 bytes of padding per slot.
26. **A triangle's bucket of waiting points in its slot** (`Overlay`): the padding of 25 holds the bucket's head, read right after the triangle itself; whole run minimum 8.69 -> 8.56 s.
27. **Overlay edges named by a half-edge of their smaller triangle** (`Stitch`): compaction built an edge list and per-triangle edge ids (24 bytes per triangle) and stitch four arrays over the edges; the ids 3c + i come in the order the dense ids had, so nothing else changes, and one flag byte per half-edge replaces the arrays. points 1e6, 5 alternating runs: whole run minimum 8.74 -> 8.06 s, stitch phase 1.42-2.47 -> 0.91-1.42 s, core peak 111.7 -> 87.6 bytes per triangle; .vtp output byte-identical.
28. **Regions by union-find in triangle order** (`Domain`): the floods' depth-first order jumped around memory; uniting triangles across unconstrained edges in index order reads them in spatial order, and numbering components by their smallest triangle gives the same region ids. points 1e6: domain phase median 0.409 -> 0.314 s.

29. **No generation array in the refinement** (`Overlay`, found with `perf annotate`: the generation bump of every new triangle was 13% of `insertVertex`'s samples, a cache miss in an array of its own): an insertion puts the new vertex at index 2 of every triangle it makes, so a slot and its vertex 2 name one triangle over the whole run, and the queue items carry that vertex instead. 9 interleaved runs: points 3e5 whole run median 2.724 -> 2.609 s; the same meshes.

Tried after 24-29 and not kept: compacting the overlay in the refinement's slot order instead of sorting triangles by their lowest vertex (compaction cheaper, but the later phases lost their locality: points 3e5 whole run +0.28 s); the angle statistics' cosine filter by squares without a square root or division, and taking the statistics during the output loop (no measurable change); telling cavity triangles apart by scanning lists, to give the stamp's room to the refinement's generation counter (overlay 2-4% slower); the stitch edge loop without divisions (no measurable change).

30. **The insertion's scratch array given back when the refinement ends** (`Triangulation`, `Overlay`, found when the fan-linking experiment below lowered the peak): the array over the vertices that links a new fan of triangles (up to twice the vertex count) stayed allocated through compaction, where the core's peak is. The same meshes; core peak random-segments 2e5 95.7 -> 90.2 bytes per triangle, us48.poly 100.9 -> 96.4, random-segments 1.2e6 94.0 -> 91.6.

Tried after 30 and not kept (in-process A/B runs, alternating, 6-10 rounds; differences under about 5% are within this machine's noise): linking a new fan by matching the ends of its own edges instead of that array (the same meshes and no array at all, but 0.6% more instructions and us48.poly 6% slower in the median); starting the circumcenter's cavity search at the triangle being refined instead of walking to the one that contains it (4-5% fewer overlay instructions, but every mesh changes, 0.2-0.5% more triangles, and no time difference above the noise); prefetching the slot of the queue's next triangle (no difference at 1.2e6 points); the segment's length computed once per stitching walk instead of per crossing (0.04% fewer instructions); a smaller padded box (A.poly 1.01 -> 0.63 ms, still 2.4 times Mesh_2's time, and every mesh and the Box domain change).

31. **Transparent huge pages for the large arrays** (`HugePages`, found with `perf stat -e page-faults` and `perf record` on a new machine: a points 1e6 run spent 1.9 of its 10.0 s in the kernel on 299,000 first-touch page faults, and the refinement's scattered accesses to its triangle slots missed the TLB; the process-wide `GLIBC_TUNABLES=glibc.malloc.hugetlb=1` cut that run to 6.0-6.5 s): the core asks the kernel (`madvise(MADV_HUGEPAGE)`, Linux; Debian's kernels give huge pages only to memory that asks) for 2 MiB pages for its own arrays of 8 MiB or more, before they are first touched, and grows the triangulation's arrays and the refinement queue into such memory; the VTK filter does the same for its output arrays. The host application's heap is left as it is, and `OSM_NO_HUGE_PAGES=1` turns the advice off. Page faults on points 1e6: 299,000 -> 62,000. `bench_osm` CPU seconds, median of 3 alternating runs, before -> after: points 1e5 1.107 -> 0.722, random-segments 2e5 2.299 -> 1.253, us48.poly 1.474 -> 0.843, aust.poly 1.431 -> 1.266, points 1e6 9.745 -> 7.282, random-segments 1.2e6 11.3 -> 11.3 in that series but 11.5-15.4 -> 8.4-8.7 in the next (this machine's noise at that size). The same meshes: the 17 real inputs in both domains, written by `osm-mesh` as .node/.ele/.edge, are byte-identical. Items 15 and 18 found the glibc tunable slower on the machine of the time (more system time); on this one (kernel 6.18, THP in madvise mode) it is 30-40% faster. The gain depends on the kernel and on how fragmented its free memory is.

32. **Fewer first touches of small pages** (`HugePages`, `Triangulation`, found with `perf record -e page-faults --call-graph dwarf` on random-segments 2e5 after 31, which still took 20,000 faults; on this virtual machine each first touch of a 4 KiB page costs about 11 us: a fresh 8 MB array filled with `memset` takes 22 ms in 4 KiB pages and 0.7 ms in huge pages). The huge-page advice now covers every whole 2 MiB page of an array, not only arrays of 8 MiB or more: faults 19,600 -> 15,600; CPU seconds, median of 9 alternating runs: random-segments 2e4 0.141 -> 0.118, points 1e5 0.565 -> 0.535, us48.poly 0.812 -> 0.776, random-segments 2e5 unchanged (1.086 -> 1.091); peak memory per triangle +13% at 1e4 triangles (94.6 -> 107.2 B), +8% at 2e4, unchanged from 1e5 up (a huge page is resident whole once touched). A new fan is linked by comparing its own edges' ends when it has at most 16 triangles, instead of through an array over all the vertices, whose regrowth first-touched 2,500 pages: 1.6-2.2% faster on random-segments 2e5 and points 1e5 (9 rounds), within the noise on us48 and aust (0.98-0.99, 15 rounds); item 30 had measured this on the previous machine as 6% slower on us48, so the gain depends on the machine. The refinement's per-step calls are inlined (circumcenterOffset, the common case of pushBackHuge): 2.1% fewer instructions, about 1% less time. The same meshes (the 40 written by `osm-mesh`, byte for byte). Tried and not kept: off-centers (Ungor) for skinny overlay triangles, 2.5-3.4% fewer triangles but the overlay would no longer be the paper's SVR; a yield radius of 0.8 or 0.95 (more instructions, no fewer triangles); a byte per triangle slot counting its generations, so that a stale queue item (38% of all) is skipped without loading its slot (no measurable difference); an allocator giving every internal array of 1 MiB or more its own 2 MiB-aligned huge pages (faults 20,800 -> 18,100 only: the later arrays then faulted the memory that the freed ones used to leave in the heap). What remains: random-segments 2e5 still first-touches about 15,600 small pages, about 0.15 s of its 1.05 s here; the process-wide `GLIBC_TUNABLES=glibc.malloc.hugetlb=1` removes 80% of them and 13% of the time, but that is the host application's setting to make.

33. **Every core array in huge pages of its own** (`HugePages`: `osm::Array`, found with `perf record -e page-faults` after 32 and an `LD_PRELOAD` experiment that served every large allocation of the process from 2 MiB-aligned huge-page mappings: 8-25% faster): 32 advised the whole huge pages inside glibc's blocks, which start anywhere, so the small pages at both ends of every block, and every array not made through its helpers, were still faulted one by one. `osm::Array` (a `std::vector` with the allocator `HugeAllocator`) is now the type of every array of the core, its input (`Pslg`) and its `Result`: a block of 512 KiB or more gets a mapping of its own, 2 MiB-aligned and advised, smaller ones come from `operator new`; `pages::Reuse`, one per `osm::mesh` call, keeps freed mappings of up to 16 MiB (16 MiB in all) for the next request of the same size. random-segments 2e5: page faults 15,263 -> 951, system time 0.35 -> 0.03 s, huge pages cleared 185 -> 138 with the reuse. CPU seconds, median of 11 alternating runs against the code before: random-segments 2e5 1.068 -> 0.925, us48.poly 0.767 -> 0.632, points 1e5 0.538 -> 0.436, Constrained_Sweden.poly 0.053 -> 0.039, random-segments 1e4 0.060 -> 0.048. The cost is memory at 1e4 to 1e5 triangles, where a live array of 512 KiB holds a whole 2 MiB page: peak per triangle random-segments 1e4 93 -> 153 B, Constrained_Sweden.poly 160 -> 329 B; none from 1e5 triangles up (random-segments 2e5 91 -> 92 B). The same meshes (the 40 written by `osm-mesh`, byte for byte). What remains is the clearing of fresh memory itself: `clear_page_erms` is 13% of the samples, 276 MB cleared on this machine at about 3 GB/s for a peak of 150 MB; keeping every freed mapping for reuse (fit, the tail given back) would clear as much, by a simulation of the run's sequence of mappings. Also: the cleaned points and segments are moved, not copied, into the mesher's working set and scaled by a multiplication (clean phase 0.0238 -> 0.0220 s). With the core faster, the VTK filter's own share grew past its target (+30% of the core's time at 8.3e5 triangles in a suite run between the two changes): its output arrays, from `malloc`, took 8,118 page faults on random-segments 1e5. They now live in the same huge-page mappings (handed to VTK with `SetArray` and a free function, the mapping's size in a header before the values), and MinAngle/MaxAngle take two `atan2` per triangle, at the vertices opposite the shortest and the longest edge, instead of three: faults 8,118 -> 3,175, filter overhead (median of 7 alternating runs) random-segments 1e5 +31.7% -> +17.2%, 2e5 +27.3% -> +18.0%; 20 of the 2.5 million angle values of us48.poly differ, by at most 1.4e-14 degree (two edges of equal length within rounding). Tried and not kept: testing only the angles opposite the shortest and longest edge in the core's own angle statistics as well (no measurable change: the cosine filter already skips nearly all).

34. **The overlay refines only where the domain may be** (`Overlay`, `Mesher`, found by comparing overlay and output sizes: A.poly had 939 overlay triangles for 196 output triangles). The overlay covers a padded box 16 times the input's bounding box in area; with the enclosed or hull domain no output triangle can come from the part beyond the input's bounds (the segments' bounds for the enclosed domain, the points' for the hull). An overlay triangle that holds no waiting input point and lies beyond one side of those bounds is now left as it is; every triangle that meets them is refined as before, so the paper's bounds hold where the mesh is. Overlay triangles: A.poly 939 -> 511, face 360 -> 218, double_hex 1,097 -> 693, guitar 1,825 -> 1,125, la 2,430 -> 1,552, random-segments 2e5 1,678,827 -> 1,665,826. The box domain is unchanged (its meshes are byte-identical); the others change (output triangles from -2% to +21%, e.g. clusters.poly 198 -> 240; largest angle on the real inputs 149.86 degrees). CPU seconds, median of 11 alternating runs against the code before: A.poly 1.23 -> 1.03 ms, face -19%, double_hex -19%, guitar -22%, la -15%, random-segments 1e3 -16%, points 1e3 -8%, airfoil and clusters unchanged. Freed huge-page mappings are now all kept during a call (merged where they touch) and a request takes the front of the smallest kept range that holds it; a request none holds gives them all back first, so the process never holds more than without reuse: random-segments 2e5 clears 96 huge pages instead of 135, peak 158 -> 146 MB, system time 0.102 -> 0.077 s (6 runs), CPU time within the noise; peak per triangle random-segments 1e4 177 -> 155 B, Constrained_Sweden.poly 404 -> 348 B. Measured: on this virtual machine the first touch of fresh memory is the largest single cost (page faults and clearing are 18% of random-segments 2e5's samples): 192 MB of huge pages take 359 ms to touch the first time in a process and 17 ms when the same process maps them again (the host backs freed guest memory again only when it is touched). Measured too: meshing A.poly again in the same process takes 0.32 ms against Mesh_2's 0.075 ms, so the gap on the smallest inputs is the overlay's size, not start-up. Tried and not kept: a coarse grid over the segments, flooded from its border, so that overlay triangles outside the enclosed region are not refined either (Constrained_Sweden.poly's overlay only 1.5% smaller at 4 cells per segment, 8% at 64: the exterior's overlay triangles lie near the coastline); prefetching a cavity triangle's neighbours (in-process A/B: the same minimum time); binding symbols at load time (`LD_BIND_NOW`, no change); renumbering the overlay along the Hilbert curve in place and compacting it into the refinement's vertex-triangle array (peak at the end of the overlay 145 -> 131 MB, but the run's peak and time did not improve).

35. **Wider size classes in the refinement queue** (`SizeQueue`, found by trying class widths: the overlay is memory-bound, its time per insertion 1.1 us while the mesh fits in cache and 1.6 us beyond). A class now spans a factor of 8 in circumradius instead of 2. A triangle an insertion creates is refined next, while its neighbourhood is in cache, only if it falls into the class being refined; with a factor of 2 most fell into the next class, which waits until the current one is done all over the mesh. SVR needs the order only within a constant factor. Overlay phase, median of 9 alternating runs against the code before: random-segments 2e5 0.598 -> 0.549 s, us48 0.377 -> 0.332 s, points 1e6 4.38 -> 3.97 s, spread 3e3 0.323 -> 0.289 s, with 0.4-6% fewer triangles on the large inputs; a factor of the square root of 2 was 10% slower, 16 and 64 no faster than 8. Small inputs move with their triangle counts (clusters.poly 240 -> 196, airfoil.poly 5,867 -> 6,392); largest angle on the real inputs 149.59 degrees. With the same meshes (120 files written by `osm-mesh`, byte for byte): the output's angle statistics filter on cos|cos| multiplied out, each triangle's three corners from its three edge vectors, instead of a square root, a division and modulo index arithmetic per angle (`buildOutput` 77 M -> 55 M instructions on random-segments 3e4); a stitching walk computes its segment's length once and reuses orient2d's value in its snap test instead of a `hypot` call and a second orient2d per vertex (stitch phase -2% to -4%); the hull boundary computes each chain edge's length once (28 M -> 20 M instructions); the queue reads a key's exponent from its bits instead of calling `ilogb`. All together, median of 11 alternating runs against the code before: random-segments 2e5 0.905 -> 0.826 s (-8.7%), us48 0.630 -> 0.563 s (-10.7%). Tried and not kept: the quality test without the circumcenter's two divisions (0.3% fewer instructions, no measurable time); freeing the refiner's arrays before the Hilbert renumbering (2 fewer huge pages cleared of 94, the same peak); moving the kept huge pages into the front of a fresh mapping (`mremap`) when no kept range holds a request, instead of giving them back: huge pages cleared on random-segments 2e5 94 -> 75, us48 84 -> 64, points 1e6 444 -> 368, but the core's peak 3-8% higher and no time gain measurable here (median of 15 alternating runs: random-segments 2e5, us48 and aust.poly within 1.5% either way).

36. **Medium arrays in huge pages too** (`BlockPool`, found by counting each call's page faults, now in every driver's output as `minor_faults`, and timing first touches on this machine: 11 us per fresh 4 KiB page, 60-220 us per fresh 2 MiB page). Array blocks from 4 KiB to 512 KiB came from `operator new`, fresh small pages each: random-segments 1e3 took 263 faults in its call and Constrained_Sweden.poly 1,122, about a third of their time. While `osm::mesh` runs, such blocks now come from 2 MiB huge-page chunks of a pool, which hands freed blocks out again (merged within their chunk). A call starts pooling at its first block of 64 KiB (a mesh of a few thousand triangles), so small meshes clear no huge page; a block that outlives the call (the result's arrays) keeps its chunk mapped, its free parts given back, until it is freed. Page faults per call: Constrained_Sweden 1,122 -> 28, random-segments 1e3 263 -> 58, 1e4 871 -> 82, us48.poly 753 -> 141. CPU time, median of 13 alternating runs against the code before: airfoil.poly 5.37 -> 3.39 ms, nazca_monkey 7.32 -> 4.85, Constrained_Sweden 43.9 -> 28.7, img5 4.54 -> 3.06, lake_superior 4.06 -> 3.11, square_circle_hole 3.25 -> 2.37, random-segments 1e3 9.92 -> 6.17, points 1e3 9.83 -> 6.12 (-23% to -38%); inputs that never ask for a 64 KiB block (A, double_hex, guitar, airfoil_exterior, la: 100-1,800 triangles) take the path of before, measured -5% to +9% (noise). With the pool's first version (same chunks, pooling from 256 KiB asked for in all), 9-13 alternating runs: random-segments 1e4 -20%, points 1e4 -16%, us48 -9%, random-segments 2e5 -4%, points 1e5 -2.5%. Peak memory grows by at most one huge page: random-segments 1e4 12.8 -> 15.0 MB, Constrained_Sweden 12.5 -> 13.1 MB, guitar 0.6 -> 2.8 MB (first version), us48 129 -> 131 MB. The same meshes (120 files written by `osm-mesh`, byte for byte). Tried and not kept: pooling from the first 256 KiB asked for in a call (guitar.poly and airfoil_exterior.poly then cleared a huge page for a few blocks: +17% to +27%); one pool scope around the whole VTK filter run, so that its output arrays reuse the core's freed huge pages (filter overhead at 1e4 triangles +47% -> +31%, 1e5 +20% -> +17%, 2e5 and us48 within 2%, but us48's peak 145 -> 163 MB).

37. **A chunk that outlives its call stays whole** (`BlockPool`, found by timing each part of a call on medium inputs in a fresh process: what came after the core's own total took 0.16-0.22 ms, and `strace` showed `madvise(MADV_DONTNEED)` on most of a huge page there). When a call ended, the pool gave back the free parts of every chunk still holding a block of the result; giving back part of a huge page makes the kernel split it. Such a chunk now stays whole, 2 MiB resident, until the result's last block in it is freed, when it is unmapped in one piece. Time from the core's total to the call's return, median of 21 fresh processes each: lake_superior.poly 0.216 -> 0.023 ms, nazca_monkey 0.180 -> 0.019, airfoil 0.190 -> 0.022, img5 0.217 -> 0.019, square_circle_hole 0.162 -> 0.023 (la.poly and guitar.poly, which never pool, 0.04 both ways). CPU time of `bench_osm`, median of 15-21 alternating runs against the code before: lake_superior 2.997 -> 2.740 ms (-9%), square_circle_hole -8%, img5 -7%, airfoil -4%, nazca_monkey -4%; the same meshes (the pool only places arrays). The cost: a result of a medium mesh keeps up to 2 MiB per chunk resident while it lives (the VTK filter and `osm-mesh` free theirs at once). Tested by `BlockPool.AChunkThatOutlivesItsScopeStaysWhole`, which fails on the code before (the mapping's resident size fell from 2,048 to 100 KiB).

Tried after 37 and not kept:

- **Leaving the exterior's poor triangles unrefined.** The enclosed and hull domains drop every triangle of the exterior, yet the overlay refines it near the coastline, where the input points grade it. An exact, conservative test (a grid over the segments; grid nodes flooded from the border along grid edges no segment touches; a poor triangle left as it is when it touches no segment and a straight path touching no segment joins one of its vertices to such a node) cut the overlay's triangles substantially: Constrained_Sweden.poly 64,037 -> 48,507, nazca_monkey 8,543 -> 7,104, lake_superior 4,640 -> 3,906, A 521 -> 411, with valid meshes. But it cost more than it saved. Instructions of the mesh call (callgrind): lake_superior 18.87 M -> 20.06 M, Constrained_Sweden 244.4 M -> 245.7 M, nazca_monkey 34.5 M -> 36.3 M, A 2.72 M -> 2.86 M, face 1.30 M -> 1.80 M. The insertions themselves fell by about 15% on lake_superior (`cavityOf` 2.83 M -> 2.45 M, `insertIntoCavity` 3.64 M -> 3.05 M), but the test on every poor triangle (1.8 M) and building the grid (1.4 M) more than ate that. A first version with a coarse grid of empty cells only is item 34's.
- **The first call's fixed costs on the smallest inputs** (measured, not changed). In a fresh process meshing face.poly (95 triangles) takes about 0.7 ms, and a call after a first one in the same process 0.15-0.4 ms. Warming one thing at a time before the timed call (median of 41 fresh processes each): libm's `sin` and `cos`, which the call uses for its constants from the minimum angle, save 0.10-0.13 ms (their code and tables fault in); 256 KiB of heap touched beforehand 0.08 ms in the overlay and 0.04 ms in stitching; the exact predicates' stack and code 0.04 ms; a tiny overlay built first (code and data of that phase) 0.18 ms. Mesh_2 pays such costs too (0.33 ms on face.poly in a fresh process). With all of them gone (a whole call first), face.poly would be about level with Mesh_2, and A.poly, at 0.36 ms on a repeat call against Mesh_2's 0.29 ms in a fresh process, would still lose; replacing libm's `sin` with code of our own, to save 0.1 ms only in a fresh process, was left then (item 46 did it).

38. **A few hole seeds are found by a scan** (`carveDomain`, callgrind on the small real inputs: the grid that finds the triangle under each hole seed took about 0.9 M instructions on lake_superior.poly for its 6 seeds). Up to 8 seeds, each is now found by scanning the triangles (box test first), which gives the same triangle as the grid: the first in index order whose closure holds the seed (`Domain.HoleSeedsFoundByScanOrByGridCarveAlike` checks that on 200 random seed sets with seeds on edges and vertices; it fails if the scan takes the last match). Instructions of the mesh call: A.poly 2.72 M -> 2.60 M, guitar 5.71 M -> 5.39 M, lake_superior 18.87 M -> 17.86 M, square_circle_hole 12.05 M -> 11.19 M (-4.5% to -7.1%); CPU time, median of 21 alternating runs: -6% to -7% on those four. The same 120 output files (`osm-mesh`, every real input and 3 generated ones, both domains, byte for byte).

39. **One atan2 per completion triangle** (`triangulateMinMaxAngle`, callgrind on us48.poly: completion was 8.4% of the instructions, and 53,370 of its 53,428 faces are quadrilaterals, each costing about 5,200 instructions: 3.7 `maxAngle` calls of three `atan2` each, and four allocations). `maxAngle` now computes only the angles opposite the edges within a relative 1e-9 (in squared length) of the longest: any other angle is smaller by far more than the rounding of the angles, so the maximum is the same value (`Complete.MaxAngleIsTheLargestOfTheThreeAngles` checks it bit for bit on 40,000 random and isosceles triangles and on extreme ones; computing only the angle opposite the longest edge fails it). The search's arrays are kept from one face to the next. Instructions of the mesh call: us48 5,095 M -> 4,969 M (-2.5%), A.poly 2.60 M -> 2.40 M (-7.8%), clusters -9.3%, fish-and-rectangle -6.5%, face -5.9%; CPU time, median of 21 alternating runs: -4% to -5% on the small ones. The same 120 output files.

40. **Quadrilaterals by the dynamic program unrolled** (`triangulateMinMaxAngle`, after 39: most completed faces are quadrilaterals). For four vertices the program's arrays, loops and stack are gone, and its 24 orientation tests (two diagonal tests of eight, four apex tests) are answered by four: an exact orientation's sign only changes with the order of its three points, and a quadrilateral has four triples. The same tests in the same order, so the same triangles: `Complete.QuadrilateralsAsTheDynamicProgram` compares both on 100,000 quadrilaterals, half on a 4 x 4 integer grid (ties, straight and zero angles, repeated points, reflex and clockwise ones); it fails when a tie goes to the other diagonal or when one sign flip of the triple order is left out. Instructions of the mesh call: A.poly 2.397 M -> 2.310 M (-3.6%), la 8.381 M -> 8.017 M (-4.3%), clusters -4.3%, face -2.9%, Constrained_Sweden 236.6 M -> 233.2 M (-1.4%), us48 4,969 M -> 4,914 M (-1.1%); CPU time, median of 21 alternating runs, within this machine's noise (-4.7% to +2.5%). The same 120 output files.

41. **The scaling measured in rounds** (the suite itself, found by comparing the suite's runs: the scaling verdict changed from run to run on the same core, as the small sizes and the large ones, minutes apart, fell into different phases of this machine). After the main pass the suite now times the core on every size of a family in turn, in 5 rounds (forward, then backward), and compares each size with the smallest one in the same round; the target's verdict takes the median of those paired ratios, and the main pass's figures stay beside it. Every driver also reports the kernel's part of its CPU time: the kernel's share of the large runs (page faults and the clearing of fresh pages, which this virtual machine makes slow: a fresh 4 KiB page costs 10-15 us to touch, 1 us of it in the guest) is most of their growth per triangle. In a trial of 3 rounds before the change of 40: random segments x1.31, points x1.42, spread x1.07.

Tried after 39 and not kept: renumbering the overlay's vertices along the Hilbert curve in place, by following the permutation's cycles, instead of copying into fresh arrays (30 fewer huge pages cleared of 445 on points 1e6, but its overlay phase took 0.4-2.1 s longer in 4 alternating runs: each swap waits for the load before it, where the copy's independent writes overlap); sorting the Hilbert keys as packed 64-bit (key, index) pairs with 11-bit digits, read in order instead of gathered (0.19 -> 0.13 s alone on 4.7 million points, but 0.28 -> 0.25 s inside a run of 5-6 s, whose renumbering takes 0.5 s: its 16 bytes per point are fresh memory too).

42. **Segments walked in spatial order** (`walkSegments`, found with `perf record` on random-segments 1.2e6, where the walks were 7.3% of the samples and 2.2% of the instructions: each walk of a segment soup starts where the one before did not, with cache misses). Stitching now walks the segments in the order of their smaller overlay vertex, which the overlay numbers along the Hilbert curve (a bucket sort into as many classes as segments: linear time, 8 bytes per segment). The walks' pieces and crossings then come in that order, so every use of them that shapes the output visits them in segment order (each segment's pieces are contiguous, `Walk::firstPiece` gives the first): duplicate pieces keep the first by segment, a triangle's pieces pair up by segment, the segment crossings are recorded and the input subsegments added in segment order. The same 138 output files (`osm-mesh`, `.node`/`.ele`/`.edge`, both domains, 17 real inputs and 6 generated ones, two of them with 235 and 11,474 segment crossings and collinear overlaps) and `.vtp` files, byte for byte; `Stitch.TheStitchedGraphDoesNotDependOnTheWalkOrder` compares the graph, the inspected edges and the segment crossings of walks in index, reverse, random and spatial order (it fails if duplicates keep the first by piece, or the subsegments come in piece order). Stitch phase, median of alternating runs against the code before: random-segments 1.2e6 1.305 -> 0.966 s (11 runs), 2e5 0.169 -> 0.120 s (7 runs); inputs whose segments come in chains were already walked locally (us48.poly 0.136 -> 0.147 s, aust.poly 0.130 -> 0.117 s, water-huge3.poly 0.018 -> 0.015 s, 15 runs: within this machine's noise), and on us48.poly the mesh call takes 0.6% more instructions (4,913 M -> 4,944 M: the sorts of the pieces and crossings see them in another order).

43. **The vtkDelaunay2D target against the mean of 5 OSM runs** (the suite itself, found by comparing the pairs of run 8: 33.8, 46.1 and 47.7 to one). Each vtkDelaunay2D run at 1e5 segments averages this machine's speed over about 50 seconds; the single OSM run of about a second after it sampled one second of it, and on this machine the same OSM run took 0.95 to 1.67 s from one minute to the next. Each pair now takes the mean of 5 OSM runs (a mean, not a median: the median of a spread skewed towards slow runs would favour OSM).

44. **Compaction's peak lowered** (`compactOverlay`, found by tracing the resident memory at each huge-page mapping of random-segments 1.2e6, with `perf record` beside it: `clear_page_erms`, the kernel clearing fresh pages, was 20% of the samples, and the process's high-water mark, 772 MB, was at compaction, where the overlay's triangle slots and their compact copy live together). Compaction now frees the overlay's vertex-triangle links before it copies (nothing after it walks from a vertex), keeps each slot's compact index in the slot's mark (the cavity search's stamp, unused from there on) instead of an array over the slots, and builds the compact vertex links once the slots are freed, in their pages. Peak resident memory of `bench_osm`: random-segments 1.2e6 772 -> 714 MB, points 1e6 716 -> 658 MB; random-segments 2e5, us48.poly and aust.poly within 4 MB (their peaks lie elsewhere). CPU seconds, median of alternating runs against the code before: random-segments 1.2e6 6.10 -> 5.80 (6 runs; system time 0.75 -> 0.55), points 1e6 4.86 -> 4.62 (4 runs; system time 0.56 -> 0.25). The same 144 output files (`osm-mesh`, 17 real inputs and 7 generated ones, both domains, byte for byte). Tried before it and not kept: when no kept range holds a request, filling the front of the fresh mapping with the kept ranges' pages, moved by `mremap`, instead of giving them back (on the idea that pages this process has touched are backed by the host already). No gain: CPU 6.14 -> 6.25 s and system time 0.87 -> 1.05 s (median of 8 alternating runs), and the peak rose 772 -> 826 MB, as moved pages landed in reserved room that is never touched. On this machine a page the guest freed a moment ago is cheap to take again; what costs is raising the process's high-water mark.

45. **Output cells in 32-bit storage** (`vtkOverlayStitchMesher`, found by looking at what the filter's output holds per triangle: 24 bytes of connectivity and 8 of offsets in `vtkIdType`, more than the angles and region id together). The filter now builds each port's `vtkCellArray` from `vtkTypeInt32Array` offsets and connectivity whenever the ids fit (below about 700 million triangles), 64-bit beyond; the MPI gather converts its cells the same way, so that serial and parallel outputs stay byte-identical. Measured after suite run 10, one run each of the code before (575f1f9) and after, each with its own build of the filter library: `osm-mesh` on random-segments 1.2e6 (writing .vtp), GNU time's maximum RSS 1,810 -> 1,485 MB (twice each, within 0.1 MB), 188 -> 154 bytes per output triangle, and the .vtp file 364.9 -> 355.6 MB; `bench_vtk_osm`, peak increase during `Update()`: random-segments 2e5 181 -> 157 MB, 1.2e6 958 -> 808 MB.

46. **A fresh process's fixed costs on meshes of up to 10,000 triangles** (`BlockPool`, `Series`, found by recording every page fault of a call with its call stack, `perf record -e page-faults --call-graph dwarf`, and timing first touches on this machine again: 12 us per fresh 4 KiB page, 120-220 us per fresh 2 MiB page, and 115-250 us for the first `sin` of a process, 17-56 us for the first `asin`). (a) A call now pools its medium blocks from its first block of 32 KiB instead of 64 KiB: meshes of 500 to 2,000 triangles never asked for 64 KiB and took every block in fresh small pages; page faults in the call: la.poly 71 -> 25, guitar 54 -> 26, airfoil_exterior 53 -> 23. (b) The sine, cosine and arcsine of the constants from the minimum angle, and the cosines in the angle statistics' filter, come from Taylor series of the project's own (`Filters/Core/Series.h`): within an ulp of libm's for the constants and equal to them at whole degrees, within 1e-15 for the filter's cosines, which only widen a 1e-9 margin (`Series.*` tests); libm's first call faulted in 5 to 7 pages of its code and tables. Wall time of the call, median of 21 fresh processes alternating the code before (8bf18db) / (b) alone / both: A.poly 1.297 / 1.198 / 1.262 ms, face 1.081 / 1.154 / 1.135, clusters 0.995 / 0.990 / 0.855, double_hex 1.176 / 1.088 / 1.150, fish-and-rectangle 1.020 / 0.977 / 0.955, guitar 1.851 / 1.766 / 1.571, airfoil_exterior 1.644 / 1.775 / 1.464, la 2.332 / 2.310 / 1.912, lake_superior 3.267 / 3.210 / 3.149, square_circle_hole 2.073 / 2.013 / 2.001, nazca_monkey 4.786 / 4.648 / 4.431, airfoil 3.566 / 3.572 / 3.395, img5 3.019 / 2.916 / 2.905; from Constrained_Sweden.poly (36k triangles) and random-segments 1e3 up, within 1.5% either way. The same 144 output files (`osm-mesh`, every real input and 7 generated ones, both domains, byte for byte). Tried and not kept: pooling from 16 KiB (41 fresh processes each: face.poly +24%, fish-and-rectangle +10%, where a huge page was cleared for a few blocks).

47. **What a fresh process pays on the smallest inputs, and where this machine's memory noise comes from** (measurements only; the code is unchanged, the meshes too). (a) face.poly (95 triangles), timed inside one process: the first call 0.69-0.90 ms, a repeated call 0.15 ms; with a 256 MB cache-thrashing pass between two calls, 0.20-0.30 ms. Before the first call, reading one byte of every executable page of the process (883 pages, 1 ms) and touching 4 MB of heap that the call's allocations then reuse (glibc's trim threshold raised) still leave 0.38-0.41 ms and 8 page faults (stack, libm's tables): about 0.25 ms of the first call is state no page touching warms (branch predictors, TLBs). Mesh_2's whole call on face.poly takes 0.30 ms in a fresh process. The per-phase shares stay alike (overlay 0.26 of 0.53 ms first, 0.08 of 0.16 ms repeated). (b) Populating small pages ahead does not help here: 256 KiB mapped and touched page by page took 0.72-0.91 ms; with `MAP_POPULATE` (or `MADV_POPULATE_WRITE`) the populate took 0.06 ms but the first touches after it still 0.35-0.43 ms, since this guest's shadow page tables charge each page's first access again. (c) The host backs the guest's memory lazily and takes freed memory back: touching 20 GiB took 45.4 s (4.4 ms per 2 MiB page), 1.34 s right after, and 45.8 s again about 15 minutes later (`virtio_balloon`, loaded here, reports free guest memory to the host). That is the occasional 5 ms stall of a huge page (item 46) and part of the large runs' kernel share; warming the memory before a suite run would not last through it. Right after such a warm-up, Constrained_Sweden.poly's first call in a process equalled its second (26-28 ms, against 40 ms with stalls before). (d) Tried and not kept: limiting the refinement to the bounding octagon of the segments' ends (bounds along x + y and x - y as well as x and y) instead of their bounding box. Overlay triangles fell on 9 of the 17 real inputs (A.poly 521 -> 475, guitar 1,262 -> 1,154, img5 3,970 -> 3,576, nazca_monkey 8,543 -> 7,876, Constrained_Sweden 64,037 -> 62,759) but rose on face.poly (212 -> 232, and its output 95 -> 117 triangles) and fish-and-rectangle (327 -> 333): the triangles it leaves unrefined lie far from the input, where the overlay is coarse anyway. The exterior triangles that matter lie along the segments (item 34), where only an exact test against the segments at each triangle's own scale could leave them out.

48. **The scaling pass backs the memory of its runs first** (the suite itself, found when suite run 12, on the same code as run 11, gave random segments x1.53, points x1.48 and spread x1.39 against run 11's x1.34 / x1.34 / x1.05, on a machine booted 20 minutes before). The kernel's share of the 1e7-triangle runs was 20-21% (11-17% in run 11), and on user time alone the growth was the same as before (x1.25 / x1.18 / x1.05). The host of this virtual machine takes freed guest memory back within about 30 s (item 47): random-segments 1.2e6 right after 16 GiB had been touched and freed took 0.49 s of system time, and 1.44-1.52 s when started 30, 60 and 120 s later. The pass's smallest sizes reuse memory freed a moment before; the largest need more than that and pay the host's first touches. So before each run the pass now touches 4 times the size's main-pass peak and frees it (random-segments 1.2e6, system time after touching 1 / 2 / 3 / 4 GiB: 0.98 / 1.02 / 0.40 / 0.33 s; 1.25 times its 750 MB peak left 1.08-1.21 s, as the guest does not hand the freed pages out first). The main pass and every comparison between tools run as before, without it.

49. **The overlay left coarse in the segments' exterior face, tried and not kept; repeated calls in one process; why short runs' CPU clock is coarse; the vtkDelaunay2D target missed** (the open question of item 47 (d); the drivers' new `--warm K` and the suite's repeated-calls pass). (a) Item 47 left one way to thin the overlay outside the enclosed domain: an exact test, per triangle, of whether it lies in the segments' exterior face (the unbounded face, which carving removes from the enclosed and hull domains). Tried: a grid over the segments' bounds (2 cells per segment; empty cells flooded from the border are exterior) let the refinement leave a poor triangle holding no waiting input point when every cell it may touch is exterior, or when it meets no segment (exact orientation tests against the segments listed in its cells) and a straight path from a corner to an exterior cell crosses none. It was sound on 200,000 random triangles near the segments of each of Constrained_Sweden, aust and A (none meeting a segment was left), and the meshes stayed valid (largest angle at most 149.5 degrees). Overlay triangles: Constrained_Sweden 64,037 -> 56,605 (51,983 with 16 cells per segment), us48 1,365,308 -> 1,318,964, aust 1,306,077 -> 1,273,357, guitar 1,262 -> 1,070, A 521 -> 431; square_circle_hole and airfoil_exterior unchanged; output triangles mostly up a little (Constrained_Sweden 35,858 -> 36,681, guitar 527 -> 535, face 95 -> 110). CPU time, median of 21 alternating fresh processes: Constrained_Sweden 23.8 -> 27.4 ms (16 cells per segment: 24.0 -> 25.6), guitar 1.19 -> 1.33 ms, A 0.905 -> 0.876 ms; us48 0.570 -> 0.652 s (7 runs). Not kept: of the 34,811 poor triangles tested on Constrained_Sweden only 2,569 could be left. About half of the final overlay lies in the exterior face (some 30,000 of 64,037 triangles), but nearly all of it is good when made: the input points and the circumcenters of the triangles that must be refined set the scale on both sides of the segments, and the test costs about as much as the insertions it saves. (b) Item 47 put the smallest inputs' gap to Mesh_2 down to a fresh process's costs. Timing both tools after 10 unmeasured calls in the same process (the new pass, *Repeated calls* above) says otherwise: in suite run 15 the core is faster on 2 of the 13 real inputs that both mesh in under 0.1 s (la, airfoil), the same 2 as in fresh processes. Warmth moves the ratios both ways: towards Mesh_2 on A.poly (OSM 0.648 -> 0.204 ms, Mesh_2 0.231 -> 0.047 ms: Mesh_2 / OSM 0.36 fresh, 0.23 repeated), guitar (0.50 -> 0.29) and square_circle_hole (0.80 -> 0.41); towards OSM on face (0.51 -> 0.77), clusters (0.52 -> 0.67), fish-and-rectangle (0.38 -> 0.52) and airfoil_exterior (0.67 -> 0.88). On those 11 inputs the gap is work per call: a 30-degree overlay over the segments' bounding box (A.poly: 521 overlay triangles for 199 output triangles; Mesh_2 makes 75), stitching and completion, against Mesh_2's refinement of the constrained triangulation alone. (c) Why the main pass times runs under 0.05 s by their shortest wall time: the suite starts each run under `RLIMIT_CPU`, which arms a process-wide CPU timer, and `CLOCK_PROCESS_CPUTIME_ID` then reads the time the kernel accumulates for the process at scheduler events, stale within a tick: a 0.27 ms call read 2.4 us (without the limit 0.35 ms; with only the address-space limit 0.25 ms). The repeated-calls pass takes its times the same way. Not changed: the calling thread's own clock would be exact, but the VTK filter's driver may run more threads. (d) The vtkDelaunay2D target failed in both suite runs of this change: 41.1x in run 14 (pairs 40.7 to 43.7) and 42.7x in run 15 (42.4 to 43.7), against 51.9x in run 13 (45.3 to 67.5) on the same core, the machine being faster for both tools (OSM 0.73 against 1.31 s, vtkDelaunay2D 33.7 against 59.5 s). Within each pair the first of the five OSM runs right after vtkDelaunay2D's is the slowest (0.91-0.95 s against 0.70-0.76 s for the second, fourth and fifth: it pays the host's first touches, item 47), but even the fastest OSM run of run 15 (0.70 s) is 48 times faster than vtkDelaunay2D's median (33.7 s), still short of 50: the target is not met on this machine as it runs now, and the pairing is left as it is.
50. **Off-centers for skinny overlay triangles** (`Overlay`, found by counting the Steiner points of the refinement against where they land: the circumcenter of a skinny triangle lies far beyond its short edge, the edge that made it poor). A triangle is now refined at its off-center (Üngör, LATIN 2004) when that is nearer than the circumcenter: the point on the bisector of the shortest edge at 0.95 of the apex distance of the isosceles triangle with angle theta1 on that edge (Gamma (1 + cos theta1) times the edge), so that edge and point make a triangle just inside the bound. The overlay stays a Delaunay mesh with every angle at least theta1, and a new point still lies at least Gamma times the refined triangle's shortest edge from every vertex (it sits in the empty circumdisk, farther than that from its boundary), which is what bounds the refinement and its size; the paper allows any point-set mesher with SVR's guarantees. Item 32 had tried off-centers at about 0.7 of the apex distance and found 2.5-3.4% fewer triangles; by output triangles over the 17 real inputs and random-segments 1e4, points 1e4 and spread 1e3, the fraction matters: 0.7 gave 3% fewer in total, 0.8 8%, and 0.86 to 1.0 9-11% (8-10% in the geometric mean over the inputs) with no clear trend between them. At 0.95: 8% fewer in the geometric mean, from 19% fewer (A.poly 199 -> 162) to 8% more (double_hex.poly 342 -> 368), us48.poly 1,241,088 -> 1,089,238, aust.poly 1,290,961 -> 1,163,697, random-segments 2e5 1,648,621 -> 1,494,529; largest angle on the real inputs 149.59 -> 149.96 degrees. Instructions of `bench_osm random-segments:30000:1` (callgrind, whole process) 1,290 M -> 1,196 M (-7.3%): fewer insertions, but the waiting input points move between buckets as often as before. CPU seconds, median of alternating fresh processes against the code before (this machine was in a noisy phase; the suite runs are what to read): random-segments 2e5 0.905 -> 0.678 (9 runs), us48.poly 0.544 -> 0.484 (7, the prototype at the same distance), Constrained_Sweden 33.5 -> 23.6 ms, square_circle_hole 2.14 -> 1.75 ms, A 1.05 -> 0.94 ms (21 runs each); aust.poly moved within the noise (fastest run 0.577 -> 0.549 s, median 0.654 -> 0.778). With fewer triangles the generated families' largest sizes no longer reached 1e7 triangles (random-segments 1.2e6: 8.8 million), so they are now random-segments 1.4e6 and points 1.3e6. Found on the way: above 30 degrees (Gamma below 1), which the options allow up to 35, the refinement is not proven to end, and it does not: at 34-35 degrees even 4 points ran into the cap of 1,000 Steiner points per input point plus 10^6, with an error blaming the input's numerics; at 31, 32 and 33 degrees us48.poly took 1.7, 3.5 and 12 times the triangles of 30, and spread 1e3 failed at 32.5. Such angles now come with a warning, and the cap's error says that the angle is the cause.
51. **No per-vertex triangle in the overlay** (`Triangulation`, found reading what the refinement writes after `perf` showed it bound by memory, not instructions): every new triangle recorded itself as the incident triangle of its three vertices, three scattered writes per triangle, and nothing read them before `compactOverlay` dropped the array and built its own; the plain Delaunay (tests, benchmarks) starts each walk from its last fan instead. The same meshes (the 60 .node/.ele/.edge files `osm-mesh` writes for the 17 real inputs and 3 generated ones, byte for byte); instructions of `bench_osm random-segments:30000:1` 983.0 M -> 978.5 M (-0.45%); random-segments 2e5, median CPU of 11 alternating runs, 0.738 -> 0.728 s (within the noise). Tried with it and not kept (the same meshes, but no time difference beyond this machine's 2-3% noise in 11-15 alternating runs, on random-segments 2e5, points 1e5 and us48.poly): a quality test without divisions (r^2 d^2 against Gamma^2 l^2 d^2; its first version underflowed on a 2e-56 feature, which a unit test from an earlier fuzzing find caught) and the rays from a new vertex computed once per fan for the waiting points' orientation tests, together 1.7% fewer instructions; link-time optimisation of the whole core (no difference); a smaller padded box (half-width 1 or 0.75 times the input's size instead of 2: no gain left since item 34); moving freed huge-page mappings (`mremap`) into a new one when no kept range holds a request, instead of giving them back and mapping fresh, which item 44 had already tried and rejected at 1.2e6 (tried again here at a smaller size, with the same outcome: random-segments 2e5, huge pages first touched 91 -> 70, but peak +10%, 122 -> 134 MB, and no time gain while the host kept the memory backed). Measured for angles above 30 degrees (item 50): whether a refinement that will not end can be told early from one that ends, by each Steiner point's insertion radius against an upper bound of the local feature size (the nearest input neighbour's distance, carried along by the triangle inequality). It cannot: runs that ended went down to 0.0038 (us48.poly at 33 degrees, 7.0 million Steiner points), while spread 1e3 at 33 degrees stayed above 0.0046 until the cap; so the cap on Steiner points stays the only stop.
52. **A waiting point tries its neighbour's wedge first** (`Overlay`, found with `perf annotate` on `bench_osm square_circle_hole.poly --warm 3000`: the self time of `insertVertex` was the orientation tests that put each waiting input point of a cavity into the new fan's triangle). The waiting points come in Hilbert order, so most lie in the same fan triangle as the one before: that wedge is tried first, and taken only when the point lies strictly inside it, where it is in no other closed wedge, so the scan that follows otherwise picks the same triangle. The same meshes (the .node/.ele files `osm-mesh` writes for the 17 real inputs and 4 generated ones, byte for byte). Instructions of `bench_osm points:30000:1` (callgrind) 1,017.8 M -> 957.9 M (-5.9%); median CPU of alternating fresh processes against the code before: points 1e5 0.362 -> 0.338 s (9 runs each, -7%), random-segments 1e5 0.349 -> 0.340 s (7, -2%), square_circle_hole.poly after 50 warm calls 1.1 ms either way. Tried again and not kept: the quality test without divisions of item 51 (957.9 M -> 956.8 M instructions, and no time difference in 9 alternating runs).
53. **The memory limits read only where a mesh could need them** (`Overlay`, `Stitch`, `Mesher`, found with `strace` on `bench_osm A.poly`: every fresh process read `/proc/self/cgroup` and the memory limits along its path during its first call, 0.2 to 0.7 ms, timed apart). A mesh of at most 65,536 points (20 MB) is not checked against the memory; the overlay asks when its Steiner points pass them, the stitching walk when its crossings do. `bench_osm` as fresh processes, 40 interleaved runs of the code before and after on a loaded machine, median: A.poly 1.24 -> 1.05 ms, face.poly 1.04 -> 0.77 ms, guitar.poly 2.08 -> 1.50 ms, double_hex.poly 1.43 -> 1.13 ms.
54. **Output cells back in 64-bit storage** (`vtkOverlayStitchMesher`, reverses item 45; found by a review: ParaView's *Loop Subdivision* and *Subdivide* refuse every mesh in `vtkCellArray`'s 32-bit storage as "non-manifold", a VTK defect). Correct output for VTK's filters costs the memory item 45 saved: `osm-mesh` on random-segments 1.4e6 (10.3 million triangles, writing .vtp) peaked at 1,191 MB, 115 bytes per triangle (GNU time, one run on a loaded machine), against 979 MB in the last suite run.
55. **A leaner cavity insertion, tried and not kept** (`Triangulation`, `Overlay`; a helper's profile with `perf annotate` and callgrind after item 52). `insertIntoCavity` rewritten to give each fan triangle the slot the free-then-take sequence gave it (so the same slot numbers, queue and meshes) without the free list's round trip, without divisions (a table of next corners, back-links as triangle and local edge), linking a fan of up to 16 triangles through a 32-entry hash table instead of comparing every pair of its edges, and taking the counter-clockwise order from the links made while linking; fan entries written field by field (`perf` put 16% of the function's samples on a store-forwarding stall of a braced temporary); `takeSlot` inlined; a new fan queued by `enqueueIfNeeded` in one call. The same 168 .node/.ele/.edge/.poly files (`osm-mesh`, the 17 real inputs and 4 generated ones, two domains). Instructions of the meshing call on `bench_osm random-segments:30000:1` 999.6 M -> 948.2 M (-5.1%; the overlay 679.4 M -> 627.5 M, -7.6%), on `points:30000:1` -5.5%. CPU time of random-segments 2e5, alternating runs: medians 0.986 -> 0.979 s over three pooled series of 33 runs each, 0.853 -> 0.969 s in a later series of 11, and 0.860 -> 0.865 s on a quiet machine after a warm call (11 each): no difference this machine can measure. The refinement waits on memory (a neighbour slot's mark in `cavityOf`, 24% of its samples; the waiting input points in the yield scan), not on instructions, as items 10 and 51 found; the more intricate code was not kept for instructions alone. Also tried: one record per input point (position, bucket link and vertex, 24 bytes) against the cache misses on the waiting points: simulated first-level read misses of the overlay rose 1.42 M -> 1.60 M, as the separate arrays pack more points per cache line."""


def profile_text(p):
    if p.get("error"):
        return "Profile not available: %s." % p["error"]
    total = p.get("total_ir") or 1
    L = ["Profile: callgrind (`perf stat -e instructions` is %s on this machine) on "
         "`bench_osm %s` (%s output triangles: callgrind runs about 50 times slower, and "
         "instruction counts do not depend on the machine's load). Instructions per phase "
         "(inclusive):" % (
             "supported" if p.get("perf_instructions") else "not supported",
             p["input"], fmt_int(p.get("run", {}).get("out_triangles"))), "",
         "| phase (function) | instructions | share |", "|---|---:|---:|"]
    for name, cost in p["phases"]:
        L.append("| %s | %s | %.1f%% |" % (name, fmt_int(cost), 100.0 * cost / total))
    L.append("| whole run | %s | 100%% |" % fmt_int(total))
    L += ["", "Most expensive functions by their own instructions:", "",
          "| function | share |", "|---|---:|"]
    for n, c in p["top_exclusive"][:12]:
        L.append("| `%s` | %.1f%% |" % (short_name(n), 100.0 * c / total))
    L.append("")
    sort3 = sum(c for n, c in p["top_exclusive"]
                if "__introsort_loop" in n and "std::array<int, 3ul>" in n)
    atan = sum(c for n, c in p["top_exclusive"] if "atan2" in n)
    carve = sum(c for n, c in p["top_exclusive"] if n.startswith("osm::carveDomain"))
    if sort3 > 0.08 * total:
        L.append(
            "**Hot spot.** %.0f%% of all instructions sort `std::array<int, 3>` edge keys: "
            "`carveDomain` (Domain.cxx) rebuilds triangle adjacency by sorting 3 keys per "
            "triangle and then binary-searches every edge among the constrained ones (its own "
            "instructions, another %.0f%%, are that search, the keys and the flood fill), and `complete` (Complete.cxx) "
            "pairs half-edges with their twins by sorting 2 keys per edge. Both are "
            "O(m log m) where a linear pass does: bucket the edges by their smaller vertex "
            "(a counting sort into rows, as `buildRotation` already has for the half-edges), "
            "find a twin or a constrained edge by scanning one short row (degree about 6); "
            "and skip the flood fill when the domain is the hull or the box with no hole "
            "seeds and no enclosed region (one region). The output's angle statistics call "
            "`atan2` three times per triangle (%.0f%%); comparing cosines and taking one "
            "`acos` for the extremes would do. These are suggestions for the core's owner: "
            "the core was not changed by this suite. A trial of the two linear passes on a "
            "copy of the core (outside the repository, 2026-11-30) gave the same meshes on 4 "
            "inputs and cut the instructions of this profile from 2.83e9 to 1.95e9 (-31%%: "
            "`complete` 618e6 -> 223e6, `carveDomain` 643e6 -> 153e6); on random-segments "
            "2e5 its CPU time went from 7.65 s to 6.90 s (median of 3, loaded machine), the "
            "domain phase from 2.2 s to 0.83 s." % (
                100.0 * sort3 / total, 100.0 * carve / total, 100.0 * atan / total))
    return "\n".join(L)


def short_name(name):
    # Drop argument lists and template arguments, keep the qualified name.
    what = ""
    if "sort" in name and "std::array<int, 3ul>" in name:
        what = " (of std::array<int, 3>)"
    elif "sort" in name and "buildRotation" in name:
        what = " (buildRotation's angular order)"
    name = name.replace("(anonymous namespace)", "anon")
    out, depth = [], 0
    for ch in name:
        if ch in "<(":
            depth += 1
        elif ch in ">)":
            depth -= 1
        elif depth == 0:
            out.append(ch)
    return ("".join(out).strip() or name[:60]) + what


def warmed_text(data):
    """What the scaling pass touched before its runs (older suites recorded nothing)."""
    runs = data["scaling_pass"]["runs"] if data.get("scaling_pass") else []
    sizes = [b for r in runs for b in r.get("warmed", [])]
    if not sizes:
        return "The runs of this report predate it."
    return "In this suite run: %d of the pass's %d runs, %s MiB at most." % (
        sum(1 for b in sizes if b), len(sizes), "{:,}".format(max(sizes) >> 20))


def notes_text(data, plot_note):
    meta = data["meta"]
    fams = meta["families"]
    lines = [
        "- **Tools.** *OSM core*: `osm::mesh()` with default options (θ1 = 30°, domain Auto), "
        "without keeping the overlay and the edge classes (the mesh only, like the others). "
        "*OSM VTK filter*: `vtkOverlayStitchMesher::Update()` on the same input as vtkPolyData "
        "lines, Edges and Overlay outputs off; the core's own time inside the same call comes "
        "from the field data `SecondsTotal`. *CGAL Mesh_2*: CGAL 5.5 "
        "`refine_Delaunay_mesh_2` with `Delaunay_mesh_size_criteria_2` defaults (shape "
        "0.125, about 20.7°; no size bound), Epick kernel, timed from the input (CDT "
        "construction included); its domain follows OSM's Auto (enclosed regions if the "
        "segments enclose any, else the convex hull with its edges as constraints), with the "
        "input's holes as seeds. *CGAL CDT alone*: the constrained Delaunay triangulation of "
        "the input (bulk insertion in spatial order), all of its convex hull. *OSM Delaunay "
        "of points*: `osm::delaunayTriangulation` of the points only (segments ignored), the "
        "core's triangulation layer next to CGAL's. *vtkDelaunay2D*: ParaView 5.11's VTK, the "
        "segments as line cells given to `SetSourceData`, default Tolerance (1e-5 of the "
        "bounding box, which merges closer points), the convex hull.",
        "- **Inputs.** Every `.poly` in `../shared/data/pslg` (%s), and generated families "
        "(Testing/Benchmarks/Generators.h, seed %d): `random-segments` (N/2 segments, each "
        "inside its own cell of a grid), `points` (N uniform points, no segments), `spread` "
        "(like random-segments, lengths log-uniform over 6 decades). Sizes N: %s." % (
            "present" if meta["data_present"] else "absent here: skipped", SEED,
            "; ".join("%s %s" % (k, ", ".join(human(n) for n in v)) for k, v in fams.items())),
        "- **Caps** (to keep the suite near an hour on 2 shared cores): spread stops at 1e4 "
        "input vertices (OSM makes about 4 million triangles there; at 1e5 it made 45 million "
        "in an earlier trial, 8.4 GB); random segments go to 1.4e6 vertices so that OSM "
        "reaches 1e7 output triangles; vtkDelaunay2D runs up to %s vertices (1e5 segments), "
        "the VTK filter up to %s, the VTK filter and osm-mesh on random segments and the "
        "real inputs only. After a time-out or a crash a tool is not run on the larger "
        "members of that family (shown as skipped)." % (
            human(meta["caps"].get("vtk-delaunay2d")), human(meta["caps"].get("vtk-osm"))),
        "- **Time.** Every ratio, per-triangle time and the plot use the process CPU time "
        "of the meshing call (median over the runs), not its wall time: the machine was "
        "shared with other builds (see the load average above), and a process waiting for "
        "a core is not working. Runs under %g s wall use their shortest wall time instead "
        "(the process CPU clock lags by up to a scheduler tick under the suite's own RLIMIT_CPU, "
        "which arms a process-wide CPU timer: a 1 ms call can read 0 or 4 ms). Wall times are in "
        "the table too. osm-mesh's CPU time is GNU time's user + system time (0.01 s "
        "resolution)." % SHORT_RUN,
        "- **Runs.** %d runs when one takes under %g CPU s, else %d; fewer when they would "
        "exceed %d s of wall time together; the first run also checks the output (angles, "
        "conformity). Limit per run: %d CPU seconds (RLIMIT_CPU; a run killed by it is a "
        "time-out), %d s of wall time, %d GiB of address space." % (
            RUNS_FAST, FAST_SECONDS, RUNS, REPEAT_BUDGET,
            meta["timeout"], meta["timeout"] * WALL_FACTOR, MEMORY_LIMIT >> 30),
        "- **Backed memory (scaling pass only).** This virtual machine's host backs the "
        "guest's memory at its first touch and takes freed memory back within about 30 s "
        "(item 47: about 4.4 ms per 2 MiB page then, 0.13 ms once backed), so a large run "
        "pays first touches that the smallest size of its round, reusing memory freed a "
        "moment before, mostly does not. In the scaling pass, before each run, the suite "
        "touches %d times that size's main-pass peak (leaving 2 GiB free) and frees it. "
        "The main pass, and every comparison between tools, runs without it. %s" % (
            WARM_FACTOR, warmed_text(data)),
        "- **Memory.** Peak RSS of the child during the meshing call (the kernel's peak mark "
        "is reset just before it); *B/tri* is its increase over the RSS before the call, so "
        "the input's own memory is not counted, the output and all working memory are.",
    ]
    if meta.get("cli"):
        lines.append(
            "- **osm-mesh** (end to end): the whole process, timed from outside: reading the "
            "`.poly` file (generated inputs are first written as `.poly` files with 17 digits "
            "by `bench_make_poly`), meshing, writing the mesh (`%s`). Its memory is GNU "
            "time's peak RSS of the whole process (input, mesh and writing included), so "
            "*B/tri* for it is that peak divided by the output triangles. It reads the file "
            "with the project's VTK reader and meshes through the VTK filter; its output is "
            "not inspected again (the filter's row checks the same mesh). %s" % (
                " ".join(os.path.basename(x) if i == 0 else x
                         for i, x in enumerate(cli_command("osm-mesh", "IN.poly", "OUT"))),
                "Its source was in git when the suite started (last commit to Filters/CLI: "
                "`%s`)." % meta["cli_commit"] if meta.get("cli_commit") else
                "Its source was not in git when the suite started."))
    else:
        lines.append("- **Not measured: the `osm-mesh` command-line tool** (end to end, with "
                     "I/O). It was not in the tree when this suite ran (it was being written); "
                     "rerunning the command measures it once it is built.")
    lines.append("- **Data.** The table as CSV: `Testing/Benchmarks/results.csv`; the raw "
                 "per-run JSON (`build-bench/bench/results.json`, with every run's times and "
                 "phases) is not kept in the repository. `run_benchmarks.py --report-only` "
                 "rewrites this file from it.")
    lines.append("- **Plot.** Made with matplotlib (Debian: `apt-get install python3-matplotlib`; "
                 "it is not a dependency of the project or its CI). Without it the report is "
                 "written without the plot.")
    if meta.get("missing_tools"):
        lines.append("- **Missing drivers** in this build (not run): %s." %
                     ", ".join(meta["missing_tools"]))
    if plot_note:
        lines.append("- " + plot_note)
    return "\n".join(lines)


MARKERS = {"real": "o", "random-segments": "s", "points": "^", "spread": "D"}
COLORS = {"osm": "#d62728", "vtk-osm": "#ff9896", "osm-mesh": "#8c564b", "cgal-mesh2": "#1f77b4",
          "cgal-cdt": "#aec7e8", "osm-delaunay": "#ffbb78", "vtk-delaunay2d": "#2ca02c"}


def write_plot(data, png_path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.lines import Line2D
    except ImportError:
        return "The plot was not made: matplotlib is missing (python3-matplotlib)."
    fig, ax = plt.subplots(figsize=(9.5, 5.2), dpi=90)
    for tool in TOOL_ORDER:
        for cls, marker in MARKERS.items():
            pts = sorted((e["first"]["out_triangles"], per_triangle(e) * 1e9)
                         for e in data["results"]
                         if e["tool"] == tool and e["class"] == cls and ok(e)
                         and e["first"]["out_triangles"] >= 100)
            if not pts:
                continue
            xs, ys = zip(*pts)
            ax.plot(xs, ys, linestyle="-" if cls != "real" else "none", marker=marker,
                    color=COLORS[tool], markersize=4, linewidth=1, alpha=0.9)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("output triangles")
    ax.set_ylabel("CPU time per output triangle (ns)")
    ax.set_title("Time per output triangle (median CPU time of runs; lower is better)")
    ax.grid(True, which="both", alpha=0.25)
    handles = [Line2D([], [], color=COLORS[t], marker="o", linestyle="-", label=TOOLS[t][2])
               for t in TOOL_ORDER if any(e["tool"] == t and ok(e) for e in data["results"])]
    handles += [Line2D([], [], color="gray", marker=m, linestyle="none", label=c)
                for c, m in MARKERS.items()
                if any(e["class"] == c for e in data["results"])]
    ax.legend(handles=handles, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    fig.savefig(png_path)
    plt.close(fig)
    return None


def write_csv(data, path):
    """One row per (tool, input): the figures of the tables, small enough to keep."""
    import csv
    cols = ["input", "class", "tool", "status", "runs", "cpu_s", "wall_s", "input_vertices",
            "input_segments", "out_vertices", "out_triangles", "min_angle", "max_angle",
            "missing_segments", "outside_segments", "overlap_edges", "peak_rss_bytes",
            "bytes_per_triangle"]
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(cols)
        for e in data["results"]:
            fr = e.get("first", {})
            good = ok(e)
            out.writerow([
                e["name"], e["class"], e["tool"],
                "skipped" if "skipped" in e else fr.get("status", ""),
                len(e.get("seconds", [])),
                "%.6g" % median_seconds(e) if good else "",
                "%.6g" % median_wall(e) if good else "",
                fr.get("input_vertices", ""), fr.get("input_segments", ""),
                fr.get("out_vertices", "") if good else "",
                fr.get("out_triangles", "") if good else "",
                "%.6g" % fr["min_angle"] if good and "min_angle" in fr else "",
                "%.6g" % fr["max_angle"] if good and "max_angle" in fr else "",
                fr.get("missing_segments", "") if good else "",
                fr.get("outside_segments", "") if good else "",
                overlap_edges(e) if good and overlap_edges(e) is not None else "",
                peak_bytes(fr) or "" if good else "",
                "%.4g" % bytes_per_triangle(e) if good and bytes_per_triangle(e) else ""])


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--build", default=os.path.join(ROOT, "build-bench"),
                   help="build directory holding bench/ (default: build-bench)")
    p.add_argument("--data", default=os.path.join(ROOT, "..", "shared", "data", "pslg"),
                   help="folder of .poly inputs (default: ../shared/data/pslg; skipped if absent)")
    p.add_argument("--quick", action="store_true", help="small sizes only (to try the suite)")
    p.add_argument("--timeout", type=float, default=TIMEOUT, help="seconds per run (120)")
    p.add_argument("--report-only", action="store_true",
                   help="rewrite the report from the saved results, run nothing")
    p.add_argument("--no-profile", action="store_true",
                   help="skip the profiles (callgrind and perf)")
    p.add_argument("--profile-only", default=None, metavar="OUT.json",
                   help="only run the callgrind profile and save it (its instruction counts "
                        "do not depend on the load, so it may run beside the suite)")
    p.add_argument("--profile-from", default=None, metavar="FILE.json",
                   help="with --report-only: take the profile from this file")
    p.add_argument("--sampled-profile-only", default=None, metavar="OUT.json",
                   help="only run the sampled (perf) profile and save it")
    p.add_argument("--sampled-profile-from", default=None, metavar="FILE.json",
                   help="with --report-only: take the sampled profile from this file")
    p.add_argument("--partial", default=None,
                   help="also save the results after every run to this file")
    p.add_argument("--tools", default="",
                   help="comma-separated tools to run (default: all): " + ",".join(TOOL_ORDER))
    p.add_argument("--results", default=None,
                   help="raw results (written, or read with --report-only; default: "
                        "<build>/bench/results.json, too large to commit)")
    p.add_argument("--markdown", default=os.path.join(ROOT, "BENCHMARKS.md"))
    p.add_argument("--png", default=os.path.join(HERE, "benchmarks.png"))
    p.add_argument("--csv", default=os.path.join(HERE, "results.csv"),
                   help="the table as CSV (small; the raw JSON is not meant to be kept)")
    args = p.parse_args()
    args.data = os.path.normpath(args.data)
    if args.results is None:
        args.results = os.path.join(args.build, "bench", "results.json")

    if args.sampled_profile_only:
        with open(args.sampled_profile_only, "w") as f:
            json.dump(run_sampled_profile(args), f, indent=1)
        return
    if args.profile_only:
        with open(args.profile_only, "w") as f:
            json.dump(run_profile(args), f, indent=1)
        return
    if args.report_only:
        with open(args.results) as f:
            data = json.load(f)
        if args.profile_from:
            with open(args.profile_from) as f:
                data["profile"] = json.load(f)
        if args.sampled_profile_from:
            with open(args.sampled_profile_from) as f:
                data["sampled_profile"] = json.load(f)
    else:
        data = run_suite(args)
        if not args.no_profile:
            print("profiling bench_osm under callgrind ...", flush=True)
            data["profile"] = run_profile(args)
            print("profiling bench_osm under perf ...", flush=True)
            data["sampled_profile"] = run_sampled_profile(args)
        with open(args.results, "w") as f:
            json.dump(data, f, indent=1)
            f.write("\n")
    write_csv(data, args.csv)
    plot_note = write_plot(data, args.png)
    write_report(data, data.get("profile"), args.markdown, args.png, plot_note)
    print("wrote %s, %s and %s" % (args.markdown, args.png, args.results))


if __name__ == "__main__":
    main()
