// <mask> (SVG 1.1 14.4, CSS Masking 1 7.1-7.3). Expected pixels are reasoned from the specification and
// the compositing of canvas.h: a mask of coverage m over an opaque colour c gives the premultiplied pixel
// MUL_UN8(c, m) with alpha m (pixman's rounding, exact), so every check below is exact unless it says
// otherwise.
#include "curvescan/raster/mask.h"

#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

// A 40 x 40 document.
const std::string kGreen = "fill=\"#00ff00\"";

}  // namespace

TEST_CASE("mask: luminance of a 50% grey lets half through — mask-type=alpha uses alpha", "[svg][mask]") {
  // Luminance 0.2125·128 + 0.7154·128 + 0.0721·128 = 127.87 -> 128.
  const RenderedDocument grey =
      render_square(40,
                    "<mask id=\"m\"><rect width=\"40\" height=\"40\" fill=\"#808080\"/></mask>"
                    "<rect width=\"40\" height=\"40\" " +
                        kGreen + " mask=\"url(#m)\"/>");
  CHECK(grey.image.at(20, 20) == Rgba8{0, 128, 0, 128});
  CHECK(grey.warnings.empty());
  // Pure colours weigh by their coefficients: blue -> 0.0721·255 = 18.4 -> 18; red -> 54.2 -> 54.
  const RenderedDocument blue = render_square(
      40,
      "<mask id=\"m\"><rect width=\"20\" height=\"40\" fill=\"blue\"/><rect x=\"20\" width=\"20\" "
      "height=\"40\" "
      "fill=\"red\"/></mask><rect width=\"40\" height=\"40\" fill=\"white\" mask=\"url(#m)\"/>");
  CHECK(blue.image.at(10, 20).a == 18);
  CHECK(blue.image.at(30, 20).a == 54);
  // alpha: black at 50 % opacity has alpha 128 (Cairo's conversion of 0.5, paint.h) and lets that through;
  // as luminance the same black lets nothing through.
  const std::string content = "<rect width=\"40\" height=\"40\" fill=\"black\" fill-opacity=\"0.5\"/>";
  const RenderedDocument alpha =
      render_square(40, "<mask id=\"m\" mask-type=\"alpha\">" + content +
                            "</mask><rect width=\"40\" height=\"40\" " + kGreen + " mask=\"url(#m)\"/>");
  CHECK(alpha.image.at(20, 20) == Rgba8{0, 128, 0, 128});
  const RenderedDocument styled =
      render_square(40, "<mask id=\"m\" style=\"mask-type: alpha\">" + content +
                            "</mask><rect width=\"40\" height=\"40\" " + kGreen + " mask=\"url(#m)\"/>");
  CHECK(styled.image.at(20, 20) == Rgba8{0, 128, 0, 128});
  const RenderedDocument luminance =
      render_square(40, "<mask id=\"m\">" + content + "</mask><rect width=\"40\" height=\"40\" " + kGreen +
                            " mask=\"url(#m)\"/>");
  CHECK(luminance.image.at(20, 20) == Rgba8{});
}

TEST_CASE("mask: the default region is the bounding box grown by 10% on each side, strokes excluded",
          "[svg][mask]") {
  // Box 10..30 (20 wide): the region is 8..32. The stroke reaches 6..34, so columns 6-7 and 32-33 are cut.
  const RenderedDocument doc =
      render_square(40,
                    "<mask id=\"m\"><rect width=\"40\" height=\"40\" fill=\"white\"/></mask>"
                    "<rect x=\"10\" y=\"10\" width=\"20\" height=\"20\" fill=\"none\" stroke=\"#00ff00\" "
                    "stroke-width=\"8\" "
                    "mask=\"url(#m)\"/>");
  CHECK(doc.image.at(7, 20) == Rgba8{});
  CHECK(doc.image.at(8, 20) == Rgba8{0, 255, 0, 255});
  CHECK(doc.image.at(31, 20) == Rgba8{0, 255, 0, 255});
  CHECK(doc.image.at(32, 20) == Rgba8{});
  // Explicit fractions of the box: x=0.5 width=0.5 keeps the right half of the box.
  const RenderedDocument half = render_square(
      40,
      "<mask id=\"m\" x=\"0.5\" y=\"0\" width=\"50%\" height=\"1\"><rect width=\"40\" height=\"40\" "
      "fill=\"white\"/>"
      "</mask><rect x=\"10\" y=\"10\" width=\"20\" height=\"20\" " +
          kGreen + " mask=\"url(#m)\"/>");
  CHECK(half.image.at(19, 20) == Rgba8{});
  CHECK(half.image.at(20, 20) == Rgba8{0, 255, 0, 255});
}

