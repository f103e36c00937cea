// Each bad-input case gets a named problem (kind + ids in the message), never a crash.
#include "Mesh/MeshTopology.h"
#include "Mesh/ProceduralMeshes.h"
#include "Mesh/SurfaceCheck.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace boolsurf;

namespace
{
SurfaceCheckResult Check(const MeshData& d)
{
  TriangleMesh mesh(d.Positions, d.Triangles);
  return CheckSurface(mesh, MeshTopology::Compute(mesh));
}

// Two triangles sharing edge (0,1): a valid little square.
MeshData Square()
{
  MeshData d;
  d.Positions = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
  d.Triangles = { { 0, 1, 2 }, { 0, 2, 3 } };
  return d;
}
} // namespace

TEST(SurfaceCheck, ValidMeshesHaveNoProblems)
{
  EXPECT_TRUE(Check(Square()).Problems.empty());
  EXPECT_TRUE(Check(MakeIcosphere(2)).Problems.empty());
  EXPECT_TRUE(Check(MakeTorus(2, 1, 10, 8)).Problems.empty());
}

TEST(SurfaceCheck, ProceduralClosedMeshesAreOrientedOutward)
{
  for (const MeshData& d : { MakeIcosphere(2), MakeTorus(2, 1, 16, 8) })
  {
    double volume = 0;
    for (const auto& t : d.Triangles)
    {
      volume += Dot(d.Positions[t[0]], Cross(d.Positions[t[1]], d.Positions[t[2]])) / 6.0;
    }
    EXPECT_GT(volume, 0.0);
  }
}

TEST(SurfaceCheck, EmptyInput)
{
  SurfaceCheckResult r = Check(MeshData());
  ASSERT_TRUE(r.Has("EmptyInput"));
  EXPECT_TRUE(r.HasErrors());
  EXPECT_NE(r.Find("EmptyInput")->Message.find("empty"), std::string::npos);
}

TEST(SurfaceCheck, NonFiniteCoordinatesNamePoints)
{
  MeshData d = Square();
  d.Positions[2].y = std::numeric_limits<double>::quiet_NaN();
  d.Positions[3].x = std::numeric_limits<double>::infinity();
  SurfaceCheckResult r = Check(d);
  const SurfaceProblem* p = r.Find("NonFiniteCoordinates");
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->Ids, (std::vector<long long>{ 2, 3 }));
  EXPECT_NE(p->Message.find("2, 3"), std::string::npos) << p->Message;
}

TEST(SurfaceCheck, DegenerateTriangleIsNamed)
{
  MeshData d = Square();
  d.Positions.push_back({ 2, 0, 0 }); // 4: collinear with 0 and 1
  d.Triangles.push_back({ 1, 0, 4 });
  SurfaceCheckResult r = Check(d);
  const SurfaceProblem* p = r.Find("DegenerateTriangle");
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->Ids, (std::vector<long long>{ 2 }));
  EXPECT_EQ(r.Find("DegenerateTriangle")->Level, Severity::Error);
}

TEST(SurfaceCheck, RepeatedAndOutOfRangeIndices)
{
  MeshData d = Square();
  d.Triangles.push_back({ 1, 1, 2 });
  d.Triangles.push_back({ 0, 1, 17 });
  SurfaceCheckResult r = Check(d);
  ASSERT_TRUE(r.Has("RepeatedVertexIndex"));
  EXPECT_EQ(r.Find("RepeatedVertexIndex")->Ids, (std::vector<long long>{ 2 }));
  ASSERT_TRUE(r.Has("InvalidVertexIndex"));
  EXPECT_EQ(r.Find("InvalidVertexIndex")->Ids, (std::vector<long long>{ 3 }));
}

