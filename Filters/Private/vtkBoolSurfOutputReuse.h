// How BoolSurf filters prepare their outputs for an update (a private header of the module).
// A chain of stage filters rewrites about a hundred arrays per edit, and on a small scene VTK's
// bookkeeping for them costs more than the geometry: emptying a dataset that is already empty,
// and growing a field data's list of arrays one slot at a time (each slot a reallocation and a
// Modified event that the dataset observes).
#ifndef vtkBoolSurfOutputReuse_h
#define vtkBoolSurfOutputReuse_h

#include <array>

class vtkPolyData;

namespace boolsurf
{

/// Empties `data` unless it is empty already (no points, cells or arrays). VTK's Initialize
/// does tens of thousands of instructions on an empty dataset and drops the array slots that
/// ReserveArraySlots reserved.
void EmptyPolyData(vtkPolyData* data);

/// How many point, cell and field arrays `data` holds.
std::array<int, 3> CountArrays(vtkPolyData* data);

/// Reserves that many point, cell and field array slots in those of `data`'s attributes that
/// hold no array (an output about to be written with the arrays its last update wrote), so
/// adding them does not regrow the lists.
void ReserveArraySlots(vtkPolyData* data, const std::array<int, 3>& counts);

} // namespace boolsurf

#endif
