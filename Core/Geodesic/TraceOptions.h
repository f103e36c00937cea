// How control curves are traced into polylines on the surface: the settings every stage that
// traces curves shares (Trace Surface Curves, the one-step filter, Surface Curves' display,
// winding numbers, offset, resolution).
#ifndef boolsurf_TraceOptions_h
#define boolsurf_TraceOptions_h

#include "Geodesic/GeodesicPathOptions.h" // for GeodesicMethod

namespace boolsurf
{

struct TraceOptions
{
  int Resolution = 4;
  double ProjectionTolerance = 0.01; ///< fraction of the surface's bounding-box diagonal
  /// How each geodesic leg is computed (see GeodesicMethod in Geodesic/GeodesicPathOptions.h).
  GeodesicMethod Method = GeodesicMethod::Bounded;
  /// Curves traced at once (0: all cores; see CurveTracer::TraceCurves).
  int Threads = 0;
  /// Curves still being drawn (cell data Complete 0): traced as far as they are valid (for
  /// display) instead of left out.
  bool TraceValidPartOfIncompleteCurves = false;
};

} // namespace boolsurf

#endif
