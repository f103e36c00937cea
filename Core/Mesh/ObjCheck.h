// Checks the element indices of a Wavefront OBJ file before vtkOBJReader reads it: that
// reader follows every index of `f`, `l` and `p` lines (vertex, texture coordinate, normal)
// without checking it, and crashes on one that names nothing, e.g. `f 4/5 3` in a file without
// texture coordinates. The scene reader runs this check first so that such a mesh is an error.
#ifndef boolsurf_ObjCheck_h
#define boolsurf_ObjCheck_h

#include <string>

namespace boolsurf
{
/// False, with a message naming the line and the index, when an `f`, `l` or `p` line uses an
/// index that is not an integer or names no `v`, `vt` or `vn` line read before it (indices
/// count from 1; negative ones count back from the last line read, as OBJ allows).
bool CheckObjIndices(const std::string& path, std::string& error);
} // namespace boolsurf

#endif
