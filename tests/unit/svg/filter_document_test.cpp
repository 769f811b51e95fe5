// Filters in documents (Filter Effects 1, sections 7-11): regions, subregions, units, references, chains,
// colour spaces, errors and limits. Most checks use primitives whose result is known exactly (feFlood,
// feOffset by whole pixels, feComponentTransfer), so the expected pixels follow from the spec's formulas
// and the 8-bit rounding of the result (value · 255 rounded to nearest); where a value goes through the
// linearRGB table a tolerance of one level is stated.
#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <string>

#include "curvescan/raster/zeroed_memory.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

RenderedDocument render100(const std::string& body, const RenderOptions& options = {}) {
  return render(svg_document("width=\"100\" height=\"100\"", body), options);
}

int level(double v) {
  return static_cast<int>(std::floor(v * 255.0 + 0.5));
}

}  // namespace

TEST_CASE("filter: the default region is the bounding box grown by 10 % on each side", "[svg][filter]") {
  // rect 20..70: region 15..75 on both axes; feFlood fills exactly that.
  const RenderedDocument doc = render100(
      "<filter id=\"f\"><feFlood flood-color=\"#0000ff\"/></filter>"
      "<rect x=\"20\" y=\"20\" width=\"50\" height=\"50\" filter=\"url(#f)\"/>");
  CHECK(doc.warnings.empty());
  CHECK(doc.image.at(14, 40) == Rgba8{});
  CHECK(doc.image.at(15, 40) == Rgba8{0, 0, 255, 255});
  CHECK(doc.image.at(74, 74) == Rgba8{0, 0, 255, 255});
  CHECK(doc.image.at(75, 40) == Rgba8{});
  CHECK(doc.image.at(40, 75) == Rgba8{});
}

TEST_CASE("filter: userSpaceOnUse and objectBoundingBox regions, primitive subregions", "[svg][filter]") {
  const RenderedDocument user = render100(
      "<filter id=\"f\" filterUnits=\"userSpaceOnUse\" x=\"10\" y=\"30\" width=\"50%\" height=\"20\">"
      "<feFlood flood-color=\"red\"/></filter><rect width=\"1\" height=\"1\" filter=\"url(#f)\"/>");
  CHECK(user.image.at(10, 30) == Rgba8{255, 0, 0, 255});
  CHECK(user.image.at(59, 49) == Rgba8{255, 0, 0, 255});
  CHECK(user.image.at(60, 40) == Rgba8{});
  CHECK(user.image.at(9, 40) == Rgba8{});
  // primitiveUnits="objectBoundingBox": the flood's x/y/width/height are fractions of the box 20..70.
  const RenderedDocument box = render100(
      "<filter id=\"f\" primitiveUnits=\"objectBoundingBox\">"
      "<feFlood x=\"0.2\" y=\"40%\" width=\"0.5\" height=\"0.2\" flood-color=\"lime\"/></filter>"
      "<rect x=\"20\" y=\"20\" width=\"50\" height=\"50\" filter=\"url(#f)\"/>");
  // x 30..55, y 40..50.
  CHECK(box.image.at(30, 40) == Rgba8{0, 255, 0, 255});
  CHECK(box.image.at(54, 49) == Rgba8{0, 255, 0, 255});
  CHECK(box.image.at(29, 45) == Rgba8{});
  CHECK(box.image.at(55, 45) == Rgba8{});
  CHECK(box.image.at(40, 50) == Rgba8{});
  // A subregion defaults to the union of its inputs' subregions: the offset of a small flood stays small.
  const RenderedDocument chained = render100(
      "<filter id=\"f\" filterUnits=\"userSpaceOnUse\" x=\"0\" y=\"0\" width=\"100\" height=\"100\">"
      "<feFlood x=\"10\" y=\"10\" width=\"20\" height=\"20\" flood-color=\"red\"/><feOffset "
      "dx=\"15\"/></filter>"
      "<rect width=\"10\" height=\"10\" filter=\"url(#f)\"/>");
  CHECK(chained.image.at(12, 15) == Rgba8{});  // the flood moved away
  CHECK(chained.image.at(27, 15) == Rgba8{255, 0, 0, 255});
  CHECK(chained.image.at(32, 15) == Rgba8{});  // beyond the subregion 10..30 the offset is cut
}

TEST_CASE("filter: the drop-shadow recipe (offset, flood, composite in, merge)", "[svg][filter]") {
  // sRGB so that the colours are exact; no blur so that the shadow is a sharp square.
  const RenderedDocument doc = render100(
      "<filter id=\"s\" color-interpolation-filters=\"sRGB\">"
      "<feOffset in=\"SourceAlpha\" dx=\"10\" dy=\"10\" result=\"o\"/>"
      "<feFlood flood-color=\"#000080\" flood-opacity=\"0.5\"/><feComposite in2=\"o\" operator=\"in\"/>"
      "<feMerge><feMergeNode/><feMergeNode in=\"SourceGraphic\"/></feMerge></filter>"
      "<rect x=\"20\" y=\"20\" width=\"40\" height=\"40\" fill=\"#ff0000\" filter=\"url(#s)\"/>");
  CHECK(doc.warnings.empty());
  CHECK(doc.image.at(30, 30) == Rgba8{255, 0, 0, 255});
  // Shadow alone (the region ends at 60 + 4): 0x80 at alpha 0.5 -> premultiplied 64, alpha 128.
  CHECK(doc.image.at(62, 62) == Rgba8{0, 0, static_cast<std::uint8_t>(level(128.0 / 255.0 * 0.5)), 128});
  CHECK(doc.image.at(15, 65) == Rgba8{});
}

