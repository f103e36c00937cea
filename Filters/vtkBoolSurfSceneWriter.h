/**
 * @class   vtkBoolSurfSceneWriter
 * @brief   write control curves as a scene (.json) of the BoolSurf format, for saving and reopening
 *
 * vtkBoolSurfSceneWriter writes the curves of a BoolSurf pipeline in the scene format that
 * vtkBoolSurfSceneReader reads (the format of the original BoolSurf code's test scenes,
 * documented in Docs/VectorOutput.md), so that a user's curves, a shape set made by Resolve
 * Inconsistent Shapes or any other control-curves polydata can be saved and opened again:
 *
 * - `model`: the mesh the face indices refer to: MeshReference when set; else the input's
 *   field data `MeshFileName` (the mesh file vtkBoolSurfSceneReader read), relative to the
 *   new scene's folder when it lies below it, else as it is; else its field data `SceneModel`
 *   (the `model` string of the scene it was read from). With none of these the write fails:
 *   a scene without its mesh cannot be read again.
 * - `points`: one `{"face": TriangleId, "uv": Barycentric}` per input point, in point order
 *   (point id = index in `points`), doubles written with round-trip precision so a read of the
 *   file gives the same bits.
 * - `polygons`: one per line or polygon cell, the list of its point ids; a polyline whose last
 *   point repeats its first (the same id or the same surface point) is closed and its last
 *   point is dropped, as vtkBoolSurfTraceCurves reads it. A curve goes to polygon `CurveId`
 *   when the input has that cell data and its values are distinct (so a scene read and
 *   written keeps its numbering, empty polygons included); else curve k goes to polygon k + 1
 *   (polygon 0 is reserved and left empty, as BoolSurf does).
 * - `are_closed`, `shapes` (from cell data `ShapeId`; without it curve k is shape k, as in
 *   the tracer), `operations` (from field data `OperationA`, `OperationB`, `OperationType`).
 * - `curve_types`: written only when a curve is a cubic Bezier spline (`CurveType` 1): a key
 *   of ours, one int per polygon, that vtkBoolSurfSceneReader reads and the original code
 *   ignores.
 *
 * The JSON is written by Core (Core/Scene/SceneJson, EmitSceneJson) from the scene this class
 * fills from its input.
 *
 * Errors (vtkErrorMacro naming the point or curve id; no file is written): no FileName, no
 * mesh reference, no point data `TriangleId` and `Barycentric` (two components), a TriangleId
 * that is not a triangle index, barycentric coordinates outside the triangle (tolerance 1e-6)
 * or not finite, a curve of fewer than two points, a ShapeId or CurveId that is negative or not
 * an integer, a CurveType other than 0 and 1, a file that cannot be written.
 *
 * @sa vtkBoolSurfSceneReader vtkBoolSurfTraceCurves
 */
#ifndef vtkBoolSurfSceneWriter_h
#define vtkBoolSurfSceneWriter_h

#include "BoolSurfFiltersModule.h" // for export macro
#include "vtkWriter.h"

#include <string> // for std::string

class vtkPolyData;

class BOOLSURFFILTERS_EXPORT vtkBoolSurfSceneWriter : public vtkWriter
{
public:
  static vtkBoolSurfSceneWriter* New();
  vtkTypeMacro(vtkBoolSurfSceneWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The scene file to write (.json).
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  ///@{
  /// The mesh reference written as `model`, as given (relative paths are looked up by the
  /// reader beside the scene file first). Empty (default): taken from the input's field data.
  vtkSetStdStringFromCharMacro(MeshReference);
  vtkGetCharFromStdStringMacro(MeshReference);
  ///@}

  ///@{
  /// Spaces per JSON nesting level (default 1); -1 writes the whole scene on one line.
  vtkSetClampMacro(Indent, int, -1, 8);
  vtkGetMacro(Indent, int);
  ///@}

  ///@{
  /// When the input has cell data `BoundaryLoop` (BoolSurf's Boundary Control Curves), write
  /// each loop's pieces as one closed curve (default on), so the saved boundary bounds the
  /// region again when reopened: every loop is shape 0, oriented with the region on its left,
  /// so the region is shape 0 under the non-zero fill rule. Off writes the pieces as they are.
  vtkSetMacro(JoinBoundaryLoops, vtkTypeBool);
  vtkGetMacro(JoinBoundaryLoops, vtkTypeBool);
  vtkBooleanMacro(JoinBoundaryLoops, vtkTypeBool);
  ///@}

  /// The `model` written by the last successful write.
  const char* GetWrittenMeshReference() { return this->WrittenMeshReference.c_str(); }

protected:
  vtkBoolSurfSceneWriter();
  ~vtkBoolSurfSceneWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  std::string FileName;
  std::string MeshReference;
  int Indent = 1;
  vtkTypeBool JoinBoundaryLoops = 1;
  std::string WrittenMeshReference;

private:
  vtkBoolSurfSceneWriter(const vtkBoolSurfSceneWriter&) = delete;
  void operator=(const vtkBoolSurfSceneWriter&) = delete;
};

#endif
