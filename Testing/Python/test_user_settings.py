"""pvpython test: the tests ignore the user's ParaView settings.

Usage: pvpython test_user_settings.py <path/to/OverlayStitchMesher.so>

Run with HOME set to a folder of its own (CMake sets it): the script writes
there, before ParaView starts, the settings file a user could have
(~/.config/ParaView/ParaView-UserSettings.json) with other defaults for the
filter. The test folders' XDG_CONFIG_HOME (osm_ignore_user_settings in
Testing/CMakeLists.txt) must keep ParaView from reading it: without it the
filter would start at Minimum Angle 20 with Resolve Intersections off.
"""
import json
import os
import sys

settings = os.path.join(os.environ["HOME"], ".config", "ParaView")
os.makedirs(settings, exist_ok=True)
with open(os.path.join(settings, "ParaView-UserSettings.json"), "w") as f:
    json.dump({"filters": {"OverlayStitchMesher": {"MinimumAngle": 20, "ResolveIntersections": 0}}}, f)

from paraview.simple import *  # noqa: E402,F401,F403 (LoadPlugin, Sphere, ...)

LoadPlugin(sys.argv[1], remote=False, ns=globals())
mesher = OverlayStitchMesher(Input=Sphere())  # noqa: F405
angle, resolve = mesher.MinimumAngle, mesher.ResolveIntersections
print("XDG_CONFIG_HOME=%s: MinimumAngle %s, ResolveIntersections %s"
      % (os.environ.get("XDG_CONFIG_HOME"), angle, resolve))
if angle != 30 or resolve != 1:
    print("FAILED  the user's settings changed the filter's defaults")
    sys.exit(1)
print("ok      the filter's defaults, whatever the user's settings say")
