// The stage filters (Trace Surface Curves -> Surface Arrangement -> Label Arrangement Cells ->
// Surface Boolean) give the one-step BoolSurf filter's answer: same refusals, same arrangement
// cells, same labels, same region. Curves are random, on flat, spherical, toroidal and open
// meshes in float32 and float64, with control points given as coordinates (projected), as exact
// surface points, and as exact points pushed 1e-16 .. 1e-12 off mesh edges and vertices on
// either side, in either triangle. Also the regressions that refused through the stage chain.
#include "FilterTestUtils.h"
#include "vtkBoolSurf.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfBSC.h"
#include "vtkBoolSurfBoolean.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfResolve.h"
#include "vtkBoolSurfTraceCurves.h"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkTriangleFilter.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <random>
#include <string>

namespace
{

struct Answer
{
  std::string Errors;
  double Area = 0;
  vtkIdType RegionTriangles = 0;
  std::vector<int> CellLabels; ///< cells x shapes, the labeling's table
  std::vector<int> ShapeConsistent;
};

std::vector<int> IntsOf(vtkFieldData* fd, const char* name)
{
  std::vector<int> values;
  vtkDataArray* a = fd ? fd->GetArray(name) : nullptr;
  for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
  {
    for (int k = 0; k < a->GetNumberOfComponents(); ++k)
    {
      values.push_back(static_cast<int>(a->GetComponent(i, k)));
    }
  }
  return values;
}

/// Errors and warnings of every filter of a pipeline.
struct Messages
{
  vtkNew<testutils::MessageCatcher> Catcher;
  void Watch(vtkAlgorithm* a)
  {
    a->AddObserver(vtkCommand::ErrorEvent, this->Catcher);
    a->AddObserver(vtkCommand::WarningEvent, this->Catcher);
  }
};

void ReadAnswer(vtkPolyData* region, vtkFieldData* labels, const std::string& errors, Answer& out)
{
  out.Errors = errors;
  out.Area = testutils::Area(region);
  out.RegionTriangles = region->GetNumberOfCells();
  out.CellLabels = IntsOf(labels, "CellLabels");
  out.ShapeConsistent = IntsOf(labels, "ShapeConsistent");
}

Answer OneStep(vtkPolyData* surface, vtkPolyData* curves, int operation)
{
  vtkNew<vtkBoolSurf> f;
  Messages m;
  m.Watch(f);
  f->SetInputData(0, surface);
  f->SetInputData(1, curves);
  f->SetOperation(operation);
  f->SetShapeA(operation == 0 ? -1 : 0);
  f->SetShapeB(operation == 0 ? -1 : 1);
  f->Update();
  Answer a;
  ReadAnswer(f->GetOutput(0), f->GetOutput(0)->GetFieldData(), m.Catcher->Errors, a);
  return a;
}

Answer StageChain(vtkPolyData* surface, vtkPolyData* curves, int operation)
{
  vtkNew<vtkBoolSurfTraceCurves> trace;
  vtkNew<vtkBoolSurfArrangement> arrange;
  vtkNew<vtkBoolSurfLabeling> label;
  vtkNew<vtkBoolSurfBoolean> boolean;
  Messages m;
  for (vtkAlgorithm* a : std::initializer_list<vtkAlgorithm*>{ trace, arrange, label, boolean })
  {
    m.Watch(a);
  }
  trace->SetInputData(0, surface);
  trace->SetInputData(1, curves);
  arrange->SetInputData(0, surface);
  arrange->SetInputConnection(1, trace->GetOutputPort());
  label->SetInputConnection(arrange->GetOutputPort(0));
  boolean->SetInputConnection(label->GetOutputPort(0));
  boolean->SetOperation(operation);
  boolean->SetShapeA(operation == 0 ? -1 : 0);
  boolean->SetShapeB(operation == 0 ? -1 : 1);
  boolean->Update();
  Answer a;
  ReadAnswer(boolean->GetOutput(0), label->GetOutput()->GetFieldData(), m.Catcher->Errors, a);
  return a;
}

/// Messages differ (the chain names the filter that failed); whether there is one does not.
bool Refused(const Answer& a)
{
  return !a.Errors.empty();
}

void ExpectSameAnswer(const Answer& oneStep, const Answer& chain, const std::string& what)
{
  ASSERT_EQ(Refused(oneStep), Refused(chain))
    << what << "\none-step: " << oneStep.Errors << "\nstage chain: " << chain.Errors;
  if (Refused(oneStep))
  {
    return;
  }
  EXPECT_EQ(oneStep.RegionTriangles, chain.RegionTriangles) << what;
  EXPECT_NEAR(oneStep.Area, chain.Area, 1e-12) << what;
  EXPECT_EQ(oneStep.CellLabels, chain.CellLabels) << what;
  EXPECT_EQ(oneStep.ShapeConsistent, chain.ShapeConsistent) << what;
}

/// Surface points of `curves` as point data TriangleId/Barycentric.
void AddSurfacePoints(vtkPolyData* curves,
  const std::vector<int>& triangles,
  const std::vector<std::array<double, 2>>& uv)
{
  vtkNew<vtkIdTypeArray> tri;
  tri->SetName("TriangleId");
  vtkNew<vtkDoubleArray> bary;
  bary->SetName("Barycentric");
  bary->SetNumberOfComponents(2);
  for (std::size_t i = 0; i < triangles.size(); ++i)
  {
    tri->InsertNextValue(triangles[i]);
    bary->InsertNextTuple2(uv[i][0], uv[i][1]);
  }
  curves->GetPointData()->AddArray(tri);
  curves->GetPointData()->AddArray(bary);
}

vtkSmartPointer<vtkPolyData> AsFloat32(vtkPolyData* surface)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(surface->GetNumberOfPoints());
  for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
  {
    points->SetPoint(p, surface->GetPoint(p));
  }
  out->SetPoints(points);
  out->SetPolys(surface->GetPolys());
  return out;
}

