#include "Geodesic/EdgeGraphSearch.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <ctime>
#include <functional>
#include <limits>

namespace boolsurf
{

//------------------------------------------------------------------------------
EdgeGraphSearch::EdgeGraphSearch(const TriangleMesh& mesh)
  : Mesh(mesh)
{
  const int nv = mesh.GetNumberOfVertices();
  // Morton order of the vertex positions (21 bits per axis in the bounding box).
  std::vector<std::pair<std::uint64_t, int>> keys(nv);
  Vec3 lo{ 0, 0, 0 }, hi{ 0, 0, 0 };
  if (nv > 0)
  {
    lo = hi = mesh.GetPosition(0);
  }
  for (const Vec3& p : mesh.GetPositions())
  {
    lo = { std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z) };
    hi = { std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z) };
  }
  auto spread = [](std::uint64_t x)
  {
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffULL;
    x = (x | x << 16) & 0x1f0000ff0000ffULL;
    x = (x | x << 8) & 0x100f00f00f00f00fULL;
    x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2) & 0x1249249249249249ULL;
    return x;
  };
  auto quantize = [](double v, double a, double b)
  {
    const double s = b > a ? (v - a) / (b - a) : 0.0;
    return static_cast<std::uint64_t>(std::min(std::max(s, 0.0), 1.0) * 2097151.0);
  };
  for (int v = 0; v < nv; ++v)
  {
    const Vec3& p = mesh.GetPosition(v);
    keys[v] = { spread(quantize(p.x, lo.x, hi.x)) | spread(quantize(p.y, lo.y, hi.y)) << 1 |
        spread(quantize(p.z, lo.z, hi.z)) << 2,
      v };
  }
  std::sort(keys.begin(), keys.end());
  this->Internal.resize(nv);
  this->External.resize(nv);
  for (int i = 0; i < nv; ++i)
  {
    this->External[i] = keys[i].second;
    this->Internal[keys[i].second] = i;
  }

  this->Offsets.assign(nv + 1, 0);
  this->Nodes.resize(nv);
  // Each vertex lists the other two corners of every usable triangle around it, deduplicated
  // (an interior edge is seen from both of its triangles).
  std::vector<int> row;
  for (int i = 0; i < nv; ++i)
  {
    const int v = this->External[i];
    row.clear();
    for (int corner : mesh.GetVertexCorners(v))
    {
      const int t = corner / 3, k = corner % 3;
      if (!mesh.IsUsable(t))
      {
        continue;
      }
      const Triangle& tri = mesh.GetTriangle(t);
      row.push_back(tri[(k + 1) % 3]);
      row.push_back(tri[(k + 2) % 3]);
    }
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    const Vec3& p = mesh.GetPosition(v);
    this->Nodes[i].Position = p;
    this->Nodes[i].Seen = 0;
    for (int w : row)
    {
      this->Neighbors.push_back(this->Internal[w]);
      this->EdgeCosts.push_back(Distance(p, mesh.GetPosition(w)));
    }
    this->Offsets[i + 1] = static_cast<int>(this->Neighbors.size());
  }
}

//------------------------------------------------------------------------------
std::uint64_t EdgeGraphSearch::RadixQueue::Bits(double key)
{
  // Order-preserving map of doubles to unsigned integers.
  std::uint64_t b;
  std::memcpy(&b, &key, sizeof b);
  return (b >> 63) ? ~b : (b | (std::uint64_t(1) << 63));
}

void EdgeGraphSearch::RadixQueue::Clear()
{
  for (auto& bucket : this->Buckets)
  {
    bucket.clear();
  }
  this->Last = -std::numeric_limits<double>::infinity();
  this->LastBits = 0;
  this->Size = 0;
}

void EdgeGraphSearch::RadixQueue::Push(double key, int vertex)
{
  if (!(key >= this->Last))
  {
    key = this->Last; // rounding noise of a reduced arc length of zero
  }
  const std::uint64_t x = Bits(key) ^ this->LastBits;
  const int bucket = x == 0 ? 0 : 64 - __builtin_clzll(x);
  this->Buckets[bucket].emplace_back(key, vertex);
  ++this->Size;
}

