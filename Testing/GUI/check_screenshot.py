"""Check that a screenshot is not blank.

Usage: pvpython check_screenshot.py <image.png> [min-foreground-fraction] [min-colours]

The most common colour is taken as the background. The image passes when
enough pixels differ from it and it has enough distinct colours (a mesh
coloured by MinAngle with its edges drawn has many).
"""
import sys

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader


def main(path, min_fraction=0.02, min_colours=16):
    reader = vtkPNGReader()
    if not reader.CanReadFile(path):
        print("not a readable PNG: " + path)
        return 1
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    rgb = pixels.reshape(len(pixels), -1)[:, :3]
    colours, counts = numpy.unique(rgb, axis=0, return_counts=True)
    background = tuple(int(v) for v in colours[numpy.argmax(counts)])
    fraction = 1.0 - counts.max() / float(width * height)
    print("%s: %dx%d, background %s, %.1f%% foreground, %d colours"
          % (path, width, height, background, 100 * fraction, len(colours)))
    if fraction < min_fraction:
        print("FAILED: blank image (foreground below %.1f%%)" % (100 * min_fraction))
        return 1
    if len(colours) < min_colours:
        print("FAILED: only %d colours (need %d)" % (len(colours), min_colours))
        return 1
    print("ok: the screenshot is not blank")
    return 0


if __name__ == "__main__":
    if len(sys.argv) < 2:
        print(__doc__)
        sys.exit(2)
    args = [sys.argv[1]] + [float(a) for a in sys.argv[2:4]]
    sys.exit(main(*args))
