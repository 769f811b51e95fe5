// clip-path on the children of a <clipPath> and on the <clipPath> itself, invalid children, loops, and
// clip-path, opacity and transform on the root <svg> (SVG 1.1 14.3.5, CSS Masking 1 6.1). Every region is
// a whole-pixel rectangle, so each checked pixel is fully inside or fully outside: exact values.
#include <catch2/catch.hpp>
#include <string>

#include "curvescan/raster/limits.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

const Rgba8 kGreen{0, 128, 0, 255};
const std::string kFill = "<rect width=\"40\" height=\"40\" fill=\"green\" clip-path=\"url(#c)\"/>";

}  // namespace

TEST_CASE("clipPath: a clip-path on a child clips that child only — the union of the children remains",
          "[svg][clip]") {
  // Child 1: 0..20 wide, clipped to rows 0..10. Child 2: 20..40, unclipped.
  const RenderedDocument doc =
      render_square(40,
                    "<clipPath id=\"top\"><rect width=\"40\" height=\"10\"/></clipPath>"
                    "<clipPath id=\"c\"><rect width=\"20\" height=\"40\" clip-path=\"url(#top)\"/>"
                    "<rect x=\"20\" width=\"20\" height=\"40\"/></clipPath>" +
                        kFill);
  CHECK(doc.image.at(10, 5) == kGreen);
  CHECK(doc.image.at(10, 30) == Rgba8{});
  CHECK(doc.image.at(30, 30) == kGreen);
}

TEST_CASE("clipPath: a clip-path on the clipPath element intersects, in the user space of the element",
          "[svg][clip]") {
  const RenderedDocument doc = render_square(
      40,
      "<clipPath id=\"left\"><rect width=\"20\" height=\"40\"/></clipPath>"
      "<clipPath id=\"c\" clip-path=\"url(#left)\"><rect y=\"20\" width=\"40\" height=\"20\"/></clipPath>"
      "<rect width=\"40\" height=\"40\" fill=\"green\" clip-path=\"url(#c)\" transform=\"translate(10 "
      "0)\"/>");
  // The element spans 10..50; both clips move with it: x 10..30, y 20..40.
  CHECK(doc.image.at(15, 30) == kGreen);
  CHECK(doc.image.at(35, 30) == Rgba8{});
  CHECK(doc.image.at(15, 10) == Rgba8{});
}

TEST_CASE("clipPath: children with different clip-rules keep their own rules", "[svg][clip]") {
  // A frame (two nested squares) with evenodd has a hole; a nonzero frame of the same winding does not.
  const std::string frame = "d=\"M0 0H20V40H0Z M5 15H15V25H5Z\"";
  const RenderedDocument doc = render_square(40, "<clipPath id=\"c\"><path " + frame +
                                                     " clip-rule=\"evenodd\"/>"
                                                     "<path transform=\"translate(20 0)\" " +
                                                     frame + "/></clipPath>" + kFill);
  CHECK(doc.image.at(10, 20) == Rgba8{});  // evenodd hole
  CHECK(doc.image.at(30, 20) == kGreen);   // nonzero: filled
  CHECK(doc.image.at(2, 2) == kGreen);
}

TEST_CASE("clipPath: <use> and <text> children count, groups do not — an empty clip hides everything",
          "[svg][clip]") {
  const RenderedDocument used =
      render_square(40,
                    "<defs><rect id=\"r\" width=\"10\" height=\"40\"/><g id=\"g\"><rect width=\"40\" "
                    "height=\"40\"/></g></defs>"
                    "<clipPath id=\"c\"><use href=\"#r\" x=\"5\"/><use href=\"#g\"/><g><rect width=\"40\" "
                    "height=\"40\"/></g>"
                    "</clipPath>" +
                        kFill);
  CHECK(used.image.at(10, 20) == kGreen);
  CHECK(used.image.at(20, 20) == Rgba8{});  // the group and the <use> of a group are not valid children
  CHECK(used.image.at(2, 20) == Rgba8{});
  CHECK(render_square(40, "<clipPath id=\"c\"/>" + kFill).image.at(20, 20) == Rgba8{});
  // A child clipped by an empty clipPath contributes nothing.
  CHECK(render_square(40,
                      "<clipPath id=\"none\"/><clipPath id=\"c\"><rect width=\"40\" height=\"40\" "
                      "clip-path=\"url(#none)\"/></clipPath>" +
                          kFill)
            .image.at(20, 20) == Rgba8{});
}