TEST_CASE("filter: color-interpolation-filters picks the space a primitive computes in", "[svg][filter]") {
  // feComponentTransfer slope 0.5 on grey 0.6 (153): in sRGB 0.3; in linearRGB to_srgb(0.5 · to_linear(0.6)).
  const auto grey_after = [](const std::string& space) {
    const RenderedDocument doc = render100("<filter id=\"f\"" + space +
                                           "><feComponentTransfer><feFuncR type=\"linear\" slope=\"0.5\"/>"
                                           "</feComponentTransfer></filter><rect width=\"50\" height=\"50\" "
                                           "fill=\"rgb(153,0,0)\" filter=\"url(#f)\"/>");
    return static_cast<int>(doc.image.at(25, 25).r);
  };
  const auto to_linear = [](double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  const auto to_srgb = [](double c) {
    return c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
  };
  CHECK(grey_after(" color-interpolation-filters=\"sRGB\"") == level(0.3));
  // The linearRGB path goes through the conversion tables (error < 2e-5) and 8-bit input: one level.
  CHECK(std::abs(grey_after("") - level(to_srgb(0.5 * to_linear(0.6)))) <= 1);
  CHECK(std::abs(grey_after(" style=\"color-interpolation-filters: linearRGB\"") -
                 level(to_srgb(0.5 * to_linear(0.6)))) <= 1);
}

TEST_CASE("filter: references that disable rendering, and errors that give a transparent result",
          "[svg][filter]") {
  const std::string rect = "<rect x=\"10\" y=\"10\" width=\"50\" height=\"50\" fill=\"red\" ";
  // A reference to nothing, or to something that is not a <filter>: not rendered.
  const RenderedDocument missing = render100(rect + "filter=\"url(#nothing)\"/>");
  CHECK(missing.image.at(30, 30) == Rgba8{});
  CHECK(contains(missing.warnings, "which is not a <filter>"));
  const RenderedDocument not_filter = render100("<g id=\"g\"/>" + rect + "filter=\"url(#g)\"/>");
  CHECK(not_filter.image.at(30, 30) == Rgba8{});
  // In a list with usable filters, such a reference is skipped (as Chrome and resvg do); with only such
  // references, the element is not rendered.
  const RenderedDocument skipped = render100(rect + "filter=\"url(#nothing) opacity(0.5)\"/>");
  // Half of 255 is 127.5: either neighbour is a correct rounding.
  const Rgba8 half = skipped.image.at(30, 30);
  CHECK((half.a == 127 || half.a == 128));
  CHECK(half.r == half.a);
  CHECK((half.g == 0 && half.b == 0));
  CHECK(contains(skipped.warnings, "skipped"));
  CHECK(render100(rect + "filter=\"url(#a) url(#b)\"/>").image.at(30, 30) == Rgba8{});
  // An empty filter, and a region without area: nothing drawn.
  CHECK(render100("<filter id=\"f\"/>" + rect + "filter=\"url(#f)\"/>").image.at(30, 30) == Rgba8{});
  CHECK(render100("<filter id=\"f\" width=\"0\"><feOffset/></filter>" + rect + "filter=\"url(#f)\"/>")
            .image.at(30, 30) == Rgba8{});
  // A negative stdDeviation disables the primitive: its result is its input (Filter Effects 1, 9.13), and
  // so is a malformed one (as if not specified: 0). Named in a warning.
  for (const char* deviation : {"-1", "1 2 3", "", "4px"}) {
    INFO(deviation);
    const RenderedDocument disabled =
        render100("<filter id=\"f\"><feGaussianBlur stdDeviation=\"" + std::string(deviation) +
                  "\"/></filter>" + rect + "filter=\"url(#f)\"/>");
    CHECK(disabled.image.at(30, 30) == Rgba8{255, 0, 0, 255});
    CHECK(disabled.image.at(10, 30) == Rgba8{255, 0, 0, 255});  // unblurred: the edge stays sharp
    CHECK(disabled.image.at(9, 30) == Rgba8{});
    CHECK(contains(disabled.warnings, "stdDeviation"));
  }
  // A negative stdDeviation disables the blur before the next primitive, which still runs.
  const RenderedDocument chained =
      render100("<filter id=\"f\"><feGaussianBlur stdDeviation=\"-1\"/><feOffset dx=\"20\"/></filter>" +
                rect + "filter=\"url(#f)\"/>");
  CHECK(chained.image.at(62, 30) == Rgba8{255, 0, 0, 255});  // the region ends at 65
  CHECK(chained.image.at(25, 30) == Rgba8{});
  // feOffset's dx that is not a number is as if not specified (0), with a warning.
  const RenderedDocument percent =
      render100("<filter id=\"f\"><feOffset dx=\"20%\" dy=\"5\"/></filter>" + rect + "filter=\"url(#f)\"/>");
  CHECK(percent.image.at(10, 15) == Rgba8{255, 0, 0, 255});
  CHECK(percent.image.at(10, 14) == Rgba8{});
  CHECK(contains(percent.warnings, "dx"));
  // stdDeviation 0 is the input unchanged (Filter Effects 1).
  CHECK(render100("<filter id=\"f\"><feGaussianBlur stdDeviation=\"0\"/></filter>" + rect +
                  "filter=\"url(#f)\"/>")
            .image.at(30, 30) == Rgba8{255, 0, 0, 255});
  // A primitive in error (a kernelMatrix of 3 numbers for order 3): named in a warning, and the filter's
  // result is transparent.
  const RenderedDocument in_error =
      render100("<filter id=\"f\"><feConvolveMatrix order=\"3\" kernelMatrix=\"1 0 0\"/></filter>" + rect +
                "filter=\"url(#f)\"/>");
  CHECK(in_error.image.at(30, 30) == Rgba8{});
  CHECK(contains(in_error.warnings, "kernelMatrix"));
  // `in` naming no result is not an error: it reads the previous result (here SourceGraphic, as first).
  const RenderedDocument fallback = render100(
      "<filter id=\"f\"><feOffset in=\"nowhere\" dx=\"5\"/></filter>" + rect + "filter=\"url(#f)\"/>");
  CHECK(fallback.image.at(62, 30) == Rgba8{255, 0, 0, 255});
  CHECK(fallback.image.at(12, 30) == Rgba8{});
}

TEST_CASE("filter: objectBoundingBox on an element without area disables it — userSpaceOnUse does not",
          "[svg][filter]") {
  const std::string line =
      "<line x1=\"10\" y1=\"50\" x2=\"90\" y2=\"50\" stroke=\"black\" stroke-width=\"10\" ";
  CHECK(render100("<filter id=\"f\"><feOffset/></filter>" + line + "filter=\"url(#f)\"/>").image.at(50, 50) ==
        Rgba8{});
  CHECK(render100("<filter id=\"f\" filterUnits=\"userSpaceOnUse\"><feOffset/></filter>" + line +
                  "filter=\"url(#f)\"/>")
            .image.at(50, 50) == Rgba8{0, 0, 0, 255});
}

TEST_CASE("filter: chains and CSS filter functions", "[svg][filter]") {
  const RenderedDocument chain = render100(
      "<filter id=\"a\" x=\"-1\" width=\"3\"><feOffset dx=\"10\"/></filter>"
      "<filter id=\"b\" x=\"-1\" width=\"3\"><feOffset dx=\"10\"/></filter>"
      "<rect x=\"10\" y=\"10\" width=\"20\" height=\"20\" fill=\"red\" filter=\"url(#a) url(#b)\"/>");
  CHECK(chain.image.at(45, 20) == Rgba8{255, 0, 0, 255});
  CHECK(chain.image.at(25, 20) == Rgba8{});
  // opacity(50%): alpha table [0, 0.5] -> 128 (0.5 · 255 = 127.5 rounds up).
  const RenderedDocument half =
      render100("<rect width=\"50\" height=\"50\" fill=\"#00ff00\" style=\"filter: opacity(50%)\"/>");
  CHECK(half.image.at(25, 25) == Rgba8{0, 128, 0, 128});
  // invert() of red is cyan; brightness(0) is black; the functions compute in sRGB.
  CHECK(render100("<rect width=\"50\" height=\"50\" fill=\"red\" filter=\"invert(1)\"/>").image.at(25, 25) ==
        Rgba8{0, 255, 255, 255});
  CHECK(render100("<rect width=\"50\" height=\"50\" fill=\"red\" filter=\"brightness(0)\"/>")
            .image.at(25, 25) == Rgba8{0, 0, 0, 255});
  // grayscale(1) of red: 0.2126 -> 54 on every channel.
  CHECK(render100("<rect width=\"50\" height=\"50\" fill=\"red\" filter=\"grayscale(100%)\"/>")
            .image.at(25, 25) == Rgba8{54, 54, 54, 255});
  // drop-shadow with no blur: a copy in the given colour, offset.
  const RenderedDocument shadow = render100(
      "<rect x=\"10\" y=\"10\" width=\"30\" height=\"30\" fill=\"red\" filter=\"drop-shadow(20px 20px "
      "blue)\"/>");
  CHECK(shadow.image.at(20, 20) == Rgba8{255, 0, 0, 255});
  CHECK(shadow.image.at(55, 55) == Rgba8{0, 0, 255, 255});
  // An invalid value is ignored with a warning: the element renders unfiltered.
  const RenderedDocument invalid =
      render100("<rect width=\"50\" height=\"50\" fill=\"red\" filter=\"blur(-2px)\"/>");
  CHECK(invalid.image.at(25, 25) == Rgba8{255, 0, 0, 255});
  CHECK(!invalid.warnings.empty());
}

TEST_CASE("filter: a rotated element is filtered in its own axes and drawn rotated", "[svg][filter]") {
  // A flood of the default region of a 40 x 10 rect, rotated 90° about (50, 50): the region 46 x 12 becomes
  // tall and thin. The centre is blue, points beyond the rotated short side are not.
  const RenderedDocument doc = render100(
      "<filter id=\"f\"><feFlood flood-color=\"blue\"/></filter>"
      "<rect x=\"30\" y=\"45\" width=\"40\" height=\"10\" transform=\"rotate(90 50 50)\" "
      "filter=\"url(#f)\"/>");
  CHECK(doc.image.at(50, 50) == Rgba8{0, 0, 255, 255});
  CHECK(doc.image.at(50, 30) == Rgba8{0, 0, 255, 255});  // along the rotated long side
  CHECK(doc.image.at(30, 50) == Rgba8{});                // beyond the short side
  CHECK(doc.image.at(50, 75) == Rgba8{});                // beyond 50 + 23
}

TEST_CASE("filter: href inheritance and feImage of an element", "[svg][filter]") {
  const RenderedDocument inherited = render100(
      "<filter id=\"base\" filterUnits=\"userSpaceOnUse\" x=\"0\" y=\"0\" width=\"30\" height=\"30\">"
      "<feFlood flood-color=\"red\"/></filter><filter id=\"f\" href=\"#base\"/>"
      "<rect x=\"50\" y=\"50\" width=\"10\" height=\"10\" filter=\"url(#f)\"/>");
  CHECK(inherited.image.at(10, 10) == Rgba8{255, 0, 0, 255});
  CHECK(inherited.image.at(55, 55) == Rgba8{});
  const RenderedDocument image = render100(
      "<defs><rect id=\"r\" x=\"5\" y=\"5\" width=\"10\" height=\"10\" fill=\"blue\"/></defs>"
      "<filter id=\"f\" filterUnits=\"userSpaceOnUse\" x=\"0\" y=\"0\" width=\"100\" height=\"100\">"
      "<feImage href=\"#r\"/></filter><rect x=\"50\" y=\"50\" width=\"10\" height=\"10\" "
      "filter=\"url(#f)\"/>");
  CHECK(image.image.at(10, 10) == Rgba8{0, 0, 255, 255});
  CHECK(image.image.at(55, 55) == Rgba8{});
}

TEST_CASE("filter: a huge region is filtered at reduced resolution, promptly, with a warning",
          "[svg][filter]") {
  const auto start = std::chrono::steady_clock::now();
  const RenderedDocument doc = render100(
      "<filter id=\"f\" filterUnits=\"userSpaceOnUse\" x=\"-1e9\" y=\"-1e9\" width=\"2e9\" height=\"2e9\">"
      "<feGaussianBlur stdDeviation=\"1e30\"/><feFlood flood-color=\"red\"/></filter>"
      "<rect width=\"10\" height=\"10\" filter=\"url(#f)\"/>");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(seconds < 20.0);  // generous for sanitizer builds; the work is bounded by the pixel limit
  CHECK(contains(doc.warnings, "of the resolution"));
  CHECK(doc.image.at(50, 50) == Rgba8{255, 0, 0, 255});
}

TEST_CASE("filter: a very long chain of primitives runs at a reduced resolution (the work limit)",
          "[svg][filter]") {
  // 40 000 primitives over the default region (the box 10..90 grown by 10 %: 2..98, 96 x 96 pixels):
  // 3.7 * 10^8 pixel-primitives, past kFilterWorkPixels (2^28), so the filter image is scaled down to at
  // most 2^28 / 40 001 = 6 710 pixels (about 85 % of the resolution along each axis), with the warning.
  // Offsets by 0 keep the blue square.
  std::string body = "<filter id=\"f\">";
  for (int i = 0; i < 40000; ++i) body += "<feOffset dx=\"0\"/>";
  body += "</filter><rect x=\"10\" y=\"10\" width=\"80\" height=\"80\" fill=\"blue\" filter=\"url(#f)\"/>";
  const RenderedDocument doc = render100(body);
  CHECK(contains(doc.warnings, "work limits"));
  CHECK(doc.image.at(50, 50) == Rgba8{0, 0, 255, 255});  // inside: every sample of the scaled image is blue
  // 1000 primitives over the same region are 9.2 * 10^6: the full resolution, no warning.
  std::string short_body = "<filter id=\"f\">";
  for (int i = 0; i < 1000; ++i) short_body += "<feOffset dx=\"0\"/>";
  short_body +=
      "</filter><rect x=\"10\" y=\"10\" width=\"80\" height=\"80\" fill=\"blue\" filter=\"url(#f)\"/>";
  const RenderedDocument full = render100(short_body);
  CHECK_FALSE(contains(full.warnings, "of the resolution"));
  CHECK(full.image.at(10, 10) == Rgba8{0, 0, 255, 255});
  CHECK(full.image.at(9, 9) == Rgba8{});
}

TEST_CASE("filter: the images a filter keeps alive are budgeted against --max-memory", "[svg][filter]") {
  // 200 floods all kept for a final merge: 200 images alive at once. Under an 8 MiB budget the 120 x 120
  // region (6.5 KB a pixel for 400 images and their conversions) does not fit, so the filter runs at a
  // reduced resolution, with a warning, instead of allocating 90 MB.
  std::string body = "<filter id=\"f\">";
  std::string merge = "<feMerge>";
  for (int i = 0; i < 200; ++i) {
    body += "<feFlood flood-color=\"red\" flood-opacity=\"0.01\" result=\"r" + std::to_string(i) + "\"/>";
    merge += "<feMergeNode in=\"r" + std::to_string(i) + "\"/>";
  }
  body += merge + "</feMerge></filter><rect width=\"100\" height=\"100\" filter=\"url(#f)\"/>";
  RenderOptions options;
  options.limits.render.max_memory_bytes = std::int64_t{8} << 20;
  const RenderedDocument doc = render100(body, options);
  CHECK(contains(doc.warnings, "of the resolution"));
  // 200 layers of 1 % red: 1 - 0.99^200 = 0.866 of coverage (linearRGB keeps pure red red).
  CHECK(std::abs(doc.image.at(50, 50).a - level(1.0 - std::pow(0.99, 200))) <= 2);  // resampling: 2 levels
}

TEST_CASE("filter: --max-memory counts the rounding of large filter images to huge pages", "[svg][filter]") {
  // A 500 x 500 region: 250 000 pixels, at most 108 bytes each (the canvas byte, the source and current
  // image, four images of the filter, two blur planes: 4 + 16 * 6 + 8), 27 MB, which fits in 32 MiB
  // beside the 1 MB canvas. But each of those eight images is 4 MB and may be rounded up by up to 2 MiB of
  // huge page (curvescan/raster/zeroed_memory.h): 16 MiB more, which does not fit, so the filter runs at a
  // reduced resolution, with a warning. Where blocks are not mapped in huge pages there is no rounding to
  // count.
  if (curvescan::zeroed_block_rounding_bytes() == 0) return;
  const std::string body =
      "<filter id=\"f\" filterUnits=\"userSpaceOnUse\" x=\"0\" y=\"0\" width=\"500\" height=\"500\">"
      "<feOffset dx=\"1\"/></filter><rect width=\"500\" height=\"500\" fill=\"blue\" filter=\"url(#f)\"/>";
  RenderOptions options;
  options.limits.render.max_memory_bytes = std::int64_t{32} << 20;
  const RenderedDocument doc = render(svg_document("width=\"500\" height=\"500\"", body), options);
  CHECK(contains(doc.warnings, "of the resolution"));
  // With room for the rounding too (64 MiB), the filter runs at full resolution.
  options.limits.render.max_memory_bytes = std::int64_t{64} << 20;
  const RenderedDocument roomy = render(svg_document("width=\"500\" height=\"500\"", body), options);
  CHECK_FALSE(contains(roomy.warnings, "of the resolution"));
  CHECK(roomy.image.at(250, 250) == Rgba8{0, 0, 255, 255});
}

TEST_CASE(
    "filter: BackgroundImage, BackgroundAlpha, FillPaint and StrokePaint read the previous result, with a "
    "warning",
    "[svg][filter]") {
  // These standard inputs are not supported here: as in browsers (Chrome provides none of them), they read
  // as a name no primitive gave (Filter Effects 1, 9.2): the previous result, SourceGraphic for the first.
  // Named once. FillPaint of a flat fill reads the shape, not the paint over the whole region.
  for (const std::string input : {"BackgroundImage", "BackgroundAlpha", "FillPaint", "StrokePaint"}) {
    INFO(input);
    const RenderedDocument first =
        render100("<filter id=\"f\" filterUnits=\"userSpaceOnUse\"><feOffset in=\"" + input +
                  "\" dx=\"30\"/></filter><rect width=\"100\" height=\"100\" fill=\"#fff\"/>"
                  "<rect x=\"20\" y=\"20\" width=\"40\" height=\"40\" fill=\"blue\" stroke=\"lime\" "
                  "stroke-width=\"0.01\" filter=\"url(#f)\"/>");
    CHECK(contains(first.warnings, "filter input " + input + " (the previous result is read instead)"));
    CHECK(first.image.at(80, 40) == Rgba8{0, 0, 255, 255});      // the source, moved
    CHECK(first.image.at(30, 40) == Rgba8{255, 255, 255, 255});  // the white background, not doubled
    CHECK(first.image.at(10, 10) == Rgba8{255, 255, 255, 255});  // no paint over the region
    const RenderedDocument later = render100(
        "<filter id=\"f\" filterUnits=\"userSpaceOnUse\"><feFlood flood-color=\"lime\"/><feOffset in=\"" +
        input +
        "\"/></filter><rect x=\"20\" y=\"20\" width=\"40\" height=\"40\" fill=\"blue\" "
        "filter=\"url(#f)\"/>");
    CHECK(later.image.at(40, 40) == Rgba8{0, 255, 0, 255});  // the flood before it
  }
  // Named once however many primitives and elements read it.
  const RenderedDocument many = render100(
      "<filter id=\"f\"><feOffset in=\"BackgroundImage\"/><feOffset in=\"BackgroundImage\" dx=\"1\"/>"
      "</filter><rect width=\"10\" height=\"10\" filter=\"url(#f)\"/>"
      "<rect x=\"20\" width=\"10\" height=\"10\" filter=\"url(#f)\"/>");
  CHECK(std::count_if(many.warnings.begin(), many.warnings.end(), [](const std::string& w) {
          return w.find("BackgroundImage") != std::string::npos;
        }) == 1);
}

TEST_CASE("filter: feImage draws a referenced group with its transform, clipped to the subregion",
          "[svg][filter]") {
  const RenderedDocument doc = render100(
      "<defs><g id=\"g\" transform=\"translate(10 0)\"><rect x=\"5\" y=\"5\" width=\"30\" height=\"10\" "
      "fill=\"lime\"/><circle cx=\"20\" cy=\"40\" r=\"8\" fill=\"blue\"/></g></defs>"
      "<filter id=\"f\" filterUnits=\"userSpaceOnUse\" x=\"0\" y=\"0\" width=\"100\" height=\"100\">"
      "<feImage href=\"#g\" x=\"0\" y=\"0\" width=\"40\" height=\"100\"/></filter>"
      "<rect x=\"60\" y=\"60\" width=\"10\" height=\"10\" filter=\"url(#f)\"/>");
  CHECK(doc.image.at(20, 10) == Rgba8{0, 255, 0, 255});  // the rect, moved by the group's transform
  CHECK(doc.image.at(30, 40) == Rgba8{0, 0, 255, 255});  // the circle's centre (20 + 10, 40)
  CHECK(doc.image.at(42, 10) == Rgba8{});                // the rect reaches 45, the subregion ends at 40
  CHECK(doc.image.at(65, 65) == Rgba8{});                // the filtered element itself is not drawn
  CHECK(doc.warnings.empty());
}

TEST_CASE("filter: an attribute value that is not valid is as if not specified", "[svg][filter]") {
  const std::string rect =
      "<rect x=\"10\" y=\"10\" width=\"50\" height=\"50\" fill=\"red\" filter=\"url(#f)\"/>";
  // feColorMatrix type="qwe": the lacuna value matrix, so the values apply (here red -> green).
  const RenderedDocument matrix = render100(
      "<filter id=\"f\" color-interpolation-filters=\"sRGB\"><feColorMatrix type=\"qwe\" "
      "values=\"0 0 0 0 0  1 0 0 0 0  0 0 1 0 0  0 0 0 1 0\"/></filter>" +
      rect);
  CHECK(matrix.image.at(30, 30) == Rgba8{0, 255, 0, 255});
  CHECK(contains(matrix.warnings, "qwe"));
}

TEST_CASE("filter: flood-color inherit and currentColor without a color", "[svg][filter]") {
  const std::string rect =
      "<rect x=\"10\" y=\"10\" width=\"50\" height=\"50\" fill=\"red\" filter=\"url(#f)\"/>";
  // inherit: the parent's computed value; flood-color is not inherited, so that is the parent's own
  // declaration (the <filter>'s), and without one the initial value, opaque black.
  CHECK(render100("<filter id=\"f\" flood-color=\"lime\"><feFlood flood-color=\"inherit\"/></filter>" + rect)
            .image.at(30, 30) == Rgba8{0, 255, 0, 255});
  CHECK(render100("<g flood-color=\"lime\"><filter id=\"f\"><feFlood flood-color=\"inherit\"/></filter></g>" +
                  rect)
            .image.at(30, 30) == Rgba8{0, 0, 0, 255});
  // currentColor with no `color` anywhere: color's initial value, black (not lighting-color's white).
  CHECK(render100("<filter id=\"f\"><feFlood flood-color=\"currentColor\"/></filter>" + rect)
            .image.at(30, 30) == Rgba8{0, 0, 0, 255});
  CHECK(render100("<filter id=\"f\" color-interpolation-filters=\"sRGB\"><feDiffuseLighting "
                  "lighting-color=\"currentColor\"><feDistantLight elevation=\"90\"/></feDiffuseLighting>"
                  "</filter>" +
                  rect)
            .image.at(30, 30) == Rgba8{0, 0, 0, 255});
  CHECK(render100("<filter id=\"f\" color=\"blue\"><feFlood flood-color=\"currentColor\"/></filter>" + rect)
            .image.at(30, 30) == Rgba8{0, 0, 255, 255});
}

TEST_CASE("filter: feImage of an element is drawn at the subregion's corner, as <use x y> would",
          "[svg][filter]") {
  // Region 20..80 (userSpaceOnUse); the referenced square at the origin lands at the region's corner.
  const RenderedDocument doc = render100(
      "<defs><rect id=\"r\" width=\"10\" height=\"10\" fill=\"blue\"/></defs>"
      "<filter id=\"f\" filterUnits=\"userSpaceOnUse\" x=\"20\" y=\"20\" width=\"60\" height=\"60\">"
      "<feImage href=\"#r\"/></filter>"
      "<rect x=\"30\" y=\"30\" width=\"40\" height=\"40\" fill=\"red\" filter=\"url(#f)\"/>");
  CHECK(doc.image.at(25, 25) == Rgba8{0, 0, 255, 255});
  CHECK(doc.image.at(5, 5) == Rgba8{});
  CHECK(doc.image.at(31, 31) == Rgba8{});
  // With x, y on the primitive, the subregion's corner moves, and the image with it.
  const RenderedDocument moved = render100(
      "<defs><rect id=\"r\" width=\"10\" height=\"10\" fill=\"blue\"/></defs>"
      "<filter id=\"f\" filterUnits=\"userSpaceOnUse\" x=\"20\" y=\"20\" width=\"60\" height=\"60\">"
      "<feImage href=\"#r\" x=\"40\" y=\"50\"/></filter>"
      "<rect x=\"30\" y=\"30\" width=\"40\" height=\"40\" fill=\"red\" filter=\"url(#f)\"/>");
  CHECK(moved.image.at(45, 55) == Rgba8{0, 0, 255, 255});
  CHECK(moved.image.at(25, 25) == Rgba8{});
}

TEST_CASE("filter: function lengths may be unitless, and em is the element's font size", "[svg][filter]") {
  const std::string rect = "<rect x=\"10\" y=\"10\" width=\"40\" height=\"40\" fill=\"blue\" ";
  // blur(2) is blur(2px): the same image, and a blurred one (the sharp edge at x = 10 is gone).
  const RenderedDocument unitless = render100(rect + "filter=\"blur(2)\"/>");
  const RenderedDocument px = render100(rect + "filter=\"blur(2px)\"/>");
  CHECK(unitless.image.pixels() == px.image.pixels());
  CHECK(unitless.image.at(9, 30).a > 0);
  CHECK(unitless.image.at(10, 30).a < 255);
  // drop-shadow(lime 1em 0) with font-size 20: the shadow is 20 px to the right (30..70), unblurred.
  const RenderedDocument em = render100(rect + "font-size=\"20\" filter=\"drop-shadow(lime 1em 0)\"/>");
  CHECK(em.image.at(60, 30) == Rgba8{0, 255, 0, 255});
  CHECK(em.image.at(69, 30) == Rgba8{0, 255, 0, 255});
  CHECK(em.image.at(71, 30) == Rgba8{});
  CHECK(em.image.at(40, 30) == Rgba8{0, 0, 255, 255});
}

TEST_CASE("filter: a blur reads its input beyond its own subregion, which only clips the result",
          "[svg][filter]") {
  // The square covers 10..90; the blur's subregion ends at x = 50. Inside it, near its edge, the blur sees
  // the square continuing beyond 50: fully opaque (σ = 2 reaches 6 px; the square's own edges are 40 px
  // away). Regression: the blur read only its subregion, so the result faded out towards x = 50.
  const RenderedDocument doc = render100(
      "<filter id=\"f\" filterUnits=\"userSpaceOnUse\" x=\"0\" y=\"0\" width=\"100\" height=\"100\">"
      "<feGaussianBlur stdDeviation=\"2\" x=\"0\" width=\"50\"/></filter>"
      "<rect x=\"10\" y=\"10\" width=\"80\" height=\"80\" fill=\"blue\" filter=\"url(#f)\"/>");
  CHECK(doc.image.at(49, 50) == Rgba8{0, 0, 255, 255});
  CHECK(doc.image.at(50, 50) == Rgba8{});  // clipped by the subregion
  CHECK(doc.image.at(10, 50).a < 255);     // the square's own edge is blurred
  // edgeMode duplicate extends the input image at the input's edge (here the filter region's), not at the
  // blur's subregion: the same opaque pixels inside.
  const RenderedDocument duplicate = render100(
      "<filter id=\"f\" filterUnits=\"userSpaceOnUse\" x=\"0\" y=\"0\" width=\"100\" height=\"100\">"
      "<feGaussianBlur stdDeviation=\"2\" edgeMode=\"duplicate\" x=\"0\" width=\"50\"/></filter>"
      "<rect x=\"10\" y=\"10\" width=\"80\" height=\"80\" fill=\"blue\" filter=\"url(#f)\"/>");
  CHECK(duplicate.image.at(49, 50) == Rgba8{0, 0, 255, 255});
  CHECK(duplicate.image.at(50, 50) == Rgba8{});
}

TEST_CASE("filter: an feImage cycle is broken where it closes: the element is drawn without its filter",
          "[svg][filter]") {
  // rect r is filtered by f, whose feImage draws r again: inside, r is drawn unfiltered (its red fill),
  // at the subregion's corner (the region starts at 15 = 20 - 10 % of 50). Outside, f's result: that.
  const RenderedDocument self = render100(
      "<filter id=\"f\"><feImage href=\"#r\"/></filter>"
      "<rect id=\"r\" x=\"20\" y=\"20\" width=\"50\" height=\"50\" fill=\"red\" filter=\"url(#f)\"/>");
  CHECK(self.image.at(40, 40) == Rgba8{255, 0, 0, 255});
  CHECK(self.image.at(36, 36) == Rgba8{255, 0, 0, 255});  // 20 + 15 = 35: where the drawn copy starts
  CHECK(self.image.at(33, 33) == Rgba8{});
  CHECK(contains(self.warnings, "drawn there without its filters"));
  // Through a second element: g (filtered by f) is drawn unfiltered inside f's feImage.
  const RenderedDocument through = render100(
      "<defs><filter id=\"f\"><feImage href=\"#g\"/></filter>"
      "<rect id=\"g\" x=\"10\" y=\"10\" width=\"20\" height=\"20\" fill=\"lime\" filter=\"url(#f)\"/></defs>"
      "<rect x=\"20\" y=\"20\" width=\"50\" height=\"50\" fill=\"red\" filter=\"url(#f)\"/>");
  CHECK(through.image.at(30, 30) == Rgba8{0, 255, 0, 255});  // 10..30 moved by 15: 25..45
  CHECK(through.image.at(50, 50) == Rgba8{});
}

TEST_CASE("filter: feImage content nested past the limit is named as too deep, not as a cycle",
          "[svg][filter]") {
  // e1 … e6 are distinct elements: filter fk's feImage draws ek, which is filtered by f(k+1). No cycle,
  // but each level renders offscreen once more; past four levels the innermost is not drawn.
  std::string defs = "<defs>";
  for (int k = 1; k <= 6; ++k) {
    const std::string n = std::to_string(k), next = std::to_string(k + 1);
    defs += "<filter id=\"f" + n + "\"><feImage href=\"#e" + n + "\"/></filter>";
    defs += "<rect id=\"e" + n + "\" width=\"10\" height=\"10\" fill=\"lime\"" +
            (k < 6 ? " filter=\"url(#f" + next + ")\"" : std::string()) + "/>";
  }
  defs += "</defs>";
  const RenderedDocument doc =
      render100(defs + "<rect x=\"20\" y=\"20\" width=\"50\" height=\"50\" filter=\"url(#f1)\"/>");
  CHECK(contains(doc.warnings, "inside 4 other <feImage>s' content"));
  CHECK_FALSE(contains(doc.warnings, "refers to itself"));
}

TEST_CASE("filter: a tableValues that is not a list of numbers is the identity", "[svg][filter]") {
  const RenderedDocument doc = render100(
      "<filter id=\"f\" color-interpolation-filters=\"sRGB\"><feComponentTransfer><feFuncB type=\"table\" "
      "tableValues=\"1px\"/></feComponentTransfer></filter>"
      "<rect x=\"10\" y=\"10\" width=\"50\" height=\"50\" fill=\"#aabbcc\" filter=\"url(#f)\"/>");
  CHECK(doc.image.at(30, 30) == Rgba8{0xaa, 0xbb, 0xcc, 255});
  CHECK(contains(doc.warnings, "tableValues"));
}

TEST_CASE("filter: an invalid flood-color or lighting-color falls back to the next valid declaration",
          "[svg][filter][css]") {
  // CSS Cascade 4, 4.1: an invalid declaration is not part of the cascade. The style attribute's
  // 'nonsense' is dropped, so the presentation attribute (lime) applies — not the initial black.
  const RenderedDocument flood = render100(
      "<filter id=\"f\"><feFlood flood-color=\"lime\" style=\"flood-color: nonsense\"/></filter>"
      "<rect x=\"20\" y=\"20\" width=\"50\" height=\"50\" filter=\"url(#f)\"/>");
  CHECK(flood.image.at(40, 40) == Rgba8{0, 255, 0, 255});
  CHECK(contains(flood.warnings, "flood-color 'nonsense' is not a colour"));
  // A sheet rule with an invalid value loses to nothing: the attribute's colour stays.
  const RenderedDocument sheet = render100(
      "<style>feFlood { flood-color: 12px }</style>"
      "<filter id=\"f\"><feFlood flood-color=\"#0000ff\"/></filter>"
      "<rect x=\"20\" y=\"20\" width=\"50\" height=\"50\" filter=\"url(#f)\"/>");
  CHECK(sheet.image.at(40, 40) == Rgba8{0, 0, 255, 255});
  // lighting-color: an invalid value in the style attribute leaves the attribute's black, so a diffuse
  // light lights nothing (the result is opaque black), where the initial white would light the surface.
  const RenderedDocument light = render100(
      "<filter id=\"f\"><feDiffuseLighting lighting-color=\"black\" style=\"lighting-color: notacolour\">"
      "<feDistantLight azimuth=\"0\" elevation=\"90\"/></feDiffuseLighting></filter>"
      "<rect x=\"20\" y=\"20\" width=\"50\" height=\"50\" filter=\"url(#f)\"/>");
  CHECK(light.image.at(40, 40) == Rgba8{0, 0, 0, 255});
  CHECK(contains(light.warnings, "lighting-color 'notacolour' is not a colour"));
}

TEST_CASE("filter: feImage of an SVG image draws the document in the subregion with preserveAspectRatio",
          "[svg][filter]") {
  // A 10 x 10 document whose left half is lime, in the subregion 20..60 x 20..40. xMidYMid meet scales it
  // by 2 to 20 x 20, centred: x 30..50, lime over 30..40. none stretches it to 40 x 20: lime over 20..40.
  const std::string image =
      "data:image/svg+xml,%3Csvg xmlns='http://www.w3.org/2000/svg' width='10' height='10'%3E"
      "%3Crect width='5' height='10' fill='%2300ff00'/%3E%3C/svg%3E";
  const auto filtered = [&](const std::string& aspect) {
    return render100("<filter id=\"f\" filterUnits=\"userSpaceOnUse\" x=\"0\" y=\"0\" width=\"100\" "
                     "height=\"100\"><feImage href=\"" +
                     image + "\" x=\"20\" y=\"20\" width=\"40\" height=\"20\" " + aspect +
                     "/></filter><rect x=\"70\" y=\"70\" width=\"10\" height=\"10\" fill=\"red\" "
                     "filter=\"url(#f)\"/>");
  };
  const RenderedDocument meet = filtered("");
  CHECK_FALSE(contains(meet.warnings, "feImage"));
  CHECK(meet.image.at(35, 30) == Rgba8{0, 255, 0, 255});
  CHECK(meet.image.at(45, 30) == Rgba8{});  // the document's empty right half
  CHECK(meet.image.at(25, 30) == Rgba8{});  // beside the image (meet)
  CHECK(meet.image.at(75, 75) == Rgba8{});  // the source is replaced
  const RenderedDocument none = filtered("preserveAspectRatio=\"none\"");
  CHECK(none.image.at(22, 22) == Rgba8{0, 255, 0, 255});
  CHECK(none.image.at(38, 38) == Rgba8{0, 255, 0, 255});
  CHECK(none.image.at(42, 30) == Rgba8{});
  // A document that is not well formed is a warning, and the primitive is transparent.
  const RenderedDocument broken = render100(
      "<filter id=\"f\"><feImage href=\"data:image/svg+xml,%3Csvg\"/></filter>"
      "<rect x=\"20\" y=\"20\" width=\"50\" height=\"50\" fill=\"red\" filter=\"url(#f)\"/>");
  CHECK(contains(broken.warnings, "<feImage>"));
  CHECK(broken.image.at(40, 40) == Rgba8{});
}

TEST_CASE("filter: contrast(), hue-rotate(), saturate() and sepia() are their Filter Effects 1 matrices",
          "[svg][filter]") {
  // Filter Effects 1, section 13, computed in sRGB on the 8-bit fill (exact inputs); the expected bytes are
  // the formulas' values · 255 rounded to nearest, written out here.
  const auto one = [](const std::string& fill, const std::string& function) {
    return render100("<rect width=\"50\" height=\"50\" fill=\"" + fill + "\" style=\"filter: " + function +
                     "\"/>")
        .image.at(25, 25);
  };
  // contrast(1.5): C' = 1.5 C - 0.25 (slope a, intercept 0.5 - a / 2). #4080c0 = (64, 128, 192) / 255 ->
  // 0.1265, 0.5029, 0.8794 -> 32.25, 128.25, 224.25.
  CHECK(one("#4080c0", "contrast(1.5)") == Rgba8{32, 128, 224, 255});
  CHECK(one("#4080c0", "contrast(150%)") == Rgba8{32, 128, 224, 255});
  // hue-rotate(180deg) of red: the hueRotate matrix at cos = -1, sin = 0 has first column
  // (0.213 - 0.787, 0.213 + 0.213, 0.213 + 0.213) = (-0.574 -> 0, 0.426, 0.426): 0.426 · 255 = 108.6.
  CHECK(one("red", "hue-rotate(180deg)") == Rgba8{0, 109, 109, 255});
  CHECK(one("red", "hue-rotate(0.5turn)") == Rgba8{0, 109, 109, 255});
  // saturate(0.5) of red: first column (0.213 + 0.787 s, 0.213 - 0.213 s, 0.213 - 0.213 s) =
  // (0.6065, 0.1065, 0.1065) -> 154.7, 27.2, 27.2.
  CHECK(one("red", "saturate(0.5)") == Rgba8{155, 27, 27, 255});
  // sepia(1) of red: the first column (0.393, 0.349, 0.272) -> 100.2, 89.0, 69.4; of white the row sums
  // (1.351, 1.203, 0.937), clamped: 255, 255, 238.9.
  CHECK(one("red", "sepia(1)") == Rgba8{100, 89, 69, 255});
  CHECK(one("white", "sepia(100%)") == Rgba8{255, 255, 239, 255});
  // sepia(0) is the identity.
  CHECK(one("#4080c0", "sepia(0)") == Rgba8{64, 128, 192, 255});
}

TEST_CASE("filter: luminanceToAlpha, an identity transfer function, and feImage of a PNG", "[svg][filter]") {
  // luminanceToAlpha (Filter Effects 1, 9.8): A' = 0.2125 R + 0.7154 G + 0.0721 B, colour 0. Pure red is
  // 1 in linearRGB too: alpha 0.2125 -> 54.2, black.
  const RenderedDocument luminance = render100(
      "<filter id=\"f\"><feColorMatrix type=\"luminanceToAlpha\"/></filter>"
      "<rect width=\"50\" height=\"50\" fill=\"red\" filter=\"url(#f)\"/>");
  CHECK(luminance.image.at(25, 25) == Rgba8{0, 0, 0, 54});
  // type="identity" ignores the other attributes: red stays red although slope="0" is given.
  const RenderedDocument identity = render100(
      "<filter id=\"f\"><feComponentTransfer><feFuncR type=\"identity\" slope=\"0\" intercept=\"0\"/>"
      "<feFuncG type=\"linear\" intercept=\"1\"/></feComponentTransfer></filter>"
      "<rect width=\"50\" height=\"50\" fill=\"red\" filter=\"url(#f)\"/>");
  CHECK(identity.image.at(25, 25) == Rgba8{255, 255, 0, 255});
  // feImage of a raster image: a 2 x 1 PNG (blue, lime) stretched over a 40 x 40 subregion with
  // preserveAspectRatio="none": the left half blue, the right half lime (away from the middle, where the
  // image is resampled).
  const RenderedDocument png = render100(
      "<filter id=\"f\" filterUnits=\"userSpaceOnUse\" x=\"0\" y=\"0\" width=\"100\" height=\"100\">"
      "<feImage x=\"10\" y=\"10\" width=\"40\" height=\"40\" preserveAspectRatio=\"none\" "
      "href=\"data:image/png;base64,"
      "iVBORw0KGgoAAAANSUhEUgAAAAIAAAABCAYAAAD0In+KAAAAD0lEQVR4nGNgYPj/nwEIAQ76A/2ILbfFAAAAAElFTkSuQmCC\"/>"
      "</filter><rect width=\"100\" height=\"100\" filter=\"url(#f)\"/>");
  CHECK(png.image.at(15, 30) == Rgba8{0, 0, 255, 255});
  CHECK(png.image.at(45, 30) == Rgba8{0, 255, 0, 255});
  CHECK(png.image.at(55, 30) == Rgba8{});  // outside the subregion
}

TEST_CASE("filter: a skewed element is filtered in its own axes and drawn skewed", "[svg][filter]") {
  // skewX(45) maps (x, y) to (x + y, y). The flood of a 20 x 20 square's default region (-2..22 on both
  // axes) is a parallelogram: at y = 20 it spans x = 18..42, at y = 0 x = -2..22.
  const RenderedDocument doc = render100(
      "<filter id=\"f\"><feFlood flood-color=\"blue\"/></filter>"
      "<rect width=\"20\" height=\"20\" transform=\"translate(20 20) skewX(45)\" filter=\"url(#f)\"/>");
  CHECK(doc.image.at(20 + 35, 20 + 15) == Rgba8{0, 0, 255, 255});  // (20, 15) in user space: x 35
  CHECK(doc.image.at(20 + 5, 20 + 15) == Rgba8{});                 // left of the slanted edge (x 13)
  CHECK(doc.image.at(20 + 2, 20 + 1) == Rgba8{0, 0, 255, 255});    // (1, 1) -> (2, 1)
}

TEST_CASE("filter: under a scale the filter runs at device resolution, with user-space numbers",
          "[svg][filter]") {
  // scale(2, 1): the filter space is the user space scaled to device pixels, so feOffset dx="10" dy="10"
  // moves 20 device pixels right and 10 down, and the 10 x 10 square (20 x 10 device pixels at 10..30,
  // 5..15) lands at 30..50, 15..25.
  const RenderedDocument doc = render100(
      "<filter id=\"f\" x=\"-1\" y=\"-1\" width=\"3\" height=\"3\"><feOffset dx=\"10\" dy=\"10\"/></filter>"
      "<g transform=\"scale(2 1)\"><rect x=\"5\" y=\"5\" width=\"10\" height=\"10\" fill=\"blue\" "
      "filter=\"url(#f)\"/></g>");
  CHECK(doc.image.at(30, 15) == Rgba8{0, 0, 255, 255});
  CHECK(doc.image.at(49, 24) == Rgba8{0, 0, 255, 255});
  CHECK(doc.image.at(50, 20) == Rgba8{});
  CHECK(doc.image.at(29, 20) == Rgba8{});
  CHECK(doc.image.at(20, 10) == Rgba8{});  // the source's own place is empty
}
