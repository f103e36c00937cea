#include "Winding/HarmonicBasis.h"

#include "Homology/HomologyBasis.h"
#include "Mesh/MeshTopology.h"

#include <Eigen/Dense>

#include <algorithm>

namespace boolsurf
{

bool HarmonicBasis::Compute(const TriangleMesh& mesh,
  const CotanLaplacian& laplacian,
  std::string& error)
{
  this->Smooth.clear();
  this->Lifts.clear();
  this->GramInverse.clear();
  const MeshTopology topology = MeshTopology::Compute(mesh);
  HomologyBasis basis;
  if (!basis.Compute(mesh, topology, HomologyOptions(), error))
  {
    return false;
  }
  const int ng = basis.GetNumberOfGenerators();
  if (ng == 0)
  {
    return true;
  }
  const int nv = mesh.GetNumberOfVertices();
  std::vector<double> columns(static_cast<size_t>(nv) * ng, 0.0);
  this->Lifts.resize(ng);
  for (int g = 0; g < ng; ++g)
  {
    // The generator as a closed traced curve (edge points; chords of triangles between).
    TracedCurve curve;
    curve.Points = basis.GetGenerator(g).Points;
    curve.Closed = true;
    Arrangement arr;
    if (!ComputeArrangement(mesh, { curve }, ArrangementOptions(), arr, error))
    {
      error = "homology generator " + std::to_string(g) + " could not be arranged: " + error;
      return false;
    }
    CurveEdgeList edges;
    AppendCurveEdges(arr, 0, true, edges);
    ComputeJumpLift(mesh, arr, edges, this->Lifts[g]);
    AddLiftLoad(mesh, this->Lifts[g], columns.data() + static_cast<size_t>(g) * nv);
  }
  for (double& b : columns)
  {
    b = -b;
  }
  laplacian.Solve(columns, ng);
  this->Smooth.resize(ng);
  for (int g = 0; g < ng; ++g)
  {
    this->Smooth[g].assign(columns.begin() + static_cast<size_t>(g) * nv,
      columns.begin() + static_cast<size_t>(g + 1) * nv);
  }
  // Gram matrix of the fields: sum over triangles of area * G_g . G_h.
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(ng, ng);
  std::vector<Vec3> field(ng);
  for (int t = 0; t < mesh.GetNumberOfTriangles(); ++t)
  {
    const TriangleGradients tg = ComputeTriangleGradients(mesh, t);
    if (tg.Area == 0.0)
    {
      continue;
    }
    for (int g = 0; g < ng; ++g)
    {
      field[g] = this->FieldOn(mesh, g, t);
    }
    for (int g = 0; g < ng; ++g)
    {
      for (int h = g; h < ng; ++h)
      {
        gram(g, h) += tg.Area * Dot(field[g], field[h]);
      }
    }
  }
  gram = gram.selfadjointView<Eigen::Upper>();
  const Eigen::MatrixXd inverse = gram.inverse();
  this->GramInverse.assign(inverse.data(), inverse.data() + ng * ng);
  return true;
}

Vec3 HarmonicBasis::FieldOn(const TriangleMesh& mesh, int g, int t) const
{
  const TriangleGradients tg = ComputeTriangleGradients(mesh, t);
  if (tg.Area == 0.0)
  {
    return Vec3{ 0, 0, 0 };
  }
  const Triangle& tri = mesh.GetTriangle(t);
  Vec3 grad{ 0, 0, 0 };
  for (int k = 0; k < 3; ++k)
  {
    grad = grad + this->Smooth[g][tri[k]] * tg.Hat[k];
  }
  const JumpLift& lift = this->Lifts[g];
  const auto it = std::lower_bound(lift.MeshTriangles.begin(), lift.MeshTriangles.end(), t);
  if (it != lift.MeshTriangles.end() && *it == t)
  {
    grad = grad + (1.0 / tg.Area) * lift.Flux[it - lift.MeshTriangles.begin()];
  }
  return grad;
}

std::vector<double> HarmonicBasis::Coefficients(const TriangleMesh& mesh,
  const JumpLift& lift) const
{
  const int ng = this->GetNumberOfGenerators();
  std::vector<double> pairing(ng, 0.0), result(ng, 0.0);
  for (size_t h = 0; h < lift.MeshTriangles.size(); ++h)
  {
    for (int g = 0; g < ng; ++g)
    {
      pairing[g] += Dot(lift.Flux[h], this->FieldOn(mesh, g, lift.MeshTriangles[h]));
    }
  }
  for (int g = 0; g < ng; ++g)
  {
    for (int h = 0; h < ng; ++h)
    {
      result[g] += this->GramInverse[g + h * ng] * pairing[h];
    }
  }
  return result;
}

} // namespace boolsurf
