// vtkBoolSurfSVGMapper: every shared SVG mapped onto bunny, bimba and igea goes through the
// one-step Boolean without an error (warnings counted); the output is control curves of the
// API (cubic Beziers, ShapeId per SVG element, exact surface points); bad input is named.
#include "vtkBoolSurf.h"
#include "vtkBoolSurfSVGMapper.h"

#include "FilterTestUtils.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>

#include <vtkMath.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace
{
namespace fs = std::filesystem;

fs::path SharedData()
{
  const char* data = std::getenv("BOOLSURF_SHARED_DATA");
  return data && *data ? fs::path(data) : fs::path();
}
} // namespace

TEST(SvgMapperFilter, EverySharedSvgOnBunnyBimbaIgea)
{
  const fs::path data = SharedData();
  if (data.empty() || !fs::is_directory(data / "boolsurf-scenes" / "svgs"))
  {
    GTEST_SKIP() << "BOOLSURF_SHARED_DATA is not set or has no boolsurf-scenes/svgs: the "
                    "shared SVGs and meshes are needed";
  }
  std::vector<fs::path> svgs;
  for (const auto& e : fs::recursive_directory_iterator(data / "boolsurf-scenes" / "svgs"))
  {
    if (e.path().extension() == ".svg")
    {
      svgs.push_back(e.path());
    }
  }
  std::sort(svgs.begin(), svgs.end());
  ASSERT_GE(svgs.size(), 36u);
  int runs = 0, warned = 0, filled = 0;
  for (const char* name : { "bunny_boolsurf.ply", "bimba.ply", "igea.ply" })
  {
    vtkNew<vtkPLYReader> reader;
    reader->SetFileName((data / "meshes" / name).string().c_str());
    reader->Update();
    vtkPolyData* mesh = reader->GetOutput();
    ASSERT_GT(mesh->GetNumberOfCells(), 0) << name;
    vtkNew<vtkBoolSurfSVGMapper> mapper;
    mapper->SetInputData(mesh);
    mapper->SetCenterTriangleId(mesh->GetNumberOfCells() / 2);
    vtkNew<vtkBoolSurf> boolean;
    boolean->SetInputData(0, mesh);
    boolean->SetInputConnection(1, mapper->GetOutputPort());
    boolean->SetResolution(1);
    boolean->SetShapeA(-1); // the union of every shape of the drawing
    boolean->SetShapeB(-1);
    for (const fs::path& svg : svgs)
    {
      SCOPED_TRACE(std::string(name) + " " + svg.filename().string());
      mapper->SetFileName(svg.string().c_str());
      ASSERT_EQ(testutils::ErrorsOf(mapper), "");
      vtkPolyData* curves = mapper->GetOutput();
      ASSERT_GT(curves->GetNumberOfCells(), 0);
      ASSERT_NE(curves->GetPointData()->GetArray("TriangleId"), nullptr);
      EXPECT_EQ(curves->GetCellData()->GetArray("CurveType")->GetRange()[0], 1);
      warned += curves->GetFieldData()->GetAbstractArray("SvgWarnings") ? 1 : 0;
      EXPECT_EQ(testutils::ErrorsOf(boolean), "");
      filled += boolean->GetOutput()->GetNumberOfCells() > 0 ? 1 : 0;
      ++runs;
    }
  }
  EXPECT_EQ(runs, 3 * static_cast<int>(svgs.size()));
  // Open drawings (polylines) fill nothing; most drawings have closed shapes.
  EXPECT_GT(filled, runs * 3 / 4) << filled << " of " << runs << " unions are not empty";
  RecordProperty("NonEmptyUnions", filled);
  RecordProperty("RunsWithWarnings", warned);
}

