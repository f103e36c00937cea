"""Check Surface on surfaces split across MPI ranks, its outputs written as JSON: run by
TestPython3MpiPieces.py with pvbatch on 1 to 4 ranks, whose answers must agree per global
cell id (each rank checks its own piece; nothing is gathered).

    mpiexec -np N pvbatch Testing/Python/MpiPieces.py --json out.json [--scan mesh.ply]
        [--pvtp pieces.pvtp]

Surfaces: a sphere, a sphere with an open cap (one boundary loop), a torus, Data/eight.ply
(genus 2) and optionally a shared scan; each gets global ids in its serial order
(GenerateGlobalIds), then RedistributeDataSet and Extract Surface split it across the ranks.
Also: a rank with no triangles (fewer partitions than ranks), pieces with ghost cells (cells on
a cut copied to every region they touch), pieces without global ids (generated, with a warning) and overlapping pieces without ghost marks (every rank holds the
whole surface: a clear error, no hang). --pvtp writes eight.ply's pieces as a partitioned file.
"""
import argparse
import json
import os
import sys
import tempfile

source_dir = os.environ.get("BOOLSURF_SOURCE_DIR",
                            os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(source_dir, "Examples"))
sys.path.insert(0, os.path.join(source_dir, "Testing", "Python"))
from boolsurf_example_utils import load_plugin, ranks  # noqa: E402
from torus_mesh import torus_polydata  # noqa: E402
from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager as sm  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkSphereSource  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkTriangleFilter  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--json", required=True)
parser.add_argument("--scan")
parser.add_argument("--pvtp")
args = parser.parse_args()
load_plugin(globals())
folder = tempfile.mkdtemp(prefix="boolsurf-pieces-")


def written(name, pd):
    """A serial reader of `pd` (its data on the first rank only, as a file's)."""
    path = os.path.join(folder, name + ".vtp")
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(pd)
    writer.Write()
    return XMLPolyDataReader(FileName=[path])


def sphere(end_phi=180.0):
    source = vtkSphereSource()
    source.SetThetaResolution(40)
    source.SetPhiResolution(30)
    source.SetEndPhi(end_phi)
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(source.GetOutputPort())
    triangles.Update()
    return triangles.GetOutput()


# A filter run on every rank: the field data of its rank's output as a cell array, so that the
# fetched union shows whether every rank has the same field data.
DIGEST = """
import zlib
from vtkmodules.vtkCommonCore import vtkIntArray
inp = self.GetInput()
out = self.GetOutput()
out.ShallowCopy(inp)
fd = inp.GetFieldData()
text = ""
for i in range(fd.GetNumberOfArrays()):
    a = fd.GetAbstractArray(i)
    values = [a.GetVariantValue(j).ToString() for j in range(a.GetNumberOfValues())]
    if a.GetName() == "BoundaryLoopLength":
        values = ["%.9g" % float(v) for v in values]
    text += a.GetName() + repr(values)
digest = vtkIntArray()
digest.SetName("FieldDigest")
digest.SetNumberOfTuples(out.GetNumberOfCells())
digest.Fill(zlib.crc32(text.encode()) & 0x7fffffff)
out.GetCellData().AddArray(digest)
"""


# The ghost cells of a rank's piece, as cells (the fetched union counts them over ranks).
GHOSTS = """
inp = self.GetInput()
out = self.GetOutput()
ghosts = inp.GetCellGhostArray()
ids = [c for c in range(inp.GetNumberOfCells()) if ghosts and ghosts.GetValue(c)]
out.SetPoints(inp.GetPoints())
out.Allocate(len(ids))
for c in ids:
    out.InsertNextCell(inp.GetCellType(c), inp.GetCell(c).GetPointIds())
"""


