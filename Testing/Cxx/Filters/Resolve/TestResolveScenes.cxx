// Resolve Inconsistent Shapes on the reference scenes with inconsistent shapes (torus3-9,
// tritorus-*loops, 3torus-spiral-rev; ../shared/data, skipped when absent): with each strategy,
// tracing + arrangement + labeling of the resolved curves find every shape consistent, with a
// zero HomologyExcess; RemoveCurves keeps only null-homologous sets; DuplicateReversed strips
// never cross the curve they duplicate. Also the filter's bad input and no-op notes on a
// procedural torus.
#include "FilterTestUtils.h"

#include "Mesh/SurfacePoint.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfResolve.h"
#include "vtkBoolSurfSceneReader.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;
using namespace boolsurf;

namespace
{

struct Catcher
{
  std::string Text;
  vtkNew<vtkCallbackCommand> Command;
  Catcher()
  {
    this->Command->SetClientData(&this->Text);
    this->Command->SetCallback([](vtkObject*, unsigned long, void* text, void* data)
      { *static_cast<std::string*>(text) += static_cast<const char*>(data); });
  }
  void Watch(vtkObject* o, unsigned long event) { o->AddObserver(event, this->Command); }
};

TriangleMesh MeshOf(vtkPolyData* pd)
{
  std::vector<Vec3> positions;
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    double x[3];
    pd->GetPoint(i, x);
    positions.push_back({ x[0], x[1], x[2] });
  }
  std::vector<Triangle> triangles;
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = pd->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    triangles.push_back(
      { static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) });
  }
  return TriangleMesh(positions, triangles);
}

// Traced polyline `cell` of the tracing output as canonical points (closing repeat dropped).
std::vector<CanonicalPoint> TracedPoints(const TriangleMesh& mesh,
  vtkPolyData* traced,
  vtkIdType cell)
{
  vtkDataArray* tid = traced->GetPointData()->GetArray("TriangleId");
  vtkDataArray* bary = traced->GetPointData()->GetArray("Barycentric");
  vtkIdType n;
  const vtkIdType* ids;
  traced->GetCellPoints(cell, n, ids);
  std::vector<CanonicalPoint> out;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (i == n - 1 && n > 1 && ids[i] == ids[0])
    {
      break;
    }
    SurfacePoint p{ static_cast<int>(tid->GetComponent(ids[i], 0)),
      bary->GetComponent(ids[i], 0),
      bary->GetComponent(ids[i], 1) };
    out.push_back(Canonicalize(mesh, p));
  }
  return out;
}

// True when segments of the two closed polylines inside a common triangle meet (with a == b:
// segments that are not neighbours along the curve).
bool CurvesMeet(const TriangleMesh& mesh,
  const std::vector<CanonicalPoint>& a,
  const std::vector<CanonicalPoint>& b,
  bool self = false)
{
  auto orient = [](Vec2 p, Vec2 q, Vec2 s) { return Cross(q - p, s - p); };
  for (size_t i = 0; i < a.size(); ++i)
  {
    const CanonicalPoint &p0 = a[i], &p1 = a[(i + 1) % a.size()];
    const int t = SharedTriangle(mesh, p0, p1);
    if (t < 0)
    {
      continue;
    }
    for (size_t j = 0; j < b.size(); ++j)
    {
      const size_t gap = (j + b.size() - i) % b.size();
      if (self && (gap <= 1 || gap == b.size() - 1))
      {
        continue;
      }
      const CanonicalPoint &q0 = b[j], &q1 = b[(j + 1) % b.size()];
      if (!TriangleContains(mesh, q0, t) || !TriangleContains(mesh, q1, t))
      {
        continue;
      }
      auto flat = [&](const CanonicalPoint& c)
      {
        const auto w = WeightsInTriangle(mesh, c, t);
        return Vec2{ w[1], w[2] };
      };
      const Vec2 A = flat(p0), B = flat(p1), C = flat(q0), D = flat(q1);
      const double d1 = orient(A, B, C), d2 = orient(A, B, D), d3 = orient(C, D, A),
                   d4 = orient(C, D, B);
      if (((d1 <= 0 && d2 >= 0) || (d1 >= 0 && d2 <= 0)) &&
        ((d3 <= 0 && d4 >= 0) || (d3 >= 0 && d4 <= 0)))
      {
        return true;
      }
    }
  }
  return false;
}

