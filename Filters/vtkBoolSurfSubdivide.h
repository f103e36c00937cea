/**
 * @class   vtkBoolSurfSubdivide
 * @brief   subdivide a surface and carry curves' surface points onto it
 *
 * vtkBoolSurfSubdivide refines a triangle surface with VTK's linear (vtkLinearSubdivisionFilter)
 * or Loop (vtkLoopSubdivisionFilter) subdivision and moves the exact surface points
 * (`TriangleId`, `Barycentric`) of a curves polydata onto the finer surface (paper §4.5, last
 * paragraph), so that curves, a resolved shape set or a result's control points drawn on a coarse
 * surface can be traced and combined on a finer one.
 *
 * Each step splits every triangle into four (corner triangles at the old vertices, one in the
 * middle); a point goes to the child that contains it in its parent's barycentric parameters
 * (Core's SubdivisionMap, which reads the split from the two meshes' triangles). With Linear
 * subdivision the surface does not move and every point keeps its 3D position (to rounding);
 * with Loop subdivision the surface is smoothed and the points move with it, staying at the same
 * place of the parametrization.
 *
 * Inputs: port 0 the surface (triangles only), port 1 the curves, with point data TriangleId and
 * Barycentric (2 components), as the scene reader and Resolve Inconsistent Shapes give them (and
 * as vtkBoolSurfTraceCurves accepts them). Outputs: port 0 the subdivided surface, port 1 the
 * curves with the same cells and cell data, TriangleId and Barycentric on the subdivided surface
 * and 3D points at those places; other point data is copied.
 *
 * Errors (empty outputs): a surface cell that is not a triangle, curves without TriangleId and
 * Barycentric, a TriangleId out of range or barycentric coordinates outside the triangle (named
 * with the point id), a subdivision filter that fails (for example Loop on a non-manifold
 * surface) or whose output is not a 1-to-4 split.
 *
 * @sa vtkLinearSubdivisionFilter vtkLoopSubdivisionFilter vtkBoolSurfTraceCurves
 */
#ifndef vtkBoolSurfSubdivide_h
#define vtkBoolSurfSubdivide_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkBoolSurfAlgorithm.h"

class BOOLSURFFILTERS_EXPORT vtkBoolSurfSubdivide : public vtkBoolSurfAlgorithm
{
public:
  static vtkBoolSurfSubdivide* New();
  vtkTypeMacro(vtkBoolSurfSubdivide, vtkBoolSurfAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Schemes
  {
    LINEAR = 0,
    LOOP = 1
  };

  ///@{
  /// Linear (0, default: the surface keeps its shape) or Loop (1: smoothed) subdivision.
  vtkSetClampMacro(Scheme, int, LINEAR, LOOP);
  vtkGetMacro(Scheme, int);
  void SetSchemeToLinear() { this->SetScheme(LINEAR); }
  void SetSchemeToLoop() { this->SetScheme(LOOP); }
  ///@}

  ///@{
  /// Number of 1-to-4 steps (default 1; the triangle count grows by 4 per step).
  vtkSetClampMacro(NumberOfSubdivisions, int, 0, 8);
  vtkGetMacro(NumberOfSubdivisions, int);
  ///@}

  /// Port 0: the surface; port 1: the curves.
  void SetSurfaceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetCurvesConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  /// The curves output (port 1).
  vtkPolyData* GetCurvesOutput() { return this->GetOutput(1); }

protected:
  vtkBoolSurfSubdivide();
  ~vtkBoolSurfSubdivide() override;

  bool Execute(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs,
    std::string& error) override;

  int Scheme = LINEAR;
  int NumberOfSubdivisions = 1;

private:
  vtkBoolSurfSubdivide(const vtkBoolSurfSubdivide&) = delete;
  void operator=(const vtkBoolSurfSubdivide&) = delete;
};

#endif
