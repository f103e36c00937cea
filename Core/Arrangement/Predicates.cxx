#include "Arrangement/Predicates.h"

#include <cmath>

namespace boolsurf
{
namespace
{

// Error-free transformations: a + b = x + y and a * b = x + y exactly (round to nearest).
inline void TwoSum(double a, double b, double& x, double& y)
{
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

inline void TwoProduct(double a, double b, double& x, double& y)
{
  x = a * b;
  y = std::fma(a, b, -x);
}

// Adds b to the nonoverlapping expansion e[0..n) (increasing magnitude) in place, dropping
// zero components; returns the new length. Shewchuk's GROW-EXPANSION with zero elimination.
int GrowExpansion(double* e, int n, double b)
{
  double q = b;
  int m = 0;
  for (int i = 0; i < n; ++i)
  {
    double sum, err;
    TwoSum(q, e[i], sum, err);
    q = sum;
    if (err != 0.0)
    {
      e[m++] = err;
    }
  }
  if (q != 0.0 || m == 0)
  {
    e[m++] = q;
  }
  return m;
}

// The sign of an expansion is the sign of its most significant (last) component.
inline double MostSignificant(const double* e, int n)
{
  return n > 0 ? e[n - 1] : 0.0;
}

// Shewchuk's bound on the relative error of the double evaluation below.
const double Epsilon = std::ldexp(1.0, -53);
const double CcwErrorBoundA = (3.0 + 16.0 * Epsilon) * Epsilon;

} // namespace

//------------------------------------------------------------------------------
double Orient2dExact(Vec2 a, Vec2 b, Vec2 c)
{
  // det = ax*by - ax*cy - ay*bx + ay*cx + bx*cy - by*cx: six exact products of inputs, each
  // split into two doubles, summed without error.
  const double terms[6][2] = {
    { a.x, b.y }, { -a.x, c.y }, { -a.y, b.x }, { a.y, c.x }, { b.x, c.y }, { -b.y, c.x }
  };
  double e[16];
  int n = 0;
  for (const auto& t : terms)
  {
    double hi, lo;
    TwoProduct(t[0], t[1], hi, lo);
    n = GrowExpansion(e, n, lo);
    n = GrowExpansion(e, n, hi);
  }
  return MostSignificant(e, n);
}

//------------------------------------------------------------------------------
double Orient2d(Vec2 a, Vec2 b, Vec2 c)
{
  const double detLeft = (a.x - c.x) * (b.y - c.y);
  const double detRight = (a.y - c.y) * (b.x - c.x);
  const double det = detLeft - detRight;
  double detSum;
  if (detLeft > 0.0)
  {
    if (detRight <= 0.0)
    {
      return det;
    }
    detSum = detLeft + detRight;
  }
  else if (detLeft < 0.0)
  {
    if (detRight >= 0.0)
    {
      return det;
    }
    detSum = -detLeft - detRight;
  }
  else
  {
    // detLeft == 0: either a factor is an exact zero (a rounded difference of doubles is
    // zero only for equal doubles), so det = -detRight has the exact sign unless detRight
    // underflowed; or the product underflowed, and only the exact path can tell.
    if ((a.x - c.x) != 0.0 && (b.y - c.y) != 0.0)
    {
      return Orient2dExact(a, b, c);
    }
    if (detRight != 0.0 || (a.y - c.y) == 0.0 || (b.x - c.x) == 0.0)
    {
      return det;
    }
    return Orient2dExact(a, b, c);
  }
  const double errBound = CcwErrorBoundA * detSum;
  if (det >= errBound || -det >= errBound)
  {
    return det;
  }
  return Orient2dExact(a, b, c);
}

//------------------------------------------------------------------------------
int Orient2dSign(Vec2 a, Vec2 b, Vec2 c)
{
  const double d = Orient2d(a, b, c);
  return d > 0.0 ? 1 : (d < 0.0 ? -1 : 0);
}

//------------------------------------------------------------------------------
int SumMinusOneSign(double a, double b)
{
  double e[4];
  int n = 0;
  n = GrowExpansion(e, n, a);
  n = GrowExpansion(e, n, b);
  n = GrowExpansion(e, n, -1.0);
  const double s = MostSignificant(e, n);
  return s > 0.0 ? 1 : (s < 0.0 ? -1 : 0);
}

} // namespace boolsurf