TEST_CASE("mask: maskUnits=userSpaceOnUse and maskContentUnits=objectBoundingBox", "[svg][mask]") {
  // Region in user space: 0..15 wide (the element spans 10..30, so only 10..15 shows).
  const RenderedDocument user =
      render_square(40,
                    "<mask id=\"m\" maskUnits=\"userSpaceOnUse\" x=\"0\" y=\"0\" width=\"15\" height=\"40\">"
                    "<rect width=\"40\" height=\"40\" fill=\"white\"/></mask>"
                    "<rect x=\"10\" y=\"10\" width=\"20\" height=\"20\" " +
                        kGreen + " mask=\"url(#m)\"/>");
  CHECK(user.image.at(14, 20) == Rgba8{0, 255, 0, 255});
  CHECK(user.image.at(15, 20) == Rgba8{});
  // Content in box units: a white rect of width 0.25 covers 10..15 of the box 10..30.
  const RenderedDocument content =
      render_square(40,
                    "<mask id=\"m\" maskContentUnits=\"objectBoundingBox\"><rect width=\"0.25\" height=\"1\" "
                    "fill=\"white\"/>"
                    "</mask><rect x=\"10\" y=\"10\" width=\"20\" height=\"20\" " +
                        kGreen + " mask=\"url(#m)\"/>");
  CHECK(content.image.at(14, 20) == Rgba8{0, 255, 0, 255});
  CHECK(content.image.at(15, 20) == Rgba8{});
  // The mask's transform attribute has no effect (it is not a transformable element); the element's
  // transform moves its mask with it.
  const RenderedDocument moved = render_square(
      40,
      "<mask id=\"m\" maskUnits=\"userSpaceOnUse\" transform=\"translate(100 0)\"><rect width=\"10\" "
      "height=\"40\" "
      "fill=\"white\"/></mask><rect width=\"20\" height=\"40\" " +
          kGreen + " mask=\"url(#m)\" transform=\"translate(20 0)\"/>");
  CHECK(moved.image.at(25, 20) == Rgba8{0, 255, 0, 255});
  CHECK(moved.image.at(35, 20) == Rgba8{});
}

TEST_CASE("mask: on groups, with opacity, nested on the mask and on its content, with clip-path inside",
          "[svg][mask]") {
  const std::string grey = "<mask id=\"grey\"><rect width=\"40\" height=\"40\" fill=\"#808080\"/></mask>";
  // On a group whose box is the union of its children (box 0..40 here), composited as one group: the
  // overlap of the two rects is not darker than the rest.
  const RenderedDocument group =
      render_square(40, grey + "<g mask=\"url(#grey)\"><rect width=\"30\" height=\"40\" " + kGreen +
                            "/><rect x=\"10\" width=\"30\" height=\"40\" " + kGreen + "/></g>");
  CHECK(group.image.at(5, 20) == Rgba8{0, 128, 0, 128});
  CHECK(group.image.at(20, 20) == Rgba8{0, 128, 0, 128});
  // Group opacity 0.5 (alpha 128) and a mask of 128 multiply: MUL_UN8(128, 128) = 64.
  const RenderedDocument faded =
      render_square(40, grey +
                            "<rect width=\"40\" height=\"40\" fill=\"white\" opacity=\"0.5\" "
                            "mask=\"url(#grey)\"/>");
  CHECK(faded.image.at(20, 20).a == 64);
  // A mask on the <mask> element multiplies in: white content seen through grey -> 128.
  const RenderedDocument on_mask = render_square(
      40, grey +
              "<mask id=\"m\" mask=\"url(#grey)\"><rect width=\"40\" height=\"40\" fill=\"white\"/></mask>"
              "<rect width=\"40\" height=\"40\" " +
              kGreen + " mask=\"url(#m)\"/>");
  CHECK(on_mask.image.at(20, 20) == Rgba8{0, 128, 0, 128});
  // A mask on the content: white through grey is (128,128,128,128) premultiplied, luminance 128.
  const RenderedDocument on_content = render_square(
      40, grey +
              "<mask id=\"m\"><rect width=\"40\" height=\"40\" fill=\"white\" mask=\"url(#grey)\"/></mask>"
              "<rect width=\"40\" height=\"40\" " +
              kGreen + " mask=\"url(#m)\"/>");
  CHECK(on_content.image.at(20, 20) == Rgba8{0, 128, 0, 128});
  // clip-path inside the mask's content keeps the left half only.
  const RenderedDocument clipped = render_square(
      40,
      "<clipPath id=\"c\"><rect width=\"20\" height=\"40\"/></clipPath>"
      "<mask id=\"m\"><rect width=\"40\" height=\"40\" fill=\"white\" clip-path=\"url(#c)\"/></mask>"
      "<rect width=\"40\" height=\"40\" " +
          kGreen + " mask=\"url(#m)\"/>");
  CHECK(clipped.image.at(10, 20) == Rgba8{0, 255, 0, 255});
  CHECK(clipped.image.at(30, 20) == Rgba8{});
}

