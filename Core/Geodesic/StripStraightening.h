// The shortest path through a strip of triangles, made locally shortest on the surface.
//
// Whatever method found the strip (GeodesicPathSolver: the exact window search, a site-graph
// route, the shortest edge path or the dual A*), the path itself comes from here, after
// Lee-Preparata and the strip straightening used by BoolSurf/b-Surf:
//  1. The strip is unfolded into the plane and the funnel algorithm finds the shortest
//     polyline inside it; it bends only at strip vertices.
//  2. Where that polyline passes through a mesh vertex and the angle on the side outside the
//     strip is below pi, going around the vertex on that side is shorter: the strip is
//     rerouted there and the funnel runs again, until no such vertex is left. The result is
//     locally shortest: at every interior mesh vertex it passes through, both angles are at
//     least pi. A boundary vertex cannot be walked around on the outside, so paths hug
//     boundaries instead of leaving the surface.
// Every point is canonical (a vertex, an edge with a parameter, or the start or end point)
// and consecutive points share a triangle.
#ifndef boolsurf_StripStraightening_h
#define boolsurf_StripStraightening_h

#include "Mesh/EdgeIndex.h"
#include "Mesh/SurfacePoint.h"
#include "Mesh/TriangleMesh.h"

#include <array>
#include <vector>

namespace boolsurf
{

/// Local index (0, 1, 2) of vertex v in `tri`, -1 when `tri` does not hold it.
inline int CornerOf(const Triangle& tri, int v)
{
  return tri[0] == v ? 0 : (tri[1] == v ? 1 : (tri[2] == v ? 2 : -1));
}

/// Straightens paths through strips of triangles of one mesh. Holds the per-path scratch
/// (kept to reuse capacity), so keep one per solver.
class StripStraightener
{
public:
  /// A point of the straightened path; for Vertex points, the strip portals that hold it.
  struct PathPoint
  {
    CanonicalPoint Point;
    int FirstPortal = -1, LastPortal = -1;
  };

  /// `mesh` must outlive the straightener.
  explicit StripStraightener(const TriangleMesh& mesh)
    : Mesh(mesh)
  {
  }

  /// Forgets the unfolding kept from the last Straighten (which later calls on the same path
  /// reuse for the strip's unchanged prefix): call when a new leg begins.
  void ForgetUnfolding() { this->UnfoldedStrip.clear(); }

  /// Funnel and vertex rerouting on `strip` (a chain of neighbouring triangles from one
  /// holding `start` to one holding `end`, rerouted in place) until the path is locally
  /// shortest or `rounds` (incremented per funnel run) reaches `maximumRounds`. The path is
  /// then GetPoints(). False when consecutive strip triangles are not neighbours.
  bool Straighten(const CanonicalPoint& start,
    const CanonicalPoint& end,
    std::vector<int>& strip,
    int maximumRounds,
    int& rounds);

  /// The path of the last successful Straighten, start to end.
  const std::vector<PathPoint>& GetPoints() const { return this->Points; }

  /// When set, every Straighten appends each strip it unfolds (the path's rounds): the
  /// triangles it read, with the fans of their corners it may sweep (see
  /// GeodesicPathSolver::SetPieceReads). Null (default): nothing is recorded.
  void SetStripRecorder(std::vector<int>* recorder) { this->Recorder = recorder; }

private:
  struct Portal
  {
    int Left = -1, Right = -1; // mesh vertex ids, seen walking from the start to the end
    Vec2 LeftPosition, RightPosition;
    int Edge = -1;
  };
  struct Corner
  {
    Vec2 Position;
    int Vertex = -1; // -2: start, -3: end
    int Portal = 0;  // funnel portal index it was found at (0 = start)
  };

  void TrimStrip(const CanonicalPoint& start, const CanonicalPoint& end, std::vector<int>& strip);
  bool UnfoldStrip(const CanonicalPoint& start,
    const CanonicalPoint& end,
    const std::vector<int>& strip);
  void RunFunnel();
  void CollectPathPoints(const CanonicalPoint& start, const CanonicalPoint& end);
  void EmitVertex(int vertex, int portal);
  bool RerouteAroundVertices(std::vector<int>& strip);
  /// Angle at vertex v between the directions to `before` and `after`, swept from strip
  /// triangle `first` away from strip triangle `second` until strip triangle `last`;
  /// negative when a boundary (or a non-manifold fan) blocks the way.
  double OutsideAngle(int v,
    const Vec3& before,
    const Vec3& after,
    int first,
    int second,
    int last,
    std::vector<int>& swept) const;

  const TriangleMesh& Mesh;
  std::vector<int> NewStrip, Swept;
  std::vector<std::array<Vec2, 3>> Unfolded;
  std::vector<int> UnfoldedStrip; // the strip Unfolded and Portals were computed for
  std::vector<Portal> Portals;    // Portals[i] joins strip[i] and strip[i + 1]
  Vec2 StartPosition, EndPosition;
  std::vector<Corner> Corners;
  std::vector<PathPoint> Points;
  EdgeIndex StripPosition; ///< triangle -> its index in the strip (keyed by triangle id)
  std::vector<int>* Recorder = nullptr;
};

} // namespace boolsurf

#endif
