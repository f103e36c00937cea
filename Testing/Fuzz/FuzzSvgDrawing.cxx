// libFuzzer target: the SVG reader (Core/Svg/SvgDrawing: a nesting scan, libxml2, svgpp) on
// arbitrary document text. Every input must give a drawing or an error message; a drawing
// must hold cubic splines (3n + 1 control points open, 3n closed) of finite points within its
// bounds.
#include "FuzzSupport.h"
#include "Svg/SvgDrawing.h"

#include <cmath>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace boolsurf;
  const std::string text(reinterpret_cast<const char*>(data), size);
  SvgDrawing drawing;
  std::string error;
  if (!ParseSvg(text, drawing, error))
  {
    BOOLSURF_FUZZ_CHECK(!error.empty(), "a failed read must say why");
    return 0;
  }
  BOOLSURF_FUZZ_CHECK(!drawing.Paths.empty(), "a drawing read has a path");
  for (const SvgPath& path : drawing.Paths)
  {
    for (const SvgSubpath& subpath : path.Subpaths)
    {
      const std::size_t n = subpath.Points.size();
      BOOLSURF_FUZZ_CHECK(n > 0 && (subpath.Closed ? n % 3 == 0 : n % 3 == 1),
        std::to_string(n) + " control points, closed " + std::to_string(subpath.Closed));
      for (const Vec2& p : subpath.Points)
      {
        BOOLSURF_FUZZ_CHECK(std::isfinite(p.x) && std::isfinite(p.y), "a non-finite point");
        BOOLSURF_FUZZ_CHECK(p.x >= drawing.Min[0] && p.x <= drawing.Max[0] &&
            p.y >= drawing.Min[1] && p.y <= drawing.Max[1],
          "a point outside the bounds");
      }
    }
  }
  return 0;
}
