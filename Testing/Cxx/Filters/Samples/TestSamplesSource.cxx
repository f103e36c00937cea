// BSC Samples (vtkBoolSurfSamples): the samples given as properties come out as one vertex per
// point with its Direction, only in the first piece, and a Directions count that is not the
// Points count is an error naming both counts, with an empty output.
#include "FilterTestUtils.h"
#include "vtkBoolSurfArrayNames.h"
#include "vtkBoolSurfSamples.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <gtest/gtest.h>

TEST(SamplesSource, PointsComeOutAsVerticesWithTheirDirections)
{
  vtkNew<vtkBoolSurfSamples> samples;
  samples->SetNumberOfPoints(3);
  samples->SetNumberOfDirections(3);
  const double points[3][3] = { { 0.1, 0.2, 0.0 }, { 0.5, 0.5, 0.0 }, { 0.9, 0.3, 0.25 } };
  const double directions[3][3] = { { 1, 0, 0 }, { 0, 2, 0 }, { -1, -1, 3 } };
  for (int i = 0; i < 3; ++i)
  {
    samples->SetPoint(i, points[i][0], points[i][1], points[i][2]);
    samples->SetDirection(i, directions[i][0], directions[i][1], directions[i][2]);
  }
  ASSERT_EQ(testutils::ErrorsOf(samples), "");
  vtkPolyData* out = samples->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), 3);
  ASSERT_EQ(out->GetNumberOfVerts(), 3);
  vtkDataArray* direction = out->GetPointData()->GetArray(boolsurf::names::Direction);
  ASSERT_NE(direction, nullptr);
  ASSERT_EQ(direction->GetNumberOfComponents(), 3);
  for (int i = 0; i < 3; ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_EQ(x[k], points[i][k]);
      EXPECT_EQ(direction->GetComponent(i, k), directions[i][k]) << "sample " << i;
    }
  }
}

TEST(SamplesSource, OnlyTheFirstPieceHoldsTheSamples)
{
  vtkNew<vtkBoolSurfSamples> samples;
  samples->SetNumberOfPoints(1);
  samples->SetNumberOfDirections(1);
  samples->SetPoint(0, 0.5, 0.5, 0.0);
  samples->SetDirection(0, 0, 1, 0);
  samples->UpdatePiece(1, 2, 0);
  EXPECT_EQ(samples->GetOutput()->GetNumberOfPoints(), 0);
  samples->UpdatePiece(0, 2, 0);
  EXPECT_EQ(samples->GetOutput()->GetNumberOfPoints(), 1);
}

TEST(SamplesSource, DirectionCountMismatchIsNamed)
{
  vtkNew<vtkBoolSurfSamples> samples;
  samples->SetNumberOfPoints(2);
  samples->SetNumberOfDirections(1);
  const std::string errors = testutils::ErrorsOf(samples);
  EXPECT_NE(errors.find("Each of the 2 sample Points needs a Direction; got 1 Directions"),
    std::string::npos)
    << errors;
  EXPECT_EQ(samples->GetOutput()->GetNumberOfPoints(), 0);
}
