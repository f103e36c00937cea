// The names of the arrays the BoolSurf filters read and write, and of the curve editor's own
// arrays. They are part of the public API (README, "Data contract"): users' scripts, files, the
// curve editor (Plugin/) and other filters find the data by these names, so every one of them
// spells them from here (the `lint.ArrayNameLiterals` test finds literals elsewhere).
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
/// vtkBoolSurfArrangementRebuildWriter.h): the mesh's size (components Vertices, Triangles), the
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

// Trace Surface Curves (field data).
/// string, one line per problem when tracing failed (the output is then empty).
constexpr const char* TraceErrors = "TraceErrors";
/// The Bounded geodesic method's per-surface graph (see AddSiteGraphField).
constexpr const char* GeodesicSiteGraph = "GeodesicSiteGraph";
/// The control points of the traced curves: ControlOffsets[c]..ControlOffsets[c + 1] index
/// curve c's points, each a triangle and two barycentric coordinates.
constexpr const char* ControlOffsets = "ControlOffsets";
constexpr const char* ControlTriangleId = "ControlTriangleId";
constexpr const char* ControlBarycentric = "ControlBarycentric";
/// Under MPI (field data, 64-bit integers): the traced curves as the pieces of a surface split
/// across ranks need them (Core/Distributed/PieceWire.h, message 0: points on the surface's
/// point and cell GlobalIds), for Surface Arrangement on each rank's piece.
constexpr const char* PieceCurvesMessage = "PieceCurvesMessage";
/// Trace Surface Curves' output when it traced on each rank's piece (field data, doubles, one
/// tuple on every rank, components named): what the rank sent and received (bytes) and did:
/// DirectorySent, DirectoryReceived, FetchSent, FetchReceived, TracesSent, TracesReceived,
/// Rounds, OwnRounds, TracedCurves, FetchedTriangles, HeldTriangles, RingedTriangles,
/// ReusedPiece (1 when an edit kept the ringed piece, directory and tracer).
constexpr const char* PieceTracingTraffic = "PieceTracingTraffic";
/// Surface Curves' port 0 when it ran on each rank's piece (field data, doubles, one tuple on
/// every rank, components named): Sent, Received (bytes of the queries and answers that placed
/// the control points), OwnedTriangles (the triangles the rank searched: its own), Points.
constexpr const char* PieceSnapping = "PieceSnapping";
/// Surface Arrangement's output on each rank's piece (field data, int: the number of
/// ranks): the output is one rank's part of the refined surface, not the whole.
constexpr const char* ArrangementOnPieces = "ArrangementOnPieces";
/// Surface Arrangement's output on each rank's piece (field data, doubles, one tuple,
/// components named): what the update kept from the last one. KeptPiece (1 when the piece, its
/// neighbours, its ring and its mesh were kept: the surface unchanged on every rank),
/// KeptArrangement (1 when the piece's arrangement was computed again into one on the same
/// mesh: Core's edit path), RefinedTriangles (the piece's mesh triangles curves cross, ghosts
/// included), OwnedTriangles, RingedTriangles.
constexpr const char* PieceArrangementReuse = "PieceArrangementReuse";
/// The stages run on pieces (field data, double, one tuple): the bytes this rank sent and
/// received in this update, two components per message named <message>Sent and
/// <message>Received (vtkBoolSurfPieceCosts.h); StageTimes holds the rank's wall times.
constexpr const char* PieceBytes = "PieceBytes";
/// Surface Curves (point data of the traced curves): the surface's normal at each point.
constexpr const char* SurfaceNormal = "SurfaceNormal";

// Results given back as control points (BoolSurf's ports 2 and 3, Surface Boolean, Offset):
// cell data of the sub-curves, and the group names of their kinds.
constexpr const char* SourceCurveId = "SourceCurveId";
constexpr const char* SourceShapeId = "SourceShapeId";
constexpr const char* Reversed = "Reversed";
constexpr const char* ParameterRange = "ParameterRange";
constexpr const char* BoundaryLoop = "BoundaryLoop";
constexpr const char* ClippedPiece = "ClippedPiece";
constexpr const char* OffsetCurve = "OffsetCurve";
/// The arrangement's patches as control points (field data).
constexpr const char* PatchControlOffsets = "PatchControlOffsets";
constexpr const char* PatchControlInfo = "PatchControlInfo";
constexpr const char* PatchControlTriangleId = "PatchControlTriangleId";
constexpr const char* PatchControlBarycentric = "PatchControlBarycentric";
constexpr const char* PatchControlPosition = "PatchControlPosition";
constexpr const char* PatchParameterRange = "PatchParameterRange";

