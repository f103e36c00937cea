// libxml2's declarations first: svgpp's libxml2 adapter uses them without including them.
#include <libxml/parser.h>
#include <libxml/tree.h>

#include "Svg/SvgDrawing.h"
#include "Svg/XmlNestingDepth.h"

#include <svgpp/policy/xml/libxml2.hpp>
#include <svgpp/svgpp.hpp>
#include <svgpp/utility/arc_endpoint_to_center.hpp>

#include <boost/mpl/set.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>

namespace boolsurf
{
namespace
{

/// x' = a x + c y + e, y' = b x + d y + f, as (a, b, c, d, e, f) like SVG's matrix().
using Matrix = std::array<double, 6>;

Matrix Multiply(const Matrix& m, const Matrix& n)
{
  return { m[0] * n[0] + m[2] * n[1],
    m[1] * n[0] + m[3] * n[1],
    m[0] * n[2] + m[2] * n[3],
    m[1] * n[2] + m[3] * n[3],
    m[0] * n[4] + m[2] * n[5] + m[4],
    m[1] * n[4] + m[3] * n[5] + m[5] };
}

Vec2 Apply(const Matrix& m, double x, double y)
{
  return { m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5] };
}

/// Whether a and b differ only by rounding, relative to the extent of `points`.
bool SamePoint(const Vec2& a, const Vec2& b, const std::vector<Vec2>& points)
{
  double extent = 0;
  for (const Vec2& p : points)
  {
    extent = std::max({ extent, std::abs(p.x - b.x), std::abs(p.y - b.y) });
  }
  return std::abs(a.x - b.x) <= 1e-12 * extent && std::abs(a.y - b.y) <= 1e-12 * extent;
}

/// Removes the segments of a spline (P0, then 3 points per segment) whose four control points
/// are one point up to rounding: a line to where the path already is, the edge of a rect whose
/// corners' radii take its whole side. A segment of no length is no curve, and traced it would
/// be a leg between a point and itself.
void DropEmptySegments(std::vector<Vec2>& p)
{
  if (p.size() < 4)
  {
    return;
  }
  double extent = 0;
  for (const Vec2& q : p)
  {
    extent = std::max({ extent, std::abs(q.x - p[0].x), std::abs(q.y - p[0].y) });
  }
  const double tolerance = 1e-12 * extent;
  auto same = [tolerance](const Vec2& a, const Vec2& b)
  { return std::abs(a.x - b.x) <= tolerance && std::abs(a.y - b.y) <= tolerance; };
  std::vector<Vec2> kept = { p[0] };
  for (std::size_t s = 0; 3 * s + 3 < p.size(); ++s)
  {
    const Vec2& start = kept.back();
    const Vec2 *h1 = &p[3 * s + 1], *h2 = &p[3 * s + 2], *end = &p[3 * s + 3];
    if (same(start, *h1) && same(start, *h2) && same(start, *end))
    {
      continue;
    }
    kept.insert(kept.end(), { *h1, *h2, *end });
  }
  p = std::move(kept);
}

/// Receives svgpp's events for the whole document (one context: element state on stacks).
class Collector
{
public:
  explicit Collector(SvgDrawing& out)
    : Out(out)
  {
  }

  void on_enter_element(svgpp::tag::element::any)
  {
    this->Transforms.push_back(this->Transforms.back());
    this->EvenOdd.push_back(this->EvenOdd.back());
    ++this->Elements;
  }
  void on_exit_element()
  {
    this->Transforms.pop_back();
    this->EvenOdd.pop_back();
  }
  void transform_matrix(const boost::array<double, 6>& m)
  {
    this->Transforms.back() =
      Multiply(this->Transforms.back(), { m[0], m[1], m[2], m[3], m[4], m[5] });
  }
  void set(svgpp::tag::attribute::fill_rule, svgpp::tag::value::nonzero)
  {
    this->EvenOdd.back() = false;
  }
  void set(svgpp::tag::attribute::fill_rule, svgpp::tag::value::evenodd)
  {
    this->EvenOdd.back() = true;
  }
  template <class Value>
  void set(svgpp::tag::attribute::fill_rule, Value)
  {
  }

