#include "pqBoolSurfCurveEditorWidget.h"

#include "pqBoolSurfCurveEditorControls.h"
#include "pqBoolSurfDrawing.h"

#include "pqRenderView.h"
#include "pqUndoStack.h"
#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkEventQtSlotConnect.h"
#include "vtkGlyph3DMapper.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPVDataInformation.h"
#include "vtkPVRenderView.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSMInputProperty.h"
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

// One group of markers: spheres of a color at some control points.
struct Markers
{
  vtkNew<vtkPolyData> Centers;
  vtkNew<vtkSphereSource> Sphere;
  vtkNew<vtkGlyph3DMapper> Mapper;
  vtkNew<vtkActor> Actor;

  Markers(double r, double g, double b)
  {
    this->Sphere->SetThetaResolution(16);
    this->Sphere->SetPhiResolution(12);
    this->Mapper->SetInputData(this->Centers);
    this->Mapper->SetSourceConnection(this->Sphere->GetOutputPort());
    this->Mapper->ScalingOff();
    this->Mapper->ScalarVisibilityOff();
    this->Actor->SetMapper(this->Mapper);
    this->Actor->GetProperty()->SetColor(r, g, b);
    this->Actor->PickableOff();
  }
  void Set(const std::vector<std::array<double, 3>>& centers, double radius)
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (const auto& c : centers)
    {
      points->InsertNextPoint(c.data());
    }
    this->Centers->SetPoints(points);
    this->Sphere->SetRadius(radius);
    this->Actor->SetVisibility(!centers.empty());
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
  double MarkerRadius = 0.006;
  // The surface's facet normals met so far, by triangle id (for points reloaded from the
  // properties, which hold no normals).
  std::unordered_map<vtkIdType, std::array<double, 3>> FacetNormals;
  Markers Others{ 0.95, 0.85, 0.25 };
  Markers CurrentCurve{ 1.0, 0.5, 0.05 };
  Markers SelectedPoint{ 0.85, 0.1, 0.1 };
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
  layout->addWidget(controls);
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
  for (Markers* markers : { &internal.Others, &internal.CurrentCurve, &internal.SelectedPoint })
  {
    internal.MarkerRenderer->AddActor(markers->Actor);
  }
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
    for (Markers* markers : { &internal.Others, &internal.CurrentCurve, &internal.SelectedPoint })
    {
      internal.MarkerRenderer->RemoveActor(markers->Actor);
    }
  }
  internal.MarkerRenderer = nullptr;
  if (internal.Dragging)
  {
    END_UNDO_SET(); // the drag's undo set, opened at the press, ends with the editing
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

  // The control point under the mouse, if any.
  auto pointUnderMouse = [&]()
  {
    pqBoolSurfDrawing::Handle best;
    double bestDistance = GrabRadius;
    vtkRenderer* renderer = viewProxy->GetRenderer();
    std::array<double, 3> eye;
    const bool culled = CameraEye(renderer, eye);
    for (int c = 0; c < static_cast<int>(internal.Drawing.Curves.size()); ++c)
    {
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
      const pqBoolSurfDrawing::Handle under = pointUnderMouse();
      if (!under.Valid())
      {
        internal.ClickPending = !internal.Interactor->GetShiftKey();
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
      BEGIN_UNDO_SET(tr("Move control point"));
      this->Refresh();
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
          curve->Closed = true; // a click on the first point closes the curve
          this->Push();
        }
        else if (internal.DragMoved)
        {
          this->ReadBackExactPoints();
        }
        END_UNDO_SET();
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
        curve.Shape = internal.NewShape >= 0 ? internal.NewShape : curve.Shape;
        curve.Type = internal.NewType;
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
    // The source failed (its message says why, e.g. a Bezier curve with a point count that
    // does not fit).
    return nullptr;
  }
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(output);
  return copy;
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::ReadSurfaceNormals(vtkPolyData* output)
{
  vtkDataArray* normals = output ? output->GetPointData()->GetArray("SurfaceNormal") : nullptr;
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
  vtkDataArray* triangles = output ? output->GetPointData()->GetArray("TriangleId") : nullptr;
  vtkDataArray* weights = output ? output->GetPointData()->GetArray("Barycentric") : nullptr;
  if (!triangles || !weights || weights->GetNumberOfComponents() != 2)
  {
    return; // the points stay positions to snap
  }
  vtkIdType next = 0;
  for (auto& curve : internal.Drawing.Curves)
  {
    for (auto& point : curve.Points)
    {
      point.Triangle = static_cast<vtkIdType>(triangles->GetComponent(next, 0));
      point.Weights = { weights->GetComponent(next, 0), weights->GetComponent(next, 1) };
      output->GetPoint(next, point.Position.data());
      ++next;
    }
  }
  this->ReadSurfaceNormals(output);
  this->Push();
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
  // pipeline update here: this runs right after an undo); others show until the next edit
  // reads the source's output back.
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
  internal.Controls->DeletePoint->setEnabled(internal.Drawing.Find(internal.Selected) != nullptr);
  internal.Controls->Shape->setValue(curve
      ? curve->Shape
      : (internal.NewShape >= 0 ? internal.NewShape : internal.Drawing.UnusedShape()));
  internal.Controls->Type->setCurrentIndex(curve ? curve->Type : internal.NewType);
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
  if (curve && curve->Type == 1 &&
    (curve->Closed ? curve->Points.size() % 3 != 0 : curve->Points.size() % 3 != 1))
  {
    status += tr(" The current Bezier curve needs %1 control points (anchor, handle, handle, "
                 "...).")
                .arg(curve->Closed ? tr("3n") : tr("3n+1"));
  }
  internal.Controls->Status->setText(status);
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::UpdateMarkers()
{
  // Marker size (asked of the server here, not while the view renders): a fraction of the surface's
  // size.
  double diagonal = 1;
  vtkSMProxy* smproxy = this->proxy();
  auto* input = vtkSMInputProperty::SafeDownCast(smproxy->GetProperty("Surface"));
  auto* surface = input && input->GetNumberOfProxies() > 0
    ? vtkSMSourceProxy::SafeDownCast(input->GetProxy(0))
    : nullptr;
  if (surface)
  {
    double bounds[6];
    surface->GetDataInformation(input->GetOutputPortForConnection(0))->GetBounds(bounds);
    if (bounds[0] <= bounds[1])
    {
      diagonal = std::hypot(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]);
    }
  }
  this->Internal->MarkerRadius = 0.006 * diagonal;
  this->PlaceMarkers();
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::PlaceMarkers()
{
  Internals& internal = *this->Internal;
  // Where the camera looks from: markers whose surface faces away are hidden (they are drawn
  // over the geometry, so they would show through a closed surface).
  std::array<double, 3> eye;
  const bool culled = CameraEye(internal.ViewRenderer, eye);
  std::vector<std::array<double, 3>> others, current, selected;
  for (int c = 0; c < static_cast<int>(internal.Drawing.Curves.size()); ++c)
  {
    const auto& points = internal.Drawing.Curves[c].Points;
    for (int k = 0; k < static_cast<int>(points.size()); ++k)
    {
      if (culled && !pqBoolSurfDrawing::FacesEye(points[k], eye))
      {
        continue;
      }
      if (internal.Selected == pqBoolSurfDrawing::Handle{ c, k })
      {
        selected.push_back(points[k].Position);
      }
      else
      {
        (c == internal.Current ? current : others).push_back(points[k].Position);
      }
    }
  }
  const double radius = internal.MarkerRadius;
  internal.Others.Set(others, radius);
  internal.CurrentCurve.Set(current, radius);
  internal.SelectedPoint.Set(selected, 1.4 * radius);
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
  this->EditCurrentCurve(tr("Set curve shape"), [shape](auto& curve) { curve.Shape = shape; });
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::setCurveType(int type)
{
  if (!this->Internal->CurrentCurvePtr())
  {
    this->Internal->NewType = type;
    return;
  }
  this->EditCurrentCurve(tr("Set curve type"), [type](auto& curve) { curve.Type = type; });
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorWidget::setClosed(bool closed)
{
  this->EditCurrentCurve(closed ? tr("Close curve") : tr("Open curve"),
    [closed](auto& curve) { curve.Closed = closed; });
}
