#include "Distributed/PartialSurface.h"

#include <algorithm>

namespace boolsurf
{

//------------------------------------------------------------------------------
PartialSurface::PartialSurface(const PieceInput& piece)
{
  for (size_t i = 0; i < piece.Positions.size(); ++i)
  {
    this->Points[piece.PointGlobalIds[i]] = piece.Positions[i];
  }
  for (size_t t = 0; t < piece.Triangles.size(); ++t)
  {
    std::array<int, 3> corners;
    for (int k = 0; k < 3; ++k)
    {
      corners[k] = piece.PointGlobalIds[piece.Triangles[t][k]];
    }
    this->Triangles[piece.TriangleGlobalIds[t]] = corners;
    if (!piece.Ghost[t])
    {
      this->Owned.insert(piece.TriangleGlobalIds[t]);
      this->Whole.insert(corners.begin(), corners.end());
    }
  }
}

//------------------------------------------------------------------------------
bool PartialSurface::Add(const FetchedTriangles& fetched, std::string& error)
{
  for (size_t i = 0; i < fetched.PointGlobalIds.size(); ++i)
  {
    this->Points.emplace(fetched.PointGlobalIds[i], fetched.Positions[i]);
  }
  for (size_t t = 0; t < fetched.TriangleGlobalIds.size(); ++t)
  {
    const int g = fetched.TriangleGlobalIds[t];
    for (int v : fetched.Corners[t])
    {
      if (!this->Points.count(v))
      {
        error = "fetched triangle " + std::to_string(g) + " names point " + std::to_string(v) +
          " without its position";
        return false;
      }
    }
    const auto inserted = this->Triangles.emplace(g, fetched.Corners[t]);
    if (!inserted.second && inserted.first->second != fetched.Corners[t])
    {
      error = "fetched triangle " + std::to_string(g) + " has other corners than the held copy";
      return false;
    }
    this->Fetched += inserted.second ? 1 : 0;
    this->Built = this->Built && !inserted.second;
  }
  for (int v : fetched.WholeVertices)
  {
    const bool added = this->Whole.insert(v).second;
    this->Built = this->Built && !added;
  }
  return true;
}

//------------------------------------------------------------------------------
bool PartialSurface::Build(std::string& error)
{
  if (this->Built)
  {
    return true;
  }
  PieceInput input;
  std::unordered_map<int, int> index;
  for (const auto& entry : this->Triangles)
  {
    Triangle local;
    for (int k = 0; k < 3; ++k)
    {
      const int g = entry.second[k];
      const auto found = index.emplace(g, static_cast<int>(input.Positions.size()));
      if (found.second)
      {
        input.Positions.push_back(this->Points.at(g));
        input.PointGlobalIds.push_back(g);
      }
      local[k] = found.first->second;
    }
    input.Triangles.push_back(local);
    input.TriangleGlobalIds.push_back(entry.first);
    input.Ghost.push_back(this->Owned.count(entry.first) ? 0 : 1);
  }
  if (!BuildPieceMesh(input, this->Piece, error))
  {
    return false;
  }
  this->WholeLocal.assign(this->Piece.GlobalVertex.size(), 0);
  for (size_t v = 0; v < this->WholeLocal.size(); ++v)
  {
    this->WholeLocal[v] = this->Whole.count(this->Piece.GlobalVertex[v]) ? 1 : 0;
  }
  this->Exact.assign(this->Piece.Mesh.GetNumberOfTriangles(), 0);
  this->Built = true;
  return true;
}

//------------------------------------------------------------------------------
bool PartialSurface::IsExactTriangle(int t) const
{
  char& known = this->Exact[t];
  if (known == 0)
  {
    const TriangleMesh& mesh = this->Piece.Mesh;
    known = 1;
    for (int v : mesh.GetTriangle(t))
    {
      if (!this->WholeLocal[v])
      {
        known = 2;
        break;
      }
      for (int corner : mesh.GetVertexCorners(v))
      {
        for (int w : mesh.GetTriangle(corner / 3))
        {
          known = this->WholeLocal[w] ? known : 2;
        }
      }
    }
  }
  return known == 1;
}

//------------------------------------------------------------------------------
// A read triangle is exact when its corners are whole (its neighbours and their corner order
// are the surface's) and so are the corners of the triangles round them: the exact search
// emits windows from a corner across the far edges of its fan, and the straightener sweeps
// the fans of the strip's corners, so their neighbours must be the surface's too.
void PartialSurface::FindMissing(const std::vector<int>& reads, std::vector<int>& missing) const
{
  missing.clear();
  const TriangleMesh& mesh = this->Piece.Mesh;
  const int nt = mesh.GetNumberOfTriangles();
  this->Seen.assign(static_cast<size_t>(nt) + this->WholeLocal.size(), 0);
  char* seenTriangle = this->Seen.data();
  char* seenVertex = this->Seen.data() + nt;
  auto need = [&](int v)
  {
    if (!seenVertex[v])
    {
      seenVertex[v] = 1;
      missing.push_back(this->Piece.GlobalVertex[v]);
    }
  };
  for (int t : reads)
  {
    if (t < 0 || t >= nt || seenTriangle[t])
    {
      continue;
    }
    seenTriangle[t] = 1;
    for (int v : mesh.GetTriangle(t))
    {
      if (!this->WholeLocal[v])
      {
        need(v);
        continue;
      }
      for (int corner : mesh.GetVertexCorners(v))
      {
        for (int w : mesh.GetTriangle(corner / 3))
        {
          if (!this->WholeLocal[w])
          {
            need(w);
          }
        }
      }
    }
  }
  std::sort(missing.begin(), missing.end());
}

} // namespace boolsurf
