// SubdivisionMap: points of a coarse mesh carried onto a 1-to-4 split keep their 3D position on
// a linear split whatever the order of the children and the rotation of their corners; corner
// and edge points stay on the corresponding vertices and edges; a mesh that is not a split of
// the coarse one is a named error.
#include "Mesh/ProceduralMeshes.h"
#include "Mesh/SubdivisionMap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

namespace
{
using namespace boolsurf;

struct Split
{
  std::vector<Vec3> Positions;
  std::vector<Triangle> Triangles;
};

/// The linear 1-to-4 split of `mesh`, children shuffled and their corners rotated by `rng`.
Split LinearSplit(const MeshData& mesh, std::mt19937& rng)
{
  Split s;
  s.Positions = mesh.Positions;
  std::map<std::pair<int, int>, int> midpoint;
  auto mid = [&](int a, int b)
  {
    const auto key = std::minmax(a, b);
    auto it = midpoint.find(key);
    if (it != midpoint.end())
    {
      return it->second;
    }
    const Vec3& p = mesh.Positions[a];
    const Vec3& q = mesh.Positions[b];
    s.Positions.push_back({ 0.5 * (p.x + q.x), 0.5 * (p.y + q.y), 0.5 * (p.z + q.z) });
    const int id = static_cast<int>(s.Positions.size()) - 1;
    midpoint.emplace(key, id);
    return id;
  };
  for (const auto& t : mesh.Triangles)
  {
    const int a = t[0], b = t[1], c = t[2];
    const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    for (Triangle k : { Triangle{ a, ab, ca },
           Triangle{ b, bc, ab },
           Triangle{ c, ca, bc },
           Triangle{ ab, bc, ca } })
    {
      std::rotate(k.begin(), k.begin() + rng() % 3, k.end());
      s.Triangles.push_back(k);
    }
  }
  std::shuffle(s.Triangles.begin(), s.Triangles.end(), rng);
  return s;
}

Vec3 At(const std::vector<Vec3>& positions, const Triangle& t, double u, double v)
{
  const Vec3 &a = positions[t[0]], &b = positions[t[1]], &c = positions[t[2]];
  const double w = 1 - u - v;
  return { w * a.x + u * b.x + v * c.x, w * a.y + u * b.y + v * c.y, w * a.z + u * b.z + v * c.z };
}

} // namespace

TEST(SubdivisionMap, LinearSplitKeepsPositions)
{
  std::mt19937 rng(7);
  const MeshData coarse = MakeIcosphere(2);
  std::vector<Triangle> parent(coarse.Triangles.begin(), coarse.Triangles.end());
  std::vector<Vec3> positions = coarse.Positions;
  std::vector<SurfacePoint> points, original;
  std::uniform_real_distribution<double> unit(0, 1);
  std::uniform_int_distribution<int> triangle(0, static_cast<int>(parent.size()) - 1);
  for (int i = 0; i < 2000; ++i)
  {
    double u = unit(rng), v = unit(rng);
    if (u + v > 1)
    {
      u = 1 - u;
      v = 1 - v;
    }
    // Every few points on a corner, an edge or a child boundary (weight exactly 1/2).
    switch (i % 8)
    {
      case 1:
        u = 0, v = 0;
        break;
      case 2:
        u = 1, v = 0;
        break;
      case 3:
        v = 0;
        break;
      case 4:
        u = 0.5;
        v = std::min(v, 0.5);
        break;
      case 5:
        u = 0.25, v = 0.25;
        break;
      default:
        break;
    }
    points.push_back({ triangle(rng), u, v });
  }
  original = points;
  std::vector<Vec3> expected;
  for (const SurfacePoint& p : points)
  {
    expected.push_back(At(positions, parent[p.Triangle], p.U, p.V));
  }
  MeshData level{ positions, coarse.Triangles };
  for (int step = 0; step < 3; ++step)
  {
    const Split split = LinearSplit(level, rng);
    SubdivisionMap map;
    std::string error;
    ASSERT_TRUE(map.Build(parent, static_cast<int>(positions.size()), split.Triangles, error))
      << error;
    for (SurfacePoint& p : points)
    {
      p = map.Map(p);
      ASSERT_GE(p.U, 0);
      ASSERT_GE(p.V, 0);
      ASSERT_LE(p.U + p.V, 1);
    }
    parent = split.Triangles;
    positions = split.Positions;
    level.Positions = positions;
    level.Triangles.assign(parent.begin(), parent.end());
  }
  ASSERT_EQ(parent.size(), 64 * coarse.Triangles.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    EXPECT_LT(
      Distance(At(positions, parent[points[i].Triangle], points[i].U, points[i].V), expected[i]),
      1e-14)
      << "point " << i << " (triangle " << original[i].Triangle << ", " << original[i].U << ", "
      << original[i].V << ")";
    // A point on a coarse vertex ends on that very vertex (ids of old vertices are kept).
    if (original[i].U == 0 && original[i].V == 0)
    {
      const Triangle& t = parent[points[i].Triangle];
      const int corner = static_cast<int>(coarse.Triangles[original[i].Triangle][0]);
      const double w[3] = { 1 - points[i].U - points[i].V, points[i].U, points[i].V };
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_EQ(w[k], t[k] == corner ? 1.0 : 0.0) << "point " << i;
      }
    }
  }
}

TEST(SubdivisionMap, NotASplitIsANamedError)
{
  std::mt19937 rng(3);
  const MeshData coarse = MakeFlatSquare(3);
  const std::vector<Triangle> parent(coarse.Triangles.begin(), coarse.Triangles.end());
  const int n = static_cast<int>(coarse.Positions.size());
  Split split = LinearSplit(coarse, rng);
  SubdivisionMap map;
  std::string error;
  // Too few triangles.
  std::vector<Triangle> fewer(split.Triangles.begin(), split.Triangles.end() - 1);
  EXPECT_FALSE(map.Build(parent, n, fewer, error));
  EXPECT_NE(error.find("has 71 triangles for 18"), std::string::npos) << error;
  // A child triangle with two old vertices.
  std::vector<Triangle> twoOld = split.Triangles;
  twoOld[0] = { 0, 1, n + 2 };
  EXPECT_FALSE(map.Build(parent, n, twoOld, error));
  EXPECT_NE(error.find("subdivided triangle 0 (0, 1, "), std::string::npos) << error;
  // The split of another mesh (same sizes, different connectivity).
  const MeshData other = MakeFlatSquare(3, 1.0, 0.3, 9);
  Split otherSplit = LinearSplit(other, rng);
  if (other.Triangles != coarse.Triangles)
  {
    EXPECT_FALSE(map.Build(parent, n, otherSplit.Triangles, error));
    EXPECT_NE(error.find("coarse triangle"), std::string::npos) << error;
  }
  // And the right one is accepted.
  EXPECT_TRUE(map.Build(parent, n, split.Triangles, error)) << error;
}
