#include "vtkBoolSurfArrayView.h"

#include <mutex>
#include <unordered_map>

namespace boolsurf
{
namespace
{

// Views are released by whichever thread destroys the last dataset holding them.
std::mutex& ViewMutex()
{
  static std::mutex mutex;
  return mutex;
}

std::unordered_multimap<void*, std::shared_ptr<const void>>& ViewOwners()
{
  static std::unordered_multimap<void*, std::shared_ptr<const void>> owners;
  return owners;
}

} // namespace

//------------------------------------------------------------------------------
void RegisterArrayView(void* data, std::shared_ptr<const void> owner)
{
  std::lock_guard<std::mutex> lock(ViewMutex());
  ViewOwners().emplace(data, std::move(owner));
}

//------------------------------------------------------------------------------
void ReleaseArrayView(void* data)
{
  std::shared_ptr<const void> released; // destroyed after the lock is given back
  {
    std::lock_guard<std::mutex> lock(ViewMutex());
    auto it = ViewOwners().find(data);
    if (it != ViewOwners().end())
    {
      released = std::move(it->second);
      ViewOwners().erase(it);
    }
  }
}

} // namespace boolsurf
