"""/usr/bin/python3 with the build on PYTHONPATH: `import boolsurf` gives the VTK filters."""
import boolsurf
from vtkmodules.vtkFiltersSources import vtkSphereSource

sphere = vtkSphereSource()
sphere.SetThetaResolution(24)
sphere.SetPhiResolution(12)
check = boolsurf.vtkBoolSurfCheckSurface()
check.SetInputConnection(sphere.GetOutputPort())
check.Update()
fd = check.GetOutput().GetFieldData()
assert fd.GetArray("Genus").GetValue(0) == 0
assert fd.GetArray("EulerCharacteristic").GetValue(0) == 2
assert fd.GetArray("Components").GetValue(0) == 1
print("IMPORT_OK")