void CheckScene(const fs::path& file, int strategy)
{
  SCOPED_TRACE(file.filename().string() + " strategy " + std::to_string(strategy));
  vtkNew<vtkBoolSurfSceneReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  ASSERT_GT(reader->GetCurvesOutput()->GetNumberOfCells(), 0);
  vtkNew<vtkBoolSurfResolve> resolve;
  resolve->SetInputConnection(0, reader->GetOutputPort(0));
  resolve->SetInputConnection(1, reader->GetOutputPort(1));
  resolve->SetStrategy(strategy);
  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputConnection(0, reader->GetOutputPort(0));
  trace->SetInputConnection(1, resolve->GetOutputPort());
  vtkNew<vtkBoolSurfArrangement> arrange;
  arrange->SetInputConnection(0, reader->GetOutputPort(0));
  arrange->SetInputConnection(1, trace->GetOutputPort());
  vtkNew<vtkBoolSurfLabeling> label;
  label->SetInputConnection(arrange->GetOutputPort(0));
  Catcher errors, warnings;
  for (vtkObject* o : { static_cast<vtkObject*>(resolve),
         static_cast<vtkObject*>(trace),
         static_cast<vtkObject*>(arrange),
         static_cast<vtkObject*>(label) })
  {
    errors.Watch(o, vtkCommand::ErrorEvent);
    warnings.Watch(o, vtkCommand::WarningEvent);
  }
  resolve->Update();
  vtkPolyData* resolved = resolve->GetOutput();
  if (strategy == vtkBoolSurfResolve::REMOVE_CURVES && resolved->GetNumberOfCells() == 0)
  {
    // Every shape was one winding loop: all removed, each named with its reason.
    vtkDataArray* removed = resolved->GetFieldData()->GetArray("RemovedCurves");
    ASSERT_NE(removed, nullptr);
    EXPECT_EQ(removed->GetNumberOfTuples(), reader->GetCurvesOutput()->GetNumberOfCells());
    return;
  }
  label->Update();
  ASSERT_TRUE(errors.Text.empty()) << errors.Text;
  vtkDataArray* treated = resolved->GetFieldData()->GetArray("TreatedShapes");
  ASSERT_NE(treated, nullptr) << "no shape was treated";
  vtkFieldData* fd = label->GetOutput(0)->GetFieldData();
  vtkDataArray* consistent = fd->GetArray("ShapeConsistent");
  vtkDataArray* excess = fd->GetArray("HomologyExcess");
  ASSERT_NE(consistent, nullptr);
  for (vtkIdType s = 0; s < consistent->GetNumberOfTuples(); ++s)
  {
    EXPECT_EQ(consistent->GetComponent(s, 0), 1) << "shape index " << s << ": " << warnings.Text;
    if (excess)
    {
      for (int g = 0; g < excess->GetNumberOfComponents(); ++g)
      {
        EXPECT_EQ(excess->GetComponent(s, g), 0);
      }
    }
  }
  vtkDataArray* action = resolved->GetCellData()->GetArray("Resolution");
  vtkDataArray* source = resolved->GetCellData()->GetArray("ResolutionSource");
  ASSERT_NE(action, nullptr);
  int changed = 0;
  for (vtkIdType c = 0; c < action->GetNumberOfTuples(); ++c)
  {
    changed += action->GetComponent(c, 0) != 0;
  }
  changed += resolved->GetFieldData()->GetArray("RemovedCurves") ? 1 : 0;
  EXPECT_GT(changed, 0);
  if (strategy == vtkBoolSurfResolve::DUPLICATE_REVERSED)
  {
    // Each strip's copy against its original (found by CurveId = ResolutionSource).
    const TriangleMesh mesh = MeshOf(reader->GetOutput(0));
    vtkPolyData* traced = trace->GetOutput();
    vtkDataArray* curveId = traced->GetCellData()->GetArray("CurveId");
    std::map<int, vtkIdType> cellOfCurve;
    int checked = 0, selfCrossing = 0;
    for (vtkIdType c = 0; c < traced->GetNumberOfCells(); ++c)
    {
      cellOfCurve[static_cast<int>(curveId->GetComponent(c, 0))] = c;
    }
    for (vtkIdType c = 0; c < action->GetNumberOfTuples(); ++c)
    {
      if (action->GetComponent(c, 0) != 2)
      {
        continue;
      }
      // Resolved cell c is traced as CurveId c; its original is the resolved cell whose
      // ResolutionSource is the same input curve and which was kept.
      const int original = static_cast<int>(source->GetComponent(c, 0));
      vtkIdType originalCell = -1;
      for (vtkIdType k = 0; k < action->GetNumberOfTuples(); ++k)
      {
        if (action->GetComponent(k, 0) == 0 && source->GetComponent(k, 0) == original)
        {
          originalCell = k;
        }
      }
      ASSERT_GE(originalCell, 0);
      const auto copy = TracedPoints(mesh, traced, cellOfCurve[static_cast<int>(c)]);
      const auto curve = TracedPoints(mesh, traced, cellOfCurve[static_cast<int>(originalCell)]);
      if (CurvesMeet(mesh, curve, curve, true))
      {
        ++selfCrossing; // a copy beside a curve that crosses itself meets its other branch
        continue;
      }
      ++checked;
      EXPECT_FALSE(CurvesMeet(mesh, copy, curve))
        << "the strip of curve " << original << " crosses it";
    }
  }
}

} // namespace

