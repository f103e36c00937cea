// The selected cells of a Core arrangement written as outputs (a private header of the module):
// what the one-step vtkBoolSurf writes, and what Surface Boolean and Boundary Sampled Curves
// write when the arrangement came to them in Core form (vtkBoolSurfStageHandoff.h), so a chain
// of stage filters gives the one-step answer bit for bit. The cost is the size of the region.
#ifndef vtkBoolSurfSelectionOutput_h
#define vtkBoolSurfSelectionOutput_h

#include "Arrangement/Arrangement.h"
#include "Selection/BoundaryControlPoints.h"
#include "Selection/RegionExtraction.h"
#include "vtkBoolSurfSurfaceAdapter.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace boolsurf
{

class GeodesicPathSolver;
class ResultPathSolver;
struct ArrangementResult;

/// Buffers kept between updates, so an edit reuses them.
struct SelectionOutputBuffers
{
  std::vector<int> RegionTriangles;
  RegionExtractor Extractor;
  RegionMesh Region;
  std::vector<ControlSubCurve> SubCurves;
  /// At most this many threads list, renumber and write a large region (0: all).
  int Threads = 0;
};

/// Milliseconds spent in WriteSelectedCells.
struct SelectionOutputTimes
{
  double Extraction = 0;    ///< finding the region's triangles and points
  double Output = 0;        ///< region and boundary polydata
  double ControlCurves = 0; ///< ports 2 and 3
  /// The same time per output port (what a user pays for each port ParaView shows): the
  /// region's triangles found and written (port 0), its boundary loops (1), the boundary's
  /// control curves with the Bezier cuts both control outputs share (2), the clipped open
  /// curves (3).
  double Ports[4] = { 0, 0, 0, 0 };
};

/// Writes the cells with selected[cell] != 0: `region` (the refined triangles with
/// ArrangementCell, SourceTriangle, TriangleId/Barycentric and the surface's own arrays),
/// `boundary` (oriented loops, region on the left) and, when `solver` is given, `controls` and
/// `clipped`: the boundary and the clipped open curves as control points of the input curves
/// `sources` (ports 2 and 3 of vtkBoolSurf). False with a message when those control points
/// cannot be recovered; the outputs are then empty. `cutSolvers` (optional: one per thread,
/// see BezierPieces::CutCurves) cut the output's Bezier segments in parallel.
bool WriteSelectedCells(const vtkSurfaceInput& surface,
  const Arrangement& arrangement,
  const std::vector<CurveSource>& sources,
  const std::vector<char>& selected,
  GeodesicPathSolver* solver,
  SelectionOutputBuffers& buffers,
  vtkPolyData* region,
  vtkPolyData* boundary,
  vtkPolyData* controls,
  vtkPolyData* clipped,
  std::string& error,
  SelectionOutputTimes* times = nullptr,
  const std::vector<GeodesicPathSolver*>& cutSolvers = {});

/// WriteSelectedCells on an arrangement handed over by Surface Arrangement (the stage filters'
/// path to the one-step outputs): the control-point outputs are computed with `solver` when the
/// arrangement carries its curves' control points; otherwise they stay empty and `note` says
/// why (empty when they are written).
bool WriteHandedOverSelection(const ArrangementResult& arranged,
  const std::vector<char>& selected,
  ResultPathSolver& solver,
  SelectionOutputBuffers& buffers,
  vtkPolyData* region,
  vtkPolyData* boundary,
  vtkPolyData* controls,
  vtkPolyData* clipped,
  std::string& error,
  std::string& note);

} // namespace boolsurf

#endif
