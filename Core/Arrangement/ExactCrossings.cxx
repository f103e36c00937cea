#include "Arrangement/ExactCrossings.h"

#include <gmpxx.h>

#include <atomic>
#include <cmath>

namespace boolsurf
{
namespace
{

// A double with a bound on its distance to the exact value of the expression it stands for.
// Each operation adds its own rounding (half an ulp of the result, counted as a full one) to
// the propagated bounds, plus a tiny absolute term for results in the subnormal range, where
// rounding is absolute rather than relative.
struct Filtered
{
  double V = 0.0;
  double E = 0.0;
  Filtered() = default;
  explicit Filtered(double v)
    : V(v)
  {
  }
  Filtered(double v, double e)
    : V(v)
    , E(e)
  {
  }
};

constexpr double RoundingUnit = 0x1p-52;
constexpr double Subnormal = 0x1p-1000;

inline Filtered operator+(Filtered a, Filtered b)
{
  const double v = a.V + b.V;
  return { v, a.E + b.E + RoundingUnit * std::abs(v) + Subnormal };
}

inline Filtered operator-(Filtered a, Filtered b)
{
  const double v = a.V - b.V;
  return { v, a.E + b.E + RoundingUnit * std::abs(v) + Subnormal };
}

inline Filtered operator*(Filtered a, Filtered b)
{
  const double v = a.V * b.V;
  return { v,
    std::abs(a.V) * b.E + std::abs(b.V) * a.E + a.E * b.E + RoundingUnit * std::abs(v) +
      Subnormal };
}

/// +1 / -1 when the bound settles the sign, 0 when it does not. The bound itself was computed
/// in rounded arithmetic: the margin covers that (a few dozen operations, each off by at most
/// an ulp, move it by far less than one part in 10^12).
inline int CertainSign(const Filtered& f)
{
  const double margin = f.E * (1.0 + 1e-12) + Subnormal;
  return f.V > margin ? 1 : (f.V < -margin ? -1 : 0);
}

inline int Sign(const mpq_class& q)
{
  return sgn(q);
}

template <class T>
struct Homogeneous
{
  T X, Y, W;
};

/// Homogeneous coordinates of p: (x, y, 1) for explicit points; for a crossing, with
/// d = P1 - P0, e = Q1 - Q0, w = d x e and n = (Q0 - P0) x e, the point P0 + d n / w is
/// (P0 w + d n, w).
template <class T>
Homogeneous<T> HomogeneousOf(const ExactPoint& p)
{
  if (!p.Crossing)
  {
    return { T(p.P.x), T(p.P.y), T(1.0) };
  }
  const SegmentCrossing& c = *p.Crossing;
  const T p0x(c.P0.x), p0y(c.P0.y);
  const T dx = T(c.P1.x) - p0x, dy = T(c.P1.y) - p0y;
  const T ex = T(c.Q1.x) - T(c.Q0.x), ey = T(c.Q1.y) - T(c.Q0.y);
  const T fx = T(c.Q0.x) - p0x, fy = T(c.Q0.y) - p0y;
  const T w = dx * ey - dy * ex;
  const T n = fx * ey - fy * ex;
  return { p0x * w + dx * n, p0y * w + dy * n, w };
}

/// Determinant of the three points' homogeneous coordinates; its sign times the signs of the
/// three w is the orientation.
template <class T>
T OrientDeterminant(const Homogeneous<T>& a, const Homogeneous<T>& b, const Homogeneous<T>& c)
{
  return a.X * (b.Y * c.W - c.Y * b.W) - b.X * (a.Y * c.W - c.Y * a.W) +
    c.X * (a.Y * b.W - b.Y * a.W);
}

template <class T>
T CompareDeterminant(const Homogeneous<T>& a, const Homogeneous<T>& b, int axis)
{
  return axis == 0 ? a.X * b.W - b.X * a.W : a.Y * b.W - b.Y * a.W;
}

std::atomic<long long> Fallbacks{ 0 };

int ExactOrientSlow(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c)
{
  ++Fallbacks;
  const Homogeneous<mpq_class> ha = HomogeneousOf<mpq_class>(a);
  const Homogeneous<mpq_class> hb = HomogeneousOf<mpq_class>(b);
  const Homogeneous<mpq_class> hc = HomogeneousOf<mpq_class>(c);
  return Sign(OrientDeterminant(ha, hb, hc)) * Sign(ha.W) * Sign(hb.W) * Sign(hc.W);
}

int ExactCompareSlow(const ExactPoint& a, const ExactPoint& b, int axis)
{
  ++Fallbacks;
  const Homogeneous<mpq_class> ha = HomogeneousOf<mpq_class>(a);
  const Homogeneous<mpq_class> hb = HomogeneousOf<mpq_class>(b);
  return Sign(CompareDeterminant(ha, hb, axis)) * Sign(ha.W) * Sign(hb.W);
}

} // namespace

//------------------------------------------------------------------------------
int ExactOrient(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c)
{
  const Homogeneous<Filtered> ha = HomogeneousOf<Filtered>(a);
  const Homogeneous<Filtered> hb = HomogeneousOf<Filtered>(b);
  const Homogeneous<Filtered> hc = HomogeneousOf<Filtered>(c);
  const int wa = CertainSign(ha.W), wb = CertainSign(hb.W), wc = CertainSign(hc.W);
  const int d = CertainSign(OrientDeterminant(ha, hb, hc));
  if (wa != 0 && wb != 0 && wc != 0 && d != 0)
  {
    return d * wa * wb * wc;
  }
  return ExactOrientSlow(a, b, c);
}

//------------------------------------------------------------------------------
int ExactCompare(const ExactPoint& a, const ExactPoint& b, int axis)
{
  if (!a.Crossing && !b.Crossing)
  {
    const double x = axis == 0 ? a.P.x : a.P.y, y = axis == 0 ? b.P.x : b.P.y;
    return x < y ? -1 : (x > y ? 1 : 0);
  }
  const Homogeneous<Filtered> ha = HomogeneousOf<Filtered>(a);
  const Homogeneous<Filtered> hb = HomogeneousOf<Filtered>(b);
  const int wa = CertainSign(ha.W), wb = CertainSign(hb.W);
  const int d = CertainSign(CompareDeterminant(ha, hb, axis));
  if (wa != 0 && wb != 0 && d != 0)
  {
    return d * wa * wb;
  }
  return ExactCompareSlow(a, b, axis);
}

//------------------------------------------------------------------------------
Vec2 RoundedCrossing(const SegmentCrossing& c)
{
  const Vec2 d = c.P1 - c.P0, e = c.Q1 - c.Q0, f = c.Q0 - c.P0;
  const double w = d.x * e.y - d.y * e.x;
  const double n = f.x * e.y - f.y * e.x;
  return c.P0 + (n / w) * d;
}

//------------------------------------------------------------------------------
bool ExactStrictlyBetween(const ExactPoint& a, const ExactPoint& b, const ExactPoint& q)
{
  int axis = 0;
  int ab = ExactCompare(a, b, 0);
  if (ab == 0)
  {
    axis = 1;
    ab = ExactCompare(a, b, 1);
  }
  const int aq = ExactCompare(a, q, axis), qb = ExactCompare(q, b, axis);
  return ab != 0 && aq == ab && qb == ab;
}

//------------------------------------------------------------------------------
long long ExactFallbackCount()
{
  return Fallbacks.load();
}

} // namespace boolsurf
