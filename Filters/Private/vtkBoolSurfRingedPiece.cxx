#include "vtkBoolSurfRingedPiece.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkGhostCellsGenerator.h>
#include <vtkIdList.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <unordered_map>
#include <vector>

namespace boolsurf
{

//------------------------------------------------------------------------------
bool BuildRingedPiece(vtkMultiProcessController* controller,
  vtkPolyData* local,
  PieceInput& out,
  std::string& error)
{
  out = PieceInput();
  vtkNew<vtkPolyData> input;
  if (local)
  {
    input->ShallowCopy(local);
  }
  // Every rank runs the generator (it is collective), with whatever it holds.
  vtkNew<vtkGhostCellsGenerator> ring;
  ring->SetController(controller);
  ring->BuildIfRequiredOff();
  ring->SetNumberOfGhostLayers(1);
  ring->SetInputData(input);
  ring->Update();
  vtkPolyData* ringed = vtkPolyData::SafeDownCast(ring->GetOutputDataObject(0));
  if (!ringed || ringed->GetNumberOfCells() == 0)
  {
    return true; // a rank without triangles: an empty piece
  }
  vtkDataArray* cellIds = ringed->GetCellData()->GetGlobalIds();
  vtkDataArray* pointIds = ringed->GetPointData()->GetGlobalIds();
  if (!cellIds || !pointIds)
  {
    error = std::string("the piece has no global ids of its ") + (cellIds ? "points" : "cells") +
      " (vtkGenerateGlobalIds gives both)";
    return false;
  }
  vtkUnsignedCharArray* ghosts = ringed->GetCellGhostArray();
  // The generator may bring one point twice (from two neighbours, where three or more pieces
  // meet): points are one per global id.
  const vtkIdType points = ringed->GetNumberOfPoints();
  std::vector<int> pointOf(static_cast<std::size_t>(points), -1);
  std::unordered_map<long long, int> byGlobalId;
  for (vtkIdType p = 0; p < points; ++p)
  {
    const long long id = static_cast<long long>(pointIds->GetTuple1(p));
    double x[3];
    ringed->GetPoint(p, x);
    const auto found = byGlobalId.emplace(id, static_cast<int>(out.Positions.size()));
    if (found.second)
    {
      out.Positions.push_back({ x[0], x[1], x[2] });
      out.PointGlobalIds.push_back(static_cast<int>(id));
    }
    else
    {
      const Vec3& first = out.Positions[found.first->second];
      if (first.x != x[0] || first.y != x[1] || first.z != x[2])
      {
        error = "point global id " + std::to_string(id) + " names two positions";
        return false;
      }
    }
    pointOf[p] = found.first->second;
  }
  vtkNew<vtkIdList> corners;
  for (vtkIdType c = 0; c < ringed->GetNumberOfCells(); ++c)
  {
    ringed->GetCellPoints(c, corners);
    if (corners->GetNumberOfIds() != 3)
    {
      error = "cell with global id " +
        std::to_string(static_cast<long long>(cellIds->GetTuple1(c))) + " is not a triangle (" +
        std::to_string(corners->GetNumberOfIds()) + " points)";
      return false;
    }
    out.Triangles.push_back(
      { pointOf[corners->GetId(0)], pointOf[corners->GetId(1)], pointOf[corners->GetId(2)] });
    out.TriangleGlobalIds.push_back(static_cast<int>(cellIds->GetTuple1(c)));
    const bool ghost = ghosts && (ghosts->GetValue(c) & vtkDataSetAttributes::DUPLICATECELL);
    out.Ghost.push_back(ghost ? 1 : 0);
  }
  return true;
}

} // namespace boolsurf