def checked(surface, ids=True):
    check = CheckSurface(Input=surface)
    data = sm.Fetch(ProgrammableFilter(Input=check, Script=DIGEST))
    field = {}
    fd = data.GetFieldData()
    for i in range(fd.GetNumberOfArrays()):
        a = fd.GetAbstractArray(i)
        field[a.GetName()] = [a.GetVariantValue(j).ToString() for j in range(a.GetNumberOfValues())]
    field["BoundaryLoopLength"] = [float(v) for v in field.get("BoundaryLoopLength", [])]
    result = {"field": field, "triangles": data.GetNumberOfCells()}
    digests = data.GetCellData().GetArray("FieldDigest")
    result["digests"] = len({digests.GetValue(i) for i in range(digests.GetNumberOfTuples())}) \
        if digests else 0
    if ids:
        gids = data.GetCellData().GetArray("GlobalCellIds")
        comp = data.GetCellData().GetArray("ComponentId")
        result["components"] = {str(int(gids.GetTuple1(c))): comp.GetValue(c)
                                for c in range(data.GetNumberOfCells())}
        loops = data.GetPointData().GetArray("BoundaryLoopId")
        by_point = {}
        for p in range(data.GetNumberOfPoints()):
            by_point.setdefault("%r" % (data.GetPoint(p),), set()).add(loops.GetValue(p))
        result["loops"] = {k: sorted(v) for k, v in by_point.items()}
    return result


def distributed(reader, partitions=None, ids=True, ghosts=False):
    source = GenerateGlobalIds(Input=reader) if ids else reader
    redistributed = RedistributeDataSet(Input=source)
    if partitions:
        redistributed.NumberOfPartitions = partitions
    surface = ExtractSurface(Input=redistributed)
    if ghosts:
        # A layer of the neighbours' cells on each piece, marked as ghost cells.
        surface = GhostCellsGenerator(Input=surface, BuildIfRequired=0)
    return surface


eight = PLYReader(FileNames=[os.path.join(source_dir, "Data", "eight.ply")])
meshes = {"sphere": written("sphere", sphere()), "open_sphere": written("open", sphere(140.0)),
          "torus": written("torus", torus_polydata(1.0, 0.35, 48, 20)), "eight": eight}
if args.scan:
    meshes["scan"] = PLYReader(FileNames=[args.scan])
results = {"ranks": ranks()}
for name, reader in meshes.items():
    results[name] = checked(distributed(reader))
if ranks() >= 3:
    # Ranks with no triangles: two partitions on three ranks or more.
    results["empty_rank"] = checked(distributed(eight, partitions=2))
    pieces = sm.Fetch(ProcessIdScalars(Input=distributed(eight, partitions=2)))
    held = pieces.GetPointData().GetArray("ProcessId")
    results["empty_rank"]["holding"] = len({held.GetValue(i)
                                            for i in range(held.GetNumberOfTuples())})
    results["empty_rank_no_ids"] = checked(distributed(eight, partitions=2, ids=False),
                                           ids=False)
results["no_ids"] = checked(distributed(eight, ids=False), ids=False)
results["ghosts"] = checked(distributed(eight, ghosts=True))
ghost_counts = sm.Fetch(ProgrammableFilter(Input=distributed(eight, ghosts=True), Script=GHOSTS))
results["ghosts"]["ghost_cells"] = ghost_counts.GetNumberOfCells()

# Every rank holds the whole surface with the same global ids: overlapping pieces.
WHOLE = """
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkCommonCore import vtkIdTypeArray
reader = vtkPLYReader()
reader.SetFileName(%r)
reader.Update()
out = self.GetOutput()
out.ShallowCopy(reader.GetOutput())
ids = vtkIdTypeArray()
ids.SetName("GlobalCellIds")
for c in range(out.GetNumberOfCells()):
    ids.InsertNextValue(c)
out.GetCellData().SetGlobalIds(ids)
""" % os.path.join(source_dir, "Data", "eight.ply")
overlap = CheckSurface(Input=ProgrammableSource(OutputDataSetType="vtkPolyData", Script=WHOLE))
results["overlap"] = {"triangles": sm.Fetch(overlap).GetNumberOfCells()}

if args.pvtp:
    SaveData(args.pvtp, proxy=distributed(eight, ids=False))
with open(args.json, "w") as f:
    json.dump(results, f, indent=1, sort_keys=True)
print("done", ranks())
