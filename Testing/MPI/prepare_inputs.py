"""Writes the inputs of the MPI tests as .vtp files (run with pvpython or pvbatch).

    pvpython prepare_inputs.py --output-dir DIR [--wedge wedge.vtk] [--poly a.poly ...]
        [--pieces 2 3] [--ghost-pieces 2] [--global-ids]

Every input becomes line data in the convention of the project's .poly reader:
points with z = 0, one 2-point line cell per segment, one vertex cell per point
that is on no segment, and the field data "HolePoints" (3-component doubles).
Single segments (not polylines) let a redistribution spread the lines evenly
over the ranks. The partitioned inputs are also written as unstructured grids
(.pvtu), their lines first and their vertex cells last. Prints one line per
file written.
"""
import argparse
import os
import sys

from vtkmodules.vtkCommonCore import (vtkDoubleArray, vtkIdList, vtkIdTypeArray, vtkPoints,
                                     vtkUnsignedCharArray)
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData, vtkUnstructuredGrid
from vtkmodules.vtkIOLegacy import vtkPolyDataReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter, vtkXMLUnstructuredGridWriter

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
from poly_rows import poly_rows  # noqa: E402


def make_polydata(points, segments, holes, global_ids=None):
    """points: [(x, y)], segments: [(a, b)] 0-based, holes: [(x, y)]; global_ids: per
    point, its index in the whole input (the point data's GlobalIds attribute)."""
    vtk_points = vtkPoints()
    vtk_points.SetDataTypeToDouble()
    for x, y in points:
        vtk_points.InsertNextPoint(x, y, 0.0)
    lines = vtkCellArray()
    on_segment = [False] * len(points)
    for a, b in segments:
        lines.InsertNextCell(2)
        lines.InsertCellPoint(a)
        lines.InsertCellPoint(b)
        on_segment[a] = on_segment[b] = True
    verts = vtkCellArray()
    for i, used in enumerate(on_segment):
        if not used:
            verts.InsertNextCell(1)
            verts.InsertCellPoint(i)
    data = vtkPolyData()
    data.SetPoints(vtk_points)
    data.SetLines(lines)
    if verts.GetNumberOfCells():
        data.SetVerts(verts)
    hole_array = vtkDoubleArray()
    hole_array.SetName("HolePoints")
    hole_array.SetNumberOfComponents(3)
    for x, y in holes:
        hole_array.InsertNextTuple3(x, y, 0.0)
    data.GetFieldData().AddArray(hole_array)
    if global_ids is not None:
        ids = vtkIdTypeArray()
        ids.SetName("GlobalPointIds")
        for i in global_ids:
            ids.InsertNextValue(i)
        data.GetPointData().SetGlobalIds(ids)
    return data


def read_poly(path):
    """A minimal reader of Triangle's .poly format (test-side, independent of the core's)."""
    rows = poly_rows(path)
    count, dim, nattr, nmark = (int(v) for v in rows[0][:4])
    if count == 0 or dim != 2:
        raise ValueError("%s: needs its vertices inline and dim 2" % path)
    ids = {}
    points = []
    for r in rows[1 : 1 + count]:
        ids[int(r[0])] = len(points)
        points.append((float(r[1]), float(r[2])))
    k = 1 + count
    nseg = int(rows[k][0])
    segments = [(ids[int(r[1])], ids[int(r[2])]) for r in rows[k + 1 : k + 1 + nseg]]
    k += 1 + nseg
    holes = []
    if k < len(rows):
        nholes = int(rows[k][0])
        holes = [(float(r[1]), float(r[2])) for r in rows[k + 1 : k + 1 + nholes]]
    return points, segments, holes


def read_legacy_lines(path):
    """Line data from a legacy .vtk file, polylines split into single segments."""
    reader = vtkPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    points = [data.GetPoint(i)[:2] for i in range(data.GetNumberOfPoints())]
    segments = []
    lines = data.GetLines()
    ids = lines.GetConnectivityArray()
    offsets = lines.GetOffsetsArray()
    for c in range(lines.GetNumberOfCells()):
        start, end = int(offsets.GetValue(c)), int(offsets.GetValue(c + 1))
        cell = [int(ids.GetValue(k)) for k in range(start, end)]
        segments += [(cell[k], cell[k + 1]) for k in range(len(cell) - 1) if cell[k] != cell[k + 1]]
    return points, segments, []


