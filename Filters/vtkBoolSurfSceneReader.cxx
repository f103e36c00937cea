#include "vtkBoolSurfSceneReader.h"

#include "vtkBoolSurfArrayNames.h"

#include "vtkBoolSurfControlCurveWriter.h"
#include "vtkBoolSurfRankGather.h"

#include "Mesh/ObjCheck.h"
#include "Mesh/PlyReader.h"
#include "Scene/SceneCurves.h"
#include "Scene/SceneJson.h"
#include "Scene/SceneMeshLookup.h"
#include "Scene/ScenePlacement.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkObjectFactory.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

vtkStandardNewMacro(vtkBoolSurfSceneReader);

namespace
{
namespace fs = std::filesystem;

std::string Lower(std::string s)
{
  std::transform(s.begin(),
    s.end(),
    s.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// Reads a PLY or OBJ mesh and triangulates it the BoolSurf/Yocto way; null, with `error`
/// saying why, when the file is not a mesh.
vtkSmartPointer<vtkPolyData> ReadMesh(const fs::path& file, std::string& note, std::string& error)
{
  const std::string ext = Lower(file.extension().string());
  vtkSmartPointer<vtkPolyData> raw;
  if (ext == ".ply")
  {
    // vtkPLYReader aborts or crashes on truncated and garbage files: the checked reader sees
    // the file first.
    boolsurf::MeshData checked;
    std::string why;
    if (!boolsurf::ReadPly(file.string(), checked, why))
    {
      error = "mesh " + file.string() + " is not a valid PLY file: " + why;
      return nullptr;
    }
    vtkNew<vtkPLYReader> reader;
    reader->SetFileName(file.string().c_str());
    reader->Update();
    raw = reader->GetOutput();
  }
  else if (ext == ".obj")
  {
    // vtkOBJReader crashes on an index that names nothing: the indices are checked first.
    std::string why;
    if (!boolsurf::CheckObjIndices(file.string(), why))
    {
      error = "mesh " + file.string() + " is not a valid OBJ file: " + why;
      return nullptr;
    }
    vtkNew<vtkOBJReader> reader;
    reader->SetFileName(file.string().c_str());
    reader->Update();
    raw = reader->GetOutput();
  }
  else
  {
    error = "mesh " + file.string() + " is neither a .ply nor an .obj file";
    return nullptr;
  }
  if (!raw || raw->GetNumberOfPolys() == 0)
  {
    error = "mesh " + file.string() + " holds no triangle (unreadable or empty)";
    return nullptr;
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(raw->GetPoints());
  mesh->GetPointData()->ShallowCopy(raw->GetPointData());
  vtkNew<vtkCellArray> triangles;
  vtkCellData* inCD = raw->GetCellData();
  vtkCellData* outCD = mesh->GetCellData();
  outCD->CopyAllocate(inCD, raw->GetNumberOfPolys());
  const vtkIdType firstPoly = raw->GetNumberOfVerts() + raw->GetNumberOfLines();
  vtkIdType cellId = firstPoly, n = 0, out = 0, split = 0;
  const vtkIdType* ids = nullptr;
  vtkCellArray* polys = raw->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids); ++cellId)
  {
    if (n == 3)
    {
      triangles->InsertNextCell({ ids[0], ids[1], ids[2] });
      outCD->CopyData(inCD, cellId, out++);
    }
    else if (n == 4) // Yocto: (a,b,c,d) -> (a,b,d), (c,d,b)
    {
      triangles->InsertNextCell({ ids[0], ids[1], ids[3] });
      outCD->CopyData(inCD, cellId, out++);
      triangles->InsertNextCell({ ids[2], ids[3], ids[1] });
      outCD->CopyData(inCD, cellId, out++);
      ++split;
    }
    else if (n > 4) // not BoolSurf's format: a fan, so that the face numbering stays defined
    {
      for (vtkIdType k = 1; k + 1 < n; ++k)
      {
        triangles->InsertNextCell({ ids[0], ids[k], ids[k + 1] });
        outCD->CopyData(inCD, cellId, out++);
      }
      ++split;
    }
  }
  mesh->SetPolys(triangles);
  if (split > 0)
  {
    note = std::to_string(split) + " polygon(s) of " + file.string() +
      " were split into triangles (quads as (a,b,d),(c,d,b), like BoolSurf)";
  }
  return mesh;
}

/// The triangles of `mesh` (as ReadMesh leaves it: triangles only) for Core's placement.
boolsurf::MeshData ToMeshData(vtkPolyData* mesh)
{
  boolsurf::MeshData out;
  vtkPoints* points = mesh->GetPoints();
  out.Positions.resize(static_cast<std::size_t>(mesh->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    out.Positions[static_cast<std::size_t>(i)] = { x[0], x[1], x[2] };
  }
  out.Triangles.reserve(static_cast<std::size_t>(mesh->GetNumberOfPolys()));
  vtkCellArray* triangles = mesh->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (triangles->InitTraversal(); triangles->GetNextCell(n, ids);)
  {
    out.Triangles.push_back(
      { static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) });
  }
  return out;
}

/// Core's flat grid as the mesh output, with the normals (0, 0, 1) of a surface in z = 0.
vtkSmartPointer<vtkPolyData> GridPolyData(const boolsurf::MeshData& grid)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(grid.Positions.size()));
  vtkNew<vtkDoubleArray> normals;
  normals->SetName(boolsurf::names::Normals);
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(static_cast<vtkIdType>(grid.Positions.size()));
  for (std::size_t i = 0; i < grid.Positions.size(); ++i)
  {
    const boolsurf::Vec3& x = grid.Positions[i];
    points->SetPoint(static_cast<vtkIdType>(i), x.x, x.y, x.z);
    normals->SetTuple3(static_cast<vtkIdType>(i), 0, 0, 1);
  }
  vtkNew<vtkCellArray> triangles;
  triangles->AllocateExact(static_cast<vtkIdType>(grid.Triangles.size()),
    3 * static_cast<vtkIdType>(grid.Triangles.size()));
  for (const std::array<int, 3>& t : grid.Triangles)
  {
    triangles->InsertNextCell({ t[0], t[1], t[2] });
  }
  pd->SetPoints(points);
  pd->SetPolys(triangles);
  pd->GetPointData()->SetNormals(normals);
  return pd;
}

