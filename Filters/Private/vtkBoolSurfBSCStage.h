// The Boundary-Sampled Curves stage on VTK data, shared by vtkBoolSurfBSC and the one-step
// vtkBoolSurf filter (a private header of the module): reading the samples, selecting on a
// refined surface in VTK form, and the field data that says what became of each sample.
#ifndef vtkBoolSurfBSCStage_h
#define vtkBoolSurfBSCStage_h

#include "Mesh/TriangleMesh.h"
#include "Selection/BoundarySamples.h"
#include "vtkBoolSurfArrangementOutput.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace boolsurf
{

/// The samples' points and point data `Direction` (3 components). With `mesh`, point data
/// `TriangleId`/`Barycentric`, when present, give exact surface points instead of the
/// coordinates. False with a message naming the missing array or the bad sample.
bool ReadSampleQueries(vtkPolyData* samples,
  const TriangleMesh* mesh,
  std::vector<SampleQuery>& queries,
  std::string& error);

/// Field data on `output`: `SamplePatch` (patch each sample snapped to), `SampleDistance`,
/// `SampleOnBoundary` (1 kept on the boundary, 0 dropped), `DroppedSamples` (ids),
/// `BoundaryLength`, `BSCCuts` (minimum cuts computed) and `Selection` = "BSC".
void AddSampleFields(const std::vector<PatchSnap>& snaps,
  const BscResult& result,
  vtkPolyData* output);

} // namespace boolsurf

#endif