const std::pair<double, int>& EdgeGraphSearch::RadixQueue::Top()
{
  if (this->Buckets[0].empty())
  {
    int i = 1;
    while (this->Buckets[i].empty())
    {
      ++i;
    }
    std::vector<std::pair<double, int>>& source = this->Buckets[i];
    double smallest = source.front().first;
    for (const auto& e : source)
    {
      smallest = std::min(smallest, e.first);
    }
    this->Last = smallest;
    this->LastBits = Bits(smallest);
    for (const auto& e : source)
    {
      const std::uint64_t x = Bits(e.first) ^ this->LastBits;
      this->Buckets[x == 0 ? 0 : 64 - __builtin_clzll(x)].push_back(e);
    }
    source.clear();
  }
  return this->Buckets[0].back();
}

void EdgeGraphSearch::RadixQueue::Pop()
{
  this->Top();
  this->Buckets[0].pop_back();
  --this->Size;
}

//------------------------------------------------------------------------------
void EdgeGraphSearch::SetNumberOfLandmarks(int n)
{
  n = std::max(0, n);
  if (n != this->LandmarkCount)
  {
    this->LandmarkCount = n;
    this->Landmarks.clear();
    this->Landmarks.shrink_to_fit();
    this->LandmarkSeconds = 0;
    this->SettledSinceStart = 0;
  }
}

//------------------------------------------------------------------------------
void EdgeGraphSearch::LandmarkDistances(const std::vector<int>& sources,
  std::vector<float>& distance)
{
  const float infinity = std::numeric_limits<float>::infinity();
  distance.assign(this->Nodes.size(), infinity);
  RadixQueue heap; // keys (floats, exact as doubles) never drop below the last one taken
  heap.Clear();
  for (int s : sources)
  {
    distance[s] = 0.0f;
    heap.Push(0.0, s);
  }
  while (!heap.Empty())
  {
    const int u = heap.Top().second;
    const float du = static_cast<float>(heap.Top().first);
    heap.Pop();
    if (du > distance[u])
    {
      continue;
    }
    for (int i = this->Offsets[u], end = this->Offsets[u + 1]; i < end; ++i)
    {
      const int w = this->Neighbors[i];
      // Rounded down: the stored value never exceeds d(u) + |uw|, so the table is exactly
      // 1-Lipschitz along edges (what keeps the potentials consistent), and sums never drop
      // below d(u), so the search stays monotone.
      const double sum = static_cast<double>(du) + this->EdgeCosts[i];
      float d = static_cast<float>(sum);
      if (static_cast<double>(d) > sum) // then d > 0: the next float down
      {
        std::uint32_t bits;
        std::memcpy(&bits, &d, sizeof bits);
        --bits;
        std::memcpy(&d, &bits, sizeof d);
      }
      if (d < distance[w])
      {
        distance[w] = d;
        heap.Push(d, w);
      }
    }
  }
}

//------------------------------------------------------------------------------
// Farthest-point landmarks, per connected component: the first is the vertex farthest from an
// arbitrary one, each next one the vertex farthest from all chosen so far.
void EdgeGraphSearch::BuildLandmarks()
{
  const int k = this->LandmarkCount;
  const int nv = static_cast<int>(this->Nodes.size());
  if (k == 0 || nv == 0 || !this->Landmarks.empty())
  {
    return;
  }
#if defined(CLOCK_THREAD_CPUTIME_ID)
  auto now = []()
  {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  };
#else
  auto now = []() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; };
