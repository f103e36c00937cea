// Small fixed-size vector types used throughout the Core library.
//
// Core keeps its own tiny value types instead of Eigen so that headers stay light and
// every stage can pass plain arrays across the VTK boundary without conversions.
#ifndef boolsurf_Vec3_h
#define boolsurf_Vec3_h

#include <cmath>

namespace boolsurf
{

struct Vec2
{
  double x = 0, y = 0;
};

inline Vec2 operator+(Vec2 a, Vec2 b)
{
  return { a.x + b.x, a.y + b.y };
}
inline Vec2 operator-(Vec2 a, Vec2 b)
{
  return { a.x - b.x, a.y - b.y };
}
inline Vec2 operator*(double s, Vec2 a)
{
  return { s * a.x, s * a.y };
}
inline double Dot(Vec2 a, Vec2 b)
{
  return a.x * b.x + a.y * b.y;
}
/// z component of the 3D cross product: > 0 when b is counter-clockwise from a.
inline double Cross(Vec2 a, Vec2 b)
{
  return a.x * b.y - a.y * b.x;
}
inline double Length(Vec2 a)
{
  return std::sqrt(Dot(a, a));
}

struct Vec3
{
  double x = 0, y = 0, z = 0;
  double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

inline Vec3 operator+(Vec3 a, Vec3 b)
{
  return { a.x + b.x, a.y + b.y, a.z + b.z };
}
inline Vec3 operator-(Vec3 a, Vec3 b)
{
  return { a.x - b.x, a.y - b.y, a.z - b.z };
}
inline Vec3 operator*(double s, Vec3 a)
{
  return { s * a.x, s * a.y, s * a.z };
}
inline double Dot(Vec3 a, Vec3 b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 Cross(Vec3 a, Vec3 b)
{
  return { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
}
inline double Length(Vec3 a)
{
  return std::sqrt(Dot(a, a));
}
inline double Distance(Vec3 a, Vec3 b)
{
  return Length(a - b);
}

/// The point of segment [a, b] closest to p (a when a == b).
inline Vec3 ClosestPointOnSegment(const Vec3& a, const Vec3& b, const Vec3& p)
{
  const Vec3 ab = b - a;
  const double l2 = Dot(ab, ab);
  double t = l2 > 0.0 ? Dot(p - a, ab) / l2 : 0.0;
  t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
  return a + t * ab;
}

/// Distance from p to the segment [a, b] (a point when a == b).
inline double SegmentPointDistance(const Vec3& a, const Vec3& b, const Vec3& p)
{
  return Distance(ClosestPointOnSegment(a, b, p), p);
}

inline bool IsFinite(Vec3 a)
{
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

} // namespace boolsurf

#endif
