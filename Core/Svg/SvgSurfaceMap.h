// An SVG drawing placed on a surface by the discrete exponential map around a center point
// (BoolSurf §5: "mapped to the surface via normal coordinates, then traced as geodesic
// splines"). The drawing's bounding-box center goes to the center point; a control point at
// offset q from it (SVG's y axis flipped so the drawing reads upright, scaled, rotated) goes
// where the straightest geodesic leaving the center in the direction of q, measured in the
// center triangle's frame (first edge, then normal x first edge), ends after length |q|. On a
// flat mesh this is the affine map; on a curved surface distances from the center are geodesic
// and angles at the center are kept.
//
// Limits, named in warnings: a walk that leaves the surface through an open boundary stops
// there; beyond the injectivity radius (half the shortest loop through the center, or the cut
// locus) straightest geodesics cross and the drawing folds over itself, which is not detected.
#ifndef boolsurf_SvgSurfaceMap_h
#define boolsurf_SvgSurfaceMap_h

#include "Curves/ControlCurve.h"
#include "Mesh/SurfacePoint.h"
#include "Svg/SvgDrawing.h"

#include <string>
#include <vector>

namespace boolsurf
{

struct SvgMapOptions
{
  SurfacePoint Center;
  double Scale = 1.0;    ///< surface length per SVG unit
  double Rotation = 0.0; ///< degrees, counter-clockwise around the center normal
  /// Threads walking the control points (0: all cores); the points are the same on any number.
  int Threads = 0;
};

/// A subpath as a control curve: a cubic spline (3n + 1 control points open, 3n closed) whose
/// ShapeId is the SVG shape element it comes from (in document order of paths).
struct MappedSvgCurve : ControlCurve
{
  bool EvenOdd = false; ///< that element's fill-rule
};

/// Maps every subpath; each path's subpaths are oriented so that its filled area (total signed
/// area positive in the upright drawing) is on their left. Points that hit a boundary are
/// counted in a warning.
bool MapSvgOntoSurface(const TriangleMesh& mesh,
  const SvgDrawing& drawing,
  const SvgMapOptions& options,
  std::vector<MappedSvgCurve>& out,
  std::vector<std::string>& warnings,
  std::string& error);

} // namespace boolsurf

#endif
