#include "vtkBoolSurfPieceTracing.h"

#include "vtkBoolSurfPieceEdgeLength.h"
#include "vtkBoolSurfSurfacePiece.h"

#include <vtkCommunicator.h>
#include <vtkMultiProcessController.h>

#include <algorithm>
#include <map>
#include <unordered_map>

using boolsurf::FetchedTriangles;
using boolsurf::GlobalCurvePoint;
using boolsurf::GlobalCurveTrace;
using boolsurf::WireBuffer;

namespace
{

/// Reads a WireBuffer front to back; past its end it gives 0 and marks itself bad.
struct Reader
{
  const WireBuffer& In;
  std::size_t At = 0;
  bool Bad = false;
  long long Next()
  {
    if (this->At >= this->In.size())
    {
      this->Bad = true;
      return 0;
    }
    return this->In[this->At++];
  }
  int Int() { return static_cast<int>(this->Next()); }
  double Double() { return boolsurf::WireDoubleOf(this->Next()); }
};

/// The triangle fetcher over messages, and the owner side answering other ranks' requests.
class MessageFetcher : public boolsurf::TriangleFetcher
{
public:
  MessageFetcher(vtkMultiProcessController* controller,
    const boolsurf::PieceMesh& piece,
    vtkBoolSurfPieceTracing::Traffic& bytes)
    : Controller(controller)
    , Piece(piece)
    , Bytes(bytes)
  {
  }

  /// Owner rank of global triangle g with corners `corners` (also names an owner for each).
  void SetOwner(int g, const std::array<int, 3>& corners, int owner)
  {
    this->TriangleOwner[g] = owner;
    for (int v : corners)
    {
      if (v >= 0)
      {
        this->VertexOwner.emplace(v, owner);
      }
    }
  }
  int OwnerOf(int g) const
  {
    const auto it = this->TriangleOwner.find(g);
    return it == this->TriangleOwner.end() ? -1 : it->second;
  }

  bool Fetch(const std::vector<int>& vertices,
    const std::vector<int>& triangles,
    int rings,
    FetchedTriangles& out,
    std::string& error) override
  {
    const int ranks = this->Controller->GetNumberOfProcesses();
    std::vector<std::vector<int>> askVertices(ranks), askTriangles(ranks);
    for (int v : vertices)
    {
      const auto it = this->VertexOwner.find(v);
      if (it == this->VertexOwner.end())
      {
        error = "no held triangle has vertex " + std::to_string(v);
        return false;
      }
      askVertices[it->second].push_back(v);
    }
    for (int t : triangles)
    {
      const int owner = this->OwnerOf(t);
      if (owner < 0)
      {
        error = "no rank holds triangle " + std::to_string(t);
        return false;
      }
      askTriangles[owner].push_back(t);
    }
    std::vector<WireBuffer> requests(ranks);
    for (int r = 0; r < ranks; ++r)
    {
      if (askVertices[r].empty() && askTriangles[r].empty())
      {
        continue;
      }
      WireBuffer& q = requests[r];
      q.push_back(rings);
      q.push_back(static_cast<long long>(askVertices[r].size()));
      q.insert(q.end(), askVertices[r].begin(), askVertices[r].end());
      q.push_back(static_cast<long long>(askTriangles[r].size()));
      q.insert(q.end(), askTriangles[r].begin(), askTriangles[r].end());
    }
    std::vector<WireBuffer> answers;
    this->Round(&requests, answers);
    ++this->Bytes.OwnRounds;
    // Merged answers: a triangle or point sent by two owners is taken once.
    std::unordered_map<int, char> took, tookPoint;
    for (const WireBuffer& a : answers)
    {
      Reader in{ a };
      if (a.empty())
      {
        continue;
      }
      const int nt = in.Int();
      for (int i = 0; i < nt && !in.Bad; ++i)
      {
        const int g = in.Int();
        std::array<int, 3> corners;
        for (int& c : corners)
        {
          c = in.Int();
        }
        const int owner = in.Int();
        this->SetOwner(g, corners, owner);
        if (took.emplace(g, 1).second)
        {
          out.TriangleGlobalIds.push_back(g);
          out.Corners.push_back(corners);
        }
      }
      const int np = in.Int();
      for (int i = 0; i < np && !in.Bad; ++i)
      {
        const int g = in.Int();
        const double x = in.Double(), y = in.Double(), z = in.Double();
        if (tookPoint.emplace(g, 1).second)
        {
          out.PointGlobalIds.push_back(g);
          out.Positions.push_back({ x, y, z });
        }
      }
      const int nw = in.Int();
      for (int i = 0; i < nw && !in.Bad; ++i)
      {
        out.WholeVertices.push_back(in.Int());
      }
      if (in.Bad)
      {
        error = "a truncated answer to a fetch";
        return false;
      }
    }
    return true;
  }

