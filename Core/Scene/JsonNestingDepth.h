// How deep a JSON text nests arrays and objects, found by scanning its characters (strings
// skipped) before any parser builds a value from it.
//
// Why before: a JSON value nested 10^5 deep is parsed by nlohmann without recursion, but
// copying it recurses once per level (an ordered_json object copies its values when it grows),
// and so would any walk over it: a file from anywhere could overflow the stack. The scan is
// exact on valid JSON; on invalid JSON it counts the brackets outside strings, which is all a
// parser could have built before stopping at the error.
#ifndef boolsurf_JsonNestingDepth_h
#define boolsurf_JsonNestingDepth_h

#include <cstddef>
#include <optional>
#include <string>

namespace boolsurf
{

/// The first '[' or '{' of a JSON text that opens more than the allowed levels.
struct JsonNestingExcess
{
  int Depth = 0;          ///< its level (the top-level value is level 1)
  char Bracket = '[';     ///< '[' an array, '{' an object
  std::size_t Line = 1;   ///< 1-based, counting '\n'
  std::size_t Column = 1; ///< 1-based, in bytes
  /// The key of the top-level object whose value holds it, as written between the quotes
  /// (escapes kept, cut to 40 bytes); empty when the top level is not an object.
  std::string TopLevelKey;
};

/// Where `text` first nests arrays and objects deeper than `maxDepth` levels; none when it
/// never does.
std::optional<JsonNestingExcess> FindJsonNestingBeyond(const std::string& text, int maxDepth);

} // namespace boolsurf

#endif
