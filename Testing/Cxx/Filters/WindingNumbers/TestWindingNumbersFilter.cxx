// Winding Numbers (vtkBoolSurfWindingNumbers) and BoolSurf's CloseBrokenShapes, through fresh
// VTK pipelines on a jittered flat square: a closed circle's winding number is its label and
// its completed curve is itself; a circle broken by gaps completes to nearly the same region,
// which BoolSurf then cuts exactly; the one-step option gives the chain's answer; bad input
// gets named errors; a torus meridian bounds nothing and is named.
#include "FilterTestUtils.h"
#include "vtkBoolSurf.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfSurfaceCurves.h"
#include "vtkBoolSurfWindingNumbers.h"

#include <vtkAppendPolyData.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
using testutils::ControlPolygon;

constexpr double Radius = 0.25;
constexpr int Legs = 48; // control points of the circle

std::array<double, 3> CirclePoint(int k)
{
  const double t = 2 * vtkMath::Pi() * k / Legs;
  return { 0.5 + Radius * std::cos(t), 0.5 + Radius * std::sin(t), 0.0 };
}

// The circle (counter-clockwise: its inside on the left) as one closed curve of shape 0.
ControlPolygon Circle()
{
  ControlPolygon c;
  for (int k = 0; k < Legs; ++k)
  {
    c.Points.push_back(CirclePoint(k));
  }
  return c;
}

// The circle broken by leaving out the legs that start at control points `gaps` (ascending):
// open curves of shape 0 through the remaining legs.
std::vector<ControlPolygon> BrokenCircle(const std::vector<int>& gaps)
{
  std::vector<ControlPolygon> pieces;
  for (std::size_t g = 0; g < gaps.size(); ++g)
  {
    const int from = gaps[g] + 1;
    const int to = g + 1 < gaps.size() ? gaps[g + 1] : gaps[0] + Legs;
    ControlPolygon piece;
    piece.Closed = false;
    for (int k = from; k <= to; ++k)
    {
      piece.Points.push_back(CirclePoint(k % Legs));
    }
    if (piece.Points.size() >= 2) // gaps side by side: one wider gap
    {
      pieces.push_back(piece);
    }
  }
  return pieces;
}

// An axis-aligned square of shape 1 across the circle's right side.
ControlPolygon Square()
{
  ControlPolygon s;
  s.ShapeId = 1;
  s.Points = { { 0.6, 0.3, 0 }, { 0.9, 0.3, 0 }, { 0.9, 0.6, 0 }, { 0.6, 0.6, 0 } };
  return s;
}

// The curves as Surface Curves writes them (exact surface points), so that curves appended to
// another filter's control curves keep their points bit for bit.
vtkSmartPointer<vtkPolyData> Drawing(vtkPolyData* mesh, const std::vector<ControlPolygon>& curves)
{
  vtkNew<vtkBoolSurfSurfaceCurves> drawing;
  drawing->SetInputData(mesh);
  int points = 0;
  for (const ControlPolygon& c : curves)
  {
    points += static_cast<int>(c.Points.size());
  }
  drawing->SetNumberOfPoints(points);
  drawing->SetNumberOfCurveSizes(static_cast<int>(curves.size()));
  drawing->SetNumberOfShapeIds(static_cast<int>(curves.size()));
  drawing->SetNumberOfClosedCurves(static_cast<int>(curves.size()));
  int i = 0;
  for (std::size_t c = 0; c < curves.size(); ++c)
  {
    for (const auto& p : curves[c].Points)
    {
      drawing->SetPoint(i++, p[0], p[1], p[2]);
    }
    drawing->SetCurveSize(static_cast<int>(c), static_cast<int>(curves[c].Points.size()));
    drawing->SetShapeId(static_cast<int>(c), curves[c].ShapeId);
    drawing->SetClosedCurve(static_cast<int>(c), curves[c].Closed ? 1 : 0);
  }
  EXPECT_EQ(testutils::ErrorsOf(drawing), "");
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(drawing->GetOutput());
  return out;
}

