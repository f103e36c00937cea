#include "Selection/BoundarySampledCurves.h"

// GCC 12 reports a false "may be used uninitialized" inside Boost's edge iterator (its
// boost::optional end marker) wherever the max flow is instantiated.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>

#include <algorithm>
#include <map>
#include <queue>
#include <set>
#include <unordered_map>

namespace boolsurf
{
namespace
{

using GraphTraits = boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS>;

struct FlowEdge
{
  double Capacity = 0;
  double Residual = 0;
  GraphTraits::edge_descriptor Reverse;
};

using FlowGraph =
  boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS, boost::no_property, FlowEdge>;

/// Per patch, how the samples on it constrain the cut.
struct PatchSamples
{
  int Left = 0, Right = 0; ///< samples asking for the left / right cell inside
};

/// The (a, c, d) energy of BSC as a graph: vertex c is cell c, then source (inside) and sink.
class CutProblem
{
public:
  CutProblem(const BscInput& input, const std::vector<PatchSamples>& samples)
    : Input(input)
  {
    double lengths = 0, penalties = 0;
    for (const BscPatch& p : input.Patches)
    {
      lengths += IsSeparatingPatch(p) ? std::max(0.0, p.Length) : 0.0;
    }
    // A sample off the boundary costs more than all boundary length together, so the cut keeps
    // as many samples as it can before it minimizes length.
    this->Penalty = lengths + 1;
    for (const PatchSamples& s : samples)
    {
      penalties += this->Penalty * (s.Left + s.Right);
    }
    // Larger than any finite cut: every finite capacity together.
    this->Infinity = 4 * (penalties + 2 * lengths) + 1;

    // Terms are summed per cell (source and sink arcs) and per pair of cells once: many patches
    // separate the same two cells, so the graph is as small as the cell adjacency, and a cut
    // with forbidden patches only adds infinite capacity to their pairs. Pairs are numbered in
    // sorted order: the same input always builds the same graph.
    const int n = input.NumberOfCells;
    this->FromSource.assign(n, 0.0);
    this->ToSink.assign(n, 0.0);
    std::map<std::pair<int, int>, std::pair<double, double>> between; // (u < v) -> (uv, vu)
    auto addBetween = [&](int u, int v, double uv, double vu)
    {
      auto& c = u < v ? between[{ u, v }] : between[{ v, u }];
      c.first += u < v ? uv : vu;
      c.second += u < v ? vu : uv;
    };
    for (std::size_t i = 0; i < input.Patches.size(); ++i)
    {
      const BscPatch& p = input.Patches[i];
      if (!IsSeparatingPatch(p))
      {
        continue;
      }
      const double w = std::max(0.0, p.Length);
      const PatchSamples& s = samples[i];
      if (s.Left > 0 && s.Right > 0)
      {
        // Sampled both ways: the two sides must agree.
        addBetween(p.LeftCell, p.RightCell, this->Infinity, this->Infinity);
      }
      else if (s.Left + s.Right > 0)
      {
        // E(in, out) over (inside, outside) cells: E(1,0) = w, E(0,0) = E(1,1) = n * Penalty,
        // E(0,1) = infinite; as unary terms plus one infinite arc outside -> inside.
        const int inside = s.Left > 0 ? p.LeftCell : p.RightCell;
        const int outside = s.Left > 0 ? p.RightCell : p.LeftCell;
        const double keep = this->Penalty * (s.Left + s.Right) - w;
        this->FromSource[inside] += keep;
        this->ToSink[outside] += keep;
        addBetween(outside, inside, this->Infinity, 0);
      }
      else
      {
        addBetween(p.LeftCell, p.RightCell, w, w);
      }
    }
    std::map<std::pair<int, int>, int> pairIndex;
    for (const auto& [cells, caps] : between)
    {
      pairIndex.emplace(cells, static_cast<int>(this->Pairs.size()));
      this->Pairs.push_back({ cells.first, cells.second, caps.first, caps.second });
    }
    this->PairOf.assign(input.Patches.size(), -1);
    for (std::size_t i = 0; i < input.Patches.size(); ++i)
    {
      const BscPatch& p = input.Patches[i];
      if (IsSeparatingPatch(p))
      {
        this->PairOf[i] =
          pairIndex.at({ std::min(p.LeftCell, p.RightCell), std::max(p.LeftCell, p.RightCell) });
      }
    }
  }

