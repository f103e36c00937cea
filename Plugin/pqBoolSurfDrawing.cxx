#include "pqBoolSurfDrawing.h"

#include <algorithm>
#include <set>

namespace
{
int PerCurve(const std::vector<int>& values, size_t curve, int fallback)
{
  return curve < values.size() ? values[curve] : fallback;
}
}

//------------------------------------------------------------------------------
pqBoolSurfDrawing pqBoolSurfDrawing::FromProperties(const Properties& values)
{
  pqBoolSurfDrawing drawing;
  const size_t points = values.Points.size() / 3;
  std::vector<int> sizes = values.CurveSizes;
  if (sizes.empty() && points > 0)
  {
    sizes.push_back(static_cast<int>(points));
  }
  const bool exact =
    values.TriangleIds.size() == points && values.Barycentrics.size() == 2 * points;
  size_t next = 0;
  for (size_t c = 0; c < sizes.size(); ++c)
  {
    Curve curve;
    curve.ShapeId = PerCurve(values.ShapeIds, c, static_cast<int>(c));
    curve.Type = static_cast<boolsurf::CurveType>(PerCurve(values.CurveTypes, c, 0));
    curve.Closed = PerCurve(values.ClosedCurves, c, 1) != 0;
    for (int k = 0; k < sizes[c] && next < points; ++k, ++next)
    {
      Point point;
      std::copy_n(&values.Points[3 * next], 3, point.Position.begin());
      if (exact)
      {
        point.Triangle = static_cast<int>(values.TriangleIds[next]);
        point.U = values.Barycentrics[2 * next];
        point.V = values.Barycentrics[2 * next + 1];
      }
      curve.Points.push_back(point);
    }
    drawing.Curves.push_back(curve);
  }
  return drawing;
}

//------------------------------------------------------------------------------
pqBoolSurfDrawing::Properties pqBoolSurfDrawing::ToProperties() const
{
  Properties values;
  for (const Curve& curve : this->Curves)
  {
    for (const Point& point : curve.Points)
    {
      values.Points.insert(values.Points.end(), point.Position.begin(), point.Position.end());
      values.TriangleIds.push_back(point.Triangle);
      values.Barycentrics.push_back(point.U);
      values.Barycentrics.push_back(point.V);
    }
    values.CurveSizes.push_back(static_cast<int>(curve.Points.size()));
    values.ShapeIds.push_back(curve.ShapeId);
    values.CurveTypes.push_back(static_cast<int>(curve.Type));
    values.ClosedCurves.push_back(curve.Closed ? 1 : 0);
  }
  return values;
}

//------------------------------------------------------------------------------
int pqBoolSurfDrawing::NumberOfPoints() const
{
  int points = 0;
  for (const Curve& curve : this->Curves)
  {
    points += static_cast<int>(curve.Points.size());
  }
  return points;
}

//------------------------------------------------------------------------------
int pqBoolSurfDrawing::MissingPoints(const Curve& curve)
{
  // Core's rule, the one the Surface Curves source and the filters apply.
  return boolsurf::MissingControlPoints(curve.Type == boolsurf::CurveType::CubicBezier,
    curve.Closed,
    static_cast<int>(curve.Points.size()));
}

//------------------------------------------------------------------------------
bool pqBoolSurfDrawing::ReverseCurve(int curve)
{
  if (curve < 0 || curve >= static_cast<int>(this->Curves.size()))
  {
    return false;
  }
  std::vector<Point>& points = this->Curves[curve].Points;
  // Open: p0 .. pn-1 becomes pn-1 .. p0. Closed: p0 stays first, then pn-1 .. p1, which for a
  // closed Bezier spline (anchor, handle, handle, anchor, ...) keeps anchors at 0, 3, 6, ...
  std::reverse(points.begin() + (this->Curves[curve].Closed ? 1 : 0), points.end());
  return true;
}

//------------------------------------------------------------------------------
int pqBoolSurfDrawing::UnusedShape() const
{
  std::set<int> used;
  for (const Curve& curve : this->Curves)
  {
    used.insert(curve.ShapeId);
  }
  int shape = 0;
  while (used.count(shape))
  {
    ++shape;
  }
  return shape;
}

//------------------------------------------------------------------------------
int pqBoolSurfDrawing::AddCurve()
{
  Curve curve;
  curve.ShapeId = this->UnusedShape();
  curve.Closed = false; // drawn point by point: closed by a click on its first point
  this->Curves.push_back(curve);
  return static_cast<int>(this->Curves.size()) - 1;
}

//------------------------------------------------------------------------------
pqBoolSurfDrawing::Handle pqBoolSurfDrawing::InsertPoint(int curve,
  int after,
  const std::array<double, 3>& position)
{
  if (curve < 0 || curve >= static_cast<int>(this->Curves.size()))
  {
    curve = this->AddCurve();
  }
  std::vector<Point>& points = this->Curves[curve].Points;
  const int index = after < 0 || after >= static_cast<int>(points.size())
    ? static_cast<int>(points.size())
    : after + 1;
  Point point;
  point.Position = position;
  points.insert(points.begin() + index, point);
  return Handle{ curve, index };
}

//------------------------------------------------------------------------------
bool pqBoolSurfDrawing::RemovePoint(const Handle& handle)
{
  if (!this->Find(handle))
  {
    return false;
  }
  std::vector<Point>& points = this->Curves[handle.Curve].Points;
  points.erase(points.begin() + handle.Index);
  if (points.empty())
  {
    this->Curves.erase(this->Curves.begin() + handle.Curve);
  }
  return true;
}

//------------------------------------------------------------------------------
bool pqBoolSurfDrawing::RemoveCurve(int curve)
{
  if (curve < 0 || curve >= static_cast<int>(this->Curves.size()))
  {
    return false;
  }
  this->Curves.erase(this->Curves.begin() + curve);
  return true;
}

//------------------------------------------------------------------------------
pqBoolSurfDrawing::Point* pqBoolSurfDrawing::Find(const Handle& handle)
{
  if (handle.Curve < 0 || handle.Curve >= static_cast<int>(this->Curves.size()))
  {
    return nullptr;
  }
  std::vector<Point>& points = this->Curves[handle.Curve].Points;
  if (handle.Index < 0 || handle.Index >= static_cast<int>(points.size()))
  {
    return nullptr;
  }
  return &points[handle.Index];
}

//------------------------------------------------------------------------------
bool pqBoolSurfDrawing::FacesEye(const Point& point, const std::array<double, 3>& eye)
{
  double toEye = 0, known = 0;
  for (int k = 0; k < 3; ++k)
  {
    toEye += point.Normal[k] * (eye[k] - point.Position[k]);
    known += point.Normal[k] * point.Normal[k];
  }
  return known == 0 || toEye > 0;
}