  /// Collective: one round of requests (null: this rank asks nothing). False when no rank
  /// asked: the rounds are over.
  bool Round(const std::vector<WireBuffer>* requests, std::vector<WireBuffer>& answers)
  {
    int asking = requests ? 1 : 0, any = 0;
    this->Controller->AllReduce(&asking, &any, 1, vtkCommunicator::MAX_OP);
    if (any == 0)
    {
      return false;
    }
    ++this->Bytes.Rounds;
    const int ranks = this->Controller->GetNumberOfProcesses();
    const std::vector<WireBuffer> asked = vtkBoolSurfSurfacePiece::ExchangeAll(this->Controller,
      requests ? *requests : std::vector<WireBuffer>(ranks),
      &this->Bytes.FetchSent,
      &this->Bytes.FetchReceived);
    std::vector<WireBuffer> replies(ranks);
    for (int r = 0; r < ranks; ++r)
    {
      if (!asked[r].empty())
      {
        this->Answer(asked[r], replies[r]);
      }
    }
    answers = vtkBoolSurfSurfacePiece::ExchangeAll(
      this->Controller, std::move(replies), &this->Bytes.FetchSent, &this->Bytes.FetchReceived);
    return true;
  }

private:
  /// From the ringed piece: `rings` rings round the asked vertices and the asked triangles'
  /// corners, growing only from vertices whose fan this rank holds whole (corners of its
  /// owned triangles), which are the vertices it names whole.
  void Answer(const WireBuffer& request, WireBuffer& reply)
  {
    const boolsurf::PieceMesh& p = this->Piece;
    const boolsurf::TriangleMesh& mesh = p.Mesh;
    Reader in{ request };
    const int rings = in.Int();
    std::vector<int> frontier;
    std::vector<char> seen(mesh.GetNumberOfVertices(), 0), sent(mesh.GetNumberOfTriangles(), 0);
    auto reach = [&](int v)
    {
      if (v >= 0 && !seen[v])
      {
        seen[v] = 1;
        frontier.push_back(v);
      }
    };
    const int nv = in.Int();
    for (int i = 0; i < nv && !in.Bad; ++i)
    {
      reach(p.LocalVertex(in.Int()));
    }
    const int nt = in.Int();
    for (int i = 0; i < nt && !in.Bad; ++i)
    {
      const int t = p.LocalTriangle(in.Int());
      if (t >= 0)
      {
        for (int v : mesh.GetTriangle(t))
        {
          reach(v);
        }
      }
    }
    std::vector<int> triangles, whole;
    for (int ring = 0; ring < rings; ++ring)
    {
      const std::vector<int> current = std::move(frontier);
      frontier.clear();
      for (int v : current)
      {
        if (!this->IsWholeHere(v))
        {
          continue;
        }
        whole.push_back(p.GlobalVertex[v]);
        for (int corner : mesh.GetVertexCorners(v))
        {
          const int t = corner / 3;
          if (!sent[t])
          {
            sent[t] = 1;
            triangles.push_back(t);
            for (int w : mesh.GetTriangle(t))
            {
              reach(w);
            }
          }
        }
      }
    }
    reply.push_back(static_cast<long long>(triangles.size()));
    std::fill(seen.begin(), seen.end(), 0);
    std::vector<int> points;
    for (int t : triangles)
    {
      const int g = p.GlobalTriangle[t];
      reply.push_back(g);
      for (int v : mesh.GetTriangle(t))
      {
        reply.push_back(p.GlobalVertex[v]);
        if (!seen[v])
        {
          seen[v] = 1;
          points.push_back(v);
        }
      }
      reply.push_back(this->OwnerOf(g));
    }
    reply.push_back(static_cast<long long>(points.size()));
    for (int v : points)
    {
      const boolsurf::Vec3 x = mesh.GetPosition(v);
      reply.insert(reply.end(),
        { p.GlobalVertex[v],
          boolsurf::WireBitsOf(x.x),
          boolsurf::WireBitsOf(x.y),
          boolsurf::WireBitsOf(x.z) });
    }
    reply.push_back(static_cast<long long>(whole.size()));
    reply.insert(reply.end(), whole.begin(), whole.end());
  }

