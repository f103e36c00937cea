// vtkBoolSurfSceneReader: BoolSurf's scene format (points {face, uv}, polygons, are_closed,
// shapes, operations, screenspace), mesh lookup, and named errors for malformed files.
#include "vtkBoolSurfSceneReader.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include "Support/ScratchDirectory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace
{
namespace fs = std::filesystem;

/// A scratch folder per test process, removed at exit.
fs::path Scratch()
{
  static const boolsurf::testing::ScratchDirectory dir("boolsurf-scene-reader-", { "meshes" });
  return dir.Path;
}

/// A 2x1 quad strip in z = 0 (two quads: the reader splits them into 4 triangles).
void WriteQuadMesh(const fs::path& file)
{
  vtkNew<vtkPoints> points;
  for (double x : { 0.0, 1.0, 2.0 })
  {
    points->InsertNextPoint(x, 0, 0);
  }
  for (double x : { 0.0, 1.0, 2.0 })
  {
    points->InsertNextPoint(x, 1, 0);
  }
  vtkNew<vtkCellArray> quads;
  quads->InsertNextCell({ 0, 1, 4, 3 });
  quads->InsertNextCell({ 1, 2, 5, 4 });
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(points);
  pd->SetPolys(quads);
  vtkNew<vtkPLYWriter> writer;
  writer->SetInputData(pd);
  writer->SetFileName(file.string().c_str());
  writer->Write();
}

fs::path WriteScene(const std::string& name, const std::string& text)
{
  const fs::path file = Scratch() / name;
  std::ofstream(file) << text;
  return file;
}

struct Read
{
  vtkNew<vtkBoolSurfSceneReader> Reader;
  std::string Errors;
  vtkNew<vtkCallbackCommand> OnError;
  vtkNew<vtkCallbackCommand> OnWarning;

  explicit Read(const fs::path& file, const std::string& mesh = "", const std::string& path = "")
  {
    this->OnError->SetClientData(&this->Errors);
    this->OnError->SetCallback([](vtkObject*, unsigned long, void* errors, void* text)
      { *static_cast<std::string*>(errors) += static_cast<const char*>(text); });
    this->Reader->AddObserver(vtkCommand::ErrorEvent, this->OnError);
    this->Reader->AddObserver(vtkCommand::WarningEvent, this->OnWarning);
    this->Reader->SetFileName(file.string().c_str());
    this->Reader->SetMeshFileName(mesh.c_str());
    this->Reader->SetMeshSearchPath(path.c_str());
    this->Reader->Update();
  }
  vtkPolyData* Mesh() { return this->Reader->GetOutput(0); }
  vtkPolyData* Curves() { return this->Reader->GetCurvesOutput(); }
  std::vector<int> CellInts(const char* name)
  {
    std::vector<int> out;
    vtkDataArray* a = this->Curves()->GetCellData()->GetArray(name);
    for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
    {
      out.push_back(static_cast<int>(a->GetComponent(i, 0)));
    }
    return out;
  }
};

const char* ValidScene = R"({
  "model": "./data/models/quads.ply",
  "points": [ {"face": 0, "uv": [0.25, 0.25]}, {"face": 1, "uv": [0.5, 0.25]},
              {"face": 2, "uv": [0.2, 0.3]},   {"face": 3, "uv": [0.1, 0.1]},
              {"face": 2, "uv": [0.0, 1.0]} ],
  "polygons": [ [], [0, 1, 2], [2, 3, 4], [], [1, 4] ],
  "are_closed": [true, true, false, true, true],
  "shapes": [ [0], [1, 2] ],
  "operations": [ {"a": 1, "b": 3, "type": 2} ]
})";

