"""The area of a proxy's output (its triangles), for the pvpython tests."""
from paraview import servermanager as sm
from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter


def area(proxy):
    sizes = vtkCellSizeFilter()
    sizes.SetInputData(sm.Fetch(proxy))
    sizes.Update()
    a = sizes.GetOutput().GetCellData().GetArray("Area")
    return sum(a.GetValue(i) for i in range(a.GetNumberOfTuples())) if a else 0.0
