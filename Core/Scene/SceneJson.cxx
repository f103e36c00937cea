#include "Scene/SceneJson.h"

#include "Scene/JsonNestingDepth.h"
#include "Scene/SceneError.h"
#include "Scene/ScenePlacement.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <istream>
#include <iterator>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace boolsurf
{
namespace
{
// Objects keep their keys in document order (NumberSpellings counts numbers in that order).
using json = nlohmann::ordered_json;

std::string Where(const std::string& key, std::size_t index)
{
  return "'" + key + "'[" + std::to_string(index) + "]";
}

/// How the floating-point numbers of the scene being read were spelled in the file, so that
/// messages quote "1e20" as written and not as nlohmann re-prints it ("1e+20").
struct NumberSpellings
{
  const json* Root = nullptr;
  std::vector<std::string> Lexemes; ///< in document order
  /// Each floating-point node's place in document order, built on the first message that
  /// needs it (objects keep their keys in document order: `json` is nlohmann::ordered_json).
  std::unordered_map<const json*, std::size_t> Order;
  bool Ordered = false;

  const std::string* Of(const json& node)
  {
    if (!this->Ordered)
    {
      this->Ordered = true;
      std::vector<const json*> stack{ this->Root };
      while (!stack.empty())
      {
        const json* n = stack.back();
        stack.pop_back();
        if (n->is_number_float())
        {
          this->Order.emplace(n, this->Order.size());
        }
        else if (n->is_structured())
        {
          for (auto it = n->crbegin(); it != n->crend(); ++it)
          {
            stack.push_back(&*it);
          }
        }
      }
      // A key given twice keeps one value: the places no longer match the lexemes.
      if (this->Order.size() != this->Lexemes.size())
      {
        this->Order.clear();
      }
    }
    auto it = this->Order.find(&node);
    return it == this->Order.end() ? nullptr : &this->Lexemes[it->second];
  }
};

/// nlohmann's DOM builder that also keeps each floating-point number's lexeme.
class SpellingDomParser : public nlohmann::detail::json_sax_dom_parser<json>
{
public:
  SpellingDomParser(json& root, std::vector<std::string>& lexemes)
    : json_sax_dom_parser(root)
    , Lexemes(lexemes)
  {
  }
  bool number_float(double value, const std::string& lexeme)
  {
    this->Lexemes.push_back(lexeme);
    return json_sax_dom_parser::number_float(value, lexeme);
  }

private:
  std::vector<std::string>& Lexemes;
};

/// Throws when `text` nests arrays and objects deeper than MaxSceneNestingDepth, naming where.
void RefuseDeepNesting(const std::string& text)
{
  const auto excess = FindJsonNestingBeyond(text, MaxSceneNestingDepth);
  if (!excess)
  {
    return;
  }
  std::string where =
    "line " + std::to_string(excess->Line) + ", column " + std::to_string(excess->Column);
  if (!excess->TopLevelKey.empty())
  {
    where += " (in '" + excess->TopLevelKey + "')";
  }
  throw SceneError(std::string("nesting too deep: ") +
    (excess->Bracket == '[' ? "an array" : "an object") + " at " + where + " is " +
    std::to_string(excess->Depth) +
    " levels deep; scene files may nest arrays and objects at most " +
    std::to_string(MaxSceneNestingDepth) + " levels");
}

/// Whether a JSON text is an object with a given key at its top level, read as events without
/// building any value (so at any depth).
class TopLevelKeyFinder : public nlohmann::json_sax<json>
{
public:
  explicit TopLevelKeyFinder(const char* key)
    : Key(key)
  {
  }
  bool IsObjectWithKey() const { return this->TopLevelIsObject && this->Found; }

  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return this->Open(true); }
  bool start_array(std::size_t) override { return this->Open(false); }
  bool end_object() override { return this->Close(); }
  bool end_array() override { return this->Close(); }
  bool key(string_t& name) override
  {
    this->Found = this->Found || (this->Depth == 1 && name == this->Key);
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override
  {
    return false;
  }

private:
  bool Open(bool object)
  {
    this->TopLevelIsObject = this->Depth++ == 0 ? object : this->TopLevelIsObject;
    return true;
  }
  bool Close()
  {
    --this->Depth;
    return true;
  }

  std::string Key;
  long long Depth = 0;
  bool TopLevelIsObject = false;
  bool Found = false;
};

/// One file being read: its document, the spellings of its numbers, and the checks.
class SceneParser
{
public:
  explicit SceneParser(std::istream& in)
  {
    this->Spellings.Root = &this->Root;
    const std::string text{ std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>() };
    RefuseDeepNesting(text);
    try
    {
      SpellingDomParser parser(this->Root, this->Spellings.Lexemes);
      json::sax_parse(text, &parser);
    }
    catch (const json::parse_error& e)
    {
      throw SceneError(std::string("bad JSON: ") + e.what());
    }
  }
  SceneParser(const SceneParser&) = delete;
  SceneParser& operator=(const SceneParser&) = delete;

  const json& GetRoot() const { return this->Root; }

  void ReadSurfaceScene(const SceneParseOptions& options, SceneModel& out);
  void ReadScreenSpace(SceneModel& out);
  void ReadOperations(SceneModel& out);

private:
  void AppendAsWritten(const json& value, std::string& text);
  std::string Brief(const json& value);
  long long AsIndex(const json& value, const std::string& where);
  std::vector<bool> ClosedFlags(std::size_t polygons);
  std::vector<int> CurveTypes(std::size_t polygons);
  std::vector<int> PolygonShapes(std::size_t polygons, int& numberOfShapes);

  json Root;
  NumberSpellings Spellings;
};

const json& Required(const json& object, const char* key, const std::string& where)
{
  auto it = object.find(key);
  if (it == object.end())
  {
    throw SceneError(where + " has no key '" + key + "'");
  }
  return *it;
}

//------------------------------------------------------------------------------
/// `value` as JSON text, numbers as spelled in the file; `value` is known to be small and
/// shallow (Brief checks), so recursion is bounded.
void SceneParser::AppendAsWritten(const json& value, std::string& text)
{
  if (value.is_number_float())
  {
    if (const std::string* lexeme = this->Spellings.Of(value))
    {
      text += *lexeme;
      return;
    }
  }
  if (value.is_array() || value.is_object())
  {
    text += value.is_array() ? '[' : '{';
    bool first = true;
    for (auto it = value.begin(); it != value.end(); ++it)
    {
      text += first ? "" : ",";
      first = false;
      if (value.is_object())
      {
        text += json(it.key()).dump(-1, ' ', false, json::error_handler_t::replace) + ":";
      }
      this->AppendAsWritten(*it, text);
    }
    text += value.is_array() ? ']' : '}';
    return;
  }
  text += value.dump(-1, ' ', false, json::error_handler_t::replace);
}

//------------------------------------------------------------------------------
/// A JSON value for a message: as written when small and shallow; else described by its kind
/// and size (dump() recurses once per nesting level: a value nested 10^5 deep would overflow
/// the stack).
std::string SceneParser::Brief(const json& value)
{
  // Walk at most a few hundred nodes, without recursion, to bound depth and size.
  std::vector<std::pair<const json*, int>> stack{ { &value, 0 } };
  int visited = 0;
  bool small = true;
  while (!stack.empty() && small)
  {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    if (++visited > 200 || depth > 8)
    {
      small = false;
      break;
    }
    if (node->is_structured())
    {
      for (const json& child : *node)
      {
        stack.emplace_back(&child, depth + 1);
      }
    }
  }
  if (small)
  {
    std::string text;
    this->AppendAsWritten(value, text);
    if (text.size() <= 120)
    {
      return text;
    }
  }
  if (value.is_array())
  {
    return "an array of " + std::to_string(value.size()) + " item(s)";
  }
  if (value.is_object())
  {
    return "an object with " + std::to_string(value.size()) + " key(s)";
  }
  return value.dump(-1, ' ', false, json::error_handler_t::replace).substr(0, 117) + "...";
}

//------------------------------------------------------------------------------
/// An integer in [0, INT_MAX] (accepting integral floating-point values); anything else is an
/// error showing the value as written (never wrapped or truncated to an int).
long long SceneParser::AsIndex(const json& value, const std::string& where)
{
  if (value.is_number_unsigned() && value.get<unsigned long long>() <= INT_MAX)
  {
    return value.get<long long>();
  }
  if (value.is_number_integer() && !value.is_number_unsigned())
  {
    const long long v = value.get<long long>();
    if (v >= 0 && v <= INT_MAX)
    {
      return v;
    }
  }
  if (value.is_number_float())
  {
    const double d = value.get<double>();
    if (std::isfinite(d) && std::floor(d) == d && d >= 0 && d <= INT_MAX)
    {
      return static_cast<long long>(d);
    }
  }
  throw SceneError(where + " is " + this->Brief(value) + ", not an integer in [0, " +
    std::to_string(INT_MAX) + "]");
}

//------------------------------------------------------------------------------
/// `are_closed` as one flag per polygon (default true).
std::vector<bool> SceneParser::ClosedFlags(std::size_t polygons)
{
  std::vector<bool> closed(polygons, true);
  auto it = this->Root.find("are_closed");
  if (it == this->Root.end() || it->is_null())
  {
    return closed;
  }
  if (!it->is_array())
  {
    throw SceneError("'are_closed' is not an array");
  }
  for (std::size_t i = 0; i < it->size() && i < polygons; ++i)
  {
    const json& c = (*it)[i];
    if (c.is_boolean())
    {
      closed[i] = c.get<bool>();
    }
    else if (c.is_number())
    {
      closed[i] = c.get<double>() != 0;
    }
    else
    {
      throw SceneError(Where("are_closed", i) + " is " + this->Brief(c) + ", not a bool");
    }
  }
  return closed;
}

//------------------------------------------------------------------------------
/// `curve_types` (a key of ours, written for Bezier curves): one type per polygon, 0 geodesic
/// polygon (the default) or 1 cubic Bezier spline.
std::vector<int> SceneParser::CurveTypes(std::size_t polygons)
{
  std::vector<int> types(polygons, 0);
  auto it = this->Root.find("curve_types");
  if (it == this->Root.end() || it->is_null())
  {
    return types;
  }
  if (!it->is_array())
  {
    throw SceneError("'curve_types' is not an array");
  }
  for (std::size_t i = 0; i < it->size() && i < polygons; ++i)
  {
    const long long t = this->AsIndex((*it)[i], Where("curve_types", i));
    if (t > 1)
    {
      throw SceneError(Where("curve_types", i) + " is " + this->Brief((*it)[i]) +
        ": 0 geodesic polygon, 1 cubic Bezier spline");
    }
    types[i] = static_cast<int>(t);
  }
  return types;
}

//------------------------------------------------------------------------------
/// Scene shape id of every polygon (-1 for none yet), from `shapes`.
std::vector<int> SceneParser::PolygonShapes(std::size_t polygons, int& numberOfShapes)
{
  std::vector<int> shapeOf(polygons, -1);
  auto it = this->Root.find("shapes");
  if (it == this->Root.end() || it->is_null())
  {
    for (std::size_t i = 0; i < polygons; ++i)
    {
      shapeOf[i] = static_cast<int>(i);
    }
    numberOfShapes = static_cast<int>(polygons);
    return shapeOf;
  }
  if (!it->is_array())
  {
    throw SceneError("'shapes' is not an array");
  }
  numberOfShapes = static_cast<int>(it->size());
  for (std::size_t s = 0; s < it->size(); ++s)
  {
    const json& shape = (*it)[s];
    if (!shape.is_array())
    {
      throw SceneError(
        Where("shapes", s) + " is " + this->Brief(shape) + ", not a list of polygons");
    }
    for (std::size_t k = 0; k < shape.size(); ++k)
    {
      const std::string where = Where("shapes", s) + "[" + std::to_string(k) + "]";
      const long long p = this->AsIndex(shape[k], where);
      if (p < 0 || p >= static_cast<long long>(polygons))
      {
        throw SceneError(where + " names polygon " + this->Brief(shape[k]) +
          ", but the scene has " + std::to_string(polygons) + " polygons");
      }
      if (shapeOf[p] >= 0 && shapeOf[p] != static_cast<int>(s))
      {
        throw SceneError(where + ": polygon " + std::to_string(p) + " is already in shape " +
          std::to_string(shapeOf[p]));
      }
      shapeOf[p] = static_cast<int>(s);
    }
  }
  return shapeOf;
}

//------------------------------------------------------------------------------
void SceneParser::ReadOperations(SceneModel& out)
{
  auto it = this->Root.find("operations");
  if (it == this->Root.end() || it->is_null())
  {
    return;
  }
  if (!it->is_array())
  {
    throw SceneError("'operations' is not an array");
  }
  std::vector<SceneOperation> operations;
  for (std::size_t i = 0; i < it->size(); ++i)
  {
    const json& op = (*it)[i];
    const std::string where = Where("operations", i);
    if (!op.is_object())
    {
      throw SceneError(where + " is " + this->Brief(op) + ", not an object {a, b, type}");
    }
    SceneOperation o;
    o.A = static_cast<int>(this->AsIndex(Required(op, "a", where), where + ".a"));
    o.B = static_cast<int>(this->AsIndex(Required(op, "b", where), where + ".b"));
    const json& typeValue = Required(op, "type", where);
    const long long t = this->AsIndex(typeValue, where + ".type");
    if (t < 0 || t > 3)
    {
      throw SceneError(where + ".type is " + this->Brief(typeValue) +
        ": 0 union, 1 difference, 2 intersection, 3 symmetric difference");
    }
    o.Type = static_cast<int>(t);
    operations.push_back(o);
  }
  out.Operations = std::move(operations);
}

//------------------------------------------------------------------------------
/// The screen-space scenes: 2D polylines, checked and kept as written.
void SceneParser::ReadScreenSpace(SceneModel& out)
{
  out.ScreenSpace = true;
  const json& polygons = Required(this->Root, "polygons", "the scene");
  if (!polygons.is_array())
  {
    throw SceneError("'polygons' is not an array");
  }
  std::vector<std::vector<Vec2>> polylines(polygons.size());
  for (std::size_t i = 0; i < polygons.size(); ++i)
  {
    const json& poly = polygons[i];
    if (!poly.is_array())
    {
      throw SceneError(Where("polygons", i) + " is not a list of [x, y] points");
    }
    for (std::size_t k = 0; k < poly.size(); ++k)
    {
      const json& p = poly[k];
      const std::string where = Where("polygons", i) + "[" + std::to_string(k) + "]";
      if (!p.is_array() || p.size() < 2 || !p[0].is_number() || !p[1].is_number())
      {
        throw SceneError(where + " is " + this->Brief(p) + ", not an [x, y] point");
      }
      const Vec2 xy = { p[0].get<double>(), p[1].get<double>() };
      if (!std::isfinite(xy.x) || !std::isfinite(xy.y))
      {
        throw SceneError(where + " is not finite");
      }
      polylines[i].push_back(xy);
    }
  }
  const std::vector<bool> closed = this->ClosedFlags(polygons.size());
  const std::vector<int> shapeOf = this->PolygonShapes(polygons.size(), out.NumberOfShapes);
  out.NumberOfPolygons = static_cast<int>(polygons.size());
  for (std::size_t i = 0; i < polylines.size(); ++i)
  {
    if (!polylines[i].empty())
    {
      ScenePolygon polygon;
      polygon.Index = static_cast<int>(i);
      polygon.Closed = closed[i];
      polygon.Polyline = std::move(polylines[i]);
      out.Polygons.push_back(std::move(polygon));
    }
  }
  ScreenSpaceFrame frame; // all points the same: an error before any other
  std::string error;
  if (!FitScreenSpace(out.Polygons, frame, error))
  {
    throw SceneError(error);
  }
  int nextShape = out.NumberOfShapes;
  for (ScenePolygon& polygon : out.Polygons)
  {
    if (polygon.Polyline.size() < 2)
    {
      throw SceneError(
        Where("polygons", polygon.Index) + " has a single point; a curve needs at least 2");
    }
    const int shape = shapeOf[polygon.Index];
    polygon.Shape = shape >= 0 ? shape : nextShape++;
  }
  if (out.Polygons.empty())
  {
    throw SceneError("'polygons' are all empty: the scene has no curve");
  }
}

//------------------------------------------------------------------------------
void SceneParser::ReadSurfaceScene(const SceneParseOptions& options, SceneModel& out)
{
  const json& polygons = Required(this->Root, "polygons", "the scene");
  if (!polygons.is_array())
  {
    throw SceneError("'polygons' is not an array");
  }
  const json& points = Required(this->Root, "points", "the scene");
  if (!points.is_array())
  {
    throw SceneError("'points' is not an array");
  }
  if (options.ReadModel)
  {
    const json& m = Required(this->Root, "model", "the scene (and MeshFileName is not set)");
    if (!m.is_string())
    {
      throw SceneError("'model' is " + this->Brief(m) + ", not a file name");
    }
    out.Model = m.get<std::string>();
  }
  const std::vector<bool> closed = this->ClosedFlags(polygons.size());
  const std::vector<int> types = this->CurveTypes(polygons.size());
  const std::vector<int> shapeOf = this->PolygonShapes(polygons.size(), out.NumberOfShapes);
  out.NumberOfPolygons = static_cast<int>(polygons.size());

  // The curve structure, checked before a possibly big mesh is read.
  for (std::size_t i = 0; i < polygons.size(); ++i)
  {
    const json& poly = polygons[i];
    if (!poly.is_array())
    {
      throw SceneError(
        Where("polygons", i) + " is " + this->Brief(poly) + ", not a list of points");
    }
    if (poly.size() == 1)
    {
      // A one-point polygon bounds nothing: skipped, as the authors' tool does.
      out.Notes.push_back(Where("polygons", i) + " has a single point (" + this->Brief(poly[0]) +
        "): skipped, a curve needs at least 2");
    }
    for (std::size_t k = 0; k < poly.size(); ++k)
    {
      const std::string where = Where("polygons", i) + "[" + std::to_string(k) + "]";
      const long long p = this->AsIndex(poly[k], where);
      if (p < 0 || p >= static_cast<long long>(points.size()))
      {
        throw SceneError(where + " names point " + this->Brief(poly[k]) + ", but the scene has " +
          std::to_string(points.size()) + " points");
      }
    }
  }

  std::optional<SceneMeshInfo> mesh;
  if (options.FindMesh)
  {
    SceneMeshInfo found;
    std::string error;
    if (!options.FindMesh(out, found, error))
    {
      throw SceneError(error);
    }
    mesh = found;
  }

  out.Points.reserve(points.size());
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    const json& p = points[k];
    const std::string where = Where("points", k);
    if (!p.is_object())
    {
      throw SceneError(where + " is " + this->Brief(p) + ", not {\"face\": f, \"uv\": [u, v]}");
    }
    ScenePoint point;
    const json& faceValue = Required(p, "face", where);
    point.Face = this->AsIndex(faceValue, where + ".face");
    point.FaceText = this->Brief(faceValue);
    if (mesh && point.Face >= mesh->NumberOfTriangles)
    {
      throw SceneError(
        FaceOutOfRangeMessage(k, point.FaceText, mesh->Name, mesh->NumberOfTriangles));
    }
    const json& uv = Required(p, "uv", where);
    if (!uv.is_array() || uv.size() != 2 || !uv[0].is_number() || !uv[1].is_number())
    {
      throw SceneError(where + ".uv is " + this->Brief(uv) + ", not two numbers [u, v]");
    }
    point.U = uv[0].get<double>();
    point.V = uv[1].get<double>();
    point.UVText = this->Brief(uv);
    const double u = point.U, v = point.V;
    if (!IsInsideTriangle(u, v))
    {
      throw SceneError(where + ".uv = " + point.UVText +
        " is outside the triangle (needs u >= 0, v >= 0, u + v <= 1)");
    }
    out.Points.push_back(std::move(point));
  }

  int nextShape = out.NumberOfShapes;
  for (std::size_t i = 0; i < polygons.size(); ++i)
  {
    const json& poly = polygons[i];
    if (poly.size() < 2)
    {
      // Polygon 0 is reserved by BoolSurf; its editor also leaves trailing empty ones; one-point
      // polygons were named in a note above.
      continue;
    }
    ScenePolygon polygon;
    polygon.Index = static_cast<int>(i);
    for (const json& p : poly)
    {
      polygon.Points.push_back(static_cast<int>(this->AsIndex(p, "")));
    }
    polygon.Closed = closed[i];
    polygon.CurveType = types[i];
    polygon.Shape = shapeOf[i] >= 0 ? shapeOf[i] : nextShape++;
    out.Polygons.push_back(std::move(polygon));
  }
  if (out.Polygons.empty())
  {
    throw SceneError("'polygons' are all empty: the scene has no curve");
  }
}

/// ParseSceneJson, throwing SceneError.
SceneModel ParseScene(std::istream& in, const SceneParseOptions& options)
{
  SceneParser parser(in);
  const json& root = parser.GetRoot();
  if (!root.is_object())
  {
    throw SceneError("the top level is not a JSON object");
  }
  SceneModel scene;
  auto ss = root.find("screenspace");
  if (ss != root.end() && ss->is_boolean() && ss->get<bool>())
  {
    parser.ReadScreenSpace(scene);
  }
  else
  {
    parser.ReadSurfaceScene(options, scene);
  }
  parser.ReadOperations(scene);
  return scene;
}
} // namespace

