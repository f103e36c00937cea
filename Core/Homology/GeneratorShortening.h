// Generators drawn as locally shortest loops (paper Fig. 16 right): each tree-cotree loop is
// replaced by a geodesic polygon through a few of its points, then the polygon is re-traced
// through the midpoints of its own sides a few times (each pass shortens it and moves the
// corners along it). The result is kept only when its homology class is still the generator's
// own (a unit vector); otherwise the generator has no shortened loop.
#ifndef boolsurf_GeneratorShortening_h
#define boolsurf_GeneratorShortening_h

#include "Geodesic/CurveTracer.h"
#include "Homology/HomologyBasis.h"

namespace boolsurf
{

/// Shortened loop of generator `g` into `out` (closed). False when tracing fails or the
/// shortened loop left the generator's class.
bool ShortenGenerator(const TriangleMesh& mesh,
  const HomologyBasis& basis,
  int g,
  CurveTracer& tracer,
  TracedCurve& out,
  int passes = 6);

/// Length of a traced curve (closed: with the closing side).
double TracedLength(const TriangleMesh& mesh, const TracedCurve& curve);

} // namespace boolsurf

#endif
