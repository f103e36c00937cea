// The winding stage's field from its solved parts (Winding/SurfaceWinding.h): what is kept per
// surface, the curve edges each shape imposes a jump on, the field's assembly with its
// constants, and how much each curve edge bounds.
#ifndef boolsurf_WindingField_h
#define boolsurf_WindingField_h

#include "Mesh/MeshTopology.h"
#include "Winding/CotanLaplacian.h"
#include "Winding/HarmonicBasis.h"
#include "Winding/JumpLift.h"
#include "Winding/SurfaceWinding.h"

#include <cstdint>
#include <map>
#include <memory>
#include <vector>

namespace boolsurf
{

/// What is kept per surface: the factorized Laplacian, the topology and, on genus > 0, the
/// generators' harmonic fields.
class WindingSystem
{
public:
  std::uint64_t MeshSerial = 0;
  CotanLaplacian Laplacian;
  MeshTopology Topology;
  int Genus = 0;
  bool HarmonicReady = false;
  HarmonicBasis Harmonic;
  /// Per block of the Laplacian: its longest boundary loop (-1 for a closed block).
  std::vector<int> BlockLoop;
  /// The solved smooth part u of each shape at the last call, with the curves it came from:
  /// an edit that leaves a shape's curves as they were reuses it (u depends on the shape's
  /// curves alone), so moving one of ten shapes is one back-substitution, not ten. Kept only
  /// for shapes where nothing was dropped (drops name refined edges, renumbered by any edit).
  struct SolvedShape
  {
    std::vector<TracedCurve> Curves;
    std::shared_ptr<const std::vector<double>> Smooth;
    std::vector<double> Shift; ///< its constant per block (WindingResult::BlockShift)
  };
  std::map<int, SolvedShape> Solved;
};

/// One traversal of a refined edge by a curve: edge Index of curve Curve (From -> To).
struct Traversal
{
  int From = -1, To = -1, Curve = -1, Index = -1;
};

/// Appends the traversals of curve c of arr (the closing edge of a closed curve included).
void AppendTraversals(const Arrangement& arr, int c, bool closed, std::vector<Traversal>& out);

/// Fills out's jump triangles, smooth parts, lifts and constants from each shape's lift and
/// solved u (one per shape, at the mesh vertices): each block's constant makes the values on
/// the free part of its longest boundary loop (else all of them) integer levels, lowest 0
/// (knownShift[s], when not null: the constants of a shape kept from the last edit).
void BuildField(const TriangleMesh& mesh,
  const Arrangement& arr,
  const WindingSystem& system,
  const std::vector<int>& shapes,
  const std::vector<std::vector<Traversal>>& shapeEdges,
  const std::vector<JumpLift>& lifts,
  const std::vector<std::shared_ptr<const std::vector<double>>>& smooth,
  const std::vector<const std::vector<double>*>& knownShift,
  WindingResult& out);

/// How much each traversal of shape s bounds, in [0, 1]: with J the net jump of the shape
/// across the edge and L, R the field on its left and right, a curve that bounds has its sides
/// at integer levels R and R + J, while a spur, an overshoot or an isolated arc sits at the
/// middle of a level, (L + R - J) / 2 half-way between integers. The degree is
/// 1 - 2 * distance((L + R - J) / 2, integers), read at the edge's ends where the jump is whole
/// (not at an open curve's end point, where it fades), the better of the two. -1 for a
/// traversal that imposes no jump of its own: against the edge's net direction, or cancelled
/// by one the other way (a curve retracing itself).
std::vector<double> BoundingDegrees(const TriangleMesh& mesh,
  const Arrangement& arr,
  const WindingResult& field,
  int s,
  const std::vector<Traversal>& edges,
  const JumpLift& lift);

/// The traversals of the curves that bound nothing on the whole: a curve whose counted
/// traversals (degree >= 0) have a length-weighted degree below 1/2 (a spur, an isolated arc).
std::vector<char> CurvesThatBoundNothing(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<Traversal>& edges,
  const std::vector<double>& degree);

/// The traversals of stretches that bound nothing: runs of consecutive counted traversals of a
/// curve with degree below 1/2 making up at least a twentieth of the curve (an overshooting
/// tail, not the few edges next to an open end). Every traversal of a dropped edge goes, so no
/// traversal the other way is left without its partner.
std::vector<char> StretchesThatBoundNothing(const TriangleMesh& mesh,
  const Arrangement& arr,
  const std::vector<Traversal>& edges,
  const std::vector<double>& degree);

} // namespace boolsurf

#endif