  /// Minimum cut with the patches in `forbidden` (sorted) kept off the boundary: selected cells
  /// and the cut's energy.
  double Cut(const std::vector<int>& forbidden, std::vector<char>& selected) const
  {
    const int n = this->Input.NumberOfCells;
    FlowGraph g(n + 2);
    const int source = n, sink = n + 1;
    auto addPair = [&](int u, int v, double uv, double vu)
    {
      const auto e1 = boost::add_edge(u, v, g).first;
      const auto e2 = boost::add_edge(v, u, g).first;
      g[e1].Capacity = uv;
      g[e2].Capacity = vu;
      g[e1].Reverse = e2;
      g[e2].Reverse = e1;
    };
    for (int c = 0; c < n; ++c)
    {
      if (this->FromSource[c] > 0)
      {
        addPair(source, c, this->FromSource[c], 0);
      }
      if (this->ToSink[c] > 0)
      {
        addPair(c, sink, this->ToSink[c], 0);
      }
    }
    std::vector<char> merged(this->Pairs.size(), 0);
    for (int f : forbidden)
    {
      if (this->PairOf[f] >= 0)
      {
        merged[this->PairOf[f]] = 1;
      }
    }
    for (std::size_t k = 0; k < this->Pairs.size(); ++k)
    {
      const PairTerm& t = this->Pairs[k];
      addPair(t.U, t.V, merged[k] ? this->Infinity : t.UV, merged[k] ? this->Infinity : t.VU);
    }
    std::vector<boost::default_color_type> color(n + 2);
    std::vector<GraphTraits::edge_descriptor> predecessor(n + 2);
    std::vector<long> distance(n + 2);
    const auto index = boost::get(boost::vertex_index, g);
    const double flow = boost::boykov_kolmogorov_max_flow(g,
      boost::get(&FlowEdge::Capacity, g),
      boost::get(&FlowEdge::Residual, g),
      boost::get(&FlowEdge::Reverse, g),
      boost::make_iterator_property_map(predecessor.begin(), index),
      boost::make_iterator_property_map(color.begin(), index),
      boost::make_iterator_property_map(distance.begin(), index),
      index,
      source,
      sink);
    // The source tree at the end is the set reachable from the source in the residual graph:
    // the smallest minimum-cut side (free cells stay outside).
    selected.assign(n, 0);
    for (int c = 0; c < n; ++c)
    {
      selected[c] = color[c] == boost::color_traits<boost::default_color_type>::black() ? 1 : 0;
    }
    return flow;
  }

private:
  struct PairTerm
  {
    int U, V;
    double UV, VU;
  };
  const BscInput& Input;
  double Penalty = 1, Infinity = 1;
  std::vector<double> FromSource, ToSink;
  std::vector<PairTerm> Pairs;
  std::vector<int> PairOf; ///< per patch, its pair of cells (-1: separates nothing)
};

bool OnBoundary(const BscPatch& p, const std::vector<char>& selected)
{
  return IsSeparatingPatch(p) && selected[p.LeftCell] != selected[p.RightCell];
}

/// The connected pieces (patches of one curve sharing end points) of a region's boundary that
/// hold no sample. The patches' neighbours along their curves are found once; each query walks
/// only the boundary.
class PieceFinder
{
public:
  PieceFinder(const BscInput& in, const std::vector<PatchSamples>& samples)
    : Input(in)
    , Samples(samples)
  {
    const int np = static_cast<int>(in.Patches.size());
    std::unordered_map<long long, std::vector<int>> atEnd; // (curve, point) -> patches
    for (int i = 0; i < np; ++i)
    {
      const BscPatch& p = in.Patches[i];
      if (!IsSeparatingPatch(p))
      {
        continue;
      }
      for (int end : { p.FirstPoint, p.LastPoint })
      {
        atEnd[(static_cast<long long>(p.Curve) << 32) ^ static_cast<unsigned>(end)].push_back(i);
      }
    }
    std::vector<std::vector<int>> neighbours(np);
    for (const auto& entry : atEnd)
    {
      for (int i : entry.second)
      {
        for (int j : entry.second)
        {
          if (i != j)
          {
            neighbours[i].push_back(j);
          }
        }
      }
    }
    this->Offset.assign(np + 1, 0);
    for (int i = 0; i < np; ++i)
    {
      std::sort(neighbours[i].begin(), neighbours[i].end());
      this->Offset[i + 1] = this->Offset[i] + static_cast<int>(neighbours[i].size());
      this->Neighbours.insert(this->Neighbours.end(), neighbours[i].begin(), neighbours[i].end());
    }
  }

