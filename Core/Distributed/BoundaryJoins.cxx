#include "Distributed/BoundaryJoins.h"

#include <algorithm>
#include <map>

namespace boolsurf
{
namespace
{

std::string EdgeName(std::uint64_t edge)
{
  return "(" + std::to_string(edge >> 32) + ", " + std::to_string(edge & 0xffffffffu) + ")";
}

// A boundary sub-segment's sides, as given.
struct SubSegmentSides
{
  PieceCellRef Side[2];
  bool Forward[2] = { false, false };
  int Count = 0, Sides = 0;
  bool Blocked = false;
};

using SidesMap = std::map<std::pair<std::uint64_t, int>, SubSegmentSides>;

bool CollectSides(const std::vector<int>& pieceIds,
  const std::vector<const PieceSummary*>& pieces,
  SidesMap& sides,
  std::string& error)
{
  for (size_t i = 0; i < pieces.size(); ++i)
  {
    for (const BoundarySubSegment& b : pieces[i]->Boundary)
    {
      SubSegmentSides& s = sides[{ b.Edge, b.Index }];
      if (s.Sides == 2 || (s.Sides == 1 && (s.Count != b.Count || s.Blocked != b.Blocked)))
      {
        error = "pieces disagree on edge " + EdgeName(b.Edge) + " (piece " +
          std::to_string(pieceIds[i]) +
          "): " + (s.Sides == 2 ? "more than two sides" : "different sub-segments");
        return false;
      }
      s.Side[s.Sides] = { pieceIds[i], b.Cell };
      s.Forward[s.Sides] = b.Forward;
      s.Count = b.Count;
      s.Blocked = b.Blocked;
      ++s.Sides;
    }
  }
  return true;
}

bool Reports(const SubSegmentSides& s, int focus)
{
  return focus < 0 || std::min(s.Side[0].Piece, s.Side[1].Piece) == focus;
}

} // namespace

//------------------------------------------------------------------------------
std::size_t BoundaryJoins::GetBytes() const
{
  std::size_t bytes = this->Joins.size() * sizeof(this->Joins[0]);
  for (const BoundaryCrossing& c : this->Crossings)
  {
    bytes += 2 * sizeof(PieceCellRef) + c.Delta.size() * sizeof(std::pair<int, int>);
  }
  return bytes;
}

//------------------------------------------------------------------------------
bool JoinPieceBoundaries(const std::vector<int>& pieceIds,
  const std::vector<const PieceSummary*>& pieces,
  int focus,
  BoundaryJoins& out,
  std::string& error)
{
  SidesMap sides;
  if (!CollectSides(pieceIds, pieces, sides, error))
  {
    return false;
  }
  std::vector<std::pair<PieceCellRef, PieceCellRef>> joins;
  for (const auto& entry : sides)
  {
    const SubSegmentSides& s = entry.second;
    if (s.Sides != 2)
    {
      if (focus < 0 || s.Side[0].Piece == focus)
      {
        error = "edge " + EdgeName(entry.first.first) + " of piece " +
          std::to_string(s.Side[0].Piece) +
          " has one side only: a piece lacks its ring of ghost triangles";
        return false;
      }
      continue;
    }
    if (!s.Blocked && Reports(s, focus))
    {
      joins.push_back(std::minmax(s.Side[0], s.Side[1]));
    }
  }
  std::sort(joins.begin(), joins.end());
  joins.erase(std::unique(joins.begin(), joins.end()), joins.end());
  out.Joins.insert(out.Joins.end(), joins.begin(), joins.end());
  // Curve steps along the boundary, grouped by sub-segment: a step running the edge upwards
  // crosses from the side whose triangle runs it downwards to the other (a triangle lies left
  // of its edges).
  std::vector<BoundaryCurveStep> steps;
  for (const PieceSummary* piece : pieces)
  {
    steps.insert(steps.end(), piece->BoundarySteps.begin(), piece->BoundarySteps.end());
  }
  std::sort(steps.begin(), steps.end());
  for (size_t i = 0; i < steps.size();)
  {
    size_t j = i;
    std::vector<std::pair<int, int>> delta;
    for (; j < steps.size() && steps[j].Edge == steps[i].Edge && steps[j].Index == steps[i].Index;
         ++j)
    {
      delta.push_back({ steps[j].Shape, steps[j].Forward ? 1 : -1 });
    }
    const auto found = sides.find({ steps[i].Edge, steps[i].Index });
    if (found != sides.end() && found->second.Sides == 2 && Reports(found->second, focus))
    {
      const SubSegmentSides& s = found->second;
      const int up = s.Forward[0] ? 0 : 1;
      out.Crossings.push_back({ s.Side[1 - up], s.Side[up], SumByShape(std::move(delta)) });
    }
    i = j;
  }
  return true;
}

} // namespace boolsurf
