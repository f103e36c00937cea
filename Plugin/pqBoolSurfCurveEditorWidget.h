/**
 * @class   pqBoolSurfCurveEditorWidget
 * @brief   draws BoolSurf control curves on the surface, in the render view
 *
 * The panel of the "Surface Curves" source (panel_widget="boolsurf_curve_editor" on the
 * property group holding Points and CurveSizes). While the source's panel is active and "Edit
 * in view" is on, in the active render view:
 *
 * - a click on the surface adds a control point to the current curve (after the selected
 *   point; a new curve when there is none), snapped to the surface and then stored exactly
 *   (TriangleIds, Barycentrics);
 * - dragging a control point slides it along the surface, and the curve and everything
 *   downstream (Trace Surface Curves, BoolSurf) follow live;
 * - a click on the first point of an open curve of three or more points closes it;
 * - Shift+click on a point deletes it;
 * - Ctrl+click on a point of another curve makes that curve current (without Ctrl, points of
 *   other curves are not grabbed, so clicks near them add to the curve being drawn).
 *
 * Dragging anywhere else rotates the camera as usual. The panel chooses the current curve, its
 * shape, type (polygon or Bezier) and closure, starts a new curve and deletes points and
 * curves. Every edit is written to the source's properties at once (no Apply needed) inside an
 * undo set and a Python trace scope, so undo/redo, state files and traces keep the drawing.
 *
 * Points are picked with vtkSMRenderViewProxy::ConvertDisplayToPointOnSurface (a selection
 * render on the server), so the editor also works connected to a pvserver; the exact surface
 * points are read back from the source's output once a point is placed (not during a drag).
 * Markers (control points; the current curve's and the selected point highlighted) and arrows
 * (beside each point, toward the next one: the curve's direction, which decides the side it
 * encloses) are drawn in the view's non-composited renderer, sized in pixels and set in front
 * of the surface; before each render, those of points whose surface faces away from the camera
 * are hidden (they would show through a closed surface).
 */
#ifndef pqBoolSurfCurveEditorWidget_h
#define pqBoolSurfCurveEditorWidget_h

#include "pqPropertyWidget.h"

#include "pqBoolSurfDrawing.h" // for pqBoolSurfDrawing::Curve

#include <functional> // for std::function
#include <memory>     // for std::unique_ptr

#include "vtkSmartPointer.h" // for vtkSmartPointer

class vtkObject;
class vtkPolyData;
class vtkSMPropertyGroup;

class pqBoolSurfCurveEditorWidget : public pqPropertyWidget
{
  Q_OBJECT
  typedef pqPropertyWidget Superclass;

public:
  pqBoolSurfCurveEditorWidget(vtkSMProxy* proxy,
    vtkSMPropertyGroup* group,
    QWidget* parent = nullptr);
  ~pqBoolSurfCurveEditorWidget() override;

  /// Edits are written to the proxy as they happen: nothing is pending at Apply.
  void apply() override {}
  /// Reloads the drawing from the proxy's properties.
  void reset() override;
  void select() override;
  void deselect() override;

public Q_SLOTS:
  void setView(pqView* view) override;

private Q_SLOTS:
  void loadFromProxy();
  void scheduleLoad();
  void forgetFacetNormals();
  void newCurve();
  void deleteCurve();
  void reverseCurve();
  void deletePoint();
  void clearAll();
  void setCurrentCurve(int curve);
  void setShape(int shape);
  void setCurveType(int type);
  void setClosed(bool closed);
  void setEditing(bool editing);

private:
  Q_DISABLE_COPY(pqBoolSurfCurveEditorWidget)

  static void OnInteractorEvent(vtkObject* caller, unsigned long event, void* self, void*);
  /// Returns true when the editor consumed the event (the camera must not see it).
  bool HandleInteractorEvent(unsigned long event);
  void Attach();
  void Detach();
  /// Writes the drawing to the proxy (inside the caller's undo set) and renders.
  void Push();
  /// Reads the exact surface points (TriangleId, Barycentric) of the source's output into
  /// the drawing, then pushes them: the state then holds exact points, not positions to snap.
  void ReadBackExactPoints();
  /// The source's output (Control Curves) on the client, or null when it failed or does not
  /// hold the drawing's points.
  vtkSmartPointer<vtkPolyData> FetchControlCurves();
  /// The drawing's points' surface normals from that output (point data SurfaceNormal).
  void ReadSurfaceNormals(vtkPolyData* output);
  /// The markers and arrows of the drawing as it is now (PlaceMarkers).
  void UpdateMarkers();
  /// Markers at the drawing's points that face the camera, and an arrow beside each toward
  /// the next point of its curve, sized in pixels for the camera (before each render too).
  void PlaceMarkers();
  /// The surface normals of the drawing's points, from the source's output, when some are
  /// unknown (points loaded from a state file or by undo): their markers hide on the far side.
  void FetchMissingNormals();
  void UpdateControls();
  /// Markers and panel from the drawing, then a render of the view.
  void Refresh();
  /// Deletes a control point (Delete Point, Shift+click) as one undoable step.
  void DeletePointAt(const pqBoolSurfDrawing::Handle& point);
  /// After a point or curve was removed: keeps the current curve valid, clears the
  /// selection, pushes.
  void PushRemoval();
  /// Applies `edit` to the current curve (if any) as one undoable step, and pushes.
  void EditCurrentCurve(const QString& label,
    const std::function<void(pqBoolSurfDrawing::Curve&)>& edit);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
