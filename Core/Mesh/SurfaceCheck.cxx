#include "Mesh/SurfaceCheck.h"

#include <algorithm>
#include <sstream>

namespace boolsurf
{

//------------------------------------------------------------------------------
bool SurfaceCheckResult::HasErrors() const
{
  return std::any_of(this->Problems.begin(),
    this->Problems.end(),
    [](const SurfaceProblem& p) { return p.Level == Severity::Error; });
}

//------------------------------------------------------------------------------
bool SurfaceCheckResult::Has(const std::string& kind) const
{
  return this->Find(kind) != nullptr;
}

//------------------------------------------------------------------------------
const SurfaceProblem* SurfaceCheckResult::Find(const std::string& kind) const
{
  for (const SurfaceProblem& p : this->Problems)
  {
    if (p.Kind == kind)
    {
      return &p;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
std::string SurfaceCheckResult::ErrorSummary() const
{
  std::string s;
  for (const SurfaceProblem& p : this->Problems)
  {
    if (p.Level == Severity::Error)
    {
      s += (s.empty() ? "" : "\n") + p.Message;
    }
  }
  return s;
}

//------------------------------------------------------------------------------
std::string FormatIds(const std::vector<long long>& ids, int maxIds)
{
  std::ostringstream os;
  const int n = static_cast<int>(ids.size());
  for (int i = 0; i < n && i < maxIds; ++i)
  {
    os << (i ? ", " : "") << ids[i];
  }
  if (n > maxIds)
  {
    os << " ... and " << (n - maxIds) << " more";
  }
  return os.str();
}

//------------------------------------------------------------------------------
SurfaceCheckResult CheckSurface(const TriangleMesh& mesh,
  const MeshTopology& topology,
  const SurfaceCheckOptions& options)
{
  SurfaceCheckResult result;
  const int maxIds = options.MaxIdsInMessage;
  // ids by rvalue reference: callers write `std::to_string(ids.size()) ..., std::move(ids)`,
  // and a by-value parameter could be moved into before the count is taken (the arguments'
  // order of evaluation is unspecified), printing 0.
  auto add =
    [&](const char* kind, Severity level, const std::string& what, std::vector<long long>&& ids)
  {
    SurfaceProblem p;
    p.Kind = kind;
    p.Level = level;
    p.Message = what + (ids.empty() ? "" : ": " + FormatIds(ids, maxIds));
    p.Ids = std::move(ids);
    result.Problems.push_back(std::move(p));
  };

  const int nv = mesh.GetNumberOfVertices();
  const int nt = mesh.GetNumberOfTriangles();
  if (nv == 0 || nt == 0)
  {
    add("EmptyInput",
      Severity::Error,
      "the surface is empty (" + std::to_string(nv) + " points, " + std::to_string(nt) +
        " triangles)",
      {});
    return result;
  }

  std::vector<long long> ids;
  for (int v = 0; v < nv; ++v)
  {
    if (!IsFinite(mesh.GetPosition(v)))
    {
      ids.push_back(v);
    }
  }
  if (!ids.empty())
  {
    add("NonFiniteCoordinates",
      Severity::Error,
      std::to_string(ids.size()) + " point(s) have NaN or infinite coordinates, point ids",
      std::move(ids));
  }

  std::vector<long long> outOfRange, repeated, degenerate;
  for (int t = 0; t < nt; ++t)
  {
    const Triangle& tri = mesh.GetTriangle(t);
    if (!mesh.IsUsable(t))
    {
      bool inRange = true;
      for (int v : tri)
      {
        inRange = inRange && v >= 0 && v < nv;
      }
      (inRange ? repeated : outOfRange).push_back(t);
      continue;
    }
    const Vec3 a = mesh.GetPosition(tri[0]), b = mesh.GetPosition(tri[1]),
               c = mesh.GetPosition(tri[2]);
    if (!IsFinite(a) || !IsFinite(b) || !IsFinite(c))
    {
      continue; // already reported through its points
    }
    const double twiceArea = Length(Cross(b - a, c - a));
    const double longest = std::max({ Dot(b - a, b - a), Dot(c - b, c - b), Dot(a - c, a - c) });
    if (twiceArea <= options.DegenerateTolerance * longest)
    {
      degenerate.push_back(t);
    }
  }
  if (!outOfRange.empty())
  {
    add("InvalidVertexIndex",
      Severity::Error,
      std::to_string(outOfRange.size()) + " triangle(s) use point ids outside [0, " +
        std::to_string(nv) + "), triangle ids",
      std::move(outOfRange));
  }
  if (!repeated.empty())
  {
    add("RepeatedVertexIndex",
      Severity::Error,
      std::to_string(repeated.size()) +
        " triangle(s) use the same point twice (topologically degenerate), triangle ids",
      std::move(repeated));
  }
  if (!degenerate.empty())
  {
    add("DegenerateTriangle",
      Severity::Error,
      std::to_string(degenerate.size()) + " triangle(s) have zero area, triangle ids",
      std::move(degenerate));
  }

  if (!mesh.GetNonManifoldEdges().empty())
  {
    std::ostringstream os;
    int shown = 0;
    for (const NonManifoldEdge& e : mesh.GetNonManifoldEdges())
    {
      if (shown++ == maxIds)
      {
        os << " ... and " << (mesh.GetNonManifoldEdges().size() - maxIds) << " more";
        break;
      }
      os << (shown > 1 ? ", " : "") << "(" << e.V0 << ", " << e.V1 << ") in " << e.Triangles.size()
         << " triangles";
    }
    SurfaceProblem p;
    p.Kind = "NonManifoldEdge";
    p.Message = std::to_string(mesh.GetNonManifoldEdges().size()) +
      " non-manifold edge(s) shared by more than two triangles, edges by point ids: " + os.str();
    for (const NonManifoldEdge& e : mesh.GetNonManifoldEdges())
    {
      p.Ids.push_back(e.V0);
      p.Ids.push_back(e.V1);
    }
    result.Problems.push_back(std::move(p));
    result.IsManifold = false;
  }
  if (!topology.NonManifoldVertices.empty())
  {
    add("NonManifoldVertex",
      Severity::Error,
      std::to_string(topology.NonManifoldVertices.size()) +
        " non-manifold vertex(es) where separate fans of triangles meet, point ids",
      std::vector<long long>(
        topology.NonManifoldVertices.begin(), topology.NonManifoldVertices.end()));
    result.IsManifold = false;
  }
  if (!mesh.GetMisorientedEdges().empty())
  {
    std::ostringstream os;
    int shown = 0;
    std::vector<long long> pairs;
    for (const MisorientedEdge& e : mesh.GetMisorientedEdges())
    {
      pairs.push_back(e.Triangle0);
      pairs.push_back(e.Triangle1);
      if (shown++ < maxIds)
      {
        os << (shown > 1 ? ", " : "") << e.Triangle0 << "/" << e.Triangle1;
      }
    }
    if (shown > maxIds)
    {
      os << " ... and " << (shown - maxIds) << " more";
    }
    SurfaceProblem p;
    p.Kind = "InconsistentOrientation";
    p.Message = std::to_string(mesh.GetMisorientedEdges().size()) +
      " pair(s) of neighbouring triangles are oriented inconsistently (flip one of each), "
      "triangle pairs: " +
      os.str();
    p.Ids = std::move(pairs);
    result.Problems.push_back(std::move(p));
  }
  for (size_t c = 0; c < topology.Components.size(); ++c)
  {
    if (!topology.Components[c].Orientable)
    {
      add("NonOrientable",
        Severity::Error,
        "connected component " + std::to_string(c) + " is not orientable",
        { (long long)c });
    }
  }

  ids.clear();
  for (int v = 0; v < nv; ++v)
  {
    if (mesh.GetVertexCorners(v).size() == 0)
    {
      ids.push_back(v);
    }
  }
  if (!ids.empty())
  {
    add("UnreferencedPoints",
      Severity::Warning,
      std::to_string(ids.size()) + " point(s) are used by no triangle (ignored), point ids",
      std::move(ids));
  }
  return result;
}

} // namespace boolsurf
