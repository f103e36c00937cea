// What the labeling reads from an arrangement: the cell graph with shapes as dense indices,
// crossings grouped by place, the surface component of each cell and a zero cell per component
// (BoolSurf §3.4, §4.4). Shared by the VTK filters (which also write it as field data) and
// the one-step filter, which labels straight from the Core arrangement.
#ifndef boolsurf_ArrangementLabelingInput_h
#define boolsurf_ArrangementLabelingInput_h

#include "Arrangement/Arrangement.h"
#include "Labeling/BoundaryPlugs.h"
#include "Labeling/CellLabeling.h"
#include "Mesh/MeshTopology.h"

#include <vector>

namespace boolsurf
{

/// The distinct ShapeIds of `curves`, sorted: shape index i is ShapeIds[i]. Labels and
/// selections work on indices, so memory never depends on how large the ids are.
std::vector<int> DistinctShapeIds(const std::vector<TracedCurve>& curves);

/// Index of `shapeId` in the sorted `shapeIds`, or -1.
int ShapeIndexOf(const std::vector<int>& shapeIds, int shapeId);

/// Where a patch runs: patches on the same refined sub-edges (overlapping curves, maybe
/// reversed, or a curve retracing itself) share a Location and are crossed together.
struct PatchPlace
{
  int Location = -1;
  /// +1 when the patch runs along the place's own orientation, -1 against it: the sign of its
  /// label change when both sides are one cell (a retraced piece: +1 - 1 = 0).
  int Direction = 1;
};

/// The place of every patch.
std::vector<PatchPlace> PatchPlaces(const std::vector<ArrangementPatch>& patches);

/// Surface component of each cell (that of its lowest triangle).
std::vector<int> CellComponents(const TriangleMesh& mesh,
  const MeshTopology& topology,
  const Arrangement& arrangement);

/// The labeling input of an arrangement of `curves` (the curves it was computed from):
/// shapes as indices into DistinctShapeIds(curves), arcs located by PatchPlaces, cell
/// components, and the boundary loops' plugs (BoundaryPlugs.h) with their arcs and links; the
/// zero node of a component with a boundary is the plug of its longest loop.
LabelingInput MakeLabelingInput(const TriangleMesh& mesh,
  const MeshTopology& topology,
  const std::vector<TracedCurve>& curves,
  const Arrangement& arrangement);

/// Adds the shapes of `shapeIds` that `input` does not have yet, as shapes without curves
/// (outside every cell): shapes whose curves are all still being drawn, which operations may
/// name before they have a region. Arcs keep their shapes (indices renumbered).
void AddShapesWithoutCurves(LabelingInput& input, const std::vector<int>& shapeIds);

/// The cell of `arrangement` holding the point (u, v) of mesh triangle t (barycentric weights
/// of corners 1 and 2), or -1 when t is not part of the refined surface.
int CellAtSurfacePoint(const TriangleMesh& mesh,
  const Arrangement& arrangement,
  int t,
  double u,
  double v);

} // namespace boolsurf

#endif
