// Parallel loops over an index range whose bodies each write only their own slots, so results
// never depend on scheduling or on the number of threads.
#ifndef boolsurf_ParallelRange_h
#define boolsurf_ParallelRange_h

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace boolsurf
{

/// Runs body(i) for i in [0, n) on the arena's threads, in chunks of at least `grain` (the
/// default suits cheap bodies over the whole mesh).
template <class Body>
void ParallelRange(tbb::task_arena& arena, int n, const Body& body, int grain = 4096)
{
  arena.execute(
    [&]
    {
      tbb::parallel_for(tbb::blocked_range<int>(0, n, grain),
        [&](const tbb::blocked_range<int>& range)
        {
          for (int i = range.begin(); i != range.end(); ++i)
          {
            body(i);
          }
        });
    });
}

/// ParallelRange for bodies that do real work per index (triangles, segments, blocks).
template <class Body>
void ParallelFor(tbb::task_arena& arena, int n, const Body& body)
{
  ParallelRange(arena, n, body, 1);
}

/// Runs body(first, last) over consecutive blocks of [0, n) of at least `grain` indices, on at
/// most `threads` threads (0: all) when `parallel`, else body(0, n) on the calling thread (for
/// a small input, where waking other threads costs more than the work). A block body keeps its
/// own loops, which a per-index body cannot (WriteRegion's two loops ran 30 % slower merged).
template <class Body>
void ParallelBlocks(int threads, bool parallel, int n, const Body& body, int grain)
{
  if (!parallel)
  {
    body(0, n);
    return;
  }
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute(
    [&]
    {
      tbb::parallel_for(tbb::blocked_range<int>(0, n, grain),
        [&](const tbb::blocked_range<int>& range) { body(range.begin(), range.end()); });
    });
}

/// ParallelBlocks for a body of one index: body(i) for i in [0, n).
template <class Body>
void ParallelRange(int threads, bool parallel, int n, const Body& body, int grain)
{
  ParallelBlocks(
    threads,
    parallel,
    n,
    [&](int first, int last)
    {
      for (int i = first; i < last; ++i)
      {
        body(i);
      }
    },
    grain);
}

} // namespace boolsurf

#endif
