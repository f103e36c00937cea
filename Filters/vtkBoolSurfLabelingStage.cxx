#include "vtkBoolSurfLabelingStage.h"

#include "Labeling/ArrangementLabelingInput.h"
#include "Selection/BooleanExpression.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>

#include <vector>

namespace boolsurf
{
namespace
{

// ArrangementCell per triangle as ints (the arrangement writes a vtkIntArray; anything else
// is converted once).
std::vector<int> CellOfTriangles(vtkDataArray* cellOf)
{
  const vtkIdType n = cellOf->GetNumberOfTuples();
  std::vector<int> cells(n);
  if (auto* ints = vtkArrayDownCast<vtkIntArray>(cellOf))
  {
    std::copy_n(ints->GetPointer(0), n, cells.data());
  }
  else
  {
    for (vtkIdType t = 0; t < n; ++t)
    {
      cells[t] = static_cast<int>(cellOf->GetComponent(t, 0));
    }
  }
  return cells;
}

} // namespace

//------------------------------------------------------------------------------
std::string InconsistencyWarning(const LabelingResult& labels)
{
  std::string warning;
  for (const LabelConflict& c : labels.Conflicts)
  {
    warning += (warning.empty() ? "" : "; ") + std::string("shape S") +
      std::to_string(labels.ShapeIdOf(c.Shape)) + " is inconsistent: cell " +
      std::to_string(c.Cell) + " is reached with labels " + std::to_string(c.FirstLabel) + " and " +
      std::to_string(c.SecondLabel);
  }
  if (!warning.empty())
  {
    warning += " (its curves do not bound a region; Booleans refuse it)";
  }
  return warning;
}

//------------------------------------------------------------------------------
bool LabelArrangement(vtkPolyData* input,
  const LabelingOutputOptions& options,
  vtkPolyData* output,
  ArrangementFields& fields,
  LabelingResult& labels,
  std::string& error,
  std::string& warning)
{
  if (!ReadArrangementFields(input, fields, error))
  {
    return false;
  }
  vtkDataArray* cellOf = input->GetCellData()->GetArray("ArrangementCell");
  LabelingInput in;
  in.NumberOfCells = fields.NumberOfCells;
  in.NumberOfShapes = fields.NumberOfShapes;
  in.ShapeIds = fields.ShapeIds;
  in.Arcs = fields.Arcs;
  in.CellComponent = fields.CellComponent;
  in.ZeroCells = fields.ZeroCellCandidates;
  if (options.ZeroCellPoint)
  {
    vtkNew<vtkStaticCellLocator> locator;
    locator->SetDataSet(input);
    locator->BuildLocator();
    double closest[3], dist2;
    vtkIdType cell = -1;
    int sub;
    vtkNew<vtkGenericCell> scratch;
    locator->FindClosestPoint(options.ZeroCellPoint, closest, scratch, cell, sub, dist2);
    if (cell < 0)
    {
      error = "no surface cell found near ZeroCellPoint";
      return false;
    }
    const int zero = static_cast<int>(cellOf->GetComponent(cell, 0));
    const int comp = in.CellComponent.empty() ? 0 : in.CellComponent[zero];
    if (static_cast<int>(in.ZeroCells.size()) <= comp)
    {
      in.ZeroCells.resize(comp + 1, -1);
    }
    in.ZeroCells[comp] = zero;
  }
  labels = LabelCells(in);

  output->ShallowCopy(input);
  const int ns = fields.NumberOfShapes;
  warning = InconsistencyWarning(labels);
  if (ns > 0)
  {
    vtkNew<vtkIntArray> consistent;
    consistent->SetName("ShapeConsistent");
    consistent->SetNumberOfTuples(ns);
    for (int s = 0; s < ns; ++s)
    {
      consistent->SetValue(s, labels.ShapeConsistent[s]);
    }
    output->GetFieldData()->AddArray(consistent);
    if (fields.NumberOfCells > 0)
    {
      vtkNew<vtkIntArray> cellLabels;
      cellLabels->SetName("CellLabels");
      cellLabels->SetNumberOfComponents(ns);
      for (int s = 0; s < ns; ++s)
      {
        cellLabels->SetComponentName(s, ("S" + std::to_string(labels.ShapeIdOf(s))).c_str());
      }
      cellLabels->SetNumberOfTuples(fields.NumberOfCells);
      std::copy(labels.Labels.begin(), labels.Labels.end(), cellLabels->GetPointer(0));
      output->GetFieldData()->AddArray(cellLabels);
    }
  }

  // Per-triangle arrays only on request: the table above is what the labels are.
  const bool color = options.ColorShape >= 0;
  if (!color && !options.PerTriangleLabels)
  {
    return true;
  }
  const std::vector<int> cells = CellOfTriangles(cellOf);
  const vtkIdType nt = static_cast<vtkIdType>(cells.size());
  if (color)
  {
    const int s = ShapeIndexOf(fields.ShapeIds, options.ColorShape);
    if (s < 0)
    {
      warning += (warning.empty() ? "" : "; ") + std::string("ColorShape S") +
        std::to_string(options.ColorShape) + " is not a shape of the input (" +
        ShapeList(fields.ShapeIds) + "): no ShapeLabel array";
    }
    else
    {
      vtkNew<vtkIntArray> shapeLabel;
      shapeLabel->SetName("ShapeLabel");
      shapeLabel->SetNumberOfTuples(nt);
      int* out = shapeLabel->GetPointer(0);
      const int* table = labels.Labels.data();
      for (vtkIdType t = 0; t < nt; ++t)
      {
        out[t] = table[static_cast<size_t>(cells[t]) * ns + s];
      }
      output->GetCellData()->AddArray(shapeLabel);
    }
  }
  if (options.PerTriangleLabels && ns > 0)
  {
    vtkNew<vtkIntArray> perTriangle;
    perTriangle->SetName("Labels");
    perTriangle->SetNumberOfComponents(ns);
    for (int s = 0; s < ns; ++s)
    {
      perTriangle->SetComponentName(s, ("S" + std::to_string(labels.ShapeIdOf(s))).c_str());
    }
    perTriangle->SetNumberOfTuples(nt);
    int* out = perTriangle->GetPointer(0);
    for (vtkIdType t = 0; t < nt; ++t)
    {
      std::copy_n(labels.Labels.data() + static_cast<size_t>(cells[t]) * ns, ns, out + t * ns);
    }
    output->GetCellData()->AddArray(perTriangle);
  }
  return true;
}

} // namespace boolsurf