vtkSmartPointer<vtkIntArray> IntArray(const char* name, const std::vector<int>& values)
{
  auto a = vtkSmartPointer<vtkIntArray>::New();
  a->SetName(name);
  a->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    a->SetValue(static_cast<vtkIdType>(i), values[i]);
  }
  return a;
}

void AddString(vtkFieldData* fd, const char* name, const std::string& value)
{
  vtkNew<vtkStringArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  fd->AddArray(a);
}

/// The curves output of a placed scene: its control curves (SceneControlCurves) through the
/// one writer of control-curve arrays, each point at its placed position and with cell data
/// CurveId; the operations as field data.
vtkSmartPointer<vtkPolyData> CurvesPolyData(const boolsurf::SceneModel& scene)
{
  // Every point comes with its placed position: the writer computes none.
  boolsurf::ControlCurveWriter writer(boolsurf::ControlCurveWriter::PositionOf(), nullptr, true);
  const std::vector<boolsurf::ControlCurve> curves = boolsurf::SceneControlCurves(scene);
  std::vector<boolsurf::Vec3> positions;
  for (std::size_t c = 0; c < curves.size(); ++c)
  {
    positions.clear();
    for (int id : scene.Polygons[c].Points)
    {
      positions.push_back(scene.Points[static_cast<std::size_t>(id)].Position);
    }
    writer.Add(curves[c], positions);
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  writer.Write(pd);
  // Never an empty numeric field array (VTK's XML writer cannot read it back).
  if (scene.Operations && !scene.Operations->empty())
  {
    std::vector<int> a, b, type;
    for (const boolsurf::SceneOperation& o : *scene.Operations)
    {
      a.push_back(o.A);
      b.push_back(o.B);
      type.push_back(o.Type);
    }
    pd->GetFieldData()->AddArray(IntArray(boolsurf::names::OperationA, a));
    pd->GetFieldData()->AddArray(IntArray(boolsurf::names::OperationB, b));
    pd->GetFieldData()->AddArray(IntArray(boolsurf::names::OperationType, type));
  }
  return pd;
}
} // namespace

//------------------------------------------------------------------------------
vtkBoolSurfSceneReader::vtkBoolSurfSceneReader()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkBoolSurfSceneReader::~vtkBoolSurfSceneReader() = default;