  void path_move_to(double x, double y, svgpp::tag::coordinate::absolute)
  {
    this->EndSubpath(false);
    this->Current.Points = { this->Map(x, y) };
    this->At = this->SubpathStart = { x, y };
  }
  void path_line_to(double x, double y, svgpp::tag::coordinate::absolute)
  {
    this->path_line_to_mapped(this->Map(x, y));
    this->At = { x, y };
  }
  void path_cubic_bezier_to(double x1,
    double y1,
    double x2,
    double y2,
    double x,
    double y,
    svgpp::tag::coordinate::absolute)
  {
    this->Current.Points.push_back(this->Map(x1, y1));
    this->Current.Points.push_back(this->Map(x2, y2));
    this->Current.Points.push_back(this->Map(x, y));
    this->At = { x, y };
  }
  /// An elliptical arc (SVG's endpoint form, rotation in degrees) as few cubic pieces as it
  /// has quarter turns, so a circle (two half-turn arcs from svgpp's basic shapes) is 4 pieces
  /// (svgpp's own conversion makes a half turn 3), a rounded corner 1; the last piece ends
  /// exactly at the arc's end, so a closed circle closes without a sliver.
  void path_elliptical_arc_to(double rx,
    double ry,
    double rotation,
    bool largeArc,
    bool sweep,
    double x,
    double y,
    svgpp::tag::coordinate::absolute)
  {
    const Vec2 from = this->At;
    if (from.x == x && from.y == y)
    {
      return; // SVG: an arc to its own start is left out
    }
    if (rx == 0 || ry == 0)
    {
      this->path_line_to(x, y, svgpp::tag::coordinate::absolute()); // SVG: a straight line
      return;
    }
    const double pi = std::acos(-1.0);
    const double phi = rotation * pi / 180;
    rx = std::abs(rx);
    ry = std::abs(ry);
    double cx, cy, t0, t1;
    svgpp::arc_endpoint_to_center(
      from.x, from.y, x, y, rx, ry, phi, largeArc, sweep, cx, cy, t0, t1);
    if (sweep && t1 < t0)
    {
      t1 += 2 * pi;
    }
    else if (!sweep && t1 > t0)
    {
      t1 -= 2 * pi;
    }
    const double c = std::cos(phi), s = std::sin(phi);
    auto point = [&](double t)
    {
      const double ex = rx * std::cos(t), ey = ry * std::sin(t);
      return Vec2{ cx + c * ex - s * ey, cy + s * ex + c * ey };
    };
    auto tangent = [&](double t)
    {
      const double ex = -rx * std::sin(t), ey = ry * std::cos(t);
      return Vec2{ c * ex - s * ey, s * ex + c * ey };
    };
    const int pieces =
      std::max(1, static_cast<int>(std::ceil(std::abs(t1 - t0) / (pi / 2) - 1e-9)));
    for (int k = 0; k < pieces; ++k)
    {
      const double a = t0 + (t1 - t0) * k / pieces, b = t0 + (t1 - t0) * (k + 1) / pieces;
      const double handle = 4.0 / 3.0 * std::tan((b - a) / 4);
      const Vec2 p0 = point(a), p3 = k + 1 == pieces ? Vec2{ x, y } : point(b);
      const Vec2 p1 = p0 + handle * tangent(a), p2 = point(b) - handle * tangent(b);
      this->Current.Points.push_back(this->Map(p1.x, p1.y));
      this->Current.Points.push_back(this->Map(p2.x, p2.y));
      this->Current.Points.push_back(this->Map(p3.x, p3.y));
    }
    this->At = { x, y };
  }
  void path_close_subpath()
  {
    this->EndSubpath(true);
    this->At = this->SubpathStart;
  }

  void path_exit()
  {
    this->EndSubpath(false);
    if (!this->Path.Subpaths.empty())
    {
      this->Path.EvenOdd = this->EvenOdd.back();
      this->Path.Element = static_cast<int>(this->Out.Paths.size());
      this->Out.Paths.push_back(std::move(this->Path));
    }
    this->Path = SvgPath();
  }

