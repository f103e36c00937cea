// The OBJ index check run before vtkOBJReader (which crashed on `f 4/5 3` without texture
// coordinates: found by fuzzing, Testing/Fuzz/Corpus/FuzzSceneReader/regression-obj-*).
#include "Mesh/ObjCheck.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace boolsurf;

namespace
{
std::string Check(const std::string& name, const std::string& text)
{
  const std::filesystem::path path =
    std::filesystem::temp_directory_path() / ("boolsurf-test-obj-" + name + ".obj");
  std::ofstream(path, std::ios::binary) << text;
  std::string error;
  const bool ok = CheckObjIndices(path.string(), error);
  std::filesystem::remove(path);
  return ok ? "ok" : error;
}

const std::string Square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
} // namespace

TEST(ObjCheck, ValidIndicesPass)
{
  EXPECT_EQ(Check("plain", Square + "f 1 2 3\nf 1 3 4\n"), "ok");
  EXPECT_EQ(Check("negative", Square + "f -4 -3 -2\n"), "ok");
  EXPECT_EQ(Check("full",
              Square + "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\nf 1/1/1 2/2/1 3/3/1\nf 1//1 3//1 4//1\n"),
    "ok");
  EXPECT_EQ(Check("lines", Square + "# comment\nl 1 2 3\np 4\nusemtl x\n"), "ok");
  EXPECT_EQ(Check("crlf", "v 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nf 1 2 3\r\n"), "ok");
}

TEST(ObjCheck, IndicesNamingNothingAreNamed)
{
  // The input that crashed vtkOBJReader: a texture coordinate index without any vt line.
  const std::string noTexture = Check("no-vt", Square + "f 1 2 3\nf 4/5 3\n");
  EXPECT_NE(noTexture.find("line 6: '4/5' names texture coordinate 5, but 0 texture "
                           "coordinate(s) precede it"),
    std::string::npos)
    << noTexture;
  EXPECT_NE(
    Check("far", Square + "f 1 2 9\n").find("names vertex 9, but 4 vertex(s)"), std::string::npos);
  EXPECT_NE(Check("zero", Square + "f 0 1 2\n").find("names vertex 0"), std::string::npos);
  EXPECT_NE(Check("back", Square + "f -5 1 2\n").find("names vertex -5"), std::string::npos);
  EXPECT_NE(Check("normal", Square + "vn 0 0 1\nf 1//2 2//1 3//1\n").find("names normal 2"),
    std::string::npos);
  EXPECT_NE(Check("text", Square + "f 1 2 x\n").find("names vertex x"), std::string::npos);
  EXPECT_NE(Check("huge", Square + "f 1 2 99999999999999999999999\n").find("names vertex 9999"),
    std::string::npos);
  // A trailing slash (found by the scene reader's fuzzer: vtkOBJReader crashed on `f 4/ 5 3`).
  EXPECT_NE(Check("slash", Square + "f 1 2 3\nf 4/ 1 3\n").find("line 6: '4/' ends with '/'"),
    std::string::npos);
  EXPECT_NE(Check("slashes", Square + "f 1/ 2/ 3/\n").find("ends with '/'"), std::string::npos);
  // A vertex is named only after its line.
  EXPECT_NE(Check("early", "f 1 2 3\n" + Square).find("line 1"), std::string::npos);
}