// The arrangement's cell graph and patches (field data of Surface Arrangement's output, read
// back by the labeling and the Boolean).
constexpr const char* CellGraphArcs = "CellGraphArcs";
constexpr const char* CellGraphShape = "CellGraphShape";
constexpr const char* CellGraphPatch = "CellGraphPatch";
constexpr const char* CellGraphLocation = "CellGraphLocation";
constexpr const char* CellGraphDirection = "CellGraphDirection";
constexpr const char* CellComponent = "CellComponent";
constexpr const char* ZeroCellCandidates = "ZeroCellCandidates";
constexpr const char* PatchOffsets = "PatchOffsets";
constexpr const char* PatchPoints = "PatchPoints";
constexpr const char* PatchLeftCell = "PatchLeftCell";
constexpr const char* PatchRightCell = "PatchRightCell";
constexpr const char* PatchShape = "PatchShape";
constexpr const char* PatchCurve = "PatchCurve";
constexpr const char* PatchClosed = "PatchClosed";

// Homology (field data of the arrangement; loops of generators as <prefix><suffix> arrays).
constexpr const char* NumberOfHomologyGenerators = "NumberOfHomologyGenerators";
constexpr const char* CurveHomology = "CurveHomology";
constexpr const char* CurveHomologyCurveId = "CurveHomologyCurveId";
constexpr const char* CurveHomologyShapeId = "CurveHomologyShapeId";
constexpr const char* HomologyExcess = "HomologyExcess";
constexpr const char* GeneratorId = "GeneratorId";
constexpr const char* Shortened = "Shortened";
constexpr const char* HomologyGenerator = "HomologyGenerator";           ///< a prefix
constexpr const char* HomologyShortGenerator = "HomologyShortGenerator"; ///< a prefix
constexpr const char* LoopOffsets = "Offsets";                           ///< a suffix
constexpr const char* LoopId = "Id";                                     ///< a suffix
constexpr const char* LoopPoints = "Points";                             ///< a suffix
/// HomologyGenerator + LoopPoints: the array whose presence says the homology was written.
constexpr const char* HomologyGeneratorPoints = "HomologyGeneratorPoints";

// Labels (Label Arrangement Cells: cell data).
constexpr const char* Labels = "Labels";
constexpr const char* ShapeLabel = "ShapeLabel";

// Selections (field data) and BSC's samples.
constexpr const char* Selection = "Selection";
constexpr const char* SamplePatch = "SamplePatch";
constexpr const char* SampleOnBoundary = "SampleOnBoundary";
constexpr const char* DroppedSamples = "DroppedSamples";
constexpr const char* SampleDistance = "SampleDistance";
constexpr const char* BoundaryLength = "BoundaryLength";
constexpr const char* BSCCuts = "BSCCuts";

// Resolve Inconsistent Shapes (cell data of the curves; field data).
constexpr const char* ResolutionAction = "Resolution"; ///< 0 kept, 1 added, 2 duplicated, 3 flipped
constexpr const char* ResolutionSource = "ResolutionSource";
constexpr const char* ResolutionReason = "ResolutionReason";
constexpr const char* RemovedCurves = "RemovedCurves";
constexpr const char* RemovedCurveReasons = "RemovedCurveReasons";
constexpr const char* TreatedShapes = "TreatedShapes";
constexpr const char* ResolutionNotes = "ResolutionNotes";

// Offset Shapes (field data).
constexpr const char* OffsetStatistics = "OffsetStatistics";
constexpr const char* OffsetDistance = "OffsetDistance";
constexpr const char* OffsetShapeId = "OffsetShapeId";
constexpr const char* OffsetExpression = "OffsetExpression";

// Check Surface (cell, point and field data).
constexpr const char* ComponentId = "ComponentId";
constexpr const char* BoundaryLoopId = "BoundaryLoopId";
constexpr const char* Components = "Components";
constexpr const char* Genus = "Genus";
constexpr const char* BoundaryLoops = "BoundaryLoops";
constexpr const char* EulerCharacteristic = "EulerCharacteristic";
constexpr const char* IsManifold = "IsManifold";
constexpr const char* BoundaryLoopLength = "BoundaryLoopLength";
constexpr const char* Problems = "Problems";

// Map SVG Onto Surface (field data).
constexpr const char* SuggestedFillRule = "SuggestedFillRule";
constexpr const char* ShapeEvenOdd = "ShapeEvenOdd";
constexpr const char* SvgWarnings = "SvgWarnings";

// Scene files (Scene Reader writes them, Scene Writer reads them back): the screen-space
// surface's normals (point data) and the scene's operations (field data).
constexpr const char* Normals = "Normals";
constexpr const char* OperationA = "OperationA";
constexpr const char* OperationB = "OperationB";
constexpr const char* OperationType = "OperationType";
/// Field data (string): the scene file read, the mesh file it names, and its model name.
constexpr const char* SceneFileName = "SceneFileName";
constexpr const char* MeshFileName = "MeshFileName";
constexpr const char* SceneModel = "SceneModel";

// The curve editor's own markers (point data of its glyph source, Plugin/).
constexpr const char* EditorMarkerRadius = "Radius";
constexpr const char* EditorMarkerDirection = "Direction";
} // namespace names
} // namespace boolsurf

#endif
