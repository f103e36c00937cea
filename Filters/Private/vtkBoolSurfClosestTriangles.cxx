#include "vtkBoolSurfClosestTriangles.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace boolsurf
{

//------------------------------------------------------------------------------
void ClosestTriangles::SetSurface(vtkPolyData* surface, bool owned)
{
  if (this->Cells && surface == this->Surface && surface->GetMTime() == this->SurfaceTime &&
    owned == this->Owned)
  {
    return;
  }
  this->Surface = surface;
  this->SurfaceTime = surface ? surface->GetMTime() : 0;
  this->Owned = owned;
  this->Locator = nullptr;
  this->Ids.clear();
  this->CellOf.clear();
  this->Cells = vtkSmartPointer<vtkPolyData>::New();
  if (!surface || surface->GetNumberOfCells() == 0)
  {
    return;
  }
  if (!owned)
  {
    this->Cells = surface;
  }
  else
  {
    // This rank's own cells only: a ghost copy's answer is its owner's to give.
    vtkUnsignedCharArray* ghosts = surface->GetCellGhostArray();
    vtkDataArray* ids = surface->GetCellData()->GetGlobalIds();
    this->Cells->SetPoints(surface->GetPoints());
    this->Cells->AllocateEstimate(surface->GetNumberOfCells(), 3);
    vtkNew<vtkIdList> corners;
    for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
    {
      if (ghosts && (ghosts->GetValue(c) & vtkDataSetAttributes::DUPLICATECELL))
      {
        continue;
      }
      surface->GetCellPoints(c, corners);
      const vtkIdType to = this->Cells->InsertNextCell(surface->GetCellType(c), corners);
      const long long id = ids ? static_cast<long long>(ids->GetTuple1(c)) : c;
      this->Ids.push_back(id);
      this->CellOf.emplace(id, to);
    }
  }
  this->Diagonal = this->Cells->GetLength();
}

//------------------------------------------------------------------------------
vtkIdType ClosestTriangles::GetNumberOfCells() const
{
  return this->Cells ? this->Cells->GetNumberOfCells() : 0;
}

//------------------------------------------------------------------------------
long long ClosestTriangles::IdOf(vtkIdType cell) const
{
  return this->Owned ? this->Ids[static_cast<std::size_t>(cell)] : cell;
}

//------------------------------------------------------------------------------
void ClosestTriangles::ReadCorners(vtkIdType cell, PlacedPoint& placed) const
{
  vtkIdType n;
  const vtkIdType* corners;
  this->Cells->GetCellPoints(cell, n, corners);
  placed.Found = true;
  placed.Triangle = this->IdOf(cell);
  placed.Corners = static_cast<int>(n);
  for (int k = 0; k < 3 && n == 3; ++k)
  {
    this->Cells->GetPoint(corners[k], placed.P[k]);
  }
}

//------------------------------------------------------------------------------
vtkStaticCellLocator* ClosestTriangles::GetLocator() const
{
  if (!this->Locator)
  {
    this->Locator = vtkSmartPointer<vtkStaticCellLocator>::New();
    this->Locator->SetDataSet(this->Cells);
    this->Locator->BuildLocator();
  }
  return this->Locator;
}

//------------------------------------------------------------------------------
double ClosestTriangles::FindDistance2(const PointQuery& query) const
{
  if (this->GetNumberOfCells() == 0)
  {
    return std::numeric_limits<double>::infinity();
  }
  double x[3] = { query.X[0], query.X[1], query.X[2] };
  double closest[3];
  vtkIdType cell = -1;
  int subId;
  double distance2 = 0;
  this->GetLocator()->FindClosestPoint(x, closest, cell, subId, distance2);
  return cell < 0 ? std::numeric_limits<double>::infinity() : distance2;
}

//------------------------------------------------------------------------------
PlacedPoint ClosestTriangles::Place(const PointQuery& query, double distance2) const
{
  PlacedPoint placed;
  const vtkIdType cells = this->GetNumberOfCells();
  if (cells == 0)
  {
    return placed;
  }
  if (query.Named)
  {
    vtkIdType cell = -1;
    if (this->Owned)
    {
      const auto found = this->CellOf.find(query.Triangle);
      cell = found == this->CellOf.end() ? -1 : found->second;
    }
    else if (query.Triangle >= 0 && query.Triangle < cells)
    {
      cell = static_cast<vtkIdType>(query.Triangle);
    }
    if (cell >= 0)
    {
      this->ReadCorners(cell, placed);
    }
    return placed;
  }
  if (!(distance2 < std::numeric_limits<double>::infinity()))
  {
    return placed;
  }
  // Every cell as close: those whose bounds reach the distance (padded for rounding), compared
  // by the distance each one gives and then by id.
  double x[3] = { query.X[0], query.X[1], query.X[2] };
  const double reach = std::sqrt(distance2) * (1 + 1e-9) + 1e-12 * this->Diagonal;
  double box[6];
  for (int k = 0; k < 3; ++k)
  {
    box[2 * k] = x[k] - reach;
    box[2 * k + 1] = x[k] + reach;
  }
  vtkNew<vtkIdList> candidates;
  this->GetLocator()->FindCellsWithinBounds(box, candidates);
  vtkNew<vtkGenericCell> cell;
  vtkIdType best = -1;
  double bestDistance2 = std::numeric_limits<double>::infinity();
  double bestPoint[3] = { 0, 0, 0 };
  std::vector<double> weights;
  for (vtkIdType i = 0; i < candidates->GetNumberOfIds(); ++i)
  {
    const vtkIdType c = candidates->GetId(i);
    this->Cells->GetCell(c, cell);
    weights.resize(static_cast<std::size_t>(std::max<vtkIdType>(3, cell->GetNumberOfPoints())));
    double point[3], pcoords[3], d2;
    int subId;
    if (cell->EvaluatePosition(x, point, subId, pcoords, d2, weights.data()) == -1)
    {
      continue;
    }
    if (best < 0 || d2 < bestDistance2 || (d2 == bestDistance2 && this->IdOf(c) < this->IdOf(best)))
    {
      best = c;
      bestDistance2 = d2;
      std::copy(point, point + 3, bestPoint);
    }
  }
  if (best < 0)
  {
    // Rounding put even the locator's cell outside the box: its answer, then.
    int subId;
    this->GetLocator()->FindClosestPoint(x, bestPoint, cell, best, subId, bestDistance2);
    if (best < 0)
    {
      return placed;
    }
  }
  this->ReadCorners(best, placed);
  std::copy(bestPoint, bestPoint + 3, placed.Closest);
  placed.Distance2 = bestDistance2;
  return placed;
}

} // namespace boolsurf
