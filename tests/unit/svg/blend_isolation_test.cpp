// mix-blend-mode and isolation (CSS Compositing and Blending 1, sections 3.2 and 3.3) in documents: an
// element with a blend mode is drawn as a group and blended with what lies under it inside the nearest
// isolated group (a group with opacity, a mask, a blend mode or isolation: isolate; or the canvas). The
// shapes are opaque and cover whole pixels, so the expected colours are the modes' formulas on 0/255
// values: exact.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <string>

#include "svg/painting_properties.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

}  // namespace

TEST_CASE("mix-blend-mode blends an element with what is drawn under it", "[svg][blend]") {
  // A blue square under a red one with screen: magenta where they overlap, red elsewhere.
  const RenderedDocument screen =
      render_square(20,
                    "<rect width=\"10\" height=\"20\" fill=\"blue\"/>"
                    "<rect width=\"20\" height=\"20\" fill=\"red\" style=\"mix-blend-mode: screen\"/>");
  CHECK(screen.image.at(5, 5) == Rgba8{255, 0, 255, 255});
  CHECK(screen.image.at(15, 5) == Rgba8{255, 0, 0, 255});  // over the transparent canvas: the source
  CHECK(screen.warnings.empty());
  // multiply from a style sheet, on a group: red multiplied by yellow stays red, by blue black.
  const RenderedDocument multiply = render_square(
      20,
      "<style>g { mix-blend-mode: multiply }</style>"
      "<rect width=\"10\" height=\"20\" fill=\"yellow\"/><rect x=\"10\" width=\"10\" height=\"20\" "
      "fill=\"blue\"/>"
      "<g><rect width=\"20\" height=\"20\" fill=\"red\"/></g>");
  CHECK(multiply.image.at(5, 5) == Rgba8{255, 0, 0, 255});
  CHECK(multiply.image.at(15, 5) == Rgba8{0, 0, 0, 255});
}

// Regression: mix-blend-mode and isolation were read as presentation attributes. SVG 2 6.6 gives no
// attribute to properties newer than SVG 1.1 (both come from CSS Compositing 1), and browsers ignore
// them: the attribute draws normally and is named once in a warning.
TEST_CASE("mix-blend-mode and isolation as attributes are not presentation attributes", "[svg][blend]") {
  const RenderedDocument blend =
      render_square(20,
                    "<rect width=\"20\" height=\"20\" fill=\"blue\"/>"
                    "<rect width=\"20\" height=\"20\" fill=\"red\" mix-blend-mode=\"screen\"/>");
  CHECK(blend.image.at(5, 5) == Rgba8{255, 0, 0, 255});  // screen would give magenta
  CHECK(contains(blend.warnings, "mix-blend-mode attribute"));
  const std::string child =
      "<rect width=\"20\" height=\"20\" fill=\"red\" style=\"mix-blend-mode: difference\"/>";
  const RenderedDocument isolation = render_square(
      20, "<rect width=\"20\" height=\"20\" fill=\"white\"/><g isolation=\"isolate\">" + child + "</g>");
  CHECK(isolation.image.at(5, 5) == Rgba8{0, 255, 255, 255});  // not isolated: red difference white
  CHECK(contains(isolation.warnings, "isolation attribute"));
}

