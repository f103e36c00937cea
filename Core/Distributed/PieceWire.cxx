#include "Distributed/PieceWire.h"

#include <cstring>
#include <unordered_map>

namespace boolsurf
{

//------------------------------------------------------------------------------
long long WireBitsOf(double x)
{
  long long bits = 0;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}

//------------------------------------------------------------------------------
double WireDoubleOf(long long bits)
{
  double x = 0;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

namespace
{

void PackDelta(const std::vector<std::pair<int, int>>& delta, WireBuffer& out)
{
  out.push_back(static_cast<long long>(delta.size()));
  for (const std::pair<int, int>& d : delta)
  {
    out.push_back(d.first);
    out.push_back(d.second);
  }
}

/// Reads a buffer front to back; every read checks that the buffer holds it, and the first
/// failed read makes every later one fail too, so a message is read in straight-line code and
/// checked once at the end.
class WireReader
{
public:
  explicit WireReader(const WireBuffer& in)
    : In(in)
  {
  }
  long long Next()
  {
    if (this->At >= this->In.size())
    {
      this->Failed = true;
      return 0;
    }
    return this->In[this->At++];
  }
  int NextInt() { return static_cast<int>(this->Next()); }
  /// A count of `words`-word records: fails when the buffer cannot hold them.
  std::size_t NextCount(std::size_t words)
  {
    const long long n = this->Next();
    if (n < 0 || static_cast<std::size_t>(n) * words > this->In.size() - this->At)
    {
      this->Failed = true;
      return 0;
    }
    return static_cast<std::size_t>(n);
  }
  std::vector<std::pair<int, int>> NextDelta()
  {
    std::vector<std::pair<int, int>> delta(this->NextCount(2));
    for (std::pair<int, int>& d : delta)
    {
      d.first = this->NextInt();
      d.second = this->NextInt();
    }
    return delta;
  }
  /// True when every read succeeded and the whole buffer was read; else `error` names `what`.
  bool Done(const char* what, std::string& error) const
  {
    if (this->Failed || this->At != this->In.size())
    {
      error = std::string("malformed ") + what + " message (" + std::to_string(this->In.size()) +
        " words)";
      return false;
    }
    return true;
  }

private:
  const WireBuffer& In;
  std::size_t At = 0;
  bool Failed = false;
};

} // namespace

//------------------------------------------------------------------------------
void PackTracedCurves(const std::vector<TracedCurve>& curves,
  const TriangleMesh& mesh,
  const std::vector<int>& vertexGlobalId,
  const std::vector<int>& triangleGlobalId,
  WireBuffer& out)
{
  auto vertex = [&](int v) { return vertexGlobalId.empty() ? v : vertexGlobalId[v]; };
  out.clear();
  std::unordered_map<int, int> edgeIndex; // mesh edge -> index in the message's edge table
  WireBuffer edges;
  out.push_back(static_cast<long long>(curves.size()));
  for (const TracedCurve& c : curves)
  {
    out.insert(out.end(),
      { c.Closed ? 1 : 0, c.ShapeId, c.CurveId, static_cast<long long>(c.Points.size()) });
    for (const CanonicalPoint& p : c.Points)
    {
      long long id = p.Id;
      if (p.Location == PointLocation::Vertex)
      {
        id = vertex(p.Id);
      }
      else if (p.Location == PointLocation::Edge)
      {
        const auto found = edgeIndex.emplace(p.Id, static_cast<int>(edgeIndex.size()));
        if (found.second)
        {
          const std::array<int, 2> ends = mesh.GetEdgeVertices(p.Id);
          edges.push_back(vertex(ends[0]));
          edges.push_back(vertex(ends[1]));
        }
        id = found.first->second;
      }
      else if (!triangleGlobalId.empty())
      {
        id = triangleGlobalId[p.Id];
      }
      out.insert(out.end(),
        { static_cast<long long>(p.Location),
          id,
          WireBitsOf(p.U),
          WireBitsOf(p.V),
          WireBitsOf(p.T) });
    }
  }
  out.push_back(static_cast<long long>(edges.size() / 2));
  out.insert(out.end(), edges.begin(), edges.end());
}

//------------------------------------------------------------------------------
bool UnpackTracedCurves(const WireBuffer& in,
  std::vector<TracedCurve>& curves,
  std::vector<std::array<int, 2>>& edgeVertices,
  std::string& error)
{
  WireReader r(in);
  curves.resize(r.NextCount(4));
  for (TracedCurve& c : curves)
  {
    c.Closed = r.Next() != 0;
    c.ShapeId = r.NextInt();
    c.CurveId = r.NextInt();
    c.Points.resize(r.NextCount(5));
    for (CanonicalPoint& p : c.Points)
    {
      p.Location = static_cast<PointLocation>(r.NextInt());
      p.Id = r.NextInt();
      p.U = WireDoubleOf(r.Next());
      p.V = WireDoubleOf(r.Next());
      p.T = WireDoubleOf(r.Next());
    }
  }
  edgeVertices.resize(r.NextCount(2));
  for (std::array<int, 2>& e : edgeVertices)
  {
    e = { r.NextInt(), r.NextInt() };
  }
  if (!r.Done("traced curves", error))
  {
    return false;
  }
  for (const TracedCurve& c : curves)
  {
    for (const CanonicalPoint& p : c.Points)
    {
      if (p.Location == PointLocation::Edge &&
        (p.Id < 0 || p.Id >= static_cast<int>(edgeVertices.size())))
      {
        error = "malformed traced curves message (edge " + std::to_string(p.Id) + ")";
        return false;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void PackBoundaryRecords(const PieceSummary& summary, WireBuffer& out)
{
  out.clear();
  out.reserve(2 + 6 * summary.Boundary.size() + 4 * summary.BoundarySteps.size());
  out.push_back(static_cast<long long>(summary.Boundary.size()));
  for (const BoundarySubSegment& s : summary.Boundary)
  {
    out.push_back(static_cast<long long>(s.Edge));
    out.push_back(s.Index);
    out.push_back(s.Count);
    out.push_back(s.Cell);
    out.push_back(s.Forward ? 1 : 0);
    out.push_back(s.Blocked ? 1 : 0);
  }
  out.push_back(static_cast<long long>(summary.BoundarySteps.size()));
  for (const BoundaryCurveStep& s : summary.BoundarySteps)
  {
    out.push_back(static_cast<long long>(s.Edge));
    out.push_back(s.Index);
    out.push_back(s.Shape);
    out.push_back(s.Forward ? 1 : 0);
  }
}

//------------------------------------------------------------------------------
bool UnpackBoundaryRecords(const WireBuffer& in, PieceSummary& out, std::string& error)
{
  WireReader r(in);
  out.Boundary.resize(r.NextCount(6));
  for (BoundarySubSegment& s : out.Boundary)
  {
    s.Edge = static_cast<std::uint64_t>(r.Next());
    s.Index = r.NextInt();
    s.Count = r.NextInt();
    s.Cell = r.NextInt();
    s.Forward = r.Next() != 0;
    s.Blocked = r.Next() != 0;
  }
  out.BoundarySteps.resize(r.NextCount(4));
  for (BoundaryCurveStep& s : out.BoundarySteps)
  {
    s.Edge = static_cast<std::uint64_t>(r.Next());
    s.Index = r.NextInt();
    s.Shape = r.NextInt();
    s.Forward = r.Next() != 0;
  }
  return r.Done("boundary records", error);
}

//------------------------------------------------------------------------------
void PackMergeInput(const PieceSummary& summary, const BoundaryJoins& joins, WireBuffer& out)
{
  out.clear();
  out.push_back(summary.NumberOfLocalCells);
  out.push_back(static_cast<long long>(summary.Cells.size()));
  for (const PieceCell& c : summary.Cells)
  {
    out.push_back(c.LocalCell);
    out.push_back(c.Lowest.Source);
    out.push_back(c.Lowest.Index);
    out.push_back(WireBitsOf(c.Area));
  }
  out.push_back(static_cast<long long>(summary.Crossings.size()));
  for (const CellCrossing& c : summary.Crossings)
  {
    out.push_back(c.FromCell);
    out.push_back(c.ToCell);
    PackDelta(c.Delta, out);
  }
  out.push_back(static_cast<long long>(joins.Joins.size()));
  for (const std::pair<PieceCellRef, PieceCellRef>& j : joins.Joins)
  {
    out.insert(out.end(), { j.first.Piece, j.first.Cell, j.second.Piece, j.second.Cell });
  }
  out.push_back(static_cast<long long>(joins.Crossings.size()));
  for (const BoundaryCrossing& c : joins.Crossings)
  {
    out.insert(out.end(), { c.From.Piece, c.From.Cell, c.To.Piece, c.To.Cell });
    PackDelta(c.Delta, out);
  }
  out.push_back(static_cast<long long>(summary.LoopFragments.size()));
  for (const BoundaryLoopFragment& f : summary.LoopFragments)
  {
    out.insert(out.end(),
      { static_cast<long long>(f.First),
        static_cast<long long>(f.Next),
        f.LowestHalfEdge,
        f.LowestIndex });
    out.push_back(static_cast<long long>(f.EdgeLengths.size()));
    for (const double l : f.EdgeLengths)
    {
      out.push_back(WireBitsOf(l));
    }
  }
  out.push_back(static_cast<long long>(summary.PlugCrossings.size()));
  for (const PlugCrossing& c : summary.PlugCrossings)
  {
    out.push_back(c.Fragment);
    out.push_back(c.Cell);
    PackDelta(c.Delta, out);
  }
}

//------------------------------------------------------------------------------
bool UnpackMergeInput(const WireBuffer& in,
  PieceSummary& summary,
  BoundaryJoins& joins,
  std::string& error)
{
  WireReader r(in);
  summary = PieceSummary();
  summary.NumberOfLocalCells = r.NextInt();
  summary.Cells.resize(r.NextCount(4));
  for (PieceCell& c : summary.Cells)
  {
    c.LocalCell = r.NextInt();
    c.Lowest.Source = r.NextInt();
    c.Lowest.Index = r.NextInt();
    c.Area = WireDoubleOf(r.Next());
  }
  summary.Crossings.resize(r.NextCount(3));
  for (CellCrossing& c : summary.Crossings)
  {
    c.FromCell = r.NextInt();
    c.ToCell = r.NextInt();
    c.Delta = r.NextDelta();
  }
  const std::size_t numberOfJoins = r.NextCount(4);
  for (std::size_t j = 0; j < numberOfJoins; ++j)
  {
    std::pair<PieceCellRef, PieceCellRef> join;
    join.first.Piece = r.NextInt();
    join.first.Cell = r.NextInt();
    join.second.Piece = r.NextInt();
    join.second.Cell = r.NextInt();
    joins.Joins.push_back(join);
  }
  const std::size_t numberOfCrossings = r.NextCount(5);
  for (std::size_t k = 0; k < numberOfCrossings; ++k)
  {
    BoundaryCrossing c;
    c.From.Piece = r.NextInt();
    c.From.Cell = r.NextInt();
    c.To.Piece = r.NextInt();
    c.To.Cell = r.NextInt();
    c.Delta = r.NextDelta();
    joins.Crossings.push_back(std::move(c));
  }
  summary.LoopFragments.resize(r.NextCount(5));
  for (BoundaryLoopFragment& f : summary.LoopFragments)
  {
    f.First = static_cast<std::uint64_t>(r.Next());
    f.Next = static_cast<std::uint64_t>(r.Next());
    f.LowestHalfEdge = r.Next();
    f.LowestIndex = r.NextInt();
    f.EdgeLengths.resize(r.NextCount(1));
    for (double& l : f.EdgeLengths)
    {
      l = WireDoubleOf(r.Next());
    }
  }
  summary.PlugCrossings.resize(r.NextCount(3));
  for (PlugCrossing& c : summary.PlugCrossings)
  {
    c.Fragment = r.NextInt();
    c.Cell = r.NextInt();
    c.Delta = r.NextDelta();
  }
  return r.Done("merge input", error);
}

//------------------------------------------------------------------------------
void PackMergedForPiece(const MergedArrangement& merged, int piece, WireBuffer& out)
{
  out.clear();
  out.push_back(merged.NumberOfCells);
  const std::vector<int>& row = merged.GlobalCellOfLocal[piece];
  out.push_back(static_cast<long long>(row.size()));
  out.insert(out.end(), row.begin(), row.end());
  out.push_back(static_cast<long long>(merged.CellArea.size()));
  for (double a : merged.CellArea)
  {
    out.push_back(WireBitsOf(a));
  }
  for (const std::vector<CellCrossing>* crossings : { &merged.Crossings, &merged.PlugCrossings })
  {
    out.push_back(static_cast<long long>(crossings->size()));
    for (const CellCrossing& c : *crossings)
    {
      out.push_back(c.FromCell);
      out.push_back(c.ToCell);
      PackDelta(c.Delta, out);
    }
  }
  out.push_back(merged.NumberOfPlugs);
  for (const std::vector<int>* numbers : { &merged.NodeComponent, &merged.ZeroNodes })
  {
    out.push_back(static_cast<long long>(numbers->size()));
    out.insert(out.end(), numbers->begin(), numbers->end());
  }
}

//------------------------------------------------------------------------------
bool UnpackMergedForPiece(const WireBuffer& in, MergedArrangement& out, std::string& error)
{
  WireReader r(in);
  out = MergedArrangement();
  out.NumberOfCells = r.NextInt();
  out.GlobalCellOfLocal.resize(1);
  out.GlobalCellOfLocal[0].resize(r.NextCount(1));
  for (int& g : out.GlobalCellOfLocal[0])
  {
    g = r.NextInt();
  }
  out.CellArea.resize(r.NextCount(1));
  for (double& a : out.CellArea)
  {
    a = WireDoubleOf(r.Next());
  }
  for (std::vector<CellCrossing>* crossings : { &out.Crossings, &out.PlugCrossings })
  {
    crossings->resize(r.NextCount(3));
    for (CellCrossing& c : *crossings)
    {
      c.FromCell = r.NextInt();
      c.ToCell = r.NextInt();
      c.Delta = r.NextDelta();
    }
  }
  out.NumberOfPlugs = r.NextInt();
  for (std::vector<int>* numbers : { &out.NodeComponent, &out.ZeroNodes })
  {
    numbers->resize(r.NextCount(1));
    for (int& n : *numbers)
    {
      n = r.NextInt();
    }
  }
  return r.Done("merged arrangement", error);
}

} // namespace boolsurf
