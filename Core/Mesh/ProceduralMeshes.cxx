#include "Mesh/ProceduralMeshes.h"

#include <cmath>
#include <map>
#include <random>
#include <utility>

namespace boolsurf
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

// Splits every quad (a b c d, counter-clockwise seen from outside) into two triangles along
// a-c or b-d.
void AddQuad(MeshData& m, int a, int b, int c, int d, bool diagonalAC)
{
  if (diagonalAC)
  {
    m.Triangles.push_back({ a, b, c });
    m.Triangles.push_back({ a, c, d });
  }
  else
  {
    m.Triangles.push_back({ a, b, d });
    m.Triangles.push_back({ b, c, d });
  }
}
} // namespace

//------------------------------------------------------------------------------
MeshData MakeFlatSquare(int n, double size, double jitter, std::uint32_t seed)
{
  MeshData m;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> offset(-jitter, jitter);
  std::bernoulli_distribution coin(0.5);
  const double h = size / n;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      // i * size / n rather than i * h: with size 1 the grid is exactly i / n.
      double x = i * size / n, y = j * size / n;
      if (jitter > 0 && i > 0 && i < n && j > 0 && j < n)
      {
        x += offset(rng) * h;
        y += offset(rng) * h;
      }
      m.Positions.push_back({ x, y, 0.0 });
    }
  }
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const int a = j * (n + 1) + i;
      const int q[4] = { a, a + 1, a + n + 2, a + n + 1 };
      bool ac = jitter > 0 ? coin(rng) : true;
      // Jitter can make a cell non-convex; then only the diagonal through its reflex corner
      // gives two counter-clockwise triangles (the other would fold the mesh over itself).
      auto ccw = [&](int x, int y, int z)
      {
        const Vec3 &p = m.Positions[x], &r = m.Positions[y], &t = m.Positions[z];
        return (r.x - p.x) * (t.y - p.y) - (t.x - p.x) * (r.y - p.y) > 0;
      };
      const bool acValid = ccw(q[0], q[1], q[2]) && ccw(q[0], q[2], q[3]);
      const bool bdValid = ccw(q[0], q[1], q[3]) && ccw(q[1], q[2], q[3]);
      if (ac ? !acValid : !bdValid)
      {
        ac = !ac;
      }
      AddQuad(m, q[0], q[1], q[2], q[3], ac);
    }
  }
  return m;
}

//------------------------------------------------------------------------------
MeshData MakeIcosphere(int levels, double radius)
{
  MeshData m;
  const double p = (1.0 + std::sqrt(5.0)) / 2.0;
  const double base[12][3] = { { -1, p, 0 },
    { 1, p, 0 },
    { -1, -p, 0 },
    { 1, -p, 0 },
    { 0, -1, p },
    { 0, 1, p },
    { 0, -1, -p },
    { 0, 1, -p },
    { p, 0, -1 },
    { p, 0, 1 },
    { -p, 0, -1 },
    { -p, 0, 1 } };
  for (const auto& b : base)
  {
    Vec3 v{ b[0], b[1], b[2] };
    m.Positions.push_back((radius / Length(v)) * v);
  }
  m.Triangles = { { 0, 11, 5 },
    { 0, 5, 1 },
    { 0, 1, 7 },
    { 0, 7, 10 },
    { 0, 10, 11 },
    { 1, 5, 9 },
    { 5, 11, 4 },
    { 11, 10, 2 },
    { 10, 7, 6 },
    { 7, 1, 8 },
    { 3, 9, 4 },
    { 3, 4, 2 },
    { 3, 2, 6 },
    { 3, 6, 8 },
    { 3, 8, 9 },
    { 4, 9, 5 },
    { 2, 4, 11 },
    { 6, 2, 10 },
    { 8, 6, 7 },
    { 9, 8, 1 } };
  for (int l = 0; l < levels; ++l)
  {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b)
    {
      auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = midpoint.find(key);
      if (it != midpoint.end())
      {
        return it->second;
      }
      Vec3 v = 0.5 * (m.Positions[a] + m.Positions[b]);
      m.Positions.push_back((radius / Length(v)) * v);
      const int id = static_cast<int>(m.Positions.size()) - 1;
      midpoint.emplace(key, id);
      return id;
    };
    std::vector<std::array<int, 3>> next;
    next.reserve(4 * m.Triangles.size());
    for (const auto& t : m.Triangles)
    {
      const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      next.push_back({ t[0], ab, ca });
      next.push_back({ t[1], bc, ab });
      next.push_back({ t[2], ca, bc });
      next.push_back({ ab, bc, ca });
    }
    m.Triangles = std::move(next);
  }
  return m;
}

//------------------------------------------------------------------------------
MeshData MakeTorus(double R, double r, int nu, int nv)
{
  MeshData m;
  for (int i = 0; i < nu; ++i)
  {
    const double u = 2 * Pi * i / nu;
    for (int j = 0; j < nv; ++j)
    {
      const double v = 2 * Pi * j / nv;
      m.Positions.push_back({ (R + r * std::cos(v)) * std::cos(u),
        (R + r * std::cos(v)) * std::sin(u),
        r * std::sin(v) });
    }
  }
  auto id = [&](int i, int j) { return (i % nu) * nv + (j % nv); };
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      // u grows counter-clockwise around z, v grows from outside to top: (du, dv) is
      // counter-clockwise seen from outside.
      AddQuad(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), true);
    }
  }
  return m;
}

//------------------------------------------------------------------------------
MeshData MakeOpenCylinder(double radius, double height, int around, int along)
{
  MeshData m;
  for (int j = 0; j <= along; ++j)
  {
    for (int i = 0; i < around; ++i)
    {
      const double a = 2 * Pi * i / around;
      m.Positions.push_back(
        { radius * std::cos(a), radius * std::sin(a), height * j / static_cast<double>(along) });
    }
  }
  auto id = [&](int i, int j) { return j * around + (i % around); };
  for (int j = 0; j < along; ++j)
  {
    for (int i = 0; i < around; ++i)
    {
      AddQuad(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), (i + j) % 2 == 0);
    }
  }
  return m;
}

//------------------------------------------------------------------------------
MeshData MakeBoxLateral(double a, double b, double h, int n)
{
  MeshData m;
  // Walk the rectangle's perimeter counter-clockwise seen from +z; 4n samples around.
  const Vec3 corners[5] = { { 0, 0, 0 }, { a, 0, 0 }, { a, b, 0 }, { 0, b, 0 }, { 0, 0, 0 } };
  const int around = 4 * n;
  for (int j = 0; j <= n; ++j)
  {
    for (int s = 0; s < 4; ++s)
    {
      for (int i = 0; i < n; ++i)
      {
        const double f = static_cast<double>(i) / n;
        Vec3 p = (1 - f) * corners[s] + f * corners[s + 1];
        p.z = h * j / static_cast<double>(n);
        m.Positions.push_back(p);
      }
    }
  }
  auto id = [&](int i, int j) { return j * around + (i % around); };
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < around; ++i)
    {
      AddQuad(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), true);
    }
  }
  return m;
}

} // namespace boolsurf