// How the control points of the random curves are given.
enum class PointForm
{
  Coordinates, ///< 3D points near the surface, projected by the filters
  Exact,       ///< TriangleId/Barycentric strictly inside triangles
  NearEdge,    ///< 1e-16 .. 1e-12 off a mesh edge, either side, either triangle
  NearVertex,  ///< 1e-16 .. 1e-12 off a mesh vertex, either triangle
};

const char* NameOf(PointForm f)
{
  switch (f)
  {
    case PointForm::Coordinates:
      return "coordinates";
    case PointForm::Exact:
      return "exact";
    case PointForm::NearEdge:
      return "near-edge";
    case PointForm::NearVertex:
      return "near-vertex";
  }
  return "?";
}

/// Random closed polygons (2 or 3 shapes, 3..6 points, each point in a small neighbourhood of a
/// random center so that curves overlap) as control curves.
vtkSmartPointer<vtkPolyData> RandomCurves(vtkPolyData* surface, PointForm form, std::mt19937& rng)
{
  const vtkIdType nt = surface->GetNumberOfCells();
  std::uniform_int_distribution<vtkIdType> anyTriangle(0, nt - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> exponent(12, 16);
  const auto tiny = [&] { return std::pow(10.0, -exponent(rng)) * (1 + unit(rng)); };
  const int shapes = 2 + static_cast<int>(unit(rng) * 2);
  // A neighbourhood: triangles whose first vertex is within a radius of a center vertex.
  double bounds[6];
  surface->GetBounds(bounds);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  std::vector<testutils::ControlPolygon> polygons;
  std::vector<int> triangles;
  std::vector<std::array<double, 2>> uvs;
  const vtkIdType center = anyTriangle(rng);
  double c[3];
  surface->GetPoint(surface->GetCell(center)->GetPointId(0), c);
  std::vector<vtkIdType> near;
  for (vtkIdType t = 0; t < nt; ++t)
  {
    double x[3];
    surface->GetPoint(surface->GetCell(t)->GetPointId(0), x);
    if (std::sqrt(vtkMath::Distance2BetweenPoints(x, c)) < 0.25 * diagonal)
    {
      near.push_back(t);
    }
  }
  std::uniform_int_distribution<std::size_t> pick(0, near.size() - 1);
  for (int s = 0; s < shapes; ++s)
  {
    testutils::ControlPolygon polygon;
    polygon.ShapeId = s;
    const int n = 3 + static_cast<int>(unit(rng) * 4);
    for (int i = 0; i < n; ++i)
    {
      const int t = static_cast<int>(near[pick(rng)]);
      double u = 0.05 + 0.9 * unit(rng), v = (1 - u) * (0.05 + 0.9 * unit(rng));
      if (form == PointForm::NearEdge)
      {
        // Off the edge opposite a random corner by +-tiny (outside is clamped back).
        const int corner = static_cast<int>(unit(rng) * 3);
        const double off = unit(rng) < 0.5 ? tiny() : -tiny();
        const double along = 0.1 + 0.8 * unit(rng);
        if (corner == 0)
        {
          u = along;
          v = 1 - along - off;
        }
        else if (corner == 1)
        {
          u = off;
          v = along;
        }
        else
        {
          u = along;
          v = off;
        }
      }
      else if (form == PointForm::NearVertex)
      {
        const int corner = static_cast<int>(unit(rng) * 3);
        const double a = tiny(), b = tiny();
        u = corner == 1 ? 1 - a - b : a;
        v = corner == 2 ? 1 - a - b : (corner == 1 ? b : a);
      }
      double p[3], x0[3], x1[3], x2[3];
      vtkCell* cell = surface->GetCell(t);
      surface->GetPoint(cell->GetPointId(0), x0);
      surface->GetPoint(cell->GetPointId(1), x1);
      surface->GetPoint(cell->GetPointId(2), x2);
      for (int k = 0; k < 3; ++k)
      {
        p[k] = (1 - u - v) * x0[k] + u * x1[k] + v * x2[k];
      }
      polygon.Points.push_back({ p[0], p[1], p[2] });
      triangles.push_back(t);
      uvs.push_back({ u, v });
    }
    polygons.push_back(polygon);
  }
  auto curves = testutils::ToCurves(polygons);
  if (form != PointForm::Coordinates)
  {
    AddSurfacePoints(curves, triangles, uvs);
  }
  return curves;
}

struct NamedSurface
{
  std::string Name;
  vtkSmartPointer<vtkPolyData> Surface;
};

std::vector<NamedSurface> Surfaces()
{
  std::vector<NamedSurface> all;
  const std::vector<std::pair<std::string, boolsurf::MeshData>> meshes{
    { "flat", boolsurf::MakeFlatSquare(10, 1.0, 0.3, 7) },
    { "sphere", boolsurf::MakeIcosphere(2) },
    { "torus", boolsurf::MakeTorus(1.0, 0.4, 24, 12) },
    { "open cylinder", boolsurf::MakeOpenCylinder(0.5, 1.0, 20, 8) },
  };
  for (const auto& m : meshes)
  {
    auto surface = testutils::ToPolyData(m.second);
    all.push_back({ m.first + " float64", surface });
    all.push_back({ m.first + " float32", AsFloat32(surface) });
  }
  // Genus 2 and a scan shipped in Data/ (float32 PLY files), and a scan of the shared
  // collection when it is there.
  std::vector<std::pair<std::string, std::string>> files;
  if (const char* source = std::getenv("BOOLSURF_SOURCE_DIR"))
  {
    files.push_back({ "eight (genus 2)", std::string(source) + "/Data/eight.ply" });
    files.push_back({ "bunny_npm (scan)", std::string(source) + "/Data/bunny_npm.ply" });
  }
  const char* shared = std::getenv("BOOLSURF_SHARED_DATA");
  if (shared && std::ifstream(std::string(shared) + "/meshes/kitten.ply"))
  {
    files.push_back({ "kitten (shared scan)", std::string(shared) + "/meshes/kitten.ply" });
  }
  else
  {
    std::cout << "shared mesh collection absent (BOOLSURF_SHARED_DATA): kitten case skipped\n";
  }
  for (const auto& f : files)
  {
    vtkNew<vtkPLYReader> reader;
    reader->SetFileName(f.second.c_str());
    reader->Update();
    if (reader->GetOutput()->GetNumberOfCells() > 0)
    {
      auto surface = vtkSmartPointer<vtkPolyData>::New();
      surface->ShallowCopy(reader->GetOutput());
      all.push_back({ f.first, surface });
    }
  }
  return all;
}

} // namespace

