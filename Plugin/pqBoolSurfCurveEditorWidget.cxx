#include "pqBoolSurfCurveEditorWidget.h"

#include "vtkBoolSurfArrayNames.h"

#include "pqBoolSurfCurveEditorControls.h"
#include "pqBoolSurfDrawing.h"

#include "pqRenderView.h"
#include "pqUndoStack.h"
#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkConeSource.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkEventQtSlotConnect.h"
#include "vtkGlyph3DMapper.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPVRenderView.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMRenderViewProxy.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMSourceProxy.h"
#include "vtkSMTrace.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkWeakPointer.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QPointer>
#include <QPushButton>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>
#include <limits>
#include <unordered_map>

namespace
{
// The properties the editor writes, in the order of pqBoolSurfDrawing::Properties.
const char* const EditedProperties[] = { "Points",
  "TriangleIds",
  "Barycentrics",
  "CurveSizes",
  "ShapeIds",
  "CurveTypes",
  "ClosedCurves" };

// A press and release closer than this (pixels) is a click, not a camera drag.
constexpr double ClickSlack = 4;
// A control point is under the mouse within this distance (pixels).
constexpr double GrabRadius = 10;
// Marker and arrow sizes on screen (pixels), whatever the zoom.
constexpr double MarkerPixels = 6;
constexpr double ArrowPixels = 9;

template <typename T>
void SetVector(vtkSMProxy* proxy, const char* name, const std::vector<T>& values)
{
  vtkSMPropertyHelper helper(proxy, name);
  if (values.empty())
  {
    helper.SetNumberOfElements(0);
  }
  else
  {
    helper.Set(values.data(), static_cast<unsigned int>(values.size()));
  }
}

// Where `renderer`'s camera looks from, for pqBoolSurfDrawing::FacesEye (a parallel
// projection's eye far back along its direction); false without a renderer.
bool CameraEye(vtkRenderer* renderer, std::array<double, 3>& eye)
{
  if (!renderer)
  {
    return false;
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->GetPosition(eye.data());
  if (camera->GetParallelProjection())
  {
    double direction[3];
    camera->GetDirectionOfProjection(direction);
    for (int k = 0; k < 3; ++k)
    {
      eye[k] -= 1e9 * direction[k];
    }
  }
  return true;
}

// How many world units one pixel spans at `x` in `renderer`'s view (0 without a renderer or a
// size): markers and arrows are sized in pixels, so they look the same at every zoom.
double WorldPerPixel(vtkRenderer* renderer, const std::array<double, 3>& x)
{
  if (!renderer || renderer->GetSize()[1] <= 0)
  {
    return 0;
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  const double height = renderer->GetSize()[1];
  if (camera->GetParallelProjection())
  {
    return 2.0 * camera->GetParallelScale() / height;
  }
  double eye[3], direction[3];
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(direction);
  const double depth = (x[0] - eye[0]) * direction[0] + (x[1] - eye[1]) * direction[1] +
    (x[2] - eye[2]) * direction[2];
  const double pi = 3.14159265358979323846;
  return 2.0 * std::max(depth, 0.0) * std::tan(0.5 * camera->GetViewAngle() * pi / 180.0) / height;
}

// A glyph placed on the surface and sized in pixels: its center moved toward the eye by its
// radius, so that it sits in front of the surface there instead of half inside it.
struct Glyph
{
  std::array<double, 3> Center;
  double Radius = 0;                              // world units
  std::array<double, 3> Direction{ { 1, 0, 0 } }; // arrows only
};

// One group of glyphs of a color (spheres at control points, or cones along the curves).
struct Markers
{
  vtkNew<vtkPolyData> Centers;
  vtkNew<vtkGlyph3DMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkSmartPointer<vtkPolyDataAlgorithm> Shape;

  Markers(double r, double g, double b, bool arrows = false)
  {
    if (arrows)
    {
      vtkNew<vtkConeSource> cone; // unit size along +x, the glyph's direction
      cone->SetResolution(12);
      cone->SetHeight(2.0);
      cone->SetRadius(0.8);
      this->Shape = cone;
      this->Mapper->SetOrientationArray(boolsurf::names::EditorMarkerDirection);
      this->Mapper->SetOrientationModeToDirection();
      this->Mapper->OrientOn();
    }
    else
    {
      vtkNew<vtkSphereSource> sphere;
      sphere->SetThetaResolution(16);
      sphere->SetPhiResolution(12);
      sphere->SetRadius(1.0);
      this->Shape = sphere;
      this->Mapper->OrientOff();
    }
    this->Mapper->SetInputData(this->Centers);
    this->Mapper->SetSourceConnection(this->Shape->GetOutputPort());
    this->Mapper->SetScaleArray(boolsurf::names::EditorMarkerRadius);
    this->Mapper->SetScaleModeToScaleByMagnitude();
    this->Mapper->ScalingOn();
    this->Mapper->ScalarVisibilityOff();
    this->Actor->SetMapper(this->Mapper);
    this->Actor->GetProperty()->SetColor(r, g, b);
    this->Actor->PickableOff();
  }
  void Set(const std::vector<Glyph>& glyphs)
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    vtkNew<vtkDoubleArray> radius;
    radius->SetName(boolsurf::names::EditorMarkerRadius);
    vtkNew<vtkDoubleArray> direction;
    direction->SetName(boolsurf::names::EditorMarkerDirection);
    direction->SetNumberOfComponents(3);
    for (const Glyph& g : glyphs)
    {
      points->InsertNextPoint(g.Center.data());
      radius->InsertNextValue(g.Radius);
      direction->InsertNextTuple(g.Direction.data());
    }
    this->Centers->Initialize();
    this->Centers->SetPoints(points);
    this->Centers->GetPointData()->AddArray(radius);
    this->Centers->GetPointData()->AddArray(direction);
    this->Actor->SetVisibility(!glyphs.empty());
  }
};
}

struct pqBoolSurfCurveEditorWidget::Internals
{
  pqBoolSurfDrawing Drawing;
  int Current = -1; // the curve clicks add to (-1: the next click starts a curve)
  // What the next new curve gets, set in the panel after New Curve (before its first click):
  // a shape (-1: the first unused one) and a type. Closing needs points: a new curve is open.
  int NewShape = -1;
  int NewType = 0;
  pqBoolSurfDrawing::Handle Selected;

