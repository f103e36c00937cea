#include "Arrangement/ExactCrossings.h"

#include "Arrangement/Predicates.h"

#include <gmpxx.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <utility>

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

// The second filter: double-double numbers (an unevaluated sum hi + lo, about 106 bits), with
// the same running bound. Near-degenerate configurations (three curves nearly through one
// point, their crossings a rounding apart: common in drawings on lattices) have orientations
// of about 1e-16 relative to their terms, which doubles cannot decide and double-doubles do,
// at a fraction of the rationals' cost.
inline void TwoSum(double a, double b, double& s, double& e)
{
  s = a + b;
  const double bv = s - a;
  e = (a - (s - bv)) + (b - bv);
}

inline void FastTwoSum(double a, double b, double& s, double& e)
{
  s = a + b;
  e = b - (s - a);
}

struct DoubleDouble
{
  double Hi = 0.0, Lo = 0.0;
  double E = 0.0; ///< bound on the distance to the exact value
  DoubleDouble() = default;
  explicit DoubleDouble(double v)
    : Hi(v)
  {
  }
  double Magnitude() const { return std::abs(this->Hi) + std::abs(this->Lo); }
};

// Relative rounding of one double-double operation: at most a few units of 2^-106 for the
// accurate sum and the product below; 2^-100 leaves a wide margin.
constexpr double DoubleDoubleUnit = 0x1p-100;

inline DoubleDouble Add(const DoubleDouble& a, const DoubleDouble& b, double sign)
{
  DoubleDouble r;
  double s, e, t, f;
  TwoSum(a.Hi, sign * b.Hi, s, e);
  TwoSum(a.Lo, sign * b.Lo, t, f);
  e += t;
  FastTwoSum(s, e, s, e);
  e += f;
  FastTwoSum(s, e, r.Hi, r.Lo);
  r.E = a.E + b.E + DoubleDoubleUnit * (a.Magnitude() + b.Magnitude()) + Subnormal;
  return r;
}

inline DoubleDouble operator+(const DoubleDouble& a, const DoubleDouble& b)
{
  return Add(a, b, 1.0);
}

inline DoubleDouble operator-(const DoubleDouble& a, const DoubleDouble& b)
{
  return Add(a, b, -1.0);
}

inline DoubleDouble operator*(const DoubleDouble& a, const DoubleDouble& b)
{
  DoubleDouble r;
  const double p = a.Hi * b.Hi;
  double e = std::fma(a.Hi, b.Hi, -p);
  e += a.Hi * b.Lo + a.Lo * b.Hi;
  FastTwoSum(p, e, r.Hi, r.Lo);
  const double ma = a.Magnitude(), mb = b.Magnitude();
  r.E = ma * b.E + mb * a.E + a.E * b.E + DoubleDoubleUnit * ma * mb + Subnormal;
  return r;
}

inline int CertainSign(const DoubleDouble& f)
{
  const double margin = f.E * (1.0 + 1e-12) + Subnormal;
  const double low = std::abs(f.Hi) - std::abs(f.Lo);
  return low > margin ? (f.Hi > 0 ? 1 : -1) : 0;
}

template <class T>
struct Homogeneous
{
  T X, Y, W;
};

/// Homogeneous coordinates of p: (x, y, 1) for explicit points; for a crossing, with
/// d = P1 - P0, e = Q1 - Q0, w = d x e and n = (Q0 - P0) x e, the point P0 + d n / w is
/// (P0 w + d n, w).
template <class T, class Convert>
Homogeneous<T> ComputeHomogeneous(const ExactPoint& p, Convert&& to)
{
  if (!p.Crossing)
  {
    return { to(p.P.x), to(p.P.y), T(1.0) };
  }
  const SegmentCrossing& c = *p.Crossing;
  const T p0x = to(c.P0.x), p0y = to(c.P0.y);
  const T dx = to(c.P1.x) - p0x, dy = to(c.P1.y) - p0y;
  const T ex = to(c.Q1.x) - to(c.Q0.x), ey = to(c.Q1.y) - to(c.Q0.y);
  const T fx = to(c.Q0.x) - p0x, fy = to(c.Q0.y) - p0y;
  const T w = dx * ey - dy * ex;
  const T n = fx * ey - fy * ex;
  return { p0x * w + dx * n, p0y * w + dy * n, w };
}

