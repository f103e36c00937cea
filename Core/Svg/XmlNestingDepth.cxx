#include "Svg/XmlNestingDepth.h"

#include <algorithm>
#include <cctype>
#include <cstring>

namespace boolsurf
{
namespace
{

/// Reads an XML text's markup, one construct at a time, counting lines.
class MarkupScanner
{
public:
  explicit MarkupScanner(const std::string& text)
    : Text(text)
  {
  }

  bool AtEnd() const { return this->Pos >= this->Text.size(); }
  bool LookingAt(const char* s) const
  {
    return this->Text.compare(this->Pos, std::strlen(s), s) == 0;
  }
  char Peek(std::size_t ahead = 0) const
  {
    return this->Pos + ahead < this->Text.size() ? this->Text[this->Pos + ahead] : '\0';
  }
  std::size_t GetLine() const { return this->Line; }

  void Advance(std::size_t n = 1)
  {
    for (; n > 0 && !this->AtEnd(); --n, ++this->Pos)
    {
      this->Line += this->Text[this->Pos] == '\n';
    }
  }
  /// Moves past the next `end` (to the end of the text when there is none).
  void SkipPast(const char* end)
  {
    while (!this->AtEnd() && !this->LookingAt(end))
    {
      this->Advance();
    }
    this->Advance(std::strlen(end));
  }
  /// Moves past the '>' ending a tag or declaration: not one inside quotes, nor (in a
  /// DOCTYPE's internal subset) inside brackets.
  void SkipTag()
  {
    char quote = '\0';
    int brackets = 0;
    for (; !this->AtEnd(); this->Advance())
    {
      const char c = this->Peek();
      if (quote != '\0')
      {
        quote = c == quote ? '\0' : quote;
      }
      else if (c == '"' || c == '\'')
      {
        quote = c;
      }
      else if (c == '[' || c == ']')
      {
        brackets += c == '[' ? 1 : -1;
      }
      else if (c == '>' && brackets <= 0)
      {
        this->Advance();
        return;
      }
    }
  }
  /// The name starting here (letters, digits, '_', '-', '.', ':' and any byte of a UTF-8
  /// character), consumed.
  std::string Name()
  {
    const std::size_t start = this->Pos;
    while (!this->AtEnd())
    {
      const unsigned char c = static_cast<unsigned char>(this->Peek());
      if (!(std::isalnum(c) || c == '_' || c == '-' || c == '.' || c == ':' || c >= 0x80))
      {
        break;
      }
      this->Advance();
    }
    return this->Text.substr(start, this->Pos - start);
  }
  /// Whether the tag just skipped ended with "/>" (an empty element).
  bool EndedEmpty() const { return this->Pos >= 2 && this->Text[this->Pos - 2] == '/'; }

private:
  const std::string& Text;
  std::size_t Pos = 0;
  std::size_t Line = 1;
};

} // namespace

//------------------------------------------------------------------------------
std::optional<XmlNestingExcess> FindXmlNestingBeyond(const std::string& text, int maxDepth)
{
  MarkupScanner scan(text);
  int depth = 0;
  while (!scan.AtEnd())
  {
    if (scan.Peek() != '<')
    {
      scan.Advance();
    }
    else if (scan.LookingAt("<!--"))
    {
      scan.SkipPast("-->");
    }
    else if (scan.LookingAt("<![CDATA["))
    {
      scan.SkipPast("]]>");
    }
    else if (scan.LookingAt("<?"))
    {
      scan.SkipPast("?>");
    }
    else if (scan.Peek(1) == '!') // DOCTYPE (with its internal subset) and other declarations
    {
      scan.SkipTag();
    }
    else if (scan.Peek(1) == '/')
    {
      scan.SkipTag();
      depth = std::max(depth - 1, 0);
    }
    else
    {
      const std::size_t line = scan.GetLine();
      scan.Advance();
      std::string name = scan.Name();
      scan.SkipTag();
      // An empty element (<path/>) is at a level of its own too, but holds no other.
      const int level = depth + 1;
      if (level > maxDepth)
      {
        XmlNestingExcess excess;
        excess.Depth = level;
        excess.Element = name.substr(0, 40);
        excess.Line = line;
        return excess;
      }
      depth = scan.EndedEmpty() ? depth : level;
    }
  }
  return std::nullopt;
}

} // namespace boolsurf
