#include "BoolSurfPluginSettings.h"

#include "vtkSMSettings.h"

namespace
{
// Array-specific defaults are read by vtkSMTransferFunctionManager when it creates the color
// map of an array: ".standard_presets.<array>" names a preset, ".array_lookup_tables.<array>"
// sets the properties of its lookup table (proxy PVLookupTable).
const char* const DefaultSettings = R"json({
  "array_lookup_tables": {
    "Region": { "PVLookupTable": {
      "IndexedLookup": 1,
      "AnnotationsInitialized": 1,
      "Annotations": ["1", "region"],
      "IndexedColors": [0.95, 0.55, 0.12],
      "IndexedOpacities": [1]
    } },
    "ArrangementCell": { "PVLookupTable": {
      "ColorSpace": "RGB",
      "Discretize": 1,
      "NumberOfTableValues": 12,
      "RGBPoints": [0.0, 0.12, 0.47, 0.90, 0.1, 0.10, 0.70, 0.80, 0.2, 0.20, 0.70, 0.30,
        0.3, 0.60, 0.80, 0.20, 0.4, 0.95, 0.80, 0.15, 0.5, 0.98, 0.55, 0.10, 0.6, 0.90, 0.30,
        0.25, 0.7, 0.85, 0.35, 0.60, 0.8, 0.60, 0.40, 0.85, 0.9, 0.40, 0.45, 0.95, 1.0, 0.55,
        0.75, 0.95]
    } },
    "ShapeLabel": { "PVLookupTable": {
      "IndexedLookup": 1,
      "AnnotationsInitialized": 1,
      "Annotations": ["-3", "-3", "-2", "-2", "-1", "-1", "0", "0 (outside)", "1", "1", "2", "2",
        "3", "3"],
      "IndexedColors": [0.40, 0.24, 0.60, 0.12, 0.47, 0.71, 0.65, 0.81, 0.89, 0.80, 0.80, 0.80,
        0.89, 0.47, 0.10, 0.84, 0.15, 0.16, 0.55, 0.34, 0.29],
      "IndexedOpacities": [1, 1, 1, 1, 1, 1, 1]
    } }
  }
})json";

// ParaView's own defaults of this kind (vtkBlockColors, AtomicNumbers) have priority 0: the
// site and user settings files override them, and these.
constexpr double Priority = 0.0;
}

void BoolSurfAddDefaultSettings()
{
  vtkSMSettings::GetInstance()->AddCollectionFromString(DefaultSettings, Priority);
}
