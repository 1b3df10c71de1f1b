"""Run inside the real ParaView GUI: paraview --script=gui_script.py --exit.

The plugin is loaded by ParaView at startup from PV_PLUGIN_PATH, as a user
would have it. Inputs and outputs come through the environment (--script
takes no arguments):
  OSM_GUI_DATA        the line data to open
  OSM_GUI_SCREENSHOT  the PNG to save
  OSM_GUI_REPORT      a text file: the number of triangles the filter produced
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
    view.OrientationAxesVisibility = 0
    ResetCamera(view)
    Render(view)
    SaveScreenshot(screenshot, view, ImageResolution=[800, 600])
    out.write("triangles %d\n" % mesher.GetDataInformation().GetNumberOfCells())
