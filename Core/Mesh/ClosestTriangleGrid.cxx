#include "Mesh/ClosestTriangleGrid.h"

#include <algorithm>
#include <cmath>

namespace boolsurf
{

namespace
{

double Distance2(const Vec3& a, const Vec3& b)
{
  const Vec3 d = a - b;
  return Dot(d, d);
}

} // namespace

//------------------------------------------------------------------------------
Vec3 ClosestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  // Which Voronoi region of the triangle (a corner, an edge, the face) p projects into,
  // from the signs of dot products with the edges.
  const Vec3 ab = b - a, ac = c - a;
  const double d1 = Dot(ab, p - a), d2 = Dot(ac, p - a);
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    return a;
  }
  const double d3 = Dot(ab, p - b), d4 = Dot(ac, p - b);
  if (d3 >= 0.0 && d4 <= d3)
  {
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 && d1 - d3 > 0.0)
  {
    return a + (d1 / (d1 - d3)) * ab;
  }
  const double d5 = Dot(ab, p - c), d6 = Dot(ac, p - c);
  if (d6 >= 0.0 && d5 <= d6)
  {
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 && d2 - d6 > 0.0)
  {
    return a + (d2 / (d2 - d6)) * ac;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 && (d4 - d3) + (d5 - d6) > 0.0)
  {
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0) || !std::isfinite(sum))
  {
    // A degenerate (flat) triangle: the closest of its three sides.
    Vec3 best = ClosestPointOnSegment(a, b, p);
    for (const Vec3& q : { ClosestPointOnSegment(b, c, p), ClosestPointOnSegment(c, a, p) })
    {
      if (Distance2(p, q) < Distance2(p, best))
      {
        best = q;
      }
    }
    return best;
  }
  return a + (vb / sum) * ab + (vc / sum) * ac;
}

//------------------------------------------------------------------------------
ClosestTriangleGrid::ClosestTriangleGrid(const TriangleMesh& mesh)
  : Mesh(mesh)
{
  const int nt = mesh.GetNumberOfTriangles();
  Vec3 lo{ std::numeric_limits<double>::infinity(),
    std::numeric_limits<double>::infinity(),
    std::numeric_limits<double>::infinity() };
  Vec3 hi = -1.0 * lo;
  double edgeSum = 0.0;
  for (int t = 0; t < nt; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Vec3& q = mesh.GetCornerPosition(t, k);
      lo = { std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z) };
      hi = { std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z) };
      edgeSum += Distance(q, mesh.GetCornerPosition(t, (k + 1) % 3));
    }
  }
  if (nt == 0)
  {
    this->CellStart.assign(2, 0);
    return;
  }
  this->Origin = lo;
  const Vec3 extent = hi - lo;
  // Cells of about twice the mean edge, so a triangle meets a few cells, and at most four
  // cells per triangle overall (a mesh spread thin in a large box).
  double step = 2.0 * edgeSum / (3.0 * nt);
  const double longest = std::max(extent.x, std::max(extent.y, extent.z));
  if (!(step > 0.0))
  {
    step = longest > 0.0 ? longest : 1.0;
  }
  auto cellsFor = [&](double h)
  {
    double cells = 1.0;
    for (int a = 0; a < 3; ++a)
    {
      cells *= std::floor(extent[a] / h) + 1.0;
    }
    return cells;
  };
  while (cellsFor(step) > 4.0 * nt + 8.0)
  {
    step *= 1.25;
  }
  this->Step = step;
  for (int a = 0; a < 3; ++a)
  {
    this->Dims[a] = static_cast<int>(std::floor(extent[a] / step)) + 1;
  }
  const std::size_t cells = static_cast<std::size_t>(this->Dims[0]) * this->Dims[1] * this->Dims[2];
  this->CellStart.assign(cells + 1, 0);
  auto forCells = [&](int t, auto&& visit)
  {
    std::array<int, 3> from, to;
    for (int a = 0; a < 3; ++a)
    {
      double mn = mesh.GetCornerPosition(t, 0)[a], mx = mn;
      for (int k = 1; k < 3; ++k)
      {
        mn = std::min(mn, mesh.GetCornerPosition(t, k)[a]);
        mx = std::max(mx, mesh.GetCornerPosition(t, k)[a]);
      }
      from[a] = this->Coordinate(mn, a);
      to[a] = this->Coordinate(mx, a);
    }
    for (int k = from[2]; k <= to[2]; ++k)
      for (int j = from[1]; j <= to[1]; ++j)
        for (int i = from[0]; i <= to[0]; ++i)
          visit(this->CellIndex(i, j, k));
  };
  for (int t = 0; t < nt; ++t)
  {
    forCells(t, [&](int c) { ++this->CellStart[c + 1]; });
  }
  for (std::size_t c = 0; c < cells; ++c)
  {
    this->CellStart[c + 1] += this->CellStart[c];
  }
  this->Triangles.resize(this->CellStart[cells]);
  std::vector<int> fill(this->CellStart.begin(), this->CellStart.end() - 1);
  for (int t = 0; t < nt; ++t)
  {
    forCells(t, [&](int c) { this->Triangles[fill[c]++] = t; });
  }
}

