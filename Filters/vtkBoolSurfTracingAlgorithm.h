/**
 * @class   vtkBoolSurfTracingAlgorithm
 * @brief   base of the BoolSurf filters that trace curves: the trace settings, declared once
 *
 * Trace Surface Curves, Resolve Inconsistent Shapes, Offset Shapes, Winding Numbers and the
 * one-step BoolSurf filter all trace control curves on the surface before their own stage, with
 * the same settings: Resolution, ProjectionTolerance, GeodesicMethod (with the deprecated
 * ExactGeodesics switch) and NumberOfThreads. They are held here as one Core options value
 * (boolsurf::TraceOptions) that a filter hands to its stage as it is, so that a new setting, or
 * a new filter that traces, is written once (NumberOfThreads, which Surface Arrangement has
 * too, is declared in vtkBoolSurfStageSettings.h). The server-manager XML declares the same
 * properties once too (XML/Shared/TraceSettings.xml); a filter's XML exposes the ones it uses.
 *
 * @sa vtkBoolSurfAlgorithm, vtkBoolSurfTraceCurves
 */
#ifndef vtkBoolSurfTracingAlgorithm_h
#define vtkBoolSurfTracingAlgorithm_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkBoolSurfAlgorithm.h"
#include "vtkBoolSurfStageSettings.h" // for the settings' declarations

#include <memory> // for std::unique_ptr

namespace boolsurf
{
struct TraceOptions;
}

class BOOLSURFFILTERS_EXPORT vtkBoolSurfTracingAlgorithm : public vtkBoolSurfAlgorithm
{
public:
  vtkTypeMacro(vtkBoolSurfTracingAlgorithm, vtkBoolSurfAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// De Casteljau subdivision levels of Bezier splines (default 4: 16 pieces per segment),
  /// in [0, 16].
  vtkBoolSurfClampedSettingMacro(Resolution, int, 0, 16);
  ///@}

  ///@{
  /// Largest allowed distance from a control point to the surface, as a fraction of the
  /// surface's bounding-box diagonal (default 0.01). Farther points are errors.
  vtkBoolSurfClampedSettingMacro(ProjectionTolerance, double, 0.0, VTK_DOUBLE_MAX);
  ///@}

  ///@{
  /// How each geodesic leg (between two consecutive points of a geodesic polygon or of a
  /// Bezier spline's refined control polygon) is computed:
  ///
  /// - GEODESIC_BOUNDED (0, default): the shortest path in practice at a bounded cost per leg.
  ///   The exact search is used while it stays small; past that, the leg is straightened in
  ///   the homotopy class of the route found on a coarse graph built once per surface.
  /// - GEODESIC_EXACT (1): the exact polyhedral shortest path (window propagation); it can take
  ///   seconds between far points on large meshes.
  /// - GEODESIC_LOCALLY_SHORTEST (2): the shortest mesh-edge path, straightened: the fastest,
  ///   but with no guarantee of being the shortest (it may pass on the wrong side of a bump, a
  ///   saddle or a handle).
  vtkBoolSurfClampedSettingMacro(GeodesicMethod, int, GEODESIC_BOUNDED, GEODESIC_LOCALLY_SHORTEST);
  void SetGeodesicMethodToBounded() { this->SetGeodesicMethod(GEODESIC_BOUNDED); }
  void SetGeodesicMethodToExact() { this->SetGeodesicMethod(GEODESIC_EXACT); }
  void SetGeodesicMethodToLocallyShortest() { this->SetGeodesicMethod(GEODESIC_LOCALLY_SHORTEST); }
  ///@}

  ///@{
  /// @deprecated Use SetGeodesicMethod(). Kept for existing scripts: on sets GeodesicMethod to
  /// GEODESIC_EXACT, off to GEODESIC_LOCALLY_SHORTEST; GetExactGeodesics() is 1 exactly when
  /// GeodesicMethod is GEODESIC_EXACT.
  void SetExactGeodesics(vtkTypeBool exact)
  {
    this->SetGeodesicMethod(exact ? GEODESIC_EXACT : GEODESIC_LOCALLY_SHORTEST);
  }
  vtkTypeBool GetExactGeodesics() { return this->GetGeodesicMethod() == GEODESIC_EXACT ? 1 : 0; }
  void ExactGeodesicsOn() { this->SetExactGeodesics(1); }
  void ExactGeodesicsOff() { this->SetExactGeodesics(0); }
  ///@}

  /// Threads of the tracing and of the filter's own stage (the arrangement, the winding
  /// numbers); 0 (default) uses every hardware thread, in [0, 1024]. Results do not depend on
  /// it. Declared once for every filter that has it (vtkBoolSurfStageSettings.h).
  vtkBoolSurfThreadSettingsMacro();

protected:
  vtkBoolSurfTracingAlgorithm();
  ~vtkBoolSurfTracingAlgorithm() override;

  /// The settings, as the stages take them.
  const boolsurf::TraceOptions& GetTraceOptions() const { return *this->TraceSettings; }

private:
  std::unique_ptr<boolsurf::TraceOptions> TraceSettings;

  vtkBoolSurfTracingAlgorithm(const vtkBoolSurfTracingAlgorithm&) = delete;
  void operator=(const vtkBoolSurfTracingAlgorithm&) = delete;
};

#endif
