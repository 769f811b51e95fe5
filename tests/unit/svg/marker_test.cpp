// <marker> (SVG 1.1 11.6, SVG 2 11.6): vertices and their orientation from the geometry, and the marker's
// placement checked with pixels. Markers here are axis-aligned squares on whole pixels (or rotated by a
// multiple of 90 degrees), so each checked pixel is fully inside or outside: exact values.
#include "svg/marker.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <tuple>

#include "curvescan/raster/path_builder.h"
#include "curvescan/svg/path_data.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

const Rgba8 kBlue{0, 0, 255, 255};

// A marker whose content is a 4 x 2 blue bar to the right of the vertex (0..4, -1..1 in marker units):
// its direction shows the orientation.
const std::string kBar =
    "<marker id=\"m\" markerUnits=\"userSpaceOnUse\" markerWidth=\"8\" markerHeight=\"8\" refX=\"4\" "
    "refY=\"4\" "
    "viewBox=\"0 0 8 8\" overflow=\"visible\" ORIENT><rect x=\"4\" y=\"3\" width=\"4\" height=\"2\" "
    "fill=\"blue\"/>"
    "</marker>";

std::string bar(const std::string& orient) {
  std::string text = kBar;
  text.replace(text.find("ORIENT"), 6, orient);
  return text;
}

}  // namespace

TEST_CASE("marker vertices: one per moveto and segment end, closepath included, auto angles",
          "[svg][marker]") {
  const Path path = *PathBuilder().move_to({0, 0}).line_to({10, 0}).line_to({10, 10}).close().build();
  const std::vector<svg::detail::MarkerVertex> v = svg::detail::marker_vertices(path, true);
  REQUIRE(v.size() == 4);
  CHECK(v[0].position == Point{0, 0});
  CHECK(v[0].angle == Approx(0.0));                                   // outgoing only
  CHECK(v[1].angle == Approx(45.0));                                  // bisects 0 and 90
  CHECK(v[2].angle == Approx(180.0 - 22.5).margin(1e-9).epsilon(0));  // 90 in, 225 out (the closing line)
  CHECK(v[3].position == Point{0, 0});
  CHECK(v[3].angle == Approx(-135.0));  // incoming only: the closing line points up-left
  // Pieces of one arc are one segment in path data; kept apart for basic shapes.
  PathBuilder arc;
  arc.move_to({10, 0}).arc({0, 0}, 10, 10, 0.0, 0.0, 3.14159265358979 * 1.5);
  const Path built = *arc.build();
  CHECK(svg::detail::marker_vertices(built, true).size() == 2);
  CHECK(svg::detail::marker_vertices(built, false).size() > 2);
}

TEST_CASE("marker: start, mid and end on a polyline — orient auto, angles and auto-start-reverse",
          "[svg][marker]") {
  // Vertices (10,10) (30,10) (30,30). Fixed orient 0: every bar points right of its vertex.
  const std::string line =
      "<polyline points=\"10 10 30 10 30 30\" fill=\"none\" marker-start=\"url(#m)\" "
      "marker-mid=\"url(#m)\" marker-end=\"url(#m)\"/>";
  const RenderedDocument fixed = render_square(40, bar("") + line);
  CHECK(fixed.image.at(12, 10) == kBlue);
  CHECK(fixed.image.at(32, 10) == kBlue);
  CHECK(fixed.image.at(32, 30) == kBlue);
  CHECK(fixed.image.at(8, 10) == Rgba8{});
  // auto: the end vertex comes in downwards, so its bar points down.
  const RenderedDocument automatic = render_square(40, bar("orient=\"auto\"") + line);
  CHECK(automatic.image.at(30, 32) == kBlue);
  CHECK(automatic.image.at(32, 30) == Rgba8{});
  CHECK(automatic.image.at(12, 10) == kBlue);  // start: outgoing to the right
  // auto-start-reverse: the start bar points back, to the left.
  const RenderedDocument reversed = render_square(40, bar("orient=\"auto-start-reverse\"") + line);
  CHECK(reversed.image.at(8, 10) == kBlue);
  CHECK(reversed.image.at(12, 10) == Rgba8{});
  // A fixed angle with a unit: 0.25turn = 90 degrees, the bars point down.
  const RenderedDocument turned = render_square(40, bar("orient=\"0.25turn\"") + line);
  CHECK(turned.image.at(10, 12) == kBlue);
  CHECK(turned.image.at(12, 10) == Rgba8{});
}

