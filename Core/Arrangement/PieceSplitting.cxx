#include "Arrangement/PieceSplitting.h"

#include "Arrangement/Predicates.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace boolsurf
{
namespace
{

struct Piece
{
  int Chain;
  int Index; ///< the piece runs from Chains[Chain][Index] to Chains[Chain][Index + 1]
};

struct Insertion
{
  int Chain;
  int Index;
  double S; ///< parameter along the piece
  int Point;
};

} // namespace

//------------------------------------------------------------------------------
bool SplitPiecesAtCrossings(LocalArrangement& arr, double snapDistance, std::string& problem)
{
  const std::size_t firstPoints = arr.Points.size();
  const std::size_t pointLimit = 16 * firstPoints + 4096;
  constexpr int MaximumRounds = 64;
  const auto p = [&arr](int i) { return arr.Points[i].P; };
  std::vector<Piece> pieces;
  std::vector<Insertion> insertions;
  for (int round = 0; round < MaximumRounds; ++round)
  {
    pieces.clear();
    for (int c = 0; c < static_cast<int>(arr.Chains.size()); ++c)
    {
      const std::vector<int>& chain = arr.Chains[c];
      for (int i = 0; i + 1 < static_cast<int>(chain.size()); ++i)
      {
        const Vec2 a = p(chain[i]), b = p(chain[i + 1]);
        if (a.x != b.x || a.y != b.y)
        {
          pieces.push_back({ c, i });
        }
      }
    }
    insertions.clear();
    const auto ends = [&arr](const Piece& piece)
    {
      const std::vector<int>& chain = arr.Chains[piece.Chain];
      return std::array<int, 2>{ chain[piece.Index], chain[piece.Index + 1] };
    };
    // A point strictly inside piece `piece` (exactly on its line) becomes one of its points.
    const auto insertIfInside = [&](const Piece& piece, int q)
    {
      const std::array<int, 2> e = ends(piece);
      const Vec2 a = p(e[0]), b = p(e[1]), x = p(q);
      if (q != e[0] && q != e[1] && !(x.x == a.x && x.y == a.y) && !(x.x == b.x && x.y == b.y) &&
        Orient2dSign(a, b, x) == 0 && StrictlyBetween(a, b, x))
      {
        insertions.push_back({ piece.Chain, piece.Index, ParameterAlong(a, b, x), q });
        return true;
      }
      return false;
    };
    for (std::size_t i = 0; i < pieces.size(); ++i)
    {
      const std::array<int, 2> e = ends(pieces[i]);
      for (std::size_t j = i + 1; j < pieces.size(); ++j)
      {
        const std::array<int, 2> f = ends(pieces[j]);
        const Vec2 a = p(e[0]), b = p(e[1]), c = p(f[0]), d = p(f[1]);
        // Quick rejection by bounding boxes (exact: coordinates are compared as they are).
        if (std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
          std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y))
        {
          continue;
        }
        bool touched = false;
        for (const int q : f)
        {
          touched = insertIfInside(pieces[i], q) || touched;
        }
        for (const int q : e)
        {
          touched = insertIfInside(pieces[j], q) || touched;
        }
        if (touched)
        {
          continue;
        }
        const int o1 = Orient2dSign(a, b, c), o2 = Orient2dSign(a, b, d);
        const int o3 = Orient2dSign(c, d, a), o4 = Orient2dSign(c, d, b);
        if (o1 == 0 || o2 == 0 || o3 == 0 || o4 == 0 || o1 == o2 || o3 == o4)
        {
          continue; // no proper crossing (touching ends are shared points or handled above)
        }
        // A proper crossing: within rounding of an end of either piece, that end; else a new
        // point on both.
        const double da = Orient2d(c, d, a), db = Orient2d(c, d, b);
        const double s = da / (da - db);
        const Vec2 x = a + s * (b - a);
        int at = -1;
        double best = snapDistance;
        for (const int q : { e[0], e[1], f[0], f[1] })
        {
          const double dist = Length(p(q) - x);
          if (dist <= best)
          {
            best = dist;
            at = q;
          }
        }
        if (at < 0)
        {
          if (arr.Points.size() >= pointLimit)
          {
            problem = "splitting crossing pieces adds too many points";
            return false;
          }
          at = static_cast<int>(arr.Points.size());
          arr.Points.push_back({ x, -1, -1 });
        }
        if (at != e[0] && at != e[1])
        {
          insertions.push_back(
            { pieces[i].Chain, pieces[i].Index, ParameterAlong(a, b, p(at)), at });
        }
        if (at != f[0] && at != f[1])
        {
          insertions.push_back(
            { pieces[j].Chain, pieces[j].Index, ParameterAlong(c, d, p(at)), at });
        }
      }
    }
    if (insertions.empty())
    {
      return true;
    }
    // Apply the round's insertions chain by chain, each piece's in order along it.
    std::sort(insertions.begin(),
      insertions.end(),
      [](const Insertion& u, const Insertion& v)
      {
        return u.Chain != v.Chain ? u.Chain < v.Chain
                                  : (u.Index != v.Index ? u.Index < v.Index : u.S < v.S);
      });
    std::vector<int> rebuilt;
    for (std::size_t k = 0; k < insertions.size();)
    {
      const int c = insertions[k].Chain;
      std::vector<int>& chain = arr.Chains[c];
      rebuilt.clear();
      for (int i = 0; i < static_cast<int>(chain.size()); ++i)
      {
        rebuilt.push_back(chain[i]);
        for (; k < insertions.size() && insertions[k].Chain == c && insertions[k].Index == i; ++k)
        {
          if (insertions[k].Point != rebuilt.back())
          {
            rebuilt.push_back(insertions[k].Point);
          }
        }
      }
      chain.swap(rebuilt);
    }
  }
  problem = "splitting crossing pieces does not settle";
  return false;
}

} // namespace boolsurf
