// The Set/Get methods vtkBoolSurfStageSettings.h declares, defined on the fields of the Core
// options structs (a private header of the module: Core's headers are private to it). A filter
// that expands a settings macro in its header expands the matching ...Definitions macro once in
// its .cxx, and creates the group's struct in its constructor.
//
// A setter calls Modified() exactly when vtkSetMacro (or vtkSetClampMacro, ...) would: when
// the value, clamped to the setting's range, differs from the one held.
#ifndef vtkBoolSurfStageSettingsDefinitions_h
#define vtkBoolSurfStageSettingsDefinitions_h

#include "vtkBoolSurfStageSettings.h"

#include "Labeling/ZeroCellOptions.h"
#include "Selection/BooleanOptions.h"
#include "Selection/BoundarySamples.h"

#include <algorithm>
#include <array>
#include <string>

namespace boolsurf
{

/// Stores `value` (converted to the field's type: an enumeration from its integer value) in
/// `field`; whether it differed.
template <typename Field, typename Value>
bool ChangeSetting(Field& field, const Value& value)
{
  const Field converted = static_cast<Field>(value);
  if (field == converted)
  {
    return false;
  }
  field = converted;
  return true;
}

/// `value` clamped to [low, high] (as vtkSetClampMacro clamps), then ChangeSetting.
template <typename Field, typename Value>
bool ChangeClampedSetting(Field& field, Value value, Value low, Value high)
{
  return ChangeSetting(field, std::min(std::max(value, low), high));
}

} // namespace boolsurf

/// Get##name() of a setting held in `field`, as its Set/Get macros declare it.
#define vtkBoolSurfSettingGetterDefinition(cls, name, type, field)                                 \
  type cls::Get##name()                                                                            \
  {                                                                                                \
    return static_cast<type>(field);                                                               \
  }

/// The methods of vtkBoolSurfSettingMacro(name, type) on `field`, e.g.
/// this->BooleanSettings->ShapeA (`type` may be an enumeration's integer type).
#define vtkBoolSurfSettingDefinition(cls, name, type, field)                                       \
  void cls::Set##name(type value)                                                                  \
  {                                                                                                \
    if (boolsurf::ChangeSetting(field, value))                                                     \
    {                                                                                              \
      this->Modified();                                                                            \
    }                                                                                              \
  }                                                                                                \
  vtkBoolSurfSettingGetterDefinition(cls, name, type, field)

/// The methods of vtkBoolSurfClampedSettingMacro: the range is the one its Get...MinValue()
/// and Get...MaxValue() give.
#define vtkBoolSurfClampedSettingDefinition(cls, name, type, field)                                \
  void cls::Set##name(type value)                                                                  \
  {                                                                                                \
    if (boolsurf::ChangeClampedSetting(                                                            \
          field, value, this->Get##name##MinValue(), this->Get##name##MaxValue()))                 \
    {                                                                                              \
      this->Modified();                                                                            \
    }                                                                                              \
  }                                                                                                \
  vtkBoolSurfSettingGetterDefinition(cls, name, type, field)

/// The methods of vtkBoolSurfStringSettingMacro on a std::string `field` (null sets "").
#define vtkBoolSurfStringSettingDefinition(cls, name, field)                                       \
  void cls::Set##name(const char* value)                                                           \
  {                                                                                                \
    if (boolsurf::ChangeSetting(field, std::string(value ? value : "")))                           \
    {                                                                                              \
      this->Modified();                                                                            \
    }                                                                                              \
  }                                                                                                \
  const char* cls::Get##name()                                                                     \
  {                                                                                                \
    return field.c_str();                                                                          \
  }

/// The methods of vtkBoolSurfVector3SettingMacro on a std::array<type, 3> `field`.
#define vtkBoolSurfVector3SettingDefinition(cls, name, type, field)                                \
  void cls::Set##name(type x, type y, type z)                                                      \
  {                                                                                                \
    if (boolsurf::ChangeSetting(field, std::array<type, 3>{ x, y, z }))                            \
    {                                                                                              \
      this->Modified();                                                                            \
    }                                                                                              \
  }                                                                                                \
  type* cls::Get##name()                                                                           \
  {                                                                                                \
    return field.data();                                                                           \
  }

/// vtkBoolSurfThreadSettingsMacro's methods on `field`, the thread count of the options the
/// filter's stage takes (this->TraceSettings->Threads, this->ArrangementSettings->Threads).
#define vtkBoolSurfThreadSettingsDefinitions(cls, field)                                           \
  vtkBoolSurfClampedSettingDefinition(cls, NumberOfThreads, int, field)

/// vtkBoolSurfBooleanSettingsMacro's methods, on this->BooleanSettings.
#define vtkBoolSurfBooleanSettingsDefinitions(cls)                                                 \
  vtkBoolSurfClampedSettingDefinition(cls, Operation, int, this->BooleanSettings->Operation);      \
  vtkBoolSurfSettingDefinition(cls, ShapeA, int, this->BooleanSettings->ShapeA);                   \
  vtkBoolSurfSettingDefinition(cls, ShapeB, int, this->BooleanSettings->ShapeB);                   \
  vtkBoolSurfStringSettingDefinition(cls, Expression, this->BooleanSettings->Expression);          \
  vtkBoolSurfClampedSettingDefinition(cls, FillRule, int, this->BooleanSettings->Rule)

/// vtkBoolSurfZeroCellSettingsMacro's methods, on this->ZeroCellSettings.
#define vtkBoolSurfZeroCellSettingsDefinitions(cls)                                                \
  vtkBoolSurfClampedSettingDefinition(cls, ZeroCellMode, int, this->ZeroCellSettings->Mode);       \
  vtkBoolSurfVector3SettingDefinition(cls, ZeroCellPoint, double, this->ZeroCellSettings->Point)

/// vtkBoolSurfBSCSettingsMacro's methods, on this->BscSettings.
#define vtkBoolSurfBSCSettingsDefinitions(cls)                                                     \
  vtkBoolSurfClampedSettingDefinition(                                                             \
    cls, SnapTolerance, double, this->BscSettings->SnapTolerance);                                 \
  vtkBoolSurfClampedSettingDefinition(cls, MaxSearchStates, int, this->BscSettings->MaxSearchStates)

#endif