TEST_CASE("clipPath: loops are broken where they close — clip-rule inherits from the clipPath's ancestors",
          "[svg][clip]") {
  // c's child refers to c itself: that reference is ignored, the child clips as if unclipped.
  const RenderedDocument self = render_square(
      40, "<clipPath id=\"c\"><rect width=\"20\" height=\"40\" clip-path=\"url(#c)\"/></clipPath>" + kFill);
  CHECK(self.image.at(10, 20) == kGreen);
  CHECK(self.image.at(30, 20) == Rgba8{});
  CHECK(contains(self.warnings, "refers to itself"));
  const RenderedDocument on_itself = render_square(
      40, "<clipPath id=\"c\" clip-path=\"url(#c)\"><rect width=\"20\" height=\"40\"/></clipPath>" + kFill);
  CHECK(on_itself.image.at(10, 20) == kGreen);
  const RenderedDocument inherited =
      render_square(40,
                    "<g clip-rule=\"evenodd\"><clipPath id=\"c\"><path d=\"M0 0H40V40H0Z M10 "
                    "10H30V30H10Z\"/></clipPath></g>" +
                        kFill);
  CHECK(inherited.image.at(20, 20) == Rgba8{});
  CHECK(inherited.image.at(5, 5) == kGreen);
}

TEST_CASE("clipPath: objectBoundingBox units on a group use the group's box — on a line the element goes",
          "[svg][clip]") {
  const RenderedDocument group = render_square(
      40,
      "<clipPath id=\"c\" clipPathUnits=\"objectBoundingBox\"><rect width=\"0.5\" height=\"1\"/></clipPath>"
      "<g clip-path=\"url(#c)\"><rect x=\"10\" width=\"10\" height=\"40\" fill=\"green\"/>"
      "<rect x=\"20\" width=\"10\" height=\"40\" fill=\"green\"/></g>");
  CHECK(group.image.at(15, 20) == kGreen);
  CHECK(group.image.at(25, 20) == Rgba8{});
  CHECK(render_square(
            40,
            "<clipPath id=\"c\" clipPathUnits=\"objectBoundingBox\"><rect width=\"1\" height=\"1\"/>"
            "</clipPath><line x1=\"0\" y1=\"20\" x2=\"40\" y2=\"20\" stroke=\"green\" stroke-width=\"8\" "
            "clip-path=\"url(#c)\"/>")
            .image.at(20, 20) == Rgba8{});
}

TEST_CASE("root <svg>: clip-path, opacity and transform apply to the whole drawing", "[svg][clip]") {
  const RenderedDocument clipped = render_square(
      40,
      "<clipPath id=\"c\"><rect width=\"20\" height=\"40\"/></clipPath><rect width=\"40\" height=\"40\" "
      "fill=\"green\"/>",
      {}, "clip-path=\"url(#c)\"");
  CHECK(clipped.image.at(10, 20) == kGreen);
  CHECK(clipped.image.at(30, 20) == Rgba8{});
  // Two overlapping opaque rects under a root opacity of 0.5: one layer, alpha 128 everywhere.
  const RenderedDocument faded = render_square(
      40,
      "<rect width=\"30\" height=\"40\" fill=\"black\"/><rect x=\"10\" width=\"30\" height=\"40\" "
      "fill=\"black\"/>",
      {}, "opacity=\"0.5\"");
  CHECK(faded.image.at(5, 20).a == 128);
  CHECK(faded.image.at(20, 20).a == 128);
  const RenderedDocument moved = render_square(40, "<rect width=\"10\" height=\"10\" fill=\"green\"/>", {},
                                               "transform=\"translate(20 20)\"");
  CHECK(moved.image.at(25, 25) == kGreen);
  CHECK(moved.image.at(5, 5) == Rgba8{});
}

TEST_CASE("clipPath: a chain of clip-paths deeper than the clip limit hides its element, with a warning",
          "[svg][clip][limits]") {
  // clipPath c0 is clipped by c1, c1 by c2, ..., each the whole canvas: `links` clips in force at once. Up
  // to kMaxClipDepth (limits.h) they draw; one more and the clipped element is not drawn, the render goes
  // on (the unclipped square after it), and a warning says why in words.
  const auto chain = [](int links) {
    std::string defs;
    for (int i = 0; i < links; ++i) {
      defs += "<clipPath id=\"c" + std::to_string(i) + "\"" +
              (i + 1 < links ? " clip-path=\"url(#c" + std::to_string(i + 1) + ")\"" : std::string()) +
              "><rect width=\"40\" height=\"40\"/></clipPath>";
    }
    return render_square(40, defs +
                                 "<rect width=\"20\" height=\"40\" fill=\"green\" clip-path=\"url(#c0)\"/>" +
                                 "<rect x=\"20\" width=\"20\" height=\"40\" fill=\"green\"/>");
  };
  const RenderedDocument within = chain(kMaxClipDepth);
  CHECK(within.image.at(10, 20) == kGreen);
  CHECK(within.image.at(30, 20) == kGreen);
  CHECK_FALSE(contains(within.warnings, "nested more than"));
  const RenderedDocument beyond = chain(kMaxClipDepth + 1);
  CHECK(beyond.image.at(10, 20) == Rgba8{});
  CHECK(beyond.image.at(30, 20) == kGreen);
  CHECK(contains(beyond.warnings, "clip-paths nested more than 32 deep"));
  for (const std::string& warning : beyond.warnings) CHECK(warning.find("kMax") == std::string::npos);
}