TEST_CASE("isolation: isolate keeps a group's children from blending with what lies outside it", "[svg][blend]") {
  const std::string child = "<rect width=\"20\" height=\"20\" fill=\"red\" style=\"mix-blend-mode: difference\"/>";
  // Not isolated: red difference over white = cyan.
  const RenderedDocument open =
      render_square(20, "<rect width=\"20\" height=\"20\" fill=\"white\"/><g>" + child + "</g>");
  CHECK(open.image.at(5, 5) == Rgba8{0, 255, 255, 255});
  // Isolated: the child blends with the group's transparent start (plain red), and the group is drawn
  // source-over.
  const RenderedDocument isolated =
      render_square(20, "<rect width=\"20\" height=\"20\" fill=\"white\"/><g style=\"isolation: isolate\">" +
                            child + "</g>");
  CHECK(isolated.image.at(5, 5) == Rgba8{255, 0, 0, 255});
  // Opacity isolates too (a group with opacity is drawn offscreen as a whole).
  const RenderedDocument faded = render_square(
      20, "<rect width=\"20\" height=\"20\" fill=\"white\"/><g opacity=\"0.999\">" + child + "</g>");
  // Opacity 0.999 is layer alpha 254 (layer_alpha): plain red over white at 254/255 leaves g = 255·1/255
  // = 1 and r = 255, give or take the one step of composite_source_over's rounding; blended through the
  // group (not isolated) it would be cyan, g = 255.
  CHECK(faded.image.at(5, 5).r >= 254);
  CHECK(faded.image.at(5, 5).g <= 1);
}

TEST_CASE("mix-blend-mode and isolation: keywords, and what is refused", "[svg][blend]") {
  CHECK(detail::parse_blend_mode("color-dodge") == BlendMode::kColorDodge);
  CHECK(detail::parse_blend_mode("luminosity") == BlendMode::kLuminosity);
  CHECK(detail::parse_blend_mode("Multiply") == BlendMode::kMultiply);  // CSS keywords: any ASCII case
  CHECK_FALSE(detail::parse_blend_mode("add"));
  // An invalid value is ignored with a warning (normal blending); plus-lighter (a later draft) warns as
  // unsupported.
  const RenderedDocument invalid = render_square(
      20,
      "<rect width=\"20\" height=\"20\" fill=\"blue\"/><rect width=\"20\" height=\"20\" fill=\"red\" "
      "style=\"mix-blend-mode: add\"/>");
  CHECK(invalid.image.at(5, 5) == Rgba8{255, 0, 0, 255});
  CHECK(contains(invalid.warnings, "mix-blend-mode"));
  const RenderedDocument later = render_square(
      20, "<rect width=\"20\" height=\"20\" fill=\"red\" style=\"mix-blend-mode: plus-lighter\"/>");
  CHECK(contains(later.warnings, "plus-lighter"));
}

namespace {

// CSS Compositing and Blending 1, section 5 (separable) and 6 (non-separable), written out from the
// specification here, independently of the library's tables: B(Cb, Cs) per channel in [0, 1].
using Colour = std::array<double, 3>;

double hard_light(double b, double s) {
  return s <= 0.5 ? b * 2 * s : b + (2 * s - 1) - b * (2 * s - 1);
}

double separable(const std::string& mode, double b, double s) {
  if (mode == "normal") return s;
  if (mode == "multiply") return b * s;
  if (mode == "screen") return b + s - b * s;
  if (mode == "overlay") return hard_light(s, b);
  if (mode == "darken") return std::min(b, s);
  if (mode == "lighten") return std::max(b, s);
  if (mode == "color-dodge") return b == 0 ? 0 : s == 1 ? 1 : std::min(1.0, b / (1 - s));
  if (mode == "color-burn") return b == 1 ? 1 : s == 0 ? 0 : 1 - std::min(1.0, (1 - b) / s);
  if (mode == "hard-light") return hard_light(b, s);
  if (mode == "soft-light") {
    if (s <= 0.5) return b - (1 - 2 * s) * b * (1 - b);
    const double d = b <= 0.25 ? ((16 * b - 12) * b + 4) * b : std::sqrt(b);
    return b + (2 * s - 1) * (d - b);
  }
  if (mode == "difference") return std::abs(b - s);
  return b + s - 2 * b * s;  // exclusion
}

double lum(const Colour& c) {
  return 0.3 * c[0] + 0.59 * c[1] + 0.11 * c[2];
}

Colour clip_colour(Colour c) {
  const double l = lum(c), n = std::min({c[0], c[1], c[2]}), x = std::max({c[0], c[1], c[2]});
  for (double& v : c) {
    if (n < 0) v = l + (v - l) * l / (l - n);
    if (x > 1) v = l + (v - l) * (1 - l) / (x - l);
  }
  return c;
}

Colour set_lum(Colour c, double l) {
  const double d = l - lum(c);
  for (double& v : c) v += d;
  return clip_colour(c);
}

double sat(const Colour& c) {
  return std::max({c[0], c[1], c[2]}) - std::min({c[0], c[1], c[2]});
}

Colour set_sat(Colour c, double s) {
  std::array<int, 3> order{0, 1, 2};  // indices of min, mid, max
  std::sort(order.begin(), order.end(), [&](int i, int j) { return c[i] < c[j]; });
  double& lo = c[order[0]];
  double& mid = c[order[1]];
  double& hi = c[order[2]];
  if (hi > lo) {
    mid = (mid - lo) * s / (hi - lo);
    hi = s;
  } else {
    mid = hi = 0;
  }
  lo = 0;
  return c;
}

Colour blend(const std::string& mode, const Colour& b, const Colour& s) {
  if (mode == "hue") return set_lum(set_sat(s, sat(b)), lum(b));
  if (mode == "saturation") return set_lum(set_sat(b, sat(s)), lum(b));
  if (mode == "color") return set_lum(s, lum(b));
  if (mode == "luminosity") return set_lum(b, lum(s));
  return {separable(mode, b[0], s[0]), separable(mode, b[1], s[1]), separable(mode, b[2], s[2])};
}

}  // namespace

