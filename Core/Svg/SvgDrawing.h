// An SVG drawing as cubic Bezier splines in the plane (the input of MapSvgOntoSurface).
//
// Parsing is svgpp's (libsvgpp-dev, with libxml2 as the XML parser): path data M/L/H/V/C/S/Q/T/A/Z
// absolute and relative, quadratic segments and elliptical arcs turned into cubics, basic
// shapes (rect, circle, ellipse, line, polyline, polygon) as paths, `transform` on paths and
// groups, `fill-rule` as an attribute or in `style`, inherited. Straight segments become cubics
// with handles at a third and two thirds, so every subpath is one cubic spline: anchor,
// handle, handle, anchor, ... (3n + 1 points open, 3n closed). Attributes and CSS properties
// svgpp does not know are skipped and named in the warnings; text, images, gradients are not
// drawn (only shape elements are read).
#ifndef boolsurf_SvgDrawing_h
#define boolsurf_SvgDrawing_h

#include "Mesh/Vec3.h"

#include <string>
#include <vector>

namespace boolsurf
{

struct SvgSubpath
{
  std::vector<Vec2> Points; ///< cubic spline control points, in the SVG's user units
  bool Closed = false;
};

struct SvgPath
{
  std::vector<SvgSubpath> Subpaths;
  bool EvenOdd = false; ///< fill-rule: evenodd (else nonzero)
  int Element = 0;      ///< index of the shape element among the drawing's shapes
};

struct SvgDrawing
{
  std::vector<SvgPath> Paths;
  std::vector<std::string> Warnings;
  double Min[2] = { 0, 0 }, Max[2] = { 0, 0 }; ///< bounds of all control points
};

/// How deep a drawing may nest elements (the root `svg` is level 1; editors nest a few groups
/// per layer). Deeper is refused before the document is parsed: svgpp walks the elements by
/// recursion, once per level. 256 as for scene files; libxml2 itself stops at 257.
constexpr int MaxSvgNestingDepth = 256;

/// Reads an SVG file. False with a sentence naming the problem (missing file, elements nested
/// deeper than MaxSvgNestingDepth: "nesting too deep: element <g> at line 3 is 257 levels deep;
/// ...", malformed XML, an SVG error from svgpp, no path at all).
bool LoadSvg(const std::string& fileName, SvgDrawing& out, std::string& error);

/// The same from the text of a document.
bool ParseSvg(const std::string& text, SvgDrawing& out, std::string& error);

} // namespace boolsurf

#endif