TEST(SceneReader, SurfacePointsShapesAndOperations)
{
  WriteQuadMesh(Scratch() / "meshes" / "quads.ply");
  Read r(WriteScene("valid.json", ValidScene));
  ASSERT_EQ(r.Errors, "");
  ASSERT_EQ(r.Mesh()->GetNumberOfPolys(), 4); // quads split the Yocto way
  // Quad (0,1,4,3) -> (0,1,3), (4,3,1).
  vtkIdType n;
  const vtkIdType* ids;
  r.Mesh()->GetPolys()->GetCellAtId(1, n, ids);
  EXPECT_EQ(
    (std::vector<vtkIdType>{ ids[0], ids[1], ids[2] }), (std::vector<vtkIdType>{ 4, 3, 1 }));

  vtkPolyData* c = r.Curves();
  // Every curve has points of its own (3 + 3 + 2): the writer of control curves shares none,
  // so scene points 1, 2 and 4, named by two polygons each, are written twice.
  ASSERT_EQ(c->GetNumberOfPoints(), 8);
  ASSERT_EQ(c->GetNumberOfLines(), 3); // empty polygons 0 and 3 skipped
  EXPECT_EQ(r.CellInts("CurveId"), (std::vector<int>{ 1, 2, 4 }));
  // Polygons 1, 2 are shape 1; polygon 4 is in no shape: a new shape after the scene's two.
  EXPECT_EQ(r.CellInts("ShapeId"), (std::vector<int>{ 1, 1, 2 }));
  EXPECT_EQ(r.CellInts("Closed"), (std::vector<int>{ 1, 0, 1 }));
  EXPECT_EQ(r.CellInts("CurveType"), (std::vector<int>{ 0, 0, 0 }));
  // A closed curve repeats its first point id; an open one does not.
  c->GetLines()->GetCellAtId(0, n, ids);
  EXPECT_EQ((std::vector<vtkIdType>(ids, ids + n)), (std::vector<vtkIdType>{ 0, 1, 2, 0 }));
  c->GetLines()->GetCellAtId(1, n, ids);
  EXPECT_EQ((std::vector<vtkIdType>(ids, ids + n)), (std::vector<vtkIdType>{ 3, 4, 5 }));
  c->GetLines()->GetCellAtId(2, n, ids);
  EXPECT_EQ((std::vector<vtkIdType>(ids, ids + n)), (std::vector<vtkIdType>{ 6, 7, 6 }));

  // TriangleId/Barycentric are exactly face/uv, and the point is (1-u-v)p0 + u p1 + v p2.
  vtkDataArray* tid = c->GetPointData()->GetArray("TriangleId");
  vtkDataArray* bary = c->GetPointData()->GetArray("Barycentric");
  ASSERT_TRUE(tid && bary);
  EXPECT_EQ(tid->GetComponent(1, 0), 1);
  EXPECT_EQ(bary->GetComponent(1, 0), 0.5);
  EXPECT_EQ(bary->GetComponent(1, 1), 0.25);
  double x[3];
  c->GetPoint(1, x); // triangle (4,3,1): p0 (1,1), p1 (0,1), p2 (1,0)
  EXPECT_NEAR(x[0], 0.25 * 1 + 0.5 * 0 + 0.25 * 1, 1e-15);
  EXPECT_NEAR(x[1], 0.25 * 1 + 0.5 * 1 + 0.25 * 0, 1e-15);

  vtkFieldData* fd = c->GetFieldData();
  ASSERT_TRUE(
    fd->GetArray("OperationA") && fd->GetArray("OperationB") && fd->GetArray("OperationType"));
  EXPECT_EQ(fd->GetArray("OperationA")->GetComponent(0, 0), 1);
  EXPECT_EQ(fd->GetArray("OperationB")->GetComponent(0, 0), 3);
  EXPECT_EQ(fd->GetArray("OperationType")->GetComponent(0, 0), 2);
  auto* mesh = vtkStringArray::SafeDownCast(fd->GetAbstractArray("MeshFileName"));
  ASSERT_TRUE(mesh);
  EXPECT_EQ(fs::path(std::string(mesh->GetValue(0))).filename(), "quads.ply");
}

