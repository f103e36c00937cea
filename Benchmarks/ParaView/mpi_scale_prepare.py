"""The inputs of mpi_scale.py, made once per mesh: the surface with point and cell GlobalIds as
one file (the one-rank run reads it) and as a partitioned file of P pieces (P ranks each read
their own piece, so no rank ever reads the whole surface), and the scenes' curves.

    pvpython mpi_scale_prepare.py --mesh M.ply [--subdivide 1] --out DIR/NAME --whole
        writes DIR/NAME.vtp (global ids in the mesh's order) and, for each --scene, the
        placed curves DIR/NAME-<scene>.json (paper_scale_scene.py; placed on the whole mesh)
    mpiexec -np P pvbatch mpi_scale_prepare.py --out DIR/NAME --pieces
        reads DIR/NAME.vtp on rank 0, splits it with RedistributeDataSet (P pieces) and writes
        DIR/NAME-P.pvtp (its pieces DIR/NAME-P/NAME-P_<rank>.vtp)

Subdivision is VTK's vtkLinearSubdivisionFilter (1-to-4 midpoint), as the 4.3M benchmark of
Benchmarks/VTK/BenchmarkFilterEdits.cxx makes igea_1m subdivided once.
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from vtkmodules.vtkFiltersParallelDIY2 import vtkGenerateGlobalIds  # noqa: E402
from vtkmodules.vtkFiltersModeling import vtkLinearSubdivisionFilter  # noqa: E402
from vtkmodules.vtkIOPLY import vtkPLYReader  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter  # noqa: E402


def whole(args):
    from paper_scale_scene import scene_versions
    reader = vtkPLYReader()
    reader.SetFileName(args.mesh)
    reader.Update()
    mesh = reader.GetOutput()
    if args.subdivide:
        subdivide = vtkLinearSubdivisionFilter()
        subdivide.SetInputData(mesh)
        subdivide.SetNumberOfSubdivisions(args.subdivide)
        subdivide.Update()
        mesh = subdivide.GetOutput()
    ids = vtkGenerateGlobalIds()
    ids.SetInputData(mesh)
    ids.Update()
    mesh = ids.GetOutput()
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(args.out + ".vtp")
    writer.SetDataModeToAppended()
    writer.EncodeAppendedDataOff()
    writer.Write()
    print("%s.vtp: %d triangles, %d points" % (args.out, mesh.GetNumberOfCells(),
                                                mesh.GetNumberOfPoints()))
    for scene in args.scene:
        versions = scene_versions(mesh, scene, "%s-%s.json" % (args.out, scene))
        print("%s-%s.json: %d curves" % (args.out, scene, len(versions[0][3])))


def pieces(args):
    from paraview.simple import ExtractSurface, RedistributeDataSet, SaveData, XMLPolyDataReader
    from vtkmodules.vtkParallelCore import vtkMultiProcessController
    ranks = vtkMultiProcessController.GetGlobalController().GetNumberOfProcesses()
    surface = XMLPolyDataReader(FileName=[args.out + ".vtp"])
    split = ExtractSurface(Input=RedistributeDataSet(Input=surface))
    split.UpdatePipeline()
    path = "%s-%d.pvtp" % (args.out, ranks)
    SaveData(path, proxy=split, DataMode="Appended", EncodeAppendedData=0,
             CompressorType="None")
    print("%s: %d pieces, %d triangles" % (path, ranks,
                                           split.GetDataInformation().GetNumberOfCells()))


parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--mesh")
parser.add_argument("--subdivide", type=int, default=0)
parser.add_argument("--out", required=True, help="DIR/NAME of the files written")
parser.add_argument("--scene", action="append", default=[], choices=("ten", "paper"))
parser.add_argument("--whole", action="store_true")
parser.add_argument("--pieces", action="store_true")
args = parser.parse_args()
if args.whole:
    whole(args)
if args.pieces:
    pieces(args)