  // Interaction state.
  bool Dragging = false;
  bool DragMoved = false;
  bool ClickPending = false;
  int PressPosition[2] = { 0, 0 };
  bool Writing = false; // our own property writes must not reload the drawing

  QPointer<pqRenderView> View;
  vtkWeakPointer<vtkRenderWindowInteractor> Interactor;
  vtkWeakPointer<vtkRenderer> MarkerRenderer;
  vtkNew<vtkCallbackCommand> Observer;
  std::vector<unsigned long> ObserverTags;
  // Before each render of the view: markers of points on the far side of the surface are
  // hidden for the camera about to be used.
  vtkNew<vtkCallbackCommand> RenderObserver;
  vtkWeakPointer<vtkRenderer> ViewRenderer;
  unsigned long RenderTag = 0;

  // The surface's facet normals met so far, by triangle id (for points reloaded from the
  // properties, which hold no normals).
  std::unordered_map<vtkIdType, std::array<double, 3>> FacetNormals;
  Markers Others{ 0.95, 0.85, 0.25 };
  Markers CurrentCurve{ 1.0, 0.5, 0.05 };
  Markers SelectedPoint{ 0.85, 0.1, 0.1 };
  // Each curve's direction: an arrow beside every control point, toward the next one (a closed
  // curve encloses the region on its left, so this is what tells a shape from its complement).
  Markers Arrows{ 0.2, 0.45, 0.95, true };
  vtkNew<vtkEventQtSlotConnect> PropertyConnections;
  QTimer LoadTimer;

  pqBoolSurfCurveEditorControls* Controls = nullptr; // the panel's widgets

