/**
 * @class   vtkBoolSurfExampleCellAreas
 * @brief   the example stage of Docs/Architecture.md: the area of every arrangement cell
 *
 * vtkBoolSurfExampleCellAreas takes Surface Arrangement's refined surface (or Label
 * Arrangement Cells' output) and passes it through with field data `CellArea`: the area of
 * each arrangement cell, in cell order, times AreaScale (a unit conversion).
 *
 * It is the smallest complete stage: the base class gives it the arrangement in Core form
 * (attached by Surface Arrangement, or rebuilt from the arrays of a file), Core computes
 * (CellAreas.h), and the filter only writes the answer. In a real stage this file is
 * Filters/vtkBoolSurf<Name>.h. Errors name the problem and leave an empty output.
 *
 * @sa vtkBoolSurfArrangement vtkBoolSurfAlgorithm
 */
#ifndef vtkBoolSurfExampleCellAreas_h
#define vtkBoolSurfExampleCellAreas_h

#include "vtkBoolSurfAlgorithm.h"

namespace boolsurf
{
namespace names
{
/// In a real stage: a line of Filters/vtkBoolSurfArrayNames.h.
constexpr const char* CellArea = "CellArea";
}
}

class vtkBoolSurfExampleCellAreas : public vtkBoolSurfAlgorithm
{
public:
  static vtkBoolSurfExampleCellAreas* New();
  vtkTypeMacro(vtkBoolSurfExampleCellAreas, vtkBoolSurfAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Factor applied to every area (default 1), e.g. 0.01 for mm^2 to cm^2. Must be positive.
  vtkSetMacro(AreaScale, double);
  vtkGetMacro(AreaScale, double);
  ///@}

protected:
  vtkBoolSurfExampleCellAreas();
  ~vtkBoolSurfExampleCellAreas() override = default;

  bool Execute(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

private:
  double AreaScale = 1.0;

  vtkBoolSurfExampleCellAreas(const vtkBoolSurfExampleCellAreas&) = delete;
  void operator=(const vtkBoolSurfExampleCellAreas&) = delete;
};

#endif
