/**
 * @file    vtkBoolSurfStageSettings.h
 * @brief   the settings filters share, declared once, held as Core options structs
 *
 * Several filters take the same settings: the thread count (every filter that traces curves or
 * arranges them), and the settings of the stages the one-step vtkBoolSurf chains, under the
 * stages' own names: the Boolean (vtkBoolSurfBoolean), the choice of the zero cell
 * (vtkBoolSurfLabeling) and BSC (vtkBoolSurfBSC). Each group is declared here once, as one
 * macro that a filter expands in its public section: the group's enumeration and its Set/Get
 * methods with their ranges. A group's values live in one Core options struct
 * (boolsurf::BooleanOptions, boolsurf::ZeroCellOptions, boolsurf::BscOptions), a protected
 * member the macro declares and the filter's constructor creates; the filter hands it to its
 * stage whole. The methods are defined by the matching ...Definitions macro of
 * Private/vtkBoolSurfStageSettingsDefinitions.h, expanded once in the filter's .cxx (Core's
 * headers are private to the module, so the public header only declares). Both the stage
 * filter and vtkBoolSurf expand the same macros, so a setting, its range or its default (the
 * struct's) is changed in one place and the two filters cannot drift apart.
 *
 * Why macros rather than a shared base class or a mixin: the filters have different bases
 * (vtkBoolSurfAlgorithm, vtkBoolSurfTracingAlgorithm) and the VTK wrappers (Python, ParaView's
 * client-server) see only the vtkObject base chain, so a second base's methods would not be
 * properties; the wrappers expand these macros as they expand vtkSetMacro.
 *
 * The trace settings are vtkBoolSurfTracingAlgorithm's (one boolsurf::TraceOptions), with the
 * thread count declared here. The resolve, offset and winding settings of the one-step filter
 * are not the stages' under other names: they switch an optional step on (ResolveStrategy -1,
 * OffsetShape -1, an empty CloseBrokenShapes: none) and take one value where the stage takes a
 * list, so they are declared in vtkBoolSurf.h.
 */
#ifndef vtkBoolSurfStageSettings_h
#define vtkBoolSurfStageSettings_h

#include <vtkSetGet.h> // for VTK_SIZEHINT, VTK_WRAPEXCLUDE, VTK_DOUBLE_MAX

#include <memory> // for std::unique_ptr

namespace boolsurf
{
struct BooleanOptions;
struct BscOptions;
struct ZeroCellOptions;
}

/**
 * One setting held in a field of a Core options struct, as vtkSetMacro/vtkGetMacro would
 * declare it (with vtkSetClampMacro's range for the clamped form, the string form of
 * vtkSetStdStringFromCharMacro and the vector form of vtkSetVector3Macro/vtkGetVector3Macro).
 * The matching ...SettingDefinition macro of Private/vtkBoolSurfStageSettingsDefinitions.h
 * defines the Set and Get methods.
 */
#define vtkBoolSurfSettingMacro(name, type)                                                        \
  virtual void Set##name(type value);                                                              \
  virtual type Get##name()
#define vtkBoolSurfClampedSettingMacro(name, type, low, high)                                      \
  vtkBoolSurfSettingMacro(name, type);                                                             \
  virtual type Get##name##MinValue()                                                               \
  {                                                                                                \
    return low;                                                                                    \
  }                                                                                                \
  virtual type Get##name##MaxValue()                                                               \
  {                                                                                                \
    return high;                                                                                   \
  }
#define vtkBoolSurfStringSettingMacro(name)                                                        \
  virtual void Set##name(const char* value);                                                       \
  virtual const char* Get##name()
#define vtkBoolSurfVector3SettingMacro(name, type)                                                 \
  virtual void Set##name(type x, type y, type z);                                                  \
  virtual void Set##name(const type value[3])                                                      \
  {                                                                                                \
    this->Set##name(value[0], value[1], value[2]);                                                 \
  }                                                                                                \
  virtual type* Get##name() VTK_SIZEHINT(3);                                                       \
  VTK_WRAPEXCLUDE                                                                                  \
  virtual void Get##name(type& x, type& y, type& z)                                                \
  {                                                                                                \
    const type* v = this->Get##name();                                                             \
    x = v[0];                                                                                      \
    y = v[1];                                                                                      \
    z = v[2];                                                                                      \
  }                                                                                                \
  VTK_WRAPEXCLUDE                                                                                  \
  virtual void Get##name(type value[3])                                                            \
  {                                                                                                \
    this->Get##name(value[0], value[1], value[2]);                                                 \
  }

