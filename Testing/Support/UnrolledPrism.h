// The open regular prism of MakeOpenCylinder(radius, height, around, along) rolled out flat:
// it is developable, so the shortest path between two of its points is a straight line in
// the unrolling, the shorter way around. The exact oracle of the prism geodesic tests.
#ifndef boolsurf_UnrolledPrism_h
#define boolsurf_UnrolledPrism_h

#include "Mesh/Vec3.h"

#include <algorithm>
#include <cmath>

namespace boolsurf
{
namespace testing
{

struct UnrolledPrism
{
  int Around = 48;
  double Radius = 1.0;

  double Sector() const { return 2 * std::acos(-1.0) / this->Around; }
  double Facet() const { return 2 * this->Radius * std::sin(this->Sector() / 2); }
  /// The unrolled prism's width (its perimeter).
  double Width() const { return this->Around * this->Facet(); }

  /// (distance along the perimeter from the facet at angle 0, height) of a point of the prism.
  Vec2 Unroll(const Vec3& p) const
  {
    double phi = std::atan2(p.y, p.x);
    if (phi < 0)
    {
      phi += 2 * std::acos(-1.0);
    }
    const int j = static_cast<int>(std::floor(phi / this->Sector() + 1e-12)) % this->Around;
    const Vec3 corner{
      this->Radius * std::cos(j * this->Sector()), this->Radius * std::sin(j * this->Sector()), 0
    };
    return Vec2{ j * this->Facet() + Distance(Vec3{ p.x, p.y, 0 }, corner), p.z };
  }

  /// Distance around the perimeter between a and b, one way (in [0, Width())).
  double AroundDistance(const Vec3& a, const Vec3& b) const
  {
    return std::abs(this->Unroll(a).x - this->Unroll(b).x);
  }

  /// Length of the shortest path from a to b on the prism.
  double ShortestLength(const Vec3& a, const Vec3& b) const
  {
    const double dx = this->AroundDistance(a, b);
    return std::hypot(std::min(dx, this->Width() - dx), b.z - a.z);
  }
};

} // namespace testing
} // namespace boolsurf

#endif
