#include "Distributed/PieceSelection.h"

namespace boolsurf
{

//------------------------------------------------------------------------------
void SelectOwnedTriangles(const PieceMesh& piece,
  const Arrangement& arr,
  const std::vector<int>& globalCellOfLocal,
  const std::vector<char>& selected,
  PieceRegion& out)
{
  out = PieceRegion();
  const auto isSelected = [&](int r)
  {
    const int local = arr.CellOfTriangle(r);
    if (local < 0 || local >= static_cast<int>(globalCellOfLocal.size()))
    {
      return -1;
    }
    const int global = globalCellOfLocal[local];
    return global >= 0 && global < static_cast<int>(selected.size()) && selected[global] ? global
                                                                                         : -1;
  };
  const TriangleMesh& mesh = piece.Mesh;
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    if (!piece.Owned[t])
    {
      continue;
    }
    ForEachRefinedTriangle(mesh,
      arr,
      t,
      [&](int r)
      {
        const int cell = isSelected(r);
        if (cell >= 0)
        {
          out.Triangles.push_back(r);
          out.SourceTriangles.push_back(piece.GlobalTriangle[t]);
          out.Cells.push_back(cell);
        }
      });
  }
}

//------------------------------------------------------------------------------
bool SelectPieceBoolean(const PieceMesh& piece,
  const Arrangement& arr,
  const std::vector<int>& globalCellOfLocal,
  const LabelingResult& labels,
  const BooleanOptions& options,
  PieceRegion& out,
  std::vector<char>& selected,
  std::string& text,
  std::string& error)
{
  out = PieceRegion();
  if (!SelectBooleanCells(labels, options, selected, text, error))
  {
    return false;
  }
  SelectOwnedTriangles(piece, arr, globalCellOfLocal, selected, out);
  return true;
}

} // namespace boolsurf
