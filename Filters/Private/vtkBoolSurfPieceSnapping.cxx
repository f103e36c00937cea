#include "vtkBoolSurfPieceSnapping.h"

#include "vtkBoolSurfArrayNames.h"

#include "Distributed/PieceWire.h"

#include <vtkCommunicator.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <map>
#include <utility>

namespace boolsurf
{
namespace
{
/// One answer on the wire: found, triangle, corners, squared distance, closest point, corners'
/// positions (doubles as their bits, so rank 0 gets them exactly).
constexpr std::size_t AnswerWords = 4 + 3 + 9;
/// One query on the wire: named, triangle, position.
constexpr std::size_t QueryWords = 5;

void PackAnswer(const PlacedPoint& p, WireBuffer& out)
{
  out.insert(out.end(), { p.Found ? 1LL : 0LL, p.Triangle, p.Corners, WireBitsOf(p.Distance2) });
  for (double x : p.Closest)
  {
    out.push_back(WireBitsOf(x));
  }
  for (const auto& corner : p.P)
  {
    for (double x : corner)
    {
      out.push_back(WireBitsOf(x));
    }
  }
}

PlacedPoint UnpackAnswer(const long long* in)
{
  PlacedPoint p;
  p.Found = in[0] != 0;
  p.Triangle = in[1];
  p.Corners = static_cast<int>(in[2]);
  p.Distance2 = WireDoubleOf(in[3]);
  for (int k = 0; k < 3; ++k)
  {
    p.Closest[k] = WireDoubleOf(in[4 + k]);
  }
  for (int k = 0; k < 9; ++k)
  {
    p.P[k / 3][k % 3] = WireDoubleOf(in[7 + k]);
  }
  return p;
}

/// Whether `a` is the better answer to a query by position: nearer, or as near and of a lower
/// id (the rule of ClosestTriangles, across ranks).
bool Nearer(const PlacedPoint& a, const PlacedPoint& b)
{
  return a.Distance2 < b.Distance2 || (a.Distance2 == b.Distance2 && a.Triangle < b.Triangle);
}
} // namespace

//------------------------------------------------------------------------------
void PlaceOnPieces(vtkMultiProcessController* controller,
  const ClosestTriangles& finder,
  std::vector<PointQuery> queries,
  std::vector<PlacedPoint>& placed,
  long long& triangles,
  SnappingTraffic& traffic)
{
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  traffic = SnappingTraffic();
  placed.clear();

  // Rank 0's queries, to every rank: a named triangle, or a position.
  WireBuffer asked;
  if (rank == 0)
  {
    for (const PointQuery& q : queries)
    {
      asked.insert(asked.end(),
        { q.Named ? 1LL : 0LL,
          q.Triangle,
          WireBitsOf(q.X[0]),
          WireBitsOf(q.X[1]),
          WireBitsOf(q.X[2]) });
    }
  }
  long long length = static_cast<long long>(asked.size());
  controller->Broadcast(&length, 1, 0);
  asked.resize(static_cast<std::size_t>(length));
  if (length > 0)
  {
    controller->Broadcast(asked.data(), length, 0);
  }
  queries.resize(asked.size() / QueryWords);
  for (std::size_t i = 0; i < queries.size(); ++i)
  {
    const long long* q = asked.data() + QueryWords * i;
    queries[i].Named = q[0] != 0;
    queries[i].Triangle = q[1];
    for (int k = 0; k < 3; ++k)
    {
      queries[i].X[k] = WireDoubleOf(q[2 + k]);
    }
  }
  const std::size_t bytes = sizeof(long long) * (asked.size() + 1);
  if (rank == 0)
  {
    traffic.Sent += bytes * static_cast<std::size_t>(ranks - 1);
  }
  else
  {
    traffic.Received += bytes;
  }

  // The smallest distance of each position over every rank (one all-reduce): only the ranks
  // that close search their cells for the lowest id at that distance.
  std::vector<double> distance2(queries.size(), 0.0), smallest(queries.size(), 0.0);
  for (std::size_t i = 0; i < queries.size(); ++i)
  {
    distance2[i] = queries[i].Named ? 0.0 : finder.FindDistance2(queries[i]);
  }
  if (!queries.empty())
  {
    controller->AllReduce(distance2.data(),
      smallest.data(),
      static_cast<vtkIdType>(queries.size()),
      vtkCommunicator::MIN_OP);
  }
  traffic.Sent += sizeof(double) * queries.size();
  traffic.Received += sizeof(double) * queries.size();

  // Every rank's answers (its number of triangles first), gathered to rank 0 in one call.
  traffic.OwnedTriangles = finder.GetNumberOfCells();
  traffic.Points = static_cast<long long>(queries.size());
  WireBuffer answers{ traffic.OwnedTriangles };
  for (std::size_t i = 0; i < queries.size(); ++i)
  {
    const bool near = queries[i].Named || distance2[i] == smallest[i];
    PackAnswer(near ? finder.Place(queries[i], smallest[i]) : PlacedPoint(), answers);
  }
  WireBuffer all(rank == 0 ? answers.size() * static_cast<std::size_t>(ranks) : 0);
  controller->Gather(answers.data(), all.data(), static_cast<vtkIdType>(answers.size()), 0);
  if (rank != 0)
  {
    traffic.Sent += sizeof(long long) * answers.size();
    return;
  }
  traffic.Received += sizeof(long long) * answers.size() * static_cast<std::size_t>(ranks - 1);
  triangles = 0;
  placed.assign(queries.size(), PlacedPoint());
  for (int r = 0; r < ranks; ++r)
  {
    const long long* from = all.data() + answers.size() * static_cast<std::size_t>(r);
    triangles += from[0];
    for (std::size_t i = 0; i < queries.size(); ++i)
    {
      const PlacedPoint answer = UnpackAnswer(from + 1 + AnswerWords * i);
      PlacedPoint& kept = placed[i];
      // A named triangle has one owner (the lowest rank's answer, should pieces overlap).
      if (answer.Found && (!kept.Found || (!queries[i].Named && Nearer(answer, kept))))
      {
        kept = answer;
      }
    }
  }
}

//------------------------------------------------------------------------------
bool IsClosedOnPieces(vtkMultiProcessController* controller, const PieceInput& ringed)
{
  // Each edge of the ringed piece with the number of its triangles (edges by global point ids);
  // an owned triangle's edge has all of its triangles in the ring.
  std::map<std::pair<int, int>, int> triangles;
  auto edge = [&](std::size_t t, int k)
  {
    const int a = ringed.PointGlobalIds[ringed.Triangles[t][k]];
    const int b = ringed.PointGlobalIds[ringed.Triangles[t][(k + 1) % 3]];
    return std::make_pair(std::min(a, b), std::max(a, b));
  };
  for (std::size_t t = 0; t < ringed.Triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++triangles[edge(t, k)];
    }
  }
  int closed = 1;
  for (std::size_t t = 0; t < ringed.Triangles.size() && closed; ++t)
  {
    for (int k = 0; k < 3 && !ringed.Ghost[t]; ++k)
    {
      closed = closed && triangles[edge(t, k)] == 2;
    }
  }
  int all = 0;
  controller->AllReduce(&closed, &all, 1, vtkCommunicator::MIN_OP);
  return all == 1;
}

//------------------------------------------------------------------------------
void AddPieceSnapping(const SnappingTraffic& t, vtkPolyData* output)
{
  const std::pair<const char*, double> values[] = {
    { "Sent", static_cast<double>(t.Sent) },
    { "Received", static_cast<double>(t.Received) },
    { "OwnedTriangles", static_cast<double>(t.OwnedTriangles) },
    { "Points", static_cast<double>(t.Points) },
  };
  vtkNew<vtkDoubleArray> array;
  array->SetName(names::PieceSnapping);
  array->SetNumberOfComponents(4);
  array->SetNumberOfTuples(1);
  for (int k = 0; k < 4; ++k)
  {
    array->SetComponentName(k, values[k].first);
    array->SetComponent(0, k, values[k].second);
  }
  output->GetFieldData()->AddArray(array);
}

} // namespace boolsurf
