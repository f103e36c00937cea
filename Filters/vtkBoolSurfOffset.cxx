#include "vtkBoolSurfOffset.h"

#include "vtkBoolSurfControlCurves.h"

#include "vtkBoolSurfOffsetStage.h"
#include "vtkBoolSurfSurfaceCache.h"

#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <sstream>

vtkStandardNewMacro(vtkBoolSurfOffset);

//------------------------------------------------------------------------------
vtkBoolSurfOffset::vtkBoolSurfOffset()
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkBoolSurfOffset::~vtkBoolSurfOffset() = default;

//------------------------------------------------------------------------------
bool vtkBoolSurfOffset::Execute(const std::vector<vtkPolyData*>& inputs,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  if (!this->GetSurface(inputs[0], error))
  {
    return false;
  }
  if (!inputs[1])
  {
    error = "no control curves on input port 1";
    return false;
  }
  if (boolsurf::PassOnDrawingStart(inputs[1], outputs))
  {
    return true; // a drawing being started: nothing to offset yet, and no message
  }
  boolsurf::OffsetStageOptions options;
  options.Distance = this->Distance;
  options.Expression = this->Expression;
  std::string list = this->Shapes;
  for (char& c : list)
  {
    c = (c == ',' || c == ';') ? ' ' : c;
  }
  std::istringstream in(list);
  std::string token;
  while (in >> token)
  {
    if (!token.empty() && (token[0] == 'S' || token[0] == 's'))
    {
      token = token.substr(1);
    }
    char* end = nullptr;
    const long id = std::strtol(token.c_str(), &end, 10);
    if (token.empty() || *end != '\0' || id < 0 || id > VTK_INT_MAX)
    {
      error = "Shapes entry '" + token + "' is not a ShapeId";
      return false;
    }
    options.Shapes.push_back(static_cast<int>(id));
  }
  options.FillRule = this->FillRule;
  options.Bands = this->Mode == BANDS;
  options.Ends = static_cast<boolsurf::OffsetEndStyle>(this->EndStyle);
  options.OutputResolution = this->OutputResolution;
  options.OutputShapeId = this->OutputShapeId;
  options.KeepInputCurves = this->KeepInputCurves;
  options.Trace = this->GetTraceOptions();
  std::vector<std::string> notes;
  const bool ok = boolsurf::OffsetControlCurves(
    this->GetSurfaceCache(), inputs[1], options, outputs[0], notes, error);
  this->ReportWarnings(notes);
  return ok;
}

//------------------------------------------------------------------------------
void vtkBoolSurfOffset::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Distance: " << this->Distance << "\n";
  os << indent << "Shapes: " << this->Shapes << "\n";
  os << indent << "Expression: " << this->Expression << "\n";
  os << indent << "FillRule: " << this->FillRule << "\n";
  os << indent << "Mode: " << (this->Mode == BANDS ? "Bands" : "Region") << "\n";
  os << indent << "EndStyle: " << (this->EndStyle == FLAT_ENDS ? "Flat" : "Round") << "\n";
  os << indent << "OutputResolution: " << this->OutputResolution << "\n";
  os << indent << "OutputShapeId: " << this->OutputShapeId << "\n";
  os << indent << "KeepInputCurves: " << this->KeepInputCurves << "\n";
}
