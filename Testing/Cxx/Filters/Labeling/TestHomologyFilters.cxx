// Homology through the filters: the arrangement writes each curve's class and the generators,
// the labeling sums them per shape (HomologyExcess), explains inconsistent shapes in its warning
// and draws the generators on port 1. Procedural torus (no shared data) and sphere (genus 0).
#include "FilterTestUtils.h"

#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>

#include <gtest/gtest.h>

#include <cmath>

using testutils::ControlPolygon;

namespace
{

// Closed curve around the tube of the torus (R, r) at angle u around the axis; `reverse` walks
// it the other way.
ControlPolygon Meridian(double R, double r, double u, int shape, bool reverse)
{
  ControlPolygon c;
  c.ShapeId = shape;
  for (int k = 0; k < 12; ++k)
  {
    const double v = 2 * M_PI * (reverse ? 12 - k : k) / 12.0;
    c.Points.push_back({ (R + r * std::cos(v)) * std::cos(u),
      (R + r * std::cos(v)) * std::sin(u),
      r * std::sin(v) });
  }
  return c;
}

struct Pipeline
{
  vtkNew<vtkBoolSurfTraceCurves> Trace;
  vtkNew<vtkBoolSurfArrangement> Arrange;
  vtkNew<vtkBoolSurfLabeling> Label;
  vtkNew<vtkCallbackCommand> Catcher;
  std::string Warnings;

  Pipeline(vtkPolyData* surface, vtkPolyData* curves)
  {
    this->Trace->SetInputData(0, surface);
    this->Trace->SetInputData(1, curves);
    this->Arrange->SetInputData(0, surface);
    this->Arrange->SetInputConnection(1, this->Trace->GetOutputPort());
    this->Label->SetInputConnection(this->Arrange->GetOutputPort(0));
    this->Catcher->SetClientData(&this->Warnings);
    this->Catcher->SetCallback([](vtkObject*, unsigned long, void* text, void* data)
      { *static_cast<std::string*>(text) += static_cast<const char*>(data); });
    this->Label->AddObserver(vtkCommand::WarningEvent, this->Catcher);
    this->Label->Update();
  }
  vtkFieldData* Fields() { return this->Label->GetOutput(0)->GetFieldData(); }
};

} // namespace

TEST(HomologyFilters, TorusMeridianExcessExplainedAndGeneratorsDrawn)
{
  const double R = 3.0, r = 1.0;
  auto mesh = testutils::ToPolyData(boolsurf::MakeTorus(R, r, 48, 24));
  // Shape 0: one meridian (inconsistent). Shape 1: a meridian and another one reversed (a
  // band: consistent although each curve winds). Shape 2: a small loop (class zero).
  ControlPolygon small;
  small.ShapeId = 2;
  for (int k = 0; k < 6; ++k)
  {
    const double u = 3.0 + 0.15 * std::cos(2 * M_PI * k / 6),
                 v = 1.5 + 0.3 * std::sin(2 * M_PI * k / 6);
    small.Points.push_back({ (R + r * std::cos(v)) * std::cos(u),
      (R + r * std::cos(v)) * std::sin(u),
      r * std::sin(v) });
  }
  auto curves = testutils::ToCurves({ Meridian(R, r, 0.2, 0, false),
    Meridian(R, r, 1.0, 1, false),
    Meridian(R, r, 1.8, 1, true),
    small });
  Pipeline p(mesh, curves);
  vtkFieldData* fd = p.Fields();

  vtkDataArray* count = fd->GetArray("NumberOfHomologyGenerators");
  ASSERT_NE(count, nullptr);
  EXPECT_EQ(count->GetComponent(0, 0), 2);
  vtkDataArray* classes = fd->GetArray("CurveHomology");
  ASSERT_NE(classes, nullptr);
  ASSERT_EQ(classes->GetNumberOfTuples(), 4);
  ASSERT_EQ(classes->GetNumberOfComponents(), 2);
  // The meridians have the same nonzero class (the reversed one the opposite); the small loop 0.
  for (int g = 0; g < 2; ++g)
  {
    EXPECT_EQ(classes->GetComponent(1, g), classes->GetComponent(0, g));
    EXPECT_EQ(classes->GetComponent(2, g), -classes->GetComponent(0, g));
    EXPECT_EQ(classes->GetComponent(3, g), 0);
  }
  EXPECT_NE(std::abs(classes->GetComponent(0, 0)) + std::abs(classes->GetComponent(0, 1)), 0);

  vtkDataArray* excess = fd->GetArray("HomologyExcess");
  vtkDataArray* consistent = fd->GetArray("ShapeConsistent");
  ASSERT_NE(excess, nullptr);
  ASSERT_NE(consistent, nullptr);
  ASSERT_EQ(excess->GetNumberOfTuples(), 3);
  for (int s = 0; s < 3; ++s)
  {
    const bool zero = excess->GetComponent(s, 0) == 0 && excess->GetComponent(s, 1) == 0;
    EXPECT_EQ(consistent->GetComponent(s, 0) != 0, zero) << "shape " << s;
  }
  EXPECT_EQ(consistent->GetComponent(0, 0), 0);
  EXPECT_EQ(consistent->GetComponent(1, 0), 1);
  EXPECT_EQ(consistent->GetComponent(2, 0), 1);

  // The warning names the curve, its generators and the fixes; not the consistent shapes.
  EXPECT_NE(p.Warnings.find("Shape S0: curve 0 winds"), std::string::npos) << p.Warnings;
  EXPECT_NE(p.Warnings.find("x G"), std::string::npos) << p.Warnings;
  for (const char* fix : { "AddGenerators", "DuplicateReversed", "RemoveCurves" })
  {
    EXPECT_NE(p.Warnings.find(fix), std::string::npos) << p.Warnings;
  }
  EXPECT_EQ(p.Warnings.find("Shape S1"), std::string::npos) << p.Warnings;

  // Port 1: two closed generator loops on the surface.
  // (plus their shortened loops, cell data Shortened = 1).
  vtkPolyData* generators = p.Label->GetOutput(1);
  vtkDataArray* shortened = generators->GetCellData()->GetArray("Shortened");
  ASSERT_NE(shortened, nullptr);
  int loops = 0, short_loops = 0;
  for (vtkIdType c = 0; c < generators->GetNumberOfCells(); ++c)
  {
    (shortened->GetComponent(c, 0) != 0 ? short_loops : loops)++;
  }
  EXPECT_EQ(loops, 2);
  EXPECT_EQ(short_loops, 2);
  ASSERT_NE(generators->GetCellData()->GetArray("GeneratorId"), nullptr);
  ASSERT_NE(generators->GetPointData()->GetArray("TriangleId"), nullptr);
  ASSERT_NE(generators->GetPointData()->GetArray("Barycentric"), nullptr);
  EXPECT_GT(generators->GetNumberOfPoints(), 10);
}

