"""pvpython / pvbatch test of the OverlayStitchMesher properties and inputs.

Usage: pvpython|pvbatch test_properties.py <OverlayStitchMesher.so> <Testing/Data> <scratch dir>

Through paraview.simple only (no rendering): the properties MergeTolerance,
ProjectToXYPlane and UseInputHolePoints and their defaults; coplanar input in
a tilted plane (meshed in its plane, input points exact); non-coplanar input
(an error naming the point, empty output) and ProjectToXYPlane; near duplicate
points merged within MergeTolerance; and, when the plugin has the reader
TrianglePolyReader, a .poly file with a hole read and meshed, the hole honoured
only when UseInputHolePoints is on. Inputs are written as .vtp files into the
scratch directory and read back with XMLPolyDataReader.
"""
import contextlib
import math
import os
import sys
import tempfile

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

failures = []


def check(condition, what):
    print(("ok      " if condition else "FAILED  ") + what, flush=True)
    if not condition:
        failures.append(what)


@contextlib.contextmanager
def stderr_captured(into):
    """Collect what the process writes to file descriptor 2 (VTK's errors) into the list."""
    sys.stderr.flush()
    saved = os.dup(2)
    with tempfile.TemporaryFile(mode="w+b") as tmp:
        os.dup2(tmp.fileno(), 2)
        try:
            yield
        finally:
            sys.stderr.flush()
            os.dup2(saved, 2)
            os.close(saved)
            tmp.seek(0)
            text = tmp.read().decode("utf-8", "replace")
            sys.stderr.write(text)
            into.append(text)


def write_lines(path, points, lines):
    """Write points (x, y, z) and line cells (lists of ids) as a .vtp file."""
    data = vtkPolyData()
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    for p in points:
        pts.InsertNextPoint(p)
    cells = vtkCellArray()
    for line in lines:
        cells.InsertNextCell(len(line))
        for i in line:
            cells.InsertCellPoint(i)
    data.SetPoints(pts)
    data.SetLines(cells)
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(data)
    writer.SetDataModeToAscii()  # keeps every double digit readable for the exactness check
    check(writer.Write() == 1, "wrote " + os.path.basename(path))
    return path


def mesh_of(mesher, errors=None):
    """Run the mesher; return the Mesh output (port 0) as a local vtkPolyData."""
    if errors is None:
        mesher.UpdatePipeline()
    else:
        with stderr_captured(errors):
            mesher.UpdatePipeline()
    return servermanager.Fetch(mesher, idx=0)