TEST(SceneReader, DefaultsOneShapePerPolygonAllClosedNoOperations)
{
  WriteQuadMesh(Scratch() / "meshes" / "quads.ply");
  Read r(WriteScene("defaults.json", R"({"model": "quads.ply",
    "points": [{"face": 0, "uv": [0.1, 0.1]}, {"face": 3, "uv": [0.1, 0.1]},
               {"face": 2, "uv": [0.3, 0.3]}],
    "polygons": [[], [0, 1, 2], [2, 1]], "operations": []})"));
  ASSERT_EQ(r.Errors, "");
  EXPECT_EQ(r.CellInts("ShapeId"), (std::vector<int>{ 1, 2 }));
  EXPECT_EQ(r.CellInts("Closed"), (std::vector<int>{ 1, 1 }));
  // No empty numeric field arrays (VTK's XML writer cannot read them back).
  EXPECT_EQ(r.Curves()->GetFieldData()->GetArray("OperationA"), nullptr);
}

TEST(SceneReader, MeshLookupByRenamedCopySearchPathAndOverride)
{
  const fs::path elsewhere = Scratch() / "elsewhere";
  fs::create_directories(elsewhere);
  WriteQuadMesh(elsewhere / "eight_200k.ply");
  const std::string scene = R"({"model": ".\\data\\complex_meshes\\eight200k-remeshed.ply",
    "points": [{"face": 0, "uv": [0.1, 0.1]}, {"face": 3, "uv": [0.1, 0.1]}],
    "polygons": [[], [0, 1]]})";
  const fs::path file = WriteScene("renamed.json", scene);
  {
    Read r(file);
    EXPECT_NE(r.Errors.find("eight200k-remeshed.ply' not found"), std::string::npos) << r.Errors;
    EXPECT_EQ(r.Curves()->GetNumberOfCells(), 0);
  }
  {
    Read r(file, "", "/nonexistent;" + elsewhere.string());
    EXPECT_EQ(r.Errors, "");
    EXPECT_EQ(fs::path(r.Reader->GetResolvedMeshFileName()).filename(), "eight_200k.ply");
    EXPECT_EQ(r.Curves()->GetNumberOfCells(), 1);
  }
  {
    Read r(file, "elsewhere/eight_200k.ply"); // relative to the scene's folder
    EXPECT_EQ(r.Errors, "");
    EXPECT_EQ(r.Mesh()->GetNumberOfPolys(), 4);
  }
  {
    Read r(file, "elsewhere/none.ply");
    EXPECT_NE(r.Errors.find("mesh 'elsewhere/none.ply' not found"), std::string::npos);
  }
}

TEST(SceneReader, ScreenSpaceScenesGoOnAFlatGrid)
{
  // A clockwise square (in screen coordinates, y down) and an open polyline.
  Read r(WriteScene("screen.json", R"({"screenspace": true,
    "polygons": [[[0, 0], [10, 0], [10, 10], [0, 10]], [[2, 2], [8, 3]]],
    "are_closed": [true, false]})"));
  ASSERT_EQ(r.Errors, "");
  EXPECT_EQ(r.Mesh()->GetNumberOfPolys(), 2 * 64 * 64);
  vtkPolyData* c = r.Curves();
  ASSERT_EQ(c->GetNumberOfLines(), 2);
  EXPECT_EQ(r.CellInts("Closed"), (std::vector<int>{ 1, 0 }));
  vtkDataArray* tid = c->GetPointData()->GetArray("TriangleId");
  vtkDataArray* bary = c->GetPointData()->GetArray("Barycentric");
  double area2 = 0;
  for (vtkIdType i = 0; i < c->GetNumberOfPoints(); ++i)
  {
    double x[3], p[3][3];
    c->GetPoint(i, x);
    EXPECT_GE(x[0], 0.1 - 1e-12);
    EXPECT_LE(x[0], 0.9 + 1e-12);
    vtkIdType n;
    const vtkIdType* ids;
    r.Mesh()->GetPolys()->GetCellAtId(static_cast<vtkIdType>(tid->GetComponent(i, 0)), n, ids);
    for (int k = 0; k < 3; ++k)
    {
      r.Mesh()->GetPoint(ids[k], p[k]);
    }
    const double u = bary->GetComponent(i, 0), v = bary->GetComponent(i, 1);
    EXPECT_GE(u, 0);
    EXPECT_GE(v, 0);
    EXPECT_LE(u + v, 1 + 1e-12);
    for (int d = 0; d < 2; ++d)
    {
      EXPECT_NEAR((1 - u - v) * p[0][d] + u * p[1][d] + v * p[2][d], x[d], 1e-12);
    }
    if (i < 4)
    {
      double y[3];
      c->GetPoint((i + 1) % 4, y);
      area2 += x[0] * y[1] - y[0] * x[1];
    }
  }
  EXPECT_GT(area2, 0); // turned counter-clockwise
}