vtkSmartPointer<vtkPolyData> Append(vtkPolyData* a, vtkPolyData* b)
{
  vtkNew<vtkAppendPolyData> append;
  append->AddInputData(a);
  append->AddInputData(b);
  append->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(append->GetOutput());
  return out;
}

// The region of BoolSurf's `expression` over `curves` on `mesh`.
double BooleanArea(vtkPolyData* mesh,
  vtkPolyData* curves,
  const std::string& expression,
  const std::string& closeBroken = std::string())
{
  vtkNew<vtkBoolSurf> boolean;
  boolean->SetInputData(0, mesh);
  boolean->SetInputData(1, curves);
  boolean->SetOperationToExpression();
  boolean->SetExpression(expression.c_str());
  boolean->SetCloseBrokenShapes(closeBroken.c_str());
  EXPECT_EQ(testutils::ErrorsOf(boolean), "");
  return testutils::Area(boolean->GetOutput());
}

struct Fixture
{
  vtkSmartPointer<vtkPolyData> Mesh =
    testutils::ToPolyData(boolsurf::MakeFlatSquare(48, 1.0, 0.3, 5));
};

} // namespace

TEST(WindingNumbersFilter, ClosedCircleIsItsLabelAndItsOwnCompletion)
{
  Fixture f;
  vtkSmartPointer<vtkPolyData> curves = Drawing(f.Mesh, { Circle() });
  vtkNew<vtkStringArray> name;
  name->SetName("ShapeName");
  name->InsertNextValue("Disc");
  curves->GetCellData()->AddArray(name);
  vtkNew<vtkBoolSurfWindingNumbers> winding;
  winding->SetInputData(0, f.Mesh);
  winding->SetInputData(1, curves);
  ASSERT_EQ(testutils::ErrorsOf(winding), "");

  // Port 0: w per refined triangle is the label of its arrangement cell.
  vtkPolyData* refined = winding->GetOutput(0);
  vtkDataArray* cellW = refined->GetCellData()->GetArray("WindingNumber");
  vtkDataArray* pointW = refined->GetPointData()->GetArray("WindingNumber");
  vtkDataArray* cellOf = refined->GetCellData()->GetArray("ArrangementCell");
  ASSERT_TRUE(cellW && pointW && cellOf);
  ASSERT_EQ(cellW->GetNumberOfComponents(), 1);
  EXPECT_STREQ(cellW->GetComponentName(0), "Disc");
  EXPECT_EQ(pointW->GetNumberOfTuples(), refined->GetNumberOfPoints());
  ASSERT_TRUE(refined->GetFieldData()->GetArray("WindingShapeIds"));
  EXPECT_EQ(refined->GetFieldData()->GetArray("WindingShapeIds")->GetTuple1(0), 0);
  vtkNew<vtkBoolSurfLabeling> labeling;
  labeling->SetInputConnection(winding->GetOutputPort(0));
  ASSERT_EQ(testutils::ErrorsOf(labeling), "");
  vtkDataArray* labels = labeling->GetOutput()->GetFieldData()->GetArray("CellLabels");
  ASSERT_TRUE(labels);
  ASSERT_EQ(refined->GetNumberOfCells(), labeling->GetOutput()->GetNumberOfCells());
  int inside = 0;
  for (vtkIdType t = 0; t < refined->GetNumberOfCells(); ++t)
  {
    const double label = labels->GetComponent(static_cast<vtkIdType>(cellOf->GetTuple1(t)), 0);
    ASSERT_NEAR(cellW->GetTuple1(t), label, 1e-8) << "refined triangle " << t;
    inside += label == 1 ? 1 : 0;
  }
  EXPECT_GT(inside, 0);
  vtkDataArray* means = refined->GetFieldData()->GetArray("CellWindingNumber");
  ASSERT_TRUE(means);
  for (vtkIdType c = 0; c < means->GetNumberOfTuples(); ++c)
  {
    EXPECT_NEAR(means->GetTuple1(c), labels->GetComponent(c, 0), 1e-8) << "cell " << c;
  }

  // Port 1: the region is BoolSurf's.
  const double booleanArea = BooleanArea(f.Mesh, curves, "S0");
  const double regionArea = testutils::Area(winding->GetOutput(1));
  EXPECT_NEAR(regionArea, booleanArea, 1e-9);
  EXPECT_NEAR(regionArea, vtkMath::Pi() * Radius * Radius, 0.01 * regionArea); // inscribed
  EXPECT_TRUE(winding->GetOutput(1)->GetCellData()->GetArray("WindingNumber"));
  EXPECT_TRUE(winding->GetOutput(1)->GetCellData()->GetArray("SourceTriangle"));

  // Port 2: one closed loop, the circle itself, keeping its shape and name; through BoolSurf
  // the same region.
  vtkPolyData* completed = winding->GetOutput(2);
  ASSERT_EQ(completed->GetNumberOfCells(), 1);
  EXPECT_EQ(completed->GetCellData()->GetArray("ShapeId")->GetTuple1(0), 0);
  EXPECT_EQ(completed->GetCellData()->GetArray("Closed")->GetTuple1(0), 1);
  EXPECT_EQ(completed->GetCellData()->GetArray("CurveType")->GetTuple1(0), 0);
  EXPECT_TRUE(completed->GetPointData()->GetArray("TriangleId"));
  EXPECT_TRUE(completed->GetPointData()->GetArray("Barycentric"));
  auto* names =
    vtkStringArray::SafeDownCast(completed->GetCellData()->GetAbstractArray("ShapeName"));
  ASSERT_TRUE(names);
  EXPECT_EQ(names->GetValue(0), "Disc");
  EXPECT_NEAR(BooleanArea(f.Mesh, completed, "S0"), booleanArea, 1e-9);

  // Port 3: the closed circle bounds its region exactly.
  vtkPolyData* traced = winding->GetOutput(3);
  ASSERT_EQ(traced->GetNumberOfCells(), 1);
  EXPECT_NEAR(traced->GetCellData()->GetArray("WindingResidual")->GetTuple1(0), 0, 1e-6);
  EXPECT_EQ(traced->GetCellData()->GetArray("BoundsRegion")->GetTuple1(0), 1);
  EXPECT_EQ(traced->GetFieldData()->GetArray("NonBoundingCurves"), nullptr);
}