def triangle_areas(poly):
    points = poly.GetPoints()
    for c in range(poly.GetNumberOfCells()):
        ids = poly.GetCell(c).GetPointIds()
        a, b, p = (points.GetPoint(ids.GetId(k)) for k in range(3))
        u = [b[i] - a[i] for i in range(3)]
        v = [p[i] - a[i] for i in range(3)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        yield 0.5 * math.sqrt(sum(x * x for x in n))


def longest_edge(poly):
    points, longest = poly.GetPoints(), 0.0
    for c in range(poly.GetNumberOfCells()):
        ids = poly.GetCell(c).GetPointIds()
        corners = [points.GetPoint(ids.GetId(k)) for k in range(3)]
        for k in range(3):
            a, b = corners[k], corners[(k + 1) % 3]
            longest = max(longest, math.sqrt(sum((a[i] - b[i]) ** 2 for i in range(3))))
    return longest


def area3d(poly):
    return sum(triangle_areas(poly))


def statistic(poly, name):
    array = poly.GetFieldData().GetArray(name)
    return array.GetValue(0) if array is not None else None


def point_set(poly):
    return {tuple(poly.GetPoint(i)) for i in range(poly.GetNumberOfPoints())}


def centroids_inside(poly, lo, hi):
    count = 0
    for c in range(poly.GetNumberOfCells()):
        ids = poly.GetCell(c).GetPointIds()
        xs = [poly.GetPoint(ids.GetId(k)) for k in range(3)]
        cx = sum(p[0] for p in xs) / 3
        cy = sum(p[1] for p in xs) / 3
        count += 1 if lo < cx < hi and lo < cy < hi else 0
    return count


def test_defaults(mesher):
    names = mesher.ListProperties()
    for name, value in (("MergeTolerance", 0.0), ("ProjectToXYPlane", 0), ("UseInputHolePoints", 1),
                        ("ApplyRegionAreas", 0), ("GapRatioOverlay", 0)):
        check(name in names, "property %s exists" % name)
        if name in names:
            check(mesher.GetPropertyValue(name) == value,
                  "%s defaults to %r (got %r)" % (name, value, mesher.GetPropertyValue(name)))


def test_tilted(scratch):
    # The square [0,10]^2 in the plane through o spanned by the orthonormal a, b.
    o, a, b = (3.0, -2.0, 5.0), (0.8, 0.36, 0.48), (-0.6, 0.48, 0.64)
    at = [tuple(o[k] + x * a[k] + y * b[k] for k in range(3))
          for x, y in ((0, 0), (10, 0), (10, 10), (0, 10), (2, 6), (7, 6))]
    path = write_lines(os.path.join(scratch, "tilted.vtp"), at, [[0, 1, 2, 3, 0], [4, 5]])
    reader = XMLPolyDataReader(FileName=[path])
    mesher = OverlayStitchMesher(Input=reader)
    mesh = mesh_of(mesher)
    check(mesh.GetNumberOfCells() > 0, "tilted plane: meshed (%d triangles)" % mesh.GetNumberOfCells())
    check(statistic(mesh, "InputPlaneFitted") == 1, "tilted plane: InputPlaneFitted = 1")
    check(abs(area3d(mesh) - 100.0) < 1e-9, "tilted plane: 3D area 100 (got %.12g)" % area3d(mesh))
    # The input as read back (the .vtp round trip is exact in ASCII with 17 digits or not:
    # compare with what the reader gives, which is what the mesher saw).
    original = servermanager.Fetch(reader)
    given = {tuple(original.GetPoint(i)) for i in range(original.GetNumberOfPoints())}
    check(given <= point_set(mesh), "tilted plane: every input point is an output point, bit for bit")
    n = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
    far = max(abs(sum((p[k] - o[k]) * n[k] for k in range(3))) for p in point_set(mesh))
    check(far < 1e-12, "tilted plane: every output point lies in the plane (farthest %.3g)" % far)
    Delete(mesher)
    Delete(reader)


def test_non_coplanar(scratch):
    points = [(0, 0, 1), (10, 0, 2), (10, 10, 0.5), (0, 10, 4), (5, 5, 3)]
    path = write_lines(os.path.join(scratch, "bumpy.vtp"), points, [[0, 1, 2, 3, 0]])
    reader = XMLPolyDataReader(FileName=[path])
    mesher = OverlayStitchMesher(Input=reader)
    errors = []
    mesh = mesh_of(mesher, errors)
    check(mesh.GetNumberOfCells() == 0 and mesh.GetNumberOfPoints() == 0,
          "non-coplanar: empty output")
    check("not coplanar" in errors[0] and "ProjectToXYPlane" in errors[0],
          "non-coplanar: the error says so and names the way out")
    mesher.ProjectToXYPlane = 1
    mesh = mesh_of(mesher)
    bounds = mesh.GetBounds()
    check(mesh.GetNumberOfCells() > 0, "ProjectToXYPlane=1: meshed")
    check(bounds[4] == bounds[5] == 2.1, "ProjectToXYPlane=1: at z = 2.1, the mean z (got %r)"
          % (bounds[4:6],))
    check(abs(area3d(mesh) - 100.0) < 1e-9, "ProjectToXYPlane=1: the XY square is meshed")
    Delete(mesher)
    Delete(reader)


def test_merge_tolerance(scratch):
    points = [(0, 0, 0), (10, 0, 0), (10, 10, 0), (0, 10, 0), (5, 5, 0), (5 + 1e-7, 5, 0)]
    path = write_lines(os.path.join(scratch, "near.vtp"), points, [[0, 1, 2, 3, 0]])
    reader = XMLPolyDataReader(FileName=[path])
    mesher = OverlayStitchMesher(Input=reader)
    check(statistic(mesh_of(mesher), "DuplicatePointsMerged") == 0,
          "MergeTolerance=0: the points 1e-7 apart are kept")
    mesher.MergeTolerance = 1e-6
    check(statistic(mesh_of(mesher), "DuplicatePointsMerged") == 1,
          "MergeTolerance=1e-6: they are merged and counted")
    Delete(mesher)
    Delete(reader)


def test_poly_with_hole(data_dir):
    # The plugin ships the reader: its absence is a failure, not a skip.
    check("TrianglePolyReader" in globals(), "the plugin provides TrianglePolyReader")
    path = os.path.join(data_dir, "square_hole.poly")
    reader = TrianglePolyReader(FileName=path)
    check(reader.GetXMLName() == "TrianglePolyReader", "the .poly file is read by TrianglePolyReader")
    data = servermanager.Fetch(reader)
    holes = data.GetFieldData().GetArray("HolePoints")
    check(holes is not None and holes.GetNumberOfTuples() == 1 and holes.GetNumberOfComponents() == 3,
          "the reader gives the file's hole seed as field data HolePoints")
    mesher = OverlayStitchMesher(Input=reader)
    mesh = mesh_of(mesher)
    area = area3d(mesh)
    check(abs(area - 96.0) < 1e-9, ".poly with a hole: the hole is cut (area %.9g, expected 96)" % area)
    check(centroids_inside(mesh, 4, 6) == 0, ".poly with a hole: no triangle centroid in the hole")
    check(statistic(mesh, "InputHolePoints") == 1, ".poly with a hole: InputHolePoints = 1")
    with_hole = mesh.GetNumberOfCells()
    mesher.UseInputHolePoints = 0
    mesh = mesh_of(mesher)
    check(abs(area3d(mesh) - 100.0) < 1e-9 and centroids_inside(mesh, 4, 6) > 0,
          "UseInputHolePoints=0: the file's hole is meshed")
    check(mesh.GetNumberOfCells() > with_hole, "UseInputHolePoints=0: more triangles")
    # No edge longer than MaximumEdgeLength: at 0.4 completion makes a longer
    # diagonal, which is split.
    mesher.UseInputHolePoints = 1
    mesher.MaximumEdgeLength = 0.4
    mesh = mesh_of(mesher)
    check(longest_edge(mesh) <= 0.4 and statistic(mesh, "LongEdgesSplit") >= 1,
          "MaximumEdgeLength=0.4: no longer edge (longest %.6g, %d long edge(s) split)" % (
              longest_edge(mesh), statistic(mesh, "LongEdgesSplit")))
    mesher.MaximumEdgeLength = 0.0
    # The file's region line (seed (1, 1), attribute 7, maximum area 0.5)
    # bounds every triangle of the ring with ApplyRegionAreas, as Triangle's -a.
    mesher.UseInputHolePoints = 1
    mesher.ApplyRegionAreas = 1
    mesh = mesh_of(mesher)
    largest = max(triangle_areas(mesh))
    check(largest <= 0.5 and mesh.GetNumberOfCells() >= 96 / 0.5,
          "ApplyRegionAreas=1: every triangle within the region's area 0.5 (%d triangles, "
          "largest %.3g)" % (mesh.GetNumberOfCells(), largest))
    mesher.ApplyRegionAreas = 0
    # GapRatioOverlay: the paper's overlay quality, at once; more triangles.
    fast = mesh_of(mesher).GetNumberOfCells()
    check(statistic(mesh_of(mesher), "GapRatioOverlay") == 0, "GapRatioOverlay off by default")
    mesher.GapRatioOverlay = 1
    mesh = mesh_of(mesher)
    check(statistic(mesh, "GapRatioOverlay") == 1 and mesh.GetNumberOfCells() > fast,
          "GapRatioOverlay=1: the gap-ratio overlay (%d triangles, %d without)" % (
              mesh.GetNumberOfCells(), fast))
    mesher.GapRatioOverlay = 0
    Delete(mesher)
    Delete(reader)


def test_seeds_follow_transform(data_dir, scratch):
    """The file's hole and region seeds follow the points through Transform
    (a review: field data passes through Transform unchanged, and a scaled
    face.poly lost its main region to a hole seed left behind)."""
    reader = TrianglePolyReader(FileName=os.path.join(data_dir, "square_hole.poly"))
    check(servermanager.Fetch(reader).GetFieldData().GetArray("SeedReferencePoints") is not None,
          "the reader records the seeds' reference points")
    moved = Transform(Input=reader)
    moved.Transform = "Transform"
    # The hole [4, 6]^2 goes to [98, 102] x [-62, -58]: x' = 110 - 2y, y' = 2x - 70.
    moved.Transform.Scale = [2, 2, 1]
    moved.Transform.Rotate = [0, 0, 90]
    moved.Transform.Translate = [110, -70, 0]
    mesher = OverlayStitchMesher(Input=moved, ApplyRegionAreas=1)
    mesh = mesh_of(mesher)
    area = area3d(mesh)
    inside = 0
    for c in range(mesh.GetNumberOfCells()):
        ids = mesh.GetCell(c).GetPointIds()
        xs = [mesh.GetPoint(ids.GetId(k)) for k in range(3)]
        cx, cy = sum(p[0] for p in xs) / 3, sum(p[1] for p in xs) / 3
        inside += 1 if 98 < cx < 102 and -62 < cy < -58 else 0
    largest = max(triangle_areas(mesh))
    check(abs(area - 384.0) < 1e-6 and inside == 0,
          "Transform (scale 2, rotate 90, translate): the hole moves with the square (area %.9g, "
          "expected 384; %d centroid(s) in the hole)" % (area, inside))
    # Unscaled, the bound of 0.5 would force at least 768 triangles, none
    # larger than 0.5.
    check(0.5 < largest <= 2.0 and 384 / 2.0 <= mesh.GetNumberOfCells() < 700,
          "Transform: the region seed moves too, its maximum area scaled by 4 (%d triangles, "
          "largest %.3g)" % (mesh.GetNumberOfCells(), largest))
    check(mesh.GetFieldData().GetArray("SeedReferencePoints") is None,
          "the reference points are not passed to the outputs")
    Delete(mesher)
    # Stood up in a vertical plane, where (x, y) names no point: the moved
    # hole seed is given in x, y and z.
    # (square_hole.poly without its region line, whose seeds have no z.)
    with open(os.path.join(data_dir, "square_hole.poly")) as f:
        text = f.read()
    holes_only = os.path.join(scratch, "square_hole_no_region.poly")
    with open(holes_only, "w") as f:
        f.write(text[:text.index("# one region seed")] + "0\n")
    hole_reader = TrianglePolyReader(FileName=holes_only)
    upright = Transform(Input=hole_reader)
    upright.Transform = "Transform"
    upright.Transform.Rotate = [90, 0, 0]
    mesher = OverlayStitchMesher(Input=upright)
    mesh = mesh_of(mesher)
    check(abs(area3d(mesh) - 96.0) < 1e-6,
          "Transform into a vertical plane: the hole moves with it (area %.9g, expected 96)"
          % area3d(mesh))
    Delete(mesher)
    Delete(upright)
    Delete(hole_reader)
    # Warped in z by a point array, the points moved by no affine map: the
    # seeds are used as written, which the XY projection still fits.
    warped = WarpByScalar(Input=reader, Scalars=["POINTS", "Attribute0"], ScaleFactor=10)
    mesher = OverlayStitchMesher(Input=warped, ProjectToXYPlane=1, ApplyRegionAreas=1)
    errors = []
    mesh = mesh_of(mesher, errors)
    largest = max(triangle_areas_xy(mesh))
    check(abs(area_xy(mesh) - 96.0) < 1e-6 and largest <= 0.5,
          "Warp By Scalar: the file's hole and region area hold in the XY projection (area %.9g, "
          "largest %.3g)" % (area_xy(mesh), largest))
    check(any("by no map of a plane onto a plane" in e for e in errors),
          "Warp By Scalar: a warning says the seeds are used as written")
    Delete(mesher)
    Delete(warped)
    # Renumbered or added to after the Transform (a ParaView user's review:
    # the hole was lost with no word), the seeds cannot follow: a warning
    # says so. Renumbered without moving, they still fit: no word.
    for name, source in (("Clean after a Transform", Clean(Input=moved)),
                         ("Append Geometry after a Transform",
                          AppendGeometry(Input=[moved, TrianglePolyReader(
                              FileName=os.path.join(data_dir, "crossing.poly"))]))):
        mesher = OverlayStitchMesher(Input=source)
        errors = []
        mesh_of(mesher, errors)
        check(any("cannot follow" in e or "renumbered and moved" in e for e in errors),
              "%s: a warning says the seeds could not follow the points" % name)
        Delete(mesher)
    mesher = OverlayStitchMesher(Input=Clean(Input=reader))
    errors = []
    mesh = mesh_of(mesher, errors)
    check(abs(area3d(mesh) - 96.0) < 1e-6 and not any("seeds" in e for e in errors),
          "Clean alone: the seeds still fit, with no word of them (area %.9g)" % area3d(mesh))
    Delete(mesher)
    Delete(moved)
    Delete(reader)


def triangle_areas_xy(poly):
    points = poly.GetPoints()
    for c in range(poly.GetNumberOfCells()):
        ids = poly.GetCell(c).GetPointIds()
        a, b, p = (points.GetPoint(ids.GetId(k)) for k in range(3))
        yield 0.5 * abs((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]))


