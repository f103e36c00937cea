// The random SVG benchmark's largest drawings scaled down onto a coarse flat mesh, so that
// hundreds of curve pieces cross single mesh triangles (issue 28's crowded triangles, from
// real drawings rather than lattices). On a flat mesh the traced curves are planar polylines,
// so the Boolean's area must be Clipper's for the same polylines, shape by shape under the
// drawing's fill rule, for every operation. Needs the shared SVGs; skips without them.
#include "ClipperOracle.h"
#include "FilterTestUtils.h"
#include "vtkBoolSurf.h"
#include "vtkBoolSurfSVGMapper.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkAppendPolyData.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>

namespace fs = std::filesystem;

namespace
{
fs::path SharedSvgs()
{
  const char* data = std::getenv("BOOLSURF_SHARED_DATA");
  return data && *data ? fs::path(data) / "boolsurf-scenes" / "svgs" : fs::path();
}

std::string UnionOfShapes(const std::set<int>& shapes)
{
  std::string text = "(";
  for (int s : shapes)
  {
    text += (text.size() > 1 ? " | S" : "S") + std::to_string(s);
  }
  return text + ")";
}

/// The closed traced curves of each shape, in Clipper's coordinates.
std::map<int, ClipperLib::Paths> TracedPathsByShape(vtkPolyData* traced)
{
  std::map<int, ClipperLib::Paths> paths;
  vtkDataArray* shape = traced->GetCellData()->GetArray("ShapeId");
  vtkDataArray* closed = traced->GetCellData()->GetArray("Closed");
  auto it = vtk::TakeSmartPointer(traced->GetLines()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    const vtkIdType c = it->GetCurrentCellId();
    if (closed->GetComponent(c, 0) == 0)
    {
      continue;
    }
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    ClipperLib::Path path;
    for (vtkIdType i = 0; i + 1 < n; ++i) // a closed polyline repeats its first point
    {
      const double* x = traced->GetPoint(ids[i]);
      path.push_back(testutils::ToClipper(x[0], x[1]));
    }
    paths[static_cast<int>(shape->GetComponent(c, 0))].push_back(path);
  }
  return paths;
}

/// The union over `shapes` of each shape's inside under `rule` (Clipper's answer).
ClipperLib::Paths UnionOf(const std::map<int, ClipperLib::Paths>& byShape,
  const std::set<int>& shapes,
  ClipperLib::PolyFillType rule)
{
  ClipperLib::Paths all;
  for (int s : shapes)
  {
    auto found = byShape.find(s);
    if (found == byShape.end())
    {
      continue;
    }
    ClipperLib::Clipper clipper;
    clipper.AddPaths(found->second, ClipperLib::ptSubject, true);
    ClipperLib::Paths inside;
    clipper.Execute(ClipperLib::ctUnion, inside, rule, rule);
    all.insert(all.end(), inside.begin(), inside.end());
  }
  ClipperLib::Clipper clipper;
  clipper.AddPaths(all, ClipperLib::ptSubject, true);
  ClipperLib::Paths merged;
  clipper.Execute(ClipperLib::ctUnion, merged, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return merged;
}
} // namespace

TEST(ScaledSvgDrawings, CrowdedTrianglesMatchClipper)
{
  const fs::path svgs = SharedSvgs();
  if (svgs.empty() || !fs::exists(svgs / "tiger.svg") || !fs::exists(svgs / "chrome.svg"))
  {
    GTEST_SKIP() << "BOOLSURF_SHARED_DATA is not set or has no boolsurf-scenes/svgs: the "
                    "shared SVGs are needed";
  }
  // 8 x 8 squares, two triangles each; the drawings cover most of them.
  vtkSmartPointer<vtkPolyData> mesh = testutils::ToPolyData(boolsurf::MakeFlatSquare(8, 1.0));
  struct Pair
  {
    const char* A;
    const char* B;
  };
  // The benchmark's slowest trials: tiger and chrome (curves drawn twice, crossing each other
  // hundreds of times), tiger and siggraph-logo-simple.
  for (const Pair& pair :
    { Pair{ "tiger.svg", "chrome.svg" }, Pair{ "siggraph-logo-simple.svg", "tiger.svg" } })
  {
    SCOPED_TRACE(std::string(pair.A) + " and " + pair.B);
    vtkNew<vtkBoolSurfSVGMapper> a, b;
    for (vtkBoolSurfSVGMapper* drawing : { a.Get(), b.Get() })
    {
      drawing->SetInputData(mesh);
      drawing->SetCenter(0.5, 0.5, 0.0);
    }
    a->SetFileName((svgs / pair.A).string().c_str());
    a->SetRadius(0.45);
    b->SetFileName((svgs / pair.B).string().c_str());
    b->SetRadius(0.4);
    b->SetRotation(30);
    b->SetShapeIdOffset(100000);
    ASSERT_EQ(testutils::ErrorsOf(a), "");
    ASSERT_EQ(testutils::ErrorsOf(b), "");
    for (vtkBoolSurfSVGMapper* drawing : { a.Get(), b.Get() })
    {
      EXPECT_EQ(drawing->GetOutput()->GetFieldData()->GetAbstractArray("SvgWarnings"), nullptr)
        << "the drawing must lie inside the square (no point stopped at its boundary)";
    }
    vtkNew<vtkAppendPolyData> both;
    both->AddInputConnection(a->GetOutputPort());
    both->AddInputConnection(b->GetOutputPort());
    std::set<int> shapesA, shapesB;
    for (auto [drawing, shapes] : { std::make_pair(a.Get(), &shapesA), { b.Get(), &shapesB } })
    {
      vtkDataArray* ids = drawing->GetOutput()->GetCellData()->GetArray("ShapeId");
      for (vtkIdType c = 0; c < ids->GetNumberOfTuples(); ++c)
      {
        shapes->insert(static_cast<int>(ids->GetComponent(c, 0)));
      }
    }

    // The traced polylines, as the one-step filter traces them (same defaults).
    vtkNew<vtkBoolSurfTraceCurves> trace;
    trace->SetInputData(0, mesh);
    trace->SetInputConnection(1, both->GetOutputPort());
    ASSERT_EQ(testutils::ErrorsOf(trace), "");
    vtkPolyData* traced = trace->GetOutput();
    // Crowded triangles: points of the traced curves per mesh triangle.
    std::map<vtkIdType, int> perTriangle;
    vtkDataArray* triangle = traced->GetPointData()->GetArray("TriangleId");
    for (vtkIdType p = 0; p < triangle->GetNumberOfTuples(); ++p)
    {
      ++perTriangle[static_cast<vtkIdType>(triangle->GetComponent(p, 0))];
    }
    int crowded = 0;
    for (const auto& entry : perTriangle)
    {
      crowded = std::max(crowded, entry.second);
    }
    EXPECT_GT(crowded, 200) << "the drawings are not crowded enough to test crowded triangles";
    RecordProperty(std::string("MostPointsInOneTriangle_") + pair.A, crowded);
    const std::map<int, ClipperLib::Paths> byShape = TracedPathsByShape(traced);

    const char* symbols[] = { " | ", " & ", " - ", " ^ " };
    const ClipperLib::ClipType ops[] = {
      ClipperLib::ctUnion, ClipperLib::ctIntersection, ClipperLib::ctDifference, ClipperLib::ctXor
    };
    vtkNew<vtkBoolSurf> boolean;
    boolean->SetInputData(0, mesh);
    boolean->SetInputConnection(1, both->GetOutputPort());
    boolean->SetOperationToExpression();
    boolean->ComputeControlCurvesOff(); // the regions are checked here, not the vector output
    for (int rule = 0; rule < 2; ++rule)
    {
      const ClipperLib::PolyFillType fill = rule ? ClipperLib::pftEvenOdd : ClipperLib::pftNonZero;
      const ClipperLib::Paths inA = UnionOf(byShape, shapesA, fill);
      const ClipperLib::Paths inB = UnionOf(byShape, shapesB, fill);
      for (int op = 0; op < 4; ++op)
      {
        SCOPED_TRACE(std::string(rule ? "even-odd" : "non-zero") + symbols[op]);
        boolean->SetFillRule(rule);
        boolean->SetExpression(
          (UnionOfShapes(shapesA) + symbols[op] + UnionOfShapes(shapesB)).c_str());
        ASSERT_EQ(testutils::ErrorsOf(boolean), "");
        ClipperLib::Clipper clipper;
        clipper.AddPaths(inA, ClipperLib::ptSubject, true);
        clipper.AddPaths(inB, ClipperLib::ptClip, true);
        ClipperLib::Paths result;
        clipper.Execute(ops[op], result, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
        const double expected = testutils::ClipperArea(result);
        EXPECT_GT(expected, 1e-3);
        EXPECT_NEAR(testutils::Area(boolean->GetOutput()), expected, 1e-9);
      }
    }
  }
}
