"""Mesh a line-data file with the OverlayStitchMesher plugin; write the mesh
as .vtp and render it as .png.

Usage (rendering needs an X server: Debian's ParaView renders through GLX):
  xvfb-run -a -s "-screen 0 1280x1024x24" pvpython mesh_example.py \
      --plugin build/lib/paraview-5.11/plugins/OverlayStitchMesher/OverlayStitchMesher.so \
      --input Testing/Data/wedge.vtk --output-dir out

Writes <output-dir>/<name>-mesh.vtp and <output-dir>/<name>-mesh.png, where
<name> is the input file name without its extension. Exits non-zero when the
filter reports an error or produces no triangles.
"""
import argparse
import os
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403


def render(reader, mesher, png):
    """Save a picture of the mesh (edges visible, coloured by MinAngle)."""
    view = CreateView("RenderView")
    try:
        view.ViewSize = [1200, 800]
        view.OrientationAxesVisibility = 0
        Show(reader, view)  # the input lines, under the mesh
        display = Show(OutputPort(mesher, 0), view)
        display.SetRepresentationType("Surface With Edges")
        ColorBy(display, ("CELLS", "MinAngle"))
        display.RescaleTransferFunctionToDataRange(True)
        display.SetScalarBarVisibility(view, True)
        view.CameraPosition = [0, 0, 1]
        view.CameraFocalPoint = [0, 0, 0]
        view.CameraViewUp = [0, 1, 0]
        view.CameraParallelProjection = 1
        ResetCamera(view)
        Render(view)
        SaveScreenshot(png, view, ImageResolution=[1200, 800])
    finally:
        # Without this, pvpython's exit after sys.exit() tears the OpenGL
        # context down in the wrong order and dies with a GLX error.
        Delete(view)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--plugin", required=True, help="path to OverlayStitchMesher.so")
    parser.add_argument("--input", required=True, help="line data (.vtk, .vtp, ...)")
    parser.add_argument("--output-dir", default="out")
    parser.add_argument("--minimum-angle", type=float, default=30.0)
    args = parser.parse_args()

    LoadPlugin(args.plugin, remote=False, ns=globals())
    os.makedirs(args.output_dir, exist_ok=True)
    name = os.path.splitext(os.path.basename(args.input))[0]
    vtp = os.path.join(args.output_dir, name + "-mesh.vtp")
    png = os.path.join(args.output_dir, name + "-mesh.png")
    for stale in (vtp, png):
        if os.path.exists(stale):
            os.remove(stale)

    reader = OpenDataFile(args.input)
    if reader is None:
        print("cannot read " + args.input)
        return 1
    mesher = OverlayStitchMesher(Input=reader, MinimumAngle=args.minimum_angle)
    mesher.UpdatePipeline()
    mesh = servermanager.Fetch(mesher, idx=0)
    triangles = mesh.GetNumberOfCells()
    if triangles == 0:
        print("the mesher produced no triangles (see the error above)")
        return 1
    angles = mesh.GetCellData().GetArray("MaxAngle").GetRange()
    smallest = mesh.GetCellData().GetArray("MinAngle").GetRange()[0]
    print("%s: %d vertices, %d triangles, angles %.2f .. %.2f degrees"
          % (args.input, mesh.GetNumberOfPoints(), triangles, smallest, angles[1]))

    SaveData(vtp, proxy=OutputPort(mesher, 0))
    print("wrote " + vtp)

    render(reader, mesher, png)
    print("wrote " + png)
    return 0 if os.path.isfile(vtp) and os.path.isfile(png) else 1


if __name__ == "__main__":
    sys.exit(main())
