// Fuzz target css: a style sheet through the CSS engine (raster/svg/css/) and the cascade.
//
// The input is the text of a style sheet. It is read three ways: as the declaration list of a style
// attribute (parse_style_attribute), and as the user style sheet of RenderOptions over a fixed document
// whose elements exercise every selector kind -- ids, classes, attributes, siblings, nesting, a
// gradient's stops, <use> -- so that the tokenizer, the rule and declaration parser, the selector parser,
// matching, the rule index and the cascade (with every property parser behind it, custom properties and
// var() substitution first: the seeds custom_properties.css and var_laughs.css) all see the bytes. The
// canvas is 32 x 32: the render is cheap and the sheet's work dominates.
//
// The render budget is 2^16 segments, 64 MiB and 2^12 dashes, not the defaults (2^22, 1 GiB, 2^20): a
// sheet that makes a shape expensive (a stroke width or dash array past what the canvas shows) is refused
// by the same checks, only sooner; tests/bad_input tests the defaults. The document is parsed again for
// each input: that is 2 % of an execution, and parsing it once (before libFuzzer starts counting) would
// hide its edges from the coverage that compares one harness with another.
#include <cstdint>
#include <string_view>

#include "curvescan/svg/document.h"
#include "curvescan/svg/style_attribute.h"
#include "fuzz_targets.h"

namespace curvescan::fuzz {
namespace {

constexpr std::string_view kDocument =
    R"svg(<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 32 32" width="32" height="32" class="root">
  <defs>
    <linearGradient id="grad"><stop class="s0" offset="0"/><stop class="s1" offset="1" stop-color="red"/></linearGradient>
    <clipPath id="clip"><rect class="c" width="20" height="20"/></clipPath>
  </defs>
  <g id="g1" class="a b" lang="en-US" data-x="one two">
    <rect id="r1" class="cls-1" width="8" height="8"/>
    <circle id="c1" class="cls-2 a" cx="12" cy="4" r="4" fill="url(#grad)"/>
    <g id="g2" clip-path="url(#clip)"><path id="p1" class="cls-1" d="M0 10h10v10z"/><path d="M10 10h5v5z"/></g>
    <ellipse cx="20" cy="20" rx="4" ry="2" style="stroke: blue; stroke-width: 1em"/>
  </g>
  <use xlink:href="#r1" x="20" class="u"/>
  <line x1="0" y1="30" x2="32" y2="30" id="l1"/>
</svg>)svg";

}  // namespace

int fuzz_css(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);  // bytes as characters
  (void)svg::parse_style_attribute(text);
  svg::RenderOptions options;
  options.style_sheet = std::string(text);
  options.limits.max_pixels = 64 * 64;
  options.limits.max_elements = 1000;
  options.limits.render.max_segments = std::int64_t{1} << 16;
  options.limits.render.max_memory_bytes = std::int64_t{64} << 20;
  options.limits.render.max_dashes = std::int64_t{1} << 12;
  (void)svg::render_svg_document(kDocument, options);
  return 0;
}

}  // namespace curvescan::fuzz
