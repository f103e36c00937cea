/**
 * @class   vtkBoolSurfBoolean
 * @brief   Boolean operations between shapes on a labeled surface arrangement
 *
 * vtkBoolSurfBoolean selects the arrangement cells that satisfy a Boolean operation between
 * shapes and outputs them as surface triangles (port 0) and their boundary as oriented
 * polylines (port 1, the region on their left).
 *
 * Operation: Union, Intersection, Difference (ShapeA minus ShapeB), SymmetricDifference, or
 * Expression. ShapeA/ShapeB = -1 means all shapes: the variadic union, intersection and
 * symmetric difference of every shape; Difference with -1 is ShapeA (the lowest ShapeId when
 * ShapeA is -1) minus the union of the others. Shapes are named by their ShapeId, whatever
 * its size (`S1000000`). Expression grammar: shapes `S<id>`, `~` not, `&` and,
 * `-` minus, `^` xor, `|` or (in decreasing precedence), parentheses; e.g.
 * `(S0 & S1) ^ S2 | ~S3`. Any expression is evaluated in one pass over the cells.
 *
 * FillRule turns a winding label into inside/outside: NonZero (label != 0), EvenOdd (odd),
 * Positive (> 0), Negative (< 0).
 *
 * The input is the output of vtkBoolSurfLabeling (field data `CellLabels`,
 * `ShapeConsistent`); the output of vtkBoolSurfArrangement is accepted too and labeled with
 * the automatic zero cell. An operation that reads an inconsistent shape is refused with an
 * error naming it (empty output): it is never answered wrongly. A malformed expression or an
 * unknown shape id is an error too.
 *
 * Port 0 keeps every array of the refined surface (`ArrangementCell`, `SourceTriangle`,
 * `TriangleId`, `Barycentric` and the input surface's own arrays) and the labels table
 * (field data `ShapeIds`, `ShapeConsistent`, `CellLabels`); the selection is evaluated once
 * per cell and only the region's triangles and points are copied; port 1 has point
 * data `TriangleId`/`Barycentric` and cell data `Closed`. Both carry field data `Expression`,
 * the expression evaluated.
 *
 * @sa vtkBoolSurfLabeling vtkBoolSurfArrangement
 */
#ifndef vtkBoolSurfBoolean_h
#define vtkBoolSurfBoolean_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkBoolSurfAlgorithm.h"
#include "vtkBoolSurfStageSettings.h" // for the Boolean settings

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class BOOLSURFFILTERS_EXPORT vtkBoolSurfBoolean : public vtkBoolSurfAlgorithm
{
public:
  static vtkBoolSurfBoolean* New();
  vtkTypeMacro(vtkBoolSurfBoolean, vtkBoolSurfAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The Boolean settings, shared with vtkBoolSurf (see vtkBoolSurfStageSettings.h):
  /// Operation (default Union), the operand shapes ShapeA and ShapeB (defaults 0 and 1; -1 means
  /// all shapes), the Expression used when Operation is Expression (e.g. "S0 & ~S1 | S2") and
  /// FillRule (default NonZero).
  vtkBoolSurfBooleanSettingsMacro();

  /// The boundary output (port 1).
  vtkPolyData* GetBoundaryOutput() { return this->GetOutput(1); }
  /// The boundary as control points of sub-curves of the input curves (port 2) and the open
  /// curves clipped by the region (port 3), as vtkBoolSurf's ports 2 and 3; empty, with a
  /// warning, when the arrangement's curves were not traced by vtkBoolSurfTraceCurves.
  vtkPolyData* GetBoundaryControlCurvesOutput() { return this->GetOutput(2); }
  vtkPolyData* GetClippedCurvesOutput() { return this->GetOutput(3); }

protected:
  vtkBoolSurfBoolean();
  ~vtkBoolSurfBoolean() override;

  bool Execute(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

  /// After Surface Arrangement on each rank's piece: on the rank's piece, from the result it
  /// attached (vtkBoolSurfPieceLabels.h), nothing gathered.
  bool ExecutesOnPieces() const override { return true; }
  bool ExecutePiece(const std::vector<vtkPolyData*>& locals,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

private:
  struct Internals;
  std::unique_ptr<Internals> Internal;

  vtkBoolSurfBoolean(const vtkBoolSurfBoolean&) = delete;
  void operator=(const vtkBoolSurfBoolean&) = delete;
};

#endif
