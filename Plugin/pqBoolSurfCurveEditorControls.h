/**
 * @class   pqBoolSurfCurveEditorControls
 * @brief   the widgets of the curve editor's panel, laid out to fit ParaView's properties dock
 *
 * Plain Qt (no ParaView): pqBoolSurfCurveEditorWidget connects them to the drawing. Kept apart
 * so that the layout is tested on its own (Testing/Cxx/Plugin): at ParaView's default dock
 * width every control shows whole. Rows, narrow to wide: the edit toggle; Curve [n] "of N";
 * Shape [n]; Type [polygon/Bezier]; Closed; the five buttons two by two; the status line.
 */
#ifndef pqBoolSurfCurveEditorControls_h
#define pqBoolSurfCurveEditorControls_h

#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QSpinBox;

class pqBoolSurfCurveEditorControls : public QWidget
{
  Q_OBJECT

public:
  explicit pqBoolSurfCurveEditorControls(QWidget* parent = nullptr);

  /// Keeps the controls inside the visible width of the scroll area that holds them (the
  /// properties panel): ParaView's display section of a selected output (Traced Curves) can
  /// make the panel wider than its dock, and controls stretched to that width were cut off at
  /// the dock's edge. Watches the scroll area's viewport once it is found.
  bool eventFilter(QObject* watched, QEvent* event) override;
  void FitVisibleWidth();

  QCheckBox* Editing = nullptr;
  QSpinBox* CurveIndex = nullptr;
  QLabel* CurveCount = nullptr;
  QSpinBox* Shape = nullptr;
  QComboBox* Type = nullptr;
  QCheckBox* Closed = nullptr;
  QPushButton* NewCurve = nullptr;
  QPushButton* ReverseCurve = nullptr;
  QPushButton* DeletePoint = nullptr;
  QPushButton* DeleteCurve = nullptr;
  QPushButton* Clear = nullptr;
  QLabel* Status = nullptr;

private:
  QWidget* WatchedViewport = nullptr;
};

#endif
