#include "vtkBoolSurfCheckSurface.h"

#include "vtkBoolSurfArrayNames.h"

#include "vtkBoolSurfArrayView.h"
#include "vtkBoolSurfDistributedCheck.h"
#include "vtkBoolSurfSurfaceAdapter.h"
#include "vtkBoolSurfSurfacePiece.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiProcessController.h>
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
  boolsurf::SurfaceCheckOptions options;
  options.DegenerateTolerance = this->DegenerateTolerance;
  boolsurf::vtkSurfaceInput surface;
  boolsurf::ConvertSurface(inputs[0], surface, options);
  this->UpdateProgress(0.7);

  const boolsurf::TriangleMesh& mesh = *surface.Mesh;
  const boolsurf::MeshTopology& topo = *surface.Topology;
  boolsurf::SurfaceCheckOutput check;
  check.ComponentId.resize(mesh.GetNumberOfTriangles());
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    check.ComponentId[t] = topo.TriangleComponent[t];
  }
  check.BoundaryLoopId.resize(mesh.GetNumberOfVertices());
  for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
  {
    check.BoundaryLoopId[v] = topo.GetVertexBoundaryLoop(v);
  }
  check.Components = topo.Components;
  check.IsManifold = surface.Check.IsManifold;
  for (const boolsurf::BoundaryLoop& loop : topo.BoundaryLoops)
  {
    check.BoundaryLoopLengths.push_back(loop.Length);
  }
  for (const std::string& w : surface.Warnings)
  {
    check.Problems.push_back("Warning Conversion: " + w);
  }
  for (const boolsurf::SurfaceProblem& p : surface.Check.Problems)
  {
    check.Problems.push_back(
      (p.Level == boolsurf::Severity::Error ? "Error " : "Warning ") + p.Kind + ": " + p.Message);
  }
  this->WriteOutput(surface.Triangles, check, outputs[0]);
  return true;
}

//------------------------------------------------------------------------------
bool vtkBoolSurfCheckSurface::ExecutePiece(const std::vector<vtkPolyData*>& locals,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  // Every rank builds its piece and checks it; the collective calls inside are the same on
  // every rank, and a failure (overlapping pieces) is known on every rank.
  vtkBoolSurfSurfacePiece piece;
  std::vector<std::string> warnings;
  if (!piece.Build(vtkMultiProcessController::GetGlobalController(), locals[0], error, warnings))
  {
    return false;
  }
  this->ReportWarnings(warnings);
  boolsurf::SurfaceCheckOutput check;
  boolsurf::CheckDistributedSurface(piece, check);
  this->WriteOutput(piece.GetSurface().Triangles, check, outputs[0]);
  return true;
}

//------------------------------------------------------------------------------
void vtkBoolSurfCheckSurface::WriteOutput(vtkPolyData* triangles,
  const boolsurf::SurfaceCheckOutput& check,
  vtkPolyData* output)
{
  output->ShallowCopy(triangles);
  const vtkIdType nt = static_cast<vtkIdType>(check.ComponentId.size());
  auto componentId = NamedIntArray(boolsurf::names::ComponentId, nt, -1);
  for (vtkIdType t = 0; t < nt; ++t)
  {
    componentId->SetValue(t, check.ComponentId[t]);
  }
  output->GetCellData()->AddArray(componentId);

  const vtkIdType nv = static_cast<vtkIdType>(check.BoundaryLoopId.size());
  auto loopId = NamedIntArray(boolsurf::names::BoundaryLoopId, nv, -1);
  for (vtkIdType v = 0; v < nv; ++v)
  {
    loopId->SetValue(v, check.BoundaryLoopId[v]);
  }
  output->GetPointData()->AddArray(loopId);

  const int nc = static_cast<int>(check.Components.size());
  auto components = NamedIntArray(boolsurf::names::Components, 1, nc);
  auto genus = NamedIntArray(boolsurf::names::Genus, nc, 0);
  auto loops = NamedIntArray(boolsurf::names::BoundaryLoops, nc, 0);
  auto euler = NamedIntArray(boolsurf::names::EulerCharacteristic, nc, 0);
  for (int c = 0; c < nc; ++c)
  {
    genus->SetValue(c, check.Components[c].Genus);
    loops->SetValue(c, check.Components[c].BoundaryLoops);
    euler->SetValue(c, check.Components[c].EulerCharacteristic);
  }
  auto manifold = NamedIntArray(boolsurf::names::IsManifold, 1, check.IsManifold ? 1 : 0);
  vtkNew<vtkDoubleArray> loopLength;
  loopLength->SetName(boolsurf::names::BoundaryLoopLength);
  for (double length : check.BoundaryLoopLengths)
  {
    loopLength->InsertNextValue(length);
  }
  vtkNew<vtkStringArray> problems;
  problems->SetName(boolsurf::names::Problems);
  for (const std::string& line : check.Problems)
  {
    problems->InsertNextValue(line);
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
}

//------------------------------------------------------------------------------
void vtkBoolSurfCheckSurface::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DegenerateTolerance: " << this->DegenerateTolerance << "\n";
  os << indent << "WarnOnProblems: " << (this->WarnOnProblems ? "On" : "Off") << "\n";
}
