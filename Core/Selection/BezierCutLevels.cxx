#include "Selection/BezierCutLevels.h"

#include "Geodesic/GeodesicBezier.h"
#include "Geodesic/SlotTasks.h"

#include <algorithm>

namespace boolsurf
{
namespace
{
/// A part of a job's segment still to cut at the cuts [First, Last).
struct Part
{
  std::size_t Job;
  std::array<CanonicalPoint, 4> Polygon;
  double From, To;
  const double* First;
  const double* Last;
};

/// Whether part (from, to) comes before (from2, to2) in the recursion's order: a part before
/// the parts inside it, and a part before those on its right.
bool SplitsFirst(double from, double to, double from2, double to2)
{
  return from < from2 || (from == from2 && to > to2);
}
} // namespace

//------------------------------------------------------------------------------
// Cutting one after the other, each cut splitting the rest of the segment, made every split's
// six legs about as long as the rest: curves that run along each other cross hundreds of
// times within one segment, and those long window searches cost seconds per edit (10k
// patches: 2.4 s). Halving shortens the legs at every level, so all but the first few splits
// work on short legs; it also takes each piece through log2(k) splits instead of up to k, so
// rounding accumulates less.
bool CutSegmentRecursively(GeodesicPathSolver& solver,
  const std::array<CanonicalPoint, 4>& polygon,
  double from,
  double to,
  const double* first,
  const double* last,
  std::vector<BezierCutPiece>& pieces,
  std::string& error)
{
  if (first == last)
  {
    pieces.push_back({ from, to, polygon });
    return true;
  }
  const double* middle = first + (last - first) / 2;
  std::array<CanonicalPoint, 4> left, right;
  if (!SplitGeodesicBezier(solver, polygon, (*middle - from) / (to - from), left, right, error) ||
    !CutSegmentRecursively(solver, left, from, *middle, first, middle, pieces, error))
  {
    return false;
  }
  return CutSegmentRecursively(solver, right, *middle, to, middle + 1, last, pieces, error);
}

//------------------------------------------------------------------------------
void CutSegmentsByLevels(const std::vector<GeodesicPathSolver*>& solvers,
  const std::vector<BezierCutJob>& jobs,
  std::vector<std::vector<BezierCutPiece>>& pieces,
  std::vector<std::string>& errors,
  std::vector<char>& ok)
{
  const std::size_t n = jobs.size();
  pieces.assign(n, {});
  errors.assign(n, std::string());
  ok.assign(n, 1);
  // Where each job's first failure (in the recursion's order) lies.
  std::vector<std::array<double, 2>> failedAt(n, { 0.0, 0.0 });
  std::vector<Part> level;
  for (std::size_t j = 0; j < n; ++j)
  {
    const std::vector<double>& at = *jobs[j].At;
    level.push_back({ j, *jobs[j].Whole, 0.0, 1.0, at.data(), at.data() + at.size() });
  }
  std::vector<Part> splits, next;
  std::vector<std::array<CanonicalPoint, 4>> left, right;
  std::vector<std::string> messages;
  std::vector<char> split;
  while (!level.empty())
  {
    splits.clear();
    for (Part& part : level)
    {
      if (part.First == part.Last)
      {
        pieces[part.Job].push_back({ part.From, part.To, part.Polygon });
      }
      else
      {
        splits.push_back(std::move(part));
      }
    }
    const std::size_t count = splits.size();
    left.assign(count, {});
    right.assign(count, {});
    messages.assign(count, std::string());
    split.assign(count, 0);
    RunTasksBySlot(static_cast<int>(solvers.size()),
      count,
      [&](int slot, std::size_t i)
      {
        const Part& part = splits[i];
        const double* middle = part.First + (part.Last - part.First) / 2;
        split[i] = SplitGeodesicBezier(*solvers[slot],
          part.Polygon,
          (*middle - part.From) / (part.To - part.From),
          left[i],
          right[i],
          messages[i]);
      });
    next.clear();
    for (std::size_t i = 0; i < count; ++i)
    {
      const Part& part = splits[i];
      if (!split[i])
      {
        std::array<double, 2>& at = failedAt[part.Job];
        if (ok[part.Job] || SplitsFirst(part.From, part.To, at[0], at[1]))
        {
          ok[part.Job] = 0;
          errors[part.Job] = messages[i];
          at = { part.From, part.To };
        }
        continue;
      }
      const std::array<double, 2>& failure = failedAt[part.Job];
      if (!ok[part.Job] && SplitsFirst(failure[0], failure[1], part.From, part.To))
      {
        continue; // the recursion would have stopped before this part
      }
      const double* middle = part.First + (part.Last - part.First) / 2;
      next.push_back({ part.Job, left[i], part.From, *middle, part.First, middle });
      next.push_back({ part.Job, right[i], *middle, part.To, middle + 1, part.Last });
    }
    level.swap(next);
  }
  // The recursion's order: by parameter (the cuts are distinct, so are the pieces' starts).
  for (std::vector<BezierCutPiece>& p : pieces)
  {
    std::sort(p.begin(),
      p.end(),
      [](const BezierCutPiece& a, const BezierCutPiece& b) { return a.A < b.A; });
  }
}

} // namespace boolsurf
