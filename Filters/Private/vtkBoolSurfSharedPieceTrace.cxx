#include "vtkBoolSurfSharedPieceTrace.h"

#include <map>
#include <mutex>

namespace boolsurf
{

//------------------------------------------------------------------------------
std::shared_ptr<PieceTraceState> SharedPieceTraceState(vtkPolyData* local,
  std::shared_ptr<PieceTraceState> current)
{
  if (current && current->HasPiece && current->Surface == local)
  {
    return current;
  }
  // The states by the piece they trace on; a piece's entry lives as long as a filter holds its
  // state (a piece deleted and another made at its address is told apart by its modification
  // time, which UpdateRingedPiece compares).
  static std::mutex lock;
  static std::map<vtkPolyData*, std::weak_ptr<PieceTraceState>> states;
  std::lock_guard<std::mutex> guard(lock);
  for (auto it = states.begin(); it != states.end();)
  {
    it = it->second.expired() ? states.erase(it) : std::next(it);
  }
  const auto found = local ? states.find(local) : states.end();
  if (found != states.end())
  {
    return found->second.lock();
  }
  auto state = std::make_shared<PieceTraceState>();
  if (local)
  {
    states[local] = state;
  }
  return state;
}

}
