// Winding-number labels of arrangement cells, one per shape (BoolSurf step 4).
//
// The cell graph has one arc per (pair of adjacent cells, shape, patch), oriented from the
// cell on the right of the curve to the cell on the left: crossing it right -> left adds 1
// to that shape's label. Where curves of several shapes overlap, one step from a cell to its
// neighbour crosses all of them at once, so arcs are grouped into crossings: arcs between
// the same two cells at the same place (same `Location`) are crossed together.
//
// One breadth-first search labels all shapes together. When a cell is reached a second time
// with a different label for shape s, s is inconsistent (its curves are not
// null-homologous, or it is open): the comparison is exact, not modulo 2. The labels of the
// other shapes do not depend on the search order, so they stay valid.
#ifndef boolsurf_CellLabeling_h
#define boolsurf_CellLabeling_h

#include <cstddef>
#include <utility>
#include <vector>

namespace boolsurf
{

struct CellArc
{
  int RightCell = -1;
  int LeftCell = -1;
  int Shape = -1;
  /// Arcs between the same two cells with the same Location are one crossing (overlapping
  /// curves). Distinct places must have distinct values (e.g. a patch or refined edge id).
  long long Location = 0;
  /// +1 or -1: the arc's direction relative to its place's orientation. It decides the sign
  /// only when RightCell == LeftCell, where the cells cannot: a curve retracing itself (a
  /// spike, a keyhole bridge) crosses one place twice in opposite directions, which cancels.
  int Direction = 1;
};

struct LabelingInput
{
  int NumberOfCells = 0;
  /// Nodes labeled beside the cells and left out of the result: the plugs of the surface's
  /// boundary loops (Labeling/BoundaryPlugs.h), nodes NumberOfCells .. + NumberOfPlugs - 1.
  /// Arcs, links, components and zero cells name cells and plugs alike by node.
  int NumberOfPlugs = 0;
  int NumberOfShapes = 0; ///< arcs name shapes by index 0..NumberOfShapes-1
  /// The user's id of each shape index (copied to the result; may be empty).
  std::vector<int> ShapeIds;
  std::vector<CellArc> Arcs;
  /// Pairs of nodes that are one region, with equal labels: a cell and the plug it meets along
  /// a stretch of boundary no curve covers.
  std::vector<std::pair<int, int>> Links;
  /// Connected component of each node (surface component); empty = all in component 0.
  std::vector<int> CellComponent;
  /// Zero node of each component, or -1: then every shape's labels in that component are
  /// shifted so their minimum is 0 (the closed-surface heuristic of the paper).
  std::vector<int> ZeroCells;

  int GetNumberOfNodes() const { return this->NumberOfCells + this->NumberOfPlugs; }
  /// Makes `cell` the zero cell of its component (a user's ZeroCellPoint).
  void SetZeroCell(int cell);
};

struct LabelConflict
{
  int Shape = -1;
  int Cell = -1;       ///< the cell reached with two different labels (never a plug)
  int FirstLabel = 0;  ///< label it had
  int SecondLabel = 0; ///< label the other path gives
};

struct LabelingResult
{
  /// Shapes are dense indices 0..NumberOfShapes-1 (labels are a cells x shapes table, so a
  /// sparse or huge user shape id costs nothing); ShapeIds[index] is the user's id (empty: the
  /// id is the index).
  int NumberOfShapes = 0;
  std::vector<int> ShapeIds;
  /// Labels[cell * NumberOfShapes + shape].
  std::vector<int> Labels;
  /// 1 when the shape's labels are path independent.
  std::vector<char> ShapeConsistent;
  /// The first conflict found for each inconsistent shape.
  std::vector<LabelConflict> Conflicts;

  int GetLabel(int cell, int shape) const
  {
    return this->Labels[static_cast<std::size_t>(cell) * this->NumberOfShapes + shape];
  }

  /// The user's id of shape index `shape`.
  int ShapeIdOf(int shape) const { return this->ShapeIds.empty() ? shape : this->ShapeIds[shape]; }
};

/// Labels every cell. Arcs naming cells or shapes out of range are ignored (the caller
/// validates).
LabelingResult LabelCells(const LabelingInput& input);

} // namespace boolsurf

#endif
