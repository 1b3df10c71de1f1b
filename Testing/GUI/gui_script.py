"""Run inside the real ParaView GUI: paraview --script=gui_script.py --exit.

The plugin is loaded by ParaView at startup from PV_PLUGIN_PATH, as a user
would have it. Inputs and outputs come through the environment (--script
takes no arguments):
  OSM_GUI_DATA        the line data to open
  OSM_GUI_SCREENSHOT  the PNG to save
  OSM_GUI_REPORT      a text file: the number of triangles the filter produced and
                      the array the Edges output is colored by when it is shown
"""
import os

from paraview.simple import *  # noqa: F401,F403

data = os.environ["OSM_GUI_DATA"]
screenshot = os.environ["OSM_GUI_SCREENSHOT"]
report = os.environ["OSM_GUI_REPORT"]

with open(report, "w") as out:
    out.write("started\n")
    reader = OpenDataFile(data)
    # Defined by the plugin: the same name as Filters > Meshing > Overlay Stitch Mesher.
    mesher = OverlayStitchMesher(Input=reader)
    view = GetActiveViewOrCreate("RenderView")
    display = Show(mesher, view)
    display.SetRepresentationType("Surface With Edges")
    ColorBy(display, ("CELLS", "MinAngle"))
    display.RescaleTransferFunctionToDataRange(True)
    Hide(reader, view)
    # The Edges output opens colored by EdgeClass (the filter makes it the
    # active cell scalars; ParaView's XML has no hint for a default coloring).
    edges = Show(OutputPort(mesher, 1), view)
    color = edges.ColorArrayName
    out.write("edges_color %s %s\n" % (color[0], color[1]))
    Hide(OutputPort(mesher, 1), view)
    view.OrientationAxesVisibility = 0
    ResetCamera(view)
    Render(view)
    # Compared with Baseline/gui-screenshot.png by compare_images.py: keep the
    # resolution, camera and coloring in step with it.
    SaveScreenshot(screenshot, view, ImageResolution=[640, 480])
    out.write("triangles %d\n" % mesher.GetDataInformation().GetNumberOfCells())
