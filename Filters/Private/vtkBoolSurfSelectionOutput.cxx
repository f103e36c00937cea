#include "vtkBoolSurfSelectionOutput.h"

#include "Geodesic/GeodesicPath.h"
#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfControlOutput.h"
#include "vtkBoolSurfRegionOutput.h"
#include "vtkBoolSurfStageHandoff.h"

#include <vtkPolyData.h>

#include <chrono>

namespace boolsurf
{
namespace
{
using Clock = std::chrono::steady_clock;
double Milliseconds(Clock::time_point from, Clock::time_point to)
{
  return std::chrono::duration<double, std::milli>(to - from).count();
}
} // namespace

//------------------------------------------------------------------------------
bool WriteSelectedCells(const vtkSurfaceInput& surface,
  const Arrangement& arr,
  const std::vector<CurveSource>& sources,
  const std::vector<char>& selected,
  GeodesicPathSolver* solver,
  SelectionOutputBuffers& buffers,
  vtkPolyData* region,
  vtkPolyData* boundary,
  vtkPolyData* controls,
  vtkPolyData* clipped,
  std::string& error,
  SelectionOutputTimes* times,
  const std::vector<GeodesicPathSolver*>& cutSolvers)
{
  const Clock::time_point start = Clock::now();
  RegionExtractor::SelectedTriangles(selected, arr, buffers.RegionTriangles, buffers.Threads);
  buffers.Extractor.Extract(
    buffers.RegionTriangles,
    arr.GetNumberOfPoints(),
    [&](int t) { return arr.GetTriangle(*surface.Mesh, t); },
    buffers.Region,
    buffers.Threads);
  const Clock::time_point extracted = Clock::now();
  WriteRegion(surface, arr, buffers.Region, region, buffers.Threads);
  const Clock::time_point regionWritten = Clock::now();
  const std::vector<BoundaryPolyline> loops = ExtractRegionBoundary(arr.Patches, selected);
  WriteBoundary(
    loops,
    [&](int p, double x[3])
    {
      const Vec3 position = arr.GetPosition(*surface.Mesh, p);
      x[0] = position.x;
      x[1] = position.y;
      x[2] = position.z;
    },
    [&](int p) { return arr.GetPointSurface(*surface.Mesh, p); },
    true,
    boundary);
  const Clock::time_point written = Clock::now();
  Clock::time_point controlsWritten = written;
  if (solver)
  {
    BezierPieces bezier(arr, sources); // each Bezier segment cut once for both outputs
    bool ok = true;
    std::string cutError;
    if (cutSolvers.size() > 1)
    {
      // The curves both outputs need: those along the boundary and the open ones with a patch
      // on a selected cell (a superset only costs cuts not used).
      std::vector<char> needed(sources.size(), 0);
      const auto need = [&](int curve)
      {
        if (curve >= 0 && curve < static_cast<int>(needed.size()))
        {
          needed[curve] = 1;
        }
      };
      for (const BoundaryPolyline& loop : loops)
      {
        for (int p : loop.Patches)
        {
          need(arr.Patches[p].Curve);
        }
      }
      for (const ArrangementPatch& p : arr.Patches)
      {
        const bool open =
          p.Curve >= 0 && p.Curve < static_cast<int>(sources.size()) && !sources[p.Curve].Closed;
        if (open &&
          ((p.LeftCell >= 0 && selected[p.LeftCell]) ||
            (p.RightCell >= 0 && selected[p.RightCell])))
        {
          need(p.Curve);
        }
      }
      std::vector<int> curves;
      for (std::size_t c = 0; c < needed.size(); ++c)
      {
        if (needed[c])
        {
          curves.push_back(static_cast<int>(c));
        }
      }
      ok = bezier.CutCurves(curves, cutSolvers, cutError);
    }
    if (ok)
    {
      ok =
        BoundaryControlCurves(*solver, arr, sources, loops, buffers.SubCurves, cutError, &bezier);
    }
    if (ok)
    {
      WriteControlSubCurves(buffers.SubCurves, boolsurf::names::BoundaryLoop, true, controls);
      controlsWritten = Clock::now();
      ok =
        ClippedControlCurves(*solver, arr, sources, selected, buffers.SubCurves, cutError, &bezier);
    }
    if (!ok)
    {
      error = "Control points of the result: " + cutError;
      region->Initialize();
      boundary->Initialize();
      controls->Initialize();
      return false;
    }
    WriteControlSubCurves(buffers.SubCurves, boolsurf::names::ClippedPiece, false, clipped);
  }
  if (times)
  {
    times->Extraction = Milliseconds(start, extracted);
    times->Output = Milliseconds(extracted, written);
    const Clock::time_point end = Clock::now();
    times->ControlCurves = Milliseconds(written, end);
    times->Ports[0] = Milliseconds(start, regionWritten);
    times->Ports[1] = Milliseconds(regionWritten, written);
    times->Ports[2] = Milliseconds(written, controlsWritten);
    times->Ports[3] = Milliseconds(controlsWritten, end);
  }
  return true;
}

//------------------------------------------------------------------------------
bool WriteHandedOverSelection(const ArrangementResult& arranged,
  const std::vector<char>& selected,
  ResultPathSolver& solver,
  SelectionOutputBuffers& buffers,
  vtkPolyData* region,
  vtkPolyData* boundary,
  vtkPolyData* controls,
  vtkPolyData* clipped,
  std::string& error,
  std::string& note)
{
  const bool withControls = !arranged.Sources.empty();
  note = withControls ? "" : NoControlPointsNote;
  return WriteSelectedCells(arranged.Surface,
    arranged.Arrangement,
    arranged.Sources,
    selected,
    withControls ? &solver.Get(arranged.Surface.Mesh, arranged.Method) : nullptr,
    buffers,
    region,
    boundary,
    controls,
    clipped,
    error);
}

} // namespace boolsurf
