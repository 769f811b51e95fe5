// How many points each verb of a Path stores after its start (path.h "Storage"), shared by the Path's
// iterator (path.cpp) and the edge walk that reads the flat arrays directly (path_edges.cpp).
#pragma once

#include <cstddef>

#include "curvescan/raster/path.h"

namespace curvescan::detail {

/// Points a verb of fixed size appends after its start; 0 for kClose, and for kBezier and
/// kRationalBezier, whose count (their degree) the Path stores separately.
[[nodiscard]] inline std::size_t fixed_point_count(PathVerb verb) noexcept {
  switch (verb) {
    case PathVerb::kMove:
    case PathVerb::kLine:
      return 1;
    case PathVerb::kQuad:
    case PathVerb::kConic:
      return 2;
    case PathVerb::kCubic:
      return 3;
    case PathVerb::kBezier:
    case PathVerb::kRationalBezier:
    case PathVerb::kClose:
      return 0;
  }
  return 0;
}

}  // namespace curvescan::detail