  /// Unsampled pieces of the boundary of `selected`, each as sorted patch ids, ordered by their
  /// lowest patch.
  std::vector<std::vector<int>> Unsampled(const std::vector<char>& selected) const
  {
    const int np = static_cast<int>(this->Input.Patches.size());
    std::vector<char> visited(np, 0);
    std::vector<std::vector<int>> pieces;
    std::vector<int> stack, piece;
    for (int i = 0; i < np; ++i)
    {
      if (visited[i] || !OnBoundary(this->Input.Patches[i], selected))
      {
        continue;
      }
      piece.clear();
      bool sampled = false;
      visited[i] = 1;
      stack.assign(1, i);
      while (!stack.empty())
      {
        const int p = stack.back();
        stack.pop_back();
        piece.push_back(p);
        sampled = sampled || this->Samples[p].Left + this->Samples[p].Right > 0;
        for (int k = this->Offset[p]; k < this->Offset[p + 1]; ++k)
        {
          const int q = this->Neighbours[k];
          if (!visited[q] && OnBoundary(this->Input.Patches[q], selected))
          {
            visited[q] = 1;
            stack.push_back(q);
          }
        }
      }
      if (!sampled)
      {
        std::sort(piece.begin(), piece.end());
        pieces.push_back(piece);
      }
    }
    return pieces;
  }

private:
  const BscInput& Input;
  const std::vector<PatchSamples>& Samples;
  std::vector<int> Offset, Neighbours; ///< patches of the same curve sharing an end point
};

std::vector<int> Merged(const std::vector<int>& a, const std::vector<int>& b)
{
  std::vector<int> out;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
  return out;
}

struct SearchState
{
  double Energy = 0;
  int Order = 0;
  std::vector<int> Forbidden;
  std::vector<char> Selected;
};

struct WorseState
{
  bool operator()(const SearchState& a, const SearchState& b) const
  {
    if (a.Energy != b.Energy)
    {
      return a.Energy > b.Energy;
    }
    if (a.Forbidden.size() != b.Forbidden.size())
    {
      return a.Forbidden.size() > b.Forbidden.size();
    }
    return a.Order > b.Order;
  }
};

} // namespace

//------------------------------------------------------------------------------
bool SelectBoundarySampledCells(const BscInput& in, BscResult& result, std::string& error)
{
  result = BscResult();
  const int np = static_cast<int>(in.Patches.size());
  for (const BscPatch& p : in.Patches)
  {
    if (p.LeftCell >= in.NumberOfCells || p.RightCell >= in.NumberOfCells)
    {
      error = "a patch names cell " + std::to_string(std::max(p.LeftCell, p.RightCell)) +
        " of an arrangement of " + std::to_string(in.NumberOfCells) + " cells";
      return false;
    }
  }
  std::vector<PatchSamples> samples(np);
  for (std::size_t k = 0; k < in.Samples.size(); ++k)
  {
    const BscSample& s = in.Samples[k];
    if (s.Patch < 0 || s.Patch >= np)
    {
      error = "sample " + std::to_string(k) + " names patch " + std::to_string(s.Patch) + " of " +
        std::to_string(np);
      return false;
    }
    if (IsSeparatingPatch(in.Patches[s.Patch]))
    {
      (s.LeftInside ? samples[s.Patch].Left : samples[s.Patch].Right)++;
    }
  }

  const CutProblem problem(in, samples);
  const PieceFinder pieceFinder(in, samples);
  std::priority_queue<SearchState, std::vector<SearchState>, WorseState> open;
  std::set<std::vector<int>> seen;
  int order = 0;
  auto aborted = [&] { return in.Abort && in.Abort(); };
  auto push = [&](std::vector<int> forbidden)
  {
    if (!seen.insert(forbidden).second)
    {
      return;
    }
    SearchState s;
    s.Energy = problem.Cut(forbidden, s.Selected);
    s.Order = order++;
    s.Forbidden = std::move(forbidden);
    ++result.Cuts;
    open.push(std::move(s));
  };
  push({});
  SearchState best;
  while (true)
  {
    best = open.top();
    open.pop();
    std::vector<std::vector<int>> pieces = pieceFinder.Unsampled(best.Selected);
    if (pieces.empty())
    {
      break;
    }
    if (result.Cuts >= in.MaxSearchStates)
    {
      // Greedy end: forbid every unsampled piece at once until none is left. Each round
      // forbids at least one more patch, so this ends.
      result.Greedy = true;
      while (!pieces.empty())
      {
        for (const std::vector<int>& piece : pieces)
        {
          best.Forbidden = Merged(best.Forbidden, piece);
        }
        best.Energy = problem.Cut(best.Forbidden, best.Selected);
        ++result.Cuts;
        pieces = pieceFinder.Unsampled(best.Selected);
      }
      break;
    }
    if (aborted())
    {
      error = "aborted";
      return false;
    }
    for (const std::vector<int>& piece : pieces)
    {
      push(Merged(best.Forbidden, piece));
    }
  }

  result.Selected = std::move(best.Selected);
  result.ForbiddenPatches = std::move(best.Forbidden);
  result.SampleOnBoundary.assign(in.Samples.size(), 0);
  for (std::size_t k = 0; k < in.Samples.size(); ++k)
  {
    const BscSample& s = in.Samples[k];
    const BscPatch& p = in.Patches[s.Patch];
    const int inside = s.LeftInside ? p.LeftCell : p.RightCell;
    result.SampleOnBoundary[k] = OnBoundary(p, result.Selected) && result.Selected[inside];
  }
  for (const BscPatch& p : in.Patches)
  {
    result.BoundaryLength += OnBoundary(p, result.Selected) ? p.Length : 0.0;
  }
  return true;
}

} // namespace boolsurf
