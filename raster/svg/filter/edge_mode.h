// edgeMode (Filter Effects 1, feGaussianBlur and feConvolveMatrix): how a kernel reads pixels beyond the
// edge of its input. none reads transparent black, duplicate the nearest edge pixel, wrap the opposite
// side (the input taken as periodic).
#pragma once

#include <optional>
#include <string_view>

namespace curvescan::svg::detail::filter {

enum class EdgeMode { kNone, kDuplicate, kWrap };

/// "none" / "duplicate" / "wrap"; nullopt for anything else.
[[nodiscard]] inline std::optional<EdgeMode> parse_edge_mode(std::string_view text) noexcept {
  if (text == "none") return EdgeMode::kNone;
  if (text == "duplicate") return EdgeMode::kDuplicate;
  if (text == "wrap") return EdgeMode::kWrap;
  return std::nullopt;
}

}  // namespace curvescan::svg::detail::filter
