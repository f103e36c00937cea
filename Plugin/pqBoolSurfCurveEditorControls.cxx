#include "pqBoolSurfCurveEditorControls.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <limits>

//------------------------------------------------------------------------------
pqBoolSurfCurveEditorControls::pqBoolSurfCurveEditorControls(QWidget* parent)
  : QWidget(parent)
{
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  this->Editing = new QCheckBox(tr("Edit curves in the render view"), this);
  this->Editing->setObjectName("EditInView");
  this->Editing->setChecked(true);
  this->Editing->setToolTip(tr("Click the surface to add a control point to the current "
                               "curve, drag a point to slide it along the surface, click the "
                               "first point of an open curve to close it, Shift+click a point "
                               "to delete it, Ctrl+click a point of another curve to make that "
                               "curve current. Dragging elsewhere rotates the camera. Arrows "
                               "show each curve's direction: a closed curve encloses the "
                               "region on its left (counter-clockwise seen from outside)."));
  layout->addWidget(this->Editing);

  // One control per row after its label: the properties dock is narrow (292 pixels by default).
  auto* grid = new QGridLayout();
  int row = 0;
  grid->addWidget(new QLabel(tr("Curve"), this), row, 0);
  this->CurveIndex = new QSpinBox(this);
  this->CurveIndex->setObjectName("CurveIndex");
  this->CurveIndex->setToolTip(tr("The current curve: clicks on the surface add to it."));
  grid->addWidget(this->CurveIndex, row, 1);
  this->CurveCount = new QLabel(this);
  this->CurveCount->setObjectName("CurveCount");
  grid->addWidget(this->CurveCount, row, 2);
  ++row;
  grid->addWidget(new QLabel(tr("Shape"), this), row, 0);
  this->Shape = new QSpinBox(this);
  this->Shape->setObjectName("Shape");
  this->Shape->setRange(0, std::numeric_limits<int>::max());
  this->Shape->setToolTip(tr("The shape (ShapeId) the current curve bounds; after New Curve, "
                             "the shape the next curve will get."));
  grid->addWidget(this->Shape, row, 1, 1, 2);
  ++row;
  grid->addWidget(new QLabel(tr("Type"), this), row, 0);
  this->Type = new QComboBox(this);
  this->Type->setObjectName("CurveType");
  this->Type->addItem(tr("Geodesic polygon"));
  this->Type->addItem(tr("Cubic Bezier spline"));
  this->Type->setToolTip(tr("A Bezier spline's points are anchor, handle, handle, ...: a "
                            "closed one has 3n points, an open one 3n+1."));
  grid->addWidget(this->Type, row, 1, 1, 2);
  ++row;
  this->Closed = new QCheckBox(tr("Closed"), this);
  this->Closed->setObjectName("Closed");
  grid->addWidget(this->Closed, row, 1, 1, 2);
  grid->setColumnStretch(1, 1);
  layout->addLayout(grid);

  auto* buttons = new QGridLayout();
  this->NewCurve = new QPushButton(tr("New Curve"), this);
  this->NewCurve->setObjectName("NewCurve");
  this->NewCurve->setToolTip(tr("The next click on the surface starts a new curve."));
  this->ReverseCurve = new QPushButton(tr("Reverse"), this);
  this->ReverseCurve->setObjectName("ReverseCurve");
  this->ReverseCurve->setToolTip(tr("Reverses the current curve's direction: a closed curve "
                                    "encloses the region on its left (the arrows in the view), "
                                    "so reversing it selects the other side."));
  this->DeletePoint = new QPushButton(tr("Delete Point"), this);
  this->DeletePoint->setObjectName("DeletePoint");
  this->DeleteCurve = new QPushButton(tr("Delete Curve"), this);
  this->DeleteCurve->setObjectName("DeleteCurve");
  this->Clear = new QPushButton(tr("Clear"), this);
  this->Clear->setObjectName("ClearAll");
  this->Clear->setToolTip(tr("Removes every curve."));
  buttons->addWidget(this->NewCurve, 0, 0);
  buttons->addWidget(this->ReverseCurve, 0, 1);
  buttons->addWidget(this->DeletePoint, 1, 0);
  buttons->addWidget(this->DeleteCurve, 1, 1);
  buttons->addWidget(this->Clear, 2, 0);
  layout->addLayout(buttons);
  this->Status = new QLabel(this);
  this->Status->setObjectName("Status");
  this->Status->setWordWrap(true);
  layout->addWidget(this->Status);
  this->installEventFilter(this); // shown or resized: fit the scroll area's visible width
}

//------------------------------------------------------------------------------
bool pqBoolSurfCurveEditorControls::eventFilter(QObject* watched, QEvent* event)
{
  if (event->type() == QEvent::Resize || event->type() == QEvent::Show)
  {
    this->FitVisibleWidth();
  }
  return QWidget::eventFilter(watched, event);
}

//------------------------------------------------------------------------------
void pqBoolSurfCurveEditorControls::FitVisibleWidth()
{
  QScrollArea* area = nullptr;
  for (QWidget* w = this->parentWidget(); w && !area; w = w->parentWidget())
  {
    area = qobject_cast<QScrollArea*>(w);
  }
  if (!area)
  {
    return;
  }
  QWidget* viewport = area->viewport();
  if (this->WatchedViewport != viewport)
  {
    this->WatchedViewport = viewport;
    viewport->installEventFilter(this);
  }
  // Where the controls start in the scrolled content, and what of it the viewport shows.
  const int left = this->mapTo(viewport, QPoint(0, 0)).x() + area->horizontalScrollBar()->value();
  const int visible = viewport->width() - left - 2;
  const int width = std::max(this->minimumSizeHint().width(), visible);
  if (this->maximumWidth() != width)
  {
    this->setMaximumWidth(width);
  }
}
