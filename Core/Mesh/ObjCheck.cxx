#include "Mesh/ObjCheck.h"

#include <array>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace boolsurf
{

bool CheckObjIndices(const std::string& path, std::string& error)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    error = "cannot open OBJ file '" + path + "'";
    return false;
  }
  // Lines read so far of each kind an element may index: v, vt, vn.
  std::array<long long, 3> counts = { 0, 0, 0 };
  static const char* const kinds[3] = { "vertex", "texture coordinate", "normal" };
  std::string line;
  long long lineNumber = 0;
  while (std::getline(in, line))
  {
    ++lineNumber;
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back(); // Windows line ends
    }
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "v" || keyword == "vt" || keyword == "vn")
    {
      ++counts[keyword == "v" ? 0 : keyword == "vt" ? 1 : 2];
      continue;
    }
    if (keyword != "f" && keyword != "l" && keyword != "p")
    {
      continue;
    }
    std::string item;
    while (words >> item)
    {
      // v, v/vt, v//vn or v/vt/vn; an empty field is absent. A slash that ends the item
      // ("4/", "4/1/") announces a field that is not there: vtkOBJReader reads past it.
      if (item.back() == '/')
      {
        error = "'" + path + "' line " + std::to_string(lineNumber) + ": '" + item.substr(0, 24) +
          "' ends with '/' (write v, v/vt, v//vn or v/vt/vn)";
        return false;
      }
      std::size_t start = 0;
      for (int k = 0; k < 3 && start <= item.size(); ++k)
      {
        const std::size_t slash = item.find('/', start);
        const std::string field =
          item.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
        start = slash == std::string::npos ? item.size() + 1 : slash + 1;
        if (field.empty() && k > 0)
        {
          continue;
        }
        char* end = nullptr;
        errno = 0;
        const long long index = std::strtoll(field.c_str(), &end, 10);
        const long long resolved = index < 0 ? counts[k] + 1 + index : index;
        if (field.empty() || *end != '\0' || errno != 0 || resolved < 1 || resolved > counts[k])
        {
          error = "'" + path + "' line " + std::to_string(lineNumber) + ": '" + item + "' names " +
            kinds[k] + " " + field.substr(0, 24) + ", but " + std::to_string(counts[k]) + " " +
            kinds[k] + "(s) precede it";
          return false;
        }
      }
    }
  }
  return true;
}

} // namespace boolsurf