TEST(HomologyFilters, SphereHasNoGeneratorsAndNoExcess)
{
  auto mesh = testutils::ToPolyData(boolsurf::MakeIcosphere(3));
  ControlPolygon loop;
  for (int k = 0; k < 8; ++k)
  {
    const double a = 2 * M_PI * k / 8;
    const double z = 0.37 + 0.05 * std::sin(a), rho = std::sqrt(1 - z * z);
    loop.Points.push_back({ rho * std::cos(a), rho * std::sin(a), z });
  }
  Pipeline p(mesh, testutils::ToCurves({ loop }));
  vtkFieldData* fd = p.Fields();
  ASSERT_NE(fd->GetArray("NumberOfHomologyGenerators"), nullptr);
  EXPECT_EQ(fd->GetArray("NumberOfHomologyGenerators")->GetComponent(0, 0), 0);
  EXPECT_EQ(fd->GetArray("CurveHomology"), nullptr);
  EXPECT_EQ(fd->GetArray("HomologyExcess"), nullptr);
  EXPECT_EQ(fd->GetArray("ShapeConsistent")->GetComponent(0, 0), 1);
  EXPECT_EQ(p.Label->GetOutput(1)->GetNumberOfLines(), 0);
  EXPECT_TRUE(p.Warnings.empty()) << p.Warnings;
}

// Port 1 is drawn again only when the generators change: it follows the surface from a torus
// to a sphere (none) and back, and stays right across edits in between.
TEST(HomologyFilters, GeneratorsFollowTheSurface)
{
  const double R = 3.0, r = 1.0;
  auto torus = testutils::ToPolyData(boolsurf::MakeTorus(R, r, 48, 24));
  auto torusCurves = testutils::ToCurves({ Meridian(R, r, 0.2, 0, false) });
  auto sphere = testutils::ToPolyData(boolsurf::MakeIcosphere(3));
  ControlPolygon loop;
  for (int k = 0; k < 8; ++k)
  {
    const double a = 2 * M_PI * k / 8, z = 0.37, rho = std::sqrt(1 - z * z);
    loop.Points.push_back({ rho * std::cos(a), rho * std::sin(a), z });
  }
  auto sphereCurves = testutils::ToCurves({ loop });
  Pipeline p(torus, torusCurves);
  auto use = [&](vtkPolyData* surface, vtkPolyData* curves)
  {
    p.Trace->SetInputData(0, surface);
    p.Trace->SetInputData(1, curves);
    p.Arrange->SetInputData(0, surface);
    p.Label->Update();
    return p.Label->GetOutput(1)->GetNumberOfLines();
  };
  const vtkIdType onTorus = p.Label->GetOutput(1)->GetNumberOfLines();
  EXPECT_EQ(onTorus, 4); // two generators and their shortened loops
  EXPECT_EQ(use(sphere, sphereCurves), 0);
  sphereCurves->Modified(); // an edit on the sphere
  EXPECT_EQ(use(sphere, sphereCurves), 0);
  EXPECT_EQ(use(torus, torusCurves), onTorus);
  torusCurves->Modified();
  EXPECT_EQ(use(torus, torusCurves), onTorus);
}
