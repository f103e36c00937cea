#include "Geodesic/GeodesicPathCache.h"

#include "Mesh/PerMeshRegistry.h"
#include "Mesh/TriangleMesh.h"

#include <functional>

namespace boolsurf
{

namespace
{
// Weak references: a cache lives as long as a solver on its mesh holds it.
PerMeshRegistry<GeodesicPathCache> registry;
} // namespace

//------------------------------------------------------------------------------
std::shared_ptr<GeodesicPathCache> GeodesicPathCache::Get(const TriangleMesh& mesh)
{
  return registry.Get(
    mesh,
    [] { return std::make_shared<GeodesicPathCache>(); },
    [](const GeodesicPathCache&) { return true; });
}

//------------------------------------------------------------------------------
std::size_t GeodesicPathCache::KeyHash::operator()(const Key& k) const
{
  std::size_t h = static_cast<std::size_t>(k.Options.Method) * 131 +
    static_cast<std::size_t>(k.Options.ExactWindows) * 7 +
    static_cast<std::size_t>(k.Options.BoundedWindows) * 3 +
    std::hash<double>()(k.Options.RouteTolerance);
  auto mix = [&h](std::size_t v) { h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2); };
  for (const CanonicalPoint* p : { &k.Start, &k.End })
  {
    mix(static_cast<std::size_t>(p->Location));
    mix(std::hash<int>()(p->Id));
    mix(std::hash<double>()(p->U));
    mix(std::hash<double>()(p->V));
    mix(std::hash<double>()(p->T));
  }
  return h;
}

//------------------------------------------------------------------------------
bool GeodesicPathCache::Find(const CanonicalPoint& start,
  const CanonicalPoint& end,
  const Settings& settings,
  Leg& leg) const
{
  std::lock_guard<std::mutex> guard(this->Lock);
  auto it = this->Legs.find(Key{ start, end, settings });
  if (it == this->Legs.end())
  {
    return false;
  }
  leg = it->second;
  ++this->Hits;
  return true;
}

//------------------------------------------------------------------------------
void GeodesicPathCache::Store(const CanonicalPoint& start,
  const CanonicalPoint& end,
  const Settings& settings,
  const Leg& leg)
{
  std::lock_guard<std::mutex> guard(this->Lock);
  if (this->Points + leg.Points.size() > MaximumPoints)
  {
    this->Legs.clear();
    this->Points = 0;
  }
  if (this->Legs.emplace(Key{ start, end, settings }, leg).second)
  {
    this->Points += leg.Points.size();
  }
}

//------------------------------------------------------------------------------
std::size_t GeodesicPathCache::GetNumberOfLegs() const
{
  std::lock_guard<std::mutex> guard(this->Lock);
  return this->Legs.size();
}

std::size_t GeodesicPathCache::GetHits() const
{
  std::lock_guard<std::mutex> guard(this->Lock);
  return this->Hits;
}

} // namespace boolsurf