TEST_CASE("marker: markerUnits=strokeWidth scales, the viewport clips unless overflow is visible",
          "[svg][marker]") {
  // Default units: stroke-width 2 doubles the marker: a 2 x 2 square at refX/refY 0 becomes 4 x 4.
  const RenderedDocument scaled = render_square(
      40,
      "<marker id=\"m\" markerWidth=\"2\" markerHeight=\"2\"><rect width=\"2\" height=\"2\" "
      "fill=\"blue\"/></marker>"
      "<line x1=\"10\" y1=\"10\" x2=\"30\" y2=\"10\" stroke-width=\"2\" marker-end=\"url(#m)\"/>");
  CHECK(scaled.image.at(33, 13) == kBlue);
  CHECK(scaled.image.at(35, 13) == Rgba8{});
  // Content larger than the 2 x 2 viewport is clipped to it; with overflow="visible" it shows.
  const std::string big =
      "<rect width=\"6\" height=\"6\" fill=\"blue\"/></marker>"
      "<line x1=\"10\" y1=\"10\" x2=\"30\" y2=\"10\" marker-end=\"url(#m)\"/>";
  const RenderedDocument clipped = render_square(
      40, "<marker id=\"m\" markerUnits=\"userSpaceOnUse\" markerWidth=\"2\" markerHeight=\"2\">" + big);
  CHECK(clipped.image.at(31, 11) == kBlue);
  CHECK(clipped.image.at(33, 13) == Rgba8{});
  const RenderedDocument visible =
      render_square(40,
                    "<marker id=\"m\" markerUnits=\"userSpaceOnUse\" markerWidth=\"2\" markerHeight=\"2\" "
                    "overflow=\"visible\">" +
                        big);
  CHECK(visible.image.at(33, 13) == kBlue);
}

TEST_CASE("marker: shapes take markers — the marker shorthand is CSS only — bad references and recursion",
          "[svg][marker]") {
  const std::string marker =
      "<marker id=\"m\" markerUnits=\"userSpaceOnUse\" markerWidth=\"2\" markerHeight=\"2\" refX=\"1\" "
      "refY=\"1\">"
      "<rect width=\"2\" height=\"2\" fill=\"blue\"/></marker>";
  // A rect's vertices are its corners.
  const RenderedDocument rect = render_square(
      40,
      marker + "<rect x=\"10\" y=\"10\" width=\"20\" height=\"20\" fill=\"none\" marker-mid=\"url(#m)\"/>");
  CHECK(rect.image.at(30, 10) == kBlue);
  CHECK(rect.image.at(30, 30) == kBlue);
  CHECK(rect.image.at(20, 10) == Rgba8{});
  const std::string line = "<line x1=\"10\" y1=\"10\" x2=\"30\" y2=\"10\" ";
  CHECK(render_square(40, marker + line + "style=\"marker: url(#m)\"/>").image.at(30, 10) == kBlue);
  CHECK(render_square(40, marker + line + "marker=\"url(#m)\"/>").image.at(30, 10) == Rgba8{});
  // marker-end is inherited.
  CHECK(render_square(40, marker + "<g marker-end=\"url(#m)\">" + line + "/></g>").image.at(30, 10) == kBlue);
  const RenderedDocument missing = render_square(40, line + "marker-end=\"url(#nope)\"/>");
  CHECK(contains(missing.warnings, "'#nope'"));
  // A marker whose content carries the same marker: drawn once, not forever.
  const RenderedDocument recursive = render_square(
      40,
      "<marker id=\"m\" markerUnits=\"userSpaceOnUse\" markerWidth=\"4\" markerHeight=\"4\">"
      "<line x1=\"0\" y1=\"1\" x2=\"2\" y2=\"1\" stroke=\"blue\" marker-end=\"url(#m)\"/></marker>" +
          line + "marker-end=\"url(#m)\"/>");
  CHECK(recursive.image.at(31, 11).a > 0);
}