// The property: over random drawings, the chain answers exactly when the one-step filter does,
// with the same cells, labels and region.
TEST(StageChain, MatchesOneStepOnRandomCurves)
{
  std::mt19937 rng(26);
  const int trials = 6;
  for (const NamedSurface& s : Surfaces())
  {
    for (PointForm form :
      { PointForm::Coordinates, PointForm::Exact, PointForm::NearEdge, PointForm::NearVertex })
    {
      for (int trial = 0; trial < trials; ++trial)
      {
        auto curves = RandomCurves(s.Surface, form, rng);
        const int operation = trial % 4; // union, intersection, difference, xor
        const std::string what = s.Name + ", " + NameOf(form) + ", trial " + std::to_string(trial);
        ExpectSameAnswer(
          OneStep(s.Surface, curves, operation), StageChain(s.Surface, curves, operation), what);
      }
    }
  }
}

// A control point 1e-15 from a grid vertex: the tracer locates it on the vertex; the chain used
// to read it back inside the triangle and refuse ("share no triangle"). Up to 1e-12 off, the
// answer is the exact point's.
TEST(StageChain, ControlPointRoundingOffAVertex)
{
  auto surface = testutils::ToPolyData(boolsurf::MakeFlatSquare(4));
  const auto answerOf = [&](double eps)
  {
    testutils::ControlPolygon polygon;
    polygon.Points.assign(3, { 0, 0, 0 });
    auto curves = testutils::ToCurves({ polygon });
    AddSurfacePoints(
      curves, { 10, 0, 1 }, { { { eps, eps } }, { { 0.2, 0.2 } }, { { 0.2, 0.2 } } });
    const Answer one = OneStep(surface, curves, 0);
    const Answer chain = StageChain(surface, curves, 0);
    ExpectSameAnswer(one, chain, "eps " + std::to_string(eps));
    EXPECT_EQ(chain.Errors, "");
    return chain;
  };
  const Answer exact = answerOf(0.0);
  EXPECT_GT(exact.Area, 0.0);
  for (double eps : { 1e-16, 1e-15, 1e-14, 1e-13, 1e-12 })
  {
    // The exact point's answer: the same region, triangle for triangle.
    const Answer near = answerOf(eps);
    EXPECT_EQ(near.Area, exact.Area) << eps;
    EXPECT_EQ(near.RegionTriangles, exact.RegionTriangles) << eps;
    EXPECT_EQ(near.CellLabels, exact.CellLabels) << eps;
  }
}

