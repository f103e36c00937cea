// The example stage of Docs/Architecture.md ("Adding a stage"), compiled and run: its Core
// function, its filter on the base class, its XML. If the recipe stops working (the base class
// no longer hands over the arrangement, a file's arrays are no longer decoded, the XML no longer
// matches the class), these tests fail.
#include "CellAreas.h"
#include "FilterTestUtils.h"
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfExampleCellAreas.h"
#include "vtkBoolSurfTraceCurves.h"

#include "Support/SourceTree.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkTrivialProducer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

using testutils::ControlPolygon;

namespace
{
/// A rectangle [0.2, 0.6] x [0.3, 0.7] (area 0.16), counter-clockwise, on the unit square.
vtkSmartPointer<vtkPolyData> Rectangle()
{
  ControlPolygon c;
  c.Points = { { 0.2, 0.3, 0 }, { 0.6, 0.3, 0 }, { 0.6, 0.7, 0 }, { 0.2, 0.7, 0 } };
  return testutils::ToCurves({ c });
}

std::vector<double> CellAreas(vtkPolyData* output)
{
  std::vector<double> areas;
  vtkDataArray* a = output->GetFieldData()->GetArray(boolsurf::names::CellArea);
  for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
  {
    areas.push_back(a->GetTuple1(i));
  }
  return areas;
}

struct Chain
{
  vtkNew<vtkBoolSurfTraceCurves> Trace;
  vtkNew<vtkBoolSurfArrangement> Arrange;
  vtkNew<vtkBoolSurfExampleCellAreas> Areas;
  Chain(vtkPolyData* surface, vtkPolyData* curves)
  {
    this->Trace->SetInputData(0, surface);
    this->Trace->SetInputData(1, curves);
    this->Arrange->SetInputData(0, surface);
    this->Arrange->SetInputConnection(1, this->Trace->GetOutputPort());
    this->Areas->SetInputConnection(this->Arrange->GetOutputPort(0));
  }
};
} // namespace

TEST(ExampleStage, CellAreasOfARectangleOnAFlatSquare)
{
  auto surface = testutils::ToPolyData(boolsurf::MakeFlatSquare(20, 1.0, 0.2, 5));
  auto curves = Rectangle();
  Chain chain(surface, curves);
  ASSERT_EQ(testutils::ErrorsOf(chain.Areas), "");
  const std::vector<double> areas = CellAreas(chain.Areas->GetOutput());
  ASSERT_EQ(areas.size(), 2u); // inside and outside the rectangle
  const double inside = std::min(areas[0], areas[1]);
  EXPECT_NEAR(inside, 0.16, 1e-12);
  EXPECT_NEAR(areas[0] + areas[1], 1.0, 1e-12);
  // The refined surface passes through.
  EXPECT_EQ(
    chain.Areas->GetOutput()->GetNumberOfCells(), chain.Arrange->GetOutput(0)->GetNumberOfCells());

  chain.Areas->SetAreaScale(0.5);
  ASSERT_EQ(testutils::ErrorsOf(chain.Areas), "");
  const std::vector<double> scaled = CellAreas(chain.Areas->GetOutput());
  ASSERT_EQ(scaled.size(), 2u);
  EXPECT_EQ(scaled[0], 0.5 * areas[0]);
  EXPECT_EQ(scaled[1], 0.5 * areas[1]);
}

TEST(ExampleStage, AFileOfTheArrangementGivesTheSameAreas)
{
  // A deep copy has no Core result attached, as a file read back has none: the base class
  // rebuilds the arrangement from the arrays.
  auto surface = testutils::ToPolyData(boolsurf::MakeFlatSquare(20, 1.0, 0.2, 5));
  auto curves = Rectangle();
  Chain chain(surface, curves);
  ASSERT_EQ(testutils::ErrorsOf(chain.Areas), "");
  const std::vector<double> handedOver = CellAreas(chain.Areas->GetOutput());

  vtkNew<vtkPolyData> copy;
  copy->DeepCopy(chain.Arrange->GetOutput(0));
  vtkNew<vtkBoolSurfExampleCellAreas> fromFile;
  fromFile->SetInputData(copy);
  ASSERT_EQ(testutils::ErrorsOf(fromFile), "");
  EXPECT_EQ(CellAreas(fromFile->GetOutput()), handedOver);
}

TEST(ExampleStage, BadInputIsNamed)
{
  auto surface = testutils::ToPolyData(boolsurf::MakeFlatSquare(4));
  vtkNew<vtkBoolSurfExampleCellAreas> areas;
  areas->SetInputData(surface); // a plain surface: no arrangement
  std::string errors = testutils::ErrorsOf(areas);
  EXPECT_NE(errors.find("ArrangementCell"), std::string::npos) << errors;
  EXPECT_EQ(areas->GetOutput()->GetNumberOfCells(), 0);

  Chain chain(surface, Rectangle());
  chain.Areas->SetAreaScale(-1);
  errors = testutils::ErrorsOf(chain.Areas);
  EXPECT_NE(errors.find("AreaScale must be positive; got -1."), std::string::npos) << errors;
  EXPECT_EQ(chain.Areas->GetOutput()->GetNumberOfCells(), 0);
}

TEST(ExampleStage, TheXmlDeclaresTheClassAndItsSetters)
{
  // The recipe's XML names the class and, for every property, a setter the class declares.
  const std::filesystem::path folder =
    boolsurf::testing::SourceTree() / "Testing" / "Cxx" / "Filters" / "ExampleStage";
  vtkXMLDataElement* root =
    vtkXMLUtilities::ReadElementFromFile((folder / "ExampleCellAreas.xml").string().c_str());
  ASSERT_NE(root, nullptr);
  vtkXMLDataElement* proxy = root->LookupElementWithName("SourceProxy");
  ASSERT_NE(proxy, nullptr);
  EXPECT_STREQ(proxy->GetAttribute("class"), "vtkBoolSurfExampleCellAreas");
  std::ifstream header(folder / "vtkBoolSurfExampleCellAreas.h");
  std::stringstream text;
  text << header.rdbuf();
  int properties = 0;
  for (int i = 0; i < proxy->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* p = proxy->GetNestedElement(i);
    const char* command = p->GetAttribute("command");
    if (!command || std::string(command) == "SetInputConnection")
    {
      continue;
    }
    ++properties;
    const std::string name = std::string(command).substr(3); // SetX -> X
    EXPECT_TRUE(std::regex_search(text.str(), std::regex("vtkSetMacro\\(" + name + ",")))
      << command << " is not declared by the class";
  }
  EXPECT_EQ(properties, 1);
  root->Delete();
}
