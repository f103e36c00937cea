/**
 * Setters for the repeatable properties of BoolSurf's sources (vtkBoolSurfSurfaceCurves,
 * vtkBoolSurfSamples): ParaView sets a property's number of elements first, then each element;
 * both report whether anything changed, so the source is marked modified only then.
 */
#ifndef vtkBoolSurfPropertyVector_h
#define vtkBoolSurfPropertyVector_h

#include <cstddef>          // for std::size_t
#include <initializer_list> // for std::initializer_list
#include <vector>           // for std::vector

namespace boolsurf
{

/// Resizes `values` to `n` elements (new ones `fill`); true when the size changed.
template <typename T>
bool ResizeProperty(std::vector<T>& values, std::size_t n, T fill = T())
{
  if (values.size() == n)
  {
    return false;
  }
  values.resize(n, fill);
  return true;
}

/// Sets the elements from `first` on; elements past the end are ignored (the size comes
/// first). True when a value changed.
template <typename T>
bool SetPropertyElements(std::vector<T>& values, std::size_t first, std::initializer_list<T> set)
{
  bool changed = false;
  for (const T& value : set)
  {
    if (first < values.size() && values[first] != value)
    {
      values[first] = value;
      changed = true;
    }
    ++first;
  }
  return changed;
}

} // namespace boolsurf

#endif
