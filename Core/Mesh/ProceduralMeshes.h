// Meshes generated in code for tests, examples and benchmarks: they need no data files and
// have known geometry (flat: geodesics are straight; sphere: areas are angle excesses;
// torus: genus 1; cylinder: developable with two boundary loops).
#ifndef boolsurf_ProceduralMeshes_h
#define boolsurf_ProceduralMeshes_h

#include "Mesh/Vec3.h"

#include <array>
#include <cstdint>
#include <vector>

namespace boolsurf
{

struct MeshData
{
  std::vector<Vec3> Positions;
  std::vector<std::array<int, 3>> Triangles;
};

/// Square [0,size]^2 in the plane z = 0, n x n cells, normals +z: vertex (i, j) has the id
/// j (n + 1) + i and the position (i size / n, j size / n, 0) (exactly i / n for size 1); cell
/// (i, j) is split into (p00, p10, p11), (p00, p11, p01). With jitter > 0 the interior
/// vertices move by up to jitter * cell size and each cell's diagonal is chosen at random
/// (seeded) among those that keep every triangle counter-clockwise, giving an irregular
/// triangulation of the same square that never folds over itself.
MeshData MakeFlatSquare(int n, double size = 1.0, double jitter = 0.0, std::uint32_t seed = 1);

/// Icosahedron subdivided `levels` times, vertices projected to the sphere of `radius`;
/// 20 * 4^levels triangles, normals outward.
MeshData MakeIcosphere(int levels, double radius = 1.0);

/// Torus around the z axis with major radius R and minor radius r, nu x nv quads split in
/// two; normals outward. Genus 1.
MeshData MakeTorus(double R, double r, int nu, int nv);

/// Lateral surface of a cylinder around the z axis (radius, height in [0,h]), open at both
/// ends; normals outward. Developable; two boundary loops.
MeshData MakeOpenCylinder(double radius, double height, int around, int along);

/// Lateral surface of an axis-aligned box [0,a]x[0,b]x[0,h] (four rectangles, open top and
/// bottom), each face an n x n grid; normals outward. Developable; two boundary loops.
MeshData MakeBoxLateral(double a, double b, double h, int n);

} // namespace boolsurf

#endif