/**
 * NumberOfThreads, the threads of the filter's tracing and of its own stage (the arrangement,
 * the winding numbers): 0 (default) uses every hardware thread, in [0, 1024]; results do not
 * depend on it. Held in the thread count of the Core options the filter's stage takes
 * (boolsurf::TraceOptions, boolsurf::ArrangementOptions), named where the methods are defined
 * (vtkBoolSurfThreadSettingsDefinitions).
 */
#define vtkBoolSurfThreadSettingsMacro()                                                           \
  vtkBoolSurfClampedSettingMacro(NumberOfThreads, int, 0, 1024)

/**
 * The Boolean (vtkBoolSurfBoolean), in boolsurf::BooleanOptions: Operation (default Union;
 * Expression uses Expression), ShapeA and ShapeB the operand shapes (defaults 0 and 1; -1 means
 * all shapes; not clamped: an id below -1 is reported, not read as -1), Expression (e.g.
 * "S0 & ~S1 | S2", default "S0 | S1") and FillRule (default NonZero).
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
  vtkBoolSurfClampedSettingMacro(Operation, int, UNION, EXPRESSION);                               \
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
  vtkBoolSurfSettingMacro(ShapeA, int);                                                            \
  vtkBoolSurfSettingMacro(ShapeB, int);                                                            \
  vtkBoolSurfStringSettingMacro(Expression);                                                       \
  vtkBoolSurfClampedSettingMacro(FillRule, int, NON_ZERO, NEGATIVE);                               \
                                                                                                   \
protected:                                                                                         \
  /* The Boolean settings, as the selection takes them (created by the constructor). */            \
  std::unique_ptr<boolsurf::BooleanOptions> BooleanSettings;                                       \
                                                                                                   \
public:

/**
 * The zero cell (vtkBoolSurfLabeling), in boolsurf::ZeroCellOptions: ZeroCellMode, how the cell
 * labeled 0 for every shape is chosen (default Automatic: the longest boundary loop, else a
 * shift to minimum 0; Point: the cell containing ZeroCellPoint, a point on or near the
 * surface).
 */
#define vtkBoolSurfZeroCellSettingsMacro()                                                         \
  enum ZeroCellModes                                                                               \
  {                                                                                                \
    AUTOMATIC = 0,                                                                                 \
    POINT = 1,                                                                                     \
  };                                                                                               \
  vtkBoolSurfClampedSettingMacro(ZeroCellMode, int, AUTOMATIC, POINT);                             \
  void SetZeroCellModeToAutomatic()                                                                \
  {                                                                                                \
    this->SetZeroCellMode(AUTOMATIC);                                                              \
  }                                                                                                \
  void SetZeroCellModeToPoint()                                                                    \
  {                                                                                                \
    this->SetZeroCellMode(POINT);                                                                  \
  }                                                                                                \
  vtkBoolSurfVector3SettingMacro(ZeroCellPoint, double);                                           \
                                                                                                   \
protected:                                                                                         \
  /* The zero-cell settings, as the labeling takes them (created by the constructor). */           \
  std::unique_ptr<boolsurf::ZeroCellOptions> ZeroCellSettings;                                     \
                                                                                                   \
public:

/**
 * BSC, the region chosen by oriented samples (vtkBoolSurfBSC), in boolsurf::BscOptions:
 * SnapTolerance, how far a sample may be from its patch as a fraction of the surface's
 * bounding-box diagonal (default 0.01), and MaxSearchStates, the minimum cuts the best-first
 * search for a sample-connected region computes before it finishes greedily (default 64).
 */
#define vtkBoolSurfBSCSettingsMacro()                                                              \
  vtkBoolSurfClampedSettingMacro(SnapTolerance, double, 0.0, VTK_DOUBLE_MAX);                      \
  vtkBoolSurfClampedSettingMacro(MaxSearchStates, int, 1, 1000000);                                \
                                                                                                   \
protected:                                                                                         \
  /* The BSC settings, as the selection takes them (created by the constructor). */                \
  std::unique_ptr<boolsurf::BscOptions> BscSettings;                                               \
                                                                                                   \
public:

#endif
