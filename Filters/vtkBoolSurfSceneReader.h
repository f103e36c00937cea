/**
 * @class   vtkBoolSurfSceneReader
 * @brief   read a scene (.json) of the original BoolSurf code: its mesh and its curves
 *
 * vtkBoolSurfSceneReader reads the test scenes of the BoolSurf paper's code (the format of
 * `load_test` in its boolsurf_io.cpp, documented in ../shared/data/boolsurf-scenes/README.md):
 *
 * - `model`: the mesh path, relative to the BoolSurf repository root (`./` and `\` allowed);
 * - `points`: control points `{"face": f, "uv": [u, v]}` at (1-u-v) p0 + u p1 + v p2 of
 *   triangle f (the convention of our `Barycentric`);
 * - `polygons`: curves as lists of point indices (polygon 0 is normally empty: reserved);
 * - `are_closed` (default all true), `shapes` (lists of polygon indices; default: polygon i is
 *   shape i), `operations` (`{a, b, type}`, type 0 union, 1 difference, 2 intersection,
 *   3 symmetric difference);
 * - `screenspace: true` scenes hold 2D polylines `[[x, y], ...]` and no mesh.
 *
 * Output port 0: the mesh, as triangles (quads are split the BoolSurf/Yocto way, (a,b,c,d) to
 * (a,b,d),(c,d,b), so that `face` indexes them). For a screen-space scene: a flat grid on
 * [0,1]^2 (z = 0, normals +z) with ScreenSpaceResolution quads per side.
 *
 * Output port 1: the curves as control polygons on that surface, ready for
 * vtkBoolSurfTraceCurves, written as every BoolSurf filter writes control curves (Core's
 * SceneControlCurves through the module's one control-curve writer): one polyline per
 * non-empty polygon with points of its own, at their 3D positions, with point data
 * `TriangleId` and `Barycentric` (exactly face and uv). Points are not shared between
 * polygons: a scene point that two polygons name is a point of each (a closed polyline
 * repeats its own first point id at its end, which the tracer reads as closed; polylines
 * rather than polygon cells so that ParaView draws them as curves). Cell data `ShapeId`,
 * `CurveType` (0, geodesic polygon), `Closed` and `CurveId` (the scene's polygon index: empty
 * polygons are skipped but do not renumber the others). Field data: `OperationA`,
 * `OperationB`, `OperationType` (only when the scene has operations), `SceneFileName`,
 * `MeshFileName` (the file actually read).
 *
 * ShapeId keeps the scene's numbering so that operations (which name shapes) apply directly:
 * with `shapes`, the index of the shape listing the polygon; without, the polygon index
 * (BoolSurf's default of one shape per polygon). A non-empty polygon in no shape gets a new
 * shape of its own, numbered after the scene's shapes in polygon order. A polygon listed by
 * two shapes is an error.
 *
 * The mesh is found, in order: MeshFileName when set (relative to the scene's folder, then
 * as given); else the scene's `model` relative to each ancestor folder of the scene file, and
 * its base name (and the renamed copy of the shared collection, e.g. eight200k-remeshed.ply
 * is eight_200k.ply, bunny.ply is bunny_boolsurf.ply) in the scene's folder, in the folders
 * of MeshSearchPath (separated by ';' or ':') and in a `meshes` folder beside any ancestor.
 * PLY (vtkPLYReader) and OBJ (vtkOBJReader) meshes are read.
 *
 * The format, its checks, the placement of the points and the curves are Core's (Core/Scene:
 * SceneJson, ScenePlacement, SceneMeshLookup, SceneCurves); this class reads the mesh and
 * makes the outputs.
 *
 * Errors (vtkErrorMacro naming the file, the key, the polygon and point index; empty outputs):
 * unreadable file, bad JSON, missing `polygons` or `points`, a value of the wrong type, a
 * face index out of range, a uv outside the triangle (tolerance 1e-6; values within it are
 * clamped), a polygon naming a point that does not exist, a polygon of one point, a shape
 * naming a polygon that does not exist, no curve at all, a missing or unreadable mesh.
 *
 * @sa vtkBoolSurfTraceCurves vtkBoolSurf
 */
#ifndef vtkBoolSurfSceneReader_h
#define vtkBoolSurfSceneReader_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // for std::string

class BOOLSURFFILTERS_EXPORT vtkBoolSurfSceneReader : public vtkPolyDataAlgorithm
{
public:
  static vtkBoolSurfSceneReader* New();
  vtkTypeMacro(vtkBoolSurfSceneReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The scene file (.json).
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  ///@{
  /// When not empty, the mesh to read instead of the scene's `model` (relative paths are
  /// looked up beside the scene file first).
  vtkSetStdStringFromCharMacro(MeshFileName);
  vtkGetCharFromStdStringMacro(MeshFileName);
  ///@}

  ///@{
  /// Folders (separated by ';' or ':') searched for the scene's mesh.
  vtkSetStdStringFromCharMacro(MeshSearchPath);
  vtkGetCharFromStdStringMacro(MeshSearchPath);
  ///@}

  ///@{
  /// Quads per side of the flat grid made for screen-space scenes (default 64).
  vtkSetClampMacro(ScreenSpaceResolution, int, 1, 4096);
  vtkGetMacro(ScreenSpaceResolution, int);
  ///@}

  /// Whether the file looks like a BoolSurf scene: a JSON object with a `polygons` key.
  static int CanReadFile(const char* fileName);

  /// The mesh file read by the last update (empty before or on error).
  const char* GetResolvedMeshFileName() { return this->ResolvedMeshFileName.c_str(); }

  /// The curves output (port 1).
  vtkPolyData* GetCurvesOutput() { return this->GetOutput(1); }

protected:
  vtkBoolSurfSceneReader();
  ~vtkBoolSurfSceneReader() override;

  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  std::string FileName;
  std::string MeshFileName;
  std::string MeshSearchPath;
  int ScreenSpaceResolution = 64;
  std::string ResolvedMeshFileName;

private:
  vtkBoolSurfSceneReader(const vtkBoolSurfSceneReader&) = delete;
  void operator=(const vtkBoolSurfSceneReader&) = delete;
};

#endif
