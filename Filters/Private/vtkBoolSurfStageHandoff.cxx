#include "vtkBoolSurfStageHandoff.h"

#include "Geodesic/CurveTracer.h"

#include <vtkAbstractArray.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkInformation.h>
#include <vtkInformationObjectBaseKey.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace
{

/// The attached result and what the witness looked like when it was attached.
class vtkBoolSurfStageResultHolder : public vtkObject
{
public:
  static vtkBoolSurfStageResultHolder* New();
  vtkTypeMacro(vtkBoolSurfStageResultHolder, vtkObject);
  static vtkInformationObjectBaseKey* STAGE_RESULT();

  std::shared_ptr<const void> Result;
  const std::type_info* Type = nullptr;
  vtkMTimeType WitnessTime = 0;
  vtkIdType WitnessValues = 0;

protected:
  vtkBoolSurfStageResultHolder() = default;
  ~vtkBoolSurfStageResultHolder() override = default;

private:
  vtkBoolSurfStageResultHolder(const vtkBoolSurfStageResultHolder&) = delete;
  void operator=(const vtkBoolSurfStageResultHolder&) = delete;
};

vtkStandardNewMacro(vtkBoolSurfStageResultHolder);
vtkInformationKeyMacro(vtkBoolSurfStageResultHolder, STAGE_RESULT, ObjectBase);

} // namespace

namespace boolsurf
{

//------------------------------------------------------------------------------
SurfaceIdentity::SurfaceIdentity(vtkPolyData* surface)
{
  if (!surface || !surface->GetPoints())
  {
    return;
  }
  this->Points = surface->GetPoints()->GetData();
  this->Polys = surface->GetPolys();
  this->PointsTime = this->Points ? this->Points->GetMTime() : 0;
  this->PolysTime = this->Polys ? this->Polys->GetMTime() : 0;
  this->NumberOfPoints = surface->GetNumberOfPoints();
  this->NumberOfPolys = surface->GetNumberOfPolys();
}

//------------------------------------------------------------------------------
bool SurfaceIdentity::Matches(vtkPolyData* surface) const
{
  if (!surface || !surface->GetPoints() || !this->Points || !this->Polys)
  {
    return false;
  }
  // Other cells (strips, polygons to triangulate) are converted too: only plain polygon
  // surfaces are recognized, which is what a surface for BoolSurf is.
  return surface->GetPoints()->GetData() == this->Points.GetPointer() &&
    surface->GetPolys() == this->Polys.GetPointer() &&
    this->Points->GetMTime() == this->PointsTime && this->Polys->GetMTime() == this->PolysTime &&
    surface->GetNumberOfPoints() == this->NumberOfPoints &&
    surface->GetNumberOfPolys() == this->NumberOfPolys && surface->GetNumberOfStrips() == 0;
}

const char* const NoControlPointsNote =
  "the arrangement does not carry its curves' control points (they were not traced by Trace "
  "Surface Curves): the control-point outputs are empty";

//------------------------------------------------------------------------------
ResultPathSolver::ResultPathSolver() = default;
ResultPathSolver::~ResultPathSolver() = default;

GeodesicPathSolver& ResultPathSolver::Get(const std::shared_ptr<const TriangleMesh>& mesh,
  GeodesicMethod method)
{
  if (!this->Tracer || this->Mesh != mesh)
  {
    this->Tracer = std::make_unique<CurveTracer>(*mesh);
    this->Mesh = mesh; // keeps the mesh alive as long as the tracer refers to it
  }
  GeodesicPathSolver& solver = this->Tracer->GetPathSolver();
  GeodesicPathOptions pathOptions = solver.GetOptions();
  pathOptions.Method = method;
  solver.SetOptions(pathOptions);
  return solver;
}

//------------------------------------------------------------------------------
vtkStaticCellLocator* SurfaceLocator::Get(vtkPolyData* surface)
{
  if (!surface)
  {
    return nullptr;
  }
  if (!this->Locator || this->Surface.GetPointer() != surface || this->Time != surface->GetMTime())
  {
    this->Locator = vtkSmartPointer<vtkStaticCellLocator>::New();
    this->Locator->SetDataSet(surface);
    this->Locator->BuildLocator();
    this->Surface = surface;
    this->Time = surface->GetMTime();
  }
  return this->Locator;
}

//------------------------------------------------------------------------------
void AttachStageResult(vtkAbstractArray* witness,
  std::shared_ptr<const void> result,
  const std::type_info& type)
{
  if (!witness)
  {
    return;
  }
  // The array's information object is created on first use, which marks the array modified:
  // create it before the array's time is recorded.
  vtkInformation* info = witness->GetInformation();
  vtkNew<vtkBoolSurfStageResultHolder> holder;
  holder->Result = std::move(result);
  holder->Type = &type;
  holder->WitnessTime = witness->GetMTime();
  holder->WitnessValues = witness->GetNumberOfValues();
  info->Set(vtkBoolSurfStageResultHolder::STAGE_RESULT(), holder);
}

//------------------------------------------------------------------------------
std::shared_ptr<const void> FindStageResult(vtkAbstractArray* witness, const std::type_info& type)
{
  if (!witness || !witness->HasInformation())
  {
    return nullptr;
  }
  auto* holder = vtkBoolSurfStageResultHolder::SafeDownCast(
    witness->GetInformation()->Get(vtkBoolSurfStageResultHolder::STAGE_RESULT()));
  if (!holder || !holder->Type || *holder->Type != type ||
    holder->WitnessTime != witness->GetMTime() ||
    holder->WitnessValues != witness->GetNumberOfValues())
  {
    return nullptr;
  }
  return holder->Result;
}

} // namespace boolsurf
