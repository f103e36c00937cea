// A surface made of appended pieces, as VTK's reader of a partitioned file (.pvtp) gives it in
// one process: each piece with its own copy of the points on its border and ghost copies of
// its neighbours' cells. Check Surface answers as on the undistributed surface.
#include "vtkBoolSurfCheckSurface.h"

#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataSetAttributes.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <map>
#include <vector>

namespace
{
// Cells [first, last) of `whole` with their own points, their global ids, and the cells
// [ghostFirst, ghostLast) as ghost copies.
vtkSmartPointer<vtkPolyData> Piece(vtkPolyData* whole,
  vtkIdType first,
  vtkIdType last,
  vtkIdType ghostFirst,
  vtkIdType ghostLast)
{
  auto piece = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("GlobalCellIds");
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  std::map<vtkIdType, vtkIdType> local;
  auto add = [&](vtkIdType c, unsigned char ghost)
  {
    vtkIdType n;
    const vtkIdType* pts;
    whole->GetPolys()->GetCellAtId(c, n, pts);
    std::vector<vtkIdType> mine;
    for (vtkIdType k = 0; k < n; ++k)
    {
      auto at = local.emplace(pts[k], points->GetNumberOfPoints());
      if (at.second)
      {
        points->InsertNextPoint(whole->GetPoint(pts[k]));
      }
      mine.push_back(at.first->second);
    }
    polys->InsertNextCell(n, mine.data());
    ids->InsertNextValue(c);
    ghosts->InsertNextValue(ghost);
  };
  for (vtkIdType c = first; c < last; ++c)
  {
    add(c, 0);
  }
  for (vtkIdType c = ghostFirst; c < ghostLast; ++c)
  {
    add(c, vtkDataSetAttributes::DUPLICATECELL);
  }
  piece->SetPoints(points);
  piece->SetPolys(polys);
  piece->GetCellData()->SetGlobalIds(ids);
  piece->GetCellData()->AddArray(ghosts);
  return piece;
}

vtkSmartPointer<vtkPolyData> Check(vtkPolyData* input)
{
  vtkNew<vtkBoolSurfCheckSurface> check;
  check->WarnOnProblemsOff();
  check->SetInputData(input);
  check->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(check->GetOutput());
  return out;
}

int FieldInt(vtkPolyData* pd, const char* name)
{
  auto* a = vtkIntArray::SafeDownCast(pd->GetFieldData()->GetAbstractArray(name));
  return a ? a->GetValue(0) : -999;
}
} // namespace

TEST(CheckSurfaceFilter, AppendedPiecesOfAPartitionedFileAreTheWholeSurface)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(16);
  sphere->Update();
  vtkPolyData* whole = sphere->GetOutput();
  const vtkIdType n = whole->GetNumberOfCells();

  // Three pieces, listed out of order, each with a few ghost copies of another's cells.
  vtkNew<vtkAppendPolyData> append;
  append->AddInputData(Piece(whole, n / 3, 2 * n / 3, 0, 5));
  append->AddInputData(Piece(whole, 0, n / 3, 2 * n / 3, 2 * n / 3 + 5));
  append->AddInputData(Piece(whole, 2 * n / 3, n, n / 3, n / 3 + 5));
  append->Update();
  vtkPolyData* pieces = append->GetOutput();
  ASSERT_GT(pieces->GetNumberOfPoints(), whole->GetNumberOfPoints());
  ASSERT_EQ(pieces->GetNumberOfCells(), n + 15);

  vtkSmartPointer<vtkPolyData> expected = Check(whole);
  vtkSmartPointer<vtkPolyData> got = Check(pieces);
  EXPECT_EQ(got->GetNumberOfCells(), n);
  EXPECT_EQ(got->GetNumberOfPoints(), whole->GetNumberOfPoints());
  for (const char* name :
    { "Components", "Genus", "BoundaryLoops", "EulerCharacteristic", "IsManifold" })
  {
    EXPECT_EQ(FieldInt(got, name), FieldInt(expected, name)) << name;
  }
  EXPECT_EQ(FieldInt(got, "Genus"), 0);
  auto* problems = vtkStringArray::SafeDownCast(got->GetFieldData()->GetAbstractArray("Problems"));
  ASSERT_NE(problems, nullptr);
  EXPECT_EQ(problems->GetNumberOfValues(), 0) << problems->GetValue(0);
  // The triangles come back in the undistributed surface's order (their global ids).
  vtkDataArray* ids = got->GetCellData()->GetGlobalIds();
  ASSERT_NE(ids, nullptr);
  for (vtkIdType c = 0; c < n; ++c)
  {
    EXPECT_EQ(ids->GetTuple1(c), c);
  }
}

TEST(CheckSurfaceFilter, SeparateSurfacesAtTheSamePlaceStayApartWhenClosed)
{
  // Two closed spheres at the same place share no boundary point: nothing is welded.
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  vtkNew<vtkAppendPolyData> append;
  append->AddInputData(sphere->GetOutput());
  append->AddInputData(sphere->GetOutput());
  append->Update();
  vtkSmartPointer<vtkPolyData> got = Check(append->GetOutput());
  EXPECT_EQ(FieldInt(got, "Components"), 2);
  EXPECT_EQ(got->GetNumberOfPoints(), 2 * sphere->GetOutput()->GetNumberOfPoints());
}

namespace
{
// A unit square of two triangles along its diagonal, the diagonal's points doubled: cells
// (0, 1, 2) and (3, 4, 5) when `appended` (two pieces), else interleaved (one piece).
vtkSmartPointer<vtkPolyData> SquareCutAlongItsDiagonal(bool appended)
{
  const double a[3] = { 0, 0, 0 }, b[3] = { 1, 0, 0 }, c[3] = { 1, 1, 0 }, d[3] = { 0, 1, 0 };
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  if (appended)
  {
    for (const double* p : { a, b, c, a, c, d })
    {
      points->InsertNextPoint(p);
    }
    const vtkIdType first[3] = { 0, 1, 2 }, second[3] = { 3, 4, 5 };
    polys->InsertNextCell(3, first);
    polys->InsertNextCell(3, second);
  }
  else
  {
    for (const double* p : { a, b, a, c, c, d })
    {
      points->InsertNextPoint(p);
    }
    const vtkIdType first[3] = { 0, 1, 3 }, second[3] = { 2, 4, 5 };
    polys->InsertNextCell(3, first);
    polys->InsertNextCell(3, second);
  }
  auto square = vtkSmartPointer<vtkPolyData>::New();
  square->SetPoints(points);
  square->SetPolys(polys);
  return square;
}
} // namespace

TEST(CheckSurfaceFilter, CoincidentBoundaryPointsAreWeldedAcrossPiecesOnly)
{
  // Two appended pieces meet along the diagonal: one component with one boundary loop.
  vtkSmartPointer<vtkPolyData> welded = Check(SquareCutAlongItsDiagonal(true));
  EXPECT_EQ(FieldInt(welded, "Components"), 1);
  EXPECT_EQ(FieldInt(welded, "BoundaryLoops"), 1);
  EXPECT_EQ(welded->GetNumberOfPoints(), 4);
  // One piece cut along a seam keeps its seam: two components.
  vtkSmartPointer<vtkPolyData> seam = Check(SquareCutAlongItsDiagonal(false));
  EXPECT_EQ(FieldInt(seam, "Components"), 2);
  EXPECT_EQ(seam->GetNumberOfPoints(), 6);
}
