// SVG drawings nested 10^6 deep (groups, groups and nested svg elements over lines) are refused
// with a named error (nesting too deep, the limit, the element and its line) before libxml2
// and svgpp see them; markup inside comments, CDATA and attribute values does not count, empty
// elements do not nest, and a path at the limit itself is read (svgpp's recursion at 256
// levels).
#include "Svg/SvgDrawing.h"

#include <gtest/gtest.h>

#include <string>

using namespace boolsurf;

namespace
{
constexpr int Levels = 1000000;

const std::string Root = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 100 100\">";
const std::string Path = "<path d='M0 0 L1 0 L1 1 Z'/>";

std::string Repeat(const std::string& s, int n)
{
  std::string out;
  out.reserve(s.size() * n);
  for (int i = 0; i < n; ++i)
  {
    out += s;
  }
  return out;
}

std::string Message(const std::string& element, int line)
{
  return "nesting too deep: element <" + element + "> at line " + std::to_string(line) + " is " +
    std::to_string(MaxSvgNestingDepth + 1) +
    " levels deep; SVG drawings may nest elements at most " + std::to_string(MaxSvgNestingDepth) +
    " levels";
}
} // namespace

TEST(SvgDeepNesting, Groups)
{
  const std::string text = Root + Repeat("<g>", Levels) + Path + Repeat("</g>", Levels) + "</svg>";
  SvgDrawing d;
  std::string error;
  EXPECT_FALSE(ParseSvg(text, d, error));
  EXPECT_EQ(error, Message("g", 1));
  EXPECT_TRUE(d.Paths.empty());
}

TEST(SvgDeepNesting, GroupsAndSvgElementsOverLines)
{
  // Level k (k >= 2) on line k: even levels <g>, odd levels nested <svg>.
  std::string text = Root + "\n";
  for (int level = 2; level <= Levels; ++level)
  {
    text += level % 2 == 0 ? "<g transform='translate(1 0)'>\n" : "<svg x='1'>\n";
  }
  text += Path;
  for (int level = Levels; level >= 2; --level)
  {
    text += level % 2 == 0 ? "</g>" : "</svg>";
  }
  text += "</svg>";
  SvgDrawing d;
  std::string error;
  EXPECT_FALSE(ParseSvg(text, d, error));
  EXPECT_EQ(error, Message("svg", MaxSvgNestingDepth + 1));
}

TEST(SvgDeepNesting, UnclosedGroups)
{
  SvgDrawing d;
  std::string error;
  EXPECT_FALSE(ParseSvg(Root + Repeat("<g>", Levels), d, error));
  EXPECT_EQ(error, Message("g", 1));
}

TEST(SvgDeepNesting, MarkupThatIsNotNestingDoesNotCount)
{
  // 10^6 start tags in a comment, a CDATA section, a processing instruction and an attribute
  // value ('>' in it ends no tag), and 10^6 empty groups side by side: one path, read.
  const std::string tags = Repeat("<g>", Levels);
  const std::string text = "<?xml version='1.0'?>\n<!DOCTYPE svg [ <!ENTITY e '<g></g>'> ]>\n" +
    Root + "<!--" + tags + "-->" + "<style><![CDATA[" + tags + "]]></style><?pi " + tags + "?>" +
    "<g data-x='" + std::string(Levels, '>') + "'>" + Repeat("<g/>", Levels) + Path + "</g></svg>";
  SvgDrawing d;
  std::string error;
  ASSERT_TRUE(ParseSvg(text, d, error)) << error.substr(0, 300);
  EXPECT_EQ(d.Paths.size(), 1u);
}

TEST(SvgDeepNesting, PathAtTheLimitIsRead)
{
  // svg at level 1, groups at 2..255, the path at 256.
  const int groups = MaxSvgNestingDepth - 2;
  auto drawing = [](int n)
  {
    return Root + Repeat("<g transform='translate(1 0)'>", n) + Path + Repeat("</g>", n) + "</svg>";
  };
  SvgDrawing d;
  std::string error;
  ASSERT_TRUE(ParseSvg(drawing(groups), d, error)) << error;
  ASSERT_EQ(d.Paths.size(), 1u);
  EXPECT_EQ(d.Paths[0].Subpaths[0].Points[0].x, groups); // every group's transform applied
  // One more level is refused.
  EXPECT_FALSE(ParseSvg(drawing(groups + 1), d, error));
  EXPECT_EQ(error, Message("path", 1));
}