// A projected control point lands 5e-16 off an edge of the neighbouring triangle of a
// double-precision torus.
TEST(StageChain, ProjectedPointOffAnEdgeOfATorus)
{
  auto surface = testutils::ToPolyData(boolsurf::MakeTorus(1.0, 0.35, 30, 14));
  std::mt19937 rng(5);
  std::uniform_int_distribution<vtkIdType> anyTriangle(0, surface->GetNumberOfCells() - 1);
  for (int trial = 0; trial < 20; ++trial)
  {
    // Three points on mesh edges (midpoints of a triangle's edges: the projection puts them a
    // rounding error inside one of the two triangles).
    testutils::ControlPolygon polygon;
    for (int k = 0; k < 3; ++k)
    {
      vtkCell* cell = surface->GetCell(anyTriangle(rng));
      double a[3], b[3];
      surface->GetPoint(cell->GetPointId(0), a);
      surface->GetPoint(cell->GetPointId(1), b);
      polygon.Points.push_back({ (a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2 });
    }
    auto curves = testutils::ToCurves({ polygon });
    ExpectSameAnswer(OneStep(surface, curves, 0),
      StageChain(surface, curves, 0),
      "torus trial " + std::to_string(trial));
  }
}

namespace
{

/// Every point coordinate and every array of two outputs, bit for bit.
void ExpectIdentical(vtkPolyData* a, vtkPolyData* b, const std::string& what)
{
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints()) << what;
  ASSERT_EQ(a->GetNumberOfCells(), b->GetNumberOfCells()) << what;
  for (vtkIdType p = 0; p < a->GetNumberOfPoints(); ++p)
  {
    double x[3], y[3];
    a->GetPoint(p, x);
    b->GetPoint(p, y);
    ASSERT_TRUE(x[0] == y[0] && x[1] == y[1] && x[2] == y[2]) << what << ": point " << p;
  }
  for (vtkDataSetAttributes* attributes : { static_cast<vtkDataSetAttributes*>(a->GetPointData()),
         static_cast<vtkDataSetAttributes*>(a->GetCellData()) })
  {
    vtkDataSetAttributes* other = attributes == a->GetPointData()
      ? static_cast<vtkDataSetAttributes*>(b->GetPointData())
      : static_cast<vtkDataSetAttributes*>(b->GetCellData());
    ASSERT_EQ(attributes->GetNumberOfArrays(), other->GetNumberOfArrays()) << what;
    for (int i = 0; i < attributes->GetNumberOfArrays(); ++i)
    {
      vtkDataArray* x = attributes->GetArray(i);
      vtkDataArray* y = x ? other->GetArray(x->GetName()) : nullptr;
      ASSERT_NE(y, nullptr) << what << ": array " << (x ? x->GetName() : "?");
      ASSERT_EQ(x->GetNumberOfValues(), y->GetNumberOfValues()) << what << ": " << x->GetName();
      for (vtkIdType v = 0; v < x->GetNumberOfValues(); ++v)
      {
        ASSERT_EQ(x->GetVariantValue(v), y->GetVariantValue(v)) << what << ": " << x->GetName();
      }
    }
  }
  vtkIdType na, nb;
  const vtkIdType *ia, *ib;
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
  {
    a->GetCellPoints(c, na, ia);
    b->GetCellPoints(c, nb, ib);
    ASSERT_EQ(na, nb) << what << ": cell " << c;
    for (vtkIdType k = 0; k < na; ++k)
    {
      ASSERT_EQ(ia[k], ib[k]) << what << ": cell " << c;
    }
  }
}

struct Chain
{
  vtkNew<vtkBoolSurfTraceCurves> Trace;
  vtkNew<vtkBoolSurfArrangement> Arrange;
  vtkNew<vtkBoolSurfLabeling> Label;
  vtkNew<vtkBoolSurfBoolean> Boolean;
  Messages Log;

  Chain(vtkPolyData* surface, vtkPolyData* curves)
  {
    for (vtkAlgorithm* a : std::initializer_list<vtkAlgorithm*>{
           this->Trace, this->Arrange, this->Label, this->Boolean })
    {
      this->Log.Watch(a);
    }
    this->Trace->SetInputData(0, surface);
    this->Trace->SetInputData(1, curves);
    this->Arrange->SetInputData(0, surface);
    this->Arrange->SetInputConnection(1, this->Trace->GetOutputPort());
    this->Label->SetInputConnection(this->Arrange->GetOutputPort(0));
    this->Boolean->SetInputConnection(this->Label->GetOutputPort(0));
    this->Boolean->SetShapeA(-1);
    this->Boolean->SetShapeB(-1);
  }
};

vtkSmartPointer<vtkPolyData> TwoSquares(double shift)
{
  return testutils::ToCurves(
    { testutils::ControlPolygon{
        { { 0.1, 0.1, 0 }, { 0.6, 0.1, 0 }, { 0.6, 0.6, 0 }, { 0.1, 0.6, 0 } }, 0 },
      testutils::ControlPolygon{ { { 0.3 + shift, 0.3, 0 },
                                   { 0.9 + shift, 0.3, 0 },
                                   { 0.9 + shift, 0.8, 0 },
                                   { 0.3 + shift, 0.8, 0 } },
        1 } });
}

} // namespace

// The chain's four outputs are the one-step filter's, bit for bit: points, cells, every array.
TEST(StageChain, OutputsAreTheOneStepOutputsBitForBit)
{
  std::mt19937 rng(4);
  for (const NamedSurface& s : Surfaces())
  {
    for (int trial = 0; trial < 3; ++trial)
    {
      auto curves =
        RandomCurves(s.Surface, trial == 0 ? PointForm::Coordinates : PointForm::NearEdge, rng);
      vtkNew<vtkBoolSurf> one;
      Messages m;
      m.Watch(one);
      one->SetInputData(0, s.Surface);
      one->SetInputData(1, curves);
      one->SetShapeA(-1);
      one->SetShapeB(-1);
      one->Update();
      Chain chain(s.Surface, curves);
      chain.Boolean->Update();
      const std::string what = s.Name + " trial " + std::to_string(trial);
      ASSERT_EQ(m.Catcher->Errors.empty(), chain.Log.Catcher->Errors.empty()) << what;
      for (int port = 0; port < 4; ++port)
      {
        ExpectIdentical(one->GetOutput(port),
          chain.Boolean->GetOutput(port),
          what + ", port " + std::to_string(port));
      }
    }
  }
}

// A shallow copy of a stage's output keeps its own answer when the chain updates again (the
// Core result it carries is never overwritten), and an input whose arrays were deep-copied (as
// from a file: no Core result) gives the same answer by reading the arrays.
TEST(StageChain, CopiesKeepTheirAnswer)
{
  auto surface = testutils::ToPolyData(boolsurf::MakeFlatSquare(12, 1.0, 0.3, 3));
  Chain chain(surface, TwoSquares(0.0));
  chain.Boolean->Update();
  ASSERT_EQ(chain.Log.Catcher->Errors, "");
  const double before = testutils::Area(chain.Boolean->GetOutput());
  vtkNew<vtkPolyData> held, deep;
  held->ShallowCopy(chain.Label->GetOutput());
  deep->DeepCopy(chain.Label->GetOutput());
  vtkNew<vtkPolyData> heldCurves, deepCurves;
  heldCurves->ShallowCopy(chain.Trace->GetOutput());
  deepCurves->DeepCopy(chain.Trace->GetOutput());
  // The refined surface reads the arrangement's memory in place (points, triangles, cells).
  // The patches share its points: held alone, they keep them too.
  vtkNew<vtkPolyData> heldRefined, deepRefined, heldPatches, deepPatches;
  heldRefined->ShallowCopy(chain.Arrange->GetOutput(0));
  deepRefined->DeepCopy(chain.Arrange->GetOutput(0));
  heldPatches->ShallowCopy(chain.Arrange->GetOutput(1));
  deepPatches->DeepCopy(chain.Arrange->GetOutput(1));

  // The chain moves on: more edits, so that every buffer it keeps is reused.
  for (double shift : { 0.05, 0.1, -0.05 })
  {
    chain.Trace->SetInputData(1, TwoSquares(shift));
    chain.Boolean->Update();
    ASSERT_EQ(chain.Log.Catcher->Errors, "");
  }

  // The shallow copy's arrays are as they were: no later update wrote into them.
  ExpectIdentical(held, deep, "shallow copy against deep copy after three edits");
  ExpectIdentical(heldRefined, deepRefined, "refined surface held across three edits");
  ExpectIdentical(heldPatches, deepPatches, "patches held across three edits");
  for (vtkPolyData* input : { held.GetPointer(), deep.GetPointer() })
  {
    vtkNew<vtkBoolSurfBoolean> boolean;
    boolean->SetInputData(input);
    boolean->SetShapeA(-1);
    boolean->SetShapeB(-1);
    EXPECT_EQ(testutils::ErrorsOf(boolean), "");
    EXPECT_NEAR(testutils::Area(boolean->GetOutput()), before, 1e-12);
  }
  for (vtkPolyData* curves : { heldCurves.GetPointer(), deepCurves.GetPointer() })
  {
    vtkNew<vtkBoolSurfArrangement> arrange;
    arrange->SetInputData(0, surface);
    arrange->SetInputData(1, curves);
    vtkNew<vtkBoolSurfBoolean> boolean;
    boolean->SetInputConnection(arrange->GetOutputPort(0));
    boolean->SetShapeA(-1);
    boolean->SetShapeB(-1);
    EXPECT_EQ(testutils::ErrorsOf(boolean), "");
    EXPECT_NEAR(testutils::Area(boolean->GetOutput()), before, 1e-12);
  }
}