TEST(WindingNumbersFilter, BrokenCircleCompletesToTheClosedRegion)
{
  Fixture f;
  const double closedArea = BooleanArea(f.Mesh, Drawing(f.Mesh, { Circle() }), "S0");
  // One gap (2% of the length), two gaps (4%), two gaps side by side (a gap of 4%).
  for (const std::vector<int>& gaps :
    { std::vector<int>{ 5 }, std::vector<int>{ 5, 29 }, std::vector<int>{ 10, 11 } })
  {
    SCOPED_TRACE("gaps after control points " + std::to_string(gaps[0]) +
      (gaps.size() > 1 ? " and " + std::to_string(gaps[1]) : std::string()));
    vtkNew<vtkBoolSurfWindingNumbers> winding;
    winding->SetInputData(0, f.Mesh);
    const std::vector<ControlPolygon> pieces = BrokenCircle(gaps);
    winding->SetInputData(1, Drawing(f.Mesh, pieces));
    ASSERT_EQ(testutils::ErrorsOf(winding), "");
    const double regionArea = testutils::Area(winding->GetOutput(1));
    EXPECT_NEAR(regionArea, closedArea, 0.01 * closedArea);

    vtkPolyData* completed = winding->GetOutput(2);
    ASSERT_GE(completed->GetNumberOfCells(), 1);
    const double completedArea = BooleanArea(f.Mesh, completed, "S0");
    EXPECT_NEAR(completedArea, regionArea, 0.01 * regionArea);

    // The open pieces bound the region but for their ends' share.
    vtkPolyData* traced = winding->GetOutput(3);
    vtkDataArray* residual = traced->GetCellData()->GetArray("WindingResidual");
    vtkDataArray* bounds = traced->GetCellData()->GetArray("BoundsRegion");
    ASSERT_TRUE(residual && bounds);
    ASSERT_EQ(traced->GetNumberOfCells(), static_cast<vtkIdType>(pieces.size()));
    for (vtkIdType c = 0; c < traced->GetNumberOfCells(); ++c)
    {
      EXPECT_GE(residual->GetTuple1(c), 0);
      EXPECT_LT(residual->GetTuple1(c), 0.5);
      EXPECT_EQ(bounds->GetTuple1(c), 1);
    }
  }
}

