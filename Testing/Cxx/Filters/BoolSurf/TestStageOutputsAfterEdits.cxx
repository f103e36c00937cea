// The stage filters keep their outputs from edit to edit and rewrite only what the curves
// change (Surface Arrangement's refined surface, Label Arrangement Cells' labeled copy, the
// input surface's arrays carried onto them): after every edit of a sequence, each output of a
// chain that saw all the edits equals, array by array and bit for bit, that of a fresh chain
// given only the last curves. The edits move curves, remove every crossing between them, add
// and remove a shape (new crossings, other cell numbers) and repeat an edit unchanged.
#include "FilterTestUtils.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfBoolean.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace
{

using testutils::ControlPolygon;

/// Every array of two attribute sets (or field data), value by value (not the timings).
void ExpectSameArrays(vtkFieldData* a, vtkFieldData* b, const std::string& what)
{
  ASSERT_EQ(a->GetNumberOfArrays(), b->GetNumberOfArrays()) << what;
  for (int i = 0; i < a->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* x = a->GetAbstractArray(i);
    ASSERT_NE(x->GetName(), nullptr) << what << ": array " << i;
    if (std::strcmp(x->GetName(), "StageTimes") == 0)
    {
      continue; // timings
    }
    vtkAbstractArray* y = b->GetAbstractArray(x->GetName());
    ASSERT_NE(y, nullptr) << what << ": " << x->GetName();
    ASSERT_EQ(x->GetDataType(), y->GetDataType()) << what << ": " << x->GetName();
    ASSERT_EQ(x->GetNumberOfComponents(), y->GetNumberOfComponents())
      << what << ": " << x->GetName();
    ASSERT_EQ(x->GetNumberOfValues(), y->GetNumberOfValues()) << what << ": " << x->GetName();
    for (vtkIdType v = 0; v < x->GetNumberOfValues(); ++v)
    {
      ASSERT_EQ(x->GetVariantValue(v), y->GetVariantValue(v))
        << what << ": " << x->GetName() << " value " << v;
    }
  }
  auto* da = vtkDataSetAttributes::SafeDownCast(a);
  auto* db = vtkDataSetAttributes::SafeDownCast(b);
  if (da && db)
  {
    vtkDataArray* sa = da->GetScalars();
    vtkDataArray* sb = db->GetScalars();
    ASSERT_EQ(sa == nullptr, sb == nullptr) << what << ": active scalars";
    if (sa)
    {
      EXPECT_STREQ(sa->GetName(), sb->GetName()) << what << ": active scalars";
    }
  }
}

/// Points, cells, point, cell and field data of two outputs, bit for bit.
void ExpectSameOutput(vtkPolyData* a, vtkPolyData* b, const std::string& what)
{
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints()) << what;
  ASSERT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells()) << what;
  for (vtkIdType p = 0; p < a->GetNumberOfPoints(); ++p)
  {
    double x[3], y[3];
    a->GetPoint(p, x);
    b->GetPoint(p, y);
    ASSERT_TRUE(x[0] == y[0] && x[1] == y[1] && x[2] == y[2]) << what << ": point " << p;
  }
  vtkIdType na, nb;
  const vtkIdType *ia, *ib;
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
  {
    a->GetCellPoints(c, na, ia);
    b->GetCellPoints(c, nb, ib);
    ASSERT_EQ(na, nb) << what << ": cell " << c;
    for (vtkIdType k = 0; k < na; ++k)
    {
      ASSERT_EQ(ia[k], ib[k]) << what << ": cell " << c;
    }
  }
  ExpectSameArrays(a->GetPointData(), b->GetPointData(), what + ", point data");
  ExpectSameArrays(a->GetCellData(), b->GetCellData(), what + ", cell data");
  ExpectSameArrays(a->GetFieldData(), b->GetFieldData(), what + ", field data");
}

/// A jittered square carrying a point array (double and float) and a cell array of its own.
vtkSmartPointer<vtkPolyData> SurfaceWithArrays()
{
  auto mesh = testutils::ToPolyData(boolsurf::MakeFlatSquare(24, 1.0, 0.3, 6));
  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  vtkNew<vtkFloatArray> color;
  color->SetName("Color");
  color->SetNumberOfComponents(3);
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    double x[3];
    mesh->GetPoint(p, x);
    height->InsertNextValue(0.3 * x[0] * x[0] - 2 * x[1] + 1);
    color->InsertNextTuple3(x[0], x[1], 0.25 * static_cast<double>(p % 7));
  }
  mesh->GetPointData()->AddArray(height);
  mesh->GetPointData()->AddArray(color);
  vtkNew<vtkIntArray> inputCell;
  inputCell->SetName("InputCell");
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    inputCell->InsertNextValue(static_cast<int>(3 * c + 1));
  }
  mesh->GetCellData()->AddArray(inputCell);
  return mesh;
}

ControlPolygon Square(double x0, double y0, double x1, double y1, int shape)
{
  return ControlPolygon{ { { x0, y0, 0 }, { x1, y0, 0 }, { x1, y1, 0 }, { x0, y1, 0 } }, shape };
}

