/**
 * @file    vtkBoolSurfStageSettings.h
 * @brief   the settings a stage filter shares with the one-step filter, declared once
 *
 * The one-step vtkBoolSurf exposes the settings of the stages it chains under the stages' own
 * names: the Boolean (vtkBoolSurfBoolean), the choice of the zero cell (vtkBoolSurfLabeling)
 * and BSC (vtkBoolSurfBSC). Each group is declared here once, as one macro that a filter
 * expands in its public section: the group's enumeration, its Set/Get methods with their
 * ranges, and its data members with their defaults (protected; the macro ends in the public
 * section again). Both the stage filter and vtkBoolSurf expand it, so a setting, its range or
 * its default is changed in one place and the two filters cannot drift apart.
 *
 * Why macros rather than a shared base class or a mixin: the two filters have different bases
 * (vtkBoolSurfAlgorithm, vtkBoolSurfTracingAlgorithm) and the VTK wrappers (Python, ParaView's
 * client-server) see only the vtkObject base chain, so a second base's methods would not be
 * properties; the wrappers expand these macros like vtkSetMacro. The members keep the names the
 * filters read (this->Operation, ...), as vtkSetMacro requires.
 *
 * The trace settings are vtkBoolSurfTracingAlgorithm's (one boolsurf::TraceOptions). The
 * resolve, offset and winding settings of the one-step filter are not the stages' under other
 * names: they switch an optional step on (ResolveStrategy -1, OffsetShape -1, an empty
 * CloseBrokenShapes: none) and take one value where the stage takes a list, so they are
 * declared in vtkBoolSurf.h.
 */
#ifndef vtkBoolSurfStageSettings_h
#define vtkBoolSurfStageSettings_h

#include <vtkSetGet.h> // for vtkSetClampMacro and the others

#include <string> // for std::string

/**
 * The Boolean (vtkBoolSurfBoolean): Operation (default Union; Expression uses Expression),
 * ShapeA and ShapeB the operand shapes (defaults 0 and 1; -1 means all shapes; not clamped: an
 * id below -1 is reported, not read as -1), Expression (e.g. "S0 & ~S1 | S2", default
 * "S0 | S1") and FillRule (default NonZero).
 */
#define vtkBoolSurfBooleanSettingsMacro()                                                          \
  enum Operations                                                                                  \
  {                                                                                                \
    UNION = 0,                                                                                     \
    INTERSECTION = 1,                                                                              \
    DIFFERENCE = 2,                                                                                \
    SYMMETRIC_DIFFERENCE = 3,                                                                      \
    EXPRESSION = 4,                                                                                \
  };                                                                                               \
  enum FillRules                                                                                   \
  {                                                                                                \
    NON_ZERO = 0,                                                                                  \
    EVEN_ODD = 1,                                                                                  \
    POSITIVE = 2,                                                                                  \
    NEGATIVE = 3,                                                                                  \
  };                                                                                               \
  vtkSetClampMacro(Operation, int, UNION, EXPRESSION);                                             \
  vtkGetMacro(Operation, int);                                                                     \
  void SetOperationToUnion()                                                                       \
  {                                                                                                \
    this->SetOperation(UNION);                                                                     \
  }                                                                                                \
  void SetOperationToIntersection()                                                                \
  {                                                                                                \
    this->SetOperation(INTERSECTION);                                                              \
  }                                                                                                \
  void SetOperationToDifference()                                                                  \
  {                                                                                                \
    this->SetOperation(DIFFERENCE);                                                                \
  }                                                                                                \
  void SetOperationToSymmetricDifference()                                                         \
  {                                                                                                \
    this->SetOperation(SYMMETRIC_DIFFERENCE);                                                      \
  }                                                                                                \
  void SetOperationToExpression()                                                                  \
  {                                                                                                \
    this->SetOperation(EXPRESSION);                                                                \
  }                                                                                                \
  vtkSetMacro(ShapeA, int);                                                                        \
  vtkGetMacro(ShapeA, int);                                                                        \
  vtkSetMacro(ShapeB, int);                                                                        \
  vtkGetMacro(ShapeB, int);                                                                        \
  vtkSetStdStringFromCharMacro(Expression);                                                        \
  vtkGetCharFromStdStringMacro(Expression);                                                        \
  vtkSetClampMacro(FillRule, int, NON_ZERO, NEGATIVE);                                             \
  vtkGetMacro(FillRule, int);                                                                      \
                                                                                                   \
protected:                                                                                         \
  int Operation = UNION;                                                                           \
  int ShapeA = 0;                                                                                  \
  int ShapeB = 1;                                                                                  \
  std::string Expression = "S0 | S1";                                                              \
  int FillRule = NON_ZERO;                                                                         \
                                                                                                   \
public:

/**
 * The zero cell (vtkBoolSurfLabeling): ZeroCellMode, how the cell labeled 0 for every shape is
 * chosen (default Automatic: the longest boundary loop, else a shift to minimum 0; Point: the
 * cell containing ZeroCellPoint, a point on or near the surface).
 */
#define vtkBoolSurfZeroCellSettingsMacro()                                                         \
  enum ZeroCellModes                                                                               \
  {                                                                                                \
    AUTOMATIC = 0,                                                                                 \
    POINT = 1,                                                                                     \
  };                                                                                               \
  vtkSetClampMacro(ZeroCellMode, int, AUTOMATIC, POINT);                                           \
  vtkGetMacro(ZeroCellMode, int);                                                                  \
  void SetZeroCellModeToAutomatic()                                                                \
  {                                                                                                \
    this->SetZeroCellMode(AUTOMATIC);                                                              \
  }                                                                                                \
  void SetZeroCellModeToPoint()                                                                    \
  {                                                                                                \
    this->SetZeroCellMode(POINT);                                                                  \
  }                                                                                                \
  vtkSetVector3Macro(ZeroCellPoint, double);                                                       \
  vtkGetVector3Macro(ZeroCellPoint, double);                                                       \
                                                                                                   \
protected:                                                                                         \
  int ZeroCellMode = AUTOMATIC;                                                                    \
  double ZeroCellPoint[3] = { 0, 0, 0 };                                                           \
                                                                                                   \
public:

/**
 * BSC, the region chosen by oriented samples (vtkBoolSurfBSC): SnapTolerance, how far a sample
 * may be from its patch as a fraction of the surface's bounding-box diagonal (default 0.01),
 * and MaxSearchStates, the minimum cuts the best-first search for a sample-connected region
 * computes before it finishes greedily (default 64).
 */
#define vtkBoolSurfBSCSettingsMacro()                                                              \
  vtkSetClampMacro(SnapTolerance, double, 0.0, VTK_DOUBLE_MAX);                                    \
  vtkGetMacro(SnapTolerance, double);                                                              \
  vtkSetClampMacro(MaxSearchStates, int, 1, 1000000);                                              \
  vtkGetMacro(MaxSearchStates, int);                                                               \
                                                                                                   \
protected:                                                                                         \
  double SnapTolerance = 0.01;                                                                     \
  int MaxSearchStates = 64;                                                                        \
                                                                                                   \
public:

#endif