TEST(WindingNumbersFilter, OneStepCloseBrokenShapesMatchesTheChain)
{
  Fixture f;
  const std::vector<ControlPolygon> broken = BrokenCircle({ 5, 29 });
  std::vector<ControlPolygon> all = broken;
  all.push_back(Square());
  vtkSmartPointer<vtkPolyData> square = Drawing(f.Mesh, { Square() });

  // The chain: Winding Numbers of the broken circle alone, its completed curves beside the
  // square, BoolSurf.
  vtkNew<vtkBoolSurfWindingNumbers> winding;
  winding->SetInputData(0, f.Mesh);
  winding->SetInputData(1, Drawing(f.Mesh, broken));
  ASSERT_EQ(testutils::ErrorsOf(winding), "");
  vtkSmartPointer<vtkPolyData> chained = Append(winding->GetOutput(2), square);
  // One step: BoolSurf completes shape 0 itself.
  vtkSmartPointer<vtkPolyData> drawing = Drawing(f.Mesh, all);
  for (const char* expression : { "S0 | S1", "S0 & S1", "S0 - S1" })
  {
    SCOPED_TRACE(expression);
    const double chain = BooleanArea(f.Mesh, chained, expression);
    const double oneStep = BooleanArea(f.Mesh, drawing, expression, "0");
    EXPECT_GT(chain, 0);
    EXPECT_NEAR(oneStep, chain, 1e-12);
  }

  // The replaced curves are named with their residuals.
  vtkNew<vtkBoolSurf> boolean;
  boolean->SetInputData(0, f.Mesh);
  boolean->SetInputData(1, drawing);
  boolean->SetCloseBrokenShapes("0");
  boolean->SetShapeA(0);
  boolean->SetShapeB(1);
  ASSERT_EQ(testutils::ErrorsOf(boolean), "");
  auto* notes = vtkStringArray::SafeDownCast(
    boolean->GetOutput()->GetFieldData()->GetAbstractArray("WindingNotes"));
  ASSERT_TRUE(notes);
  ASSERT_EQ(notes->GetNumberOfValues(), 2);
  EXPECT_NE(notes->GetValue(0).find("curve 0 of shape 0"), std::string::npos) << notes->GetValue(0);
  EXPECT_NE(notes->GetValue(0).find("residual"), std::string::npos);

  // A shape no curve has (in a drawing, a shape not drawn yet is nothing to complete).
  boolean->SetCloseBrokenShapes("0 4");
  EXPECT_EQ(testutils::ErrorsOf(boolean), "");
  std::vector<ControlPolygon> plain = BrokenCircle({ 5, 29 });
  plain.push_back(Square());
  boolean->SetInputData(1, testutils::ToCurves(plain));
  boolean->SetCloseBrokenShapes("4");
  EXPECT_NE(testutils::ErrorsOf(boolean).find("shape 4"), std::string::npos);
  boolean->SetCloseBrokenShapes("zero");
  EXPECT_NE(testutils::ErrorsOf(boolean).find("'zero'"), std::string::npos);
}

