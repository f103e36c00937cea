// The value ranges of a filter's output arrays, computed once as the filter finishes them (a
// private header of the module).
//
// After every update ParaView reads each output array's ranges for its data information: per
// component and for the tuples' L2 norm, each with and without non-finite values. VTK computes
// each of those in its own pass over the array (six passes for a 2-component array) unless the
// array's information already holds it: vtkDataArray::GetRange and GetFiniteRange keep what
// they computed in the array's information (keys PER_COMPONENT, PER_FINITE_COMPONENT,
// L2_NORM_RANGE, L2_NORM_FINITE_RANGE) until the array is Modified(). On a region of 200k
// triangles those passes cost ParaView more than the filter's writing of the region; here one
// pass per array, split over threads, stores the same numbers in the same keys.
#ifndef vtkBoolSurfArrayRanges_h
#define vtkBoolSurfArrayRanges_h

class vtkDataArray;
class vtkPolyData;

namespace boolsurf
{

/// Stores in `array`'s information every range vtkDataArray::GetRange and GetFiniteRange give
/// (each component; for several components also the L2 norm), computed as VTK computes them,
/// in one pass on at most `threads` threads (0: all). Call it after the array's last change
/// (Modified() drops them). A small array (under 4096 values), or one holding NaN or
/// infinities, is left to VTK; so is an array already holding its ranges (an array reused
/// unchanged keeps them).
void CacheArrayRanges(vtkDataArray* array, int threads = 0);

/// CacheArrayRanges on the points and on every numeric point, cell and field array of `data`.
void CacheDataRanges(vtkPolyData* data, int threads = 0);

} // namespace boolsurf

#endif
