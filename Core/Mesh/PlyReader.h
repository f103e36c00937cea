// Minimal PLY reader for triangle meshes, so Core tests and benchmarks can load meshes
// without VTK. Reads ascii and binary (little/big endian) files with `element vertex`
// (x, y, z of any numeric type, other properties skipped) and `element face` with a
// `list <count type> <index type> vertex_indices` (polygons fanned into triangles).
// VTK pipelines use vtkPLYReader instead.
#ifndef boolsurf_PlyReader_h
#define boolsurf_PlyReader_h

#include "Mesh/ProceduralMeshes.h"

#include <string>

namespace boolsurf
{

/// Returns false and a message naming the file and the problem on failure.
bool ReadPly(const std::string& path, MeshData& out, std::string& error);

} // namespace boolsurf

#endif