// A refined surface without its Core result (read from a file, deep-copied) is arranged again
// from the field data Surface Arrangement writes for it: the stages below it give the handed-over
// outputs bit for bit, labeled or not. A copy that lacks those arrays (written before they
// existed) is refused with a message naming them.
TEST(StageChain, CopiesWithoutTheirResultGiveTheHandedOverOutputs)
{
  std::mt19937 rng(17);
  std::vector<NamedSurface> surfaces{
    { "square", testutils::ToPolyData(boolsurf::MakeFlatSquare(12, 1.0, 0.3, 3)) },
    { "sphere", testutils::ToPolyData(boolsurf::MakeIcosphere(2)) },
  };
  int compared = 0;
  for (const NamedSurface& s : surfaces)
  {
    for (int trial = 0; trial < 4; ++trial)
    {
      const std::string what = s.Name + ", trial " + std::to_string(trial);
      Chain chain(s.Surface,
        s.Name == "square" && trial == 0 ? TwoSquares(0.0)
                                         : RandomCurves(s.Surface, PointForm::Exact, rng));
      chain.Boolean->Update();
      if (chain.Log.Catcher->Errors != "")
      {
        continue; // a refused drawing: the chain against one step is the test above
      }
      vtkNew<vtkPolyData> refined, labeled;
      refined->DeepCopy(chain.Arrange->GetOutput(0));
      labeled->DeepCopy(chain.Label->GetOutput());
      vtkNew<vtkBoolSurfLabeling> label;
      label->SetInputData(refined);
      vtkNew<vtkBoolSurfBoolean> fromRefined, fromLabeled;
      fromRefined->SetInputConnection(label->GetOutputPort());
      fromLabeled->SetInputData(labeled);
      for (vtkBoolSurfBoolean* boolean : { fromRefined.GetPointer(), fromLabeled.GetPointer() })
      {
        boolean->SetShapeA(-1);
        boolean->SetShapeB(-1);
        ASSERT_EQ(testutils::ErrorsOf(boolean), "") << what;
        for (int port = 0; port < 4; ++port)
        {
          ExpectIdentical(chain.Boolean->GetOutput(port),
            boolean->GetOutput(port),
            what + ", port " + std::to_string(port));
        }
      }
      EXPECT_EQ(IntsOf(label->GetOutput()->GetFieldData(), "CellLabels"),
        IntsOf(chain.Label->GetOutput()->GetFieldData(), "CellLabels"))
        << what;
      ++compared;
    }
  }
  EXPECT_GE(compared, 4);

  auto surface = testutils::ToPolyData(boolsurf::MakeFlatSquare(12, 1.0, 0.3, 3));
  Chain chain(surface, TwoSquares(0.0));
  chain.Label->Update();
  vtkNew<vtkPolyData> older;
  older->DeepCopy(chain.Label->GetOutput());
  older->GetFieldData()->RemoveArray("ArrangedMeshSize");
  vtkNew<vtkBoolSurfBoolean> boolean;
  boolean->SetInputData(older);
  const std::string errors = testutils::ErrorsOf(boolean);
  EXPECT_NE(errors.find("'ArrangedMeshSize'"), std::string::npos) << errors;
  EXPECT_NE(errors.find("run Surface Arrangement again"), std::string::npos) << errors;
}

// A refined surface outlives the filters that made it: its arrays read the arrangement's memory,
// which they keep alive (checked under AddressSanitizer in the sanitizer build).
TEST(StageChain, RefinedSurfaceOutlivesItsFilters)
{
  auto surface = testutils::ToPolyData(boolsurf::MakeIcosphere(2));
  vtkNew<vtkPolyData> held, deep, heldPatches, deepPatches;
  {
    std::mt19937 rng(8);
    Chain chain(surface, RandomCurves(surface, PointForm::Exact, rng));
    chain.Boolean->Update();
    ASSERT_EQ(chain.Log.Catcher->Errors, "");
    held->ShallowCopy(chain.Arrange->GetOutput(0));
    deep->DeepCopy(chain.Arrange->GetOutput(0));
    heldPatches->ShallowCopy(chain.Arrange->GetOutput(1));
    deepPatches->DeepCopy(chain.Arrange->GetOutput(1));
  }
  ExpectIdentical(held, deep, "refined surface after its filters were deleted");
  {
    // Still a surface VTK works with: the Boolean from the held copy alone.
    vtkNew<vtkBoolSurfBoolean> boolean;
    boolean->SetInputData(held);
    boolean->SetShapeA(-1);
    boolean->SetShapeB(-1);
    EXPECT_EQ(testutils::ErrorsOf(boolean), "");
    EXPECT_GT(testutils::Area(boolean->GetOutput()), 0.0);
  }
  held->Initialize(); // the patches alone hold the points now
  deep->Initialize();
  ExpectIdentical(heldPatches, deepPatches, "patches after their filters were deleted");
}

