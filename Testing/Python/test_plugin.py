"""pvpython test of the OverlayStitchMesher plugin.

Usage: pvpython test_plugin.py <path/to/OverlayStitchMesher.so> <Testing/Data>

Loads the plugin the way DESIGN.md section 6 measured to work
(LoadPlugin(path, remote=False, ns=globals())), meshes the bundled wedge.vtk
with paraview.simple.OverlayStitchMesher and checks the output contract
(DESIGN.md section 4) and that the properties reach the filter.
"""
import math
import os
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403 (LoadPlugin, LegacyVTKReader, ...)

failures = []


def check(condition, what):
    print(("ok      " if condition else "FAILED  ") + what)
    if not condition:
        failures.append(what)


def triangle_area(poly):
    """Sum of the triangle areas of a vtkPolyData."""
    points = poly.GetPoints()
    total = 0.0
    for c in range(poly.GetNumberOfCells()):
        ids = poly.GetCell(c).GetPointIds()
        a, b, p = (points.GetPoint(ids.GetId(k)) for k in range(3))
        total += 0.5 * abs((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]))
    return total


def fetch(proxy, port):
    proxy.UpdatePipeline()
    return servermanager.Fetch(proxy, idx=port)


def main(plugin, data_dir):
    check(os.path.isfile(plugin), "the plugin exists: " + plugin)
    LoadPlugin(plugin, remote=False, ns=globals())
    check("OverlayStitchMesher" in globals(), "LoadPlugin defines OverlayStitchMesher")
    if failures:
        return 1

    reader = LegacyVTKReader(FileNames=[os.path.join(data_dir, "wedge.vtk")])
    mesher = OverlayStitchMesher(Input=reader)

    # The properties and their defaults.
    defaults = {
        "MinimumAngle": 30.0,
        "MaximumEdgeLength": 0.0,
        "Domain": "Auto",
        "ResolveIntersections": 1,
        "MergeTolerance": 0.0,
        "ProjectToXYPlane": 0,
        "UseInputHolePoints": 1,
        "ApplyRegionAreas": 0,
        "GapRatioOverlay": 0,
        "MaximumSteinerPoints": 0,
        "InterpolatePointData": 1,
        "PassCellData": 1,
        "GenerateEdges": 1,
        "GenerateOverlay": 1,
    }
    names = mesher.ListProperties()
    for name, value in defaults.items():
        check(name in names, "property %s exists" % name)
        if name in names:
            check(mesher.GetPropertyValue(name) == value,
                  "%s defaults to %r (got %r)" % (name, value, mesher.GetPropertyValue(name)))
    check("HolePoints" in names and len(mesher.HolePoints) == 0, "HolePoints exists, empty")
    # What the panel can show (a GUI review): ParaView 5.11 makes no widget for
    # an IdTypeVectorProperty, and seeds are rows of two columns, X and Y.
    steiner = mesher.GetProperty("MaximumSteinerPoints").SMProperty
    check(steiner.IsA("vtkSMIntVectorProperty"),
          "MaximumSteinerPoints is an int property, which the panel shows (got %s)"
          % steiner.GetClassName())
    holes = mesher.GetProperty("HolePoints").SMProperty
    labels = holes.GetHints().FindNestedElementByName("ShowComponentLabels") if holes.GetHints() else None
    check(holes.GetNumberOfElementsPerCommand() == 2 and labels is not None
          and labels.GetNumberOfNestedElements() == 2,
          "HolePoints is a table of (x, y) rows with labelled columns")
    ports = [mesher.SMProxy.GetOutputPortName(i) for i in range(mesher.SMProxy.GetNumberOfOutputPorts())]
    check(ports == ["Mesh", "Edges", "Overlay"], "output ports Mesh, Edges, Overlay (got %r)" % ports)
    hints = mesher.SMProxy.GetHints()
    menu = hints.FindNestedElementByName("ShowInMenu") if hints else None
    check(menu is not None and menu.GetAttribute("category") == "Meshing",
          "shown in the Filters > Meshing menu")
    check(mesher.SMProxy.GetXMLLabel() == "Overlay Stitch Mesher", "labelled Overlay Stitch Mesher")

    # Port 0: the mesh and its arrays.
    mesh = fetch(mesher, 0)
    triangles = mesh.GetNumberOfCells()
    print("Mesh: %d points, %d triangles" % (mesh.GetNumberOfPoints(), triangles))
    check(triangles > 0, "the mesh has triangles")
    check(all(mesh.GetCellType(c) == 5 for c in range(triangles)), "every mesh cell is a triangle")
    # VTK's subdivision filters refuse cells in vtkCellArray's 32-bit storage
    # as "non-manifold" (a review): the mesh comes in VTK's default storage.
    check(mesh.GetPolys().IsStorage64Bit(), "the mesh's cells in 64-bit storage")
    for name, subdivide in (("Loop Subdivision", LoopSubdivision), ("Subdivide", Subdivide)):
        cells = fetch(subdivide(Input=mesher), 0).GetNumberOfCells()
        check(cells == 4 * triangles, "%s takes the mesh (%d cells, expected %d)" %
              (name, cells, 4 * triangles))
    origin = mesh.GetPointData().GetArray("VertexOrigin")
    check(origin is not None and origin.GetNumberOfTuples() == mesh.GetNumberOfPoints(),
          "VertexOrigin per point")
    # InputPointId: each input vertex's point in the input (same coordinates), -1 elsewhere.
    input_ids = mesh.GetPointData().GetArray("InputPointId")
    source = fetch(reader, 0)
    wrong, named = 0, 0
    for v in range(mesh.GetNumberOfPoints() if input_ids and origin else 0):
        i = int(input_ids.GetValue(v))
        if int(origin.GetValue(v)) == 0:
            named += 1
            wrong += not (0 <= i < source.GetNumberOfPoints() and
                          source.GetPoint(i) == mesh.GetPoint(v))
        else:
            wrong += i != -1
    check(input_ids is not None and named > 0 and wrong == 0,
          "InputPointId names each input vertex's input point (%d named, %d wrong)" % (named, wrong))
    for name in ("MinAngle", "MaxAngle", "RegionId"):
        array = mesh.GetCellData().GetArray(name)
        check(array is not None and array.GetNumberOfTuples() == triangles, name + " per triangle")
    max_angle = mesh.GetCellData().GetArray("MaxAngle")
    if max_angle is not None and triangles > 0:
        largest = max_angle.GetRange()[1]
        check(largest <= 170.0, "no angle above 170 degrees (largest %.3f)" % largest)
    check(mesh.GetFieldData().GetArray("OutputTriangles") is not None, "statistics in field data")

    # The Enclosed domain (Auto here) is the square plus the 5-degree spike.
    spike = 0.5 * (2 * 0.436609429) * 10
    area = triangle_area(mesh)
    check(math.isclose(area, 100 + spike, rel_tol=1e-6),
          "the mesh covers the enclosed region (area %.6f, expected %.6f)" % (area, 100 + spike))

    # An unstructured grid of the same lines (Filters > Clean to Grid) is
    # accepted, by the menu's input domain too, and meshes the same.
    grid = CleantoGrid(Input=reader)
    domain = mesher.GetProperty("Input").SMProperty.FindDomain("vtkSMDataTypeDomain")
    check(fetch(grid, 0).IsA("vtkUnstructuredGrid") and domain is not None and
          domain.IsInDomain(grid.SMProxy, 0) == 1,
          "the filter's input domain accepts an unstructured grid")
    group = GroupDatasets(Input=[reader, grid])
    check(fetch(group, 0).IsA("vtkMultiBlockDataSet") and domain.IsInDomain(group.SMProxy, 0) == 1,
          "and a multiblock of a polydata and an unstructured grid block")
    from_grid = fetch(OverlayStitchMesher(Input=grid), 0)
    check(from_grid.GetNumberOfCells() == triangles and
          math.isclose(triangle_area(from_grid), area, rel_tol=1e-12),
          "an unstructured grid of the same lines meshes the same (%d triangles, expected %d)" %
          (from_grid.GetNumberOfCells(), triangles))

    # Port 1: the classified edges.
    edges = fetch(mesher, 1)
    print("Edges: %d lines" % edges.GetNumberOfCells())
    check(edges.GetNumberOfCells() > 0, "the Edges output has lines")
    for name in ("Overlay", "Kept", "Discarded", "Input", "EdgeClass"):
        array = edges.GetCellData().GetArray(name)
        check(array is not None and array.GetNumberOfTuples() == edges.GetNumberOfCells(),
              name + " per edge")
    # PassCellData: each input subsegment names its input cell, other edges -1.
    cell_ids = edges.GetCellData().GetArray("InputCellId")
    is_input = edges.GetCellData().GetArray("Input")
    if cell_ids is not None and is_input is not None:
        named = [cell_ids.GetValue(e) for e in range(edges.GetNumberOfCells())]
        inputs = [is_input.GetValue(e) for e in range(edges.GetNumberOfCells())]
        cells = fetch(reader, 0).GetNumberOfCells()
        check(all(0 <= c < cells for c, i in zip(named, inputs) if i) and
              all(c == -1 for c, i in zip(named, inputs) if not i) and any(inputs),
              "InputCellId names an input cell on input subsegments, -1 elsewhere")
    else:
        check(False, "the Edges output has InputCellId")

    # Port 2: the overlay.
    overlay = fetch(mesher, 2)
    print("Overlay: %d triangles" % overlay.GetNumberOfCells())
    check(overlay.GetNumberOfCells() > 0, "the Overlay output has triangles")

    # Properties reach the filter: the Hull domain is the convex hull.
    mesher.Domain = "Hull"
    area = triangle_area(fetch(mesher, 0))
    check(math.isclose(area, 150.0, rel_tol=1e-6), "Domain=Hull covers the hull (area %.6f)" % area)
    mesher.Domain = "Auto"
    mesher.HolePoints = [5.0, 2.0]
    area = triangle_area(fetch(mesher, 0))
    check(area < 1e-9, "a hole seed inside the only region removes it (area %.6f)" % area)

    print("%d failure(s)" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