#endif
  const double t0 = now();

  // Vertex components of the edge graph.
  std::vector<int> component(nv, -1), stack, representatives;
  for (int v = 0; v < nv; ++v)
  {
    if (component[v] >= 0)
    {
      continue;
    }
    const int c = static_cast<int>(representatives.size());
    representatives.push_back(v);
    component[v] = c;
    stack.assign(1, v);
    while (!stack.empty())
    {
      const int u = stack.back();
      stack.pop_back();
      for (int i = this->Offsets[u], end = this->Offsets[u + 1]; i < end; ++i)
      {
        const int w = this->Neighbors[i];
        if (component[w] < 0)
        {
          component[w] = c;
          stack.push_back(w);
        }
      }
    }
  }
  const int nc = static_cast<int>(representatives.size());
  std::vector<float> distance, nearest;
  std::vector<int> sources;
  std::vector<std::pair<float, int>> farthest;
  auto farthestPerComponent = [&](const std::vector<float>& d)
  {
    farthest.assign(nc, { -1.0f, -1 });
    for (int v = 0; v < nv; ++v)
    {
      std::pair<float, int>& f = farthest[component[v]];
      if (d[v] > f.first)
      {
        f = { d[v], v };
      }
    }
    sources.clear();
    for (const auto& f : farthest)
    {
      sources.push_back(f.second);
    }
  };
  this->LandmarkDistances(representatives, nearest);
  this->Landmarks.assign(static_cast<std::size_t>(nv) * k, 0.0f);
  for (int l = 0; l < k; ++l)
  {
    farthestPerComponent(nearest);
    this->LandmarkDistances(sources, distance);
    for (int v = 0; v < nv; ++v)
    {
      this->Landmarks[static_cast<std::size_t>(v) * k + l] = distance[v];
      nearest[v] = l == 0 ? distance[v] : std::min(nearest[v], distance[v]);
    }
  }
  this->LandmarkSeconds = now() - t0;
}

//------------------------------------------------------------------------------
void EdgeGraphSearch::NextGeneration()
{
  if (this->Generation == std::numeric_limits<std::uint32_t>::max())
  {
    for (Node& n : this->Nodes)
    {
      n.Seen = 0;
    }
    this->Generation = 0;
  }
  ++this->Generation;
}

namespace
{
//------------------------------------------------------------------------------
// FindPath's landmarks (k of them per vertex in `landmarks`): the `activeLandmarks` with the
// best bounds on the distance between the ends (`active`), and per active landmark the hi/lo
// bounds of the end, then of the start (`bounds`; see FindPath).
void SelectActiveLandmarks(const std::vector<float>& landmarks,
  const std::vector<int>& internal,
  int k,
  int activeLandmarks,
  const std::vector<EdgeGraphSearch::Terminal>& sources,
  const std::vector<EdgeGraphSearch::Terminal>& targets,
  std::vector<std::pair<double, int>>& scores,
  std::vector<int>& active,
  std::vector<double>& bounds)
{
  using Terminal = EdgeGraphSearch::Terminal;
  auto value = [&](const Terminal& terminal, int l)
  { return static_cast<double>(landmarks[std::size_t(internal[terminal.Vertex]) * k + l]); };
  scores.clear();
  for (int l = 0; l < k; ++l)
  {
    double hi = -std::numeric_limits<double>::infinity();
    double lo = std::numeric_limits<double>::infinity();
    for (const Terminal& terminal : targets)
    {
      hi = std::max(hi, value(terminal, l) - terminal.Cost);
      lo = std::min(lo, value(terminal, l) + terminal.Cost);
    }
    double score = std::numeric_limits<double>::infinity();
    for (const Terminal& terminal : sources)
    {
      const double d = value(terminal, l);
      score = std::min(score, terminal.Cost + std::max(d - hi, lo - d));
    }
    scores.emplace_back(-score, l);
  }
  const int count = std::min(k, activeLandmarks);
  std::partial_sort(scores.begin(), scores.begin() + count, scores.end());
  for (int a = 0; a < count; ++a)
  {
    const int l = scores[a].second;
    active.push_back(l);
    for (int side = 0; side < 2; ++side)
    {
      double hi = -std::numeric_limits<double>::infinity();
      double lo = std::numeric_limits<double>::infinity();
      for (const Terminal& terminal : side == 0 ? targets : sources)
      {
        hi = std::max(hi, value(terminal, l) - terminal.Cost);
        lo = std::min(lo, value(terminal, l) + terminal.Cost);
      }
      bounds.push_back(hi);
      bounds.push_back(lo);
    }
  }
}

} // namespace