TEST_CASE("mask: recursion is broken where it closes — broken and degenerate masks", "[svg][mask]") {
  // resvg's rule: a reference back to a mask being applied counts as none; the rest still applies.
  const RenderedDocument self = render_square(
      40,
      "<mask id=\"m\"><rect width=\"40\" height=\"40\" fill=\"#808080\" mask=\"url(#m)\"/></mask>"
      "<rect width=\"40\" height=\"40\" " +
          kGreen + " mask=\"url(#m)\"/>");
  CHECK(self.image.at(20, 20) == Rgba8{0, 128, 0, 128});
  CHECK(contains(self.warnings, "closes a loop"));
  const RenderedDocument on_itself = render_square(
      40,
      "<mask id=\"m\" mask=\"url(#m)\"><rect width=\"40\" height=\"40\" fill=\"#808080\"/></mask>"
      "<rect width=\"40\" height=\"40\" " +
          kGreen + " mask=\"url(#m)\"/>");
  CHECK(on_itself.image.at(20, 20) == Rgba8{0, 128, 0, 128});
  const RenderedDocument mutual =
      render_square(40,
                    "<mask id=\"a\"><rect width=\"40\" height=\"40\" fill=\"white\" mask=\"url(#b)\"/></mask>"
                    "<mask id=\"b\"><rect width=\"40\" height=\"40\" fill=\"white\" mask=\"url(#a)\"/></mask>"
                    "<rect width=\"40\" height=\"40\" " +
                        kGreen + " mask=\"url(#a)\"/>");
  CHECK(mutual.image.at(20, 20) == Rgba8{0, 255, 0, 255});
  // Masks on masks that come back: a (first in the document) refers to b, whose reference back to a is
  // dropped, so an element masked by b is seen through b's white alone (resvg's rule, matching its
  // reference images; the grey of a would give 128).
  const RenderedDocument on_self = render_square(
      40,
      "<mask id=\"a\" mask=\"url(#b)\"><rect width=\"40\" height=\"40\" fill=\"#808080\"/></mask>"
      "<mask id=\"b\" mask=\"url(#a)\"><rect width=\"40\" height=\"40\" fill=\"white\"/></mask>"
      "<rect width=\"40\" height=\"40\" " +
          kGreen + " mask=\"url(#b)\"/>");
  CHECK(on_self.image.at(20, 20) == Rgba8{0, 255, 0, 255});
  // A missing mask: drawn unmasked, with a warning.
  const RenderedDocument missing =
      render_square(40, "<rect width=\"40\" height=\"40\" " + kGreen + " mask=\"url(#nope)\"/>");
  CHECK(missing.image.at(20, 20) == Rgba8{0, 255, 0, 255});
  CHECK(contains(missing.warnings, "'#nope'"));
  // An empty mask lets nothing through; a zero-sized region disables the element.
  CHECK(render_square(40, "<mask id=\"m\"/><rect width=\"40\" height=\"40\" fill=\"red\" mask=\"url(#m)\"/>")
            .image.at(20, 20) == Rgba8{});
  CHECK(render_square(40,
                      "<mask id=\"m\" width=\"0\"><rect width=\"40\" height=\"40\" fill=\"white\"/></mask>"
                      "<rect width=\"40\" height=\"40\" fill=\"red\" mask=\"url(#m)\"/>")
            .image.at(20, 20) == Rgba8{});
  // objectBoundingBox units on a horizontal line (a box without height): the element is not rendered.
  CHECK(
      render_square(
          40,
          "<mask id=\"m\"><rect width=\"40\" height=\"40\" fill=\"white\"/></mask>"
          "<line x1=\"0\" y1=\"20\" x2=\"40\" y2=\"20\" stroke=\"red\" stroke-width=\"4\" mask=\"url(#m)\"/>")
          .image.at(20, 20) == Rgba8{});
  // mask="none" is no mask.
  CHECK(
      render_square(40, "<rect width=\"40\" height=\"40\" " + kGreen + " mask=\"none\"/>").image.at(20, 20) ==
      Rgba8{0, 255, 0, 255});
}