def square_with_hole():
    """Project-made: a 10 x 10 square with a 4 x 4 square hole (one seed), an inner
    slit through the ring, and two isolated points (vertex cells)."""
    points = [(0, 0), (10, 0), (10, 10), (0, 10), (3, 3), (7, 3), (7, 7), (3, 7),
              (1, 5), (2.5, 5.5), (8.5, 1.5), (1.5, 8.5)]
    segments = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (8, 9)]
    return points, segments, [(5.0, 5.0)]


def write_with(writer, data, path):
    writer.SetFileName(path)
    writer.SetInputData(data)
    writer.SetDataModeToBinary()
    if not writer.Write():
        sys.exit("cannot write " + path)


def write(data, path):
    write_with(vtkXMLPolyDataWriter(), data, path)
    print("wrote %s: %d points, %d cells, %d hole seeds" % (
        path, data.GetNumberOfPoints(), data.GetNumberOfCells(),
        data.GetFieldData().GetArray("HolePoints").GetNumberOfTuples()))


def write_grid(data, path, tetra=False):
    """data as an unstructured grid: its line cells, then its vertex cells (the
    other order than polydata's), its point and field data; with tetra, a
    tetra on its first 4 points last (a cell the mesher ignores)."""
    grid = vtkUnstructuredGrid()
    grid.SetPoints(data.GetPoints())
    grid.GetPointData().ShallowCopy(data.GetPointData())
    grid.GetFieldData().ShallowCopy(data.GetFieldData())
    ids = vtkIdList()
    for cells in (data.GetLines(), data.GetVerts()):
        cells.InitTraversal()
        while cells.GetNextCell(ids):
            grid.InsertNextCell(3 if ids.GetNumberOfIds() == 2 else 1, ids)
    if tetra:
        grid.InsertNextCell(10, 4, [0, 1, 2, 3])
    write_with(vtkXMLUnstructuredGridWriter(), grid, path)