template <class T>
Homogeneous<T> ComputeHomogeneous(const ExactPoint& p)
{
  return ComputeHomogeneous<T>(p, [](double x) { return T(x); });
}

template <class T>
Homogeneous<T> HomogeneousOf(const ExactPoint& p)
{
  return ComputeHomogeneous<T>(p);
}

/// The first filter reads a crossing's coordinates from its cache when it has one.
template <>
Homogeneous<Filtered> HomogeneousOf<Filtered>(const ExactPoint& p)
{
  if (p.Crossing && p.Crossing->Cached)
  {
    const SegmentCrossing& c = *p.Crossing;
    return { { c.H[0], c.E[0] }, { c.H[1], c.E[1] }, { c.H[2], c.E[2] } };
  }
  return ComputeHomogeneous<Filtered>(p);
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

// The exact path: every double of the predicate is an integer times 2^e; with E the least such
// exponent among them, all of them times 2^-E are integers, held exactly by GMP's mpz. Scaling
// every point by one positive factor keeps every sign (the determinants scale by a positive
// power of it), and integers need no fraction reduction, which dominated rationals' cost.
class ScaledIntegers
{
public:
  explicit ScaledIntegers(std::initializer_list<const ExactPoint*> points)
  {
    for (const ExactPoint* p : points)
    {
      if (!p->Crossing)
      {
        this->See(p->P.x);
        this->See(p->P.y);
        continue;
      }
      for (const Vec2 v : { p->Crossing->P0, p->Crossing->P1, p->Crossing->Q0, p->Crossing->Q1 })
      {
        this->See(v.x);
        this->See(v.y);
      }
    }
  }

  mpz_class operator()(double x) const
  {
    if (x == 0.0)
    {
      return mpz_class(0); // no exponent: not counted in Least, not to be shifted
    }
    int e = 0;
    const double m = std::frexp(x, &e); // x = m 2^e, 0.5 <= |m| < 1
    mpz_class z(std::ldexp(m, 53));     // an integer, exactly
    mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), static_cast<mp_bitcnt_t>(e - 53 - this->Least));
    return z;
  }

private:
  void See(double x)
  {
    if (x != 0.0)
    {
      int e = 0;
      std::frexp(x, &e);
      this->Least = std::min(this->Least, e - 53);
    }
  }
  int Least = std::numeric_limits<int>::max();
};

inline int Sign(const mpz_class& z)
{
  return sgn(z);
}

int ExactOrientSlow(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c)
{
  ++Fallbacks;
  const ScaledIntegers to{ &a, &b, &c };
  const Homogeneous<mpz_class> ha = ComputeHomogeneous<mpz_class>(a, to);
  const Homogeneous<mpz_class> hb = ComputeHomogeneous<mpz_class>(b, to);
  const Homogeneous<mpz_class> hc = ComputeHomogeneous<mpz_class>(c, to);
  return Sign(OrientDeterminant(ha, hb, hc)) * Sign(ha.W) * Sign(hb.W) * Sign(hc.W);
}

int ExactCompareSlow(const ExactPoint& a, const ExactPoint& b, int axis)
{
  ++Fallbacks;
  const ScaledIntegers to{ &a, &b };
  const Homogeneous<mpz_class> ha = ComputeHomogeneous<mpz_class>(a, to);
  const Homogeneous<mpz_class> hb = ComputeHomogeneous<mpz_class>(b, to);
  return Sign(CompareDeterminant(ha, hb, axis)) * Sign(ha.W) * Sign(hb.W);
}

/// The orientation in filtered arithmetic T, or 0 when the filter cannot decide.
template <class T>
int FilteredOrient(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c)
{
  const Homogeneous<T> ha = HomogeneousOf<T>(a);
  const Homogeneous<T> hb = HomogeneousOf<T>(b);
  const Homogeneous<T> hc = HomogeneousOf<T>(c);
  const int wa = CertainSign(ha.W), wb = CertainSign(hb.W), wc = CertainSign(hc.W);
  const int d = CertainSign(OrientDeterminant(ha, hb, hc));
  return d * wa * wb * wc;
}