//------------------------------------------------------------------------------
int ClosestTriangleGrid::Coordinate(double x, int axis) const
{
  const double cell = std::floor((x - this->Origin[axis]) / this->Step);
  return static_cast<int>(std::min<double>(this->Dims[axis] - 1, std::max(0.0, cell)));
}

//------------------------------------------------------------------------------
ClosestTriangleGrid::Hit ClosestTriangleGrid::FindClosest(const Vec3& p) const
{
  Hit best;
  if (this->Triangles.empty() || !IsFinite(p))
  {
    return best;
  }
  const std::array<int, 3> c{
    this->Coordinate(p.x, 0), this->Coordinate(p.y, 1), this->Coordinate(p.z, 2)
  };
  auto test = [&](int cell)
  {
    for (int n = this->CellStart[cell]; n < this->CellStart[cell + 1]; ++n)
    {
      const int t = this->Triangles[n];
      const Vec3 q = ClosestPointOnTriangle(p,
        this->Mesh.GetCornerPosition(t, 0),
        this->Mesh.GetCornerPosition(t, 1),
        this->Mesh.GetCornerPosition(t, 2));
      const double d2 = Distance2(p, q);
      if (d2 < best.Distance2 || (d2 == best.Distance2 && t < best.Triangle))
      {
        best.Triangle = t;
        best.Point = q;
        best.Distance2 = d2;
      }
    }
  };
  const int most = std::max(this->Dims[0], std::max(this->Dims[1], this->Dims[2]));
  for (int r = 0; r <= most; ++r)
  {
    // The shell of cells at Chebyshev distance r from c, inside the grid.
    const int k0 = std::max(0, c[2] - r), k1 = std::min(this->Dims[2] - 1, c[2] + r);
    const int j0 = std::max(0, c[1] - r), j1 = std::min(this->Dims[1] - 1, c[1] + r);
    const int i0 = std::max(0, c[0] - r), i1 = std::min(this->Dims[0] - 1, c[0] + r);
    for (int k = k0; k <= k1; ++k)
    {
      for (int j = j0; j <= j1; ++j)
      {
        const bool face = std::abs(k - c[2]) == r || std::abs(j - c[1]) == r;
        if (face)
        {
          for (int i = i0; i <= i1; ++i)
            test(this->CellIndex(i, j, k));
        }
        else
        {
          if (c[0] - r >= 0)
            test(this->CellIndex(c[0] - r, j, k));
          if (c[0] + r < this->Dims[0]) // r > 0 here: at r = 0 every row is a face row
            test(this->CellIndex(c[0] + r, j, k));
        }
      }
    }
    // Cells beyond the shell are at least this far from p (infinitely when none is left).
    double bound = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a)
    {
      if (c[a] - r > 0)
        bound = std::min(bound, p[a] - (this->Origin[a] + (c[a] - r) * this->Step));
      if (c[a] + r + 1 < this->Dims[a])
        bound = std::min(bound, this->Origin[a] + (c[a] + r + 1) * this->Step - p[a]);
    }
    if (bound == std::numeric_limits<double>::infinity() ||
      (bound > 0.0 && best.Distance2 < bound * bound))
    {
      break;
    }
  }
  return best;
}

} // namespace boolsurf
