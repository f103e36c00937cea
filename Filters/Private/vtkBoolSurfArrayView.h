// VTK arrays that read memory owned by a Core result instead of a copy of it (a private header
// of the module). Surface Arrangement hands its refined surface to VTK this way: the points,
// triangles and per-triangle cells of a million-triangle arrangement are ~50 MB that a copy
// would write on every edit. And arrays sized once, for outputs written in place.
#ifndef vtkBoolSurfArrayView_h
#define vtkBoolSurfArrayView_h

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <memory>

namespace boolsurf
{

/// Keeps `owner` alive until ReleaseArrayView(data) is called: once per registration.
void RegisterArrayView(void* data, std::shared_ptr<const void> owner);

/// The free function of a view's buffer (VTK calls it when the array lets go of `data`).
void ReleaseArrayView(void* data);

/// An array of `tuples` x `components` values read in place at `values`, which `owner` owns
/// and keeps unchanged for as long as the owner is alive: the array (and every shallow copy of
/// a dataset holding it) keeps `owner` alive, so a pool that reuses an owner only when no one
/// else holds it never overwrites what a view shows. The values are never written through the
/// array by BoolSurf; a script that writes into them writes into the result.
template <class ArrayT>
vtkSmartPointer<ArrayT> MakeArrayView(const typename ArrayT::ValueType* values,
  vtkIdType tuples,
  int components,
  std::shared_ptr<const void> owner)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetNumberOfComponents(components);
  if (tuples == 0)
  {
    return array;
  }
  auto* data = const_cast<typename ArrayT::ValueType*>(values);
  RegisterArrayView(data, std::move(owner));
  array->SetArray(data, tuples * components, /*save=*/0, ArrayT::VTK_DATA_ARRAY_USER_DEFINED);
  array->SetArrayFreeFunction(&ReleaseArrayView);
  return array;
}

/// A new array named `name` (or unnamed) of `tuples` x `components` values, to be written in
/// place: VTK's per-value insertion (InsertNextValue, InsertNextTuple) costs tens of
/// instructions a value, more than many outputs' own computation on a small edit.
template <class ArrayT>
vtkSmartPointer<ArrayT> NewSizedArray(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}

} // namespace boolsurf

#endif
