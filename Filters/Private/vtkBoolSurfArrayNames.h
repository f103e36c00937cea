// The names of the arrays the BoolSurf filters read and write (a private header of the
// module). They are part of the public API (README, "Data contract"): users' scripts, files and
// other filters find the data by these names, so every filter spells them from here.
#ifndef vtkBoolSurfArrayNames_h
#define vtkBoolSurfArrayNames_h

namespace boolsurf
{
namespace names
{
// Surface points (point data of curves, refined surfaces, boundaries).
constexpr const char* TriangleId = "TriangleId";   ///< vtkIdType, 1 component
constexpr const char* Barycentric = "Barycentric"; ///< double, 2 components (corners 1 and 2)

// Curves (cell data), and where traced points come from (point data).
constexpr const char* ShapeId = "ShapeId";
constexpr const char* CurveId = "CurveId";
constexpr const char* CurveType = "CurveType"; ///< 0 geodesic polygon, 1 cubic Bezier
constexpr const char* Closed = "Closed";
constexpr const char* Length = "Length";
constexpr const char* CurveParameter = "CurveParameter";
constexpr const char* ControlSegment = "ControlSegment";
constexpr const char* ControlPointId = "ControlPointId";
/// Control curves (cell data): 0 for a curve still being drawn (too few points for its type),
/// which filters leave out without a message; absent means every curve is complete.
constexpr const char* Complete = "Complete";
/// Surface Curves (field data): one line per curve still being drawn, saying what it needs.
constexpr const char* IncompleteCurves = "IncompleteCurves";
/// Surface Curves (field data, both ports, value 1): the curves are a drawing, which may be
/// empty or hold only curves being drawn while the user starts it (no region, no message).
constexpr const char* Drawing = "Drawing";
/// Control curves (cell data, string, optional): the name of each curve's shape, carried by
/// Winding Numbers into component names and its completed curves; absent: shapes are unnamed.
constexpr const char* ShapeName = "ShapeName";

// The arrangement: refined surface cell data, patches, field data.
constexpr const char* ArrangementCell = "ArrangementCell";
constexpr const char* SourceTriangle = "SourceTriangle";
/// Region outputs: 1 on every triangle (unsigned char), the active scalars, so that a new
/// display shows the region in one color (the plugin's categorical color map for it).
constexpr const char* Region = "Region";
constexpr const char* NumberOfCells = "NumberOfCells";
constexpr const char* NumberOfShapes = "NumberOfShapes";
/// The plugs of the surface's boundary loops (Core/Labeling/BoundaryPlugs.h): the cell graph's
/// nodes past NumberOfCells, and the (cell, plug) pairs that are one region.
constexpr const char* NumberOfBoundaryPlugs = "NumberOfBoundaryPlugs";
constexpr const char* BoundaryPlugLinks = "BoundaryPlugLinks";
constexpr const char* ShapeIds = "ShapeIds";
constexpr const char* PatchId = "PatchId";
constexpr const char* LeftCell = "LeftCell";
constexpr const char* RightCell = "RightCell";
constexpr const char* StageTimes = "StageTimes";
/// What a refined surface read from a file needs to be arranged again (field data; see
/// vtkBoolSurfArrangementRebuild.h): the mesh's size (components Vertices, Triangles), the
/// corners of the mesh triangles the refined surface does not keep (components Triangle,
/// Corner0..2), the traced curves (offsets, per curve ShapeId/CurveId/Closed, per point the
/// canonical location Location/Id and weights U/V/T), their control points when Trace Surface
/// Curves recorded them (per curve Type/Closed/ShapeId/CurveId/InputCurveId, offsets into the
/// control points TriangleId/U/V and into the per traced point parameters) and the geodesic
/// method the curves were traced with.
constexpr const char* ArrangedMeshSize = "ArrangedMeshSize";
constexpr const char* ArrangedMeshCorners = "ArrangedMeshCorners";
constexpr const char* ArrangedCurveOffsets = "ArrangedCurveOffsets";
constexpr const char* ArrangedCurveInfo = "ArrangedCurveInfo";
constexpr const char* ArrangedCurvePointIds = "ArrangedCurvePointIds";
constexpr const char* ArrangedCurvePointWeights = "ArrangedCurvePointWeights";
constexpr const char* ArrangedSourceInfo = "ArrangedSourceInfo";
constexpr const char* ArrangedSourceControlOffsets = "ArrangedSourceControlOffsets";
constexpr const char* ArrangedSourceControls = "ArrangedSourceControls";
constexpr const char* ArrangedSourceParameterOffsets = "ArrangedSourceParameterOffsets";
constexpr const char* ArrangedSourceParameters = "ArrangedSourceParameters";
constexpr const char* ArrangedTraceMethod = "ArrangedTraceMethod";

// Labels and selections (field data), BSC samples (point data).
constexpr const char* CellLabels = "CellLabels";
constexpr const char* ShapeConsistent = "ShapeConsistent";
constexpr const char* Expression = "Expression";
constexpr const char* Direction = "Direction";

// Winding numbers (Winding Numbers, and BoolSurf's CloseBrokenShapes).
/// Point and cell data (double, one component per computed shape, named by its ShapeName or
/// "Shape <id>"): w at each refined point, and at each refined triangle's centroid.
constexpr const char* WindingNumber = "WindingNumber";
/// Field data (double, arrangement cells x computed shapes): the area-weighted mean of w over
/// each arrangement cell.
constexpr const char* CellWindingNumber = "CellWindingNumber";
/// Field data (int): the computed shapes' ids, in the order of the components above.
constexpr const char* WindingShapeIds = "WindingShapeIds";
/// Traced curves (cell data, double): how far each curve is from bounding a region (0 bounds,
/// 1 bounds nothing; WindingCurveReport::Residual); -1 for a curve of a shape not computed.
constexpr const char* WindingResidual = "WindingResidual";
/// Traced curves (cell data, int): 1 a curve that bounds (takes part in w), 0 one the homology
/// correction dropped (it bounds nothing), -1 a curve of a shape not computed.
constexpr const char* BoundsRegion = "BoundsRegion";
/// Field data (int, 2 components ShapeId, CurveId): the curves that bound nothing; absent when
/// every curve bounds.
constexpr const char* NonBoundingCurves = "NonBoundingCurves";
/// Field data (double, 9 components): milliseconds of the Winding Numbers filter's stages
/// (Trace, Arrangement, Factorization, Lift, Solve, Homology, LevelSet, Outputs, Total).
constexpr const char* WindingTimes = "WindingTimes";
/// Field data (string): one line per curve replaced by a completed curve, with its residual.
constexpr const char* WindingNotes = "WindingNotes";
} // namespace names
} // namespace boolsurf

#endif
