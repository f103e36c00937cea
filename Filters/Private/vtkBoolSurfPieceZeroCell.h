/**
 * @brief   Label Arrangement Cells' zero cell given by a point (ZeroCellMode Point) on pieces:
 *          found on the rank owning the surface triangle nearest the point, shared by one
 *          all-gather of three numbers per rank
 *
 * Each rank finds the triangle of its piece nearest the point as the one-rank labeling does
 * (a cell locator on the surface, then the arrangement's cell at the nearest point), keeps it
 * when it owns that triangle, and offers (distance, global triangle, global cell). The nearest
 * wins, ties to the lowest global triangle: every rank gets the same global cell, the one the
 * one-rank labeling finds (a point equally near two triangles in different cells, on a curve,
 * may be given the other's cell). Nothing of the surface travels.
 */
#ifndef vtkBoolSurfPieceZeroCell_h
#define vtkBoolSurfPieceZeroCell_h

#include <string>

class vtkMultiProcessController;
class vtkStaticCellLocator;

namespace boolsurf
{
struct PieceArrangementResult;

/// Collective. The global cell holding the point nearest `point` on the whole surface, or -1
/// on every rank with `error` when no rank has a triangle near it. `locator` is built on
/// arranged.Surface (the rank's piece as it arrived).
int PieceZeroCellAt(vtkMultiProcessController* controller,
  const PieceArrangementResult& arranged,
  vtkStaticCellLocator* locator,
  const double point[3],
  std::string& error);

} // namespace boolsurf

#endif
