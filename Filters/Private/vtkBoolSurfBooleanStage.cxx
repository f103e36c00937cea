#include "vtkBoolSurfBooleanStage.h"

#include "vtkBoolSurfArrayNames.h"

#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

namespace boolsurf
{

//------------------------------------------------------------------------------
void AddExpressionField(vtkPolyData* output, const std::string& text)
{
  vtkNew<vtkStringArray> e;
  e->SetName(boolsurf::names::Expression);
  e->InsertNextValue(text);
  output->GetFieldData()->AddArray(e);
}

} // namespace boolsurf