TEST(WindingNumbersFilter, BadInputIsNamed)
{
  Fixture f;
  vtkNew<vtkBoolSurfWindingNumbers> winding;
  winding->SetInputData(0, f.Mesh);

  // No curves.
  vtkNew<vtkPolyData> empty;
  winding->SetInputData(1, empty);
  EXPECT_NE(testutils::ErrorsOf(winding), "");
  EXPECT_EQ(winding->GetOutput(0)->GetNumberOfCells(), 0);

  // A shape id no curve has, and one that is not a number.
  winding->SetInputData(1, testutils::ToCurves({ Circle() }));
  winding->SetShapes("3");
  std::string errors = testutils::ErrorsOf(winding);
  EXPECT_NE(errors.find("shape 3"), std::string::npos) << errors;
  for (int port = 0; port < 4; ++port)
  {
    EXPECT_EQ(winding->GetOutput(port)->GetNumberOfCells(), 0) << "port " << port;
  }
  winding->SetShapes("S0, x");
  errors = testutils::ErrorsOf(winding);
  EXPECT_NE(errors.find("'x'"), std::string::npos) << errors;
  winding->SetShapes("");
  winding->SetThreshold(std::nan(""));
  EXPECT_NE(testutils::ErrorsOf(winding).find("Threshold"), std::string::npos);
  winding->SetThreshold(0.5);
  EXPECT_EQ(testutils::ErrorsOf(winding), "");

  // A curve of one point: left out with a warning naming it; alone, nothing is left.
  ControlPolygon dot;
  dot.Closed = false;
  dot.ShapeId = 2;
  dot.Points = { { 0.1, 0.1, 0 } };
  vtkNew<testutils::MessageCatcher> catcher;
  winding->AddObserver(vtkCommand::WarningEvent, catcher);
  winding->SetInputData(1, testutils::ToCurves({ dot, Circle() }));
  EXPECT_EQ(testutils::ErrorsOf(winding), "");
  EXPECT_NE(catcher->Warnings.find("curve 0"), std::string::npos) << catcher->Warnings;
  winding->SetInputData(1, testutils::ToCurves({ dot }));
  EXPECT_NE(testutils::ErrorsOf(winding), "");

  // A NaN control point: the curve is named.
  ControlPolygon bad = Circle();
  bad.Points[3][1] = std::nan("");
  winding->SetInputData(1, testutils::ToCurves({ bad }));
  errors = testutils::ErrorsOf(winding);
  EXPECT_NE(errors.find("NaN"), std::string::npos) << errors;
  EXPECT_NE(errors.find("curve 0"), std::string::npos) << errors;
}

TEST(WindingNumbersFilter, TorusMeridianBoundsNothing)
{
  const double R = 1.0, r = 0.4;
  const int nu = 48, nv = 24;
  vtkSmartPointer<vtkPolyData> torus = testutils::ToPolyData(boolsurf::MakeTorus(R, r, nu, nv));
  ControlPolygon meridian;
  for (int k = 0; k < nv; ++k)
  {
    const double v = 2 * vtkMath::Pi() * k / nv;
    meridian.Points.push_back({ R + r * std::cos(v), 0.0, r * std::sin(v) });
  }
  vtkNew<vtkBoolSurfWindingNumbers> winding;
  winding->SetInputData(0, torus);
  winding->SetInputData(1, testutils::ToCurves({ meridian }));
  vtkNew<testutils::MessageCatcher> catcher;
  winding->AddObserver(vtkCommand::WarningEvent, catcher);
  ASSERT_EQ(testutils::ErrorsOf(winding), "");
  EXPECT_NE(catcher->Warnings.find("curve 0 of shape 0 bounds nothing"), std::string::npos)
    << catcher->Warnings;
  vtkPolyData* traced = winding->GetOutput(3);
  EXPECT_EQ(traced->GetCellData()->GetArray("BoundsRegion")->GetTuple1(0), 0);
  vtkDataArray* listed = traced->GetFieldData()->GetArray("NonBoundingCurves");
  ASSERT_TRUE(listed);
  ASSERT_EQ(listed->GetNumberOfTuples(), 1);
  EXPECT_EQ(listed->GetComponent(0, 0), 0);
  EXPECT_EQ(listed->GetComponent(0, 1), 0);
  EXPECT_EQ(winding->GetOutput(1)->GetNumberOfCells(), 0); // no region
}
