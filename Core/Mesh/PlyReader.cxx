#include "Mesh/PlyReader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

namespace boolsurf
{
namespace
{

enum class Format
{
  Ascii,
  BinaryLittle,
  BinaryBig
};

struct Property
{
  std::string Name;
  std::string Type;      // scalar type, or the index type of a list
  std::string CountType; // non-empty for lists
};

struct Element
{
  std::string Name;
  long long Count = 0;
  std::vector<Property> Properties;
};

int TypeSize(const std::string& t)
{
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8")
    return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16")
    return 2;
  if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" || t == "float32")
    return 4;
  if (t == "double" || t == "float64")
    return 8;
  return 0;
}

bool HostIsLittleEndian()
{
  const std::uint16_t one = 1;
  unsigned char b;
  std::memcpy(&b, &one, 1);
  return b == 1;
}

// Reads one binary scalar of type t and converts it to double.
bool ReadBinary(std::istream& in, const std::string& t, bool swap, double& value)
{
  unsigned char buf[8];
  const int n = TypeSize(t);
  if (n == 0 || !in.read(reinterpret_cast<char*>(buf), n))
    return false;
  if (swap)
  {
    for (int i = 0; i < n / 2; ++i)
      std::swap(buf[i], buf[n - 1 - i]);
  }
  if (t == "char" || t == "int8")
    value = static_cast<std::int8_t>(buf[0]);
  else if (t == "uchar" || t == "uint8")
    value = buf[0];
  else if (t == "short" || t == "int16")
  {
    std::int16_t x;
    std::memcpy(&x, buf, 2);
    value = x;
  }
  else if (t == "ushort" || t == "uint16")
  {
    std::uint16_t x;
    std::memcpy(&x, buf, 2);
    value = x;
  }
  else if (t == "int" || t == "int32")
  {
    std::int32_t x;
    std::memcpy(&x, buf, 4);
    value = x;
  }
  else if (t == "uint" || t == "uint32")
  {
    std::uint32_t x;
    std::memcpy(&x, buf, 4);
    value = x;
  }
  else if (t == "float" || t == "float32")
  {
    float x;
    std::memcpy(&x, buf, 4);
    value = x;
  }
  else
  {
    double x;
    std::memcpy(&x, buf, 8);
    value = x;
  }
  return true;
}

//------------------------------------------------------------------------------
// The header: the format and the elements with their properties (only header lines; the
// stream is left at the body).
bool ReadHeader(std::istream& in,
  const std::string& path,
  Format& format,
  std::vector<Element>& elements,
  std::string& error)
{
  std::string line;
  std::getline(in, line);
  if (!line.empty() && line.back() == '\r')
    line.pop_back();
  if (line != "ply")
  {
    error = "'" + path + "' is not a PLY file (no 'ply' magic line)";
    return false;
  }
  bool formatSeen = false;
  while (std::getline(in, line))
  {
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    // Only the header lines of the PLY format: vtkPLYReader reads other lines its own way and
    // crashed on a header that this reader had skipped line by line (a fuzzed scene mesh).
    if (!keyword.empty() && keyword != "format" && keyword != "element" && keyword != "property" &&
      keyword != "comment" && keyword != "obj_info" && keyword != "end_header")
    {
      error = "'" + path + "': not a PLY header line: '" + line.substr(0, 80) + "'";
      return false;
    }
    if (keyword == "format")
    {
      std::string f, version;
      words >> f >> version;
      if (f != "ascii" && f != "binary_little_endian" && f != "binary_big_endian")
      {
        error = "'" + path + "': unknown format '" + f + "'";
        return false;
      }
      if (formatSeen || version != "1.0")
      {
        error = "'" + path + "': bad format line '" + line.substr(0, 80) + "'";
        return false;
      }
      formatSeen = true;
      format = f == "ascii" ? Format::Ascii
                            : (f == "binary_big_endian" ? Format::BinaryBig : Format::BinaryLittle);
    }
    else if (keyword == "element")
    {
      Element e;
      if (!(words >> e.Name >> e.Count) || e.Count < 0)
      {
        error = "'" + path + "': bad element line '" + line + "'";
        return false;
      }
      elements.push_back(e);
    }
    else if (keyword == "property")
    {
      // A property belongs to the element above it: one before any element, or without a
      // name, is not a PLY header (vtkPLYReader crashes on both).
      if (elements.empty())
      {
        error = "'" + path + "': property line before any element: '" + line + "'";
        return false;
      }
      Property p;
      std::string type;
      words >> type;
      if (type == "list")
      {
        words >> p.CountType >> p.Type >> p.Name;
      }
      else
      {
        p.Type = type;
        words >> p.Name;
      }
      if (TypeSize(p.Type) == 0 || (!p.CountType.empty() && TypeSize(p.CountType) == 0))
      {
        error = "'" + path + "': unknown property type in '" + line + "'";
        return false;
      }
      if (p.Name.empty())
      {
        error = "'" + path + "': property without a name: '" + line + "'";
        return false;
      }
      elements.back().Properties.push_back(p);
    }
    else if (keyword == "end_header")
    {
      break;
    }
  }
  if (!in)
  {
    error = "'" + path + "': no end_header line";
    return false;
  }
  if (!formatSeen)
  {
    error = "'" + path + "': no format line";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// The file must hold at least the fixed-size part of every element (in ascii, a digit and a
// separator per value): checked up front, so a header announcing billions of elements fails
// at once instead of looping or allocating for them.
bool CheckBodySize(std::istream& in,
  const std::string& path,
  Format format,
  const std::vector<Element>& elements,
  std::string& error)
{
  const std::streampos body = in.tellg();
  in.seekg(0, std::ios::end);
  const long double remaining = static_cast<long double>(in.tellg() - body);
  in.seekg(body);
  long double needed = 0;
  for (const Element& e : elements)
  {
    long double size = 0;
    for (const Property& prop : e.Properties)
    {
      size +=
        format == Format::Ascii ? 2 : TypeSize(prop.CountType.empty() ? prop.Type : prop.CountType);
    }
    needed += size * e.Count;
  }
  // The last ascii value may end the file without a separator.
  if (needed > remaining + (format == Format::Ascii ? 1 : 0))
  {
    error = "'" + path + "': truncated (the header announces more data than the file holds)";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// The elements a triangle mesh needs, with the properties read from them; `vertexCount` is
// the number of vertices announced.
bool CheckElements(const std::string& path,
  const std::vector<Element>& elements,
  long long& vertexCount,
  std::string& error)
{
  // A triangle mesh has both (vtkPLYReader, run next by the scene reader, crashes without them).
  for (const char* required : { "vertex", "face" })
  {
    if (std::none_of(elements.begin(),
          elements.end(),
          [required](const Element& e) { return e.Name == required; }))
    {
      error = "'" + path + "': no element '" + required + "'";
      return false;
    }
  }
  vertexCount = 0;
  for (const Element& e : elements)
  {
    if (e.Name == "face" &&
      std::none_of(e.Properties.begin(),
        e.Properties.end(),
        [](const Property& p) {
          return !p.CountType.empty() && (p.Name == "vertex_indices" || p.Name == "vertex_index");
        }))
    {
      // Faces of no vertex list are not a mesh (and crash vtkPLYReader, which the scene reader
      // runs after this check), even zero of them: vtkPLYReader crashed on "element face 0"
      // whose property line was misspelt (the fuzz target found it).
      error = "'" + path + "': element 'face' has no list property vertex_indices";
      return false;
    }
    if (e.Name == "vertex")
    {
      vertexCount = e.Count;
      // Vertices without coordinates would be made up (and take no bytes of the file).
      for (const char* axis : { "x", "y", "z" })
      {
        if (std::none_of(e.Properties.begin(),
              e.Properties.end(),
              [axis](const Property& p) { return p.Name == axis && p.CountType.empty(); }))
        {
          error = "'" + path + "': element 'vertex' has no property " + axis;
          return false;
        }
      }
    }
  }
  if (vertexCount > std::numeric_limits<int>::max())
  {
    error = "'" + path + "': " + std::to_string(vertexCount) + " vertices, more than supported";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// The body: vertex coordinates and faces (fanned into triangles); other data skipped.
bool ReadBody(std::istream& in,
  const std::string& path,
  Format format,
  const std::vector<Element>& elements,
  long long vertexCount,
  MeshData& out,
  std::string& error)
{
  const bool swap = (format == Format::BinaryBig) == HostIsLittleEndian();
  auto readValue = [&](const std::string& type, double& v) -> bool
  {
    if (format == Format::Ascii)
      return static_cast<bool>(in >> v);
    return ReadBinary(in, type, swap, v);
  };
  for (const Element& e : elements)
  {
    if (e.Properties.empty())
    {
      continue; // no data to read, however many it announces
    }
    for (long long i = 0; i < e.Count; ++i)
    {
      Vec3 p;
      for (const Property& prop : e.Properties)
      {
        if (!prop.CountType.empty())
        {
          double count = 0;
          if (!readValue(prop.CountType, count))
          {
            error =
              "'" + path + "': truncated list in element '" + e.Name + "' " + std::to_string(i);
            return false;
          }
          // Lists longer than this are garbage, not polygons.
          if (!(count >= 0 && count <= 65536) || count != std::floor(count))
          {
            error = "'" + path + "': element '" + e.Name + "' " + std::to_string(i) +
              " has a list of " + std::to_string(count) + " items";
            return false;
          }
          std::vector<int> ids(static_cast<size_t>(count));
          const bool isFace =
            e.Name == "face" && (prop.Name == "vertex_indices" || prop.Name == "vertex_index");
          for (int& id : ids)
          {
            double v = 0;
            if (!readValue(prop.Type, v))
            {
              error = "'" + path + "': truncated face " + std::to_string(i);
              return false;
            }
            if (isFace && !(v >= 0 && v < static_cast<double>(vertexCount)))
            {
              error = "'" + path + "': face " + std::to_string(i) + " uses vertex index " +
                std::to_string(static_cast<long long>(std::max(-1e18, std::min(1e18, v)))) +
                ", outside [0, " + std::to_string(vertexCount) + ")";
              return false;
            }
            // Only face indices are kept (and were checked to fit); other lists are skipped.
            id = isFace ? static_cast<int>(v) : 0;
          }
          if (isFace)
          {
            for (size_t k = 2; k < ids.size(); ++k)
              out.Triangles.push_back({ ids[0], ids[k - 1], ids[k] });
          }
          continue;
        }
        double v = 0;
        if (!readValue(prop.Type, v))
        {
          error = "'" + path + "': truncated element '" + e.Name + "' " + std::to_string(i);
          return false;
        }
        if (e.Name == "vertex")
        {
          if (prop.Name == "x")
            p.x = v;
          else if (prop.Name == "y")
            p.y = v;
          else if (prop.Name == "z")
            p.z = v;
        }
      }
      if (e.Name == "vertex")
        out.Positions.push_back(p);
    }
  }
  return true;
}

} // namespace

//------------------------------------------------------------------------------
bool ReadPly(const std::string& path, MeshData& out, std::string& error)
{
  out = MeshData();
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    error = "cannot open PLY file '" + path + "'";
    return false;
  }
  Format format = Format::Ascii;
  std::vector<Element> elements;
  long long vertexCount = 0;
  return ReadHeader(in, path, format, elements, error) &&
    CheckBodySize(in, path, format, elements, error) &&
    CheckElements(path, elements, vertexCount, error) &&
    ReadBody(in, path, format, elements, vertexCount, out, error);
}

} // namespace boolsurf
