"""Compare a screenshot with the project's baseline image, with a tolerance.

Usage:
  pvpython compare_images.py <image.png> <baseline.png> [--threshold T] [--max-fraction F]
  pvpython compare_images.py --self-test <baseline.png>

A pixel differs when one of its R, G, B channels differs from the baseline's
by more than T (default 24 of 255: small shading and anti-aliasing changes
between drivers pass). The image passes when the images have the same size and
at most a fraction F of the pixels differ (default 0.01, i.e. 1 %). The figures
are printed either way.

--self-test shows that the comparison can fail: the baseline must match
itself, and must NOT match a copy shifted by 12 pixels nor a copy whose
foreground is recolored; exit 0 only if all three come out as expected.

The baseline, Baseline/gui-screenshot.png, is made by the project: to
regenerate it after an intended change of the picture (filter output, camera,
coloring, resolution in gui_script.py), run the GUI test with
OSM_GUI_REGENERATE_BASELINE=1, e.g.
  OSM_GUI_REGENERATE_BASELINE=1 ctest --test-dir build -R gui.ApplyFilterScreenshot -V
then look at the new Testing/GUI/Baseline/gui-screenshot.png and commit it.
"""
import sys

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader


def read_rgb(path):
    reader = vtkPNGReader()
    if not reader.CanReadFile(path):
        raise SystemExit("not a readable PNG: " + path)
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels.reshape(height, width, -1)[:, :, :3].astype(numpy.int16)


def compare(image, baseline, threshold, max_fraction, label):
    """Print the figures; True when the images match within the tolerance."""
    if image.shape != baseline.shape:
        print("%s: size %dx%d, baseline %dx%d: FAILED (sizes differ)"
              % (label, image.shape[1], image.shape[0], baseline.shape[1], baseline.shape[0]))
        return False
    delta = numpy.abs(image - baseline).max(axis=2)
    differing = int((delta > threshold).sum())
    fraction = differing / float(delta.size)
    ok = fraction <= max_fraction
    print("%s: %dx%d, largest channel difference %d, %d pixel(s) differ by more than %d "
          "(%.4f %% of the image, allowed %.4f %%): %s"
          % (label, image.shape[1], image.shape[0], int(delta.max()), differing, threshold,
             100 * fraction, 100 * max_fraction, "ok" if ok else "FAILED"))
    return ok


def self_test(baseline_path, threshold, max_fraction):
    baseline = read_rgb(baseline_path)
    same = compare(baseline.copy(), baseline, threshold, max_fraction, "baseline vs itself")
    shifted = numpy.roll(baseline, 12, axis=1)
    moved = compare(shifted, baseline, threshold, max_fraction, "baseline vs shifted by 12 px")
    background = numpy.array(numpy.unravel_index(0, baseline.shape[:2]))
    back = baseline[tuple(background)]
    recolored = baseline.copy()
    foreground = numpy.any(numpy.abs(baseline - back) > threshold, axis=2)
    recolored[foreground] = 255 - recolored[foreground]
    changed = compare(recolored, baseline, threshold, max_fraction, "baseline vs recolored")
    ok = same and not moved and not changed
    print("self-test: %s" % ("ok, the comparison tells these images apart" if ok else "FAILED"))
    return ok


def main(argv):
    threshold, max_fraction = 24, 0.01
    args = []
    i = 0
    while i < len(argv):
        if argv[i] == "--threshold":
            threshold = int(argv[i + 1])
            i += 2
        elif argv[i] == "--max-fraction":
            max_fraction = float(argv[i + 1])
            i += 2
        else:
            args.append(argv[i])
            i += 1
    if len(args) == 2 and args[0] == "--self-test":
        return 0 if self_test(args[1], threshold, max_fraction) else 1
    if len(args) != 2:
        print(__doc__)
        return 2
    ok = compare(read_rgb(args[0]), read_rgb(args[1]), threshold, max_fraction,
                 "%s vs %s" % (args[0], args[1]))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