def area_xy(poly):
    return sum(triangle_areas_xy(poly))


def test_seeds_of_every_block(data_dir, scratch):
    """A composite input's blocks each bring their hole and region seeds (a
    review: only the first block's region seeds were used, the second block's
    region had neither its attribute nor its area bound); messages note that a
    block's cells count from 0 where its file counts from 1."""
    with open(os.path.join(data_dir, "square_hole.poly")) as f:
        text = f.read()
    lines = text.split("\n")
    # The same square 20 to the right: its points, hole and region seed moved,
    # its region given attribute 9 and maximum area 2.
    moved = []
    for line in lines:
        fields = line.split()
        if len(fields) == 5 and fields[0] != "9" and not line.startswith("#"):
            fields[1] = str(float(fields[1]) + 20)
            if line == "1 1 1 7 0.5":
                fields[3], fields[4] = "9", "2"
            line = " ".join(fields)
        elif len(fields) == 3 and line == "1 5 5":
            line = "1 25 5"
        moved.append(line)
    right = os.path.join(scratch, "square_hole_right.poly")
    with open(right, "w") as f:
        f.write("\n".join(moved))
    left_reader = TrianglePolyReader(FileName=os.path.join(data_dir, "square_hole.poly"))
    right_reader = TrianglePolyReader(FileName=right)
    group = GroupDatasets(Input=[left_reader, right_reader])
    mesher = OverlayStitchMesher(Input=group, ApplyRegionAreas=1)
    mesh = mesh_of(mesher)
    attribute = mesh.GetCellData().GetArray("RegionAttribute")
    seen = {"left": set(), "right": set()}
    largest = {"left": 0.0, "right": 0.0}
    for c, size in enumerate(triangle_areas(mesh)):
        side = "left" if mesh.GetCell(c).GetPoints().GetPoint(0)[0] < 15 else "right"
        seen[side].add(attribute.GetValue(c))
        largest[side] = max(largest[side], size)
    check(seen == {"left": {7.0}, "right": {9.0}},
          "Group Datasets: each block's region seed gives its region its attribute (%s)" % seen)
    # Unbounded, the right square's triangles reach about 9.
    check(largest["left"] <= 0.5 and 0.5 < largest["right"] <= 2.0,
          "Group Datasets: each block's region seed bounds its region's area (largest %.3g left, "
          "%.3g right)" % (largest["left"], largest["right"]))
    check(abs(area3d(mesh) - 192.0) < 1e-6,
          "Group Datasets: both blocks' holes are cut (area %.9g, expected 192)" % area3d(mesh))
    Delete(mesher)
    # A block whose RegionAttributes has another shape: left out, with a
    # warning that names it; the other block's seed still applies.
    from vtkmodules.vtkCommonCore import vtkDoubleArray
    odd = vtkPolyData()
    odd_points = vtkPoints()
    odd_points.SetDataTypeToDouble()
    for p in [(20, 0, 0), (30, 0, 0), (30, 10, 0), (20, 10, 0)]:
        odd_points.InsertNextPoint(p)
    odd_lines = vtkCellArray()
    for a in range(4):
        odd_lines.InsertNextCell(2)
        odd_lines.InsertCellPoint(a)
        odd_lines.InsertCellPoint((a + 1) % 4)
    odd.SetPoints(odd_points)
    odd.SetLines(odd_lines)
    seeds = vtkDoubleArray()
    seeds.SetName("RegionAttributes")
    seeds.SetNumberOfComponents(2)
    seeds.InsertNextTuple2(21, 1)
    odd.GetFieldData().AddArray(seeds)
    odd_path = os.path.join(scratch, "square_odd_regions.vtp")
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(odd_path)
    writer.SetInputData(odd)
    check(writer.Write() == 1, "wrote " + os.path.basename(odd_path))
    odd_reader = XMLPolyDataReader(FileName=[odd_path])
    odd_group = GroupDatasets(Input=[left_reader, odd_reader])
    mesher = OverlayStitchMesher(Input=odd_group)
    errors = []
    mesh = mesh_of(mesher, errors)
    attribute = mesh.GetCellData().GetArray("RegionAttribute")
    left = {attribute.GetValue(c) for c in range(mesh.GetNumberOfCells())
            if mesh.GetCell(c).GetPoints().GetPoint(0)[0] < 15}
    check(any("RegionAttributes of block" in e and "has 2 components" in e and "ignored" in e
              for e in errors) and left == {7.0},
          "Group Datasets: a block's RegionAttributes of 2 components is left out with a warning "
          "(left square's attributes %s)" % left)
    Delete(mesher)
    Delete(odd_group)
    Delete(odd_reader)
    # A crossing refused names cells of the block, which count from 0 though the
    # file counts from 1.
    one_based = os.path.join(scratch, "crossing_from_one.poly")
    with open(one_based, "w") as f:
        f.write("# crossing.poly numbered from 1\n6 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n"
                "5 1 1\n6 3 3.5\n6 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n6 2 4\n0\n")
    reader = TrianglePolyReader(FileName=one_based)
    one_block = GroupDatasets(Input=[reader])
    mesher = OverlayStitchMesher(Input=one_block, ResolveIntersections=0)
    errors = []
    mesh_of(mesher, errors)
    text = "".join(errors)
    check("cross near" in text and "also where its file counts from 1" in text,
          "Group Datasets of a file counting from 1: the error says the block's cells count from 0")
    Delete(mesher)
    Delete(one_block)
    Delete(reader)
    Delete(group)
    Delete(right_reader)
    Delete(left_reader)