// The refined surface's per-point arrays keep the mesh vertices' part between edits on one
// mesh: after a change to another mesh with as many vertices (and back), every array equals that
// of a chain that saw only that mesh.
TEST(StageChain, RefinedSurfaceAfterASurfaceChange)
{
  auto first = testutils::ToPolyData(boolsurf::MakeFlatSquare(12, 1.0, 0.3, 4));
  auto second = testutils::ToPolyData(boolsurf::MakeFlatSquare(12, 1.0, 0.3, 5));
  Chain chain(first, TwoSquares(0.0));
  int step = 0;
  for (vtkPolyData* surface : { first.GetPointer(),
         second.GetPointer(),
         second.GetPointer(),
         first.GetPointer(),
         first.GetPointer() })
  {
    const double shift = 0.02 * (step++ % 3);
    chain.Trace->SetInputData(0, surface);
    chain.Trace->SetInputData(1, TwoSquares(shift));
    chain.Arrange->SetInputData(0, surface);
    chain.Boolean->Update();
    ASSERT_EQ(chain.Log.Catcher->Errors, "");
    Chain fresh(surface, TwoSquares(shift));
    fresh.Boolean->Update();
    ExpectIdentical(chain.Arrange->GetOutput(0),
      fresh.Arrange->GetOutput(0),
      "refined surface at step " + std::to_string(step));
  }
}

// The stages of a chain share one converted surface; a surface edited in place (its points
// moved, then Modified) is converted again for all of them, and the chain answers as a fresh
// one on the edited surface does.
TEST(StageChain, SurfaceEditedInPlaceIsConvertedAgain)
{
  auto surface = testutils::ToPolyData(boolsurf::MakeFlatSquare(12, 1.0, 0.3, 6));
  Chain chain(surface, TwoSquares(0.0));
  chain.Boolean->Update();
  ASSERT_EQ(chain.Log.Catcher->Errors, "");
  vtkPoints* points = surface->GetPoints();
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    double x[3];
    points->GetPoint(p, x);
    points->SetPoint(p, 2 * x[0], x[1], x[2]); // stretched along x
  }
  points->Modified();
  chain.Trace->SetInputData(1, TwoSquares(0.0)); // the same curves, given again as coordinates
  chain.Boolean->Update();
  ASSERT_EQ(chain.Log.Catcher->Errors, "");
  vtkNew<vtkPolyData> copy; // another object: converted on its own
  copy->DeepCopy(surface);
  Chain fresh(copy, TwoSquares(0.0));
  fresh.Boolean->Update();
  ExpectIdentical(chain.Arrange->GetOutput(0), fresh.Arrange->GetOutput(0), "edited surface");
  EXPECT_EQ(
    testutils::Area(chain.Boolean->GetOutput()), testutils::Area(fresh.Boolean->GetOutput()));
}

// BoolSurf outputs do not take the executive's copy of their input's field data, but a VTK
// filter downstream of one still receives the output's field data as usual.
TEST(StageChain, FiltersDownstreamReceiveTheFieldData)
{
  auto surface = testutils::ToPolyData(boolsurf::MakeFlatSquare(8));
  Chain chain(surface, TwoSquares(0.0));
  vtkNew<vtkTriangleFilter> downstream;
  downstream->SetInputConnection(chain.Boolean->GetOutputPort(0));
  downstream->Update();
  ASSERT_EQ(chain.Log.Catcher->Errors, "");
  vtkFieldData* fd = downstream->GetOutput()->GetFieldData();
  for (const char* name : { "CellLabels", "ShapeIds" })
  {
    EXPECT_NE(fd->GetAbstractArray(name), nullptr) << name;
  }
  // Each output's field data is its own: the labels are not written into the arrangement's.
  EXPECT_EQ(chain.Arrange->GetOutput(0)->GetFieldData()->GetAbstractArray("CellLabels"), nullptr);
  EXPECT_NE(chain.Label->GetOutput(0)->GetFieldData()->GetAbstractArray("CellLabels"), nullptr);
  // The Boolean's own field data is its own: nothing of the labeled input's cell graph.
  EXPECT_EQ(
    chain.Boolean->GetOutput(0)->GetFieldData()->GetAbstractArray("CellGraphArcs"), nullptr);
}

// Boundary Sampled Curves through the chain gives the one-step BSC region.
TEST(StageChain, BoundarySampledCurvesMatchOneStep)
{
  auto surface = testutils::ToPolyData(boolsurf::MakeFlatSquare(14, 1.0, 0.3, 9));
  auto curves = TwoSquares(0.0);
  // Samples on the first square's bottom edge pointing inside, and on the second's right edge
  // pointing outside: the region is the first square minus the second.
  auto samples = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.2, 0.1, 0);
  points->InsertNextPoint(0.9, 0.5, 0);
  vtkNew<vtkDoubleArray> direction;
  direction->SetName("Direction");
  direction->SetNumberOfComponents(3);
  direction->InsertNextTuple3(0, 1, 0);
  direction->InsertNextTuple3(1, 0, 0);
  samples->SetPoints(points);
  samples->GetPointData()->AddArray(direction);

  vtkNew<vtkBoolSurf> one;
  one->SetInputData(0, surface);
  one->SetInputData(1, curves);
  one->SetInputData(2, samples);
  one->SetSelection(vtkBoolSurf::BSC_SELECTION);
  EXPECT_EQ(testutils::ErrorsOf(one), "");

  Chain chain(surface, curves);
  vtkNew<vtkBoolSurfBSC> bsc;
  bsc->SetInputConnection(0, chain.Label->GetOutputPort(0));
  bsc->SetInputData(1, samples);
  EXPECT_EQ(testutils::ErrorsOf(bsc), "");
  EXPECT_GT(testutils::Area(bsc->GetOutput()), 0.0);
  for (int port = 0; port < 4; ++port)
  {
    ExpectIdentical(one->GetOutput(port), bsc->GetOutput(port), "BSC port " + std::to_string(port));
  }
}