struct BadCase
{
  const char* Name;
  const char* Text;
  std::vector<std::string> Expected; ///< substrings of the error
};

TEST(SceneReader, MalformedScenesAreNamedErrors)
{
  WriteQuadMesh(Scratch() / "meshes" / "quads.ply");
  const std::vector<BadCase> cases = {
    { "badjson.json", R"({"model": "quads.ply", "points": [)", { "bad JSON" } },
    { "notobject.json", "[1, 2]", { "not a JSON object" } },
    { "nopolygons.json", R"({"model": "quads.ply", "points": []})", { "'polygons'" } },
    { "nopoints.json", R"({"model": "quads.ply", "polygons": [[], [0, 1]]})", { "'points'" } },
    { "nomodel.json", R"({"points": [], "polygons": [[], [0, 1]]})", { "'model'" } },
    { "face.json",
      R"({"model": "quads.ply", "points": [{"face": 0, "uv": [0.1, 0.1]},
          {"face": 4, "uv": [0.1, 0.1]}], "polygons": [[], [0, 1]]})",
      { "'points'[1].face = 4 is out of range", "has 4 triangles" } },
    { "uv.json",
      R"({"model": "quads.ply", "points": [{"face": 0, "uv": [0.7, 0.4]},
          {"face": 1, "uv": [0.1, 0.1]}], "polygons": [[], [0, 1]]})",
      { "'points'[0].uv = [0.7,0.4] is outside the triangle" } },
    { "uvtype.json",
      R"({"model": "quads.ply", "points": [{"face": 0, "uv": [0.1]}], "polygons": [[], [0, 0]]})",
      { "'points'[0].uv is [0.1], not two numbers" } },
    { "noface.json",
      R"({"model": "quads.ply", "points": [{"uv": [0.1, 0.1]}], "polygons": [[], [0, 0]]})",
      { "'points'[0] has no key 'face'" } },
    { "pointindex.json",
      R"({"model": "quads.ply", "points": [{"face": 0, "uv": [0.1, 0.1]}],
          "polygons": [[], [0, 7]]})",
      { "'polygons'[1][1] names point 7", "has 1 points" } },
    { "single.json",
      R"({"model": "quads.ply", "points": [{"face": 0, "uv": [0.1, 0.1]}],
          "polygons": [[], [0]]})",
      { "no curve" } }, // its one-point polygon is skipped with a warning: none is left
    { "allempty.json",
      R"({"model": "quads.ply", "points": [], "polygons": [[], []]})",
      { "no curve" } },
    { "shapes.json",
      R"({"model": "quads.ply", "points": [{"face": 0, "uv": [0.1, 0.1]},
          {"face": 1, "uv": [0.1, 0.1]}], "polygons": [[], [0, 1]], "shapes": [[0], [5]]})",
      { "'shapes'[1][0] names polygon 5" } },
    { "ops.json",
      R"({"model": "quads.ply", "points": [{"face": 0, "uv": [0.1, 0.1]},
          {"face": 1, "uv": [0.1, 0.1]}], "polygons": [[], [0, 1]],
          "operations": [{"a": 1, "type": 0}]})",
      { "'operations'[0] has no key 'b'" } },
    { "missingmesh.json",
      R"({"model": "./data/models/nowhere.ply", "points": [{"face": 0, "uv": [0.1, 0.1]},
          {"face": 1, "uv": [0.1, 0.1]}], "polygons": [[], [0, 1]]})",
      { "mesh './data/models/nowhere.ply' not found", "looked for" } },
  };
  for (const BadCase& bad : cases)
  {
    const fs::path file = WriteScene(bad.Name, bad.Text);
    Read r(file);
    EXPECT_NE(r.Errors.find(file.string()), std::string::npos)
      << bad.Name << ": the error names the file: " << r.Errors;
    for (const std::string& expected : bad.Expected)
    {
      EXPECT_NE(r.Errors.find(expected), std::string::npos)
        << bad.Name << ": expected '" << expected << "' in: " << r.Errors;
    }
    EXPECT_EQ(r.Curves()->GetNumberOfCells(), 0) << bad.Name;
    EXPECT_EQ(r.Mesh()->GetNumberOfCells(), 0) << bad.Name;
  }
  Read none(Scratch() / "does-not-exist.json");
  EXPECT_NE(none.Errors.find("cannot open"), std::string::npos);
}

