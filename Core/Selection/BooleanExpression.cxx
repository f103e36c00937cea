#include "Selection/BooleanExpression.h"

#include <algorithm>
#include <cctype>
#include <climits>
#include <cstdio>

namespace boolsurf
{
namespace
{

// Length of the UTF-8 sequence starting at byte `at` of s, or 1 for a byte that starts none.
size_t Utf8Length(const std::string& s, size_t at)
{
  const unsigned char c = static_cast<unsigned char>(s[at]);
  const size_t length = c < 0x80 ? 1
    : (c >> 5) == 0x6            ? 2
    : (c >> 4) == 0xE            ? 3
    : (c >> 3) == 0x1E           ? 4
                                 : 0;
  if (length == 0 || at + length > s.size())
  {
    return 1;
  }
  for (size_t k = 1; k < length; ++k)
  {
    if ((static_cast<unsigned char>(s[at + k]) & 0xC0) != 0x80)
    {
      return 1;
    }
  }
  return length;
}

// s with every byte that is not part of valid UTF-8 written as \xNN: messages stay valid UTF-8
// (Python observers receive None otherwise).
std::string Utf8Safe(const std::string& s)
{
  std::string out;
  for (size_t at = 0; at < s.size();)
  {
    const size_t length = Utf8Length(s, at);
    const unsigned char c = static_cast<unsigned char>(s[at]);
    if (length == 1 && c >= 0x80)
    {
      char hex[8];
      std::snprintf(hex, sizeof(hex), "\\x%02X", c);
      out += hex;
    }
    else
    {
      out.append(s, at, length);
    }
    at += length;
  }
  return out;
}

// Recursive-descent parser emitting postfix code.
class Parser
{
public:
  /// `ids`: the shapes' ids, sorted (S<id> compiles to the id's index), or null: S<id>
  /// compiles to id, valid below numberOfShapes (any id when numberOfShapes < 0).
  Parser(const std::string& text,
    int numberOfShapes,
    const std::vector<int>* ids,
    std::vector<int>& code)
    : Text(text)
    , NumberOfShapes(numberOfShapes)
    , Ids(ids)
    , Code(code)
  {
  }

  bool Run(std::string& error)
  {
    this->Code.clear();
    if (!this->Expr())
    {
      error = this->Error;
      return false;
    }
    this->SkipSpace();
    if (this->Pos != this->Text.size())
    {
      error = this->Message("unexpected '" + this->CharacterAt(this->Pos) +
        "' (expected an operator & | ^ - or the end)");
      return false;
    }
    return true;
  }

  enum : int
  {
    Push = 0,
    Not,
    And,
    Or,
    Xor,
    Minus
  };

private:
  // The character at byte `at` for a message: a whole UTF-8 sequence, not one byte of it.
  std::string CharacterAt(size_t at) const
  {
    return Utf8Safe(this->Text.substr(at, Utf8Length(this->Text, at)));
  }

  void SkipSpace()
  {
    while (this->Pos < this->Text.size() &&
      std::isspace(static_cast<unsigned char>(this->Text[this->Pos])))
    {
      ++this->Pos;
    }
  }
  std::string Message(const std::string& what) const
  {
    return "expression \"" + Utf8Safe(this->Text) + "\", position " +
      std::to_string(this->Pos + 1) + ": " + what;
  }
  bool Fail(const std::string& what)
  {
    this->Error = this->Message(what);
    return false;
  }
  bool Accept(char c)
  {
    this->SkipSpace();
    if (this->Pos < this->Text.size() && this->Text[this->Pos] == c)
    {
      ++this->Pos;
      return true;
    }
    return false;
  }

  // Parentheses nest by recursion: deeper than this is refused rather than overflowing the
  // stack (no real expression comes near it).
  static constexpr int MaximumDepth = 256;