  /// Whether local vertex v is a corner of an owned triangle (its fan is in the ring).
  bool IsWholeHere(int v)
  {
    if (this->WholeHere.empty())
    {
      const boolsurf::TriangleMesh& mesh = this->Piece.Mesh;
      this->WholeHere.assign(mesh.GetNumberOfVertices(), 0);
      for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
      {
        if (this->Piece.Owned[t])
        {
          for (int w : mesh.GetTriangle(t))
          {
            this->WholeHere[w] = 1;
          }
        }
      }
    }
    return this->WholeHere[v] != 0;
  }

  vtkMultiProcessController* Controller;
  const boolsurf::PieceMesh& Piece;
  vtkBoolSurfPieceTracing::Traffic& Bytes;
  std::unordered_map<int, int> TriangleOwner, VertexOwner;
  std::vector<char> WholeHere;
};

void PackTrace(int curve, const GlobalCurveTrace& t, WireBuffer& out)
{
  out.push_back(curve);
  out.push_back(static_cast<long long>(t.Points.size()));
  for (const GlobalCurvePoint& p : t.Points)
  {
    out.insert(out.end(),
      { static_cast<long long>(p.Location),
        p.Id,
        p.Second,
        boolsurf::WireBitsOf(p.U),
        boolsurf::WireBitsOf(p.V),
        boolsurf::WireBitsOf(p.T) });
  }
  out.insert(out.end(), { t.Closed ? 1 : 0, t.ShapeId, t.CurveId, boolsurf::WireBitsOf(t.Length) });
  out.push_back(static_cast<long long>(t.Segment.size()));
  out.insert(out.end(), t.Segment.begin(), t.Segment.end());
  out.push_back(static_cast<long long>(t.ControlPoint.size()));
  out.insert(out.end(), t.ControlPoint.begin(), t.ControlPoint.end());
  out.push_back(static_cast<long long>(t.Parameter.size()));
  for (double x : t.Parameter)
  {
    out.push_back(boolsurf::WireBitsOf(x));
  }
  out.push_back(static_cast<long long>(t.OnCurve.size()));
  out.insert(out.end(), t.OnCurve.begin(), t.OnCurve.end());
  out.push_back(static_cast<long long>(t.Written.size())); // 0 unless kept
  for (std::size_t i = 0; i < t.Written.size(); ++i)
  {
    const boolsurf::Vec3& x = t.Positions[i];
    const boolsurf::SurfacePoint& w = t.Written[i];
    out.insert(out.end(),
      { boolsurf::WireBitsOf(x.x),
        boolsurf::WireBitsOf(x.y),
        boolsurf::WireBitsOf(x.z),
        w.Triangle,
        boolsurf::WireBitsOf(w.U),
        boolsurf::WireBitsOf(w.V) });
  }
}

void UnpackTrace(Reader& in, GlobalCurveTrace& t)
{
  t.Points.resize(static_cast<std::size_t>(std::max(0, in.Int())));
  for (GlobalCurvePoint& p : t.Points)
  {
    p.Location = static_cast<boolsurf::PointLocation>(in.Int());
    p.Id = in.Int();
    p.Second = in.Int();
    p.U = in.Double();
    p.V = in.Double();
    p.T = in.Double();
  }
  t.Closed = in.Int() != 0;
  t.ShapeId = in.Int();
  t.CurveId = in.Int();
  t.Length = in.Double();
  t.Segment.resize(static_cast<std::size_t>(std::max(0, in.Int())));
  for (int& x : t.Segment)
  {
    x = in.Int();
  }
  t.ControlPoint.resize(static_cast<std::size_t>(std::max(0, in.Int())));
  for (int& x : t.ControlPoint)
  {
    x = in.Int();
  }
  t.Parameter.resize(static_cast<std::size_t>(std::max(0, in.Int())));
  for (double& x : t.Parameter)
  {
    x = in.Double();
  }
  t.OnCurve.resize(static_cast<std::size_t>(std::max(0, in.Int())));
  for (char& x : t.OnCurve)
  {
    x = static_cast<char>(in.Int());
  }
  const std::size_t written = static_cast<std::size_t>(std::max(0, in.Int()));
  t.Positions.resize(written);
  t.Written.resize(written);
  for (std::size_t i = 0; i < written && !in.Bad; ++i)
  {
    t.Positions[i].x = in.Double();
    t.Positions[i].y = in.Double();
    t.Positions[i].z = in.Double();
    t.Written[i].Triangle = in.Int();
    t.Written[i].U = in.Double();
    t.Written[i].V = in.Double();
  }
}

void PackString(const std::string& s, WireBuffer& out)
{
  out.push_back(static_cast<long long>(s.size()));
  out.insert(out.end(), s.begin(), s.end());
}

std::string UnpackString(Reader& in)
{
  const int n = std::max(0, in.Int());
  std::string s;
  for (int i = 0; i < n && !in.Bad; ++i)
  {
    s.push_back(static_cast<char>(in.Next()));
  }
  return s;
}

void Broadcast(vtkMultiProcessController* controller, WireBuffer& buffer)
{
  long long length = static_cast<long long>(buffer.size());
  controller->Broadcast(&length, 1, 0);
  buffer.resize(static_cast<std::size_t>(length));
  controller->Broadcast(buffer.data(), length, 0);
}

} // namespace

