#include "vtkBoolSurfLabelingStage.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>

#include <cmath>

namespace boolsurf
{

//------------------------------------------------------------------------------
bool LabelArrangement(vtkPolyData* input,
  const double* zeroCellPoint,
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
  in.Arcs = fields.Arcs;
  in.CellComponent = fields.CellComponent;
  in.ZeroCells = fields.ZeroCellCandidates;
  if (zeroCellPoint)
  {
    vtkNew<vtkStaticCellLocator> locator;
    locator->SetDataSet(input);
    locator->BuildLocator();
    double closest[3], dist2;
    vtkIdType cell = -1;
    int sub;
    vtkNew<vtkGenericCell> scratch;
    locator->FindClosestPoint(zeroCellPoint, closest, scratch, cell, sub, dist2);
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
  vtkNew<vtkIntArray> perTriangle;
  perTriangle->SetName("Labels");
  perTriangle->SetNumberOfComponents(std::max(ns, 1));
  for (int s = 0; s < ns; ++s)
  {
    perTriangle->SetComponentName(s, ("S" + std::to_string(s)).c_str());
  }
  const vtkIdType nt = input->GetNumberOfCells();
  perTriangle->SetNumberOfTuples(nt);
  if (ns == 0)
  {
    perTriangle->FillValue(0);
  }
  for (vtkIdType t = 0; t < nt && ns > 0; ++t)
  {
    const int c = static_cast<int>(cellOf->GetComponent(t, 0));
    std::copy(labels.Labels.begin() + static_cast<size_t>(c) * ns,
      labels.Labels.begin() + static_cast<size_t>(c + 1) * ns,
      perTriangle->GetPointer(t * ns));
  }
  output->GetCellData()->AddArray(perTriangle);
  if (ns > 0)
  {
    vtkNew<vtkIntArray> consistent;
    consistent->SetName("ShapeConsistent");
    for (int s = 0; s < ns; ++s)
    {
      consistent->InsertNextValue(labels.ShapeConsistent[s]);
    }
    output->GetFieldData()->AddArray(consistent);
    vtkNew<vtkIntArray> cellLabels;
    cellLabels->SetName("CellLabels");
    cellLabels->SetNumberOfComponents(ns);
    cellLabels->SetNumberOfTuples(fields.NumberOfCells);
    std::copy(labels.Labels.begin(), labels.Labels.end(), cellLabels->GetPointer(0));
    if (fields.NumberOfCells > 0)
    {
      output->GetFieldData()->AddArray(cellLabels);
    }
  }
  warning.clear();
  for (const LabelConflict& c : labels.Conflicts)
  {
    warning += (warning.empty() ? "" : "; ") + std::string("shape S") + std::to_string(c.Shape) +
      " is inconsistent: cell " + std::to_string(c.Cell) + " is reached with labels " +
      std::to_string(c.FirstLabel) + " and " + std::to_string(c.SecondLabel);
  }
  if (!warning.empty())
  {
    warning += " (its curves do not bound a region; Booleans refuse it)";
  }
  return true;
}

} // namespace boolsurf