TEST(ResolveScenes, EveryStrategyMakesTheInconsistentScenesConsistent)
{
  const char* data = std::getenv("BOOLSURF_SHARED_DATA");
  const fs::path dir = data && *data ? fs::path(data) / "boolsurf-scenes" / "tests" : fs::path();
  if (dir.empty() || !fs::exists(dir / "examples" / "torus3.json"))
  {
    GTEST_SKIP() << "reference scenes not found (set BOOLSURF_SHARED_DATA); skipping";
  }
  const char* scenes[] = { "examples/torus3.json",
    "examples/torus4.json",
    "examples/torus4-reverse.json",
    "examples/torus5.json",
    "examples/torus7.json",
    "examples/torus8.json",
    "examples/torus9.json",
    "torus3.json",
    "torus4.json",
    "examples/tritorus-3loops.json",
    "examples/tritorus-5loops.json",
    "examples/tritorus-9loops.json",
    "examples/tritorus-13loops.json",
    "3torus-spiral-rev.json" };
  for (const char* scene : scenes)
  {
    for (int strategy = 0; strategy < 3; ++strategy)
    {
      CheckScene(dir / scene, strategy);
    }
  }
}

TEST(ResolveScenes, ConsistentShapesAreNoOpsAndBadStrategiesAreNamed)
{
  const double R = 3.0, r = 1.0;
  auto mesh = testutils::ToPolyData(MakeTorus(R, r, 48, 24));
  testutils::ControlPolygon small;
  small.ShapeId = 4;
  for (int k = 0; k < 6; ++k)
  {
    const double u = 3.0 + 0.15 * std::cos(2 * M_PI * k / 6),
                 v = 1.5 + 0.3 * std::sin(2 * M_PI * k / 6);
    small.Points.push_back({ (R + r * std::cos(v)) * std::cos(u),
      (R + r * std::cos(v)) * std::sin(u),
      r * std::sin(v) });
  }
  vtkNew<vtkBoolSurfResolve> resolve;
  resolve->SetInputData(0, mesh);
  resolve->SetInputData(1, testutils::ToCurves({ small }));
  resolve->SetStrategy(vtkBoolSurfResolve::ADD_GENERATORS);
  resolve->Update();
  vtkPolyData* out = resolve->GetOutput();
  ASSERT_EQ(out->GetNumberOfCells(), 1);
  EXPECT_EQ(out->GetCellData()->GetArray("Resolution")->GetComponent(0, 0), 0);
  EXPECT_EQ(out->GetFieldData()->GetArray("TreatedShapes"), nullptr);
  auto* notes =
    vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("ResolutionNotes"));
  ASSERT_NE(notes, nullptr);
  EXPECT_NE(notes->GetValue(0).find("shape S4: no generators in excess"), std::string::npos)
    << notes->GetValue(0);

  Catcher errors;
  errors.Watch(resolve, vtkCommand::ErrorEvent);
  resolve->SetShapeStrategies("4:Fill");
  resolve->Update();
  EXPECT_NE(errors.Text.find("'4:Fill'"), std::string::npos) << errors.Text;
  EXPECT_EQ(resolve->GetOutput()->GetNumberOfCells(), 0);
}
