#include "Arrangement/RefinedSurfaceArrays.h"

#include "Arrangement/EditBuffers.h"
#include "Mesh/ParallelRange.h"

#include <tbb/task_arena.h>

namespace boolsurf
{

//------------------------------------------------------------------------------
void RefinedSurfaceArrays::Update(const TriangleMesh& mesh, const Arrangement& arr, int threads)
{
  const int nv = arr.NumberOfMeshVertices;
  const int nt = arr.NumberOfMeshTriangles;
  const int np = arr.GetNumberOfPoints();
  const int count = arr.GetNumberOfTriangles();
  const std::uint64_t serial = mesh.GetSerial();
  const bool kept = serial != 0 && this->MeshSerial == serial &&
    static_cast<int>(this->Positions.size()) >= nv &&
    static_cast<int>(this->Triangles.size()) >= nt;
  this->MeshSerial = 0; // until consistent again
  ResizeForEdits(this->Positions, np);
  ResizeForEdits(this->Triangles, count);
  ResizeForEdits(this->SourceTriangle, count);
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  if (!kept)
  {
    ParallelRange(arena, nv, [&](int v) { this->Positions[v] = mesh.GetPosition(v); });
    ParallelRange(arena,
      nt,
      [&](int t)
      {
        this->Triangles[t] = arr.GetTriangle(mesh, t);
        this->SourceTriangle[t] = arr.GetSourceTriangle(mesh, t);
      });
  }
  else
  {
    // The entries the last arrangement refined become the mesh's again, then this one's
    // refined entries are written (the same triangle may be in both lists).
    for (int t : this->WrittenRefinedSources)
    {
      this->Triangles[t] = mesh.GetTriangle(t);
      this->SourceTriangle[t] = t;
    }
    for (int t : arr.RefinedSources)
    {
      this->Triangles[t] = arr.GetTriangle(mesh, t);
    }
  }
  ParallelRange(
    arena, np - nv, [&](int i) { this->Positions[nv + i] = arr.CurvePositions[i]; }, 1 << 14);
  ParallelRange(
    arena,
    count - nt,
    [&](int i)
    {
      this->Triangles[nt + i] = arr.AppendedPieces[i];
      this->SourceTriangle[nt + i] = arr.AppendedSources[i];
    },
    1 << 14);
  this->WrittenRefinedSources = arr.RefinedSources;
  this->MeshSerial = serial;
}

//------------------------------------------------------------------------------
RefinedSurfaceArrays RefinedSurfaceArrays::Of(const TriangleMesh& mesh, const Arrangement& arr)
{
  RefinedSurfaceArrays arrays;
  arrays.Update(mesh, arr);
  return arrays;
}

} // namespace boolsurf
