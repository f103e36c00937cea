// Homology in VTK form (a private header of the module): the arrangement writes each traced
// curve's class and the surface's generators as field data of its refined surface; the
// labeling sums them per shape (the generators in excess), explains inconsistent shapes with
// them and draws the generators on its second output.
//
// Field data (array names are API, see vtkBoolSurfLabeling.h):
//   NumberOfHomologyGenerators  1 value: 2g summed over the surface's components
//   CurveHomology               curves x generators (components G0, G1, ...), row i for the
//                               curve whose id is CurveHomologyCurveId[i]
//   CurveHomologyCurveId, CurveHomologyShapeId   per row
//   HomologyGeneratorOffsets    generators + 1 offsets into the generator point arrays
//   HomologyGeneratorPoints     3 components (positions), HomologyGeneratorTriangleId,
//   HomologyGeneratorBarycentric (2 components), HomologyGeneratorId: the generators' edge
//   crossings; HomologyShortGenerator* the same for their locally shortest loops
//   HomologyExcess              (labeling) shapes x generators, rows in the order of ShapeIds
#ifndef vtkBoolSurfHomologyOutput_h
#define vtkBoolSurfHomologyOutput_h

#include "Geodesic/TracedCurve.h"
#include "Homology/InconsistencyExplanation.h"
#include "Labeling/CellLabeling.h"

#include <string>
#include <vector>

class vtkFieldData;
class vtkPolyData;

namespace boolsurf
{

class HomologyBasis;
class TriangleMesh;

/// Computes each curve's class and writes the homology field data to `fd`; `shortened` (may
/// be null; per generator, empty when none) adds the HomologyShortGenerator* arrays. False with a
/// message when a curve cannot be walked (consecutive points sharing no triangle).
/// `generatorCache` (may be null): the generators' arrays depend on the surface only, so they
/// are written into it once (when it is empty) and its very arrays added to `fd` on later
/// updates; the caller empties it when the surface changes.
bool AddHomologyFields(const TriangleMesh& mesh,
  const HomologyBasis& basis,
  const std::vector<TracedCurve>& curves,
  const std::vector<TracedCurve>* shortened,
  vtkFieldData* fd,
  std::string& error,
  vtkFieldData* generatorCache = nullptr);

/// Reads the homology field data; Present is false when there is none. Without `withLoops`
/// the generators' points are not read (classes and counts only).
HomologyFields ReadHomologyFields(vtkFieldData* fd, bool withLoops = true);

/// Field data HomologyExcess (shapes x generators, components G0...).
void AddHomologyExcess(const std::vector<std::vector<int>>& excess,
  const std::vector<int>& shapeIds,
  vtkFieldData* fd);

/// The generators as closed polylines (point data TriangleId, Barycentric; cell data
/// GeneratorId, Shortened: 0 for the tree-cotree loops, 1 for their shortened versions) into
/// `out`.
void WriteGeneratorPolylines(const HomologyFields& h, vtkPolyData* out);

} // namespace boolsurf

#endif
