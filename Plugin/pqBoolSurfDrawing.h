/**
 * @class   pqBoolSurfDrawing
 * @brief   the curve editor's drawing: curves of control points, with the edits a user makes
 *
 * pqBoolSurfDrawing is what pqBoolSurfCurveEditorWidget edits, kept apart from Qt and from the
 * server manager: a list of curves, each with its control points (a position, and the exact
 * surface point once known: a triangle and the weights of its 2nd and 3rd vertex; triangle -1
 * while the point still has to be snapped), its shape, type and closure. A curve is Core's one
 * drawn curve (boolsurf::ControlCurveOf, the type of boolsurf::ControlCurve) over points that
 * are Core's surface points with what editing adds: each point's position and normal for
 * picking and drawing (a point not placed exactly yet has triangle -1); Core's rule says when
 * a curve is complete. It converts to and from the flat property values of the "Surface
 * Curves" source (Points, TriangleIds, Barycentrics, CurveSizes, ShapeIds, CurveTypes,
 * ClosedCurves).
 */
#ifndef pqBoolSurfDrawing_h
#define pqBoolSurfDrawing_h

#include "vtkType.h" // for vtkIdType

#include "Curves/ControlCurve.h" // for boolsurf::ControlCurveOf (header-only)

#include <array>  // for std::array
#include <vector> // for std::vector

struct pqBoolSurfDrawing
{
  /// A control point: Core's surface point (Triangle -1 while not placed exactly yet: the
  /// source snaps Position; U, V the weights of the triangle's 2nd and 3rd vertex) with where
  /// it is drawn.
  struct Point : boolsurf::SurfacePoint
  {
    std::array<double, 3> Position{ { 0, 0, 0 } };
    /// The surface's unit normal there (from the pick or the source's SurfaceNormal), zero
    /// while unknown.
    std::array<double, 3> Normal{ { 0, 0, 0 } };
  };
  /// A drawn curve (its CurveId unused: a curve is its index in Curves).
  using Curve = boolsurf::ControlCurveOf<Point>;
  /// A control point: its curve and its index in the curve.
  struct Handle
  {
    int Curve = -1;
    int Index = -1;
    bool Valid() const { return this->Curve >= 0 && this->Index >= 0; }
    bool operator==(const Handle& other) const
    {
      return this->Curve == other.Curve && this->Index == other.Index;
    }
  };

  std::vector<Curve> Curves;

  /// The property values of the Surface Curves source.
  struct Properties
  {
    std::vector<double> Points;
    std::vector<vtkIdType> TriangleIds;
    std::vector<double> Barycentrics;
    std::vector<int> CurveSizes, ShapeIds, CurveTypes, ClosedCurves;
  };

  /// Reads the source's properties with its defaults (one curve of all points when CurveSizes
  /// is empty; shape = curve index, polygon, closed when a per-curve list is short). Sizes that
  /// do not add up keep the points that fit.
  static pqBoolSurfDrawing FromProperties(const Properties& values);
  /// The property values: every per-curve list complete, a TriangleId per point.
  Properties ToProperties() const;

  int NumberOfPoints() const;
  /// How many more control points `curve` needs before it can be traced (0 when complete), by
  /// Core's rule (boolsurf::MissingControlPoints): a geodesic polygon needs 2, a cubic Bezier
  /// spline 3n+1 open (n >= 1) or 3n closed. A curve that needs more is one being drawn: the
  /// source marks it, no filter reports it.
  static int MissingPoints(const Curve& curve);
  /// Reverses the direction of curve `curve` (which side it encloses): the points in reverse
  /// order, a closed curve keeping its first point (so a Bezier spline keeps its anchors as
  /// anchors); returns false for an invalid index.
  bool ReverseCurve(int curve);
  /// Whether a point's marker shows from `eye`: its surface faces the eye (the marker of a
  /// point on the far side of a closed surface would show through it otherwise). For a
  /// parallel projection, `eye` is a point far back along the direction of projection. A
  /// point whose normal is unknown shows.
  static bool FacesEye(const Point& point, const std::array<double, 3>& eye);
  /// The smallest shape id no curve uses (a new curve's shape).
  int UnusedShape() const;

  /// Appends a curve (open, unlike a curve read from the properties; polygon; an unused shape);
  /// returns its index.
  int AddCurve();
  /// Inserts a point into curve `curve` after `after` (its end when `after` is -1); returns
  /// the new point.
  Handle InsertPoint(int curve, int after, const std::array<double, 3>& position);
  /// Removes a point; an emptied curve is removed too. Returns false for an invalid handle.
  bool RemovePoint(const Handle& point);
  bool RemoveCurve(int curve);
  Point* Find(const Handle& point);
};

#endif