def test_hole_points_property(data_dir):
    """HolePoints: (x, y) pairs cut holes, one AddHolePoint per pair (the panel's two columns)."""
    path = os.path.join(data_dir, "square_hole.poly")
    # The plugin ships the reader: its absence is a failure, not a skip.
    check("TrianglePolyReader" in globals(), "the plugin provides TrianglePolyReader")
    reader = TrianglePolyReader(FileName=path)
    mesher = OverlayStitchMesher(Input=reader, UseInputHolePoints=0, HolePoints=[5.0, 5.0])
    mesh = mesh_of(mesher)
    check(abs(area3d(mesh) - 96.0) < 1e-9, "HolePoints=[5, 5] cuts the hole")
    # A seed outside every region beside it: the one inside still cuts the hole.
    errors = []
    mesher.HolePoints = [50.0, 50.0, 5.0, 5.0]
    mesh = mesh_of(mesher, errors)
    check(abs(area3d(mesh) - 96.0) < 1e-9, "HolePoints=[50, 50, 5, 5]: the second pair cuts the hole")
    check(any("hole 0" in e and "(50, 50)" in e for e in errors),
          "HolePoints=[50, 50, 5, 5]: the first pair is read as one seed, named by its coordinates")
    Delete(mesher)
    Delete(reader)


def main(plugin, data_dir, scratch):
    os.makedirs(scratch, exist_ok=True)
    LoadPlugin(plugin, remote=False, ns=globals())
    check("OverlayStitchMesher" in globals(), "LoadPlugin defines OverlayStitchMesher")
    if failures:
        return 1
    square = write_lines(os.path.join(scratch, "square.vtp"),
                         [(0, 0, 0), (10, 0, 0), (10, 10, 0), (0, 10, 0)], [[0, 1, 2, 3, 0]])
    reader = XMLPolyDataReader(FileName=[square])
    mesher = OverlayStitchMesher(Input=reader)
    test_defaults(mesher)
    Delete(mesher)
    Delete(reader)
    test_tilted(scratch)
    test_non_coplanar(scratch)
    test_merge_tolerance(scratch)
    test_poly_with_hole(data_dir)
    test_hole_points_property(data_dir)
    test_seeds_follow_transform(data_dir, scratch)
    test_seeds_of_every_block(data_dir, scratch)
    print("%d failure(s)" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 4:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(*sys.argv[1:]))