TEST_CASE("mask: memory is charged to the render budget", "[svg][mask]") {
  const std::string xml = svg_document("width=\"40\" height=\"40\"",
                                       "<mask id=\"m\"><rect width=\"40\" height=\"40\" fill=\"white\"/>"
                                       "</mask><rect width=\"40\" height=\"40\" mask=\"url(#m)\"/>");
  const Result<Document> parsed = Document::parse(xml);
  REQUIRE(parsed);
  RenderOptions tight;
  // The parsed tree and the image fit, an offscreen mask does not.
  tight.limits.render.max_memory_bytes = parsed->memory_bytes() + 40 * 40 * 4 + 100;
  const Result<RenderedDocument> refused = render_svg_document(xml, tight);
  REQUIRE_FALSE(refused.is_ok());
  CHECK(refused.error().kind == ErrorKind::kLimitExceeded);
  CHECK(refused.error().message.find("mask") != std::string::npos);
}

TEST_CASE("mask: masks in patterns in masks are bounded in total work, not only in depth",
          "[svg][mask][limits]") {
  // Level i: mask m_i is filled with pattern p_i, whose tile holds four shapes masked by m_(i+1). Each
  // level is within the depth limits (8), but the images multiply: 4 + 16 + 64 + 256 + ... masks of the
  // output's size, each with a tile. Memory stays small (each image is freed before the next), so only a
  // bound on their sum stops it: 32 times the output's pixels, counted as at least 2^24 and at most
  // max_pixels (document.cpp), here 32 x 400 = 12800 pixels, some 16 images of this 20 x 20 output.
  std::string defs;
  const int levels = 5;
  for (int i = 0; i < levels; ++i) {
    const std::string next = std::to_string(i + 1);
    defs += "<mask id=\"m" + std::to_string(i) +
            "\" maskUnits=\"userSpaceOnUse\" x=\"0\" y=\"0\" width=\"20\" "
            "height=\"20\"><rect width=\"20\" height=\"20\" fill=\"url(#p" +
            std::to_string(i) + ")\"/></mask>";
    defs += "<pattern id=\"p" + std::to_string(i) +
            "\" width=\"20\" height=\"20\" patternUnits=\"userSpaceOnUse\">";
    for (int k = 0; k < 4; ++k)
      defs += "<rect width=\"20\" height=\"20\" fill=\"white\" mask=\"url(#m" + next + ")\"/>";
    defs += "</pattern>";
  }
  defs +=
      "<mask id=\"m" + std::to_string(levels) + "\"><rect width=\"20\" height=\"20\" fill=\"white\"/></mask>";
  const std::string xml =
      svg_document("width=\"20\" height=\"20\"",
                   defs + "<rect width=\"20\" height=\"20\" fill=\"green\" mask=\"url(#m0)\"/>");
  RenderOptions options;
  options.limits.max_pixels = 400;
  const Result<RenderedDocument> refused = render_svg_document(xml, options);
  REQUIRE_FALSE(refused.is_ok());
  CHECK(refused.error().kind == ErrorKind::kLimitExceeded);
  CHECK(refused.error().message.find("offscreen images of masks, clip paths and pattern tiles") !=
        std::string::npos);
  CHECK(refused.error().message.find("at most --max-pixels") != std::string::npos);
  // The same document within a larger bound: 4^1 + ... + 4^5 = 1364 masks and as many tiles of 400
  // pixels each, 1.1 million in all, below 32 x 40000. Every level lets white through: green.
  options.limits.max_pixels = 40000;
  const Result<RenderedDocument> drawn = render_svg_document(xml, options);
  REQUIRE(drawn.is_ok());
  CHECK(drawn->image.at(10, 10) == Rgba8{0, 128, 0, 255});
}
