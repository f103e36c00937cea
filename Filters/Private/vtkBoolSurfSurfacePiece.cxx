#include "vtkBoolSurfSurfacePiece.h"

#include "vtkBoolSurfArrayNames.h"

#include <vtkCellData.h>
#include <vtkCommunicator.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkGenerateGlobalIds.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <map>
#include <set>

namespace
{
using Position = std::array<double, 3>;

/// Tags of the pairwise exchange (length, then data).
constexpr int LengthTag = 56001;
constexpr int DataTag = 56002;

/// Positions travel as the bits of their coordinates, so the match stays exact.
long long Bits(double x)
{
  long long b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}
double FromBits(long long b)
{
  double x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

/// The partner of `rank` in round `round` of a round-robin tournament over `ranks` players
/// (circle method; a player with no partner in a round gets -1).
int RoundPartner(int rank, int round, int ranks)
{
  const int n = ranks % 2 == 0 ? ranks : ranks + 1; // with a bye when odd
  int partner;
  if (rank == n - 1)
  {
    partner = round;
  }
  else if (rank == round)
  {
    partner = n - 1;
  }
  else
  {
    partner = ((2 * round - rank) % (n - 1) + (n - 1)) % (n - 1);
  }
  return partner < ranks && partner != rank ? partner : -1;
}

bool Overlaps(const double* a, const double* b)
{
  for (int k = 0; k < 3; ++k)
  {
    if (a[2 * k] > b[2 * k + 1] || b[2 * k] > a[2 * k + 1])
    {
      return false;
    }
  }
  return true;
}
} // namespace

//------------------------------------------------------------------------------
bool vtkBoolSurfSurfacePiece::IsDistributed(vtkMultiProcessController* controller,
  vtkPolyData* local)
{
  if (!controller || controller->GetNumberOfProcesses() < 2)
  {
    return false;
  }
  // A rank's part of Surface Arrangement on pieces counts even without triangles (a rank may
  // own none of the refined surface): the stages after it stay on the pieces.
  int holds = local &&
      (local->GetNumberOfPolys() + local->GetNumberOfStrips() > 0 ||
        local->GetFieldData()->GetAbstractArray(boolsurf::names::ArrangementOnPieces))
    ? 1
    : 0;
  int holding = 0;
  controller->AllReduce(&holds, &holding, 1, vtkCommunicator::SUM_OP);
  return holding >= 2;
}

//------------------------------------------------------------------------------
bool vtkBoolSurfSurfacePiece::HasGlobalIds(vtkMultiProcessController* controller,
  vtkPolyData* local)
{
  int has = !local || local->GetNumberOfCells() == 0 ||
      (local->GetPointData()->GetGlobalIds() && local->GetCellData()->GetGlobalIds())
    ? 1
    : 0;
  int all = 0;
  controller->AllReduce(&has, &all, 1, vtkCommunicator::MIN_OP);
  return all == 1;
}

//------------------------------------------------------------------------------
bool vtkBoolSurfSurfacePiece::Build(vtkMultiProcessController* controller,
  vtkPolyData* local,
  std::string& error,
  std::vector<std::string>& warnings)
{
  this->Controller = controller;
  this->BytesSent = this->BytesReceived = 0;
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  vtkSmartPointer<vtkPolyData> input = local;
  if (!input)
  {
    input = vtkSmartPointer<vtkPolyData>::New();
  }

  // Global cell ids: every rank generates them when a rank with cells has none (the filter
  // is collective, so the decision is too).
  const bool filled = input->GetNumberOfCells() > 0;
  int missing = filled && !input->GetCellData()->GetGlobalIds() ? 1 : 0;
  int anyMissing = 0;
  controller->AllReduce(&missing, &anyMissing, 1, vtkCommunicator::MAX_OP);
  if (anyMissing)
  {
    vtkNew<vtkGenerateGlobalIds> generate;
    generate->SetController(controller);
    generate->SetInputData(input);
    generate->Update();
    input = vtkPolyData::SafeDownCast(generate->GetOutputDataObject(0));
    if (rank == 0)
    {
      warnings.push_back("the pieces of the surface carry no global cell ids: generated them "
                         "(vtkGenerateGlobalIds), so triangle ids name the pieces' cells in "
                         "rank order, not the cells of the undistributed surface");
    }
  }

  // The owned triangles (ConvertSurface drops the ghost cells and welds a piece made of
  // several appended pieces), and their global ids.
  boolsurf::ConvertSurface(input, this->Surface);
  const boolsurf::TriangleMesh& mesh = *this->Surface.Mesh;
  vtkDataArray* ids = this->Surface.Triangles->GetCellData()->GetGlobalIds();
  this->GlobalCellIds.assign(mesh.GetNumberOfTriangles(), -1);
  for (int t = 0; ids && t < mesh.GetNumberOfTriangles(); ++t)
  {
    this->GlobalCellIds[t] = static_cast<long long>(ids->GetTuple1(t));
  }

  // Overlap, first test: more owned cells than global ids (ids count from 0).
  long long counts[2] = { static_cast<long long>(this->GlobalCellIds.size()), -1 };
  for (long long id : this->GlobalCellIds)
  {
    counts[1] = std::max(counts[1], id);
  }
  long long total = 0, largest = 0;
  controller->AllReduce(&counts[0], &total, 1, vtkCommunicator::SUM_OP);
  controller->AllReduce(&counts[1], &largest, 1, vtkCommunicator::MAX_OP);
  int overlap = total > largest + 1 ? 1 : 0;

  // The border: points of half-edges with no twin (boundary, cut or non-manifold edges).
  std::map<Position, vtkIdType> border;
  const double inf = std::numeric_limits<double>::infinity();
  double bounds[6] = { inf, -inf, inf, -inf, inf, -inf }; // empty: min > max
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    for (int k = 0; mesh.IsUsable(t) && k < 3; ++k)
    {
      if (mesh.GetTwin(3 * t + k) >= 0)
      {
        continue;
      }
      for (int v : { mesh.GetTriangle(t)[k], mesh.GetTriangle(t)[(k + 1) % 3] })
      {
        const boolsurf::Vec3& p = mesh.GetPosition(v);
        if (boolsurf::IsFinite(p)) // NaN does not order, and matches no other rank's point
        {
          border.emplace(Position{ p[0], p[1], p[2] }, v);
        }
      }
    }
  }
  for (const auto& point : border)
  {
    for (int k = 0; k < 3; ++k)
    {
      bounds[2 * k] = std::min(bounds[2 * k], point.first[k]);
      bounds[2 * k + 1] = std::max(bounds[2 * k + 1], point.first[k]);
    }
  }
  std::vector<double> allBounds(6 * static_cast<size_t>(ranks));
  controller->AllGather(bounds, allBounds.data(), 6);
  this->BytesSent += 6 * sizeof(double) * static_cast<std::size_t>(ranks - 1);
  this->BytesReceived += 6 * sizeof(double) * static_cast<std::size_t>(ranks - 1);

