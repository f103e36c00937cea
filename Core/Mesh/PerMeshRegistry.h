// Objects shared by everything that works on one mesh (a geodesic solver and its helpers, the
// tracer and the vector output), held weakly: an object lives as long as something holds it,
// and the mesh's serial number (TriangleMesh::GetSerial, not its address, which a new mesh can
// reuse) finds it again.
#ifndef boolsurf_PerMeshRegistry_h
#define boolsurf_PerMeshRegistry_h

#include "Mesh/TriangleMesh.h"

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>

namespace boolsurf
{

template <class T>
class PerMeshRegistry
{
public:
  /// The live object registered for `mesh` that belongs(object) accepts (an object can tell
  /// whether it was made for this very mesh), else null.
  template <class Belongs>
  std::shared_ptr<T> Find(const TriangleMesh& mesh, Belongs belongs)
  {
    std::lock_guard<std::mutex> guard(this->Lock);
    const auto it = this->Objects.find(mesh.GetSerial());
    std::shared_ptr<T> object = it == this->Objects.end() ? nullptr : it->second.lock();
    return object && belongs(*object) ? object : nullptr;
  }

  /// The same, made by make() and registered when there is none. Made under the lock, so
  /// concurrent first requests make it once; entries whose objects died are dropped here.
  template <class Make, class Belongs>
  std::shared_ptr<T> Get(const TriangleMesh& mesh, Make make, Belongs belongs)
  {
    std::lock_guard<std::mutex> guard(this->Lock);
    for (auto it = this->Objects.begin(); it != this->Objects.end();)
    {
      it = it->second.expired() ? this->Objects.erase(it) : std::next(it);
    }
    std::weak_ptr<T>& slot = this->Objects[mesh.GetSerial()];
    std::shared_ptr<T> object = slot.lock();
    if (!object || !belongs(*object))
    {
      object = make();
      slot = object;
    }
    return object;
  }

private:
  std::mutex Lock;
  std::map<std::uint64_t, std::weak_ptr<T>> Objects;
};

} // namespace boolsurf

#endif