  /// Names svgpp did not know (attributes, CSS properties), each once.
  std::set<std::string> Ignored;

private:
  Vec2 Map(double x, double y) const { return Apply(this->Transforms.back(), x, y); }

  void EndSubpath(bool close)
  {
    std::vector<Vec2>& p = this->Current.Points;
    DropEmptySegments(p);
    if (p.size() >= 4)
    {
      if (close)
      {
        // Back to the start by a straight piece if not there, then the start is not repeated.
        // An end within rounding of the start (arcs summing to a full turn) is the start: a
        // straight piece there would be a segment of no length.
        const Vec2 a = p.back(), b = p.front();
        if (!SamePoint(a, b, p))
        {
          this->path_line_to_mapped(b);
        }
        p.pop_back();
        this->Current.Closed = true;
      }
      this->Path.Subpaths.push_back(this->Current);
    }
    const Vec2 start = p.empty() ? Vec2{} : p.front();
    this->Current = SvgSubpath();
    if (close)
    {
      this->Current.Points = { start }; // a path may go on from where it closed
    }
  }
  void path_line_to_mapped(Vec2 b)
  {
    const Vec2 a = this->Current.Points.back();
    this->Current.Points.push_back(a + (1.0 / 3.0) * (b - a));
    this->Current.Points.push_back(a + (2.0 / 3.0) * (b - a));
    this->Current.Points.push_back(b);
  }

  SvgDrawing& Out;
  std::vector<Matrix> Transforms{ Matrix{ 1, 0, 0, 1, 0, 0 } };
  std::vector<char> EvenOdd{ 0 };
  int Elements = 0;
  SvgPath Path;
  SvgSubpath Current;
  Vec2 At, SubpathStart; ///< the current point and the subpath's start, in user units
};

template <class Name>
std::string Text(const Name& name)
{
  return std::string(boost::begin(name), boost::end(name));
}

/// svgpp's errors, except that attributes and CSS properties it does not know (editors write
/// data-name, serif:id, ...) are noted and skipped.
struct LenientErrors : svgpp::policy::error::raise_exception<Collector>
{
  template <class XMLAttribute, class AttributeName>
  static bool unknown_attribute(Collector const& c,
    XMLAttribute const&,
    AttributeName const& name,
    BOOST_SCOPED_ENUM(svgpp::detail::namespace_id),
    svgpp::tag::source::attribute,
    typename boost::enable_if<typename svgpp::detail::is_char_range<AttributeName>::type>::type* =
      nullptr)
  {
    const_cast<Collector&>(c).Ignored.insert("attribute " + Text(name));
    return true;
  }
  template <class XMLAttribute, class AttributeName>
  static bool unknown_attribute(Collector const&,
    XMLAttribute const&,
    AttributeName const&,
    BOOST_SCOPED_ENUM(svgpp::detail::namespace_id),
    svgpp::tag::source::attribute,
    typename boost::disable_if<typename svgpp::detail::is_char_range<AttributeName>::type>::type* =
      nullptr)
  {
    return true;
  }
  template <class XMLAttribute, class AttributeName>
  static bool unknown_attribute(Collector const& c,
    XMLAttribute const&,
    AttributeName const& name,
    svgpp::tag::source::css,
    typename boost::enable_if<typename svgpp::detail::is_char_range<AttributeName>::type>::type* =
      nullptr)
  {
    const_cast<Collector&>(c).Ignored.insert("CSS property " + Text(name));
    return true;
  }
  template <class XMLAttribute, class AttributeName>
  static bool unknown_attribute(Collector const&,
    XMLAttribute const&,
    AttributeName const&,
    svgpp::tag::source::css,
    typename boost::disable_if<typename svgpp::detail::is_char_range<AttributeName>::type>::type* =
      nullptr)
  {
    return true;
  }
};

using ProcessedElements = boost::mpl::set<svgpp::tag::element::svg,
  svgpp::tag::element::g,
  svgpp::tag::element::path,
  svgpp::tag::element::rect,
  svgpp::tag::element::circle,
  svgpp::tag::element::ellipse,
  svgpp::tag::element::line,
  svgpp::tag::element::polyline,
  svgpp::tag::element::polygon>::type;

/// svgpp's minimal path events, except that elliptical arcs come as arcs
/// (Collector::path_elliptical_arc_to converts them).
struct PathPolicy : svgpp::policy::path::minimal
{
  static const bool arc_as_cubic_bezier = false;
};

using ProcessedAttributes =
  boost::mpl::insert<boost::mpl::insert<svgpp::traits::shapes_attributes_by_element,
                       svgpp::tag::attribute::transform>::type,
    svgpp::tag::attribute::fill_rule>::type;

bool Traverse(xmlDocPtr doc, SvgDrawing& out, std::string& error)
{
  xmlNodePtr root = doc ? xmlDocGetRootElement(doc) : nullptr;
  if (!root)
  {
    error = "not an XML document";
    return false;
  }
  Collector collector(out);
  try
  {
    svgpp::document_traversal<svgpp::processed_elements<ProcessedElements>,
      svgpp::processed_attributes<ProcessedAttributes>,
      svgpp::path_policy<PathPolicy>,
      svgpp::basic_shapes_policy<svgpp::policy::basic_shapes::all_to_path>,
      svgpp::error_policy<LenientErrors>>::load_document(root, collector);
  }
  catch (const std::exception& e)
  {
    error = std::string("SVG error: ") + e.what();
    return false;
  }
  for (const std::string& name : collector.Ignored)
  {
    out.Warnings.push_back("ignored unknown " + name);
  }
  bool first = true;
  for (const SvgPath& path : out.Paths)
  {
    for (const SvgSubpath& s : path.Subpaths)
    {
      for (const Vec2& p : s.Points)
      {
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
        {
          error = "shape element " + std::to_string(path.Element) + " has a non-finite point";
          return false;
        }
        out.Min[0] = first ? p.x : std::min(out.Min[0], p.x);
        out.Min[1] = first ? p.y : std::min(out.Min[1], p.y);
        out.Max[0] = first ? p.x : std::max(out.Max[0], p.x);
        out.Max[1] = first ? p.y : std::max(out.Max[1], p.y);
        first = false;
      }
    }
  }
  if (out.Paths.empty())
  {
    error = "the drawing has no path or shape with at least one segment";
    return false;
  }
  return true;
}

struct DocumentDeleter
{
  void operator()(xmlDoc* doc) const { xmlFreeDoc(doc); }
};

} // namespace

