#include "Selection/RegionBoundary.h"

#include "Arrangement/CellPartition.h"

#include <unordered_map>

namespace boolsurf
{

//------------------------------------------------------------------------------
template <class PatchType>
std::vector<BoundaryPolyline> ExtractRegionBoundary(const std::vector<PatchType>& patches,
  const std::vector<char>& selected)
{
  struct Piece
  {
    int Patch;
    bool Reversed;
    int First, Last;
  };
  std::vector<Piece> pieces;
  auto isSelected = [&](int cell)
  { return cell >= 0 && cell < static_cast<int>(selected.size()) && selected[cell] != 0; };
  for (int p = 0; p < static_cast<int>(patches.size()); ++p)
  {
    const PatchType& patch = patches[p];
    const bool left = isSelected(patch.LeftCell), right = isSelected(patch.RightCell);
    if (left == right || patch.Points.size() < 2)
    {
      continue;
    }
    const bool reversed = right; // the region must be on the left of the walk
    const int first = reversed ? patch.Points.back() : patch.Points.front();
    const int last = reversed ? patch.Points.front() : patch.Points.back();
    pieces.push_back({ p, reversed, first, last });
  }
  // Pieces starting at each point, the last one first. At a point where several boundary
  // pieces meet (curves crossing at a corner of the region) they are taken in that order (the
  // one the multimap used here before gave, so loops are grouped as they were), which still
  // gives closed loops since every point has as many pieces in as out. Each point keeps a
  // cursor past its used pieces: where hundreds of pieces meet at one point (drawings whose
  // curves run along each other), looking each next one up from the start was quadratic.
  std::unordered_map<int, int> groupOf; // point -> its group
  std::vector<int> groupSize;
  for (const Piece& piece : pieces)
  {
    const auto [it, added] = groupOf.emplace(piece.First, static_cast<int>(groupSize.size()));
    if (added)
    {
      groupSize.push_back(0);
    }
    ++groupSize[it->second];
  }
  std::vector<int> groupStart(groupSize.size() + 1, 0);
  for (std::size_t g = 0; g < groupSize.size(); ++g)
  {
    groupStart[g + 1] = groupStart[g] + groupSize[g];
  }
  std::vector<int> cursor(groupStart.begin(), groupStart.end() - 1);
  std::vector<int> startingAt(pieces.size());
  for (int i = static_cast<int>(pieces.size()) - 1; i >= 0; --i)
  {
    startingAt[cursor[groupOf[pieces[i].First]]++] = i;
  }
  cursor.assign(groupStart.begin(), groupStart.end() - 1);
  std::vector<char> used(pieces.size(), 0);
  std::vector<BoundaryPolyline> result;
  auto append = [&](BoundaryPolyline& line, const Piece& piece)
  {
    const std::vector<int>& pts = patches[piece.Patch].Points;
    const int n = static_cast<int>(pts.size());
    // Skip the first point of every piece after the first: it is the previous one's last.
    for (int k = line.Points.empty() ? 0 : 1; k < n; ++k)
    {
      line.Points.push_back(piece.Reversed ? pts[n - 1 - k] : pts[k]);
    }
    line.Patches.push_back(piece.Patch);
    line.Reversed.push_back(piece.Reversed);
  };
  auto takeNext = [&](int point)
  {
    const auto found = groupOf.find(point);
    if (found == groupOf.end())
    {
      return -1;
    }
    const int g = found->second;
    while (cursor[g] < groupStart[g + 1] && used[startingAt[cursor[g]]])
    {
      ++cursor[g];
    }
    if (cursor[g] == groupStart[g + 1])
    {
      return -1;
    }
    const int next = startingAt[cursor[g]++];
    used[next] = 1;
    return next;
  };
  for (int i = 0; i < static_cast<int>(pieces.size()); ++i)
  {
    if (used[i])
    {
      continue;
    }
    used[i] = 1;
    BoundaryPolyline line;
    append(line, pieces[i]);
    int end = pieces[i].Last;
    while (end != pieces[i].First)
    {
      const int next = takeNext(end);
      if (next < 0)
      {
        break;
      }
      append(line, pieces[next]);
      end = pieces[next].Last;
    }
    line.Closed = end == pieces[i].First;
    if (line.Closed)
    {
      line.Points.pop_back(); // the loop came back to its first point
    }
    result.push_back(std::move(line));
  }
  return result;
}

// The patch types the project passes: read back from field data, or straight from the Core
// arrangement (the one-step filter, without copying them).
template std::vector<BoundaryPolyline> ExtractRegionBoundary(const std::vector<BoundaryPatch>&,
  const std::vector<char>&);
template std::vector<BoundaryPolyline> ExtractRegionBoundary(const std::vector<ArrangementPatch>&,
  const std::vector<char>&);

} // namespace boolsurf