//------------------------------------------------------------------------------
bool ParseSceneJson(std::istream& in,
  SceneModel& scene,
  std::string& error,
  const SceneParseOptions& options)
{
  try
  {
    scene = ParseScene(in, options);
    return true;
  }
  catch (const SceneError& e)
  {
    error = e.what();
    return false;
  }
}

//------------------------------------------------------------------------------
bool LooksLikeSceneJson(std::istream& in)
{
  try
  {
    TopLevelKeyFinder finder("polygons");
    return json::sax_parse(in, &finder) && finder.IsObjectWithKey();
  }
  catch (const std::exception&)
  {
    return false; // the stream failed
  }
}

//------------------------------------------------------------------------------
std::string EmitSceneJson(const SceneModel& scene, int indent)
{
  // Keys in alphabetical order (nlohmann::json sorts them), as scenes have always been written.
  using sorted_json = nlohmann::json;
  int numberOfPolygons = std::max(scene.NumberOfPolygons, 0);
  int numberOfShapes = std::max(scene.NumberOfShapes, 0);
  bool bezier = false;
  for (const ScenePolygon& polygon : scene.Polygons)
  {
    numberOfPolygons = std::max(numberOfPolygons, polygon.Index + 1);
    numberOfShapes = std::max(numberOfShapes, polygon.Shape + 1);
    bezier = bezier || polygon.CurveType == 1;
  }
  sorted_json polygons(numberOfPolygons, sorted_json::array());
  sorted_json closed(numberOfPolygons, true);
  sorted_json types(numberOfPolygons, 0);
  sorted_json shapes(numberOfShapes, sorted_json::array());
  for (const ScenePolygon& polygon : scene.Polygons)
  {
    const int p = polygon.Index;
    if (scene.ScreenSpace)
    {
      for (const Vec2& xy : polygon.Polyline)
      {
        polygons[p].push_back({ xy.x, xy.y });
      }
    }
    else
    {
      for (int id : polygon.Points)
      {
        polygons[p].push_back(static_cast<long long>(id));
      }
    }
    closed[p] = polygon.Closed;
    types[p] = polygon.CurveType;
    shapes[polygon.Shape].push_back(p);
  }
  sorted_json out;
  if (!scene.ScreenSpace || !scene.Model.empty())
  {
    out["model"] = scene.Model;
  }
  if (scene.ScreenSpace)
  {
    out["screenspace"] = true;
  }
  else
  {
    sorted_json points = sorted_json::array();
    for (const ScenePoint& p : scene.Points)
    {
      points.push_back({ { "face", p.Face }, { "uv", { p.U, p.V } } });
    }
    out["points"] = std::move(points);
  }
  out["polygons"] = std::move(polygons);
  out["are_closed"] = std::move(closed);
  out["shapes"] = std::move(shapes);
  if (bezier)
  {
    out["curve_types"] = std::move(types);
  }
  if (scene.Operations)
  {
    sorted_json operations = sorted_json::array();
    for (const SceneOperation& o : *scene.Operations)
    {
      operations.push_back({ { "a", o.A }, { "b", o.B }, { "type", o.Type } });
    }
    out["operations"] = std::move(operations);
  }
  return out.dump(indent) + "\n";
}

} // namespace boolsurf
