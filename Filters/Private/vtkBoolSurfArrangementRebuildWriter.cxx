#include "vtkBoolSurfArrangementRebuildWriter.h"

#include "vtkBoolSurfArrayNames.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkTypeInt64Array.h>

#include <algorithm>

namespace boolsurf
{
namespace
{

template <class A, class T>
void AddTuples(vtkFieldData* fd, const char* name, const std::vector<T>& values, int comps)
{
  // VTK 9.2's XML writer cannot store an empty numeric array: readers take a missing one as
  // empty.
  if (values.empty())
  {
    return;
  }
  vtkNew<A> a;
  a->SetName(name);
  a->SetNumberOfComponents(comps);
  a->SetNumberOfTuples(static_cast<vtkIdType>(values.size()) / comps);
  std::copy(values.begin(), values.end(), a->GetPointer(0));
  fd->AddArray(a);
}

} // namespace

//------------------------------------------------------------------------------
void WriteRebuildFields(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<TracedCurve>& curves,
  const std::vector<CurveSource>& sources,
  GeodesicMethod method,
  vtkFieldData* fd)
{
  AddTuples<vtkIntArray>(fd,
    names::ArrangedMeshSize,
    std::vector<int>{ mesh.GetNumberOfVertices(), mesh.GetNumberOfTriangles() },
    2);
  // The triangles whose corners the refined surface does not keep: those the curves cross
  // (their first piece takes their index) and the unusable ones (left out).
  std::vector<int> corners;
  const auto record = [&](int t)
  {
    const Triangle& c = mesh.GetTriangle(t);
    corners.insert(corners.end(), { t, c[0], c[1], c[2] });
  };
  for (int s = 0; s < arr.NumberOfRefinedSourceTriangles; ++s)
  {
    record(arr.RefinedSources[s]);
  }
  if (arr.NumberOfHoles > 0)
  {
    for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
    {
      if (!mesh.IsUsable(t))
      {
        record(t);
      }
    }
  }
  AddTuples<vtkIntArray>(fd, names::ArrangedMeshCorners, corners, 4);

  std::vector<int> offsets{ 0 }, info, ids;
  std::vector<double> weights;
  for (const TracedCurve& curve : curves)
  {
    info.insert(info.end(), { curve.ShapeId, curve.CurveId, curve.Closed ? 1 : 0 });
    for (const CanonicalPoint& p : curve.Points)
    {
      ids.insert(ids.end(), { static_cast<int>(p.Location), p.Id });
      weights.insert(weights.end(), { p.U, p.V, p.T });
    }
    offsets.push_back(static_cast<int>(ids.size() / 2));
  }
  AddTuples<vtkIntArray>(fd, names::ArrangedCurveOffsets, offsets, 1);
  AddTuples<vtkIntArray>(fd, names::ArrangedCurveInfo, info, 3);
  AddTuples<vtkIntArray>(fd, names::ArrangedCurvePointIds, ids, 2);
  AddTuples<vtkDoubleArray>(fd, names::ArrangedCurvePointWeights, weights, 3);

  std::vector<long long> sourceInfo;
  std::vector<int> controlOffsets{ 0 }, parameterOffsets{ 0 };
  std::vector<double> controls, parameters;
  for (const CurveSource& s : sources)
  {
    sourceInfo.insert(sourceInfo.end(),
      { static_cast<long long>(s.Type),
        s.Closed ? 1LL : 0LL,
        s.ShapeId,
        s.CurveId,
        s.InputCurveId });
    for (const SurfacePoint& p : s.Points)
    {
      controls.insert(controls.end(), { static_cast<double>(p.Triangle), p.U, p.V });
    }
    controlOffsets.push_back(static_cast<int>(controls.size() / 3));
    parameters.insert(parameters.end(), s.Parameter.begin(), s.Parameter.end());
    parameterOffsets.push_back(static_cast<int>(parameters.size()));
  }
  if (!sources.empty())
  {
    AddTuples<vtkTypeInt64Array>(fd, names::ArrangedSourceInfo, sourceInfo, 5);
    AddTuples<vtkIntArray>(fd, names::ArrangedSourceControlOffsets, controlOffsets, 1);
    AddTuples<vtkDoubleArray>(fd, names::ArrangedSourceControls, controls, 3);
    AddTuples<vtkIntArray>(fd, names::ArrangedSourceParameterOffsets, parameterOffsets, 1);
    AddTuples<vtkDoubleArray>(fd, names::ArrangedSourceParameters, parameters, 1);
  }
  AddTuples<vtkIntArray>(
    fd, names::ArrangedTraceMethod, std::vector<int>{ static_cast<int>(method) }, 1);
}

} // namespace boolsurf
