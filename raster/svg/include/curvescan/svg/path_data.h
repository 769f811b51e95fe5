// SVG path data (the `d` attribute; SVG 1.1 section 8.3 and its grammar in 8.3.9) appended to a
// PathBuilder.
//
// Every command is supported, absolute (upper case) and relative (lower case): M L H V C S Q T A Z, with
// implicit repeats (extra coordinate groups repeat the command; after a moveto they are linetos), the
// compact number forms of number.h ("M1.5.5", "1-2"), and arc flags written without separators
// ("a1 1 0 00 1 1": a flag is exactly one character, '0' or '1'). S and T reflect the previous command's
// last control point only when that command was C/S (resp. Q/T), else use the current point (8.3.6/8.3.7).
// Arcs go through PathBuilder::svg_arc_to, which follows appendix F.6 (zero radius: a line; same end
// point: nothing; radii too small: scaled up).
//
// Errors (SVG 1.1 appendix F.2 "Error processing" and SVG 2 section 9.5.4): the path is rendered up to,
// but not including, the command segment in which the first error occurs; the error is reported so that
// the caller can warn. A coordinate that overflows to infinity (a relative coordinate added to a huge
// current point) counts as an error at that segment, so the builder only ever sees finite values.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "curvescan/raster/path_builder.h"

namespace curvescan::svg {

struct PathDataError {
  std::size_t offset = 0;  ///< byte offset in the `d` text where parsing stopped
  std::string message;     ///< e.g. "path data: expected a number at offset 12"
};

/// Appends the commands of `data` to `builder` up to the first error, which is returned (nullopt when the
/// whole text is valid). An empty or all-whitespace `data` is valid and draws nothing (SVG 2 9.5.4).
[[nodiscard]] std::optional<PathDataError> append_path_data(std::string_view data, PathBuilder& builder);

}  // namespace curvescan::svg
