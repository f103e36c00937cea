// Scene regression suite: every BoolSurf reference scene of ../shared/data/boolsurf-scenes runs
// through reader -> Trace Surface Curves -> Surface Arrangement -> Label Arrangement Cells,
// and what comes out (number of arrangement cells, inconsistent shapes, or the error of the
// stage that failed) is compared with Testing/Data/scene_expectations.json.
//
// Re-record after an intended change:
//   BOOLSURF_RECORD_SCENES=/tmp/scenes ctest -R SceneRegression
//   /usr/bin/python3 Testing/Data/update_scene_expectations.py /tmp/scenes
// Skips (with a message) when the shared data (BOOLSURF_SHARED_DATA) is absent.
#include "vtkBoolSurfArrangement.h"
#include "vtkBoolSurfLabeling.h"
#include "vtkBoolSurfSceneReader.h"
#include "vtkBoolSurfTraceCurves.h"

#include "Support/SourceTree.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using json = nlohmann::json;

fs::path ExpectationsFile()
{
  return boolsurf::testing::SourceTree() / "Testing" / "Data" / "scene_expectations.json";
}

json Expectations()
{
  std::ifstream in(ExpectationsFile());
  if (!in)
  {
    return json::object();
  }
  return json::parse(in)["scenes"];
}

fs::path ScenesDir()
{
  const char* data = std::getenv("BOOLSURF_SHARED_DATA");
  return data && *data ? fs::path(data) / "boolsurf-scenes" : fs::path();
}

std::vector<std::string> SceneNames()
{
  std::vector<std::string> names;
  const json expectations = Expectations();
  for (auto& item : expectations.items())
  {
    names.push_back(item.key());
  }
  if (names.empty())
  {
    names.push_back("missing-expectations-file");
  }
  return names;
}

/// Collects the error messages of a VTK object instead of printing them.
struct ErrorCatcher
{
  std::string Messages;
  vtkNew<vtkCallbackCommand> Command;
  ErrorCatcher()
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback(
      [](vtkObject*, unsigned long, void* self, void* text)
      {
        auto* catcher = static_cast<ErrorCatcher*>(self);
        std::string message = text ? static_cast<const char*>(text) : "";
        // Keep the text after the "ClassName (0x...): " prefix: addresses change between runs.
        const auto colon = message.find("): ");
        if (colon != std::string::npos)
        {
          message = message.substr(colon + 3);
        }
        while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
        {
          message.pop_back();
        }
        if (!catcher->Messages.empty())
        {
          catcher->Messages += "\n";
        }
        catcher->Messages += message;
      });
  }
  void Watch(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this->Command);
    object->AddObserver(vtkCommand::WarningEvent, vtkNew<vtkCallbackCommand>()); // silence
  }
};