  // The ranks whose borders' bounds meet this one's get the border points inside their bounds.
  std::vector<int> partners;
  std::vector<std::vector<long long>> send;
  for (int r = 0; r < ranks; ++r)
  {
    const double* other = &allBounds[6 * r];
    if (r == rank || bounds[0] > bounds[1] || other[0] > other[1] || !Overlaps(bounds, other))
    {
      continue;
    }
    partners.push_back(r);
    send.emplace_back();
    for (const auto& point : border)
    {
      const double* p = point.first.data();
      if (p[0] >= other[0] && p[0] <= other[1] && p[1] >= other[2] && p[1] <= other[3] &&
        p[2] >= other[4] && p[2] <= other[5])
      {
        for (double x : point.first)
        {
          send.back().push_back(Bits(x));
        }
      }
    }
  }
  const std::vector<std::vector<long long>> received =
    ExchangeWith(this->Controller, partners, send);
  this->CountBytes(send, received);
  this->Neighbours.clear();
  for (size_t i = 0; i < partners.size(); ++i)
  {
    // Both ranks list the common points in increasing position: the same order on both.
    std::set<Position> theirs;
    for (size_t j = 0; j + 2 < received[i].size(); j += 3)
    {
      theirs.insert(Position{
        FromBits(received[i][j]), FromBits(received[i][j + 1]), FromBits(received[i][j + 2]) });
    }
    Neighbour neighbour;
    neighbour.Rank = partners[i];
    for (const auto& point : border)
    {
      if (theirs.count(point.first))
      {
        neighbour.Points.push_back(point.second);
      }
    }
    if (!neighbour.Points.empty())
    {
      this->Neighbours.push_back(std::move(neighbour));
    }
  }