//------------------------------------------------------------------------------
int vtkBoolSurfSceneReader::CanReadFile(const char* fileName)
{
  if (!fileName)
  {
    return 0;
  }
  std::ifstream in(fileName, std::ios::binary);
  return in && boolsurf::LooksLikeSceneJson(in) ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkBoolSurfSceneReader::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkPolyData* meshOut = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* curvesOut = vtkPolyData::GetData(outputVector, 1);
  this->ResolvedMeshFileName.clear();
  if (this->FileName.empty())
  {
    vtkErrorMacro("No FileName: set the BoolSurf scene (.json) to read.");
    return vtkBoolSurfErrorReported;
  }
  const fs::path file(this->FileName);
  vtkSmartPointer<vtkPolyData> mesh, curves;
  std::string meshFile, model;
  std::vector<std::string> notes;
  std::string error;
  // Core's Scene functions return false with a message; the readers VTK calls may still throw.
  const auto readScene = [&]() -> bool
  {
    std::ifstream in(file, std::ios::binary);
    if (!in)
    {
      error = "cannot open the file";
      return false;
    }
    // The mesh is read once the scene's curves are checked, before its points are: faces are
    // checked against it in the file's order (SceneParseOptions::FindMesh).
    boolsurf::SceneParseOptions options;
    options.ReadModel = this->MeshFileName.empty();
    std::string meshNote;
    options.FindMesh =
      [&](const boolsurf::SceneModel& scene, boolsurf::SceneMeshInfo& info, std::string& findError)
    {
      this->UpdateProgress(0.1);
      fs::path found;
      if (!boolsurf::FindSceneMesh(
            file, this->MeshFileName, scene.Model, this->MeshSearchPath, found, findError))
      {
        return false;
      }
      mesh = ReadMesh(found, meshNote, findError);
      if (!mesh)
      {
        return false;
      }
      meshFile = found.string();
      info = boolsurf::SceneMeshInfo{ mesh->GetNumberOfPolys(), meshFile };
      return true;
    };
    boolsurf::SceneModel scene;
    if (!boolsurf::ParseSceneJson(in, scene, error, options))
    {
      return false;
    }
    if (scene.ScreenSpace)
    {
      this->UpdateProgress(0.1);
      boolsurf::MeshData grid;
      if (!boolsurf::PlaceScreenSpaceScene(scene, this->ScreenSpaceResolution, grid, error))
      {
        return false;
      }
      mesh = GridPolyData(grid);
    }
    else if (!boolsurf::PlaceScenePoints(scene, ToMeshData(mesh), meshFile, error))
    {
      return false;
    }
    curves = CurvesPolyData(scene);
    notes = scene.Notes;
    if (!meshNote.empty())
    {
      notes.push_back(meshNote);
    }
    model = scene.Model;
    return true;
  };
  bool read = false;
  try
  {
    read = readScene();
  }
  catch (const std::exception& e)
  {
    error = e.what();
  }
  if (!read)
  {
    vtkErrorMacro("BoolSurf scene " << this->FileName << ": " << error);
    return 1; // empty outputs
  }
  for (const std::string& note : notes)
  {
    vtkWarningMacro("BoolSurf scene " << this->FileName << ": " << note);
  }
  this->ResolvedMeshFileName = meshFile;
  meshOut->ShallowCopy(mesh);
  curvesOut->ShallowCopy(curves);
  for (vtkPolyData* pd : { meshOut, curvesOut })
  {
    AddString(pd->GetFieldData(), boolsurf::names::SceneFileName, this->FileName);
    if (!meshFile.empty())
    {
      AddString(pd->GetFieldData(), boolsurf::names::MeshFileName, meshFile);
    }
    if (!model.empty())
    {
      AddString(pd->GetFieldData(), boolsurf::names::SceneModel, model);
    }
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkBoolSurfSceneReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "MeshFileName: " << this->MeshFileName << "\n";
  os << indent << "MeshSearchPath: " << this->MeshSearchPath << "\n";
  os << indent << "ScreenSpaceResolution: " << this->ScreenSpaceResolution << "\n";
  os << indent << "ResolvedMeshFileName: " << this->ResolvedMeshFileName << "\n";
}
