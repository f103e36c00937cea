#include "Geodesic/GeodesicPathOptions.h"

namespace boolsurf
{

//------------------------------------------------------------------------------
const char* GeodesicMethodName(GeodesicMethod method)
{
  switch (method)
  {
    case GeodesicMethod::Bounded:
      return "Bounded";
    case GeodesicMethod::Exact:
      return "Exact";
    case GeodesicMethod::LocallyShortest:
      return "LocallyShortest";
  }
  return "Unknown";
}

} // namespace boolsurf
