# SPDX-License-Identifier: BSD-3-Clause
# Copyright (c) 2026, the Overlay Stitch Meshing authors
"""The Triangle .poly reader in ParaView (pvpython, or pvbatch under MPI).

    pvpython reader_paraview.py PLUGIN DATA_DIR
    mpiexec -n 2 pvbatch --mpi reader_paraview.py PLUGIN DATA_DIR --ranks 2

Checks that OpenDataFile() picks the plugin's reader for .poly and .node,
that the named proxy TrianglePolyReader(FileName=...) works, that the file's
holes reach the mesher, and, under MPI, that the data is delivered once.
"""
import sys

from paraview.simple import LoadPlugin, OpenDataFile, servermanager

failures = []


def check(condition, what, detail=""):
    print(("ok   " if condition else "FAIL ") + what + ("" if condition else ": " + str(detail)))
    if not condition:
        failures.append(what)


plugin, data = sys.argv[1], sys.argv[2]
ranks = int(sys.argv[sys.argv.index("--ranks") + 1]) if "--ranks" in sys.argv else 1
LoadPlugin(plugin, remote=False, ns=globals())

pm = servermanager.vtkProcessModule.GetProcessModule()
check(pm.GetNumberOfLocalPartitions() == ranks, "running on %d rank(s)" % ranks,
      pm.GetNumberOfLocalPartitions())

poly = data + "/square_hole.poly"
reader = OpenDataFile(poly)
check(reader is not None and reader.GetXMLName() == "TrianglePolyReader",
      "OpenDataFile(.poly) picks TrianglePolyReader",
      reader.GetXMLName() if reader is not None else None)
node = OpenDataFile(data + "/split_pslg.node")
check(node is not None and node.GetXMLName() == "TrianglePolyReader",
      "OpenDataFile(.node) picks TrianglePolyReader")

named = TrianglePolyReader(FileName=poly)  # noqa: F821 (defined by LoadPlugin)
named.UpdatePipeline()
info = named.GetDataInformation()
# Summed over every rank: the file is delivered once, not once per rank.
check(info.GetNumberOfPoints() == 9 and info.GetNumberOfCells() == 9,
      "TrianglePolyReader(FileName=...): 9 points, 9 cells over all ranks",
      (info.GetNumberOfPoints(), info.GetNumberOfCells()))
local = servermanager.Fetch(named)
holes = local.GetFieldData().GetArray("HolePoints")
check(local.GetNumberOfLines() == 8 and local.GetNumberOfVerts() == 1,
      "fetched: 8 lines and 1 vertex cell", (local.GetNumberOfLines(), local.GetNumberOfVerts()))
check(holes is not None and holes.GetNumberOfComponents() == 3 and
      holes.GetNumberOfTuples() == 1 and tuple(holes.GetTuple3(0)) == (5.0, 5.0, 0.0),
      "fetched: HolePoints (5, 5, 0)")
check(local.GetPointData().GetArray("PointMarker") is not None and
      local.GetCellData().GetArray("SegmentMarker") is not None and
      local.GetPointData().GetArray("Attribute0") is not None,
      "fetched: PointMarker, Attribute0, SegmentMarker")

mesher = OverlayStitchMesher(Input=named)  # noqa: F821
mesh = servermanager.Fetch(mesher, idx=0)
area = 0.0
for c in range(mesh.GetNumberOfCells()):
    ids = mesh.GetCell(c).GetPointIds()
    (ax, ay, _), (bx, by, _), (cx, cy, _) = (mesh.GetPoint(ids.GetId(k)) for k in range(3))
    area += 0.5 * ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))
check(mesh.GetNumberOfCells() > 0 and abs(area - 96.0) < 1e-9,
      "the file's hole reaches the mesher: area 100 - 4", area)

# The file's vertex attribute and markers reach the mesh (InterpolatePointData),
# gathered from every rank: input vertices keep theirs, a point on the bottom
# edge takes the attribute linear along it (0.5 to 1.5), and the markers are
# Triangle's: the segment's on a segment (1 outside, 2 on the hole), else 0.
attribute = mesh.GetPointData().GetArray("Attribute0")
marker = mesh.GetPointData().GetArray("PointMarker")
inputs = {tuple(local.GetPoint(i)[:2]): (local.GetPointData().GetArray("Attribute0").GetValue(i),
                                          local.GetPointData().GetArray("PointMarker").GetValue(i))
          for i in range(local.GetNumberOfPoints())}
wrong = []
for v in range(mesh.GetNumberOfPoints() if attribute and marker else 0):
    x, y, _ = mesh.GetPoint(v)
    a, m = attribute.GetValue(v), marker.GetValue(v)
    if (x, y) in inputs:
        expected = inputs[(x, y)]
    else:
        outer = x in (0.0, 10.0) or y in (0.0, 10.0)
        hole = (x in (4.0, 6.0) and 4 <= y <= 6) or (y in (4.0, 6.0) and 4 <= x <= 6)
        expected = (0.5 + x / 10 if y == 0.0 else a, 1 if outer else 2 if hole else 0)
    if abs(a - expected[0]) > 1e-12 or m != expected[1]:
        wrong.append((x, y, a, m, expected))
check(attribute is not None and marker is not None and mesh.GetNumberOfPoints() > 9 and not wrong,
      "the file's Attribute0 and PointMarker carried to the mesh's %d points"
      % mesh.GetNumberOfPoints(), wrong[:3])

print("%d failure(s)" % len(failures))
# Under pvbatch + MPI, sys.exit(0) would skip MPI_Finalize and mpiexec would
# report an abnormal end: only exit early on failure.
if failures:
    sys.exit(1)
