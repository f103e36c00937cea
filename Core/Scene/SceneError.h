// The exception Scene's readers throw among themselves. Not part of Core's interface: only
// Scene's .cxx files include it, and every public Scene function catches it and returns false
// with its message (Docs/Decisions.md, "One error style").
#ifndef boolsurf_SceneError_h
#define boolsurf_SceneError_h

#include <stdexcept>

namespace boolsurf
{

/// A problem with a scene, already worded for the user (the caller names the file).
struct SceneError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

} // namespace boolsurf

#endif
