#include "vtkBoolSurfLabelingStage.h"

#include "vtkBoolSurfArrayNames.h"

#include "Labeling/ArrangementLabelingInput.h"
#include "Selection/BooleanExpression.h"
#include "vtkBoolSurfHomologyOutput.h"
#include "vtkBoolSurfStageHandoff.h"
#include "vtkBoolSurfTriangleLabels.h"

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

// Components named after the shapes: S<id>, in the order of the labels' shapes.
void NameShapeComponents(vtkDataArray* a, const LabelingResult& labels)
{
  a->SetNumberOfComponents(labels.NumberOfShapes);
  for (int s = 0; s < labels.NumberOfShapes; ++s)
  {
    a->SetComponentName(s, ("S" + std::to_string(labels.ShapeIdOf(s))).c_str());
  }
}

} // namespace

//------------------------------------------------------------------------------
void AddLabelTable(const LabelingResult& labels, vtkFieldData* fd)
{
  const int ns = labels.NumberOfShapes;
  if (ns == 0)
  {
    return; // no empty arrays: VTK's XML writer cannot read them back
  }
  vtkNew<vtkIntArray> ids, consistent;
  ids->SetName(boolsurf::names::ShapeIds);
  consistent->SetName(boolsurf::names::ShapeConsistent);
  ids->SetNumberOfTuples(ns);
  consistent->SetNumberOfTuples(ns);
  for (int s = 0; s < ns; ++s)
  {
    ids->SetValue(s, labels.ShapeIdOf(s));
    consistent->SetValue(s, labels.ShapeConsistent[s]);
  }
  fd->AddArray(ids);
  fd->AddArray(consistent);
  const vtkIdType cells = static_cast<vtkIdType>(labels.Labels.size()) / ns;
  if (cells > 0)
  {
    vtkNew<vtkIntArray> cellLabels;
    cellLabels->SetName(boolsurf::names::CellLabels);
    NameShapeComponents(cellLabels, labels);
    cellLabels->SetNumberOfTuples(cells);
    std::copy(labels.Labels.begin(), labels.Labels.end(), cellLabels->GetPointer(0));
    fd->AddArray(cellLabels);
  }
}

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
int ZeroCellAt(vtkStaticCellLocator* locator,
  const TriangleMesh& mesh,
  const Arrangement& arrangement,
  const double point[3],
  std::string& error)
{
  double closest[3], dist2;
  vtkIdType cell = -1;
  int sub;
  vtkNew<vtkGenericCell> scratch;
  if (locator)
  {
    locator->FindClosestPoint(point, closest, scratch, cell, sub, dist2);
  }
  if (cell < 0)
  {
    error = "no surface cell found near ZeroCellPoint";
    return -1;
  }
  const SurfacePoint at =
    PointInTriangle(mesh, static_cast<int>(cell), Vec3{ closest[0], closest[1], closest[2] });
  const int zero = CellAtSurfacePoint(mesh, arrangement, at.Triangle, at.U, at.V);
  if (zero < 0)
  {
    error = "ZeroCellPoint lies on triangle " + std::to_string(cell) +
      ", which is not part of the surface";
  }
  return zero;
}

//------------------------------------------------------------------------------
bool LabelArrangement(vtkPolyData* input,
  const ArrangementResult& arranged,
  const LabelingOutputOptions& options,
  vtkPolyData* output,
  LabelingResult& labels,
  std::string& error,
  std::string& warning)
{
  // The one-step filter's labeling, on the arrangement itself.
  const Arrangement& arr = arranged.Arrangement;
  LabelingInput in =
    MakeLabelingInput(*arranged.Surface.Mesh, *arranged.Surface.Topology, arranged.Curves, arr);
  if (options.ZeroCell.Mode == ZeroCellMode::Point)
  {
    const int zero = ZeroCellAt(
      options.SurfaceLocator, *arranged.Surface.Mesh, arr, options.ZeroCell.Point.data(), error);
    if (zero < 0)
    {
      return false;
    }
    in.SetZeroCell(zero);
  }
  labels = LabelCells(in);
  WriteLabelingOutput(input, &arr, labels, options, output, warning);
  return true;
}

//------------------------------------------------------------------------------
void WriteLabelingOutput(vtkPolyData* input,
  const Arrangement* arrangement,
  const LabelingResult& labels,
  const LabelingOutputOptions& options,
  vtkPolyData* output,
  std::string& warning)
{
  vtkDataArray* cellOf = input->GetCellData()->GetArray(boolsurf::names::ArrangementCell);
  output->ShallowCopy(input);
  const int ns = labels.NumberOfShapes;
  warning = InconsistencyWarning(labels);
  AddLabelTable(labels, output->GetFieldData());
  // Generators in excess per shape, and what they mean for the inconsistent ones.
  const HomologyFields homology = ReadHomologyFields(input->GetFieldData(), false);
  if (homology.Present)
  {
    AddHomologyExcess(
      ShapeExcess(homology, labels.ShapeIds), labels.ShapeIds, output->GetFieldData());
    const std::string why = ExplainInconsistency(labels, homology);
    warning += why.empty() ? "" : "\n" + why;
  }

  // Per-triangle arrays only on request: the table above is what the labels are.
  const bool color = options.ColorShape >= 0;
  if (!color && !options.PerTriangleLabels)
  {
    return;
  }
  // The arrangement's cells read in place (it writes them as ints), else converted.
  std::vector<int> converted;
  const int* cells = nullptr;
  if (auto* ints = vtkArrayDownCast<vtkIntArray>(cellOf))
  {
    cells = ints->GetPointer(0);
  }
  else
  {
    converted = ReadTriangleCells(cellOf);
    cells = converted.data();
  }
  const vtkIdType nt = cellOf->GetNumberOfTuples();
  KeptTriangleLabels fresh; // when the caller keeps no arrays: written whole
  if (color)
  {
    const int s = ShapeIndexOf(labels.ShapeIds, options.ColorShape);
    if (s < 0)
    {
      warning += (warning.empty() ? "" : "; ") + std::string("ColorShape S") +
        std::to_string(options.ColorShape) + " is not a shape of the input (" +
        ShapeList(labels.ShapeIds) + "): no ShapeLabel array";
    }
    else
    {
      std::vector<int> column(labels.Labels.size() / ns);
      for (std::size_t c = 0; c < column.size(); ++c)
      {
        column[c] = labels.Labels[c * ns + s];
      }
      KeptTriangleLabels& kept = options.KeptShapeLabel ? *options.KeptShapeLabel : fresh;
      vtkSmartPointer<vtkIntArray> shapeLabel = kept.Update(arrangement, cells, nt, column, 1);
      shapeLabel->SetName(boolsurf::names::ShapeLabel);
      output->GetCellData()->AddArray(shapeLabel);
      // ParaView colors a new display by the active scalars (with the plugin's categorical
      // color map for ShapeLabel).
      output->GetCellData()->SetActiveScalars(boolsurf::names::ShapeLabel);
    }
  }
  if (options.PerTriangleLabels && ns > 0)
  {
    KeptTriangleLabels& kept = options.KeptLabels ? *options.KeptLabels : fresh;
    vtkSmartPointer<vtkIntArray> perTriangle =
      kept.Update(arrangement, cells, nt, labels.Labels, ns);
    perTriangle->SetName(boolsurf::names::Labels);
    NameShapeComponents(perTriangle, labels);
    output->GetCellData()->AddArray(perTriangle);
  }
}

} // namespace boolsurf
