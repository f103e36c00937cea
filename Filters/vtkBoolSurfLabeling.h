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
 * open boundary, the cell at its longest boundary loop (the plugged holes of the paper,
 * §3.4); on a closed component, each shape's labels are shifted so their minimum is 0.
 *
 * Output: the input with cell data `Labels` (int, one component per shape, named S0, S1,
 * ...), field data `ShapeConsistent` (one value per shape) and `CellLabels` (one tuple per
 * arrangement cell). A warning names the inconsistent shapes and the cells where the
 * conflict was found.
 *
 * @sa vtkBoolSurfArrangement vtkBoolSurfBoolean
 */
#ifndef vtkBoolSurfLabeling_h
#define vtkBoolSurfLabeling_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class BOOLSURFFILTERS_EXPORT vtkBoolSurfLabeling : public vtkPolyDataAlgorithm
{
public:
  static vtkBoolSurfLabeling* New();
  vtkTypeMacro(vtkBoolSurfLabeling, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ZeroCellModes
  {
    AUTOMATIC = 0, ///< longest boundary loop, else shift to minimum 0
    POINT = 1,     ///< the cell containing ZeroCellPoint
  };

  ///@{
  /// How the zero cell is chosen (default Automatic).
  vtkSetClampMacro(ZeroCellMode, int, AUTOMATIC, POINT);
  vtkGetMacro(ZeroCellMode, int);
  void SetZeroCellModeToAutomatic() { this->SetZeroCellMode(AUTOMATIC); }
  void SetZeroCellModeToPoint() { this->SetZeroCellMode(POINT); }
  ///@}

  ///@{
  /// A point on (or near) the surface inside the cell that must have label 0 for every shape;
  /// used when ZeroCellMode is Point. Only its surface component uses it.
  vtkSetVector3Macro(ZeroCellPoint, double);
  vtkGetVector3Macro(ZeroCellPoint, double);
  ///@}

protected:
  vtkBoolSurfLabeling();
  ~vtkBoolSurfLabeling() override = default;

  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int ZeroCellMode = AUTOMATIC;
  double ZeroCellPoint[3] = { 0, 0, 0 };

private:
  vtkBoolSurfLabeling(const vtkBoolSurfLabeling&) = delete;
  void operator=(const vtkBoolSurfLabeling&) = delete;
};

#endif
