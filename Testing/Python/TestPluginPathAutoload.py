"""pvpython with PV_PLUGIN_PATH set: the plugin loads at start-up, no LoadPlugin call."""
import os

assert os.environ.get("PV_PLUGIN_PATH"), "run with PV_PLUGIN_PATH set to the plugin folder"
from paraview.simple import *  # noqa: E402,F401,F403

assert "CheckSurface" in dir(), "CheckSurface not defined: plugin not auto-loaded"
check = CheckSurface(Input=Sphere())
check.UpdatePipeline()
print("AUTOLOAD_OK")