TEST(SceneReader, CanReadFileWantsPolygons)
{
  EXPECT_EQ(vtkBoolSurfSceneReader::CanReadFile(WriteScene("valid2.json", ValidScene).c_str()), 1);
  EXPECT_EQ(vtkBoolSurfSceneReader::CanReadFile(
              WriteScene("other.json", R"({"basis": [], "model": "x.ply"})").c_str()),
    0);
  EXPECT_EQ(vtkBoolSurfSceneReader::CanReadFile(WriteScene("bad2.json", "{").c_str()), 0);
  EXPECT_EQ(vtkBoolSurfSceneReader::CanReadFile(nullptr), 0);
}
} // namespace

// Adversarial scene files: JSON nested 10^5 deep, operation indices beyond int, and PLY meshes
// that are truncated, garbage or name absent vertices, and OBJ meshes naming absent texture
// coordinates get named errors, never a crash or a
// silently changed value.
TEST(SceneReader, AdversarialFilesAreNamedErrors)
{
  WriteQuadMesh(Scratch() / "meshes" / "quads.ply");
  const std::string points = R"("points": [{"face": 0, "uv": [0.1, 0.1]},
    {"face": 1, "uv": [0.1, 0.1]}], "polygons": [[], [0, 1]])";
  struct Case
  {
    std::string Name, Text;
    std::vector<std::string> Expected;
  };
  const std::string deep(100000, '[');
  const std::vector<Case> cases = {
    { "deep.json",
      R"({"model": "quads.ply", )" + points + R"(, "are_closed": [)" + deep + "1" +
        std::string(100000, ']') + "]}",
      { "nesting too deep", "(in 'are_closed')", "at most 256 levels" } },
    { "opsbig.json",
      R"({"model": "quads.ply", )" + points +
        R"(, "operations": [{"a": 4294967297, "b": 1, "type": 0}]})",
      { "'operations'[0].a is 4294967297, not an integer in [0, 2147483647]" } },
    { "opsint.json",
      R"({"model": "quads.ply", )" + points +
        R"(, "operations": [{"a": 1, "b": 2147483648, "type": 0}]})",
      { "'operations'[0].b is 2147483648, not an integer" } },
    { "opshuge.json",
      R"({"model": "quads.ply", )" + points +
        R"(, "operations": [{"a": 1e300, "b": 1, "type": 0}]})",
      { "'operations'[0].a is 1e300, not an integer" } },
    // Numbers are quoted as written in the file, not as re-printed (1e+20, 100.0, 0.25).
    { "facehuge.json",
      R"({"model": "quads.ply", "points": [{"face": 1e20, "uv": [0.1, 0.1]},
          {"face": 1, "uv": [0.1, 0.1]}], "polygons": [[], [0, 1]]})",
      { "'points'[0].face is 1e20, not an integer" } },
    { "faceexp.json",
      R"({"model": "quads.ply", "points": [{"face": 1E2, "uv": [0.1, 0.1]},
          {"face": 1, "uv": [0.1, 0.1]}], "polygons": [[], [0, 1]]})",
      { "'points'[0].face = 1E2 is out of range" } },
    { "uvspelled.json",
      R"({"model": "quads.ply", "points": [{"face": 0, "uv": [2.5E-1, 0.25, 0.2500]},
          {"face": 1, "uv": [0.1, 0.1]}], "polygons": [[], [0, 1]]})",
      { "[2.5E-1,0.25,0.2500]" } },
  };
  // PLY files a scene may name: truncated ASCII, garbage binary, an absent vertex.
  const std::string header =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
  std::ofstream(Scratch() / "meshes" / "truncated.ply")
    << header << "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0";
  std::ofstream(Scratch() / "meshes" / "farindex.ply")
    << header << "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 100000000\n";
  {
    std::ofstream garbage(Scratch() / "meshes" / "garbage.ply", std::ios::binary);
    garbage << "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\n"
               "property float x\nproperty float y\nproperty float z\nelement face 7\n"
               "property list uchar int vertex_indices\nend_header\n";
    for (int i = 0; i < 4096; ++i)
      garbage.put(static_cast<char>((i * 7919) & 0xff));
  }
  // Found by fuzzing (Testing/Fuzz): a face list under another name crashed vtkPLYReader.
  std::ofstream(Scratch() / "meshes" / "nofacelist.ply")
    << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
       "property float z\nelement face 2\nproperty list uchar int vertex_indexes\nend_header\n"
    << "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";
  std::ofstream(Scratch() / "meshes" / "propertyfirst.ply")
    << "ply\nformat ascii 1.0\nproperty float x\nelement vertex 4\nproperty float x\n"
       "property float y\nproperty float z\nelement face 2\n"
       "property list uchar int vertex_indices\nend_header\n"
    << "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";
  std::ofstream(Scratch() / "meshes" / "novertex.ply")
    << "ply\nformat ascii 1.0\nelement vetexr 4\nproperty float x\n"
       "property float y\nproperty float z\nelement face 2\n"
       "property list uchar int vertex_indices\nend_header\n"
    << "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";
  std::ofstream(Scratch() / "meshes" / "badtexture.obj")
    << "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nf 1 2 3\nf 4/5 3 1\n";
  const std::vector<Case> meshes = {
    { "badtextureobj.json",
      R"({"model": "badtexture.obj", )" + points + "}",
      { "badtexture.obj is not a valid OBJ file",
        "'4/5' names texture coordinate 5, but 0 texture coordinate(s) precede it" } },
    { "novertexply.json",
      R"({"model": "novertex.ply", )" + points + "}",
      { "novertex.ply is not a valid PLY file", "no element 'vertex'" } },
    { "propertyfirstply.json",
      R"({"model": "propertyfirst.ply", )" + points + "}",
      { "propertyfirst.ply is not a valid PLY file", "property line before any element" } },
    { "nofacelistply.json",
      R"({"model": "nofacelist.ply", )" + points + "}",
      { "nofacelist.ply is not a valid PLY file",
        "element 'face' has no list property vertex_indices" } },
    { "truncatedply.json",
      R"({"model": "truncated.ply", )" + points + "}",
      { "truncated.ply is not a valid PLY file", "truncated face 1" } },
    { "farindexply.json",
      R"({"model": "farindex.ply", )" + points + "}",
      { "face 1 uses vertex index 100000000, outside [0, 4)" } },
    { "garbageply.json",
      R"({"model": "garbage.ply", )" + points + "}",
      { "garbage.ply is not a valid PLY file", "truncated" } },
  };
  for (const std::vector<Case>* list : { &cases, &meshes })
  {
    for (const Case& bad : *list)
    {
      Read r(WriteScene(bad.Name, bad.Text));
      for (const std::string& expected : bad.Expected)
      {
        EXPECT_NE(r.Errors.find(expected), std::string::npos)
          << bad.Name << ": expected '" << expected << "' in: " << r.Errors.substr(0, 400);
      }
      EXPECT_EQ(r.Curves()->GetNumberOfCells(), 0) << bad.Name;
    }
  }
}
