// libFuzzer target: the Boolean expression parser (Core/Selection/BooleanExpression).
//
// Input: one byte choosing how shapes are named (by a count, by an id list, or any id), a
// few bytes for the shapes, then the expression text. Every text must parse or give a
// message; a parsed expression must read only known shapes (sorted, no repeats) and evaluate
// without touching memory it does not own. The named operations' expressions, built from
// decoded shape ids, must always parse (they are what the filters send).
#include "FuzzSupport.h"
#include "Selection/BooleanExpression.h"

#include <algorithm>
#include <string>
#include <vector>

namespace
{
using namespace boolsurf;

void CheckParsed(const BooleanExpression& e, int numberOfShapes, const std::string& text)
{
  const std::vector<int>& shapes = e.GetShapes();
  BOOLSURF_FUZZ_CHECK(std::is_sorted(shapes.begin(), shapes.end()), text);
  BOOLSURF_FUZZ_CHECK(
    std::adjacent_find(shapes.begin(), shapes.end()) == shapes.end(), "repeats in " + text);
  for (int s : shapes)
  {
    BOOLSURF_FUZZ_CHECK(s >= 0 && (numberOfShapes < 0 || s < numberOfShapes),
      "shape " + std::to_string(s) + " in " + text);
  }
}

/// Evaluates on a few inside/outside patterns over the shapes the expression reads; the
/// negation must give the opposite value.
void EvaluateSome(const BooleanExpression& e, const BooleanExpression* negation, int numberOfShapes)
{
  if (numberOfShapes < 0)
  {
    return; // indices are shape ids: inside[] would need max id + 1 entries
  }
  std::vector<char> inside(static_cast<std::size_t>(numberOfShapes), 0);
  for (unsigned pattern = 0; pattern < 8; ++pattern)
  {
    for (int s = 0; s < numberOfShapes; ++s)
    {
      inside[s] = static_cast<char>(((pattern * 0x9e37u) >> (s % 16)) & 1u);
    }
    const bool value = e.Evaluate(inside);
    if (negation)
    {
      BOOLSURF_FUZZ_CHECK(negation->Evaluate(inside) == !value, "~(e) differs from !e");
    }
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  fuzz::ByteReader in(data, size);
  const std::uint8_t mode = in.Byte();
  const int count = in.Byte() % 9; // 0..8 shapes
  std::vector<int> ids;
  for (int i = 0; i < count; ++i)
  {
    // Small, large and extreme ids (the parser reads digits into an int).
    const std::uint32_t raw = in.U32();
    ids.push_back(static_cast<int>(mode & 0x80 ? raw & 0x7fffffffu : raw % 12));
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  const int a = static_cast<int>(in.Byte()) - 1; // -1: "all shapes"
  const int b = static_cast<int>(in.Byte()) - 1;
  const std::string text = in.Rest();

  BooleanExpression e, negation;
  std::string error;
  switch (mode % 3)
  {
    case 0: // shapes 0..count-1
      if (e.Parse(text, count, error))
      {
        CheckParsed(e, count, text);
        std::string negationError;
        const bool negated = negation.Parse("~(" + text + ")", count, negationError);
        // "~(" + text + ")" can fail only by nesting one level deeper than allowed.
        BOOLSURF_FUZZ_CHECK(
          negated || negationError.find("nested") != std::string::npos, negationError);
        EvaluateSome(e, negated ? &negation : nullptr, count);
      }
      else
      {
        BOOLSURF_FUZZ_CHECK(!error.empty(), "a failed parse must say why");
      }
      // Named operations over shape indices a, b (in range or -1) always parse.
      if (count > 0)
      {
        const int sa = a < 0 ? -1 : a % count, sb = b < 0 ? -1 : b % count;
        for (const std::string& op : { BooleanExpression::Union(sa, sb, count),
               BooleanExpression::Intersection(sa, sb, count),
               BooleanExpression::Difference(sa, sb, count),
               BooleanExpression::SymmetricDifference(sa, sb, count) })
        {
          BooleanExpression named;
          BOOLSURF_FUZZ_CHECK(named.Parse(op, count, error), op + ": " + error);
          CheckParsed(named, count, op);
        }
      }
      break;
    case 1: // shapes named by sparse ids
      if (e.Parse(text, ids, error))
      {
        CheckParsed(e, static_cast<int>(ids.size()), text);
        EvaluateSome(e, nullptr, static_cast<int>(ids.size()));
      }
      else
      {
        BOOLSURF_FUZZ_CHECK(!error.empty(), "a failed parse must say why");
      }
      if (!ids.empty())
      {
        const int n = static_cast<int>(ids.size());
        const int sa = a < 0 ? -1 : ids[a % n], sb = b < 0 ? -1 : ids[b % n];
        for (const std::string& op : { BooleanExpression::Union(sa, sb, ids),
               BooleanExpression::Intersection(sa, sb, ids),
               BooleanExpression::Difference(sa, sb, ids),
               BooleanExpression::SymmetricDifference(sa, sb, ids) })
        {
          BooleanExpression named;
          BOOLSURF_FUZZ_CHECK(named.Parse(op, ids, error), op + ": " + error);
          CheckParsed(named, n, op);
        }
      }
      break;
    default: // any id
      if (e.Parse(text, -1, error))
      {
        CheckParsed(e, -1, text);
      }
      else
      {
        BOOLSURF_FUZZ_CHECK(!error.empty(), "a failed parse must say why");
      }
      break;
  }
  return 0;
}
