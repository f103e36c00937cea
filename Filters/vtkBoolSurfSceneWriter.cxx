#include "vtkBoolSurfSceneWriter.h"

#include "vtkBoolSurfArrayNames.h"

#include "vtkBoolSurfTracedCurves.h" // for ForEachCurveCell

#include "Mesh/SurfacePoint.h"
#include "Scene/SceneJson.h"

#include "vtkAbstractArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <vector>

vtkStandardNewMacro(vtkBoolSurfSceneWriter);

namespace
{
namespace fs = std::filesystem;

/// A problem with the input, already worded for the user.
struct WriteError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// Polygon and shape indices become list positions in the file: an id far beyond the number
/// of curves would write millions of empty entries, so it is refused.
constexpr double LargestListIndex = 1 << 24;

bool IsIndex(double value, double largest = std::numeric_limits<int>::max())
{
  return value >= 0 && value <= largest && value == std::floor(value);
}

std::string CurveName(vtkIdType cellId)
{
  return "curve (cell) " + std::to_string(cellId);
}

std::string FieldString(vtkFieldData* fd, const char* name)
{
  auto* a = vtkStringArray::SafeDownCast(fd ? fd->GetAbstractArray(name) : nullptr);
  return a && a->GetNumberOfValues() > 0 ? a->GetValue(0) : std::string();
}

/// `mesh` relative to the scene's folder when it lies below it (the reader looks there first),
/// else as given.
std::string RelativeToScene(const std::string& mesh, const fs::path& scene)
{
  std::error_code ec;
  const fs::path folder = fs::absolute(scene, ec).parent_path();
  const fs::path target = fs::absolute(mesh, ec);
  if (ec)
  {
    return mesh;
  }
  const fs::path relative = target.lexically_relative(folder);
  if (relative.empty() || *relative.begin() == "..")
  {
    return mesh;
  }
  return relative.generic_string();
}

struct Curve
{
  vtkIdType CellId;
  std::vector<vtkIdType> Points;
  bool Closed;
  int Shape;
  int Type;
};

/// The `points` list, checked: every point must be a valid surface point for the reader.
std::vector<boolsurf::ScenePoint> PointsOf(vtkPolyData* input)
{
  vtkDataArray* triangleIds = input->GetPointData()->GetArray(boolsurf::names::TriangleId);
  vtkDataArray* barycentric = input->GetPointData()->GetArray(boolsurf::names::Barycentric);
  if (!triangleIds || !barycentric || barycentric->GetNumberOfComponents() != 2)
  {
    throw WriteError("the curves have no surface points: point data TriangleId and Barycentric "
                     "(2 components) are needed (the control points read from a scene, or the "
                     "curves of Trace Surface Curves, carry them)");
  }
  const vtkIdType n = input->GetNumberOfPoints();
  if (triangleIds->GetNumberOfTuples() < n || barycentric->GetNumberOfTuples() < n)
  {
    throw WriteError("point data TriangleId/Barycentric has fewer tuples than the " +
      std::to_string(n) + " points");
  }
  std::vector<boolsurf::ScenePoint> points(static_cast<std::size_t>(n));
  for (vtkIdType p = 0; p < n; ++p)
  {
    const double t = triangleIds->GetComponent(p, 0);
    if (!IsIndex(t))
    {
      throw WriteError("point " + std::to_string(p) + ": TriangleId " + std::to_string(t) +
        " is not a triangle index");
    }
    const double u = barycentric->GetComponent(p, 0), v = barycentric->GetComponent(p, 1);
    // Core's one tolerance, which the scene reader applies: a point outside it could not be
    // read back.
    if (!boolsurf::IsInsideTriangle(u, v))
    {
      throw WriteError("point " + std::to_string(p) + ": Barycentric (" + std::to_string(u) + ", " +
        std::to_string(v) + ") is outside its triangle (needs u, v >= 0, u + v <= 1)");
    }
    boolsurf::ScenePoint& point = points[static_cast<std::size_t>(p)];
    point.Face = static_cast<long long>(t);
    point.U = u;
    point.V = v;
  }
  return points;
}

/// Every line and polygon cell as a curve, closed the way the tracer reads it.
std::vector<Curve> CurvesOf(vtkPolyData* input)
{
  vtkDataArray* shapeIds = input->GetCellData()->GetArray(boolsurf::names::ShapeId);
  vtkDataArray* types = input->GetCellData()->GetArray(boolsurf::names::CurveType);
  vtkDataArray* triangleIds = input->GetPointData()->GetArray(boolsurf::names::TriangleId);
  vtkDataArray* barycentric = input->GetPointData()->GetArray(boolsurf::names::Barycentric);
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  std::vector<Curve> curves;
  boolsurf::ForEachCurveCell(input,
    [&](vtkIdType cellId, vtkIdType n, const vtkIdType* ids, bool polygon)
    {
      Curve c{ cellId, {}, polygon, static_cast<int>(cellId), 0 };
      if (shapeIds)
      {
        const double s = shapeIds->GetComponent(cellId, 0);
        if (!IsIndex(s, LargestListIndex))
        {
          throw WriteError(CurveName(cellId) + ": ShapeId " + std::to_string(s) +
            " is not an integer in [0, " + std::to_string(static_cast<long>(LargestListIndex)) +
            "]");
        }
        c.Shape = static_cast<int>(s);
      }
      if (types)
      {
        const double t = types->GetComponent(cellId, 0);
        if (t != 0 && t != 1)
        {
          throw WriteError(CurveName(cellId) + ": CurveType " + std::to_string(t) +
            " is neither 0 (geodesic polygon) nor 1 (cubic Bezier)");
        }
        c.Type = static_cast<int>(t);
      }
      for (vtkIdType i = 0; i < n; ++i)
      {
        if (ids[i] < 0 || ids[i] >= numberOfPoints)
        {
          throw WriteError(CurveName(cellId) + " names point id " + std::to_string(ids[i]) +
            ", outside [0, " + std::to_string(numberOfPoints) + ")");
        }
      }
      // The tracer's rule (vtkBoolSurfControlCurves): a polyline whose last point is its first
      // (same id or same surface point) is closed.
      if (!polygon && n >= 3)
      {
        const vtkIdType a = ids[0], b = ids[n - 1];
        if (a == b ||
          (triangleIds->GetComponent(a, 0) == triangleIds->GetComponent(b, 0) &&
            barycentric->GetComponent(a, 0) == barycentric->GetComponent(b, 0) &&
            barycentric->GetComponent(a, 1) == barycentric->GetComponent(b, 1)))
        {
          c.Closed = true;
          --n;
        }
      }
      if (n < 2)
      {
        throw WriteError(
          CurveName(cellId) + " has " + std::to_string(n) + " point(s): a curve needs at least 2");
      }
      c.Points.assign(ids, ids + n);
      curves.push_back(std::move(c));
    });
  if (curves.empty())
  {
    throw WriteError("the input holds no line or polygon cell: there is no curve to write");
  }
  return curves;
}

/// The pieces of each boundary loop (cell data BoundaryLoop, as BoolSurf's Boundary Control
/// Curves give them: consecutive cells, each starting where the previous one ends) joined into
/// one closed curve, so that the saved boundary bounds its region again. A loop mixing polygon
/// and Bezier pieces cannot be one curve: its pieces stay as they are, with a note.
std::vector<Curve> JoinLoops(vtkPolyData* input,
  std::vector<Curve> curves,
  std::vector<std::string>& notes)
{
  vtkDataArray* loopIds = input->GetCellData()->GetArray(boolsurf::names::BoundaryLoop);
  if (!loopIds)
  {
    return curves;
  }
  std::vector<Curve> out;
  for (std::size_t first = 0; first < curves.size();)
  {
    const double loop = loopIds->GetComponent(curves[first].CellId, 0);
    std::size_t end = first + 1;
    bool sameType = true;
    while (end < curves.size() && loopIds->GetComponent(curves[end].CellId, 0) == loop)
    {
      sameType = sameType && curves[end].Type == curves[first].Type;
      ++end;
    }
    if (!sameType || curves[first].Closed)
    {
      if (!sameType)
      {
        notes.push_back("boundary loop " + std::to_string(static_cast<long long>(loop)) +
          " mixes polygon and Bezier pieces: written as its " + std::to_string(end - first) +
          " open pieces");
      }
      out.insert(out.end(), curves.begin() + first, curves.begin() + end);
      first = end;
      continue;
    }
    Curve joined = curves[first];
    for (std::size_t k = first + 1; k < end; ++k)
    {
      joined.Points.insert(
        joined.Points.end(), curves[k].Points.begin() + 1, curves[k].Points.end());
    }
    joined.Points.pop_back(); // back where the loop started
    joined.Closed = true;
    out.push_back(std::move(joined));
    first = end;
  }
  return out;
}

/// Polygon index of every curve: its CurveId when the input has distinct ones, else k + 1.
std::vector<int> PolygonIndices(vtkPolyData* input, const std::vector<Curve>& curves)
{
  std::vector<int> index(curves.size());
  vtkDataArray* curveIds = input->GetCellData()->GetArray(boolsurf::names::CurveId);
  if (curveIds)
  {
    std::map<int, vtkIdType> seen;
    bool usable = true;
    for (std::size_t k = 0; k < curves.size() && usable; ++k)
    {
      const double id = curveIds->GetComponent(curves[k].CellId, 0);
      usable = IsIndex(id, LargestListIndex) && seen.emplace(static_cast<int>(id), k).second;
      index[k] = usable ? static_cast<int>(id) : 0;
    }
    if (usable)
    {
      return index;
    }
  }
  for (std::size_t k = 0; k < curves.size(); ++k)
  {
    index[k] = static_cast<int>(k) + 1;
  }
  return index;
}

/// `operations` from field data OperationA/B/Type (as the reader puts them), or none.
std::optional<std::vector<boolsurf::SceneOperation>> OperationsOf(vtkFieldData* fd)
{
  vtkDataArray* a = fd ? fd->GetArray(boolsurf::names::OperationA) : nullptr;
  vtkDataArray* b = fd ? fd->GetArray(boolsurf::names::OperationB) : nullptr;
  vtkDataArray* type = fd ? fd->GetArray(boolsurf::names::OperationType) : nullptr;
  if (!a || !b || !type)
  {
    return std::nullopt;
  }
  const vtkIdType n = a->GetNumberOfTuples();
  if (b->GetNumberOfTuples() != n || type->GetNumberOfTuples() != n)
  {
    throw WriteError("field data OperationA, OperationB and OperationType differ in length");
  }
  std::vector<boolsurf::SceneOperation> operations;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double va = a->GetComponent(i, 0), vb = b->GetComponent(i, 0),
                 vt = type->GetComponent(i, 0);
    if (!IsIndex(va) || !IsIndex(vb) || !IsIndex(vt, 3))
    {
      throw WriteError("operation " + std::to_string(i) +
        " is not {shape a, shape b, type 0..3}: " + std::to_string(va) + ", " + std::to_string(vb) +
        ", " + std::to_string(vt));
    }
    operations.push_back({ static_cast<int>(va), static_cast<int>(vb), static_cast<int>(vt) });
  }
  return operations;
}

} // namespace

