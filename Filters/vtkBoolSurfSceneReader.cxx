#include "vtkBoolSurfSceneReader.h"

#include "vtkBoolSurfArrayNames.h"

#include "vtkBoolSurfRankGather.h"

#include "Mesh/ObjCheck.h"
#include "Mesh/PlyReader.h"
#include "Mesh/SurfacePoint.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
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
#include "vtkUnsignedCharArray.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <climits>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkBoolSurfSceneReader);

namespace
{
namespace fs = std::filesystem;
// Objects keep their keys in document order (NumberSpellings counts numbers in that order).
using json = nlohmann::ordered_json;

/// A problem with the scene, already worded for the user (the file name is added later).
struct SceneError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// Tolerance on barycentric coordinates: values within it of the triangle are clamped.
constexpr double UVTolerance = 1e-6;

/// The renamed copies of the shared mesh collection (boolsurf-scenes/README.md, "Scene → mesh
/// map"): scene base name → file name in ../meshes.
const std::map<std::string, std::string>& RenamedMeshes()
{
  static const std::map<std::string, std::string> names = {
    { "eight200k-remeshed.ply", "eight_200k.ply" },
    { "3Torus_200k.ply", "3torus_200k.ply" },
    { "bunny.ply", "bunny_boolsurf.ply" },
    { "cow_notsolowpoly.ply", "spot.ply" },
  };
  return names;
}

std::string Lower(std::string s)
{
  std::transform(s.begin(),
    s.end(),
    s.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// `model` with '\' turned into '/' and leading "./" removed.
std::string NormalizeModelPath(std::string model)
{
  std::replace(model.begin(), model.end(), '\\', '/');
  while (model.rfind("./", 0) == 0)
  {
    model.erase(0, 2);
  }
  return model;
}

std::vector<std::string> SplitSearchPath(const std::string& path)
{
  std::vector<std::string> dirs;
  std::string current;
  for (char c : path)
  {
    if (c == ';' || c == ':')
    {
      if (!current.empty())
      {
        dirs.push_back(current);
      }
      current.clear();
    }
    else
    {
      current += c;
    }
  }
  if (!current.empty())
  {
    dirs.push_back(current);
  }
  return dirs;
}

bool IsFile(const fs::path& p)
{
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

/// Every place the mesh may be, in the documented order (duplicates removed).
std::vector<fs::path> MeshCandidates(const fs::path& sceneFile,
  const std::string& override,
  const std::string& model,
  const std::string& searchPath)
{
  std::vector<fs::path> out;
  auto add = [&](const fs::path& p)
  {
    const fs::path q = p.lexically_normal();
    if (std::find(out.begin(), out.end(), q) == out.end())
    {
      out.push_back(q);
    }
  };
  const fs::path sceneDir =
    sceneFile.parent_path().empty() ? fs::path(".") : sceneFile.parent_path();
  if (!override.empty())
  {
    const fs::path o(override);
    if (o.is_relative())
    {
      add(sceneDir / o);
    }
    add(o);
    return out;
  }
  const fs::path rel(NormalizeModelPath(model));
  const std::string base = rel.filename().string();
  std::vector<std::string> names = { base };
  auto renamed = RenamedMeshes().find(base);
  if (renamed != RenamedMeshes().end())
  {
    names.push_back(renamed->second);
  }
  // The scene's folder and its ancestors (BoolSurf's paths are relative to its repository
  // root, which is an ancestor of the scene file in the original layout).
  std::vector<fs::path> ancestors;
  fs::path abs = fs::absolute(sceneDir).lexically_normal();
  for (fs::path a = abs;; a = a.parent_path())
  {
    ancestors.push_back(a);
    if (a == a.parent_path() || ancestors.size() > 8)
    {
      break;
    }
  }
  if (rel.is_absolute())
  {
    add(rel);
  }
  for (const fs::path& a : ancestors)
  {
    add(a / rel);
  }
  for (const std::string& n : names)
  {
    add(sceneDir / n);
  }
  for (const std::string& dir : SplitSearchPath(searchPath))
  {
    add(fs::path(dir) / rel);
    for (const std::string& n : names)
    {
      add(fs::path(dir) / n);
    }
  }
  for (const fs::path& a : ancestors)
  {
    for (const std::string& n : names)
    {
      add(a / "meshes" / n);
    }
  }
  return out;
}

/// Reads a PLY or OBJ mesh and triangulates it the BoolSurf/Yocto way.
vtkSmartPointer<vtkPolyData> ReadMesh(const fs::path& file, std::string& note)
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
      throw SceneError("mesh " + file.string() + " is not a valid PLY file: " + why);
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
      throw SceneError("mesh " + file.string() + " is not a valid OBJ file: " + why);
    }
    vtkNew<vtkOBJReader> reader;
    reader->SetFileName(file.string().c_str());
    reader->Update();
    raw = reader->GetOutput();
  }
  else
  {
    throw SceneError("mesh " + file.string() + " is neither a .ply nor an .obj file");
  }
  if (!raw || raw->GetNumberOfPolys() == 0)
  {
    throw SceneError("mesh " + file.string() + " holds no triangle (unreadable or empty)");
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

std::string Where(const std::string& key, std::size_t index)
{
  return "'" + key + "'[" + std::to_string(index) + "]";
}

/// How the floating-point numbers of the scene being read were spelled in the file, so that
/// messages quote "1e20" as written and not as nlohmann re-prints it ("1e+20").
struct NumberSpellings
{
  const json* Root = nullptr;
  std::vector<std::string> Lexemes; ///< in document order
  /// Each floating-point node's place in document order, built on the first message that
  /// needs it (objects keep their keys in document order: `json` is nlohmann::ordered_json).
  std::unordered_map<const json*, std::size_t> Order;
  bool Ordered = false;

  const std::string* Of(const json& node)
  {
    if (!this->Ordered)
    {
      this->Ordered = true;
      std::vector<const json*> stack{ this->Root };
      while (!stack.empty())
      {
        const json* n = stack.back();
        stack.pop_back();
        if (n->is_number_float())
        {
          this->Order.emplace(n, this->Order.size());
        }
        else if (n->is_structured())
        {
          for (auto it = n->crbegin(); it != n->crend(); ++it)
          {
            stack.push_back(&*it);
          }
        }
      }
      // A key given twice keeps one value: the places no longer match the lexemes.
      if (this->Order.size() != this->Lexemes.size())
      {
        this->Order.clear();
      }
    }
    auto it = this->Order.find(&node);
    return it == this->Order.end() ? nullptr : &this->Lexemes[it->second];
  }
};

/// The spellings of the scene RequestData is reading, on this thread: Brief is called deep in
/// the scene's readers.
thread_local NumberSpellings* CurrentSpellings = nullptr;

/// nlohmann's DOM builder that also keeps each floating-point number's lexeme.
class SpellingDomParser : public nlohmann::detail::json_sax_dom_parser<json>
{
public:
  SpellingDomParser(json& root, std::vector<std::string>& lexemes)
    : json_sax_dom_parser(root)
    , Lexemes(lexemes)
  {
  }
  bool number_float(double value, const std::string& lexeme)
  {
    this->Lexemes.push_back(lexeme);
    return json_sax_dom_parser::number_float(value, lexeme);
  }

private:
  std::vector<std::string>& Lexemes;
};

/// `value` as JSON text, numbers as spelled in the file; `value` is known to be small and
/// shallow (Brief checks), so recursion is bounded.
void AppendAsWritten(const json& value, std::string& text)
{
  if (value.is_number_float() && CurrentSpellings)
  {
    if (const std::string* lexeme = CurrentSpellings->Of(value))
    {
      text += *lexeme;
      return;
    }
  }
  if (value.is_array() || value.is_object())
  {
    text += value.is_array() ? '[' : '{';
    bool first = true;
    for (auto it = value.begin(); it != value.end(); ++it)
    {
      text += first ? "" : ",";
      first = false;
      if (value.is_object())
      {
        text += json(it.key()).dump(-1, ' ', false, json::error_handler_t::replace) + ":";
      }
      AppendAsWritten(*it, text);
    }
    text += value.is_array() ? ']' : '}';
    return;
  }
  text += value.dump(-1, ' ', false, json::error_handler_t::replace);
}

/// A JSON value for a message: as written when small and shallow; else described by its kind
/// and size (dump() recurses once per nesting level: a value nested 10^5 deep would overflow
/// the stack).
std::string Brief(const json& value)
{
  // Walk at most a few hundred nodes, without recursion, to bound depth and size.
  std::vector<std::pair<const json*, int>> stack{ { &value, 0 } };
  int visited = 0;
  bool small = true;
  while (!stack.empty() && small)
  {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    if (++visited > 200 || depth > 8)
    {
      small = false;
      break;
    }
    if (node->is_structured())
    {
      for (const json& child : *node)
      {
        stack.emplace_back(&child, depth + 1);
      }
    }
  }
  if (small)
  {
    std::string text;
    AppendAsWritten(value, text);
    if (text.size() <= 120)
    {
      return text;
    }
  }
  if (value.is_array())
  {
    return "an array of " + std::to_string(value.size()) + " item(s)";
  }
  if (value.is_object())
  {
    return "an object with " + std::to_string(value.size()) + " key(s)";
  }
  return value.dump(-1, ' ', false, json::error_handler_t::replace).substr(0, 117) + "...";
}

/// An integer in [0, INT_MAX] (accepting integral floating-point values); anything else is an
/// error showing the value as written (never wrapped or truncated to an int).
long long AsIndex(const json& value, const std::string& where)
{
  if (value.is_number_unsigned() && value.get<unsigned long long>() <= INT_MAX)
  {
    return value.get<long long>();
  }
  if (value.is_number_integer() && !value.is_number_unsigned())
  {
    const long long v = value.get<long long>();
    if (v >= 0 && v <= INT_MAX)
    {
      return v;
    }
  }
  if (value.is_number_float())
  {
    const double d = value.get<double>();
    if (std::isfinite(d) && std::floor(d) == d && d >= 0 && d <= INT_MAX)
    {
      return static_cast<long long>(d);
    }
  }
  throw SceneError(
    where + " is " + Brief(value) + ", not an integer in [0, " + std::to_string(INT_MAX) + "]");
}

const json& Required(const json& object, const char* key, const std::string& where)
{
  auto it = object.find(key);
  if (it == object.end())
  {
    throw SceneError(where + " has no key '" + key + "'");
  }
  return *it;
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

/// A flat grid on [0,1]^2 with n quads per side, each split into (p00,p10,p11),(p00,p11,p01).
vtkSmartPointer<vtkPolyData> FlatGrid(int n)
{
  auto grid = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      points->InsertNextPoint(double(i) / n, double(j) / n, 0.0);
      normals->InsertNextTuple3(0, 0, 1);
    }
  }
  vtkNew<vtkCellArray> triangles;
  auto id = [n](int i, int j) { return static_cast<vtkIdType>(j) * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      triangles->InsertNextCell({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      triangles->InsertNextCell({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  grid->SetPoints(points);
  grid->SetPolys(triangles);
  grid->GetPointData()->SetNormals(normals);
  return grid;
}

/// The surface point of (x, y) in [0,1]^2 on FlatGrid(n): triangle id and (u, v).
void GridSurfacePoint(int n, double x, double y, vtkIdType& triangle, double& u, double& v)
{
  const double fx = std::min(std::max(x, 0.0), 1.0) * n;
  const double fy = std::min(std::max(y, 0.0), 1.0) * n;
  const int i = std::min(static_cast<int>(fx), n - 1);
  const int j = std::min(static_cast<int>(fy), n - 1);
  const double s = fx - i, t = fy - j;
  const vtkIdType quad = static_cast<vtkIdType>(j) * n + i;
  if (s >= t) // (p00, p10, p11): x = p00 + (s - t)(p10 - p00) + t (p11 - p00)
  {
    triangle = 2 * quad;
    u = s - t;
    v = t;
  }
  else // (p00, p11, p01)
  {
    triangle = 2 * quad + 1;
    u = s;
    v = t - s;
  }
}

struct Scene
{
  vtkSmartPointer<vtkPolyData> Mesh;
  vtkSmartPointer<vtkPolyData> Curves;
  std::string MeshFile;
  std::string Model; ///< the scene's `model`, as written
  std::vector<std::string> Notes;
};

/// Curves output arrays, filled while the cells are added.
struct CurveArrays
{
  vtkNew<vtkPoints> Points;
  vtkNew<vtkIdTypeArray> TriangleId;
  vtkNew<vtkDoubleArray> Barycentric;
  vtkNew<vtkIntArray> ControlPointId;
  vtkNew<vtkCellArray> Lines;
  vtkNew<vtkIntArray> CurveId, ShapeId, CurveType;
  vtkNew<vtkUnsignedCharArray> Closed;

  CurveArrays()
  {
    this->Points->SetDataTypeToDouble();
    this->TriangleId->SetName(boolsurf::names::TriangleId);
    this->Barycentric->SetName(boolsurf::names::Barycentric);
    this->Barycentric->SetNumberOfComponents(2);
    this->ControlPointId->SetName(boolsurf::names::ControlPointId);
    this->CurveId->SetName(boolsurf::names::CurveId);
    this->ShapeId->SetName(boolsurf::names::ShapeId);
    this->CurveType->SetName(boolsurf::names::CurveType);
    this->Closed->SetName(boolsurf::names::Closed);
  }

  void AddPoint(const double x[3], vtkIdType triangle, double u, double v, int controlPoint)
  {
    this->Points->InsertNextPoint(x);
    this->TriangleId->InsertNextValue(triangle);
    this->Barycentric->InsertNextTuple2(u, v);
    this->ControlPointId->InsertNextValue(controlPoint);
  }

  void AddCurve(const std::vector<vtkIdType>& ids,
    bool closed,
    int curveId,
    int shapeId,
    int curveType = 0)
  {
    this->Lines->InsertNextCell(static_cast<vtkIdType>(ids.size() + (closed ? 1 : 0)));
    for (vtkIdType id : ids)
    {
      this->Lines->InsertCellPoint(id);
    }
    if (closed)
    {
      this->Lines->InsertCellPoint(ids.front());
    }
    this->CurveId->InsertNextValue(curveId);
    this->ShapeId->InsertNextValue(shapeId);
    this->CurveType->InsertNextValue(curveType);
    this->Closed->InsertNextValue(closed ? 1 : 0);
  }

  vtkSmartPointer<vtkPolyData> Make()
  {
    auto pd = vtkSmartPointer<vtkPolyData>::New();
    pd->SetPoints(this->Points);
    pd->SetLines(this->Lines);
    pd->GetPointData()->AddArray(this->TriangleId);
    pd->GetPointData()->AddArray(this->Barycentric);
    pd->GetPointData()->AddArray(this->ControlPointId);
    pd->GetCellData()->AddArray(this->CurveId);
    pd->GetCellData()->AddArray(this->ShapeId);
    pd->GetCellData()->AddArray(this->CurveType);
    pd->GetCellData()->AddArray(this->Closed);
    return pd;
  }
};

/// `are_closed` as one flag per polygon (default true).
std::vector<bool> ClosedFlags(const json& scene, std::size_t polygons)
{
  std::vector<bool> closed(polygons, true);
  auto it = scene.find("are_closed");
  if (it == scene.end() || it->is_null())
  {
    return closed;
  }
  if (!it->is_array())
  {
    throw SceneError("'are_closed' is not an array");
  }
  for (std::size_t i = 0; i < it->size() && i < polygons; ++i)
  {
    const json& c = (*it)[i];
    if (c.is_boolean())
    {
      closed[i] = c.get<bool>();
    }
    else if (c.is_number())
    {
      closed[i] = c.get<double>() != 0;
    }
    else
    {
      throw SceneError(Where("are_closed", i) + " is " + Brief(c) + ", not a bool");
    }
  }
  return closed;
}

/// `curve_types` (a key of ours, written by vtkBoolSurfSceneWriter for Bezier curves): one
/// CurveType per polygon, 0 geodesic polygon (the default) or 1 cubic Bezier spline.
std::vector<int> CurveTypes(const json& scene, std::size_t polygons)
{
  std::vector<int> types(polygons, 0);
  auto it = scene.find("curve_types");
  if (it == scene.end() || it->is_null())
  {
    return types;
  }
  if (!it->is_array())
  {
    throw SceneError("'curve_types' is not an array");
  }
  for (std::size_t i = 0; i < it->size() && i < polygons; ++i)
  {
    const long long t = AsIndex((*it)[i], Where("curve_types", i));
    if (t > 1)
    {
      throw SceneError(Where("curve_types", i) + " is " + Brief((*it)[i]) +
        ": 0 geodesic polygon, 1 cubic Bezier spline");
    }
    types[i] = static_cast<int>(t);
  }
  return types;
}

/// Scene shape id of every polygon (-1 for none yet), from `shapes`.
std::vector<int> PolygonShapes(const json& scene, std::size_t polygons, int& numberOfShapes)
{
  std::vector<int> shapeOf(polygons, -1);
  auto it = scene.find("shapes");
  if (it == scene.end() || it->is_null())
  {
    for (std::size_t i = 0; i < polygons; ++i)
    {
      shapeOf[i] = static_cast<int>(i);
    }
    numberOfShapes = static_cast<int>(polygons);
    return shapeOf;
  }
  if (!it->is_array())
  {
    throw SceneError("'shapes' is not an array");
  }
  numberOfShapes = static_cast<int>(it->size());
  for (std::size_t s = 0; s < it->size(); ++s)
  {
    const json& shape = (*it)[s];
    if (!shape.is_array())
    {
      throw SceneError(Where("shapes", s) + " is " + Brief(shape) + ", not a list of polygons");
    }
    for (std::size_t k = 0; k < shape.size(); ++k)
    {
      const std::string where = Where("shapes", s) + "[" + std::to_string(k) + "]";
      const long long p = AsIndex(shape[k], where);
      if (p < 0 || p >= static_cast<long long>(polygons))
      {
        throw SceneError(where + " names polygon " + Brief(shape[k]) + ", but the scene has " +
          std::to_string(polygons) + " polygons");
      }
      if (shapeOf[p] >= 0 && shapeOf[p] != static_cast<int>(s))
      {
        throw SceneError(where + ": polygon " + std::to_string(p) + " is already in shape " +
          std::to_string(shapeOf[p]));
      }
      shapeOf[p] = static_cast<int>(s);
    }
  }
  return shapeOf;
}

void ReadOperations(const json& scene, vtkFieldData* fd)
{
  auto it = scene.find("operations");
  if (it == scene.end() || it->is_null())
  {
    return;
  }
  if (!it->is_array())
  {
    throw SceneError("'operations' is not an array");
  }
  std::vector<int> a, b, type;
  for (std::size_t i = 0; i < it->size(); ++i)
  {
    const json& op = (*it)[i];
    const std::string where = Where("operations", i);
    if (!op.is_object())
    {
      throw SceneError(where + " is " + Brief(op) + ", not an object {a, b, type}");
    }
    a.push_back(static_cast<int>(AsIndex(Required(op, "a", where), where + ".a")));
    b.push_back(static_cast<int>(AsIndex(Required(op, "b", where), where + ".b")));
    const json& typeValue = Required(op, "type", where);
    const long long t = AsIndex(typeValue, where + ".type");
    if (t < 0 || t > 3)
    {
      throw SceneError(where + ".type is " + Brief(typeValue) +
        ": 0 union, 1 difference, 2 intersection, 3 symmetric difference");
    }
    type.push_back(static_cast<int>(t));
  }
  if (a.empty()) // never an empty numeric field array (VTK's XML writer cannot read it back)
  {
    return;
  }
  fd->AddArray(IntArray("OperationA", a));
  fd->AddArray(IntArray("OperationB", b));
  fd->AddArray(IntArray("OperationType", type));
}

/// The screen-space scenes: 2D polylines onto a flat grid.
void ReadScreenSpace(const json& scene, int resolution, Scene& out)
{
  const json& polygons = Required(scene, "polygons", "the scene");
  if (!polygons.is_array())
  {
    throw SceneError("'polygons' is not an array");
  }
  std::vector<std::vector<std::array<double, 2>>> curves(polygons.size());
  double lo[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX }, hi[2] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (std::size_t i = 0; i < polygons.size(); ++i)
  {
    const json& poly = polygons[i];
    if (!poly.is_array())
    {
      throw SceneError(Where("polygons", i) + " is not a list of [x, y] points");
    }
    for (std::size_t k = 0; k < poly.size(); ++k)
    {
      const json& p = poly[k];
      const std::string where = Where("polygons", i) + "[" + std::to_string(k) + "]";
      if (!p.is_array() || p.size() < 2 || !p[0].is_number() || !p[1].is_number())
      {
        throw SceneError(where + " is " + Brief(p) + ", not an [x, y] point");
      }
      // Screen coordinates grow downwards: flip y so that the drawing is upright.
      const std::array<double, 2> xy = { p[0].get<double>(), -p[1].get<double>() };
      if (!std::isfinite(xy[0]) || !std::isfinite(xy[1]))
      {
        throw SceneError(where + " is not finite");
      }
      curves[i].push_back(xy);
      for (int c = 0; c < 2; ++c)
      {
        lo[c] = std::min(lo[c], xy[c]);
        hi[c] = std::max(hi[c], xy[c]);
      }
    }
  }
  const std::vector<bool> closed = ClosedFlags(scene, polygons.size());
  int numberOfShapes = 0;
  const std::vector<int> shapeOf = PolygonShapes(scene, polygons.size(), numberOfShapes);
  const double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  if (!(extent > 0))
  {
    throw SceneError("'polygons' hold no two distinct points");
  }
  // Into [0.1, 0.9]^2, aspect ratio kept, centred.
  const double scale = 0.8 / extent;
  const double offset[2] = { 0.5 - 0.5 * (lo[0] + hi[0]) * scale,
    0.5 - 0.5 * (lo[1] + hi[1]) * scale };
  out.Mesh = FlatGrid(resolution);
  CurveArrays arrays;
  int controlPoint = 0, nextShape = numberOfShapes;
  for (std::size_t i = 0; i < curves.size(); ++i)
  {
    auto& c = curves[i];
    if (c.empty())
    {
      continue;
    }
    if (c.size() < 2)
    {
      throw SceneError(Where("polygons", i) + " has a single point; a curve needs at least 2");
    }
    double area2 = 0; // BoolSurf turns every curve counter-clockwise
    for (std::size_t k = 0; k < c.size(); ++k)
    {
      const auto& p = c[k];
      const auto& q = c[(k + 1) % c.size()];
      area2 += p[0] * q[1] - q[0] * p[1];
    }
    if (area2 < 0)
    {
      std::reverse(c.begin(), c.end());
    }
    std::vector<vtkIdType> ids;
    for (const auto& p : c)
    {
      const double x[3] = { p[0] * scale + offset[0], p[1] * scale + offset[1], 0.0 };
      vtkIdType t;
      double u, v;
      GridSurfacePoint(resolution, x[0], x[1], t, u, v);
      ids.push_back(arrays.Points->GetNumberOfPoints());
      arrays.AddPoint(x, t, u, v, controlPoint++);
    }
    const int shape = shapeOf[i] >= 0 ? shapeOf[i] : nextShape++;
    arrays.AddCurve(ids, closed[i], static_cast<int>(i), shape);
  }
  if (arrays.Lines->GetNumberOfCells() == 0)
  {
    throw SceneError("'polygons' are all empty: the scene has no curve");
  }
  out.Curves = arrays.Make();
  out.Notes.push_back("screen-space scene: its polylines were placed on a flat grid on [0,1]^2");
}

void ReadSurfaceScene(const json& scene,
  const fs::path& file,
  const std::string& meshOverride,
  const std::string& searchPath,
  Scene& out)
{
  const json& polygons = Required(scene, "polygons", "the scene");
  if (!polygons.is_array())
  {
    throw SceneError("'polygons' is not an array");
  }
  const json& points = Required(scene, "points", "the scene");
  if (!points.is_array())
  {
    throw SceneError("'points' is not an array");
  }
  std::string model;
  if (meshOverride.empty())
  {
    const json& m = Required(scene, "model", "the scene (and MeshFileName is not set)");
    if (!m.is_string())
    {
      throw SceneError("'model' is " + Brief(m) + ", not a file name");
    }
    model = m.get<std::string>();
  }
  const std::vector<bool> closed = ClosedFlags(scene, polygons.size());
  const std::vector<int> types = CurveTypes(scene, polygons.size());
  int numberOfShapes = 0;
  const std::vector<int> shapeOf = PolygonShapes(scene, polygons.size(), numberOfShapes);

  // Validate the curve structure before reading a possibly big mesh.
  for (std::size_t i = 0; i < polygons.size(); ++i)
  {
    const json& poly = polygons[i];
    if (!poly.is_array())
    {
      throw SceneError(Where("polygons", i) + " is " + Brief(poly) + ", not a list of points");
    }
    if (poly.size() == 1)
    {
      // A one-point polygon bounds nothing: skipped, as the authors' tool does.
      out.Notes.push_back(Where("polygons", i) + " has a single point (" + Brief(poly[0]) +
        "): skipped, a curve needs at least 2");
    }
    for (std::size_t k = 0; k < poly.size(); ++k)
    {
      const std::string where = Where("polygons", i) + "[" + std::to_string(k) + "]";
      const long long p = AsIndex(poly[k], where);
      if (p < 0 || p >= static_cast<long long>(points.size()))
      {
        throw SceneError(where + " names point " + Brief(poly[k]) + ", but the scene has " +
          std::to_string(points.size()) + " points");
      }
    }
  }

  const std::vector<fs::path> candidates = MeshCandidates(file, meshOverride, model, searchPath);
  fs::path meshFile;
  for (const fs::path& c : candidates)
  {
    if (IsFile(c))
    {
      meshFile = c;
      break;
    }
  }
  if (meshFile.empty())
  {
    std::string tried;
    for (std::size_t k = 0; k < candidates.size() && k < 12; ++k)
    {
      tried += "\n  " + candidates[k].string();
    }
    if (candidates.size() > 12)
    {
      tried += "\n  ... (" + std::to_string(candidates.size() - 12) + " more)";
    }
    throw SceneError("mesh '" + (meshOverride.empty() ? model : meshOverride) +
      "' not found (set MeshFileName or MeshSearchPath); looked for:" + tried);
  }
  std::string note;
  out.Mesh = ReadMesh(meshFile, note);
  out.MeshFile = meshFile.string();
  if (!note.empty())
  {
    out.Notes.push_back(note);
  }
  const vtkIdType numberOfTriangles = out.Mesh->GetNumberOfPolys();
  vtkCellArray* triangles = out.Mesh->GetPolys();
  vtkPoints* meshPoints = out.Mesh->GetPoints();

  CurveArrays arrays;
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    const json& p = points[k];
    const std::string where = Where("points", k);
    if (!p.is_object())
    {
      throw SceneError(where + " is " + Brief(p) + ", not {\"face\": f, \"uv\": [u, v]}");
    }
    const json& faceValue = Required(p, "face", where);
    const long long face = AsIndex(faceValue, where + ".face");
    if (face < 0 || face >= numberOfTriangles)
    {
      throw SceneError(where + ".face = " + Brief(faceValue) + " is out of range: mesh " +
        out.MeshFile + " has " + std::to_string(numberOfTriangles) + " triangles");
    }
    const json& uv = Required(p, "uv", where);
    if (!uv.is_array() || uv.size() != 2 || !uv[0].is_number() || !uv[1].is_number())
    {
      throw SceneError(where + ".uv is " + Brief(uv) + ", not two numbers [u, v]");
    }
    double u = uv[0].get<double>(), v = uv[1].get<double>();
    if (!std::isfinite(u) || !std::isfinite(v) || u < -UVTolerance || v < -UVTolerance ||
      u + v > 1 + UVTolerance)
    {
      throw SceneError(where + ".uv = " + Brief(uv) +
        " is outside the triangle (needs u >= 0, v >= 0, u + v <= 1)");
    }
    boolsurf::ClampBarycentric(u, v);
    vtkIdType n;
    const vtkIdType* ids;
    triangles->GetCellAtId(face, n, ids);
    double p0[3], p1[3], p2[3], x[3];
    meshPoints->GetPoint(ids[0], p0);
    meshPoints->GetPoint(ids[1], p1);
    meshPoints->GetPoint(ids[2], p2);
    for (int c = 0; c < 3; ++c)
    {
      x[c] = (1 - u - v) * p0[c] + u * p1[c] + v * p2[c];
    }
    arrays.AddPoint(x, face, u, v, static_cast<int>(k));
  }

  int nextShape = numberOfShapes;
  for (std::size_t i = 0; i < polygons.size(); ++i)
  {
    const json& poly = polygons[i];
    if (poly.size() < 2)
    {
      // Polygon 0 is reserved by BoolSurf; its editor also leaves trailing empty ones; one-point
      // polygons were named in a note above.
      continue;
    }
    std::vector<vtkIdType> ids;
    for (const json& p : poly)
    {
      ids.push_back(static_cast<vtkIdType>(AsIndex(p, "")));
    }
    const int shape = shapeOf[i] >= 0 ? shapeOf[i] : nextShape++;
    arrays.AddCurve(ids, closed[i], static_cast<int>(i), shape, types[i]);
  }
  if (arrays.Lines->GetNumberOfCells() == 0)
  {
    throw SceneError("'polygons' are all empty: the scene has no curve");
  }
  out.Curves = arrays.Make();
  out.Model = model;
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
  if (!in)
  {
    return 0;
  }
  const json scene = json::parse(in, nullptr, /*allow_exceptions=*/false);
  return scene.is_object() && scene.contains("polygons") ? 1 : 0;
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
  Scene scene;
  try
  {
    std::ifstream in(file, std::ios::binary);
    if (!in)
    {
      throw SceneError("cannot open the file");
    }
    json root;
    NumberSpellings spellings;
    spellings.Root = &root;
    struct Guard
    {
      explicit Guard(NumberSpellings* s) { CurrentSpellings = s; }
      ~Guard() { CurrentSpellings = nullptr; }
    } guard(&spellings);
    try
    {
      SpellingDomParser parser(root, spellings.Lexemes);
      json::sax_parse(in, &parser);
    }
    catch (const json::parse_error& e)
    {
      throw SceneError(std::string("bad JSON: ") + e.what());
    }
    if (!root.is_object())
    {
      throw SceneError("the top level is not a JSON object");
    }
    this->UpdateProgress(0.1);
    auto ss = root.find("screenspace");
    if (ss != root.end() && ss->is_boolean() && ss->get<bool>())
    {
      ReadScreenSpace(root, this->ScreenSpaceResolution, scene);
    }
    else
    {
      ReadSurfaceScene(root, file, this->MeshFileName, this->MeshSearchPath, scene);
    }
    ReadOperations(root, scene.Curves->GetFieldData());
  }
  catch (const SceneError& e)
  {
    vtkErrorMacro("BoolSurf scene " << this->FileName << ": " << e.what());
    return 1; // empty outputs
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("BoolSurf scene " << this->FileName << ": " << e.what());
    return 1;
  }
  for (const std::string& note : scene.Notes)
  {
    vtkWarningMacro("BoolSurf scene " << this->FileName << ": " << note);
  }
  this->ResolvedMeshFileName = scene.MeshFile;
  meshOut->ShallowCopy(scene.Mesh);
  curvesOut->ShallowCopy(scene.Curves);
  for (vtkPolyData* pd : { meshOut, curvesOut })
  {
    AddString(pd->GetFieldData(), "SceneFileName", this->FileName);
    if (!scene.MeshFile.empty())
    {
      AddString(pd->GetFieldData(), "MeshFileName", scene.MeshFile);
    }
    if (!scene.Model.empty())
    {
      AddString(pd->GetFieldData(), "SceneModel", scene.Model);
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
