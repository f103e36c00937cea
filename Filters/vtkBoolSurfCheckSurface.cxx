#include "vtkBoolSurfCheckSurface.h"

#include "vtkBoolSurfArrayNames.h"

#include "vtkBoolSurfArrayView.h"
#include "vtkBoolSurfSurfaceAdapter.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

vtkStandardNewMacro(vtkBoolSurfCheckSurface);

namespace
{
vtkSmartPointer<vtkIntArray> NamedIntArray(const char* name, vtkIdType n, int fill)
{
  auto a = boolsurf::NewSizedArray<vtkIntArray>(name, 1, n);
  a->FillValue(fill);
  return a;
}
} // namespace

//------------------------------------------------------------------------------
vtkBoolSurfCheckSurface::vtkBoolSurfCheckSurface() = default;

//------------------------------------------------------------------------------
bool vtkBoolSurfCheckSurface::Execute(const std::vector<vtkPolyData*>& inputs,
  const std::vector<vtkPolyData*>& outputs,
  std::string& vtkNotUsed(error))
{
  vtkPolyData* input = inputs[0];
  vtkPolyData* output = outputs[0];

  boolsurf::SurfaceCheckOptions options;
  options.DegenerateTolerance = this->DegenerateTolerance;
  boolsurf::vtkSurfaceInput surface;
  boolsurf::ConvertSurface(input, surface, options);
  this->UpdateProgress(0.7);

  output->ShallowCopy(surface.Triangles);
  const boolsurf::TriangleMesh& mesh = *surface.Mesh;
  const boolsurf::MeshTopology& topo = *surface.Topology;

  auto componentId = NamedIntArray(boolsurf::names::ComponentId, mesh.GetNumberOfTriangles(), -1);
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    componentId->SetValue(t, topo.TriangleComponent[t]);
  }
  output->GetCellData()->AddArray(componentId);

  auto loopId = NamedIntArray(boolsurf::names::BoundaryLoopId, mesh.GetNumberOfVertices(), -1);
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    loopId->SetValue(v, topo.GetVertexBoundaryLoop(v));
  }
  output->GetPointData()->AddArray(loopId);

  const int nc = topo.GetNumberOfComponents();
  auto components = NamedIntArray(boolsurf::names::Components, 1, nc);
  auto genus = NamedIntArray(boolsurf::names::Genus, nc, 0);
  auto loops = NamedIntArray(boolsurf::names::BoundaryLoops, nc, 0);
  auto euler = NamedIntArray(boolsurf::names::EulerCharacteristic, nc, 0);
  for (int c = 0; c < nc; ++c)
  {
    genus->SetValue(c, topo.Components[c].Genus);
    loops->SetValue(c, topo.Components[c].BoundaryLoops);
    euler->SetValue(c, topo.Components[c].EulerCharacteristic);
  }
  auto manifold = NamedIntArray(boolsurf::names::IsManifold, 1, surface.Check.IsManifold ? 1 : 0);
  vtkNew<vtkDoubleArray> loopLength;
  loopLength->SetName(boolsurf::names::BoundaryLoopLength);
  for (const boolsurf::BoundaryLoop& loop : topo.BoundaryLoops)
  {
    loopLength->InsertNextValue(loop.Length);
  }
  vtkNew<vtkStringArray> problems;
  problems->SetName(boolsurf::names::Problems);
  for (const std::string& w : surface.Warnings)
  {
    problems->InsertNextValue("Warning Conversion: " + w);
  }
  for (const boolsurf::SurfaceProblem& p : surface.Check.Problems)
  {
    problems->InsertNextValue(
      (p.Level == boolsurf::Severity::Error ? "Error " : "Warning ") + p.Kind + ": " + p.Message);
  }

  vtkFieldData* fd = output->GetFieldData();
  for (vtkAbstractArray* a : std::initializer_list<vtkAbstractArray*>{
         components, genus, loops, euler, manifold, loopLength, problems })
  {
    // VTK 9.2's XML writer produces an unreadable file for an empty numeric array, so arrays
    // with nothing to say (no components, no loops) are left out.
    if (a->GetNumberOfTuples() > 0 || a == problems.GetPointer())
    {
      fd->AddArray(a);
    }
  }

  if (this->WarnOnProblems)
  {
    for (vtkIdType i = 0; i < problems->GetNumberOfValues(); ++i)
    {
      vtkWarningMacro(<< problems->GetValue(i));
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkBoolSurfCheckSurface::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DegenerateTolerance: " << this->DegenerateTolerance << "\n";
  os << indent << "WarnOnProblems: " << (this->WarnOnProblems ? "On" : "Off") << "\n";
}