// Boundary Sampled Curves on an arrangement read back from arrays (a file: no Core result
// attached) gives the answer of the handed-over arrangement and of the one-step filter: the
// surface normal that decides a sample's side is the source triangle's on every path. Samples
// point mostly along the surface normal, so a vertex-averaged normal would flip some of them.
TEST(StageChain, BoundarySampledCurvesFromArraysMatchHandedOver)
{
  std::mt19937 rng(31);
  std::normal_distribution<double> gauss;
  std::vector<NamedSurface> surfaces{
    { "coarse sphere", testutils::ToPolyData(boolsurf::MakeIcosphere(1)) },
    { "sphere", testutils::ToPolyData(boolsurf::MakeIcosphere(2)) },
  };
  int samplesChecked = 0;
  for (const NamedSurface& s : surfaces)
  {
    for (int trial = 0; trial < 8; ++trial)
    {
      const std::string what = s.Name + ", trial " + std::to_string(trial);
      auto curves = RandomCurves(s.Surface, PointForm::Exact, rng);
      Chain chain(s.Surface, curves);
      chain.Label->Update();
      if (chain.Log.Catcher->Errors != "")
      {
        continue; // a refused drawing: the chain against one step is the test above
      }
      // One sample at the middle of each patch's middle segment; the direction is the sphere's
      // normal there, tilted a little to a random side.
      vtkPolyData* patches = chain.Arrange->GetOutput(1);
      auto samples = vtkSmartPointer<vtkPolyData>::New();
      vtkNew<vtkPoints> points;
      vtkNew<vtkDoubleArray> direction;
      direction->SetName("Direction");
      direction->SetNumberOfComponents(3);
      for (vtkIdType c = 0; c < patches->GetNumberOfCells(); ++c)
      {
        vtkIdType n;
        const vtkIdType* ids;
        patches->GetCellPoints(c, n, ids);
        if (n < 2)
        {
          continue;
        }
        double a[3], b[3], x[3], d[3];
        patches->GetPoint(ids[(n - 1) / 2], a);
        patches->GetPoint(ids[(n - 1) / 2 + 1], b);
        for (int k = 0; k < 3; ++k)
        {
          x[k] = 0.5 * (a[k] + b[k]);
        }
        const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        for (int k = 0; k < 3; ++k)
        {
          d[k] = x[k] / r + 0.05 * gauss(rng);
        }
        points->InsertNextPoint(x);
        direction->InsertNextTuple(d);
      }
      samples->SetPoints(points);
      samples->GetPointData()->AddArray(direction);

      vtkNew<vtkBoolSurf> one;
      one->SetInputData(0, s.Surface);
      one->SetInputData(1, curves);
      one->SetInputData(2, samples);
      one->SetSelection(vtkBoolSurf::BSC_SELECTION);
      const std::string oneErrors = testutils::ErrorsOf(one);

      vtkNew<vtkBoolSurfBSC> handedOver;
      handedOver->SetInputConnection(0, chain.Label->GetOutputPort(0));
      handedOver->SetInputData(1, samples);
      vtkNew<vtkPolyData> deep; // arrays only, as from a file
      deep->DeepCopy(chain.Label->GetOutput());
      vtkNew<vtkBoolSurfBSC> fromArrays;
      fromArrays->SetInputData(0, deep);
      fromArrays->SetInputData(1, samples);
      EXPECT_EQ(testutils::ErrorsOf(handedOver), oneErrors) << what;
      EXPECT_EQ(testutils::ErrorsOf(fromArrays), oneErrors) << what;
      if (!oneErrors.empty())
      {
        continue;
      }
      samplesChecked += static_cast<int>(samples->GetNumberOfPoints());
      for (vtkBoolSurfBSC* bsc : { handedOver.GetPointer(), fromArrays.GetPointer() })
      {
        vtkFieldData* fd = bsc->GetOutput(0)->GetFieldData();
        vtkFieldData* expected = one->GetOutput(0)->GetFieldData();
        for (const char* name : { "SamplePatch", "SampleOnBoundary", "BSCCuts" })
        {
          EXPECT_EQ(IntsOf(fd, name), IntsOf(expected, name)) << what << ": " << name;
        }
        // The same triangles; from arrays they are written in another order, so the area's sum
        // may differ in its last bits.
        const double area = testutils::Area(one->GetOutput(0));
        EXPECT_NEAR(testutils::Area(bsc->GetOutput(0)), area, 1e-13 * area) << what;
        EXPECT_EQ(bsc->GetOutput(0)->GetNumberOfCells(), one->GetOutput(0)->GetNumberOfCells())
          << what;
      }
    }
  }
  EXPECT_GT(samplesChecked, 50);
}