  // Overlap, second test: a triangle on the border owned by a neighbour too.
  std::vector<std::vector<long long>> borderCells(this->Neighbours.size());
  std::set<long long> ownBorderCells;
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    for (int k = 0; mesh.IsUsable(t) && k < 3; ++k)
    {
      if (mesh.GetTwin(3 * t + k) < 0)
      {
        ownBorderCells.insert(this->GlobalCellIds[t]);
      }
    }
  }
  for (auto& cells : borderCells)
  {
    cells.assign(ownBorderCells.begin(), ownBorderCells.end());
  }
  const std::vector<std::vector<long long>> theirCells = this->Exchange(borderCells);
  this->CountBytes(borderCells, theirCells);
  for (const std::vector<long long>& cells : theirCells)
  {
    for (long long id : cells)
    {
      overlap = overlap || ownBorderCells.count(id) ? 1 : 0;
    }
  }
  int anyOverlap = 0;
  controller->AllReduce(&overlap, &anyOverlap, 1, vtkCommunicator::MAX_OP);
  if (anyOverlap)
  {
    error = this->NameOverlaps();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkBoolSurfSurfacePiece::CountBytes(const std::vector<std::vector<long long>>& sent,
  const std::vector<std::vector<long long>>& received)
{
  for (const std::vector<long long>& buffer : sent)
  {
    this->BytesSent += (buffer.size() + 1) * sizeof(long long); // with its length
  }
  for (const std::vector<long long>& buffer : received)
  {
    this->BytesReceived += (buffer.size() + 1) * sizeof(long long);
  }
}

//------------------------------------------------------------------------------
std::vector<std::vector<long long>> vtkBoolSurfSurfacePiece::Exchange(
  const std::vector<std::vector<long long>>& send) const
{
  std::vector<int> partners;
  for (const Neighbour& n : this->Neighbours)
  {
    partners.push_back(n.Rank);
  }
  return ExchangeWith(this->Controller, partners, send);
}

//------------------------------------------------------------------------------
std::vector<std::vector<long long>> vtkBoolSurfSurfacePiece::ExchangeWith(
  vtkMultiProcessController* controller,
  const std::vector<int>& partners,
  const std::vector<std::vector<long long>>& send)
{
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  std::vector<std::vector<long long>> received(partners.size());
  const int rounds = ranks % 2 == 0 ? ranks - 1 : ranks;
  for (int round = 0; round < rounds; ++round)
  {
    const int partner = RoundPartner(rank, round, ranks);
    const auto at = std::find(partners.begin(), partners.end(), partner);
    if (partner < 0 || at == partners.end())
    {
      continue; // partners are symmetric: the other rank skips this round too
    }
    const size_t i = static_cast<size_t>(at - partners.begin());
    auto sendTo = [&]()
    {
      long long length = static_cast<long long>(send[i].size());
      controller->Send(&length, 1, partner, LengthTag);
      controller->Send(send[i].data(), length, partner, DataTag);
    };
    auto receiveFrom = [&]()
    {
      long long length = 0;
      controller->Receive(&length, 1, partner, LengthTag);
      received[i].resize(static_cast<size_t>(length));
      controller->Receive(received[i].data(), length, partner, DataTag);
    };
    // The lower rank sends first: a blocking send always meets its receive.
    if (rank < partner)
    {
      sendTo();
      receiveFrom();
    }
    else
    {
      receiveFrom();
      sendTo();
    }
  }
  return received;
}

//------------------------------------------------------------------------------
std::string vtkBoolSurfSurfacePiece::NameOverlaps()
{
  // Every owned id to rank 0 (an error path: the cost of naming the ids is paid only then).
  vtkMultiProcessController* controller = this->Controller;
  const int ranks = controller->GetNumberOfProcesses();
  long long count = static_cast<long long>(this->GlobalCellIds.size());
  std::vector<long long> counts(ranks), offsets(ranks);
  controller->AllGather(&count, counts.data(), 1);
  long long total = 0;
  for (int r = 0; r < ranks; ++r)
  {
    offsets[r] = total;
    total += counts[r];
  }
  std::vector<long long> all(static_cast<size_t>(std::max<long long>(total, 1)));
  controller->GatherV(
    this->GlobalCellIds.data(), all.data(), count, counts.data(), offsets.data(), 0);
  std::string message;
  if (controller->GetLocalProcessId() == 0)
  {
    std::map<long long, std::vector<int>> owners;
    for (int r = 0; r < ranks; ++r)
    {
      for (long long i = offsets[r]; i < offsets[r] + counts[r]; ++i)
      {
        owners[all[i]].push_back(r);
      }
    }
    int shown = 0, more = 0;
    for (const auto& owner : owners)
    {
      if (owner.second.size() < 2)
      {
        continue;
      }
      if (shown == 10)
      {
        ++more;
        continue;
      }
      message += std::string(shown++ ? ", " : "") + std::to_string(owner.first) + " (ranks";
      for (int r : owner.second)
      {
        message += " " + std::to_string(r);
      }
      message += ")";
    }
    message = "the surface's pieces overlap without ghost marks: global cell ids owned on two "
              "ranks: " +
      message + (more ? " ... and " + std::to_string(more) + " more" : "") +
      ". Mark the copies as ghost cells (vtkGhostType) or give each cell to one rank.";
  }
  long long length = static_cast<long long>(message.size());
  controller->Broadcast(&length, 1, 0);
  message.resize(static_cast<size_t>(length));
  controller->Broadcast(&message[0], length, 0);
  return message;
}

//------------------------------------------------------------------------------
std::vector<std::vector<long long>> vtkBoolSurfSurfacePiece::ExchangeAll(
  vtkMultiProcessController* controller,
  std::vector<std::vector<long long>> send,
  std::size_t* sent,
  std::size_t* received)
{
  const auto bytesOf = [](const std::vector<std::vector<long long>>& buffers)
  {
    std::size_t n = 0;
    for (const std::vector<long long>& b : buffers)
    {
      n += (b.size() + 1) * sizeof(long long); // with its length
    }
    return n;
  };
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  std::vector<int> partners;
  std::vector<std::vector<long long>> out;
  for (int r = 0; r < ranks; ++r)
  {
    if (r != rank)
    {
      partners.push_back(r);
      out.push_back(std::move(send[r]));
    }
  }
  if (sent)
  {
    *sent += bytesOf(out);
  }
  std::vector<std::vector<long long>> back = ExchangeWith(controller, partners, out);
  if (received)
  {
    *received += bytesOf(back);
  }
  std::vector<std::vector<long long>> result(ranks);
  for (std::size_t i = 0; i < partners.size(); ++i)
  {
    result[partners[i]] = std::move(back[i]);
  }
  result[rank] = std::move(send[rank]);
  return result;
}
