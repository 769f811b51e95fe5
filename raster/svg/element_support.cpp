// The element table behind element_support.h.
#include "element_support.h"

#include <algorithm>
#include <array>

namespace curvescan::svg::detail {
namespace {

constexpr std::array<std::string_view, 14> kRendered{"g",      "svg",     "use",    "path",     "rect",
                                                     "circle", "ellipse", "line",   "polyline", "polygon",
                                                     "text",   "a",       "switch", "image"};

// Referenced or metadata only. <tspan>, <textPath>, <tref>, <altGlyph> and <stop> are read by their parents
// (outside them SVG draws nothing of theirs); the SVG 2 drafts' paint servers and their parts draw nothing
// unless a paint refers to them, which names them then (document.cpp).
constexpr std::array<std::string_view, 28> kNonRendering{
    "defs",   "symbol",    "linearGradient", "radialGradient", "stop",         "clipPath",   "title",
    "desc",   "metadata",  "mask",           "tspan",          "pattern",      "marker",     "style",
    "filter", "textPath",  "tref",           "altGlyph",       "altGlyphItem", "glyphRef",   "mpath",
    "hatch",  "hatchpath", "meshgradient",   "meshrow",        "meshpatch",    "solidcolor", "solidColor"};

// SVG 1.1 and SVG 2 elements without an implementation here, <mesh>, a graphics element of the SVG 2
// drafts (Inkscape writes it), SVG Tiny 1.2's <textArea> and the SVG 1.2 drafts' <flowRoot> (Inkscape 0.x's
// flowed text, in the SVG namespace), whose text would otherwise vanish unnamed.
// <mpath> lives inside <animateMotion>, which is reported itself.
// Filter primitives (fe*) are read by <filter>; one it does not implement is reported when a filter uses it
// (filter/primitive_table.h).
constexpr std::array<std::string_view, 23> kUnsupported{
    "animate", "animateColor",  "animateMotion", "animateTransform", "set",     "discard",
    "script",  "foreignObject", "font",          "font-face",        "glyph",   "missing-glyph",
    "hkern",   "vkern",         "altGlyphDef",   "color-profile",    "cursor",  "view",
    "audio",   "video",         "mesh",          "textArea",         "flowRoot"};

template <std::size_t N>
bool among(const std::array<std::string_view, N>& names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

ElementSupport element_support(std::string_view local_name) noexcept {
  if (among(kRendered, local_name)) return ElementSupport::kRendered;
  if (among(kNonRendering, local_name)) return ElementSupport::kNonRendering;
  if (among(kUnsupported, local_name)) return ElementSupport::kUnsupported;
  // Filter primitives (<feFlood>, <feFuncR>, ...) are read by their <filter> or primitive; elsewhere they
  // draw nothing in any renderer, and an unknown one is named when a filter uses it.
  if (local_name.size() > 2 && local_name.starts_with("fe")) return ElementSupport::kNonRendering;
  return ElementSupport::kUnknown;
}

}  // namespace curvescan::svg::detail