  bool Primary()
  {
    this->SkipSpace();
    if (this->Pos >= this->Text.size())
    {
      return this->Fail("unexpected end (expected a shape S<id>, '~' or '(')");
    }
    // A run of '~' is counted, not recursed into: only its parity matters.
    size_t nots = 0;
    while (this->Accept('~'))
    {
      ++nots;
    }
    if (nots > 0)
    {
      if (!this->Primary())
        return false;
      if (nots % 2)
        this->Code.push_back(Not);
      return true;
    }
    if (this->Accept('('))
    {
      if (++this->Depth > MaximumDepth)
      {
        --this->Pos;
        return this->Fail("parentheses nested deeper than " + std::to_string(MaximumDepth));
      }
      if (!this->Expr())
        return false;
      if (!this->Accept(')'))
        return this->Fail("missing ')'");
      --this->Depth;
      return true;
    }
    const char c = this->Text[this->Pos];
    if (c == 'S' || c == 's')
    {
      const size_t start = ++this->Pos;
      while (this->Pos < this->Text.size() &&
        std::isdigit(static_cast<unsigned char>(this->Text[this->Pos])))
      {
        ++this->Pos;
      }
      if (this->Pos == start)
      {
        return this->Fail("a shape is written S<id>, e.g. S0");
      }
      if (this->Pos - start > 10)
      {
        return this->Fail("shape id too large");
      }
      const long long id = std::stoll(this->Text.substr(start, this->Pos - start));
      int operand = static_cast<int>(id);
      if (this->Ids)
      {
        const auto it = std::lower_bound(this->Ids->begin(), this->Ids->end(), id);
        if (it == this->Ids->end() || *it != id)
        {
          this->Pos = start - 1;
          return this->Fail("unknown shape S" + std::to_string(id) + " (the input has " +
            ShapeList(*this->Ids) + ")");
        }
        operand = static_cast<int>(it - this->Ids->begin());
      }
      else if (id > INT_MAX || (this->NumberOfShapes >= 0 && id >= this->NumberOfShapes))
      {
        this->Pos = start - 1;
        return this->Fail("unknown shape S" + std::to_string(id) + " (the input has " +
          std::to_string(this->NumberOfShapes) + " shape(s): S0..S" +
          std::to_string(this->NumberOfShapes - 1) + ")");
      }
      this->Code.push_back(Push);
      this->Code.push_back(operand);
      return true;
    }
    return this->Fail(
      "unexpected '" + this->CharacterAt(this->Pos) + "' (expected a shape S<id>, '~' or '(')");
  }

  bool AndLevel()
  {
    if (!this->Primary())
      return false;
    for (;;)
    {
      int op;
      if (this->Accept('&'))
        op = And;
      else if (this->Accept('-'))
        op = Minus;
      else
        return true;
      if (!this->Primary())
        return false;
      this->Code.push_back(op);
    }
  }

  bool XorLevel()
  {
    if (!this->AndLevel())
      return false;
    while (this->Accept('^'))
    {
      if (!this->AndLevel())
        return false;
      this->Code.push_back(Xor);
    }
    return true;
  }

  bool Expr()
  {
    if (!this->XorLevel())
      return false;
    while (this->Accept('|'))
    {
      if (!this->XorLevel())
        return false;
      this->Code.push_back(Or);
    }
    return true;
  }

