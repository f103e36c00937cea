// EdgeIndex against std::unordered_map under random insertions, replacements, erasures and
// lookups, with keys crowded into few homes (so runs wrap around the table and erasures shift
// entries back across the wrap) and with the table growing from empty.
#include "Mesh/EdgeIndex.h"

#include <gtest/gtest.h>

#include <random>
#include <unordered_map>

using namespace boolsurf;

TEST(EdgeIndex, MatchesAStandardMapUnderRandomOperations)
{
  for (const int range : { 8, 64, 5000 })
  {
    std::mt19937 rng(static_cast<std::uint32_t>(range));
    EdgeIndex index;
    if (range == 64)
    {
      index.Reset(10); // small on purpose: it must grow
    }
    std::unordered_map<EdgeIndex::Key, int> truth;
    std::uniform_int_distribution<int> id(0, range), op(0, 9), value(0, 1 << 20);
    for (int step = 0; step < 200000; ++step)
    {
      const EdgeIndex::Key key =
        (static_cast<EdgeIndex::Key>(id(rng)) << 32) | static_cast<std::uint32_t>(id(rng));
      const int what = op(rng);
      if (what < 4)
      {
        const int v = value(rng);
        index.Set(key, v);
        truth[key] = v;
      }
      else if (what < 7)
      {
        ASSERT_EQ(index.Erase(key), truth.erase(key) > 0) << "step " << step;
      }
      else
      {
        const auto it = truth.find(key);
        ASSERT_EQ(index.Find(key), it == truth.end() ? -1 : it->second) << "step " << step;
      }
      ASSERT_EQ(index.Size(), truth.size());
    }
    for (const auto& [key, v] : truth)
    {
      ASSERT_EQ(index.Find(key), v);
    }
  }
}