TEST(SvgMapperFilter, OutputAndBadInput)
{
  auto sphere = testutils::ToPolyData(boolsurf::MakeIcosphere(3));
  const fs::path file = fs::temp_directory_path() / "boolsurf-svg-mapper-test.svg";
  std::ofstream(file)
    << "<svg xmlns='http://www.w3.org/2000/svg'><path d='M0 0 H10 V10 H0 Z "
       "M3 3 V7 H7 V3 Z' fill-rule='evenodd'/><circle cx='20' cy='5' r='3'/></svg>";
  vtkNew<vtkBoolSurfSVGMapper> mapper;
  mapper->SetInputData(sphere);
  mapper->SetFileName(file.string().c_str());
  mapper->SetCenter(0, 0, 1);
  mapper->SetRadius(0.5);
  ASSERT_EQ(testutils::ErrorsOf(mapper), "");
  vtkPolyData* out = mapper->GetOutput();
  ASSERT_EQ(out->GetNumberOfCells(), 3); // outer square, hole, circle
  // The circle is a closed spline of 4 cubic segments: 12 control points and the closing
  // repeat, none repeated before (it was 7 segments, the first 4 control points coincident).
  {
    vtkIdType n;
    const vtkIdType* ids;
    out->GetCellPoints(2, n, ids);
    ASSERT_EQ(n, 13);
    for (vtkIdType i = 0; i + 1 < n; ++i)
    {
      double a[3], b[3];
      out->GetPoint(ids[i], a);
      out->GetPoint(ids[i + 1], b);
      EXPECT_GT(std::sqrt(vtkMath::Distance2BetweenPoints(a, b)), 1e-3)
        << "control points " << i << " and " << i + 1 << " of the circle coincide";
    }
  }
  vtkDataArray* shape = out->GetCellData()->GetArray("ShapeId");
  EXPECT_EQ(shape->GetComponent(0, 0), shape->GetComponent(1, 0)); // a glyph with a hole
  EXPECT_NE(shape->GetComponent(0, 0), shape->GetComponent(2, 0));
  auto* rule =
    vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("SuggestedFillRule"));
  ASSERT_NE(rule, nullptr);
  EXPECT_EQ(rule->GetValue(0), "NonZero"); // the circle is nonzero
  // The square with its hole under even-odd is an annulus: a smaller area than the square.
  vtkNew<vtkBoolSurf> boolean;
  boolean->SetInputData(0, sphere);
  boolean->SetInputConnection(1, mapper->GetOutputPort());
  boolean->SetOperationToExpression();
  boolean->SetExpression(
    ("S" + std::to_string(static_cast<int>(shape->GetComponent(0, 0)))).c_str());
  boolean->SetFillRule(1); // even-odd
  ASSERT_EQ(testutils::ErrorsOf(boolean), "");
  const double annulus = testutils::Area(boolean->GetOutput());
  EXPECT_GT(annulus, 0);
  EXPECT_LT(annulus, 0.5 * 4 * std::acos(-1.0)); // less than half the sphere: the inside

  mapper->SetFileName("no/such/drawing.svg");
  EXPECT_NE(testutils::ErrorsOf(mapper).find("cannot open"), std::string::npos);
  EXPECT_EQ(mapper->GetOutput()->GetNumberOfCells(), 0);
  mapper->SetFileName(file.string().c_str());
  mapper->SetCenterTriangleId(100000);
  EXPECT_NE(testutils::ErrorsOf(mapper).find("CenterTriangleId 100000"), std::string::npos);
  fs::remove(file);
}

TEST(SvgMapperFilter, FarCenterIsProjectedWithAWarning)
{
  // Center (50, 50, 50) on the unit sphere still maps the drawing, around the nearest surface
  // point, and says how far the center was; a center on the surface, or ParaView's default
  // (the middle of the bounds), says nothing.
  auto sphere = testutils::ToPolyData(boolsurf::MakeIcosphere(3));
  const fs::path file = fs::temp_directory_path() / "boolsurf-svg-far-center.svg";
  std::ofstream(file) << "<svg xmlns='http://www.w3.org/2000/svg'><rect x='0' y='0' "
                         "width='10' height='10'/></svg>";
  auto warningsOf = [&](double x, double y, double z)
  {
    vtkNew<vtkBoolSurfSVGMapper> mapper;
    mapper->SetInputData(sphere);
    mapper->SetFileName(file.string().c_str());
    mapper->SetCenter(x, y, z);
    mapper->SetRadius(0.2);
    EXPECT_EQ(testutils::ErrorsOf(mapper), "");
    EXPECT_EQ(mapper->GetOutput()->GetNumberOfCells(), 1);
    auto* notes = vtkStringArray::SafeDownCast(
      mapper->GetOutput()->GetFieldData()->GetAbstractArray("SvgWarnings"));
    std::string text;
    for (vtkIdType i = 0; notes && i < notes->GetNumberOfValues(); ++i)
    {
      text += notes->GetValue(i) + "\n";
    }
    // The drawing is around the nearest surface point: its points are on the ray's side.
    vtkPolyData* out = mapper->GetOutput();
    double p[3];
    out->GetPoint(0, p);
    EXPECT_GE(p[0] * x + p[1] * y + p[2] * z, 0);
    return text;
  };
  const std::string far = warningsOf(50, 50, 50);
  // |(50, 50, 50)| - 1 = 85.60 (the icosphere's facets are a little inside the unit sphere),
  // 2471% of the bounding-box diagonal 2 sqrt(3).
  EXPECT_NE(far.find("Center (50, 50, 50) is 85.6"), std::string::npos) << far;
  EXPECT_NE(far.find("(2471.3% of its bounding-box diagonal)"), std::string::npos) << far;
  EXPECT_EQ(warningsOf(0, 0, 1), "");
  EXPECT_EQ(warningsOf(0, 0, 1.005), ""); // within 1% of the diagonal
  EXPECT_EQ(warningsOf(0, 0, 0), "");     // the middle of the bounds: ParaView's default
  EXPECT_NE(warningsOf(0, 0, 1.1).find("is 0.1"), std::string::npos);
  fs::remove(file);
}