//------------------------------------------------------------------------------
bool ParseSvg(const std::string& text, SvgDrawing& out, std::string& error)
{
  out = SvgDrawing();
  if (const auto excess = FindXmlNestingBeyond(text, MaxSvgNestingDepth))
  {
    error = "nesting too deep: element <" + excess->Element + "> at line " +
      std::to_string(excess->Line) + " is " + std::to_string(excess->Depth) +
      " levels deep; SVG drawings may nest elements at most " + std::to_string(MaxSvgNestingDepth) +
      " levels";
    return false;
  }
  std::unique_ptr<xmlDoc, DocumentDeleter> doc(xmlReadMemory(text.data(),
    static_cast<int>(text.size()),
    "drawing.svg",
    nullptr,
    XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING));
  if (!doc)
  {
    const xmlError* e = xmlGetLastError();
    error = std::string("malformed XML") +
      (e && e->message ? std::string(" (line ") + std::to_string(e->line) + ": " + e->message : "");
    while (!error.empty() && (error.back() == '\n' || error.back() == ' '))
    {
      error.pop_back();
    }
    if (e && e->message)
    {
      error += ")";
    }
    return false;
  }
  return Traverse(doc.get(), out, error);
}

//------------------------------------------------------------------------------
bool LoadSvg(const std::string& fileName, SvgDrawing& out, std::string& error)
{
  std::ifstream in(fileName, std::ios::binary);
  if (!in)
  {
    out = SvgDrawing();
    error = "cannot open " + fileName;
    return false;
  }
  std::stringstream text;
  text << in.rdbuf();
  if (!ParseSvg(text.str(), out, error))
  {
    error = fileName + ": " + error;
    return false;
  }
  return true;
}

} // namespace boolsurf