TEST_CASE("mix-blend-mode: each of the sixteen modes gives its formula's colour", "[svg][blend]") {
  // An opaque source over an opaque backdrop: the result is B(Cb, Cs) itself (section 5.1 with αs = αb =
  // 1). The colours reach both branches of the piecewise formulas (Cs below and above 1/2, Cb below and
  // above 1/4 for soft-light) and have different saturations, so that no two modes agree: the closest
  // two (hue and color) differ by 15.8 levels in a channel, so a mode drawn as another fails. Tolerance:
  // 1/255 per channel, the rounding of the result to 8 bits (the inputs are exact bytes; color-dodge's
  // green is 127.5).
  const std::array<int, 3> backdrop{204, 51, 128}, source{77, 153, 200};
  const auto unit = [](const std::array<int, 3>& c) {
    return Colour{c[0] / 255.0, c[1] / 255.0, c[2] / 255.0};
  };
  const auto hex = [](const std::array<int, 3>& c) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", c[0], c[1], c[2]);
    return std::string(text);
  };
  for (const std::string mode :
       {"normal", "multiply", "screen", "overlay", "darken", "lighten", "color-dodge", "color-burn",
        "hard-light", "soft-light", "difference", "exclusion", "hue", "saturation", "color", "luminosity"}) {
    const RenderedDocument rendered =
        render_square(20, "<rect width=\"20\" height=\"20\" fill=\"" + hex(backdrop) +
                              "\"/><rect width=\"20\" height=\"20\" "
                              "fill=\"" +
                              hex(source) + "\" style=\"mix-blend-mode: " + mode + "\"/>");
    const Colour expected = blend(mode, unit(backdrop), unit(source));
    const Rgba8 got = rendered.image.at(10, 10);
    INFO(mode << ": got " << int(got.r) << " " << int(got.g) << " " << int(got.b) << ", expected "
              << expected[0] * 255 << " " << expected[1] * 255 << " " << expected[2] * 255);
    CHECK(std::abs(got.r - expected[0] * 255) <= 1.0);
    CHECK(std::abs(got.g - expected[1] * 255) <= 1.0);
    CHECK(std::abs(got.b - expected[2] * 255) <= 1.0);
    CHECK(got.a == 255);
    CHECK(rendered.warnings.empty());
  }
}
