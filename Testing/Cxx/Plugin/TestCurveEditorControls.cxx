// The curve editor's panel at ParaView's default properties-dock width: every control shows
// whole (a user found "of N", Closed, Delete Curve and Clear cut off until the dock was
// widened). Laid out by Qt on its offscreen platform with the system's fonts.
#include "pqBoolSurfCurveEditorControls.h"

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QFont>
#include <QLabel>
#include <QLayout>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QVBoxLayout>

#include <gtest/gtest.h>

#include <string>

namespace
{
// ParaView 5.11's GUI on Debian 12 under X: the properties dock is 292 pixels wide by default
// and the font is "Sans Serif" 9 (both checked in the GUI test, GuiTutorial.xml, which fails
// when they change); the panel inside the dock loses the dock's frame and the scroll area's
// margins and scroll bar.
constexpr int DefaultDockWidth = 292;
constexpr int PanelWidth = DefaultDockWidth - 40;

QApplication& App()
{
  static int argc = 1;
  static char name[] = "BoolSurfPanelTests";
  static char* argv[] = { name, nullptr };
  static QApplication app(argc, argv);
  QApplication::setFont(QFont("Sans Serif", 9));
  return app;
}
} // namespace

TEST(CurveEditorControls, EveryControlShowsWholeAtTheDefaultDockWidth)
{
  App();
  pqBoolSurfCurveEditorControls controls;
  controls.CurveCount->setText("of 12");
  controls.Status->setText("24 control points in 12 curves.");
  EXPECT_LE(controls.minimumSizeHint().width(), PanelWidth)
    << "the panel needs " << controls.minimumSizeHint().width() << " pixels";
  controls.resize(PanelWidth,
    controls.heightForWidth(PanelWidth) > 0 ? controls.heightForWidth(PanelWidth)
                                            : controls.sizeHint().height());
  controls.show();
  controls.layout()->activate();
  QApplication::processEvents();
  const QRect panel = controls.rect();
  const std::vector<QWidget*> all = { controls.Editing,
    controls.CurveIndex,
    controls.CurveCount,
    controls.Shape,
    controls.Type,
    controls.Closed,
    controls.NewCurve,
    controls.ReverseCurve,
    controls.DeletePoint,
    controls.DeleteCurve,
    controls.Clear };
  for (QWidget* w : all)
  {
    const std::string name = w->objectName().toStdString();
    const QRect g = w->geometry();
    EXPECT_TRUE(panel.contains(g)) << name << " lies outside the panel";
    // Not squeezed below what its text needs (a button's or label's text would be cut).
    EXPECT_GE(g.width(), w->minimumSizeHint().width()) << name;
    if (qobject_cast<QAbstractButton*>(w) || qobject_cast<QLabel*>(w))
    {
      EXPECT_GE(g.width(), w->sizeHint().width()) << name << " is narrower than its text";
    }
  }
}

// ParaView's properties panel widens when the selected output's display section needs more than
// the dock (the Traced Curves output of Surface Curves did): the panel scrolls sideways and
// controls stretched to its width were cut off at the dock's edge (spin-box arrows, "of 2", the
// Type arrow, "Delete Poi..."). The controls stay inside the visible part.
TEST(CurveEditorControls, StayVisibleWhenThePanelIsWiderThanTheDock)
{
  App();
  // Left-aligned as the editor places them, and stretched (the cap alone must hold them).
  for (const bool aligned : { true, false })
  {
    SCOPED_TRACE(aligned ? "aligned left" : "stretched");
    QScrollArea area;
    area.setWidgetResizable(true);
    area.resize(DefaultDockWidth, 700);
    auto* content = new QWidget();
    auto* layout = new QVBoxLayout(content);
    auto* editor = new QWidget(content); // the editor's property widget, as in ParaView
    auto* editorLayout = new QVBoxLayout(editor);
    editorLayout->setContentsMargins(0, 0, 0, 0);
    auto* controls = new pqBoolSurfCurveEditorControls(editor);
    if (aligned)
    {
      editorLayout->addWidget(controls, 0, Qt::AlignLeft);
    }
    else
    {
      editorLayout->addWidget(controls);
    }
    layout->addWidget(editor);
    auto* display = new QWidget(content); // a display section wider than the dock
    display->setMinimumWidth(DefaultDockWidth + 160);
    display->setMinimumHeight(40);
    layout->addWidget(display);
    area.setWidget(content);
    controls->CurveCount->setText("of 12");
    controls->Status->setText("24 control points in 12 curves. Curve 11 needs 2 more point(s) (an "
                              "open Bezier spline has 3n+1 points: anchor, handle, handle, ..., "
                              "anchor).");
    area.show();
    for (int k = 0; k < 3; ++k)
    {
      QApplication::processEvents();
    }
    ASSERT_GT(content->width(), area.viewport()->width()) << "the panel should scroll sideways";
    QWidget* viewport = area.viewport();
    for (QWidget* w : std::vector<QWidget*>{ controls->CurveIndex,
           controls->CurveCount,
           controls->Shape,
           controls->Type,
           controls->Closed,
           controls->NewCurve,
           controls->ReverseCurve,
           controls->DeletePoint,
           controls->DeleteCurve,
           controls->Clear,
           controls->Status })
    {
      const QRect g(w->mapTo(viewport, QPoint(0, 0)), w->size());
      EXPECT_LE(g.right(), viewport->width())
        << w->objectName().toStdString() << " runs past the visible part of the panel";
      if (qobject_cast<QAbstractButton*>(w))
      {
        EXPECT_GE(g.width(), w->sizeHint().width()) << w->objectName().toStdString();
      }
    }
  }
}
