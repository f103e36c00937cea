// The arrangement of a refined surface that carries no Core result (read from a file, deep-
// copied), computed again from what Surface Arrangement writes for it
// (vtkBoolSurfArrangementRebuildWriter.h; a private header of the module): the one decoder
// behind vtkBoolSurfAlgorithm::GetArrangement, so that labeling and selections have one body,
// over Core types, whichever way their input came. The reader rebuilds the mesh, arranges the
// curves again (cells are numbered canonically) and refuses when the refined triangles or
// their cells differ from the input's.
#ifndef vtkBoolSurfArrangementRebuild_h
#define vtkBoolSurfArrangementRebuild_h

#include <vtkObject.h>
#include <vtkWeakPointer.h>

#include <memory>
#include <string>
#include <vector>

class vtkPolyData;

namespace boolsurf
{

struct ArrangementResult;
struct LabelingResult;

/// The arrangement of `refined` (port 0 of Surface Arrangement, or a copy of it further down)
/// computed again into `out` (its Surface, Curves, Sources, Method and Arrangement) with
/// `threads` (0: all). False with a message naming the missing arrays (a file written before
/// they existed: run Surface Arrangement again) or what differs from the input.
bool RebuildArrangement(vtkPolyData* refined,
  int threads,
  ArrangementResult& out,
  std::string& error);

/// The last arrangement RebuildArrangement computed for a filter's input, given again while the
/// input's points, triangles, ArrangementCell and field data are unchanged (a file's stages
/// below the arrangement then compute it once, not on every change of their own properties).
class RebuiltArrangement
{
public:
  std::shared_ptr<const ArrangementResult> Get(vtkPolyData* refined, std::string& error);

private:
  std::shared_ptr<const ArrangementResult> Result;
  std::vector<vtkWeakPointer<vtkObject>> Objects;
  std::vector<vtkMTimeType> Times;
};

/// Field data CellLabels and ShapeConsistent of `input` as Core labels of `arranged`'s cells.
/// False with a message when they do not fit its cells and shapes.
bool ReadLabelTable(vtkPolyData* input,
  const ArrangementResult& arranged,
  LabelingResult& labels,
  std::string& error);

} // namespace boolsurf

#endif
