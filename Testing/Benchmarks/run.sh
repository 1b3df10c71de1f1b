#!/usr/bin/env bash
# The benchmark suite of issue 5, in one command (from anywhere):
#
#   bash Testing/Benchmarks/run.sh [run_benchmarks.py options, e.g. --quick]
#   bash Testing/Benchmarks/run.sh --size-bound [size_bound.py options]
#
# 1. configures build-bench/ in the VTK-only mode (which gives the
#    vtkOverlayStitchMesher driver) with -DOSM_BUILD_BENCHMARKS=ON, the osm-mesh
#    command-line tool when the tree has it, and no tests;
# 2. builds the drivers (bench/bench_*) and osm-mesh;
# 3. runs Testing/Benchmarks/run_benchmarks.py, which writes BENCHMARKS.md at the
#    top level and Testing/Benchmarks/benchmarks.png (about 20 minutes on 2 cores);
#    or with --size-bound, size_bound.py, which writes
#    Testing/Benchmarks/SIZE_BOUND.md (OSM and Mesh_2 with a maximum edge
#    length, about 10 minutes).
#
# It first installs the Debian packages it needs that are missing: the
# project's own (.ci/common.sh) and, for the suite only, libcgal-dev (the CGAL
# drivers), valgrind and linux-perf (the profiles), python3-matplotlib (the plot) and time (GNU
# time, the osm-mesh memory figure). The plugin never links CGAL.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
source "$root/.ci/common.sh"
OSM_PACKAGES+=(libcgal-dev valgrind linux-perf python3-matplotlib time)
osm_install_packages
build="${OSM_BENCH_BUILD:-$root/build-bench}"
vtk_dir="${VTK_DIR:-$OSM_PARAVIEW_VTK_DIR}"

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DOSM_BUILD_PARAVIEW_PLUGIN=OFF -DVTK_DIR="$vtk_dir" \
  -DBUILD_TESTING=OFF -DOSM_BUILD_BENCHMARKS=ON
cmake --build "$build" --parallel 2

# --size-bound: the maximum-edge-length comparison (size_bound.py) instead.
if [ "${1:-}" = "--size-bound" ]; then
  shift
  exec /usr/bin/python3 "$root/Testing/Benchmarks/size_bound.py" --build "$build" "$@"
fi
exec /usr/bin/python3 "$root/Testing/Benchmarks/run_benchmarks.py" --build "$build" "$@"