/// Runs one scene; returns what the expectations file records for it.
json RunScene(const fs::path& scene)
{
  const auto start = std::chrono::steady_clock::now();
  ErrorCatcher readerErrors, traceErrors, arrangementErrors, labelErrors;
  vtkNew<vtkBoolSurfSceneReader> reader;
  reader->SetFileName(scene.string().c_str());
  readerErrors.Watch(reader);
  reader->Update();
  json result;
  auto fail = [&](const char* stage, const std::string& message)
  {
    result["status"] = "error";
    result["stage"] = stage;
    result["message"] = message;
    return result;
  };
  vtkPolyData* curves = reader->GetCurvesOutput();
  if (!readerErrors.Messages.empty() || curves->GetNumberOfCells() == 0)
  {
    std::string message = readerErrors.Messages;
    // The reader names the scene file by its absolute path: keep the part after it.
    const std::string prefix = "BoolSurf scene " + scene.string() + ": ";
    if (message.rfind(prefix, 0) == 0)
    {
      message = message.substr(prefix.size());
    }
    // Keep the first line only (the list of places searched depends on the machine), and
    // name files of the shared collection relative to it.
    message = message.substr(0, message.find('\n'));
    const std::string shared =
      fs::absolute(ScenesDir()).lexically_normal().parent_path().string() + "/";
    for (auto at = message.find(shared); at != std::string::npos; at = message.find(shared))
    {
      message.replace(at, shared.size(), "$BOOLSURF_SHARED_DATA/");
    }
    return fail("reader", message);
  }
  result["triangles"] = reader->GetOutput(0)->GetNumberOfCells();
  result["curves"] = curves->GetNumberOfCells();

  vtkNew<vtkBoolSurfTraceCurves> trace;
  trace->SetInputConnection(0, reader->GetOutputPort(0));
  trace->SetInputConnection(1, reader->GetOutputPort(1));
  traceErrors.Watch(trace);
  vtkNew<vtkBoolSurfArrangement> arrangement;
  arrangement->SetInputConnection(0, reader->GetOutputPort(0));
  arrangement->SetInputConnection(1, trace->GetOutputPort(0));
  arrangementErrors.Watch(arrangement);
  vtkNew<vtkBoolSurfLabeling> labeling;
  labeling->SetInputConnection(0, arrangement->GetOutputPort(0));
  labelErrors.Watch(labeling);

  trace->Update();
  if (!traceErrors.Messages.empty() || trace->GetOutput()->GetNumberOfCells() == 0)
  {
    return fail("trace", traceErrors.Messages);
  }
  arrangement->Update();
  vtkFieldData* afd = arrangement->GetOutput(0)->GetFieldData();
  if (!arrangementErrors.Messages.empty() || !afd->GetArray("NumberOfCells"))
  {
    return fail("arrangement", arrangementErrors.Messages);
  }
  labeling->Update();
  vtkFieldData* fd = labeling->GetOutput(0)->GetFieldData();
  vtkDataArray* cells = fd->GetArray("NumberOfCells");
  vtkDataArray* consistent = fd->GetArray("ShapeConsistent");
  if (!labelErrors.Messages.empty() || !cells || !consistent)
  {
    return fail("labeling", labelErrors.Messages);
  }
  result["status"] = "ok";
  result["cells"] = static_cast<int>(cells->GetComponent(0, 0));
  // Inconsistent shapes by ShapeId (ShapeConsistent is per shape index, in ShapeIds' order).
  vtkDataArray* shapeIds = fd->GetArray("ShapeIds");
  std::vector<int> inconsistent;
  for (vtkIdType s = 0; s < consistent->GetNumberOfTuples(); ++s)
  {
    if (consistent->GetComponent(s, 0) == 0)
    {
      inconsistent.push_back(static_cast<int>(shapeIds->GetComponent(s, 0)));
    }
  }
  result["inconsistent"] = inconsistent;
  result["seconds"] =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

class SceneRegression : public ::testing::TestWithParam<std::string>
{
};

TEST_P(SceneRegression, MatchesExpectations)
{
  const std::string name = GetParam();
  const json expectations = Expectations();
  ASSERT_TRUE(expectations.contains(name))
    << "no expectations in " << ExpectationsFile() << " for " << name;
  const json& expected = expectations[name];
  if (ScenesDir().empty() || !fs::is_directory(ScenesDir()))
  {
    GTEST_SKIP() << "BOOLSURF_SHARED_DATA is not set or has no boolsurf-scenes/: the scene "
                    "regression suite needs ../shared/data";
  }
  if (expected.value("status", "") == "skipped")
  {
    GTEST_SKIP() << name << ": " << expected.value("reason", "skipped");
  }
  const json got = RunScene(ScenesDir() / name);
  if (const char* record = std::getenv("BOOLSURF_RECORD_SCENES"))
  {
    fs::create_directories(record);
    std::string file = name;
    std::replace(file.begin(), file.end(), '/', '@');
    std::ofstream(fs::path(record) / file) << json{ { name, got } }.dump(2) << "\n";
  }
  std::cout << name << ": " << got.dump() << "\n";
  EXPECT_EQ(got.value("status", ""), expected.value("status", ""))
    << name << ": got " << got.dump() << "\nexpected " << expected.dump();
  if (expected.value("status", "") == "ok")
  {
    EXPECT_EQ(got.value("cells", -1), expected.value("cells", -2)) << name;
    EXPECT_EQ(got.value("inconsistent", json::array()), expected["inconsistent"]) << name;
    EXPECT_EQ(got.value("curves", -1), expected.value("curves", -2)) << name;
  }
  else if (expected.value("status", "") == "error")
  {
    EXPECT_EQ(got.value("stage", ""), expected.value("stage", "")) << name;
    EXPECT_EQ(got.value("message", ""), expected.value("message", "")) << name;
  }
}

INSTANTIATE_TEST_SUITE_P(BoolSurfScenes,
  SceneRegression,
  ::testing::ValuesIn(SceneNames()),
  [](const ::testing::TestParamInfo<std::string>& info)
  {
    std::string id;
    for (char c : info.param)
    {
      id += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    }
    return id;
  });

// Every scene file of the collection has an entry (run, recorded error, or a skip reason).
TEST(SceneRegressionCoverage, EverySceneHasExpectations)
{
  if (ScenesDir().empty() || !fs::is_directory(ScenesDir()))
  {
    GTEST_SKIP() << "BOOLSURF_SHARED_DATA is not set or has no boolsurf-scenes/";
  }
  const json expectations = Expectations();
  int count = 0;
  for (const auto& entry : fs::recursive_directory_iterator(ScenesDir()))
  {
    if (entry.is_regular_file() && entry.path().extension() == ".json")
    {
      const std::string name = fs::relative(entry.path(), ScenesDir()).generic_string();
      EXPECT_TRUE(expectations.contains(name)) << name << " is missing from " << ExpectationsFile();
      ++count;
    }
  }
  EXPECT_GT(count, 50);
}
} // namespace
