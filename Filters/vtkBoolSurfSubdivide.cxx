#include "vtkBoolSurfSubdivide.h"

#include "vtkBoolSurfArrayNames.h"

#include "Mesh/SubdivisionMap.h"
#include "Mesh/SurfacePoint.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLinearSubdivisionFilter.h"
#include "vtkLoopSubdivisionFilter.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkBoolSurfSubdivide);

namespace
{

/// The triangles of `pd`, or false with the id of the first cell that is not one.
bool TrianglesOf(vtkPolyData* pd, std::vector<boolsurf::Triangle>& out, std::string& error)
{
  out.clear();
  if (pd->GetNumberOfVerts() + pd->GetNumberOfLines() + pd->GetNumberOfStrips() > 0)
  {
    error = "the surface has vertex, line or strip cells: it must be triangles only";
    return false;
  }
  out.reserve(static_cast<std::size_t>(pd->GetNumberOfPolys()));
  auto it = vtk::TakeSmartPointer(pd->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    if (n != 3)
    {
      error = "surface cell " + std::to_string(it->GetCurrentCellId()) + " has " +
        std::to_string(n) + " points: the surface must be triangles only";
      return false;
    }
    out.push_back({ static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) });
  }
  if (out.empty())
  {
    error = "the surface has no triangle";
    return false;
  }
  return true;
}

/// Errors a VTK filter reports, gathered instead of printed.
struct ErrorCollector
{
  std::string Text;
  vtkNew<vtkCallbackCommand> Command;
  explicit ErrorCollector(vtkObject* watched)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback(
      [](vtkObject*, unsigned long, void* self, void* text)
      {
        auto* c = static_cast<ErrorCollector*>(self);
        c->Text += text ? static_cast<const char*>(text) : "";
      });
    watched->AddObserver(vtkCommand::ErrorEvent, this->Command);
  }
};

} // namespace

//------------------------------------------------------------------------------
vtkBoolSurfSubdivide::vtkBoolSurfSubdivide()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkBoolSurfSubdivide::~vtkBoolSurfSubdivide() = default;