//------------------------------------------------------------------------------
vtkBoolSurfSceneWriter::vtkBoolSurfSceneWriter() = default;

//------------------------------------------------------------------------------
vtkBoolSurfSceneWriter::~vtkBoolSurfSceneWriter() = default;

//------------------------------------------------------------------------------
int vtkBoolSurfSceneWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
void vtkBoolSurfSceneWriter::WriteData()
{
  this->WrittenMeshReference.clear();
  vtkPolyData* input = vtkPolyData::SafeDownCast(this->GetInput());
  if (this->FileName.empty())
  {
    vtkErrorMacro("No FileName: set the scene file (.json) to write.");
    return;
  }
  boolsurf::SceneModel scene;
  try
  {
    if (!input)
    {
      throw WriteError("no curves input (a vtkPolyData of control curves)");
    }
    // The file actually read resolves wherever the scene is saved; the original scene's
    // `model` only relative to the BoolSurf repository layout, so it comes last.
    std::string model = this->MeshReference;
    if (model.empty())
    {
      const std::string mesh = FieldString(input->GetFieldData(), boolsurf::names::MeshFileName);
      model = mesh.empty() ? mesh : RelativeToScene(mesh, this->FileName);
    }
    if (model.empty())
    {
      model = FieldString(input->GetFieldData(), boolsurf::names::SceneModel);
    }
    if (model.empty())
    {
      throw WriteError("no mesh reference: set MeshReference to the mesh file the curves lie on "
                       "(the input has no field data SceneModel or MeshFileName to take it from)");
    }
    scene.Model = model;
    scene.Points = PointsOf(input);
    this->UpdateProgress(0.5);
    std::vector<std::string> notes;
    const std::vector<Curve> curves =
      this->JoinBoundaryLoops ? JoinLoops(input, CurvesOf(input), notes) : CurvesOf(input);
    for (const std::string& note : notes)
    {
      vtkWarningMacro("BoolSurf scene " << this->FileName << ": " << note);
    }
    // Polygons and shapes are numbered from the curves; the emitter sizes `polygons` and
    // `shapes` by the largest of them.
    const std::vector<int> polygonOf = PolygonIndices(input, curves);
    for (std::size_t k = 0; k < curves.size(); ++k)
    {
      boolsurf::ScenePolygon polygon;
      polygon.Index = polygonOf[k];
      polygon.Points.assign(curves[k].Points.begin(), curves[k].Points.end());
      polygon.Closed = curves[k].Closed;
      polygon.CurveType = curves[k].Type;
      polygon.Shape = curves[k].Shape;
      scene.Polygons.push_back(std::move(polygon));
    }
    scene.Operations = OperationsOf(input->GetFieldData());
  }
  catch (const WriteError& e)
  {
    vtkErrorMacro("BoolSurf scene " << this->FileName << ": " << e.what() << "; nothing written");
    this->SetErrorCode(vtkErrorCode::UserError);
    return;
  }
  // Written to a temporary file first: a failed write never leaves half a scene.
  const fs::path target(this->FileName);
  const fs::path temporary = target.string() + ".part";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << boolsurf::EmitSceneJson(scene, this->Indent);
    if (!out)
    {
      vtkErrorMacro("BoolSurf scene " << this->FileName << ": cannot write the file");
      this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
      std::error_code ec;
      fs::remove(temporary, ec);
      return;
    }
  }
  std::error_code ec;
  fs::rename(temporary, target, ec);
  if (ec)
  {
    vtkErrorMacro(
      "BoolSurf scene " << this->FileName << ": cannot write the file (" << ec.message() << ")");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    fs::remove(temporary, ec);
    return;
  }
  this->WrittenMeshReference = scene.Model;
  this->UpdateProgress(1.0);
}

//------------------------------------------------------------------------------
void vtkBoolSurfSceneWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "MeshReference: " << this->MeshReference << "\n";
  os << indent << "Indent: " << this->Indent << "\n";
  os << indent << "JoinBoundaryLoops: " << this->JoinBoundaryLoops << "\n";
}
