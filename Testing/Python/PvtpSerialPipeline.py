"""The pieces of a partitioned file (.pvtp) read in one process give the answers of the
undistributed surface, through every filter of the one-step pipeline: run by
TestPython3MpiPieces.py with pvbatch on one rank.

    pvbatch Testing/Python/PvtpSerialPipeline.py pieces.pvtp

VTK's reader appends the pieces without merging the points on their borders (and with the
ghost cells a piece keeps for its neighbours); BoolSurf welds them back. Exits non-zero on
any difference from Data/eight.ply itself.
"""
import os
import sys

source_dir = os.environ.get("BOOLSURF_SOURCE_DIR",
                            os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(source_dir, "Examples"))
from boolsurf_example_utils import (SurfaceRays, area, curves_source, load_plugin,  # noqa: E402
                                    surface_circle)
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager as sm  # noqa: E402

load_plugin(globals())
whole = PLYReader(FileNames=[os.path.join(source_dir, "Data", "eight.ply")])
pieces = OpenDataFile(sys.argv[1])
appended = sm.Fetch(pieces)
assert appended.GetNumberOfPoints() > sm.Fetch(whole).GetNumberOfPoints(), \
    "the pieces' border points should come back unmerged from the reader"
rays = SurfaceRays(whole, axis=1)
discs = [surface_circle(rays, (0.0, -0.035), 0.06), surface_circle(rays, (0.0, 0.035), 0.06)]


def answers(surface):
    control = curves_source([(discs[0], 0), (discs[1], 1)], surface)
    check = sm.Fetch(CheckSurface(Input=surface)).GetFieldData()
    field = {}
    for i in range(check.GetNumberOfArrays()):
        a = check.GetAbstractArray(i)
        field[a.GetName()] = [a.GetVariantValue(j).ToString() for j in range(a.GetNumberOfValues())]
    traced = TraceSurfaceCurves(Surface=surface, Curves=control)
    arrangement = SurfaceArrangement(Surface=surface, Curves=traced)
    boolean = SurfaceBoolean(Input=LabelArrangementCells(Input=arrangement),
                             Operation="Intersection")
    one = BoolSurf(Surface=surface, Curves=control, Operation="SymmetricDifference")
    return {"check": field,
            "traced": sm.Fetch(traced).GetNumberOfPoints(),
            "arrangement": sm.Fetch(arrangement).GetNumberOfCells(),
            "boolean": (sm.Fetch(boolean).GetNumberOfCells(), round(area(boolean), 9)),
            "one_step": (sm.Fetch(one).GetNumberOfCells(), round(area(one), 9),
                         sm.Fetch(one, idx=1).GetNumberOfPoints())}


expected, got = answers(whole), answers(pieces)
print("undistributed:", expected)
print("pieces read serially:", got)
if expected != got:
    raise SystemExit("the pieces read in one process differ from the undistributed surface")
print("same answers")