// Regression: a cubic whose first (last) control point coincides with its start (end), exactly or within
// 1e-9 (a line or a corner drawn as a curve), gave orient="auto" the direction towards that point (45
// degrees for the 1e-9 offset) instead of the next control point's, SVG 2 "Path directionality".
TEST_CASE("marker: auto orientation skips control points coincident with the vertex, as the caps do",
          "[svg][marker]") {
  // Start direction (30,10) - (10,20) = (20,-10); end direction (30,20) - (15,30) = (15,-10).
  const double start_degrees = std::atan2(-10.0, 20.0) * 180.0 / std::numbers::pi;
  const double end_degrees = std::atan2(-10.0, 15.0) * 180.0 / std::numbers::pi;
  for (const std::string near : {"", ".000000001"}) {
    const std::string start_curve = "M10 20 C10" + near + " 20" + near + " 30 10 30 20";
    const std::string end_curve = "M10 20 C15 30 30" + near + " 20" + near + " 30 20";
    CAPTURE(near);
    PathBuilder start_builder, end_builder;
    REQUIRE_FALSE(append_path_data(start_curve, start_builder));
    REQUIRE_FALSE(append_path_data(end_curve, end_builder));
    const Path start_path = *start_builder.build();
    const Path end_path = *end_builder.build();
    // 0.25 / 64: the default tolerance's coincident length in an unscaled user space.
    CHECK(svg::detail::marker_vertices(start_path, true, 0.25 / 64).front().angle ==
          Approx(start_degrees).margin(1e-12));
    CHECK(svg::detail::marker_vertices(end_path, true, 0.25 / 64).back().angle ==
          Approx(end_degrees).margin(1e-12));

    // Drawn: an asymmetric marker (a bar with a notch on one side) with orient="auto" on the curve, and
    // the same marker with the angle computed above given as a fixed orient on the same curve.
    const auto marked = [](const std::string& d, const std::string& which, const std::string& orient) {
      return render_square(
          40,
          "<marker id=\"m\" markerUnits=\"userSpaceOnUse\" markerWidth=\"12\" markerHeight=\"12\" "
          "refX=\"0\" refY=\"0\" viewBox=\"0 0 12 12\" overflow=\"visible\" orient=\"" +
              orient +
              "\"><path d=\"M0 -1 H9 L12 -4 V1 H0 Z\" fill=\"blue\"/></marker>"
              "<path d=\"" +
              d + "\" fill=\"none\" " + which + "=\"url(#m)\"/>");
    };
    char start_text[64], end_text[64];
    std::snprintf(start_text, sizeof start_text, "%.17g", start_degrees);
    std::snprintf(end_text, sizeof end_text, "%.17g", end_degrees);
    for (const auto& [d, which, fixed] :
         {std::tuple{start_curve, std::string("marker-start"), std::string(start_text)},
          std::tuple{end_curve, std::string("marker-end"), std::string(end_text)}}) {
      const RenderedDocument automatic = marked(d, which, "auto");
      const RenderedDocument by_hand = marked(d, which, fixed);
      REQUIRE(inked_pixels(by_hand.image) > 10);
      // The angle goes through "%.17g" and back (exact to the last bit or two of a double): the marker's
      // edges move by ~1e-14 px, which can change an 8-bit coverage value by at most one step.
      CHECK(max_delta(automatic.image, by_hand.image) <= 1);
      // The check can fail: the direction towards the coincident point (45 degrees for the 1e-9 offset)
      // or the start direction reversed draws elsewhere.
      CHECK(max_delta(marked(d, which, "45").image, by_hand.image) > 100);
    }
  }
}

// Regression (resvg's painting/marker/recursive-5): a <use> inside a marker that shows the marked element
// again was refused as a circular <use> when the marked element was itself drawn through a <use>. The
// marker's content is a drawing of its own (SVG 2 11.6.2), not inside that <use>'s tree; the recursion is cut
// where a marker would be drawn inside itself, as browsers cut it. Here the top-level <use> draws #p at
// (20, 20); its start marker m1 draws #p again 5 lower, whose own m1 is cut (drawn, it would add a square
// 5 lower again) and whose end marker m2 (a 4 x 4 green square) is drawn at (30, 25). Whole pixels: exact.
TEST_CASE(
    "marker: a <use> in a marker may show the marked element again, but a marker is not drawn in itself",
    "[svg][marker]") {
  const RenderedDocument out =
      render_square(40,
                    "<defs>"
                    "<marker id=\"m1\" markerUnits=\"userSpaceOnUse\" overflow=\"visible\"><use href=\"#p\" "
                    "y=\"5\"/></marker>"
                    "<marker id=\"m2\" markerUnits=\"userSpaceOnUse\" overflow=\"visible\">"
                    "<rect width=\"4\" height=\"4\" fill=\"green\"/></marker>"
                    "<path id=\"p\" d=\"M 0 0 L 10 0\" marker-start=\"url(#m1)\" marker-end=\"url(#m2)\"/>"
                    "</defs><use href=\"#p\" x=\"20\" y=\"20\"/>");
  const Rgba8 green{0, 128, 0, 255};
  CHECK(out.image.at(32, 22) == green);    // the outer #p's end marker
  CHECK(out.image.at(32, 27) == green);    // the end marker of #p drawn inside m1
  CHECK(out.image.at(32, 32) == Rgba8{});  // m1 is not drawn inside itself
  CHECK(out.image.at(32, 17) == Rgba8{});
  for (const std::string& warning : out.warnings) CHECK(warning.find("circular") == std::string::npos);
}