//------------------------------------------------------------------------------
/// What a Run builds from the ringed piece, kept for the next Run (SetReusePiece).
struct vtkBoolSurfPieceTracing::Held
{
  boolsurf::PieceMesh Piece;
  /// Rank g % ranks learns the owner of triangle g: this rank's share of the surface's ids.
  std::unordered_map<int, int> Directory;
  std::unordered_map<int, int> OwnerOf; ///< the ring's ghosts and control points' triangles
  double MeanEdgeLength = -1.0;
  int RingedTriangles = 0;
  std::unique_ptr<MessageFetcher> Fetcher;
  std::unique_ptr<boolsurf::PieceCurveTracer> Tracer;
  /// The last successful Run's curves and the settings they were traced with (the same on
  /// every rank), and on rank 0 their traces: what the next Run may recall.
  std::vector<Curve> Curves;
  boolsurf::GeodesicPathOptions Options;
  int Resolution = -1;
  double TracedMeanEdgeLength = -1.0;
  bool KeepWrittenForms = false;
  std::vector<GlobalCurveTrace> Traces;
};

namespace
{

bool SameCurve(const vtkBoolSurfPieceTracing::Curve& a, const vtkBoolSurfPieceTracing::Curve& b)
{
  return a.Type == b.Type && a.Closed == b.Closed && a.ShapeId == b.ShapeId &&
    a.CurveId == b.CurveId &&
    std::equal(a.Points.begin(),
      a.Points.end(),
      b.Points.begin(),
      b.Points.end(),
      [](const boolsurf::SurfacePoint& p, const boolsurf::SurfacePoint& q)
      { return p.Triangle == q.Triangle && p.U == q.U && p.V == q.V; });
}

} // namespace

vtkBoolSurfPieceTracing::vtkBoolSurfPieceTracing() = default;
vtkBoolSurfPieceTracing::~vtkBoolSurfPieceTracing() = default;

