#include "Arrangement/Predicates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace boolsurf;

namespace
{
int Sign(double x)
{
  return x > 0 ? 1 : (x < 0 ? -1 : 0);
}
} // namespace

TEST(Predicates, Orient2dBasic)
{
  EXPECT_GT(Orient2d({ 0, 0 }, { 1, 0 }, { 0, 1 }), 0.0);
  EXPECT_LT(Orient2d({ 0, 0 }, { 0, 1 }, { 1, 0 }), 0.0);
  EXPECT_EQ(Orient2d({ 0, 0 }, { 1, 1 }, { 3, 3 }), 0.0);
  EXPECT_EQ(Orient2dSign({ 1, 2 }, { 1, 2 }, { 5, 7 }), 0);
}

// Points within a few ulps of the line y = x (Shewchuk's classic failure case of the naive
// formula): the exact sign is the sign of (j - i).
TEST(Predicates, Orient2dNearlyCollinear)
{
  const double ulp = std::ldexp(1.0, -53);
  int naiveWrong = 0;
  for (int i = 0; i < 64; ++i)
  {
    for (int j = 0; j < 64; ++j)
    {
      const Vec2 p{ 0.5 + i * ulp, 0.5 + j * ulp }, q{ 12, 12 }, r{ 24, 24 };
      const int expected = Sign(j - i);
      EXPECT_EQ(Orient2dSign(p, q, r), expected) << i << " " << j;
      EXPECT_EQ(Sign(Orient2dExact(p, q, r)), expected);
      const double naive = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
      naiveWrong += Sign(naive) != expected;
    }
  }
  EXPECT_GT(naiveWrong, 0); // the test does exercise the exact path
}

// Random dyadic points: exact reference with 128-bit integers.
TEST(Predicates, Orient2dAgainstIntegerArithmetic)
{
  std::mt19937_64 rng(42);
  std::uniform_int_distribution<long long> coord(-(1LL << 40), 1LL << 40);
  const double scale = std::ldexp(1.0, -37);
  for (int trial = 0; trial < 20000; ++trial)
  {
    long long c[6];
    for (long long& x : c)
      x = coord(rng);
    if (trial % 3 == 0)
    {
      // Make c collinear with a and b (exactly, in integers) half of the time.
      const long long k = trial % 7 - 3;
      c[4] = c[0] + k * (c[2] - c[0]);
      c[5] = c[1] + k * (c[3] - c[1]);
    }
    const __int128 det = static_cast<__int128>(c[2] - c[0]) * (c[5] - c[1]) -
      static_cast<__int128>(c[3] - c[1]) * (c[4] - c[0]);
    const int expected = det > 0 ? 1 : (det < 0 ? -1 : 0);
    const Vec2 a{ c[0] * scale, c[1] * scale }, b{ c[2] * scale, c[3] * scale },
      p{ c[4] * scale, c[5] * scale };
    ASSERT_EQ(Orient2dSign(a, b, p), expected) << "trial " << trial;
  }
}

TEST(Predicates, SumMinusOneSign)
{
  EXPECT_EQ(SumMinusOneSign(0.25, 0.75), 0);
  EXPECT_EQ(SumMinusOneSign(0.1, 0.9), 1); // 0.1 + 0.9 rounds to 1 but the doubles sum above
  EXPECT_LT(SumMinusOneSign(0.5, std::nextafter(0.5, 0.0)), 0);
  EXPECT_GT(SumMinusOneSign(0.5, std::nextafter(0.5, 1.0)), 0);
  EXPECT_EQ(SumMinusOneSign(1e-300, 1.0), 1);
}
