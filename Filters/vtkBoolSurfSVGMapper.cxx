#include "vtkBoolSurfSVGMapper.h"

#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfControlCurveWriter.h"

#include "Mesh/ClosestTriangleGrid.h"
#include "Svg/SvgSurfaceMap.h"
#include "vtkBoolSurfSurfaceCache.h"

#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

vtkStandardNewMacro(vtkBoolSurfSVGMapper);

//------------------------------------------------------------------------------
vtkBoolSurfSVGMapper::vtkBoolSurfSVGMapper() = default;

//------------------------------------------------------------------------------
vtkBoolSurfSVGMapper::~vtkBoolSurfSVGMapper() = default;

//------------------------------------------------------------------------------
bool vtkBoolSurfSVGMapper::Execute(const std::vector<vtkPolyData*>& inputs,
  const std::vector<vtkPolyData*>& outputs,
  std::string& error)
{
  vtkPolyData* input = inputs[0];
  vtkPolyData* output = outputs[0];
  if (this->FileName.empty())
  {
    error = "No FileName: set the SVG file to map.";
    return false;
  }
  std::vector<std::string> warnings;
  const boolsurf::vtkSurfaceInput* surface =
    this->GetSurfaceCache().GetUsable(input, warnings, error);
  if (!surface)
  {
    return false;
  }
  const boolsurf::TriangleMesh& mesh = *surface->Mesh;
  boolsurf::SvgDrawing drawing;
  if (!boolsurf::LoadSvg(this->FileName, drawing, error))
  {
    return false;
  }
  this->UpdateProgress(0.2);

  boolsurf::SvgMapOptions options;
  if (this->CenterTriangleId >= 0)
  {
    if (this->CenterTriangleId >= mesh.GetNumberOfTriangles())
    {
      std::ostringstream message;
      message << "CenterTriangleId " << this->CenterTriangleId << " is not a triangle of the "
              << mesh.GetNumberOfTriangles() << "-triangle surface";
      error = message.str();
      return false;
    }
    double u = this->CenterBarycentric[0], v = this->CenterBarycentric[1];
    if (!boolsurf::IsInsideTriangle(u, v))
    {
      std::ostringstream message;
      message << "CenterBarycentric (" << u << ", " << v << ") is outside the triangle";
      error = message.str();
      return false;
    }
    boolsurf::ClampBarycentric(u, v);
    options.Center = { static_cast<int>(this->CenterTriangleId), u, v };
  }
  else
  {
    const boolsurf::ClosestTriangleGrid::Hit hit =
      this->GetSurfaceCache().GetClosestTriangles().FindClosest(
        { this->Center[0], this->Center[1], this->Center[2] });
    if (hit.Triangle < 0)
    {
      error = "no surface point near Center";
      return false;
    }
    const double dist2 = hit.Distance2;
    options.Center = boolsurf::PointInTriangle(mesh, hit.Triangle, hit.Point);
    // A center off the surface is projected, but one far from it is more likely a mistake (a
    // point in other units, another dataset's coordinates) than a choice: say so. The middle
    // of the bounding box, ParaView's default, is a deliberate "nearest to the middle".
    const double diagonal = input->GetLength();
    const double distance = std::sqrt(dist2);
    double b[6];
    input->GetBounds(b);
    const double middle[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
    const bool isMiddle =
      std::sqrt(vtkMath::Distance2BetweenPoints(middle, this->Center)) <= 1e-9 * diagonal;
    if (distance > 0.01 * diagonal && !isMiddle)
    {
      std::ostringstream message;
      message << "Center (" << this->Center[0] << ", " << this->Center[1] << ", " << this->Center[2]
              << ") is " << distance << " from the surface (" << std::fixed << std::setprecision(1)
              << 100 * distance / diagonal << std::defaultfloat << std::setprecision(6)
              << "% of its bounding-box diagonal): the drawing is centered at the nearest "
                 "surface point ("
              << hit.Point.x << ", " << hit.Point.y << ", " << hit.Point.z << "), triangle "
              << hit.Triangle;
      warnings.push_back(message.str());
    }
  }
  // Size: the drawing's farthest bounding-box corner at Radius from the center.
  const double halfW = 0.5 * (drawing.Max[0] - drawing.Min[0]);
  const double halfH = 0.5 * (drawing.Max[1] - drawing.Min[1]);
  const double extent = std::sqrt(halfW * halfW + halfH * halfH);
  if (this->Scale > 0)
  {
    options.Scale = this->Scale;
  }
  else
  {
    double radius = this->Radius;
    if (radius <= 0)
    {
      double b[6];
      input->GetBounds(b);
      radius = 0.1 *
        std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
          (b[5] - b[4]) * (b[5] - b[4]));
    }
    options.Scale = extent > 0 ? radius / extent : 1.0;
  }
  options.Rotation = this->Rotation;

  std::vector<boolsurf::MappedSvgCurve> curves;
  if (!boolsurf::MapSvgOntoSurface(mesh, drawing, options, curves, drawing.Warnings, error))
  {
    return false;
  }
  this->UpdateProgress(0.9);

  boolsurf::ControlCurveWriter writer(mesh);
  std::vector<int> evenOdd;
  bool allEvenOdd = true;
  for (boolsurf::MappedSvgCurve& c : curves)
  {
    const int element = c.ShapeId;
    c.ShapeId = this->ShapeIdOffset + element;
    writer.Add(c);
    if (static_cast<int>(evenOdd.size()) <= element)
    {
      evenOdd.resize(element + 1, 0);
    }
    evenOdd[element] = c.EvenOdd ? 1 : 0;
    allEvenOdd = allEvenOdd && c.EvenOdd;
  }
  writer.Write(output);
  vtkNew<vtkStringArray> rule;
  rule->SetName(boolsurf::names::SuggestedFillRule);
  rule->InsertNextValue(allEvenOdd ? "EvenOdd" : "NonZero");
  output->GetFieldData()->AddArray(rule);
  vtkNew<vtkIntArray> perShape;
  perShape->SetName(boolsurf::names::ShapeEvenOdd);
  for (int e : evenOdd)
  {
    perShape->InsertNextValue(e);
  }
  output->GetFieldData()->AddArray(perShape);
  warnings.insert(warnings.end(), drawing.Warnings.begin(), drawing.Warnings.end());
  if (!warnings.empty())
  {
    vtkNew<vtkStringArray> notes;
    notes->SetName(boolsurf::names::SvgWarnings);
    for (const std::string& w : warnings)
    {
      notes->InsertNextValue(w);
      vtkWarningMacro(<< this->FileName << ": " << w);
    }
    output->GetFieldData()->AddArray(notes);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkBoolSurfSVGMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "Center: " << this->Center[0] << " " << this->Center[1] << " " << this->Center[2]
     << "\n";
  os << indent << "CenterTriangleId: " << this->CenterTriangleId << "\n";
  os << indent << "Scale: " << this->Scale << "\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "Rotation: " << this->Rotation << "\n";
  os << indent << "ShapeIdOffset: " << this->ShapeIdOffset << "\n";
}
