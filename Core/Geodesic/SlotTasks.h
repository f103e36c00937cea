// One task per item on a TBB arena of a given number of slots, each task told its thread's
// slot: state kept per slot (a solver, a tracer) is then used by one thread at a time without a
// lock. For work whose items differ in cost by orders of magnitude (curves, Bezier segments),
// so items are not grouped.
#ifndef boolsurf_SlotTasks_h
#define boolsurf_SlotTasks_h

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstddef>

namespace boolsurf
{

/// Calls task(slot, i) for every i in [0, count), with slot in [0, slots) the arena slot of
/// the thread running it. With one slot or fewer than two items, runs them in order on the
/// calling thread (slot 0).
template <class Task>
void RunTasksBySlot(int slots, std::size_t count, const Task& task)
{
  if (slots <= 1 || count < 2)
  {
    for (std::size_t i = 0; i < count; ++i)
    {
      task(0, i);
    }
    return;
  }
  tbb::task_arena arena(slots);
  arena.execute(
    [&]
    {
      tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, count, 1),
        [&](const tbb::blocked_range<std::size_t>& range)
        {
          const int slot = std::max(0, tbb::this_task_arena::current_thread_index());
          for (std::size_t i = range.begin(); i < range.end(); ++i)
          {
            task(slot, i);
          }
        },
        tbb::simple_partitioner());
    });
}

} // namespace boolsurf

#endif
