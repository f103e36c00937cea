/**
 * @brief   the closest triangle of a surface (or of a rank's piece of one) to a position,
 *          and a control point placed on it
 *
 * Surface Curves snaps a control point given by position to the closest point of the surface.
 * Where several triangles are at the same closest distance (a point above an edge or a
 * vertex), the triangle with the lowest id is taken, so that the answer does not depend on how
 * the triangles are stored: on one rank the id is the cell id, on a rank's piece of a split
 * surface it is the cell's global id, and each rank answering from the triangles it owns, the
 * nearest answer (ties to the lowest id) is the one the whole surface gives
 * (vtkBoolSurfPieceSnapping.h). The distance and closest point are vtkCell::EvaluatePosition's,
 * computed from the triangle's own corners, so they are the same bits on any rank.
 *
 * A vtkStaticCellLocator finds the distance; every cell whose bounds reach that far is then
 * compared, by distance and then id (on pieces only by the ranks whose distance is the smallest
 * of all ranks': a rank whose piece is far does not search its piece). The locator is kept
 * while the surface is the same object, unmodified.
 */
#ifndef vtkBoolSurfClosestTriangles_h
#define vtkBoolSurfClosestTriangles_h

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <unordered_map>
#include <vector>

class vtkPolyData;
class vtkStaticCellLocator;

namespace boolsurf
{
/// What a control point asks: the triangle it names exactly (Named: Triangle, which no cell
/// has when negative), or the closest point of the surface to X.
struct PointQuery
{
  bool Named = false;
  long long Triangle = -1;
  double X[3] = { 0, 0, 0 };
};

/// The answer: the triangle (Found false when no triangle has the id named, or there is none),
/// its number of corners and their positions, and for a snapped point the closest point and its
/// squared distance.
struct PlacedPoint
{
  bool Found = false;
  long long Triangle = -1;
  int Corners = 0;
  double P[3][3] = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 } };
  double Closest[3] = { 0, 0, 0 };
  double Distance2 = 0;
};

class ClosestTriangles
{
public:
  /// The cells to search: all of `surface` (ids: cell ids) or, when `owned`, those its ghost
  /// array does not mark as another rank's (ids: the cell GlobalIds). Kept while `surface` is
  /// the same object, unmodified.
  void SetSurface(vtkPolyData* surface, bool owned);
  /// The number of cells searched.
  vtkIdType GetNumberOfCells() const;
  /// The squared distance from query.X to the closest cell (infinity when there is none).
  double FindDistance2(const PointQuery& query) const;
  /// This finder's answer to `query`: a named triangle's corners (Found false when no cell has
  /// its id), or among the cells at squared distance `distance2` from the position (the
  /// smallest: FindDistance2's, over every rank on pieces), the one of lowest id.
  PlacedPoint Place(const PointQuery& query, double distance2) const;
  /// The answer on this finder's cells alone.
  PlacedPoint Place(const PointQuery& query) const
  {
    return this->Place(query, query.Named ? 0.0 : this->FindDistance2(query));
  }

private:
  /// The locator, built on first use.
  vtkStaticCellLocator* GetLocator() const;
  /// Reads cell `cell`'s corners into `placed`.
  void ReadCorners(vtkIdType cell, PlacedPoint& placed) const;
  long long IdOf(vtkIdType cell) const;

  vtkSmartPointer<vtkPolyData> Cells;
  mutable vtkSmartPointer<vtkStaticCellLocator> Locator; ///< built on the first snapped point
  /// Global id of each cell, and the cell of each global id (owned cells only; empty otherwise).
  std::vector<long long> Ids;
  std::unordered_map<long long, vtkIdType> CellOf;
  vtkPolyData* Surface = nullptr; ///< compared, never dereferenced
  vtkMTimeType SurfaceTime = 0;
  bool Owned = false;
  double Diagonal = 0;
};
}

#endif