  pqBoolSurfDrawing::Curve* CurrentCurvePtr()
  {
    return this->Current >= 0 && this->Current < static_cast<int>(this->Drawing.Curves.size())
      ? &this->Drawing.Curves[this->Current]
      : nullptr;
  }
};

//------------------------------------------------------------------------------
pqBoolSurfCurveEditorWidget::pqBoolSurfCurveEditorWidget(vtkSMProxy* smproxy,
  vtkSMPropertyGroup* group,
  QWidget* parentWidget)
  : Superclass(smproxy, parentWidget)
  , Internal(new Internals())
{
  Q_UNUSED(group);
  Internals& internal = *this->Internal;
  this->setShowLabel(false);
  this->setChangeAvailableAsChangeFinished(true);

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* controls = new pqBoolSurfCurveEditorControls(this);
  controls->setObjectName("Controls");
  layout->addWidget(controls, 0, Qt::AlignLeft);
  internal.Controls = controls;

  QObject::connect(internal.Controls->Editing,
    &QCheckBox::toggled,
    this,
    &pqBoolSurfCurveEditorWidget::setEditing);
  QObject::connect(internal.Controls->CurveIndex,
    QOverload<int>::of(&QSpinBox::valueChanged),
    this,
    &pqBoolSurfCurveEditorWidget::setCurrentCurve);
  QObject::connect(internal.Controls->Shape,
    QOverload<int>::of(&QSpinBox::valueChanged),
    this,
    &pqBoolSurfCurveEditorWidget::setShape);
  QObject::connect(internal.Controls->Type,
    QOverload<int>::of(&QComboBox::currentIndexChanged),
    this,
    &pqBoolSurfCurveEditorWidget::setCurveType);
  QObject::connect(
    internal.Controls->Closed, &QCheckBox::toggled, this, &pqBoolSurfCurveEditorWidget::setClosed);
  QObject::connect(
    controls->NewCurve, &QPushButton::clicked, this, &pqBoolSurfCurveEditorWidget::newCurve);
  QObject::connect(internal.Controls->ReverseCurve,
    &QPushButton::clicked,
    this,
    &pqBoolSurfCurveEditorWidget::reverseCurve);
  QObject::connect(internal.Controls->DeletePoint,
    &QPushButton::clicked,
    this,
    &pqBoolSurfCurveEditorWidget::deletePoint);
  QObject::connect(internal.Controls->DeleteCurve,
    &QPushButton::clicked,
    this,
    &pqBoolSurfCurveEditorWidget::deleteCurve);
  QObject::connect(
    controls->Clear, &QPushButton::clicked, this, &pqBoolSurfCurveEditorWidget::clearAll);

  // Undo, redo, state loading and Python change the properties behind our back: reload (once
  // per burst of changes).
  internal.LoadTimer.setSingleShot(true);
  internal.LoadTimer.setInterval(0);
  QObject::connect(
    &internal.LoadTimer, &QTimer::timeout, this, &pqBoolSurfCurveEditorWidget::loadFromProxy);
  for (const char* name : EditedProperties)
  {
    if (vtkSMProperty* property = smproxy->GetProperty(name))
    {
      internal.PropertyConnections->Connect(
        property, vtkCommand::ModifiedEvent, this, SLOT(scheduleLoad()));
    }
  }

  if (vtkSMProperty* surface = smproxy->GetProperty("Surface"))
  {
    internal.PropertyConnections->Connect(
      surface, vtkCommand::ModifiedEvent, this, SLOT(forgetFacetNormals()));
  }

  internal.Observer->SetClientData(this);
  internal.Observer->SetCallback(&pqBoolSurfCurveEditorWidget::OnInteractorEvent);
  internal.RenderObserver->SetClientData(this);
  internal.RenderObserver->SetCallback([](vtkObject*, unsigned long, void* self, void*)
    { static_cast<pqBoolSurfCurveEditorWidget*>(self)->PlaceMarkers(); });
  this->loadFromProxy();
}

//------------------------------------------------------------------------------
pqBoolSurfCurveEditorWidget::~pqBoolSurfCurveEditorWidget()
{
  this->Detach();
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::reset()
{
  this->loadFromProxy();
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::select()
{
  this->Superclass::select();
  this->Attach();
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::deselect()
{
  this->Superclass::deselect();
  this->Detach();
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::setView(pqView* view)
{
  this->Superclass::setView(view);
  this->Detach();
  this->Attach();
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::setEditing(bool editing)
{
  if (editing)
  {
    this->Attach();
  }
  else
  {
    this->Detach();
  }
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::Attach()
{
  Internals& internal = *this->Internal;
  auto* view = qobject_cast<pqRenderView*>(this->view());
  if (!this->isSelected() || !internal.Controls->Editing->isChecked() || !view || internal.View)
  {
    return;
  }
  vtkSMRenderViewProxy* viewProxy = view->getRenderViewProxy();
  auto* pvView = vtkPVRenderView::SafeDownCast(viewProxy->GetClientSideObject());
  vtkRenderWindowInteractor* interactor = viewProxy->GetInteractor();
  if (!pvView || !interactor)
  {
    return;
  }
  internal.View = view;
  internal.Interactor = interactor;
  // Above the camera's interactor style (priority 0) and ParaView's 3D widgets.
  const float priority = 2.0f;
  for (unsigned long event : { vtkCommand::LeftButtonPressEvent,
         vtkCommand::MouseMoveEvent,
         vtkCommand::LeftButtonReleaseEvent })
  {
    internal.ObserverTags.push_back(interactor->AddObserver(event, internal.Observer, priority));
  }
  internal.ViewRenderer = viewProxy->GetRenderer();
  if (internal.ViewRenderer)
  {
    internal.RenderTag =
      internal.ViewRenderer->AddObserver(vtkCommand::StartEvent, internal.RenderObserver);
  }
  internal.MarkerRenderer = pvView->GetNonCompositedRenderer();
  for (Markers* markers :
    { &internal.Others, &internal.CurrentCurve, &internal.SelectedPoint, &internal.Arrows })
  {
    internal.MarkerRenderer->AddActor(markers->Actor);
  }
  this->FetchMissingNormals();
  this->UpdateMarkers();
  view->render();
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::Detach()
{
  Internals& internal = *this->Internal;
  if (internal.Interactor)
  {
    for (unsigned long tag : internal.ObserverTags)
    {
      internal.Interactor->RemoveObserver(tag);
    }
  }
  internal.ObserverTags.clear();
  internal.Interactor = nullptr;
  if (internal.ViewRenderer)
  {
    internal.ViewRenderer->RemoveObserver(internal.RenderTag);
  }
  internal.ViewRenderer = nullptr;
  if (internal.MarkerRenderer)
  {
    for (Markers* markers :
      { &internal.Others, &internal.CurrentCurve, &internal.SelectedPoint, &internal.Arrows })
    {
      internal.MarkerRenderer->RemoveActor(markers->Actor);
    }
  }
  internal.MarkerRenderer = nullptr;
  if (internal.Dragging && internal.DragMoved)
  {
    END_UNDO_SET(); // the drag's undo set, opened at its first move, ends with the editing
  }
  internal.Dragging = internal.ClickPending = false;
  if (internal.View)
  {
    internal.View->render();
  }
  internal.View = nullptr;
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::OnInteractorEvent(vtkObject*,
  unsigned long event,
  void* self,
  void*)
{
  auto* widget = static_cast<pqBoolSurfCurveEditorWidget*>(self);
  widget->Internal->Observer->SetAbortFlag(widget->HandleInteractorEvent(event) ? 1 : 0);
}

//------------------------------------------------------------------------------
bool pqBoolSurfCurveEditorWidget::HandleInteractorEvent(unsigned long event)
{
  Internals& internal = *this->Internal;
  if (!internal.View || !internal.Interactor)
  {
    return false;
  }
  vtkSMRenderViewProxy* viewProxy = internal.View->getRenderViewProxy();
  int position[2];
  internal.Interactor->GetEventPosition(position);
  const double moved =
    std::hypot(position[0] - internal.PressPosition[0], position[1] - internal.PressPosition[1]);

  // The control point under the mouse, if any. While a curve is being drawn, only its own
  // points are grabbed, unless the user asks for another curve's (Ctrl, or Shift to delete):
  // a click near a marker of another curve adds to the current one, as the user meant.
  auto pointUnderMouse = [&](bool anyCurve)
  {
    pqBoolSurfDrawing::Handle best;
    double bestDistance = GrabRadius;
    vtkRenderer* renderer = viewProxy->GetRenderer();
    std::array<double, 3> eye;
    const bool culled = CameraEye(renderer, eye);
    for (int c = 0; c < static_cast<int>(internal.Drawing.Curves.size()); ++c)
    {
      if (!anyCurve && c != internal.Current)
      {
        continue;
      }
      const auto& points = internal.Drawing.Curves[c].Points;
      for (int k = 0; k < static_cast<int>(points.size()); ++k)
      {
        if (culled && !pqBoolSurfDrawing::FacesEye(points[k], eye))
        {
          continue; // hidden behind the surface: not grabbed through it
        }
        const auto& x = points[k].Position;
        renderer->SetWorldPoint(x[0], x[1], x[2], 1.0);
        renderer->WorldToDisplay();
        double display[3];
        renderer->GetDisplayPoint(display);
        const double d = std::hypot(display[0] - position[0], display[1] - position[1]);
        if (d < bestDistance)
        {
          bestDistance = d;
          best = { c, k };
        }
      }
    }
    return best;
  };
  // A picked point is in view: its normal is turned toward the eye whichever way the pick
  // gives it (the source's SurfaceNormal replaces it once the point is read back).
  std::array<double, 3> pickedNormal{ { 0, 0, 0 } };
  auto pickSurface = [&](std::array<double, 3>& world)
  {
    // The pick's selection proxies are no edit of the user's (they showed on the undo stack
    // as "Changed 'vtkSMProxy'").
    pqScopedUndoExclude noUndo;
    const bool picked =
      viewProxy->ConvertDisplayToPointOnSurface(position, world.data(), pickedNormal.data()) &&
      std::isfinite(world[0]) && std::isfinite(world[1]) && std::isfinite(world[2]);
    std::array<double, 3> eye;
    if (picked && CameraEye(viewProxy->GetRenderer(), eye))
    {
      pqBoolSurfDrawing::Point p;
      p.Position = world;
      p.Normal = pickedNormal;
      if (!pqBoolSurfDrawing::FacesEye(p, eye))
      {
        for (double& c : pickedNormal)
        {
          c = -c;
        }
      }
    }
    return picked;
  };

  switch (event)
  {
    case vtkCommand::LeftButtonPressEvent:
    {
      internal.PressPosition[0] = position[0];
      internal.PressPosition[1] = position[1];
      const bool anyCurve = internal.Current < 0 || internal.Interactor->GetControlKey() ||
        internal.Interactor->GetShiftKey();
      const pqBoolSurfDrawing::Handle under = pointUnderMouse(anyCurve);
      if (!under.Valid())
      {
        internal.ClickPending =
          !internal.Interactor->GetShiftKey() && !internal.Interactor->GetControlKey();
        return false; // the camera may start a drag
      }
      if (internal.Interactor->GetShiftKey())
      {
        this->DeletePointAt(under);
        return true;
      }
      internal.Selected = under;
      internal.Current = under.Curve;
      internal.Dragging = true;
      internal.DragMoved = false;
      this->Refresh(); // the undo set starts with the drag's first move, or at the release
      return true;
    }
    case vtkCommand::MouseMoveEvent:
    {
      if (internal.ClickPending && moved > ClickSlack)
      {
        internal.ClickPending = false; // a camera drag
      }
      if (!internal.Dragging)
      {
        return false;
      }
      if (!internal.DragMoved && moved <= ClickSlack)
      {
        return true;
      }
      if (!internal.DragMoved)
      {
        BEGIN_UNDO_SET(tr("Move control point"));
      }
      internal.DragMoved = true;
      std::array<double, 3> world;
      pqBoolSurfDrawing::Point* point = internal.Drawing.Find(internal.Selected);
      if (point && pickSurface(world))
      {
        point->Position = world;
        point->Normal = pickedNormal;
        point->Triangle = -1; // snapped by the source while dragging
        this->Push();
      }
      return true;
    }
    case vtkCommand::LeftButtonReleaseEvent:
    {
      if (internal.Dragging)
      {
        internal.Dragging = false;
        pqBoolSurfDrawing::Curve* curve = internal.CurrentCurvePtr();
        if (!internal.DragMoved && curve && !curve->Closed && internal.Selected.Index == 0 &&
          curve->Points.size() >= 3)
        {
          BEGIN_UNDO_SET(tr("Close curve"));
          curve->Closed = true; // a click on the first point closes the curve
          this->Push();
          END_UNDO_SET();
        }
        else if (internal.DragMoved)
        {
          this->ReadBackExactPoints();
          END_UNDO_SET();
        }
        return true;
      }
      if (!internal.ClickPending)
      {
        return false;
      }
      internal.ClickPending = false;
      std::array<double, 3> world;
      if (!pickSurface(world))
      {
        return false;
      }
      BEGIN_UNDO_SET(tr("Add control point"));
      const int after = internal.Selected.Curve == internal.Current ? internal.Selected.Index : -1;
      const bool starts = internal.CurrentCurvePtr() == nullptr;
      internal.Selected = internal.Drawing.InsertPoint(internal.Current, after, world);
      internal.Drawing.Find(internal.Selected)->Normal = pickedNormal;
      internal.Current = internal.Selected.Curve;
      if (starts)
      {
        pqBoolSurfDrawing::Curve& curve = internal.Drawing.Curves[internal.Current];
        curve.ShapeId = internal.NewShape >= 0 ? internal.NewShape : curve.ShapeId;
        curve.Type = static_cast<boolsurf::CurveType>(internal.NewType);
        internal.NewShape = -1; // the curve after it gets a shape of its own again
      }
      this->Push();
      this->ReadBackExactPoints();
      END_UNDO_SET();
      return false;
    }
    default:
      return false;
  }
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::Push()
{
  Internals& internal = *this->Internal;
  vtkSMProxy* smproxy = this->proxy();
  const pqBoolSurfDrawing::Properties values = internal.Drawing.ToProperties();
  internal.Writing = true;
  {
    SM_SCOPED_TRACE(PropertiesModified).arg("proxy", smproxy);
    SetVector(smproxy, "Points", values.Points);
    SetVector(smproxy, "TriangleIds", values.TriangleIds);
    SetVector(smproxy, "Barycentrics", values.Barycentrics);
    SetVector(smproxy, "CurveSizes", values.CurveSizes);
    SetVector(smproxy, "ShapeIds", values.ShapeIds);
    SetVector(smproxy, "CurveTypes", values.CurveTypes);
    SetVector(smproxy, "ClosedCurves", values.ClosedCurves);
  }
  smproxy->UpdateVTKObjects();
  internal.Writing = false;
  internal.LoadTimer.stop();
  this->Refresh(); // the source and everything downstream update with the render
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::Refresh()
{
  this->UpdateMarkers();
  this->UpdateControls();
  if (pqView* view = this->view())
  {
    view->render();
  }
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> pqBoolSurfCurveEditorWidget::FetchControlCurves()
{
  // The helper proxies' properties are no edit of the user's: kept off the undo stack (where
  // they showed as "Changed 'vtkSMProxy'").
  pqScopedUndoExclude noUndo;
  vtkSMProxy* smproxy = this->proxy();
  vtkSMSessionProxyManager* pxm = smproxy->GetSessionProxyManager();
  // As paraview.servermanager.Fetch does: a reduction filter gathers the output on the first
  // server rank (which alone holds the curves under MPI), a move-data filter brings it to the
  // client (the same process in a builtin session).
  vtkSmartPointer<vtkSMSourceProxy> reducer;
  reducer.TakeReference(
    vtkSMSourceProxy::SafeDownCast(pxm->NewProxy("filters", "ReductionFilter")));
  vtkSmartPointer<vtkSMSourceProxy> mover;
  mover.TakeReference(
    vtkSMSourceProxy::SafeDownCast(pxm->NewProxy("filters", "ClientServerMoveData")));
  if (!reducer || !mover)
  {
    return nullptr;
  }
  vtkSMPropertyHelper(reducer, "Input").Set(smproxy, 0);
  vtkSMPropertyHelper(reducer, "PostGatherHelperName").Set("vtkAppendPolyData");
  reducer->UpdateVTKObjects();
  reducer->UpdatePipeline();
  vtkSMPropertyHelper(mover, "Input").Set(reducer, 0);
  vtkSMPropertyHelper(mover, "OutputDataType").Set(VTK_POLY_DATA);
  mover->UpdateVTKObjects();
  mover->UpdatePipeline();
  auto* algorithm = vtkAlgorithm::SafeDownCast(mover->GetClientSideObject());
  auto* output = algorithm ? vtkPolyData::SafeDownCast(algorithm->GetOutputDataObject(0)) : nullptr;
  if (!output || output->GetNumberOfPoints() != this->Internal->Drawing.NumberOfPoints())
  {
    // The source failed (its message says why, e.g. a triangle id that is not one).
    return nullptr;
  }
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(output);
  return copy;
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::ReadSurfaceNormals(vtkPolyData* output)
{
  vtkDataArray* normals =
    output ? output->GetPointData()->GetArray(boolsurf::names::SurfaceNormal) : nullptr;
  if (!normals || normals->GetNumberOfComponents() != 3)
  {
    return;
  }
  vtkIdType next = 0;
  for (auto& curve : this->Internal->Drawing.Curves)
  {
    for (auto& point : curve.Points)
    {
      normals->GetTuple(next++, point.Normal.data());
      if (point.Triangle >= 0)
      {
        this->Internal->FacetNormals[point.Triangle] = point.Normal;
      }
    }
  }
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::ReadBackExactPoints()
{
  Internals& internal = *this->Internal;
  vtkSmartPointer<vtkPolyData> output = this->FetchControlCurves();
  vtkDataArray* triangles =
    output ? output->GetPointData()->GetArray(boolsurf::names::TriangleId) : nullptr;
  vtkDataArray* weights =
    output ? output->GetPointData()->GetArray(boolsurf::names::Barycentric) : nullptr;
  if (!triangles || !weights || weights->GetNumberOfComponents() != 2)
  {
    return; // the points stay positions to snap
  }
  vtkIdType next = 0;
  for (auto& curve : internal.Drawing.Curves)
  {
    for (auto& point : curve.Points)
    {
      point.Triangle = static_cast<int>(triangles->GetComponent(next, 0));
      point.U = weights->GetComponent(next, 0);
      point.V = weights->GetComponent(next, 1);
      output->GetPoint(next, point.Position.data());
      ++next;
    }
  }
  this->ReadSurfaceNormals(output);
  this->Push();
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::FetchMissingNormals()
{
  bool missing = false;
  for (const auto& curve : this->Internal->Drawing.Curves)
  {
    for (const auto& point : curve.Points)
    {
      missing = missing || (point.Normal[0] == 0 && point.Normal[1] == 0 && point.Normal[2] == 0);
    }
  }
  if (missing)
  {
    this->ReadSurfaceNormals(this->FetchControlCurves());
  }
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::forgetFacetNormals()
{
  this->Internal->FacetNormals.clear(); // another surface: other facets
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::scheduleLoad()
{
  if (!this->Internal->Writing)
  {
    this->Internal->LoadTimer.start();
  }
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::loadFromProxy()
{
  Internals& internal = *this->Internal;
  vtkSMProxy* smproxy = this->proxy();
  pqBoolSurfDrawing::Properties values;
  values.Points = vtkSMPropertyHelper(smproxy, "Points").GetDoubleArray();
  values.TriangleIds = vtkSMPropertyHelper(smproxy, "TriangleIds").GetIdTypeArray();
  values.Barycentrics = vtkSMPropertyHelper(smproxy, "Barycentrics").GetDoubleArray();
  values.CurveSizes = vtkSMPropertyHelper(smproxy, "CurveSizes").GetIntArray();
  values.ShapeIds = vtkSMPropertyHelper(smproxy, "ShapeIds").GetIntArray();
  values.CurveTypes = vtkSMPropertyHelper(smproxy, "CurveTypes").GetIntArray();
  values.ClosedCurves = vtkSMPropertyHelper(smproxy, "ClosedCurves").GetIntArray();
  internal.Drawing = pqBoolSurfDrawing::FromProperties(values);
  const int curves = static_cast<int>(internal.Drawing.Curves.size());
  if (internal.Current >= curves)
  {
    internal.Current = curves - 1;
  }
  if (!internal.Drawing.Find(internal.Selected))
  {
    internal.Selected = {};
  }
  // Undo, a state file or Python give points without their surface normals (which hide the
  // markers on the far side): a point in a triangle seen before gets that facet's normal (no
  // pipeline update here: this runs right after an undo); the others' normals are read from
  // the source's output when the editor is (or next becomes) active in a view.
  for (auto& curve : internal.Drawing.Curves)
  {
    for (auto& point : curve.Points)
    {
      auto it = internal.FacetNormals.find(point.Triangle);
      if (it != internal.FacetNormals.end())
      {
        point.Normal = it->second;
      }
    }
  }
  if (internal.View)
  {
    QTimer::singleShot(0,
      this,
      [this]()
      {
        this->FetchMissingNormals();
        this->Refresh();
      });
  }
  this->Refresh();
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::UpdateControls()
{
  Internals& internal = *this->Internal;
  const int curves = static_cast<int>(internal.Drawing.Curves.size());
  const pqBoolSurfDrawing::Curve* curve = internal.CurrentCurvePtr();
  for (QWidget* w : std::initializer_list<QWidget*>{ internal.Controls->CurveIndex,
         internal.Controls->Shape,
         internal.Controls->Type,
         internal.Controls->Closed })
  {
    w->blockSignals(true);
  }
  internal.Controls->CurveIndex->setRange(-1, std::max(0, curves - 1));
  internal.Controls->CurveIndex->setSpecialValueText(tr("(new)"));
  internal.Controls->CurveIndex->setValue(internal.Current);
  internal.Controls->CurveCount->setText(tr("of %1").arg(curves));
  // Without a current curve (after New Curve), Shape and Type are those the next curve will
  // get, and can be set before its first click; it starts open.
  internal.Controls->Closed->setEnabled(curve != nullptr);
  internal.Controls->DeleteCurve->setEnabled(curve != nullptr);
  internal.Controls->ReverseCurve->setEnabled(curve != nullptr && curve->Points.size() >= 2);
  internal.Controls->DeletePoint->setEnabled(internal.Drawing.Find(internal.Selected) != nullptr);
  internal.Controls->Shape->setValue(curve
      ? curve->ShapeId
      : (internal.NewShape >= 0 ? internal.NewShape : internal.Drawing.UnusedShape()));
  internal.Controls->Type->setCurrentIndex(
    curve ? static_cast<int>(curve->Type) : internal.NewType);
  internal.Controls->Closed->setChecked(curve ? curve->Closed : false);
  for (QWidget* w : std::initializer_list<QWidget*>{ internal.Controls->CurveIndex,
         internal.Controls->Shape,
         internal.Controls->Type,
         internal.Controls->Closed })
  {
    w->blockSignals(false);
  }
  QString status =
    tr("%1 control points in %2 curves.").arg(internal.Drawing.NumberOfPoints()).arg(curves);
  // A curve being drawn is not traced until it has the points its type needs: said here, not
  // as an error (the filters leave it out without a message).
  for (int c = 0; c < curves; ++c)
  {
    const pqBoolSurfDrawing::Curve& each = internal.Drawing.Curves[c];
    const int missing = pqBoolSurfDrawing::MissingPoints(each);
    if (missing > 0)
    {
      status += " " +
        tr("Curve %1 needs %2 more point(s)%3.")
          .arg(c)
          .arg(missing)
          .arg(each.Type == boolsurf::CurveType::CubicBezier
              ? (each.Closed ? tr(" (a closed Bezier spline has 3n points: anchor, handle, "
                                  "handle, ...)")
                             : tr(" (an open Bezier spline has 3n+1 points: anchor, handle, "
                                  "handle, ..., anchor)"))
              : QString());
    }
  }
  internal.Controls->Status->setText(status);
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::UpdateMarkers()
{
  this->PlaceMarkers();
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::PlaceMarkers()
{
  Internals& internal = *this->Internal;
  // Where the camera looks from: markers whose surface faces away are hidden (they are drawn
  // over the geometry, so they would show through a closed surface). Sizes are in pixels,
  // for the camera about to render (this runs before each render).
  vtkRenderer* renderer = internal.ViewRenderer;
  std::array<double, 3> eye;
  const bool culled = CameraEye(renderer, eye);
  // A glyph of `pixels` at surface point x, moved toward the eye by its radius.
  const auto glyphAt = [&](const std::array<double, 3>& x, double pixels)
  {
    Glyph g;
    g.Center = x;
    g.Radius = pixels * WorldPerPixel(renderer, x);
    if (culled)
    {
      const double d = std::hypot(eye[0] - x[0], eye[1] - x[1], eye[2] - x[2]);
      for (int k = 0; k < 3 && d > 0; ++k)
      {
        g.Center[k] += g.Radius * (eye[k] - x[k]) / d;
      }
    }
    return g;
  };
  std::vector<Glyph> others, current, selected, arrows;
  for (int c = 0; c < static_cast<int>(internal.Drawing.Curves.size()); ++c)
  {
    const pqBoolSurfDrawing::Curve& curve = internal.Drawing.Curves[c];
    const auto& points = curve.Points;
    const int n = static_cast<int>(points.size());
    for (int k = 0; k < n; ++k)
    {
      if (culled && !pqBoolSurfDrawing::FacesEye(points[k], eye))
      {
        continue;
      }
      const bool isSelected = internal.Selected == pqBoolSurfDrawing::Handle{ c, k };
      const Glyph marker =
        glyphAt(points[k].Position, isSelected ? 1.4 * MarkerPixels : MarkerPixels);
      (isSelected ? selected : (c == internal.Current ? current : others)).push_back(marker);
      // The arrow: just past the marker, toward the next point (along the surface: the
      // direction's component along the normal removed).
      const int next = k + 1 < n ? k + 1 : (curve.Closed && n > 1 ? 0 : -1);
      if (next < 0 || !renderer)
      {
        continue;
      }
      std::array<double, 3> d;
      for (int i = 0; i < 3; ++i)
      {
        d[i] = points[next].Position[i] - points[k].Position[i];
      }
      const auto& normal = points[k].Normal;
      const double along = d[0] * normal[0] + d[1] * normal[1] + d[2] * normal[2];
      for (int i = 0; i < 3; ++i)
      {
        d[i] -= along * normal[i];
      }
      const double length = std::hypot(d[0], d[1], d[2]);
      if (!(length > 0))
      {
        continue;
      }
      Glyph arrow = glyphAt(points[k].Position, 0.5 * ArrowPixels);
      const double offset =
        (MarkerPixels + ArrowPixels) * WorldPerPixel(renderer, points[k].Position);
      for (int i = 0; i < 3; ++i)
      {
        arrow.Direction[i] = d[i] / length;
        arrow.Center[i] += std::min(offset, 0.5 * length) * arrow.Direction[i];
      }
      arrows.push_back(arrow);
    }
  }
  internal.Others.Set(others);
  internal.CurrentCurve.Set(current);
  internal.SelectedPoint.Set(selected);
  internal.Arrows.Set(arrows);
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::setCurrentCurve(int curve)
{
  this->Internal->Current = curve;
  this->Internal->Selected = {};
  this->Refresh();
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::newCurve()
{
  // The next click starts the curve: an empty curve is no valid input.
  this->setCurrentCurve(-1);
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::deleteCurve()
{
  BEGIN_UNDO_SET(tr("Delete curve"));
  if (this->Internal->Drawing.RemoveCurve(this->Internal->Current))
  {
    this->PushRemoval();
  }
  END_UNDO_SET();
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::reverseCurve()
{
  const int current = this->Internal->Current;
  this->EditCurrentCurve(tr("Reverse curve"),
    [this, current](auto&)
    {
      this->Internal->Drawing.ReverseCurve(current);
      this->Internal->Selected = {};
    });
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::deletePoint()
{
  this->DeletePointAt(this->Internal->Selected);
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::DeletePointAt(const pqBoolSurfDrawing::Handle& point)
{
  BEGIN_UNDO_SET(tr("Delete control point"));
  if (this->Internal->Drawing.RemovePoint(point))
  {
    this->PushRemoval();
  }
  END_UNDO_SET();
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::PushRemoval()
{
  Internals& internal = *this->Internal;
  // A removed curve may have been the last one: the current curve stays a valid index (or -1).
  internal.Current = std::min(internal.Current, int(internal.Drawing.Curves.size()) - 1);
  internal.Selected = {};
  this->Push();
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::clearAll()
{
  Internals& internal = *this->Internal;
  BEGIN_UNDO_SET(tr("Clear curves"));
  internal.Drawing.Curves.clear();
  internal.Current = -1;
  internal.Selected = {};
  this->Push();
  END_UNDO_SET();
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::EditCurrentCurve(const QString& label,
  const std::function<void(pqBoolSurfDrawing::Curve&)>& edit)
{
  if (pqBoolSurfDrawing::Curve* curve = this->Internal->CurrentCurvePtr())
  {
    BEGIN_UNDO_SET(label);
    edit(*curve);
    this->Push();
    END_UNDO_SET();
  }
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::setShape(int shape)
{
  if (!this->Internal->CurrentCurvePtr())
  {
    this->Internal->NewShape = shape; // for the next new curve
    return;
  }
  this->EditCurrentCurve(tr("Set curve shape"), [shape](auto& curve) { curve.ShapeId = shape; });
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::setCurveType(int type)
{
  if (!this->Internal->CurrentCurvePtr())
  {
    this->Internal->NewType = type;
    return;
  }
  this->EditCurrentCurve(tr("Set curve type"),
    [type](auto& curve) { curve.Type = static_cast<boolsurf::CurveType>(type); });
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::setClosed(bool closed)
{
  this->EditCurrentCurve(closed ? tr("Close curve") : tr("Open curve"),
    [closed](auto& curve) { curve.Closed = closed; });
}
