#!/bin/bash
# The GUI test: start the real `paraview` under a virtual X server with the
# plugin on PV_PLUGIN_PATH, run gui_script.py in it, then check its report,
# that its screenshot is not blank, and that it matches the project's
# baseline image Baseline/gui-screenshot.png within a tolerance
# (compare_images.py, which also says how to regenerate the baseline:
# OSM_GUI_REGENERATE_BASELINE=1 copies the new screenshot over it).
#
# usage: run_gui_test.sh <paraview> <pvpython> <plugin-dir> <data-file> <output-dir>
set -euo pipefail
paraview=$1
pvpython=$2
plugin_dir=$3
data=$4
output_dir=$5
here=$(cd "$(dirname "$0")" && pwd)

mkdir -p "$output_dir"
export PV_PLUGIN_PATH=$plugin_dir
export OSM_GUI_DATA=$data
export OSM_GUI_SCREENSHOT=$output_dir/gui-screenshot.png
export OSM_GUI_REPORT=$output_dir/gui-report.txt
rm -f "$OSM_GUI_SCREENSHOT" "$OSM_GUI_REPORT"

# --dr: ignore the user's settings, so the run is the same on every machine.
status=0
timeout --kill-after=10 240 bash "$here/xvfb_run.sh" \
  "$paraview" --dr --script="$here/gui_script.py" --exit || status=$?
echo "paraview exited with status $status"

if [ ! -s "$OSM_GUI_REPORT" ]; then
  echo "FAILED: the GUI script did not run (no $OSM_GUI_REPORT)"
  exit 1
fi
cat "$OSM_GUI_REPORT"
triangles=$(awk '$1 == "triangles" { print $2 }' "$OSM_GUI_REPORT")
if [ -z "$triangles" ]; then
  echo "FAILED: the GUI script stopped before the end (see the Python error above)"
  exit 1
fi
if [ "$triangles" -le 0 ]; then
  echo "FAILED: the filter produced no triangles in the GUI"
  exit 1
fi
if [ ! -s "$OSM_GUI_SCREENSHOT" ]; then
  echo "FAILED: no screenshot"
  exit 1
fi
edges_color=$(awk '$1 == "edges_color" { print $2 " " $3 }' "$OSM_GUI_REPORT")
if [ "$edges_color" != "CELLS EdgeClass" ]; then
  echo "FAILED: the Edges output opened colored by '$edges_color', not 'CELLS EdgeClass'"
  exit 1
fi
"$pvpython" "$here/check_screenshot.py" "$OSM_GUI_SCREENSHOT"
baseline=$here/Baseline/gui-screenshot.png
if [ "${OSM_GUI_REGENERATE_BASELINE:-0}" = 1 ]; then
  mkdir -p "$(dirname "$baseline")"
  cp "$OSM_GUI_SCREENSHOT" "$baseline"
  echo "regenerated the baseline $baseline: look at it, then commit it"
fi
"$pvpython" "$here/compare_images.py" "$OSM_GUI_SCREENSHOT" "$baseline"
if [ "$status" -ne 0 ]; then
  echo "FAILED: paraview exited with status $status"
  exit 1
fi