//------------------------------------------------------------------------------
bool vtkBoolSurfSubdivide::Execute(const std::vector<vtkPolyData*>& inputs,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  vtkPolyData* surface = inputs[0];
  vtkPolyData* curves = inputs[1];
  vtkPolyData* surfaceOut = outputs[0];
  vtkPolyData* curvesOut = outputs[1];
  if (!surface || !curves)
  {
    error = "Both inputs are needed: the surface (port 0) and the curves (port 1).";
    return false;
  }
  std::vector<boolsurf::Triangle> parent;
  if (!TrianglesOf(surface, parent, error))
  {
    return false;
  }
  vtkDataArray* triangleIds = curves->GetPointData()->GetArray(boolsurf::names::TriangleId);
  vtkDataArray* barycentric = curves->GetPointData()->GetArray(boolsurf::names::Barycentric);
  const vtkIdType numberOfPoints = curves->GetNumberOfPoints();
  if (!triangleIds || !barycentric || barycentric->GetNumberOfComponents() != 2 ||
    triangleIds->GetNumberOfTuples() < numberOfPoints ||
    barycentric->GetNumberOfTuples() < numberOfPoints)
  {
    error = "The curves have no surface points: point data TriangleId and Barycentric (2 "
            "components, one per point) are needed.";
    return false;
  }
  std::vector<boolsurf::SurfacePoint> points(static_cast<std::size_t>(numberOfPoints));
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    const double t = triangleIds->GetComponent(p, 0);
    const double u = barycentric->GetComponent(p, 0), v = barycentric->GetComponent(p, 1);
    if (!(t >= 0 && t < static_cast<double>(parent.size()) && t == std::floor(t)))
    {
      std::ostringstream message;
      message << "Curve point " << p << ": TriangleId " << t << " is not a triangle of the "
              << parent.size() << "-triangle surface.";
      error = message.str();
      return false;
    }
    if (!boolsurf::IsInsideTriangle(u, v))
    {
      std::ostringstream message;
      message << "Curve point " << p << ": Barycentric (" << u << ", " << v
              << ") is outside its triangle.";
      error = message.str();
      return false;
    }
    // Located as every reader locates it (a weight within rounding of zero is zero), so the
    // subdivision does not magnify rounding off an edge or a vertex into a distance.
    points[p] = boolsurf::SnapWeights({ static_cast<int>(t), std::max(u, 0.0), std::max(v, 0.0) });
  }

  // One step at a time: the map of each step needs both of its meshes.
  vtkSmartPointer<vtkPolyData> current = vtkSmartPointer<vtkPolyData>::New();
  current->SetPoints(surface->GetPoints());
  current->SetPolys(surface->GetPolys());
  current->GetPointData()->PassData(surface->GetPointData());
  std::vector<boolsurf::Triangle> child;
  for (int level = 0; level < this->NumberOfSubdivisions; ++level)
  {
    if (this->CheckAbort())
    {
      return true;
    }
    vtkSmartPointer<vtkPolyDataAlgorithm> subdivision;
    if (this->Scheme == LOOP)
    {
      subdivision = vtkSmartPointer<vtkLoopSubdivisionFilter>::New();
    }
    else
    {
      subdivision = vtkSmartPointer<vtkLinearSubdivisionFilter>::New();
    }
    vtkSubdivisionFilter::SafeDownCast(subdivision)->SetNumberOfSubdivisions(1);
    subdivision->SetInputData(current);
    ErrorCollector errors(subdivision);
    subdivision->Update();
    vtkSmartPointer<vtkPolyData> finer = subdivision->GetOutput();
    if (!errors.Text.empty() || finer->GetNumberOfPolys() == 0)
    {
      std::ostringstream message;
      message << "Subdivision step " << level + 1 << " ("
              << (this->Scheme == LOOP ? "Loop" : "linear") << ") failed: " << errors.Text;
      error = message.str();
      return false;
    }
    boolsurf::SubdivisionMap map;
    if (!TrianglesOf(finer, child, error) ||
      !map.Build(parent, static_cast<int>(current->GetNumberOfPoints()), child, error))
    {
      error = "Subdivision step " + std::to_string(level + 1) + ": " + error;
      return false;
    }
    for (boolsurf::SurfacePoint& p : points)
    {
      p = map.Map(p);
    }
    if (this->Scheme == LINEAR)
    {
      // VTK's subdivision filters write single-precision points: the midpoints are computed
      // again in double, so that the finer surface is the coarse one exactly and curve points
      // keep their positions to rounding.
      vtkNew<vtkPoints> exact;
      exact->SetDataTypeToDouble();
      exact->SetNumberOfPoints(finer->GetNumberOfPoints());
      vtkPoints* coarsePoints = current->GetPoints();
      const auto& edgeOf = map.GetEdgeOfNewVertex();
      const vtkIdType old = current->GetNumberOfPoints();
      for (vtkIdType v = 0; v < finer->GetNumberOfPoints(); ++v)
      {
        double x[3];
        if (v < old)
        {
          coarsePoints->GetPoint(v, x);
        }
        else if (v >= static_cast<vtkIdType>(edgeOf.size()) || edgeOf[v][0] < 0)
        {
          finer->GetPoint(v, x); // a point no triangle uses
        }
        else
        {
          double a[3], b[3];
          coarsePoints->GetPoint(edgeOf[v][0], a);
          coarsePoints->GetPoint(edgeOf[v][1], b);
          for (int k = 0; k < 3; ++k)
          {
            x[k] = 0.5 * (a[k] + b[k]);
          }
        }
        exact->SetPoint(v, x);
      }
      finer->SetPoints(exact);
    }
    current = finer;
    parent.swap(child);
    this->UpdateProgress(0.9 * (level + 1) / std::max(1, this->NumberOfSubdivisions));
  }
  surfaceOut->ShallowCopy(current);

  // The curves: same cells and data, surface points on the finer surface.
  curvesOut->CopyStructure(curves);
  curvesOut->GetCellData()->PassData(curves->GetCellData());
  curvesOut->GetPointData()->DeepCopy(curves->GetPointData());
  curvesOut->GetFieldData()->PassData(curves->GetFieldData());
  vtkNew<vtkIdTypeArray> newTriangleIds;
  newTriangleIds->SetName(boolsurf::names::TriangleId);
  newTriangleIds->SetNumberOfTuples(numberOfPoints);
  vtkNew<vtkDoubleArray> newBarycentric;
  newBarycentric->SetName(boolsurf::names::Barycentric);
  newBarycentric->SetNumberOfComponents(2);
  newBarycentric->SetNumberOfTuples(numberOfPoints);
  vtkNew<vtkPoints> positions;
  positions->SetDataTypeToDouble();
  positions->SetNumberOfPoints(numberOfPoints);
  vtkPoints* meshPoints = current->GetPoints();
  for (vtkIdType p = 0; p < numberOfPoints; ++p)
  {
    const boolsurf::SurfacePoint& s = points[p];
    const boolsurf::Triangle& t = parent[s.Triangle];
    double a[3], b[3], c[3], x[3];
    meshPoints->GetPoint(t[0], a);
    meshPoints->GetPoint(t[1], b);
    meshPoints->GetPoint(t[2], c);
    for (int k = 0; k < 3; ++k)
    {
      x[k] = (1 - s.U - s.V) * a[k] + s.U * b[k] + s.V * c[k];
    }
    positions->SetPoint(p, x);
    newTriangleIds->SetValue(p, s.Triangle);
    newBarycentric->SetTuple2(p, s.U, s.V);
  }
  curvesOut->SetPoints(positions);
  curvesOut->GetPointData()->RemoveArray(boolsurf::names::TriangleId);
  curvesOut->GetPointData()->RemoveArray(boolsurf::names::Barycentric);
  curvesOut->GetPointData()->AddArray(newTriangleIds);
  curvesOut->GetPointData()->AddArray(newBarycentric);
  return true;
}

//------------------------------------------------------------------------------
void vtkBoolSurfSubdivide::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scheme: " << (this->Scheme == LOOP ? "Loop" : "Linear") << "\n";
  os << indent << "NumberOfSubdivisions: " << this->NumberOfSubdivisions << "\n";
}