//------------------------------------------------------------------------------
// Bidirectional A* with the average potential p(v) = (pi_end(v) - pi_start(v)) / 2, where
// pi_end(v) bounds d(v, to) from below (the larger of |v - to| and the landmark bounds) and
// pi_start(v) bounds d(from, v). Both are 1-Lipschitz along every edge, so p is too: the
// forward search orders vertices by g_f(v) + p(v), the backward one by g_b(v) - p(v), and both
// are Dijkstra searches on the same non-negative reduced arc lengths, so the classic
// bidirectional stopping rule applies: once the two smallest keys add up to at least the best
// complete path seen (mu), no shorter path exists. The virtual start and end nodes take any
// potentials that keep their arcs non-negative (there always are some: each has arcs one way
// only); those offsets cancel, which is why the rule reads minF + minB >= mu. Tight bounds
// only make the search smaller; exactness needs only the Lipschitz property.
double EdgeGraphSearch::FindPath(const std::vector<Terminal>& sources,
  const Vec3& from,
  const std::vector<Terminal>& targets,
  const Vec3& to,
  std::vector<int>& vertices)
{
  static_assert(sizeof(Node) == 64, "one cache line per vertex");
  vertices.clear();
  if (this->LandmarkCount > 0 && this->Landmarks.empty() &&
    this->SettledSinceStart >=
      this->BuildThreshold * (this->LandmarkCount + 1) * static_cast<double>(this->Nodes.size()))
  {
    this->BuildLandmarks();
  }
  this->LastSettled = 0;
  this->NextGeneration();
  const std::uint32_t gen = this->Generation;

  // Landmark bounds of the two ends: d(v, end) >= max(d_l(v) - hi, lo - d_l(v)) with
  // hi = max over targets of d_l(t) - cost(t), lo = min of d_l(t) + cost(t) (likewise for the
  // start). Only the landmarks with the best bounds on d(start, end) take part (the others
  // mostly give weaker bounds and cost time at every vertex).
  const int k = this->Landmarks.empty() ? 0 : this->LandmarkCount;
  this->Active.clear();
  this->Bounds.clear();
  if (k > 0)
  {
    SelectActiveLandmarks(this->Landmarks,
      this->Internal,
      k,
      this->ActiveLandmarks,
      sources,
      targets,
      this->Scores,
      this->Active,
      this->Bounds);
  }
  const int na = static_cast<int>(this->Active.size());
  const int* activeList = this->Active.data();
  const double* bounds = this->Bounds.data();
  const float* landmarks = this->Landmarks.data();
  auto potential = [&](int v, const Node& n)
  {
    double toEnd = Distance(n.Position, to), fromStart = Distance(n.Position, from);
    const float* d = landmarks + static_cast<std::size_t>(v) * k;
    for (int a = 0; a < na; ++a)
    {
      const double x = d[activeList[a]];
      const double* b = bounds + 4 * a;
      toEnd = std::max(toEnd, std::max(x - b[0], b[1] - x));
      fromStart = std::max(fromStart, std::max(x - b[2], b[3] - x));
    }
    return 0.5 * (toEnd - fromStart);
  };
  auto node = [&](int v) -> Node&
  {
    Node& n = this->Nodes[v];
    if (n.Seen != gen)
    {
      n.Seen = gen;
      n.SeenMask = n.ClosedMask = 0;
      n.Potential = potential(v, n);
    }
    return n;
  };

  double mu = std::numeric_limits<double>::infinity();
  int meetA = -1, meetB = -1; // best path: forward chain to meetA, arc, backward chain from meetB
  for (int side = 0; side < 2; ++side)
  {
    RadixQueue& heap = this->Heaps[side];
    heap.Clear();
    const double sign = side == 0 ? 1.0 : -1.0;
    const int other = 1 - side;
    for (const Terminal& terminal : side == 0 ? sources : targets)
    {
      const int v = this->Internal[terminal.Vertex];
      Node& n = node(v);
      if ((n.SeenMask & (1 << side)) && n.Cost[side] <= terminal.Cost)
      {
        continue;
      }
      n.SeenMask |= 1 << side;
      n.Cost[side] = terminal.Cost;
      n.Parent[side] = -1;
      heap.Push(terminal.Cost + sign * n.Potential, v);
      if ((n.SeenMask & (1 << other)) && n.Cost[0] + n.Cost[1] < mu)
      {
        mu = n.Cost[0] + n.Cost[1];
        meetA = meetB = v;
      }
    }
  }

  for (;;)
  {
    // Drop stale tops (vertices already settled on that side) so the bounds are tight.
    for (int side = 0; side < 2; ++side)
    {
      RadixQueue& heap = this->Heaps[side];
      while (!heap.Empty() && (this->Nodes[heap.Top().second].ClosedMask & (1 << side)))
      {
        heap.Pop();
      }
    }
    if (this->Heaps[0].Empty() || this->Heaps[1].Empty())
    {
      break; // one side exhausted its component: mu (if finite) is final
    }
    const double minF = this->Heaps[0].Top().first, minB = this->Heaps[1].Top().first;
    if (minF + minB >= mu)
    {
      break;
    }
    const int side = minF <= minB ? 0 : 1;
    const int other = 1 - side;
    const double sign = side == 0 ? 1.0 : -1.0;
    RadixQueue& heap = this->Heaps[side];
    const int u = heap.Top().second;
    heap.Pop();
    Node& nu = this->Nodes[u];
    nu.ClosedMask |= 1 << side;
    ++this->LastSettled;
    const double gu = nu.Cost[side];
    for (int i = this->Offsets[u], end = this->Offsets[u + 1]; i < end; ++i)
    {
      const int w = this->Neighbors[i];
      const double g = gu + this->EdgeCosts[i];
      Node& nw = node(w);
      if (nw.SeenMask & (1 << other))
      {
        const double total = g + nw.Cost[other];
        if (total < mu)
        {
          mu = total;
          meetA = side == 0 ? u : w;
          meetB = side == 0 ? w : u;
        }
      }
      if ((nw.ClosedMask & (1 << side)) || ((nw.SeenMask & (1 << side)) && nw.Cost[side] <= g))
      {
        continue;
      }
      nw.SeenMask |= 1 << side;
      nw.Cost[side] = g;
      nw.Parent[side] = u;
      heap.Push(g + sign * nw.Potential, w);
    }
  }
  this->SettledSinceStart += this->LastSettled;
  if (meetA < 0)
  {
    return -1.0;
  }
  // Parents only ever move to cheaper chains, so both chains stay valid and no longer than mu.
  // The bound on their length guards against cycles through zero-length edges.
  const int limit = this->Mesh.GetNumberOfVertices();
  for (int v = meetA; v >= 0 && static_cast<int>(vertices.size()) <= limit;
       v = this->Nodes[v].Parent[0])
  {
    vertices.push_back(v);
  }
  std::reverse(vertices.begin(), vertices.end());
  for (int v = meetB == meetA ? this->Nodes[meetB].Parent[1] : meetB;
       v >= 0 && static_cast<int>(vertices.size()) <= 2 * limit;
       v = this->Nodes[v].Parent[1])
  {
    vertices.push_back(v);
  }
  if (static_cast<int>(vertices.size()) > 2 * limit)
  {
    vertices.clear();
    return -1.0;
  }
  for (int& v : vertices)
  {
    v = this->External[v];
  }
  return mu;
}

} // namespace boolsurf