/// a's coordinate minus b's in filtered arithmetic T, or 0 when the filter cannot decide.
template <class T>
int FilteredCompare(const ExactPoint& a, const ExactPoint& b, int axis)
{
  const Homogeneous<T> ha = HomogeneousOf<T>(a);
  const Homogeneous<T> hb = HomogeneousOf<T>(b);
  return CertainSign(CompareDeterminant(ha, hb, axis)) * CertainSign(ha.W) * CertainSign(hb.W);
}

/// Whether the lines through (l0, l1) and (m0, m1) are one line: exact orientations of explicit
/// points (Predicates.h), fast.
bool SameLine(Vec2 l0, Vec2 l1, Vec2 m0, Vec2 m1)
{
  return Orient2dSign(l0, l1, m0) == 0 && Orient2dSign(l0, l1, m1) == 0;
}

/// Whether p lies on the line through l0 and l1 by construction: an explicit point on it, or a
/// crossing one of whose lines it is.
bool OnLineByConstruction(const ExactPoint& p, Vec2 l0, Vec2 l1)
{
  if (!p.Crossing)
  {
    return Orient2dSign(l0, l1, p.P) == 0;
  }
  const SegmentCrossing& c = *p.Crossing;
  return SameLine(l0, l1, c.P0, c.P1) || SameLine(l0, l1, c.Q0, c.Q1);
}

/// Whether a, b and c lie on one line by construction: the commonest exact zero by far (the
/// points of one segment, or of segments along one line, met again and again while their
/// pieces are inserted), decided with orientations of explicit points only.
bool CollinearByConstruction(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c)
{
  for (const ExactPoint* p : { &a, &b, &c })
  {
    if (!p->Crossing)
    {
      continue;
    }
    const SegmentCrossing& d = *p->Crossing;
    for (const auto& [l0, l1] : { std::make_pair(d.P0, d.P1), std::make_pair(d.Q0, d.Q1) })
    {
      if (OnLineByConstruction(a, l0, l1) && OnLineByConstruction(b, l0, l1) &&
        OnLineByConstruction(c, l0, l1))
      {
        return true;
      }
    }
  }
  return false;
}

/// Whether two crossings are the crossing of the same two lines (segments drawn twice, or
/// along one line): equal, decided with orientations of explicit points only.
bool SameCrossingByConstruction(const SegmentCrossing& x, const SegmentCrossing& y)
{
  return (SameLine(x.P0, x.P1, y.P0, y.P1) && SameLine(x.Q0, x.Q1, y.Q0, y.Q1)) ||
    (SameLine(x.P0, x.P1, y.Q0, y.Q1) && SameLine(x.Q0, x.Q1, y.P0, y.P1));
}

/// The certified box of p (MakeSegmentCrossing): its center and the radius within which p
/// lies on each axis. Explicit points are their own box; false for a crossing without one.
bool CertifiedBox(const ExactPoint& p, Vec2& center, double& radius)
{
  if (!p.Crossing)
  {
    center = p.P;
    radius = 0.0;
    return true;
  }
  center = p.Crossing->Center;
  radius = p.Crossing->Radius;
  return p.Crossing->Cached && std::isfinite(radius);
}

} // namespace

//------------------------------------------------------------------------------
int ExactOrient(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c)
{
  // Certified boxes first (explicit points are their own): moving each point within its box
  // moves the determinant by at most the bound below, first order in the radii plus the
  // second-order terms, plus the rounding of these few operations.
  Vec2 ca, cb, cc;
  double ra, rb, rc;
  if (CertifiedBox(a, ca, ra) && CertifiedBox(b, cb, rb) && CertifiedBox(c, cc, rc))
  {
    const Vec2 ab = cb - ca, ac = cc - ca, bc = cc - cb;
    const double l1 = std::abs(ab.x) + std::abs(ab.y), l2 = std::abs(ac.x) + std::abs(ac.y);
    const double l3 = std::abs(bc.x) + std::abs(bc.y), r = ra + rb + rc;
    const double t1 = ab.x * ac.y, t2 = ab.y * ac.x;
    const double bound = (r * (l1 + l2 + l3) + 4.0 * r * r) * (1.0 + 1e-10) +
      8.0 * RoundingUnit * (std::abs(t1) + std::abs(t2) + r * (l1 + l2 + l3)) + Subnormal;
    const double det = t1 - t2;
    if (std::abs(det) > bound)
    {
      return det > 0 ? 1 : -1;
    }
  }
  int s = FilteredOrient<Filtered>(a, b, c);
  if (s == 0)
  {
    if (CollinearByConstruction(a, b, c))
    {
      return 0;
    }
    s = FilteredOrient<DoubleDouble>(a, b, c);
  }
  return s != 0 ? s : ExactOrientSlow(a, b, c);
}

