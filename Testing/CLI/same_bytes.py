# SPDX-License-Identifier: BSD-3-Clause
# Copyright (c) 2026, the Overlay Stitch Meshing authors
"""The same mesh, byte for byte, from osm-mesh and from ParaView.

    pvpython same_bytes.py OSM_MESH PLUGIN DATA_DIR OUT_DIR
    mpiexec -n 2 pvbatch --mpi same_bytes.py OSM_MESH PLUGIN DATA_DIR OUT_DIR

For each input, osm-mesh writes a .vtp; the same input is read and meshed
with paraview.simple (TrianglePolyReader or OpenDataFile, OverlayStitchMesher
with its defaults), the Mesh output is fetched, its timings (field data
Seconds*, which osm-mesh leaves out of files) are dropped, and it is written
with vtkXMLPolyDataWriter's defaults and zlib level 1, as osm-mesh does. The two files must be
identical. Under MPI the mesher gathers the pieces on rank 0: the bytes must
still be the serial ones (once ParaView's delivery to the client has had its
array order put back, see below).
"""
import os
import subprocess
import sys

from paraview.simple import LoadPlugin, OpenDataFile, servermanager
from vtkmodules.vtkCommonDataModel import vtkFieldData, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

osm_mesh, plugin, data, out = sys.argv[1:5]
LoadPlugin(plugin, remote=False, ns=globals())
os.makedirs(out, exist_ok=True)
failures = 0
for name in ("square_hole.poly", "crossing.poly", "wedge.vtk"):
    source = os.path.join(data, name)
    stem = os.path.splitext(name)[0]
    cli_file = os.path.join(out, stem + "-cli.vtp")
    pv_file = os.path.join(out, stem + "-paraview.vtp")
    run = subprocess.run([osm_mesh, source, "-o", cli_file], capture_output=True, text=True)
    if run.returncode != 0:
        print("FAIL osm-mesh on %s: %s" % (name, run.stderr))
        failures += 1
        continue

    reader = OpenDataFile(source)
    mesher = OverlayStitchMesher(Input=reader, GenerateOverlay=0)  # noqa: F821 (LoadPlugin)
    fetched = servermanager.Fetch(mesher, idx=0)
    mesh = vtkPolyData()
    mesh.ShallowCopy(fetched)
    fields = vtkFieldData()
    for a in range(fetched.GetFieldData().GetNumberOfArrays()):
        array = fetched.GetFieldData().GetAbstractArray(a)
        if not array.GetName().startswith("Seconds"):
            fields.AddArray(array)
    mesh.SetFieldData(fields)
    # Under MPI, ParaView re-appends the output on its way to the client and
    # lists the cell arrays in another order: put them back in the order of the
    # osm-mesh file (serially this changes nothing).
    reference = vtkXMLPolyDataReader()
    reference.SetFileName(cli_file)
    reference.Update()
    for ours, theirs in ((mesh.GetPointData(), reference.GetOutput().GetPointData()),
                         (mesh.GetCellData(), reference.GetOutput().GetCellData())):
        arrays = [ours.GetAbstractArray(theirs.GetArrayName(a))
                  for a in range(theirs.GetNumberOfArrays())]
        if None in arrays or len(arrays) != ours.GetNumberOfArrays():
            print("FAIL %s: the arrays differ from the osm-mesh file's" % name)
            failures += 1
            arrays = []
        for array in arrays:
            ours.RemoveArray(array.GetName())
            ours.AddArray(array)
    # Fetching computed and cached the arrays' ranges in their information,
    # which the XML writer would then list: a cache, not mesh content.
    attributes = [mesh.GetPointData(), mesh.GetCellData()]
    arrays = [mesh.GetPoints().GetData()] + [fields.GetAbstractArray(a) for a in
                                             range(fields.GetNumberOfArrays())]
    for attribute in attributes:
        arrays += [attribute.GetAbstractArray(a) for a in range(attribute.GetNumberOfArrays())]
    for array in arrays:
        if array.HasInformation():
            array.GetInformation().Clear()
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(pv_file)
    writer.SetCompressionLevel(1)  # osm-mesh's zlib level
    writer.Write()

    with open(cli_file, "rb") as a, open(pv_file, "rb") as b:
        same = a.read() == b.read()
    print("%s %s: osm-mesh and paraview.simple write the same bytes (%d triangles)"
          % ("ok  " if same else "FAIL", name, mesh.GetNumberOfCells()))
    failures += 0 if same and mesh.GetNumberOfCells() > 0 else 1

print("%d failure(s)" % failures)
# Under pvbatch + MPI, sys.exit(0) would skip MPI_Finalize: exit only on failure.
if failures:
    sys.exit(1)