def write_pieces(points, segments, holes, count, path, global_ids, ghosts=False):
    """A partitioned .pvtp: the segments in `count` slabs of x (each piece holds the
    points its cells use, so pieces repeat the points on their common boundary);
    points on no segment go to the piece of their slab; the hole seeds are only
    in the LAST piece, so that they reach rank 0 from another rank. With ghosts,
    each piece also holds a copy of the other pieces' segments that touch its
    points, marked as duplicate ghost cells (vtkGhostType)."""
    xs = sorted(set(x for x, _ in points))
    cut = [xs[min(len(xs) - 1, (k * len(xs)) // count)] for k in range(1, count)]
    slab = lambda x: sum(1 for c in cut if x >= c)
    pieces = [([], []) for _ in range(count)]
    on_segment = [False] * len(points)
    for a, b in segments:
        on_segment[a] = on_segment[b] = True
        k = slab(0.5 * (points[a][0] + points[b][0]))
        pieces[k][0].append((a, b))
    for i, used in enumerate(on_segment):
        if not used:
            pieces[slab(points[i][0])][1].append(i)
    base = os.path.splitext(path)[0]
    sources = []
    for k, (own_segments, lonely) in enumerate(pieces):
        piece_segments = list(own_segments)
        if ghosts:
            touched = set(i for s in own_segments for i in s)
            piece_segments += [s for j, (other, _) in enumerate(pieces) if j != k
                               for s in other if s[0] in touched or s[1] in touched]
        local = {}
        local_points = []
        for i in [i for s in piece_segments for i in s] + lonely:
            if i not in local:
                local[i] = len(local_points)
                local_points.append(points[i])
        order = sorted(local, key=local.get)
        data = make_polydata(local_points, [(local[a], local[b]) for a, b in piece_segments],
                             holes if k == count - 1 else [], order if global_ids else None)
        if ghosts:
            flags = vtkUnsignedCharArray()
            flags.SetName("vtkGhostType")
            for _ in range(data.GetNumberOfVerts()):  # cell ids: vertex cells first
                flags.InsertNextValue(0)
            for n in range(len(piece_segments)):
                flags.InsertNextValue(0 if n < len(own_segments) else 1)  # 1: DUPLICATECELL
            data.GetCellData().AddArray(flags)
        name = "%s_%d.vtp" % (os.path.basename(base), k)
        write(data, os.path.join(os.path.dirname(path), name))
        if not ghosts:
            # The last piece (with the hole seeds, read by rank 1 of 2) also
            # holds a tetra, which that rank must say it ignores.
            write_grid(data, os.path.join(os.path.dirname(path), name[:-4] + ".vtu"),
                       tetra=k == count - 1)
        sources.append(name)
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="PPolyData" version="1.0" '
                'byte_order="LittleEndian" header_type="UInt64">\n <PPolyData GhostLevel="%d">\n'
                % (1 if ghosts else 0) +
                '  <PPoints><PDataArray type="Float64" NumberOfComponents="3"/></PPoints>\n')
        if global_ids:
            f.write('  <PPointData GlobalIds="GlobalPointIds">'
                    '<PDataArray type="Int64" Name="GlobalPointIds"/></PPointData>\n')
        if ghosts:
            f.write('  <PCellData><PDataArray type="UInt8" Name="vtkGhostType"/></PCellData>\n')
        for name in sources:
            f.write('  <Piece Source="%s"/>\n' % name)
        f.write(" </PPolyData>\n</VTKFile>\n")
    print("wrote %s: %d pieces%s" % (path, count, " with ghost cells" if ghosts else ""))
    if not ghosts:
        # The same pieces as the blocks of a multiblock file, which the mesher
        # takes as one graph (its ranks read different blocks).
        with open(base + ".vtm", "w") as f:
            f.write('<?xml version="1.0"?>\n<VTKFile type="vtkMultiBlockDataSet" version="1.0" '
                    'byte_order="LittleEndian" header_type="UInt64">\n <vtkMultiBlockDataSet>\n')
            for k, name in enumerate(sources):
                f.write('  <DataSet index="%d" file="%s"/>\n' % (k, name))
            f.write(" </vtkMultiBlockDataSet>\n</VTKFile>\n")
        print("wrote %s.vtm: %d blocks" % (base, count))
        # And as a partitioned unstructured grid.
        with open(base + ".pvtu", "w") as f:
            f.write('<?xml version="1.0"?>\n<VTKFile type="PUnstructuredGrid" version="1.0" '
                    'byte_order="LittleEndian" header_type="UInt64">\n'
                    ' <PUnstructuredGrid GhostLevel="0">\n'
                    '  <PPoints><PDataArray type="Float64" NumberOfComponents="3"/></PPoints>\n')
            if global_ids:
                f.write('  <PPointData GlobalIds="GlobalPointIds">'
                        '<PDataArray type="Int64" Name="GlobalPointIds"/></PPointData>\n')
            for name in sources:
                f.write('  <Piece Source="%s"/>\n' % (name[:-4] + ".vtu"))
            f.write(" </PUnstructuredGrid>\n</VTKFile>\n")
        print("wrote %s.pvtu: %d pieces" % (base, count))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--output-dir", required=True)
    parser.add_argument("--wedge")
    parser.add_argument("--poly", nargs="*", default=[])
    parser.add_argument("--pieces", type=int, nargs="*", default=[],
                        help="also write NAME-<k>.pvtp partitioned in k pieces")
    parser.add_argument("--ghost-pieces", type=int, nargs="*", default=[],
                        help="also write NAME-<k>g.pvtp: k pieces with a layer of ghost cells")
    parser.add_argument("--global-ids", action="store_true",
                        help="number the points with global ids (their index in the input)")
    args = parser.parse_args()
    os.makedirs(args.output_dir, exist_ok=True)
    inputs = [("square_hole", square_with_hole())]
    if args.wedge:
        inputs.append(("wedge", read_legacy_lines(args.wedge)))
    for path in args.poly:
        inputs.append((os.path.splitext(os.path.basename(path))[0], read_poly(path)))
    for name, pslg in inputs:
        ids = list(range(len(pslg[0]))) if args.global_ids else None
        write(make_polydata(*pslg, ids), os.path.join(args.output_dir, name + ".vtp"))
        for count in args.pieces:
            write_pieces(*pslg, count, os.path.join(args.output_dir, "%s-%d.pvtp" % (name, count)),
                         args.global_ids)
        for count in args.ghost_pieces:
            write_pieces(*pslg, count, os.path.join(args.output_dir, "%s-%dg.pvtp" % (name, count)),
                         args.global_ids, ghosts=True)


if __name__ == "__main__":
    main()
