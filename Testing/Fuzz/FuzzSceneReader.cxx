// libFuzzer target: vtkBoolSurfSceneReader on a scene (.json) and the mesh it references.
//
// Input: the scene text, optionally followed by a line "#mesh" and the mesh file's bytes.
// The scene is written to scene.json in a private folder, the mesh bytes (or, without a
// "#mesh" part, a valid ascii PLY of a 2 x 2 square) to mesh.ply and mesh.obj beside it, so
// scenes naming "model": "mesh.ply" or "mesh.obj" find them. Every input must end in outputs
// or a reported error (then with empty outputs). Where there is output, the curves must
// reference the mesh consistently: point ids of the polylines exist, TriangleId names a
// triangle of the output mesh, Barycentric lies in it, one ShapeId per curve.
#include "FuzzSupport.h"
#include "vtkBoolSurfSceneReader.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <cmath>
#include <cstring>
#include <string>

namespace
{
using namespace boolsurf;

const char* const DefaultMesh = "ply\nformat ascii 1.0\nelement vertex 9\nproperty float x\n"
                                "property float y\nproperty float z\nelement face 8\n"
                                "property list uchar int vertex_indices\nend_header\n"
                                "0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n"
                                "3 0 1 4\n3 0 4 3\n3 1 2 5\n3 1 5 4\n3 3 4 7\n3 3 7 6\n"
                                "3 4 5 8\n3 4 8 7\n";

void CountError(vtkObject*, unsigned long, void* clientData, void*)
{
  ++*static_cast<int*>(clientData);
}

void CheckOutputs(vtkPolyData* mesh, vtkPolyData* curves)
{
  const vtkIdType triangles = mesh->GetNumberOfPolys();
  const vtkIdType points = curves->GetNumberOfPoints();
  BOOLSURF_FUZZ_CHECK(triangles > 0, "curves without a mesh");
  vtkDataArray* triangleId = curves->GetPointData()->GetArray("TriangleId");
  vtkDataArray* barycentric = curves->GetPointData()->GetArray("Barycentric");
  BOOLSURF_FUZZ_CHECK(triangleId && barycentric, "TriangleId and Barycentric arrays");
  BOOLSURF_FUZZ_CHECK(
    triangleId->GetNumberOfTuples() == points && barycentric->GetNumberOfTuples() == points,
    "one TriangleId and Barycentric per point");
  for (vtkIdType p = 0; p < points; ++p)
  {
    const double t = triangleId->GetComponent(p, 0);
    BOOLSURF_FUZZ_CHECK(t >= 0 && t < triangles,
      "point " + std::to_string(p) + " on triangle " + std::to_string(t) + " of " +
        std::to_string(triangles));
    const double u = barycentric->GetComponent(p, 0), v = barycentric->GetComponent(p, 1);
    BOOLSURF_FUZZ_CHECK(u >= 0 && v >= 0 && u + v <= 1 + 1e-12,
      "point " + std::to_string(p) + " at (" + std::to_string(u) + ", " + std::to_string(v) + ")");
  }
  vtkCellArray* lines = curves->GetLines();
  BOOLSURF_FUZZ_CHECK(lines->GetNumberOfCells() > 0, "a scene read without error has a curve");
  vtkDataArray* shape = curves->GetCellData()->GetArray("ShapeId");
  BOOLSURF_FUZZ_CHECK(
    shape && shape->GetNumberOfTuples() == curves->GetNumberOfCells(), "one ShapeId per curve");
  for (vtkIdType c = 0; c < shape->GetNumberOfTuples(); ++c)
  {
    BOOLSURF_FUZZ_CHECK(shape->GetComponent(c, 0) >= 0, "negative ShapeId");
  }
  const vtkIdType* ids = nullptr;
  vtkIdType n = 0;
  for (lines->InitTraversal(); lines->GetNextCell(n, ids);)
  {
    BOOLSURF_FUZZ_CHECK(n >= 2, "a curve of " + std::to_string(n) + " point(s)");
    for (vtkIdType i = 0; i < n; ++i)
    {
      BOOLSURF_FUZZ_CHECK(ids[i] >= 0 && ids[i] < points, "curve point id");
    }
  }
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  // Errors are counted through ErrorEvent (which vtkErrorMacro only sends while warnings are
  // displayed), not printed.
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::string separator = "\n#mesh\n";
  const std::size_t split = input.find(separator);
  const std::string scene = input.substr(0, split);
  const std::string meshBytes =
    split == std::string::npos ? DefaultMesh : input.substr(split + separator.size());
  const std::string& folder = fuzz::ScratchFolder();
  fuzz::WriteFile(folder + "/scene.json", scene.data(), scene.size());
  fuzz::WriteFile(folder + "/mesh.ply", meshBytes.data(), meshBytes.size());
  fuzz::WriteFile(folder + "/mesh.obj", meshBytes.data(), meshBytes.size());

  vtkNew<vtkBoolSurfSceneReader> reader;
  int errors = 0;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(CountError);
  onError->SetClientData(&errors);
  reader->AddObserver(vtkCommand::ErrorEvent, onError);
  reader->SetFileName((folder + "/scene.json").c_str());
  reader->SetMeshSearchPath(folder.c_str());
  reader->SetScreenSpaceResolution(8); // screen-space scenes: a small grid is enough
  reader->Update();
  vtkPolyData* mesh = reader->GetOutput(0);
  vtkPolyData* curves = reader->GetOutput(1);
  if (errors > 0)
  {
    BOOLSURF_FUZZ_CHECK(mesh->GetNumberOfPoints() == 0 && curves->GetNumberOfPoints() == 0,
      "a failed read leaves empty outputs");
    return 0;
  }
  CheckOutputs(mesh, curves);
  return 0;
}