TEST(SurfaceCheck, NonManifoldEdgeNamesItsVertices)
{
  MeshData d = Square();
  d.Positions.push_back({ 0.5, 0.5, 1 }); // 4: a fin on the diagonal (0,2)
  d.Triangles.push_back({ 0, 2, 4 });
  SurfaceCheckResult r = Check(d);
  const SurfaceProblem* p = r.Find("NonManifoldEdge");
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->Ids, (std::vector<long long>{ 0, 2 }));
  EXPECT_NE(p->Message.find("(0, 2) in 3 triangles"), std::string::npos) << p->Message;
  EXPECT_FALSE(r.IsManifold);
}

TEST(SurfaceCheck, NonManifoldVertexIsNamed)
{
  // Two squares touching at one corner (point 2 of the first is point 0 of the second).
  MeshData d = Square();
  d.Positions.push_back({ 2, 1, 0 });
  d.Positions.push_back({ 2, 2, 0 });
  d.Positions.push_back({ 1, 2, 0 });
  d.Triangles.push_back({ 2, 4, 5 });
  d.Triangles.push_back({ 2, 5, 6 });
  SurfaceCheckResult r = Check(d);
  const SurfaceProblem* p = r.Find("NonManifoldVertex");
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->Ids, (std::vector<long long>{ 2 }));
  EXPECT_FALSE(r.IsManifold);
  TriangleMesh mesh(d.Positions, d.Triangles);
  MeshTopology topo = MeshTopology::Compute(mesh);
  EXPECT_EQ(topo.GetNumberOfComponents(), 2); // connected through a vertex only
  EXPECT_EQ(topo.BoundaryLoops.size(), 2u);
}

TEST(SurfaceCheck, InconsistentOrientationNamesTrianglePair)
{
  MeshData d = Square();
  d.Triangles[1] = { 0, 3, 2 }; // flipped
  SurfaceCheckResult r = Check(d);
  const SurfaceProblem* p = r.Find("InconsistentOrientation");
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->Ids, (std::vector<long long>{ 0, 1 }));
  EXPECT_NE(p->Message.find("0/1"), std::string::npos) << p->Message;
  // The topology is still computed through the flipped pair.
  TriangleMesh mesh(d.Positions, d.Triangles);
  EXPECT_EQ(MeshTopology::Compute(mesh).GetNumberOfComponents(), 1);
}

TEST(SurfaceCheck, MoebiusStripIsNotOrientable)
{
  // A strip of 6 quads whose ends are glued with a half twist.
  MeshData d;
  const int n = 6;
  for (int i = 0; i < n; ++i)
  {
    const double a = 2 * M_PI * i / n;
    const double w = std::cos(a / 2) * 0.3, h = std::sin(a / 2) * 0.3;
    d.Positions.push_back({ (1 - w) * std::cos(a), (1 - w) * std::sin(a), -h });
    d.Positions.push_back({ (1 + w) * std::cos(a), (1 + w) * std::sin(a), h });
  }
  for (int i = 0; i < n; ++i)
  {
    int a = 2 * i, b = 2 * i + 1, c = 2 * (i + 1), e = 2 * (i + 1) + 1;
    if (i == n - 1)
    {
      c = 1; // the twist: inner and outer swap
      e = 0;
    }
    d.Triangles.push_back({ a, c, e });
    d.Triangles.push_back({ a, e, b });
  }
  SurfaceCheckResult r = Check(d);
  EXPECT_TRUE(r.Has("NonOrientable"));
  EXPECT_TRUE(r.Has("InconsistentOrientation"));
}

TEST(SurfaceCheck, UnreferencedPointsAreAWarning)
{
  MeshData d = Square();
  d.Positions.push_back({ 5, 5, 5 });
  SurfaceCheckResult r = Check(d);
  ASSERT_TRUE(r.Has("UnreferencedPoints"));
  EXPECT_EQ(r.Find("UnreferencedPoints")->Level, Severity::Warning);
  EXPECT_FALSE(r.HasErrors());
}

TEST(SurfaceCheck, LongIdListsAreTruncated)
{
  std::vector<long long> ids;
  for (int i = 0; i < 25; ++i)
  {
    ids.push_back(i);
  }
  EXPECT_EQ(FormatIds(ids, 3), "0, 1, 2 ... and 22 more");
}
