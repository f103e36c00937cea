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
#include <QSpinBox>

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
