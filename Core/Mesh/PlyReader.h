// Minimal PLY reader for triangle meshes, so Core tests and benchmarks can load meshes
// without VTK. Reads ascii and binary (little/big endian) files with `element vertex`
// (x, y, z of any numeric type, other properties skipped) and `element face` with a
// `list <count type> <index type> vertex_indices` (polygons fanned into triangles).
// Every value is checked (format and types, element counts against the file size, list
// lengths, vertex indices of faces) and so is the header's shape (a vertex element with x, y,
// z, a face element with a vertex list, properties under an element, each named), so a
// truncated, garbage or malformed file is an error naming the problem: the scene reader
// validates PLY files with it before vtkPLYReader (which crashes on such files) reads them
// with their colors and normals.
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
