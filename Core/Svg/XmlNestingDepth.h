// How deep an XML text nests elements, found by scanning its markup before libxml2 parses it.
//
// Why: svgpp walks the document's elements by recursion, once per level. libxml2 stops at
// 257 levels itself (or not at all with XML_PARSE_HUGE, and other versions differ), with a
// message that names its own option rather than the drawing; this scan gives our limit and
// names where it is passed. Comments, CDATA sections, processing instructions and the
// DOCTYPE are skipped, quoted attribute values too (a '>' in them ends no tag); on malformed
// XML the count is of the start and end tags as written, and libxml2 reports the error.
#ifndef boolsurf_XmlNestingDepth_h
#define boolsurf_XmlNestingDepth_h

#include <cstddef>
#include <optional>
#include <string>

namespace boolsurf
{

/// The first start tag of an XML text that opens more than the allowed levels of elements.
struct XmlNestingExcess
{
  int Depth = 0;        ///< its level (the root element is level 1)
  std::string Element;  ///< its name as written (cut to 40 bytes)
  std::size_t Line = 1; ///< 1-based, counting '\n'
};

/// Where `text` first nests elements deeper than `maxDepth` levels; none when it never does.
std::optional<XmlNestingExcess> FindXmlNestingBeyond(const std::string& text, int maxDepth);

} // namespace boolsurf

#endif
