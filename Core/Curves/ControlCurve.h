// A curve as the user draws it: control points on the surface joined by geodesics (a polygon)
// or by a cubic geodesic Bezier spline, with the shape it bounds. Every stage that makes or
// reads curves (the editor's source, SVG drawings, scene files, tracing, offset, resolution)
// speaks of them in this one form; stages that know more of a curve hold it beside or around
// this type (CurveSource adds the traced points' parameters, MappedSvgCurve the fill rule).
#ifndef boolsurf_ControlCurve_h
#define boolsurf_ControlCurve_h

#include "Mesh/SurfacePoint.h"

#include <string>
#include <vector>

namespace boolsurf
{

/// Values of the `CurveType` cell array.
enum class CurveType : int
{
  GeodesicPolygon = 0, ///< consecutive control points joined by shortest paths
  CubicBezier = 1,     ///< anchor, handle, handle, anchor, ... (3n+1 open, 3n closed)
};

/// The one definition of a drawn curve, over the type of its points: ControlCurve holds exact
/// surface points; the curve editor's drawing (Plugin/pqBoolSurfDrawing) holds points that are
/// surface points with what drawing adds (a position to snap, a normal for picking).
/// Header-only, so that the editor uses it without linking Core.
template <class PointType>
struct ControlCurveOf
{
  int CurveId = -1; ///< its id in its input (the cell id of the curves input); -1: none
  int ShapeId = 0;
  CurveType Type = CurveType::GeodesicPolygon;
  bool Closed = true; ///< a drawn curve is a loop unless said otherwise (as Surface Curves)
  std::vector<PointType> Points; ///< the closing point of a closed curve is not repeated
};

/// A control curve of exact surface points: what every stage makes and reads.
using ControlCurve = ControlCurveOf<SurfacePoint>;

/// How many more control points a curve of `size` points needs before it can be traced (0
/// when it is complete): a geodesic polygon needs 2, a cubic Bezier spline 3n+1 open or 3n
/// closed (n >= 1). Inline: the curve editor counts with it too, without linking Core.
inline int MissingControlPoints(bool bezier, bool closed, int size)
{
  if (!bezier)
  {
    return size >= 2 ? 0 : 2 - size;
  }
  // The smallest valid count at or above `size`: 3n closed (n >= 1), 3n+1 open (n >= 1).
  const int base = closed ? 0 : 1;
  int valid = closed ? 3 : 4;
  valid = valid > size ? valid : size;
  while ((valid - base) % 3 != 0)
  {
    ++valid;
  }
  return valid - size;
}

/// What a curve of `size` control points still needs to be traced, as "an open cubic Bezier
/// spline needs 3n+1 control points (...); it has 5: 2 more complete it", or empty when it
/// is complete (a geodesic polygon needs 2 points, a Bezier spline 3n when closed, 3n+1 open).
std::string WhatCurveNeeds(bool bezier, bool closed, int size);

/// Whether the curve has two control points that are not the same surface point (bit for
/// bit): a curve of one point, or of one point repeated, has zero length and bounds nothing.
bool HasDistinctPoints(const ControlCurve& curve);

/// A curve drawn open whose last control point is its first (bit for bit; at least 3 points)
/// is closed: that last point is dropped and the curve marked closed, as the readers of
/// control-curve polylines do. Returns whether it did.
bool CloseWhereEndsMeet(ControlCurve& curve);

/// The one validity check of a control curve: every point a usable surface point
/// (CheckSurfacePoint, with Core's one tolerance for a point inside its triangle), two
/// distinct points, and a count its type can trace (WhatCurveNeeds). False with a sentence
/// naming the first problem ("control point 2: ...").
bool CheckControlCurve(const TriangleMesh& mesh, const ControlCurve& curve, std::string& problem);

} // namespace boolsurf

#endif
