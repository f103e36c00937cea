#include "vtkBoolSurfControlCurveWriter.h"

#include "vtkBoolSurfArrayNames.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

namespace boolsurf
{

//------------------------------------------------------------------------------
ControlCurveWriter::ControlCurveWriter(const TriangleMesh& mesh,
  const char* markName,
  bool curveIds,
  bool shapeNames)
  : ControlCurveWriter([&mesh](const SurfacePoint& p)
      { return mesh.Evaluate(p.Triangle, p.U, p.V); },
      markName,
      curveIds,
      shapeNames)
{
}

//------------------------------------------------------------------------------
ControlCurveWriter::ControlCurveWriter(PositionOf position,
  const char* markName,
  bool curveIds,
  bool shapeNames)
  : Position(std::move(position))
  , WriteMark(markName != nullptr)
  , WriteCurveIds(curveIds)
  , WriteShapeNames(shapeNames)
{
  this->Mark->SetName(markName);
  this->Points->SetDataTypeToDouble();
  this->TriangleId->SetName(names::TriangleId);
  this->Barycentric->SetName(names::Barycentric);
  this->Barycentric->SetNumberOfComponents(2);
  this->Shape->SetName(names::ShapeId);
  this->Type->SetName(names::CurveType);
  this->Closed->SetName(names::Closed);
  this->CurveId->SetName(names::CurveId);
  this->ShapeName->SetName(names::ShapeName);
}

//------------------------------------------------------------------------------
ControlCurveWriter::~ControlCurveWriter() = default;

//------------------------------------------------------------------------------
void ControlCurveWriter::Add(const ControlCurve& curve, int mark, const std::string& shapeName)
{
  this->AddCurve(curve, nullptr, mark, shapeName);
}

//------------------------------------------------------------------------------
void ControlCurveWriter::Add(const ControlCurve& curve, const std::vector<Vec3>& positions)
{
  this->AddCurve(curve, &positions, 0, std::string());
}

//------------------------------------------------------------------------------
void ControlCurveWriter::AddCurve(const ControlCurve& curve,
  const std::vector<Vec3>* positions,
  int mark,
  const std::string& shapeName)
{
  const vtkIdType first = this->Points->GetNumberOfPoints();
  for (std::size_t i = 0; i < curve.Points.size(); ++i)
  {
    const SurfacePoint& p = curve.Points[i];
    const Vec3 x = positions ? (*positions)[i] : this->Position(p);
    this->Points->InsertNextPoint(x.x, x.y, x.z);
    this->TriangleId->InsertNextValue(p.Triangle);
    this->Barycentric->InsertNextTuple2(p.U, p.V);
  }
  const vtkIdType n = static_cast<vtkIdType>(curve.Points.size());
  // Every closed curve repeats its first point, even a one-point one (a first click in the
  // curve editor), so its cell says it is closed.
  const bool repeat = curve.Closed && n > 0;
  this->Lines->InsertNextCell(n + (repeat ? 1 : 0));
  for (vtkIdType i = 0; i < n; ++i)
  {
    this->Lines->InsertCellPoint(first + i);
  }
  if (repeat)
  {
    this->Lines->InsertCellPoint(first);
  }
  this->Shape->InsertNextValue(curve.ShapeId);
  this->Type->InsertNextValue(static_cast<int>(curve.Type));
  this->Closed->InsertNextValue(curve.Closed ? 1 : 0);
  if (this->WriteMark)
  {
    this->Mark->InsertNextValue(mark);
  }
  if (this->WriteCurveIds)
  {
    this->CurveId->InsertNextValue(curve.CurveId);
  }
  if (this->WriteShapeNames)
  {
    this->ShapeName->InsertNextValue(shapeName);
  }
}

//------------------------------------------------------------------------------
void ControlCurveWriter::Write(vtkPolyData* output)
{
  output->SetPoints(this->Points);
  output->SetLines(this->Lines);
  output->GetPointData()->AddArray(this->TriangleId);
  output->GetPointData()->AddArray(this->Barycentric);
  vtkCellData* cd = output->GetCellData();
  cd->AddArray(this->Shape);
  cd->AddArray(this->Type);
  cd->AddArray(this->Closed);
  if (this->WriteMark)
  {
    cd->AddArray(this->Mark);
  }
  if (this->WriteCurveIds)
  {
    cd->AddArray(this->CurveId);
  }
  if (this->WriteShapeNames)
  {
    cd->AddArray(this->ShapeName);
  }
}

} // namespace boolsurf