/// The edits, in order: each the whole set of curves after it.
std::vector<std::vector<ControlPolygon>> Edits()
{
  const ControlPolygon a = Square(0.1, 0.1, 0.55, 0.6, 0);
  const ControlPolygon c{ { { 0.05, 0.45, 0 }, { 0.95, 0.5, 0 }, { 0.5, 0.95, 0 } }, 2 };
  return {
    { a, Square(0.3, 0.3, 0.85, 0.8, 1) },     // two overlapping squares
    { a, Square(0.32, 0.31, 0.87, 0.81, 1) },  // B moved: other crossings
    { a, Square(0.62, 0.2, 0.92, 0.7, 1) },    // B beside A: no crossing left
    { a, Square(0.62, 0.2, 0.92, 0.7, 1), c }, // a third shape across both
    { a, Square(0.62, 0.2, 0.92, 0.7, 1), c }, // the same edit again
    { Square(0.62, 0.2, 0.92, 0.7, 1), c },    // A removed: other cell numbers
    { a, Square(0.3, 0.3, 0.85, 0.8, 1) },     // back to the first edit
    { Square(0.12, 0.1, 0.55, 0.62, 0), Square(0.3, 0.3, 0.85, 0.8, 1), c },
  };
}

struct Chain
{
  vtkNew<vtkBoolSurfTraceCurves> Trace;
  vtkNew<vtkBoolSurfArrangement> Arrange;
  vtkNew<vtkBoolSurfLabeling> Label;
  vtkNew<vtkBoolSurfBoolean> Boolean;

  Chain(vtkPolyData* surface, int colorShape, bool perTriangle)
  {
    this->Trace->SetInputData(0, surface);
    this->Arrange->SetInputData(0, surface);
    this->Arrange->SetInputConnection(1, this->Trace->GetOutputPort());
    this->Arrange->SetNumberOfThreads(2);
    this->Label->SetInputConnection(this->Arrange->GetOutputPort(0));
    this->Label->SetColorShape(colorShape);
    this->Label->SetPerTriangleLabels(perTriangle);
    this->Boolean->SetInputConnection(this->Label->GetOutputPort(0));
    this->Boolean->SetShapeA(-1);
    this->Boolean->SetShapeB(-1);
  }

  void Run(vtkPolyData* curves)
  {
    this->Trace->SetInputData(1, curves);
    this->Boolean->Update();
  }
};

void ExpectEditsGiveFreshOutputs(int colorShape, bool perTriangle)
{
  auto surface = SurfaceWithArrays();
  Chain edited(surface, colorShape, perTriangle);
  int step = 0;
  for (const std::vector<ControlPolygon>& curves : Edits())
  {
    const std::string what = "edit " + std::to_string(step++) + " (ColorShape " +
      std::to_string(colorShape) + (perTriangle ? ", per-triangle labels)" : ")");
    edited.Run(testutils::ToCurves(curves));
    ASSERT_EQ(testutils::ErrorsOf(edited.Boolean), "") << what;
    Chain fresh(surface, colorShape, perTriangle);
    fresh.Run(testutils::ToCurves(curves));
    ExpectSameOutput(
      edited.Arrange->GetOutput(0), fresh.Arrange->GetOutput(0), what + ", refined surface");
    ExpectSameOutput(edited.Arrange->GetOutput(1), fresh.Arrange->GetOutput(1), what + ", patches");
    ExpectSameOutput(
      edited.Label->GetOutput(0), fresh.Label->GetOutput(0), what + ", labeled surface");
    ExpectSameOutput(edited.Boolean->GetOutput(0), fresh.Boolean->GetOutput(0), what + ", region");
  }
}

} // namespace

TEST(StageOutputsAfterEdits, EqualAFreshChainsOutputs)
{
  ExpectEditsGiveFreshOutputs(-1, false);
}

TEST(StageOutputsAfterEdits, EqualAFreshChainsOutputsWithPerTriangleLabels)
{
  ExpectEditsGiveFreshOutputs(1, true);
}

// Outputs held downstream keep their values while the chain goes on editing: the kept arrays
// are written in place only when nothing else holds them.
TEST(StageOutputsAfterEdits, HeldOutputsKeepTheirValues)
{
  auto surface = SurfaceWithArrays();
  Chain edited(surface, 1, true);
  std::vector<vtkSmartPointer<vtkPolyData>> held, copies;
  for (const std::vector<ControlPolygon>& curves : Edits())
  {
    edited.Run(testutils::ToCurves(curves));
    for (vtkPolyData* output : { edited.Arrange->GetOutput(0), edited.Label->GetOutput(0) })
    {
      auto shallow = vtkSmartPointer<vtkPolyData>::New();
      shallow->ShallowCopy(output);
      auto deep = vtkSmartPointer<vtkPolyData>::New();
      deep->DeepCopy(output);
      held.push_back(shallow);
      copies.push_back(deep);
    }
  }
  for (std::size_t k = 0; k < held.size(); ++k)
  {
    ExpectSameOutput(held[k], copies[k], "held output " + std::to_string(k));
  }
}