  const std::string& Text;
  int NumberOfShapes;
  const std::vector<int>* Ids;
  std::vector<int>& Code;
  size_t Pos = 0;
  int Depth = 0;
  std::string Error;
};

} // namespace

//------------------------------------------------------------------------------
std::string ShapeList(const std::vector<int>& ids)
{
  if (ids.empty())
  {
    return "no shapes";
  }
  std::string s = std::to_string(ids.size()) + " shape(s): ";
  const size_t shown = std::min<size_t>(ids.size(), 8);
  for (size_t i = 0; i < shown; ++i)
  {
    s += (i ? ", S" : "S") + std::to_string(ids[i]);
  }
  if (shown < ids.size())
  {
    s += ", ..., S" + std::to_string(ids.back());
  }
  return s;
}

namespace
{

std::string Join(const std::vector<int>& ids, const char* op)
{
  std::string s;
  for (size_t i = 0; i < ids.size(); ++i)
  {
    s += (i ? std::string(" ") + op + " " : std::string()) + "S" + std::to_string(ids[i]);
  }
  return s;
}

std::vector<int> Range(int n)
{
  std::vector<int> ids(std::max(n, 0));
  for (int i = 0; i < n; ++i)
  {
    ids[i] = i;
  }
  return ids;
}

// "Sa op Sb", or the variadic form over every shape when a or b is -1.
std::string Variadic(int a, int b, const std::vector<int>& ids, const char* op)
{
  if (a < 0 || b < 0)
  {
    return Join(ids, op);
  }
  return "S" + std::to_string(a) + " " + op + " S" + std::to_string(b);
}

} // namespace

//------------------------------------------------------------------------------
bool BooleanExpression::Parse(const std::string& text, int numberOfShapes, std::string& error)
{
  return this->Compile(text, numberOfShapes, nullptr, error);
}

//------------------------------------------------------------------------------
bool BooleanExpression::Parse(const std::string& text,
  const std::vector<int>& shapeIds,
  std::string& error)
{
  return this->Compile(text, -1, &shapeIds, error);
}

//------------------------------------------------------------------------------
bool BooleanExpression::Compile(const std::string& text,
  int numberOfShapes,
  const std::vector<int>* shapeIds,
  std::string& error)
{
  Parser parser(text, numberOfShapes, shapeIds, this->Code);
  if (!parser.Run(error))
  {
    this->Code.clear();
    this->Shapes.clear();
    return false;
  }
  this->Shapes.clear();
  for (size_t i = 0; i < this->Code.size(); ++i)
  {
    if (this->Code[i] == Push)
    {
      this->Shapes.push_back(this->Code[++i]);
    }
  }
  std::sort(this->Shapes.begin(), this->Shapes.end());
  this->Shapes.erase(std::unique(this->Shapes.begin(), this->Shapes.end()), this->Shapes.end());
  return true;
}

//------------------------------------------------------------------------------
bool BooleanExpression::Evaluate(const std::vector<char>& inside) const
{
  std::vector<char>& stack = this->Stack;
  stack.clear();
  for (size_t i = 0; i < this->Code.size(); ++i)
  {
    const int op = this->Code[i];
    if (op == Push)
    {
      const int s = this->Code[++i];
      stack.push_back(s < static_cast<int>(inside.size()) ? inside[s] : 0);
      continue;
    }
    if (op == Not)
    {
      stack.back() = !stack.back();
      continue;
    }
    const char b = stack.back();
    stack.pop_back();
    char& a = stack.back();
    switch (op)
    {
      case And:
        a = a && b;
        break;
      case Or:
        a = a || b;
        break;
      case Xor:
        a = (a != 0) != (b != 0);
        break;
      case Minus:
        a = a && !b;
        break;
    }
  }
  return !stack.empty() && stack.back();
}

//------------------------------------------------------------------------------
std::string BooleanExpression::Union(int a, int b, int n)
{
  return Union(a, b, Range(n));
}
std::string BooleanExpression::Intersection(int a, int b, int n)
{
  return Intersection(a, b, Range(n));
}
std::string BooleanExpression::SymmetricDifference(int a, int b, int n)
{
  return SymmetricDifference(a, b, Range(n));
}
std::string BooleanExpression::Difference(int a, int b, int n)
{
  return Difference(a, b, Range(n));
}
std::string BooleanExpression::Union(int a, int b, const std::vector<int>& ids)
{
  return Variadic(a, b, ids, "|");
}
std::string BooleanExpression::Intersection(int a, int b, const std::vector<int>& ids)
{
  return Variadic(a, b, ids, "&");
}
std::string BooleanExpression::SymmetricDifference(int a, int b, const std::vector<int>& ids)
{
  return Variadic(a, b, ids, "^");
}
std::string BooleanExpression::Difference(int a, int b, const std::vector<int>& ids)
{
  if (a < 0 || b < 0)
  {
    if (ids.empty())
    {
      return "S0";
    }
    const int first = a < 0 ? ids.front() : a;
    std::vector<int> others;
    for (int id : ids)
    {
      if (id != first)
        others.push_back(id);
    }
    if (others.empty())
    {
      return "S" + std::to_string(first);
    }
    return "S" + std::to_string(first) + " - (" + Join(others, "|") + ")";
  }
  return "S" + std::to_string(a) + " - S" + std::to_string(b);
}

} // namespace boolsurf
