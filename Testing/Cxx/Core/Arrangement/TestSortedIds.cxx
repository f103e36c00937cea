// SortUniqueIds against std::sort + std::unique: short lists (the std::sort path), long ones
// with few and many repeats, ids up to the largest int (three radix digits), all equal.
#include "Arrangement/SortedIds.h"

#include <gtest/gtest.h>

#include <climits>
#include <random>

using namespace boolsurf;

TEST(SortedIds, MatchesSortAndUnique)
{
  std::mt19937 rng(7);
  for (const int size : { 0, 1, 17, 1023, 1024, 5000, 100000 })
  {
    for (const int range : { 1, 100, 1 << 20, INT_MAX })
    {
      std::uniform_int_distribution<int> id(0, range);
      std::vector<int> ids(static_cast<std::size_t>(size));
      for (int& v : ids)
      {
        v = id(rng);
      }
      std::vector<int> expected = ids;
      std::sort(expected.begin(), expected.end());
      expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
      SortUniqueIds(ids);
      ASSERT_EQ(ids, expected) << "size " << size << ", ids up to " << range;
    }
  }
}

TEST(SortedIds, AllZeroAndAllEqual)
{
  std::vector<int> zeros(3000, 0), sevens(3000, 7);
  SortUniqueIds(zeros);
  SortUniqueIds(sevens);
  EXPECT_EQ(zeros, std::vector<int>{ 0 });
  EXPECT_EQ(sevens, std::vector<int>{ 7 });
}
