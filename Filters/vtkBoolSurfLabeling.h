/**
 * @class   vtkBoolSurfLabeling
 * @brief   winding-number labels of arrangement cells, one per shape, and shape consistency
 *
 * vtkBoolSurfLabeling walks the cell graph of a vtkBoolSurfArrangement output (its port 0)
 * breadth-first from a zero cell, once for all shapes: crossing a curve of shape s from its
 * right to its left adds 1 to the label of s, the other way subtracts 1, curves of other
 * shapes leave it unchanged. A closed curve counter-clockwise on a flat mesh with +z
 * normals (more generally: with its enclosed region on its left seen from where the normals
 * point) gives its inside the label +1.
 *
 * A shape is inconsistent when two paths give a cell different labels (exact comparison,
 * not parity): its curves do not bound a region (not null-homologous, e.g. a single
 * meridian on a torus). Consistent shapes are labeled even when others are not.
 *
 * Zero cell (label 0 for every shape): with ZeroCellMode Point, the cell containing
 * ZeroCellPoint (closest refined triangle); in Automatic mode, on a surface component with
 * open boundary, the plug of its longest boundary loop: every boundary loop is closed by a
 * plug (the virtual faces of the paper, §3.4) that meets the cells along the loop, across the
 * curves that run along the boundary and directly where none does, so a curve along a stretch
 * of boundary bounds the cells on its inner side and the cells along the longest loop's free
 * stretches have label 0; on a closed component, each shape's labels are shifted so their
 * minimum is 0.
 *
 * Labels belong to cells, not triangles. Output: the input (shallow copy) with field data
 * `CellLabels` (int, one tuple per arrangement cell, one component per shape named S<id>, in
 * the order of the field data `ShapeIds`) and `ShapeConsistent` (one value per shape, same
 * order). Shapes are numbered densely, so a sparse or huge ShapeId costs nothing: memory is
 * triangles + cells x shapes. Per-triangle arrays only on request: ColorShape >= 0 adds the
 * cell array `ShapeLabel` (that shape's label, for coloring the surface), PerTriangleLabels
 * adds `Labels` (every shape's label per triangle; triangles x shapes memory). A triangle's
 * labels are row ArrangementCell of CellLabels. A warning names the inconsistent shapes and
 * the cells where the conflict was found.
 *
 * Homology (BoolSurf §4.4): when the input comes from vtkBoolSurfArrangement it carries each
 * curve's class in the surface's homology generators (field data `CurveHomology`, curves x 2g,
 * components G0.., rows named by `CurveHomologyCurveId` and `CurveHomologyShapeId`; the
 * arrangement writes it). The labeling adds `HomologyExcess` (shapes x 2g, rows in the order of
 * `ShapeIds`): the sum over each shape's curves, the generators in excess. A shape is
 * consistent exactly when its excess is zero; the warning for an inconsistent shape names, per
 * curve, the generators it winds around (sign and multiplicity) and the three fixes of
 * vtkBoolSurfResolve. Output port 1: the generators as closed polylines on the surface (point
 * data `TriangleId`/`Barycentric`, cell data `GeneratorId`); empty on genus 0.
 *
 * @sa vtkBoolSurfArrangement vtkBoolSurfBoolean
 */
#ifndef vtkBoolSurfLabeling_h
#define vtkBoolSurfLabeling_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkBoolSurfAlgorithm.h"
#include "vtkBoolSurfStageSettings.h" // for the zero-cell settings

#include <memory> // for std::unique_ptr

class BOOLSURFFILTERS_EXPORT vtkBoolSurfLabeling : public vtkBoolSurfAlgorithm
{
public:
  static vtkBoolSurfLabeling* New();
  vtkTypeMacro(vtkBoolSurfLabeling, vtkBoolSurfAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// How the zero cell (label 0 for every shape) is chosen, shared with vtkBoolSurf (see
  /// vtkBoolSurfStageSettings.h): ZeroCellMode Automatic (default) or Point, the cell containing
  /// ZeroCellPoint, a point on (or near) the surface. Only its surface component uses it.
  vtkBoolSurfZeroCellSettingsMacro();

  ///@{
  /// ShapeId whose label is written per triangle as the cell array `ShapeLabel`, the active
  /// scalars (ParaView colors the output by it, with the plugin's categorical color map);
  /// -1 (default) writes none.
  vtkSetClampMacro(ColorShape, int, -1, VTK_INT_MAX);
  vtkGetMacro(ColorShape, int);
  ///@}

  ///@{
  /// Also write every shape's label per triangle as the cell array `Labels` (one component per
  /// shape). Off by default: it costs triangles x shapes memory.
  vtkSetMacro(PerTriangleLabels, bool);
  vtkGetMacro(PerTriangleLabels, bool);
  vtkBooleanMacro(PerTriangleLabels, bool);
  ///@}

protected:
  vtkBoolSurfLabeling();
  ~vtkBoolSurfLabeling() override;

  bool Execute(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

  /// After Surface Arrangement on each rank's piece: on the rank's piece, from the result it
  /// attached (vtkBoolSurfPieceLabels.h), nothing gathered.
  bool ExecutesOnPieces() const override { return true; }
  bool ExecutePiece(const std::vector<vtkPolyData*>& locals,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

  int ColorShape = -1;
  bool PerTriangleLabels = false;

private:
  struct Internals;
  std::unique_ptr<Internals> Internal;

  vtkBoolSurfLabeling(const vtkBoolSurfLabeling&) = delete;
  void operator=(const vtkBoolSurfLabeling&) = delete;
};

#endif
