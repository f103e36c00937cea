// The Boolean selection stage on VTK data, shared by vtkBoolSurfBoolean and the one-step
// vtkBoolSurf filter (a private header of the module): the selection itself is Core's
// (Selection/BooleanOptions.h), over the options the filters hold.
#ifndef vtkBoolSurfBooleanStage_h
#define vtkBoolSurfBooleanStage_h

#include "Selection/BooleanOptions.h"

#include <string>

class vtkPolyData;

namespace boolsurf
{

/// The field data `Expression` (the expression a result was selected with).
void AddExpressionField(vtkPolyData* output, const std::string& text);

} // namespace boolsurf

#endif
