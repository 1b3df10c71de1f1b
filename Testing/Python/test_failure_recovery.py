"""pvpython test: a view recovers from a failed run (rendering, under xvfb).

Usage: pvpython test_failure_recovery.py <path/to/OverlayStitchMesher.so> <Testing/Data>

ParaView 5.11 keeps a view and the Information panel on a filter's last
output for good once the filter returned failure during a render, even after
the filter succeeds again (found by a review, with ParaView's own filters
too). The plugin's XML turns the filter's ReportFailureToPipeline off, so that
a failed run returns empty outputs instead: this test renders a good run, a
failed one and good ones again, and checks what the view's data says each time.
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403

failures = []


def check(condition, what):
    print(("ok      " if condition else "FAILED  ") + what)
    if not condition:
        failures.append(what)


def main(plugin, data_dir):
    LoadPlugin(plugin, remote=False, ns=globals())
    reader = TrianglePolyReader(FileName=os.path.join(data_dir, "crossing.poly"))
    mesher = OverlayStitchMesher(Input=reader)
    check(mesher.ReportFailureToPipeline == 0, "the plugin turns ReportFailureToPipeline off")
    view = CreateView("RenderView")
    view.ViewSize = [200, 200]
    Show(OutputPort(mesher, 0), view)

    def rendered_cells():
        Render(view)
        return mesher.GetDataInformation(0).GetNumberOfCells()

    good = rendered_cells()
    check(good > 0, "a good run shows its %d triangles" % good)
    # crossing.poly's segments cross: without resolving them the run fails.
    mesher.ResolveIntersections = 0
    check(rendered_cells() == 0, "a failed run shows empty outputs")
    mesher.ResolveIntersections = 1
    again = rendered_cells()
    check(again == good, "the good run again shows its %d triangles (got %d)" % (good, again))
    mesher.HolePoints = [0.5, 0.2]
    holed = rendered_cells()
    check(0 < holed < good, "a hole then shows fewer triangles (%d of %d)" % (holed, good))
    # Without this, pvpython's exit tears the OpenGL context down in the
    # wrong order and dies with a GLX error (as in mesh_example.py).
    Delete(view)
    if failures:
        print("FAILED: %d check(s)" % len(failures))
        return 1
    print("PASSED")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
