#include "Selection/BooleanExpression.h"

#include <algorithm>
#include <cctype>

namespace boolsurf
{
namespace
{

// Recursive-descent parser emitting postfix code.
class Parser
{
public:
  Parser(const std::string& text, int numberOfShapes, std::vector<int>& code)
    : Text(text)
    , NumberOfShapes(numberOfShapes)
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
      error = this->Message("unexpected '" + std::string(1, this->Text[this->Pos]) +
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
    return "expression \"" + this->Text + "\", position " + std::to_string(this->Pos + 1) + ": " +
      what;
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

  bool Primary()
  {
    this->SkipSpace();
    if (this->Pos >= this->Text.size())
    {
      return this->Fail("unexpected end (expected a shape S<id>, '~' or '(')");
    }
    if (this->Accept('~'))
    {
      if (!this->Primary())
        return false;
      this->Code.push_back(Not);
      return true;
    }
    if (this->Accept('('))
    {
      if (!this->Expr())
        return false;
      if (!this->Accept(')'))
        return this->Fail("missing ')'");
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
      if (this->Pos - start > 9)
      {
        return this->Fail("shape id too large");
      }
      const int id = std::stoi(this->Text.substr(start, this->Pos - start));
      if (this->NumberOfShapes >= 0 && id >= this->NumberOfShapes)
      {
        this->Pos = start - 1;
        return this->Fail("unknown shape S" + std::to_string(id) + " (the input has " +
          std::to_string(this->NumberOfShapes) + " shape(s): S0..S" +
          std::to_string(this->NumberOfShapes - 1) + ")");
      }
      this->Code.push_back(Push);
      this->Code.push_back(id);
      return true;
    }
    return this->Fail(
      "unexpected '" + std::string(1, c) + "' (expected a shape S<id>, '~' or '(')");
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
  std::vector<int>& Code;
  size_t Pos = 0;
  std::string Error;
};

std::string Join(const std::vector<int>& ids, const char* op)
{
  std::string s;
  for (size_t i = 0; i < ids.size(); ++i)
  {
    s += (i ? std::string(" ") + op + " " : std::string()) + "S" + std::to_string(ids[i]);
  }
  return s;
}

std::vector<int> AllShapes(int n, int skip = -1)
{
  std::vector<int> ids;
  for (int i = 0; i < n; ++i)
  {
    if (i != skip)
      ids.push_back(i);
  }
  return ids;
}

// "Sa op Sb", or the variadic form over every shape when a or b is -1.
std::string Variadic(int a, int b, int n, const char* op)
{
  if (a < 0 || b < 0)
  {
    return Join(AllShapes(n), op);
  }
  return "S" + std::to_string(a) + " " + op + " S" + std::to_string(b);
}

} // namespace

//------------------------------------------------------------------------------
bool BooleanExpression::Parse(const std::string& text, int numberOfShapes, std::string& error)
{
  Parser parser(text, numberOfShapes, this->Code);
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
  return Variadic(a, b, n, "|");
}
std::string BooleanExpression::Intersection(int a, int b, int n)
{
  return Variadic(a, b, n, "&");
}
std::string BooleanExpression::SymmetricDifference(int a, int b, int n)
{
  return Variadic(a, b, n, "^");
}
std::string BooleanExpression::Difference(int a, int b, int n)
{
  if (a < 0 || b < 0)
  {
    const int first = a < 0 ? 0 : a;
    const std::vector<int> others = AllShapes(n, first);
    if (others.empty())
    {
      return "S" + std::to_string(first);
    }
    return "S" + std::to_string(first) + " - (" + Join(others, "|") + ")";
  }
  return "S" + std::to_string(a) + " - S" + std::to_string(b);
}

} // namespace boolsurf
