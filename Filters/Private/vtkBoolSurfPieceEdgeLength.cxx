#include "vtkBoolSurfPieceEdgeLength.h"

#include "vtkBoolSurfSurfacePiece.h"

#include "Distributed/PieceWire.h"

#include <vtkCommunicator.h>
#include <vtkMultiProcessController.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace
{
using Buffer = std::vector<long long>;

} // namespace

//------------------------------------------------------------------------------
double boolsurf::PieceMeanEdgeLength(vtkMultiProcessController* controller, const PieceMesh& piece)
{
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  const TriangleMesh& mesh = piece.Mesh;
  long long highest = -1, all = 0;
  for (int g : piece.GlobalTriangle)
  {
    highest = std::max<long long>(highest, g);
  }
  controller->AllReduce(&highest, &all, 1, vtkCommunicator::MAX_OP);
  const long long range = std::max(1LL, (all + ranks) / ranks); // ids per range holder
  // Per owned triangle: id, owned half-edges, their lengths (in corner order).
  std::vector<Buffer> send(ranks);
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    if (!piece.Owned[t])
    {
      continue;
    }
    long long lengths[3];
    int n = 0;
    for (int k = 0; k < 3; ++k)
    {
      const int e = mesh.GetEdgeId(t, k);
      if (mesh.GetEdgeHalfEdge(e) == 3 * t + k)
      {
        const std::array<int, 2> v = mesh.GetEdgeVertices(e);
        lengths[n++] =
          boolsurf::WireBitsOf(Distance(mesh.GetPosition(v[0]), mesh.GetPosition(v[1])));
      }
    }
    Buffer& b = send[piece.GlobalTriangle[t] / range];
    b.push_back(piece.GlobalTriangle[t]);
    b.push_back(n);
    b.insert(b.end(), lengths, lengths + n);
  }
  const std::vector<Buffer> got = vtkBoolSurfSurfacePiece::ExchangeAll(controller, std::move(send));
  // This range's triangles in id order, and the edges before the range.
  std::vector<std::pair<long long, std::pair<int, std::size_t>>> held; // id, (rank, offset)
  for (int r = 0; r < ranks; ++r)
  {
    for (std::size_t i = 0; i + 1 < got[r].size(); i += 2 + got[r][i + 1])
    {
      held.push_back({ got[r][i], { r, i } });
    }
  }
  std::sort(held.begin(), held.end());
  long long edges = 0;
  for (const auto& h : held)
  {
    edges += got[h.second.first][h.second.second + 1];
  }
  std::vector<long long> perRange(ranks, 0);
  controller->AllGather(&edges, perRange.data(), 1);
  long long first = 0, total = 0;
  for (int r = 0; r < ranks; ++r)
  {
    first += r < rank ? perRange[r] : 0;
    total += perRange[r];
  }
  const long long stride = std::max(1LL, total >> 16);
  // Sampled edges of this range: edge number, length.
  Buffer sampled;
  long long e = first;
  for (const auto& h : held)
  {
    const Buffer& b = got[h.second.first];
    const std::size_t at = h.second.second;
    for (long long j = 0; j < b[at + 1]; ++j, ++e)
    {
      if (e % stride == 0)
      {
        sampled.push_back(e);
        sampled.push_back(b[at + 2 + j]);
      }
    }
  }
  Buffer message(1, 0);
  if (rank == 0)
  {
    std::vector<std::pair<long long, double>> lengths;
    for (int r = 0; r < ranks; ++r)
    {
      Buffer part;
      if (r == 0)
      {
        part = sampled;
      }
      else
      {
        long long n = 0;
        controller->Receive(&n, 1, r, 56031);
        part.resize(static_cast<std::size_t>(n));
        controller->Receive(part.data(), n, r, 56032);
      }
      for (std::size_t i = 0; i + 1 < part.size(); i += 2)
      {
        lengths.emplace_back(part[i], boolsurf::WireDoubleOf(part[i + 1]));
      }
    }
    // In edge order, as one rank sums them.
    std::sort(lengths.begin(), lengths.end());
    double sum = 0.0;
    for (const auto& l : lengths)
    {
      sum += l.second;
    }
    const int count = static_cast<int>(lengths.size());
    message[0] = boolsurf::WireBitsOf(count > 0 ? sum / count : 0.0);
  }
  else
  {
    long long n = static_cast<long long>(sampled.size());
    controller->Send(&n, 1, 0, 56031);
    controller->Send(sampled.data(), n, 0, 56032);
  }
  controller->Broadcast(message.data(), 1, 0);
  return boolsurf::WireDoubleOf(message[0]);
}