//------------------------------------------------------------------------------
bool vtkBoolSurfPieceTracing::Run(vtkMultiProcessController* controller,
  const boolsurf::PieceInput& ringed,
  const std::vector<Curve>& curves,
  WireBuffer& message0,
  std::string& error)
{
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  this->Bytes = Traffic();
  this->Traces.clear();
  this->Failures.clear();
  message0.clear();
  const bool build = !(this->ReusePiece && this->Kept);
  this->Bytes.ReusedPiece = !build;
  if (build)
  {
    this->Kept.reset();
    auto held = std::make_unique<Held>();
    std::string local;
    int built = boolsurf::BuildPieceMesh(ringed, held->Piece, local) ? 1 : 0, allBuilt = 0;
    controller->AllReduce(&built, &allBuilt, 1, vtkCommunicator::MIN_OP);
    if (!allBuilt)
    {
      error = built ? "tracing on pieces: a rank's piece is not a mesh"
                    : "tracing on pieces: rank " + std::to_string(rank) + ": " + local;
      this->Failures.emplace_back(-1, error);
      return false;
    }
    held->RingedTriangles = held->Piece.Mesh.GetNumberOfTriangles();
    this->Kept = std::move(held);
  }
  Held& kept = *this->Kept;
  const boolsurf::PieceMesh& piece = kept.Piece;
  const auto label = [&curves](std::size_t c)
  { return "curve " + std::to_string(curves[c].CurveId >= 0 ? curves[c].CurveId : int(c)); };

  // The directory (rank g % ranks learns the owner of triangle g), built with the piece; then
  // the owners of the ring's ghosts (with the piece) and of every curve's control point
  // triangles (every Run).
  std::unordered_map<int, int>& directory = kept.Directory;
  if (build)
  {
    std::vector<WireBuffer> owned(ranks);
    for (int t = 0; t < piece.Mesh.GetNumberOfTriangles(); ++t)
    {
      if (piece.Owned[t])
      {
        owned[piece.GlobalTriangle[t] % ranks].push_back(piece.GlobalTriangle[t]);
      }
    }
    const std::vector<WireBuffer> got = vtkBoolSurfSurfacePiece::ExchangeAll(
      controller, std::move(owned), &this->Bytes.DirectorySent, &this->Bytes.DirectoryReceived);
    for (int r = 0; r < ranks; ++r)
    {
      for (long long g : got[r])
      {
        directory[static_cast<int>(g)] = r;
      }
    }
  }
  std::vector<int> asked;
  if (build)
  {
    for (int t = 0; t < piece.Mesh.GetNumberOfTriangles(); ++t)
    {
      if (!piece.Owned[t])
      {
        asked.push_back(piece.GlobalTriangle[t]);
      }
    }
  }
  for (const Curve& c : curves)
  {
    for (const boolsurf::SurfacePoint& p : c.Points)
    {
      if (kept.OwnerOf.find(p.Triangle) == kept.OwnerOf.end())
      {
        asked.push_back(p.Triangle);
      }
    }
  }
  std::sort(asked.begin(), asked.end());
  asked.erase(std::unique(asked.begin(), asked.end()), asked.end());
  std::vector<WireBuffer> questions(ranks);
  for (int g : asked)
  {
    if (g >= 0)
    {
      questions[g % ranks].push_back(g);
    }
  }
  std::vector<WireBuffer> replies(ranks);
  {
    const std::vector<WireBuffer> got = vtkBoolSurfSurfacePiece::ExchangeAll(
      controller, questions, &this->Bytes.DirectorySent, &this->Bytes.DirectoryReceived);
    for (int r = 0; r < ranks; ++r)
    {
      for (long long g : got[r])
      {
        const auto it = directory.find(static_cast<int>(g));
        replies[r].push_back(it == directory.end() ? -1 : it->second);
      }
    }
  }
  {
    const std::vector<WireBuffer> got = vtkBoolSurfSurfacePiece::ExchangeAll(
      controller, std::move(replies), &this->Bytes.DirectorySent, &this->Bytes.DirectoryReceived);
    for (int r = 0; r < ranks; ++r)
    {
      for (std::size_t i = 0; i < questions[r].size() && i < got[r].size(); ++i)
      {
        kept.OwnerOf[static_cast<int>(questions[r][i])] = static_cast<int>(got[r][i]);
      }
    }
  }
  const auto ownerOf = [&kept](int g)
  {
    const auto it = kept.OwnerOf.find(g);
    return it == kept.OwnerOf.end() ? -1 : it->second;
  };
  // A control point on a triangle no rank owns fails its curve, on every rank alike (every
  // rank asked about every control point).
  for (std::size_t c = 0; c < curves.size(); ++c)
  {
    if (curves[c].Points.empty())
    {
      this->Failures.emplace_back(static_cast<int>(c), label(c) + " has no control points");
      continue;
    }
    for (std::size_t i = 0; i < curves[c].Points.size(); ++i)
    {
      const int g = curves[c].Points[i].Triangle;
      if (ownerOf(g) < 0)
      {
        this->Failures.emplace_back(static_cast<int>(c),
          label(c) + ": control point " + std::to_string(i) + " names triangle " +
            std::to_string(g) + ", which no rank holds");
        break;
      }
    }
  }
  if (!this->Failures.empty())
  {
    if (!kept.Tracer)
    {
      this->Kept.reset(); // built this time but not finished: built again next time
    }
    error = this->Failures.front().second;
    return false;
  }

  if (build)
  {
    kept.MeanEdgeLength = this->MeanEdgeLength >= 0.0
      ? this->MeanEdgeLength
      : boolsurf::PieceMeanEdgeLength(controller, piece);
    kept.Fetcher = std::make_unique<MessageFetcher>(controller, piece, this->Bytes);
    for (int t = 0; t < piece.Mesh.GetNumberOfTriangles(); ++t)
    {
      const int g = piece.GlobalTriangle[t];
      std::array<int, 3> corners;
      for (int k = 0; k < 3; ++k)
      {
        corners[k] = piece.GlobalVertex[piece.Mesh.GetTriangle(t)[k]];
      }
      kept.Fetcher->SetOwner(g, corners, piece.Owned[t] ? rank : ownerOf(g));
    }
    kept.Tracer = std::make_unique<boolsurf::PieceCurveTracer>(ringed, *kept.Fetcher);
  }
  else if (this->MeanEdgeLength >= 0.0)
  {
    kept.MeanEdgeLength = this->MeanEdgeLength;
  }
  this->UsedMeanEdgeLength = kept.MeanEdgeLength;
  MessageFetcher& fetcher = *kept.Fetcher;
  for (const Curve& c : curves)
  {
    for (const boolsurf::SurfacePoint& p : c.Points)
    {
      if (fetcher.OwnerOf(p.Triangle) < 0)
      {
        fetcher.SetOwner(p.Triangle, { -1, -1, -1 }, ownerOf(p.Triangle));
      }
    }
  }

  // The curves traced last time with the same settings on this piece: recalled (every rank
  // decides alike, from the same lists; rank 0 holds their traces).
  std::vector<char> recalled(curves.size(), 0);
  if (!build && kept.Options == this->Options && kept.Resolution == this->Resolution &&
    kept.TracedMeanEdgeLength == kept.MeanEdgeLength &&
    kept.KeepWrittenForms == this->KeepWrittenForms)
  {
    for (std::size_t c = 0; c < curves.size() && c < kept.Curves.size(); ++c)
    {
      recalled[c] = SameCurve(curves[c], kept.Curves[c]) ? 1 : 0;
      this->Bytes.RecalledCurves += recalled[c];
    }
  }
  std::vector<GlobalCurveTrace> previous = std::move(kept.Traces);
  kept.Traces.clear();
  kept.Curves.clear();

  // This rank's curves, then rounds with no request until no rank asks.
  boolsurf::PieceCurveTracer& tracer = *kept.Tracer;
  tracer.SetOptions(this->Options);
  tracer.SetResolution(this->Resolution);
  tracer.SetMeanEdgeLength(kept.MeanEdgeLength);
  tracer.SetMarginRings(this->MarginRings);
  tracer.SetKeepWrittenForms(this->KeepWrittenForms);
  WireBuffer results; // per curve: id, 1 and its trace, or 0 and its error
  for (std::size_t c = 0; c < curves.size(); ++c)
  {
    if (recalled[c] || ownerOf(curves[c].Points[0].Triangle) != rank)
    {
      continue;
    }
    ++this->Bytes.TracedCurves;
    GlobalCurveTrace trace;
    std::string failure;
    const int id = curves[c].CurveId >= 0 ? curves[c].CurveId : static_cast<int>(c);
    if (tracer.Trace(curves[c].Points, curves[c].Type, curves[c].Closed, trace, failure, id))
    {
      if (curves[c].CurveId >= 0)
      {
        trace.ShapeId = curves[c].ShapeId;
        trace.CurveId = curves[c].CurveId;
      }
      results.push_back(1);
      PackTrace(static_cast<int>(c), trace, results);
    }
    else
    {
      results.insert(results.end(), { 0, static_cast<long long>(c) });
      PackString(failure, results);
    }
  }
  std::vector<WireBuffer> none;
  while (fetcher.Round(nullptr, none))
  {
  }
  this->Bytes.RingedTriangles = kept.RingedTriangles;
  this->Bytes.HeldTriangles = tracer.GetSurface().GetNumberOfTriangles();
  this->Bytes.FetchedTriangles = this->Bytes.HeldTriangles - kept.RingedTriangles;

  // The traces to rank 0, message 0 (or every failing curve's message) back to all.
  std::vector<WireBuffer> atRoot(ranks);
  if (rank == 0)
  {
    atRoot[0] = std::move(results);
    for (int r = 1; r < ranks; ++r)
    {
      long long length = 0;
      controller->Receive(&length, 1, r, 56021);
      atRoot[r].resize(static_cast<std::size_t>(length));
      controller->Receive(atRoot[r].data(), length, r, 56022);
      this->Bytes.TracesReceived += (atRoot[r].size() + 1) * sizeof(long long);
    }
  }
  else
  {
    long long length = static_cast<long long>(results.size());
    controller->Send(&length, 1, 0, 56021);
    controller->Send(results.data(), length, 0, 56022);
    this->Bytes.TracesSent += (results.size() + 1) * sizeof(long long);
  }
  WireBuffer answer; // 1 and message 0, or 0, the number of failures and each (curve, message)
  if (rank == 0)
  {
    std::map<int, GlobalCurveTrace> traces;
    std::map<int, std::string> failures;
    for (std::size_t c = 0; c < curves.size(); ++c)
    {
      if (recalled[c])
      {
        traces[static_cast<int>(c)] = std::move(previous[c]);
      }
    }
    for (const WireBuffer& b : atRoot)
    {
      Reader in{ b };
      while (in.At < b.size() && !in.Bad)
      {
        if (in.Int() == 1)
        {
          const int c = in.Int();
          UnpackTrace(in, traces[c]);
        }
        else
        {
          const int c = in.Int();
          failures[c] = UnpackString(in);
        }
      }
      if (in.Bad)
      {
        failures[-1] = "a truncated trace";
      }
    }
    if (failures.empty() && traces.size() != curves.size())
    {
      failures[-1] = "a curve was traced by no rank";
    }
    if (failures.empty())
    {
      for (auto& entry : traces)
      {
        this->Traces.push_back(std::move(entry.second));
      }
      WireBuffer packed;
      boolsurf::PackGlobalTraces(this->Traces, packed);
      answer.push_back(1);
      answer.insert(answer.end(), packed.begin(), packed.end());
    }
    else
    {
      answer.push_back(0);
      answer.push_back(static_cast<long long>(failures.size()));
      for (const auto& entry : failures)
      {
        answer.push_back(entry.first);
        PackString(entry.second, answer);
      }
    }
  }
  Broadcast(controller, answer);
  const std::size_t broadcast = (answer.size() + 1) * sizeof(long long);
  if (rank == 0)
  {
    this->Bytes.TracesSent += (ranks - 1) * broadcast;
  }
  else
  {
    this->Bytes.TracesReceived += broadcast;
  }
  if (answer.empty() || answer[0] != 1)
  {
    Reader in{ answer };
    in.At = 1;
    const int n = answer.empty() ? 0 : in.Int();
    for (int i = 0; i < n && !in.Bad; ++i)
    {
      const int c = in.Int();
      this->Failures.emplace_back(c, UnpackString(in));
    }
    if (this->Failures.empty())
    {
      this->Failures.emplace_back(-1, "no answer from rank 0");
    }
    this->Traces.clear();
    error = this->Failures.front().second;
    return false;
  }
  message0.assign(answer.begin() + 1, answer.end());
  kept.Curves = curves;
  kept.Options = this->Options;
  kept.Resolution = this->Resolution;
  kept.TracedMeanEdgeLength = kept.MeanEdgeLength;
  kept.KeepWrittenForms = this->KeepWrittenForms;
  kept.Traces = this->Traces;
  return true;
}
