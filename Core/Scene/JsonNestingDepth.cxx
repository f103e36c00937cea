#include "Scene/JsonNestingDepth.h"

#include <algorithm>

namespace boolsurf
{

//------------------------------------------------------------------------------
std::optional<JsonNestingExcess> FindJsonNestingBeyond(const std::string& text, int maxDepth)
{
  int depth = 0;
  std::size_t line = 1, lineStart = 0;
  // The last string read at level 1: in a top-level object, the key of the value that opens
  // level 2 (a string value at level 1 is always followed by a key before the next value).
  std::string levelOneString;
  bool topLevelIsObject = false;
  for (std::size_t i = 0; i < text.size(); ++i)
  {
    const char c = text[i];
    if (c == '\n')
    {
      ++line;
      lineStart = i + 1;
    }
    else if (c == '"')
    {
      const std::size_t start = i + 1;
      for (++i; i < text.size() && text[i] != '"'; ++i)
      {
        if (text[i] == '\\')
        {
          ++i; // the escaped character, a quote or a backslash included
        }
        else if (text[i] == '\n')
        {
          // Not valid JSON (the parser stops here); counted so that later lines stay right.
          ++line;
          lineStart = i + 1;
        }
      }
      if (depth == 1)
      {
        levelOneString = text.substr(start, std::min<std::size_t>(i - start, 40));
      }
    }
    else if (c == '[' || c == '{')
    {
      topLevelIsObject = depth == 0 ? c == '{' : topLevelIsObject;
      if (++depth > maxDepth)
      {
        JsonNestingExcess excess;
        excess.Depth = depth;
        excess.Bracket = c;
        excess.Line = line;
        excess.Column = i - lineStart + 1;
        excess.TopLevelKey = topLevelIsObject ? levelOneString : "";
        return excess;
      }
    }
    else if (c == ']' || c == '}')
    {
      depth = depth > 0 ? depth - 1 : 0;
    }
  }
  return std::nullopt;
}

} // namespace boolsurf