// A stage below a failed one says that its input is empty because of an upstream error, not
// that the pipeline is wired wrong.
TEST(StageChain, DownstreamOfAFailureNamesTheUpstreamError)
{
  auto surface = testutils::ToPolyData(boolsurf::MakeFlatSquare(6));
  testutils::ControlPolygon bezier;
  bezier.Type = 1; // a closed cubic Bezier needs 3n control points: 4 is an error
  bezier.Points = { { 0.1, 0.1, 0 }, { 0.5, 0.1, 0 }, { 0.5, 0.5, 0 }, { 0.1, 0.5, 0 } };
  Chain chain(surface, testutils::ToCurves({ bezier }));
  chain.Boolean->Update();
  const std::string& errors = chain.Log.Catcher->Errors;
  EXPECT_NE(errors.find("3n control points"), std::string::npos) << errors;
  EXPECT_NE(errors.find("the curves input is empty: the filter before it (Trace Surface Curves) "
                        "reported an error"),
    std::string::npos)
    << errors;
  EXPECT_NE(errors.find("the input is empty: the filter before it"), std::string::npos) << errors;
  EXPECT_EQ(errors.find("connect the"), std::string::npos) << errors;
}

// A refused traced point is named by the user's curve and control points, not only by its
// index in the traced polyline.
TEST(StageChain, ArrangementErrorNamesTheControlPoints)
{
  auto surface = testutils::ToPolyData(boolsurf::MakeFlatSquare(8));
  Chain chain(surface, TwoSquares(0.0));
  chain.Trace->Update();
  vtkNew<vtkPolyData> traced;
  traced->DeepCopy(chain.Trace->GetOutput()); // arrays only, as from a file
  // Move one traced point of the second curve, between its control points, into a far
  // triangle: it then shares no triangle with its neighbours.
  vtkDataArray* segment = traced->GetPointData()->GetArray("ControlSegment");
  vtkDataArray* control = traced->GetPointData()->GetArray("ControlPointId");
  vtkIdType n;
  const vtkIdType* ids;
  traced->GetCellPoints(1, n, ids);
  vtkIdType broken = -1;
  for (vtkIdType k = 1; k < n && broken < 0; ++k)
  {
    if (control->GetComponent(ids[k], 0) < 0)
    {
      broken = k;
    }
  }
  ASSERT_GE(broken, 0);
  const int seg = static_cast<int>(segment->GetComponent(ids[broken], 0));
  traced->GetPointData()->GetArray("TriangleId")->SetComponent(ids[broken], 0, 0);
  traced->GetPointData()->GetArray("Barycentric")->SetComponent(ids[broken], 0, 0.3);
  traced->GetPointData()->GetArray("Barycentric")->SetComponent(ids[broken], 1, 0.3);
  vtkNew<vtkBoolSurfArrangement> arrange;
  arrange->SetInputData(0, surface);
  arrange->SetInputData(1, traced);
  const std::string errors = testutils::ErrorsOf(arrange);
  EXPECT_NE(errors.find("share no triangle"), std::string::npos) << errors;
  const std::string where = "curve 1 of shape 1, between its control points " +
    std::to_string(seg) + " and " + std::to_string((seg + 1) % 4);
  EXPECT_NE(errors.find(where), std::string::npos) << errors;
}

// Resolve Inconsistent Shapes before the stage chain gives the one-step filter's
// ResolveStrategy answer: a torus meridian (no region on its own) and a disc, resolved by each
// strategy.
TEST(StageChain, ResolvedShapesMatchOneStep)
{
  const double R = 1.0, r = 0.4;
  auto surface = testutils::ToPolyData(boolsurf::MakeTorus(R, r, 32, 16));
  testutils::ControlPolygon meridian, disc;
  meridian.ShapeId = 0;
  for (int k = 0; k < 12; ++k)
  {
    const double v = 0.1 + 2 * 3.14159265358979323846 * k / 12, u = 0.3;
    meridian.Points.push_back({ (R + r * std::cos(v)) * std::cos(u),
      (R + r * std::cos(v)) * std::sin(u),
      r * std::sin(v) });
  }
  disc.ShapeId = 1;
  for (int k = 0; k < 8; ++k)
  {
    const double t = 2 * 3.14159265358979323846 * k / 8;
    const double u = 2.0 + 0.15 * std::cos(t), v = 1.2 + 0.15 * std::sin(t);
    disc.Points.push_back({ (R + r * std::cos(v)) * std::cos(u),
      (R + r * std::cos(v)) * std::sin(u),
      r * std::sin(v) });
  }
  auto curves = testutils::ToCurves({ meridian, disc });
  for (int strategy : { vtkBoolSurfResolve::ADD_GENERATORS,
         vtkBoolSurfResolve::DUPLICATE_REVERSED,
         vtkBoolSurfResolve::REMOVE_CURVES })
  {
    const std::string what = "strategy " + std::to_string(strategy);
    vtkNew<vtkBoolSurf> one;
    Messages m;
    m.Watch(one);
    one->SetInputData(0, surface);
    one->SetInputData(1, curves);
    one->SetResolveStrategy(strategy);
    one->SetResolveOffset(0.01);
    one->SetShapeA(-1);
    one->SetShapeB(-1);
    one->Update();

    vtkNew<vtkBoolSurfResolve> resolve;
    resolve->SetInputData(0, surface);
    resolve->SetInputData(1, curves);
    resolve->SetStrategy(strategy);
    resolve->SetOffset(0.01);
    Chain chain(surface, curves);
    chain.Log.Watch(resolve);
    chain.Trace->SetInputConnection(1, resolve->GetOutputPort());
    chain.Boolean->Update();
    ASSERT_EQ(m.Catcher->Errors, "") << what;
    ASSERT_EQ(chain.Log.Catcher->Errors, "") << what;
    EXPECT_GT(one->GetOutput()->GetNumberOfCells(), 0) << what;
    for (int port = 0; port < 4; ++port)
    {
      ExpectIdentical(one->GetOutput(port),
        chain.Boolean->GetOutput(port),
        what + ", port " + std::to_string(port));
    }
  }
}
