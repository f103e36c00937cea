/**
 * @class   vtkBoolSurfSamples
 * @brief   oriented samples for Boundary-Sampled Curves, given as properties
 *
 * vtkBoolSurfSamples holds the samples of Boundary-Sampled Curves (vtkBoolSurfBSC, BoolSurf
 * with Selection = BSC) as properties, as vtkBoolSurfSurfaceCurves holds the curves: `Points`
 * (x y z per sample, on or near a curve) and `Directions` (x y z per sample, pointing to the
 * side that must be inside the region). Its output is what the BSC input port takes: the
 * points, one vertex cell each, with the point-data vector `Direction`.
 *
 * A pipeline source rather than data filled in from Python: under MPI (pvbatch on several
 * ranks, a pvserver) every rank runs the same proxy, and only the first piece holds the
 * samples, so the drawing exists once whatever the number of ranks; a trivial producer filled
 * on the client holds them on one process only.
 *
 * Errors (empty output) name the problem: a Directions count that is not the Points count.
 *
 * @sa vtkBoolSurfBSC vtkBoolSurfSurfaceCurves
 */
#ifndef vtkBoolSurfSamples_h
#define vtkBoolSurfSamples_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <vector> // for std::vector

class BOOLSURFFILTERS_EXPORT vtkBoolSurfSamples : public vtkPolyDataAlgorithm
{
public:
  static vtkBoolSurfSamples* New();
  vtkTypeMacro(vtkBoolSurfSamples, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Sample positions (x y z each).
  void SetNumberOfPoints(int n);
  int GetNumberOfPoints() const { return static_cast<int>(this->Points.size() / 3); }
  void SetPoint(int i, double x, double y, double z);
  ///@}

  ///@{
  /// Per sample, the direction pointing into the region (x y z each; need not be unit).
  void SetNumberOfDirections(int n);
  void SetDirection(int i, double x, double y, double z);
  ///@}

protected:
  vtkBoolSurfSamples();
  ~vtkBoolSurfSamples() override;

  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  std::vector<double> Points;
  std::vector<double> Directions;

private:
  vtkBoolSurfSamples(const vtkBoolSurfSamples&) = delete;
  void operator=(const vtkBoolSurfSamples&) = delete;
};

#endif
