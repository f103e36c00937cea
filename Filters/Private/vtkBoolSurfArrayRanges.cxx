#include "vtkBoolSurfArrayRanges.h"

#include "Mesh/ParallelRange.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkInformationInformationVectorKey.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTemplateAliasMacro.h>
#include <vtkTypeTraits.h>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

namespace boolsurf
{
namespace
{

/// What one block of tuples holds: per component its least and greatest value (VTK's
/// accumulators: the value type's extremes to start with, the first of equal values kept, as
/// std::min and std::max do), and the least and greatest squared L2 norm of its tuples.
template <class T>
struct BlockRanges
{
  std::vector<T> Values; // min, max per component
  double Norm2[2] = { vtkTypeTraits<double>::Max(), vtkTypeTraits<double>::Min() };
  bool Finite = true;

  explicit BlockRanges(int components)
  {
    for (int c = 0; c < components; ++c)
    {
      this->Values.push_back(vtkTypeTraits<T>::Max());
      this->Values.push_back(vtkTypeTraits<T>::Min());
    }
  }

  /// Merges a later block (so that ties keep the earlier value, as one pass in order does).
  void Merge(const BlockRanges& later)
  {
    for (std::size_t k = 0; k < this->Values.size(); k += 2)
    {
      this->Values[k] = std::min(this->Values[k], later.Values[k]);
      this->Values[k + 1] = std::max(this->Values[k + 1], later.Values[k + 1]);
    }
    this->Norm2[0] = std::min(this->Norm2[0], later.Norm2[0]);
    this->Norm2[1] = std::max(this->Norm2[1], later.Norm2[1]);
    this->Finite = this->Finite && later.Finite;
  }
};

/// ScanBlock for arrays of `C` components: the accumulators in locals (registers), not in the
/// block's vectors that every value would otherwise be read from and written to. The same
/// comparisons in the same order as the general loop, so the same numbers. The squared norms
/// are summed only where they are stored (several components of a floating-point type).
template <int C, class T>
void ScanBlockOf(const T* values, vtkIdType first, vtkIdType last, BlockRanges<T>& r)
{
  T lo[C], hi[C];
  for (int c = 0; c < C; ++c)
  {
    lo[c] = r.Values[2 * c];
    hi[c] = r.Values[2 * c + 1];
  }
  constexpr bool norms = C > 1 && std::is_floating_point<T>::value;
  double norm0 = r.Norm2[0], norm1 = r.Norm2[1];
  bool finite = r.Finite;
  for (vtkIdType t = first; t < last; ++t)
  {
    const T* tuple = values + t * C;
    double squaredSum = 0.0;
    for (int c = 0; c < C; ++c)
    {
      const T value = tuple[c];
      if constexpr (std::is_floating_point<T>::value)
      {
        finite = finite & static_cast<bool>(std::isfinite(value));
      }
      lo[c] = std::min(lo[c], value);
      hi[c] = std::max(hi[c], value);
      if constexpr (norms)
      {
        const double d = static_cast<double>(value);
        squaredSum += d * d;
      }
    }
    if constexpr (norms)
    {
      norm0 = std::min(norm0, squaredSum);
      norm1 = std::max(norm1, squaredSum);
    }
  }
  for (int c = 0; c < C; ++c)
  {
    r.Values[2 * c] = lo[c];
    r.Values[2 * c + 1] = hi[c];
  }
  r.Norm2[0] = norm0;
  r.Norm2[1] = norm1;
  r.Finite = finite;
}

template <class T>
void ScanBlock(const T* values, int components, vtkIdType first, vtkIdType last, BlockRanges<T>& r)
{
  switch (components)
  {
    case 1:
      ScanBlockOf<1>(values, first, last, r);
      return;
    case 2:
      ScanBlockOf<2>(values, first, last, r);
      return;
    case 3:
      ScanBlockOf<3>(values, first, last, r);
      return;
    default:
      break;
  }
  for (vtkIdType t = first; t < last; ++t)
  {
    const T* tuple = values + t * components;
    double squaredSum = 0.0;
    for (int c = 0; c < components; ++c)
    {
      const T value = tuple[c];
      if constexpr (std::is_floating_point<T>::value)
      {
        if (!std::isfinite(value))
        {
          r.Finite = false;
        }
      }
      r.Values[2 * c] = std::min(r.Values[2 * c], value);
      r.Values[2 * c + 1] = std::max(r.Values[2 * c + 1], value);
      const double d = static_cast<double>(value);
      squaredSum += d * d;
    }
    r.Norm2[0] = std::min(r.Norm2[0], squaredSum);
    r.Norm2[1] = std::max(r.Norm2[1], squaredSum);
  }
}

/// Stores `ranges` under `key` of the array's information, one information object per
/// component, as vtkDataArray::ComputeRange does.
void SetComponentRanges(vtkInformation* info,
  vtkInformationInformationVectorKey* key,
  const std::vector<double>& ranges)
{
  vtkNew<vtkInformationVector> perComponent;
  const int components = static_cast<int>(ranges.size() / 2);
  perComponent->SetNumberOfInformationObjects(components);
  for (int c = 0; c < components; ++c)
  {
    perComponent->GetInformationObject(c)->Set(
      vtkDataArray::COMPONENT_RANGE(), ranges.data() + 2 * c, 2);
  }
  info->Set(key, perComponent);
}

template <class T>
void CacheTypedRanges(vtkDataArray* array, const T* values, int threads)
{
  const vtkIdType n = array->GetNumberOfTuples();
  const int components = array->GetNumberOfComponents();
  // Fixed blocks merged in order: the same numbers on any number of threads.
  constexpr vtkIdType BlockTuples = 1 << 15;
  const int blocks = static_cast<int>((n + BlockTuples - 1) / BlockTuples);
  std::vector<BlockRanges<T>> found(blocks, BlockRanges<T>(components));
  ParallelRange(
    threads,
    blocks > 1,
    blocks,
    [&](int b)
    {
      ScanBlock(values,
        components,
        b * BlockTuples,
        std::min<vtkIdType>(n, (b + 1) * BlockTuples),
        found[b]);
    },
    1);
  for (int b = 1; b < blocks; ++b)
  {
    found[0].Merge(found[b]);
  }
  const BlockRanges<T>& all = found[0];
  if (!all.Finite)
  {
    return; // VTK's range and finite range differ there: left to VTK
  }
  // Every value finite: the range and the finite range are the same numbers.
  const std::vector<double> ranges(all.Values.begin(), all.Values.end());
  vtkInformation* info = array->GetInformation();
  SetComponentRanges(info, vtkAbstractArray::PER_COMPONENT(), ranges);
  SetComponentRanges(info, vtkAbstractArray::PER_FINITE_COMPONENT(), ranges);
  // The L2 norm's range (component -1) of several components; one component's is its range.
  // Integer arrays are left to VTK there (how it sums their squares depends on its version).
  if (components > 1 && std::is_floating_point<T>::value)
  {
    const double norm[2] = { std::sqrt(all.Norm2[0]), std::sqrt(all.Norm2[1]) };
    info->Set(vtkDataArray::L2_NORM_RANGE(), norm, 2);
    info->Set(vtkDataArray::L2_NORM_FINITE_RANGE(), norm, 2);
  }
}

bool HoldsRanges(vtkDataArray* array)
{
  if (!array->HasInformation())
  {
    return false;
  }
  vtkInformation* info = array->GetInformation();
  return info->Has(vtkAbstractArray::PER_COMPONENT()) &&
    info->Has(vtkAbstractArray::PER_FINITE_COMPONENT());
}

void CacheAttributeRanges(vtkFieldData* data, int threads)
{
  for (int a = 0; a < data->GetNumberOfArrays(); ++a)
  {
    if (vtkDataArray* array = data->GetArray(a))
    {
      CacheArrayRanges(array, threads);
    }
  }
}

} // namespace

//------------------------------------------------------------------------------
void CacheArrayRanges(vtkDataArray* array, int threads)
{
  // A small array's ranges cost VTK next to nothing when asked, while storing them costs two
  // information vectors with an information object per component, created here and garbage
  // collected when the array goes: on a scene of a few thousand triangles that was half of an
  // edit through the stage filters, for ranges a plain VTK pipeline may never ask for.
  constexpr vtkIdType SmallArrayValues = 4096;
  if (!array || array->GetNumberOfValues() < SmallArrayValues ||
    !array->HasStandardMemoryLayout() || HoldsRanges(array))
  {
    return;
  }
  switch (array->GetDataType())
  {
    vtkTemplateAliasMacro(
      CacheTypedRanges(array, static_cast<const VTK_TT*>(array->GetVoidPointer(0)), threads));
    default:
      break;
  }
}

//------------------------------------------------------------------------------
void CacheDataRanges(vtkPolyData* data, int threads)
{
  if (vtkPoints* points = data->GetPoints())
  {
    CacheArrayRanges(points->GetData(), threads);
  }
  CacheAttributeRanges(data->GetPointData(), threads);
  CacheAttributeRanges(data->GetCellData(), threads);
  CacheAttributeRanges(data->GetFieldData(), threads);
}

} // namespace boolsurf