TEST_CASE("clipPath: a mask beyond the clip limit hides its element too", "[svg][clip][mask][limits]") {
  // 32 groups each clipped by a whole-canvas clip-path hold every clip the canvas allows; a mask inside
  // them needs one more.
  std::string open, close;
  for (int i = 0; i < kMaxClipDepth; ++i) {
    open += "<g clip-path=\"url(#all)\">";
    close += "</g>";
  }
  const RenderedDocument doc = render_square(
      40,
      "<clipPath id=\"all\"><rect width=\"40\" height=\"40\"/></clipPath>"
      "<mask id=\"m\"><rect width=\"40\" height=\"40\" fill=\"white\"/></mask>" +
          open + "<rect width=\"20\" height=\"40\" fill=\"green\"/>" +
          "<rect x=\"20\" width=\"20\" height=\"40\" fill=\"green\" mask=\"url(#m)\"/>" + close);
  CHECK(doc.image.at(10, 20) == kGreen);
  CHECK(doc.image.at(30, 20) == Rgba8{});
  CHECK(contains(doc.warnings, "masks and clip-paths nested more than 32 deep"));
}

// Regression: a clip-path reference past the element-nesting limit was reported as referring to itself.
TEST_CASE("clipPath: a chain of clip-paths past --max-depth says the nesting limit was reached",
          "[svg][clip][limits]") {
  // c0 is clipped by c1, c1 by c2, ..., each the whole canvas, no loop: 8 links, each one level deeper.
  std::string defs;
  for (int i = 0; i < 8; ++i) {
    defs += "<clipPath id=\"c" + std::to_string(i) + "\"" +
            (i + 1 < 8 ? " clip-path=\"url(#c" + std::to_string(i + 1) + ")\"" : std::string()) +
            "><rect width=\"40\" height=\"40\"/></clipPath>";
  }
  const std::string text =
      svg_document("width=\"40\" height=\"40\"",
                   defs + "<rect width=\"40\" height=\"40\" fill=\"green\" clip-path=\"url(#c0)\"/>");
  const RenderedDocument unlimited = render(text);
  CHECK_FALSE(contains(unlimited.warnings, "nested more than"));
  RenderOptions options;
  options.limits.max_depth = 4;
  const RenderedDocument limited = render(text, options);
  CHECK(contains(limited.warnings, "is nested more than 4 deep (raise --max-depth)"));
  for (const std::string& warning : limited.warnings)
    CHECK(warning.find("refers to itself") == std::string::npos);
  // The links past the limit are ignored; those drawn clip to the whole canvas: the square is drawn.
  CHECK(limited.image.at(20, 20) == kGreen);
}

// The clipPath's own clip-path is in the referencing element's box too (CSS Masking 1 6.1): on a group, as
// on a shape, a userSpaceOnUse clipPath whose own clip-path is in objectBoundingBox units clips by both.
// (A group measured its box only when the first clipPath was in objectBoundingBox units, so the inner one
// found no box and hid the group.)
TEST_CASE("clip-path: a clipPath's own objectBoundingBox clip-path uses a group's box as a shape's") {
  const std::string defs =
      "<clipPath id=\"inner\" clipPathUnits=\"objectBoundingBox\"><rect width=\"0.5\" "
      "height=\"1\"/></clipPath>"
      "<clipPath id=\"outer\" clip-path=\"url(#inner)\"><rect width=\"80\" height=\"20\"/></clipPath>";
  for (const std::string& element :
       {std::string("<g clip-path=\"url(#outer)\"><rect width=\"40\" height=\"40\" fill=\"green\"/></g>"),
        std::string("<rect width=\"40\" height=\"40\" fill=\"green\" clip-path=\"url(#outer)\"/>")}) {
    INFO(element);
    const Image image = render(svg_document("width=\"40\" height=\"40\"", defs + element)).image;
    CHECK(image.at(10, 10) == kGreen);  // inside both: x < 20 (half the box), y < 20
    CHECK(image.at(30, 10).a == 0);     // outside the inner clip path only
    CHECK(image.at(10, 30).a == 0);     // outside the outer clip path only
  }
}
