// Geodesic legs already computed on a surface, shared by every path solver on that surface.
//
// The vector output splits Bezier pieces where the boundary is cut, and each de Casteljau
// step computes the geodesic between two control points again: on a large drawing the same
// leg is computed many times, by the tracer and by the control-point output (the random SVG
// benchmark's worst trial asked for 211,809 legs of which 155,366 were distinct; the repeats
// held 60 % of the window search's work). A leg is the same result whoever computes it (the
// solvers are deterministic), so a solver stores the legs that cost it real work and any
// solver on the same surface, with the same settings, takes them back instead of searching.
//
// Only legs whose search created at least `MinimumWindows` windows, or that were routed, are
// stored: cheap legs cost less to compute than to copy, which is why an earlier cache of every
// leg was dropped. Keys are the two end points bit for bit, in order, and the settings that
// decide the result (method, budgets, route tolerance). The cache holds at most about 2^20
// path points (some 40 MB) and empties itself when full. Thread-safe.
#ifndef boolsurf_GeodesicPathCache_h
#define boolsurf_GeodesicPathCache_h

#include "Mesh/SurfacePoint.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace boolsurf
{

class GeodesicPathCache
{
public:
  /// The cache of `mesh`, shared by every caller on the same mesh (keyed by its serial number,
  /// held as long as one caller holds it).
  static std::shared_ptr<GeodesicPathCache> Get(const TriangleMesh& mesh);

  /// What decides a leg besides its ends.
  struct Settings
  {
    int Method = 0;
    int ExactWindows = 0;
    int BoundedWindows = 0;
    double RouteTolerance = 0;
    bool operator==(const Settings& o) const
    {
      return Method == o.Method && ExactWindows == o.ExactWindows &&
        BoundedWindows == o.BoundedWindows && RouteTolerance == o.RouteTolerance;
    }
  };

  /// A stored leg: its points, its length and whether it is the exact shortest path.
  struct Leg
  {
    std::vector<CanonicalPoint> Points;
    double Length = 0;
    bool Exact = false;
    bool Routed = false;
  };

  /// True (and `leg` filled) when the leg from `start` to `end` under `settings` is stored.
  bool Find(const CanonicalPoint& start,
    const CanonicalPoint& end,
    const Settings& settings,
    Leg& leg) const;
  void Store(const CanonicalPoint& start,
    const CanonicalPoint& end,
    const Settings& settings,
    const Leg& leg);

  std::size_t GetNumberOfLegs() const;
  /// Find calls answered from the cache (for tests and benchmarks).
  std::size_t GetHits() const;

  static constexpr int MinimumWindows = 500;
  static constexpr std::size_t MaximumPoints = std::size_t(1) << 20;

private:
  struct Key
  {
    CanonicalPoint Start, End;
    Settings Options;
    bool operator==(const Key& o) const
    {
      return Start == o.Start && End == o.End && Options == o.Options;
    }
  };
  struct KeyHash
  {
    std::size_t operator()(const Key& k) const;
  };

  mutable std::mutex Lock;
  std::unordered_map<Key, Leg, KeyHash> Legs;
  std::size_t Points = 0;
  mutable std::size_t Hits = 0;
};

} // namespace boolsurf

#endif
