"""Meshes one input with the Overlay Stitch Mesher under pvbatch (any number of
MPI ranks) or, with --server, through a pvserver from pvpython.

    [mpirun -np N] pvbatch mesh_parallel.py --plugin P --input in.vtp|in.pvtp|in.pvtu|in.vtm --json out.json
        [--mesh mesh.vtp] [--distribute none|one|all] [--server HOST:PORT] [--fail-first]
        [--pvtp mesh.pvtp] [--png shot.png]

A .pvtp input (a partitioned file) is read in parallel: each rank reads its own
pieces; so is a .vtm (a multiblock file), block by block. A .vtp input, or a .poly one (the plugin's TrianglePolyReader), is read
whole by rank 0. Then, unless --distribute none,
ParaView's RedistributeDataSet spreads the cells over the ranks by region
(cells on a region boundary go to one region, or with "all" to every region
they touch, the copies marked as ghost cells) and ExtractSurface turns the
result back into polydata.

Every rank prints "OSM-RANK-CELLS <rank> <cells>": the cells of the mesher's
input on that rank (a probe just before the mesher). The script writes the run's
statistics (from the Mesh output's field data, reduced over the ranks) and the
number of triangles and points of each output to --json, and the mesh itself
(fetched to this process) to --mesh.
"""
import argparse
import json
import os
import sys
import time

from paraview import servermanager
from paraview.simple import *

PROBE = """
from vtkmodules.vtkParallelCore import vtkMultiProcessController
controller = vtkMultiProcessController.GetGlobalController()
rank = controller.GetLocalProcessId() if controller else 0
data = self.GetInputDataObject(0, 0)
self.GetOutputDataObject(0).ShallowCopy(data)
print("OSM-RANK-CELLS %d %d" % (rank, data.GetNumberOfCells()), flush=True)
"""


def field_value(port, name):
    info = port.GetDataInformation().GetFieldDataInformation().GetArrayInformation(name)
    if info is None:
        return None
    return info.GetComponentRange(0)[0]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--input", required=True)
    parser.add_argument("--json", required=True)
    parser.add_argument("--mesh")
    parser.add_argument("--distribute", default="none", choices=["none", "one", "all"])
    parser.add_argument("--server", help="HOST:PORT of a running pvserver")
    parser.add_argument("--pvtp", help="also save the Mesh output with ParaView's .pvtp writer")
    parser.add_argument("--png", help="also render the Mesh output and save a screenshot")
    parser.add_argument("--fail-first", action="store_true",
                        help="first run the mesher with settings that make it fail")
    args = parser.parse_args()

    if args.server:
        host, port = args.server.rsplit(":", 1)
        Connect(host, int(port))
        LoadPlugin(args.plugin, remote=True, ns=globals())
    LoadPlugin(args.plugin, remote=False, ns=globals())

    if args.input.endswith(".pvtp"):
        # A partitioned file: each rank reads its own pieces.
        source = XMLPartitionedPolydataReader(FileName=[args.input])
    elif args.input.endswith(".pvtu"):
        # The same as unstructured grids (vtkUnstructuredGrid input).
        source = XMLPartitionedUnstructuredGridReader(FileName=[args.input])
    elif args.input.endswith(".vtm"):
        # A multiblock file: its blocks are spread over the ranks; the mesher
        # combines each rank's blocks, then gathers them.
        source = XMLMultiBlockDataReader(FileName=[args.input])
    elif args.input.endswith(".poly"):
        # The project's reader (it reads on piece 0; the other ranks get empty pieces).
        source = TrianglePolyReader(FileName=[args.input])
    else:
        source = XMLPolyDataReader(FileName=[args.input])
    if args.distribute != "none":
        # Spread the cells over the ranks by region. Cells on a region boundary go to one
        # region ("one") or to every region they touch, copies marked as ghost cells
        # ("all"); never split, which would add points to the segments.
        mode = {"one": "Assign to one region", "all": "Assign to all regions"}[args.distribute]
        redistributed = RedistributeDataSet(Input=source)
        redistributed.BoundaryMode = mode
        source = ExtractSurface(Input=redistributed)
    probe = ProgrammableFilter(Input=source, OutputDataSetType="Same as Input", Script=PROBE)

    mesher = OverlayStitchMesher(Input=probe)
    # A .poly's region areas apply (Triangle's -a): they reach rank 0 or the mesh differs.
    mesher.ApplyRegionAreas = 1
    if args.fail_first:
        # A run that fails on rank 0 only (too few Steiner points allowed): every rank
        # must still finish it with empty outputs, and the next run must work.
        mesher.MaximumSteinerPoints = 1
        mesher.UpdatePipeline()
        failed = [OutputPort(mesher, p).GetDataInformation().GetNumberOfCells() for p in range(3)]
        print("OSM-FAILED-RUN-CELLS %s" % failed, flush=True)
        if any(failed):
            sys.exit("the run meant to fail produced cells: %s" % failed)
        mesher.MaximumSteinerPoints = 0
    start = time.perf_counter()
    mesher.UpdatePipeline()
    seconds = time.perf_counter() - start

    mesh_port = OutputPort(mesher, 0)
    result = {
        "ranks": servermanager.ActiveConnection.GetNumberOfDataPartitions(),
        "wall_seconds": seconds,
        "outputs": [],
        "stats": {},
    }
    for port in range(3):
        info = OutputPort(mesher, port).GetDataInformation()
        result["outputs"].append(
            {"cells": info.GetNumberOfCells(), "points": info.GetNumberOfPoints()})
    # A composite input's Edges name each input subsegment's block.
    blocks = OutputPort(mesher, 1).GetDataInformation().GetCellDataInformation() \
        .GetArrayInformation("InputBlockId")
    result["block_ids"] = list(blocks.GetComponentRange(0)) if blocks else None
    result["region_attribute"] = mesh_port.GetDataInformation().GetCellDataInformation() \
        .GetArrayInformation("RegionAttribute") is not None
    for name in ("InputPoints", "InputSegments", "DuplicatePointsMerged",
                 "DuplicateSegmentsMerged", "ZeroLengthSegmentsDropped", "OutputTriangles",
                 "OutputVertices", "Regions", "MinAngleDeg", "MaxAngleDeg", "SecondsTotal",
                 "IgnoredCells"):
        result["stats"][name] = field_value(mesh_port, name)

    if args.mesh:
        mesh = servermanager.Fetch(mesher, idx=0)
        result["fetched_triangles"] = mesh.GetNumberOfCells()
        from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
        writer = vtkXMLPolyDataWriter()
        writer.SetFileName(args.mesh)
        writer.SetInputData(mesh)
        writer.SetDataModeToBinary()
        if not writer.Write():
            sys.exit("cannot write " + args.mesh)

    if args.pvtp:
        # ParaView's parallel writer: one piece file per rank (empty ones included).
        SaveData(args.pvtp, proxy=mesh_port)
    if args.png:
        # ParaView's parallel rendering of the distributed output (needs an X server).
        view = CreateView("RenderView")
        view.ViewSize = [500, 400]
        display = Show(mesh_port, view)
        display.SetRepresentationType("Surface With Edges")
        ColorBy(display, ("CELLS", "MaxAngle"))
        ResetCamera(view)
        Render(view)
        SaveScreenshot(args.png, view)

    with open(args.json, "w") as f:
        json.dump(result, f, indent=1)
    print("OSM-RESULT " + json.dumps(result["stats"]), flush=True)


if __name__ == "__main__":
    main()