//------------------------------------------------------------------------------
int ExactCompare(const ExactPoint& a, const ExactPoint& b, int axis)
{
  if (!a.Crossing && !b.Crossing)
  {
    const double x = axis == 0 ? a.P.x : a.P.y, y = axis == 0 ? b.P.x : b.P.y;
    return x < y ? -1 : (x > y ? 1 : 0);
  }
  // Certified boxes first: explicit points are their own box.
  Vec2 ca, cb;
  double ra, rb;
  if (CertifiedBox(a, ca, ra) && CertifiedBox(b, cb, rb))
  {
    const double d = axis == 0 ? ca.x - cb.x : ca.y - cb.y;
    const double r = ra + rb;
    if (std::abs(d) > r * (1.0 + 1e-10) +
        4.0 * RoundingUnit *
          (std::abs(axis == 0 ? ca.x : ca.y) + std::abs(axis == 0 ? cb.x : cb.y)))
    {
      return d > 0 ? 1 : -1;
    }
  }
  int s = FilteredCompare<Filtered>(a, b, axis);
  if (s == 0)
  {
    if (a.Crossing && b.Crossing && SameCrossingByConstruction(*a.Crossing, *b.Crossing))
    {
      return 0;
    }
    s = FilteredCompare<DoubleDouble>(a, b, axis);
  }
  return s != 0 ? s : ExactCompareSlow(a, b, axis);
}

//------------------------------------------------------------------------------
SegmentCrossing MakeSegmentCrossing(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1)
{
  SegmentCrossing c{ p0, p1, q0, q1 };
  const Homogeneous<Filtered> h = ComputeHomogeneous<Filtered>(ExactPoint{ p0, &c });
  c.H[0] = h.X.V;
  c.H[1] = h.Y.V;
  c.H[2] = h.W.V;
  c.E[0] = h.X.E;
  c.E[1] = h.Y.E;
  c.E[2] = h.W.E;
  c.Cached = true;
  // x = X / W with |X - X'| <= EX and |W - W'| <= EW: |x - X'/W'| <= (EX + |X'/W'| EW) /
  // (|W'| - EW); the factor covers the rounding of these few operations.
  const double w = std::abs(h.W.V);
  if (w > 2.0 * h.W.E && std::isfinite(h.X.V / h.W.V) && std::isfinite(h.Y.V / h.W.V))
  {
    c.Center = { h.X.V / h.W.V, h.Y.V / h.W.V };
    const double rx = (h.X.E + std::abs(c.Center.x) * h.W.E) / (w - h.W.E);
    const double ry = (h.Y.E + std::abs(c.Center.y) * h.W.E) / (w - h.W.E);
    c.Radius = (1.0 + 1e-10) * std::max(rx, ry) +
      4.0 * RoundingUnit * std::max(std::abs(c.Center.x), std::abs(c.Center.y)) + Subnormal;
  }
  else
  {
    c.Radius = std::numeric_limits<double>::infinity();
  }
  return c;
}

//------------------------------------------------------------------------------
Vec2 RoundedCrossing(const SegmentCrossing& c)
{
  // Along Q, from the orientations of its ends to line P: they have opposite signs for a
  // proper crossing, so the ratio is finite even where the segments are nearly parallel
  // (their cross product may round to zero there).
  const double o0 = Orient2d(c.P0, c.P1, c.Q0), o1 = Orient2d(c.P0, c.P1, c.Q1);
  if (o0 == o1)
  {
    return 0.5 * (c.Q0 + c.Q1); // parallel: no crossing; defined, not used
  }
  return c.Q0 + (o0 / (o0 - o1)) * (c.Q1 - c.Q0);
}

//------------------------------------------------------------------------------
long long ExactFallbackCount()
{
  return Fallbacks.load();
}

} // namespace boolsurf
