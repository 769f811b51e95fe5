// The markers of the render tree's Path node (svg/placed_marker.h): what path_node places for a shape --
// for each vertex that gets a marker, the <marker> object, the vertex, the orientation, the content's
// mapping (markerUnits, viewBox, refX/refY) and the overflow clip -- read from the node as the drawing
// walk makes it (path_node_probe.h), not from pixels.
#include <catch2/catch.hpp>
#include <map>
#include <string>
#include <vector>

#include "svg/path_node_probe.h"
#include "svg/placed_marker.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::detail;
using curvescan::svg::testing::check_maps;

namespace {

// What a test reads of one placed marker, copied while the node lives.
struct SeenMarker {
  std::string id;  // the <marker>'s id
  const void* object = nullptr;
  Point position;
  double angle = 0.0;
  Affine placement;  // content to the path's user space: the vertex frame, then content_to_frame
  std::optional<Rect> clip;
};

// The markers placed on each shape of a render of `body` in a 100 x 100 document, by the shape's id.
std::map<std::string, std::vector<SeenMarker>> markers_of(const std::string& body) {
  std::map<std::string, std::vector<SeenMarker>> seen;
  const Result<RenderedDocument> rendered = render_probing_paths(
      testing::svg_document("width=\"100\" height=\"100\"", body), RenderOptions{},
      [&](const pugi::xml_node& element, const PathNode& node) {
        std::vector<SeenMarker>& markers = seen[element.attribute("id").value()];
        if (!node.markers) return;  // none placed
        REQUIRE_FALSE(node.markers->placed.empty());
        for (const PlacedMarker& placed : node.markers->placed) {
          markers.push_back({placed.marker->element.attribute("id").value(), placed.marker, placed.position,
                             placed.angle, placed.frame_under(Affine::identity()) * placed.content_to_frame,
                             placed.clip});
        }
      });
  REQUIRE(rendered.is_ok());
  return seen;
}

}  // namespace

TEST_CASE("path_node: start, mid and end markers placed on the vertices, each marker read once",
          "[svg][render_tree][path][marker]") {
  // A right turn: (10,10) -> (30,10) -> (30,30); orient auto on s and e, a fixed 45deg on m.
  const auto seen = markers_of(
      "<marker id=\"s\" orient=\"auto\"><rect width=\"1\" height=\"1\"/></marker>"
      "<marker id=\"m\" orient=\"45\"><rect width=\"1\" height=\"1\"/></marker>"
      "<marker id=\"e\" orient=\"auto\"><rect width=\"1\" height=\"1\"/></marker>"
      "<polyline id=\"p\" points=\"10 10 30 10 30 30 50 30\" fill=\"none\" stroke=\"black\" "
      "marker-start=\"url(#s)\" marker-mid=\"url(#m)\" marker-end=\"url(#e)\"/>"
      "<rect id=\"plain\" width=\"5\" height=\"5\"/>");
  const std::vector<SeenMarker>& p = seen.at("p");
  REQUIRE(p.size() == 4);
  CHECK(p[0].id == "s");
  CHECK(p[0].position == Point{10.0, 10.0});
  CHECK(p[0].angle == 0.0);  // the first segment's direction
  CHECK(p[1].id == "m");
  CHECK(p[1].position == Point{30.0, 10.0});
  CHECK(p[1].angle == 45.0);  // orient's angle, not the vertex's
  CHECK(p[2].id == "m");
  CHECK(p[2].object == p[1].object);  // one object for every vertex it marks
  CHECK(p[2].position == Point{30.0, 30.0});
  CHECK(p[3].id == "e");
  CHECK(p[3].position == Point{50.0, 30.0});
  CHECK(p[3].angle == 0.0);  // the last segment's direction
  // Default markerUnits (strokeWidth, 1 here), no viewBox, refX/refY 0: the content's origin at the vertex.
  check_maps(p[0].placement, Point{0.0, 0.0}, Point{10.0, 10.0});
  // overflow hidden (the UA default): the 3 x 3 viewport clips.
  REQUIRE(p[0].clip);
  CHECK(*p[0].clip == Rect{0.0, 0.0, 3.0, 3.0});
  // A shape without marker properties places none.
  CHECK(seen.at("plain").empty());
}

TEST_CASE("path_node: orient auto-start-reverse turns the start marker only",
          "[svg][render_tree][path][marker]") {
  const auto seen = markers_of(
      "<marker id=\"a\" orient=\"auto-start-reverse\" style=\"overflow: visible\">"
      "<path d=\"M0 0 L2 0\"/></marker>"
      "<path id=\"p\" d=\"M10 10 L10 30\" stroke=\"black\" marker-start=\"url(#a)\" "
      "marker-end=\"url(#a)\"/>");
  const std::vector<SeenMarker>& p = seen.at("p");
  REQUIRE(p.size() == 2);
  CHECK(p[0].angle == Approx(270.0));  // down (90deg) reversed
  CHECK(p[1].angle == Approx(90.0));
  // The content's +x points up at the start, down at the end.
  check_maps(p[0].placement, Point{2.0, 0.0}, Point{10.0, 8.0});
  check_maps(p[1].placement, Point{2.0, 0.0}, Point{10.0, 32.0});
  CHECK_FALSE(p[0].clip);  // overflow visible: no clip
}

TEST_CASE("path_node: markerUnits strokeWidth scales the content, userSpaceOnUse does not",
          "[svg][render_tree][path][marker]") {
  const auto seen = markers_of(
      "<marker id=\"w\" markerWidth=\"4\" markerHeight=\"2\" refX=\"1\" refY=\"1\">"
      "<rect width=\"4\" height=\"2\"/></marker>"
      "<marker id=\"u\" markerUnits=\"userSpaceOnUse\" markerWidth=\"4\" markerHeight=\"2\" refX=\"1\" "
      "refY=\"1\"><rect width=\"4\" height=\"2\"/></marker>"
      "<line id=\"sw\" x1=\"10\" y1=\"50\" x2=\"90\" y2=\"50\" stroke=\"black\" stroke-width=\"3\" "
      "marker-end=\"url(#w)\"/>"
      "<line id=\"us\" x1=\"10\" y1=\"50\" x2=\"90\" y2=\"50\" stroke=\"black\" stroke-width=\"3\" "
      "marker-end=\"url(#u)\"/>");
  const SeenMarker& sw = seen.at("sw").at(0);
  // (refX, refY) at the vertex, the content scaled by the stroke width 3.
  check_maps(sw.placement, Point{1.0, 1.0}, Point{90.0, 50.0});
  check_maps(sw.placement, Point{4.0, 2.0}, Point{99.0, 53.0});
  REQUIRE(sw.clip);
  CHECK(*sw.clip == Rect{-3.0, -3.0, 9.0, 3.0});  // the 4 x 2 viewport, shifted by the ref, times 3
  const SeenMarker& us = seen.at("us").at(0);
  check_maps(us.placement, Point{1.0, 1.0}, Point{90.0, 50.0});
  check_maps(us.placement, Point{4.0, 2.0}, Point{93.0, 51.0});
  REQUIRE(us.clip);
  CHECK(*us.clip == Rect{-1.0, -1.0, 3.0, 1.0});
}

TEST_CASE("path_node: a viewBox'd marker maps its content onto its viewport, refX/refY in viewBox units",
          "[svg][render_tree][path][marker]") {
  // viewBox 0 0 20 10 onto a 4 x 2 viewport (markerUnits userSpaceOnUse): a scale of 1/5; the reference
  // point (10, 5) of the content, the viewBox's centre, goes to the vertex.
  const auto seen = markers_of(
      "<marker id=\"v\" markerUnits=\"userSpaceOnUse\" markerWidth=\"4\" markerHeight=\"2\" "
      "viewBox=\"0 0 20 10\" refX=\"10\" refY=\"5\"><rect width=\"20\" height=\"10\"/></marker>"
      "<line id=\"l\" x1=\"10\" y1=\"20\" x2=\"40\" y2=\"20\" marker-start=\"url(#v)\"/>");
  const SeenMarker& l = seen.at("l").at(0);
  CHECK(l.position == Point{10.0, 20.0});
  check_maps(l.placement, Point{10.0, 5.0}, Point{10.0, 20.0});
  check_maps(l.placement, Point{20.0, 10.0}, Point{12.0, 21.0});
  check_maps(l.placement, Point{0.0, 0.0}, Point{8.0, 19.0});
  REQUIRE(l.clip);
  CHECK(*l.clip == Rect{-2.0, -1.0, 2.0, 1.0});  // the viewport about the reference point
}

TEST_CASE("path_node: a zero-length subpath gets its markers, oriented along no direction (0)",
          "[svg][render_tree][path][marker]") {
  // One subpath of no length: the moveto's vertex and the segment's, at the same point; neither has a
  // direction.
  const auto seen = markers_of(
      "<marker id=\"m\" orient=\"auto\"><rect width=\"1\" height=\"1\"/></marker>"
      "<path id=\"dot\" d=\"M50 50 L50 50\" stroke=\"black\" stroke-linecap=\"round\" "
      "marker-start=\"url(#m)\" marker-end=\"url(#m)\"/>");
  const std::vector<SeenMarker>& dot = seen.at("dot");
  REQUIRE(dot.size() == 2);
  for (const SeenMarker& marker : dot) {
    CHECK(marker.position == Point{50.0, 50.0});
    CHECK(marker.angle == 0.0);
  }
}

TEST_CASE("path_node: no markers on a marker inside its own content, nor from a reference to no <marker>",
          "[svg][render_tree][path][marker]") {
  const auto seen = markers_of(
      "<marker id=\"self\" style=\"overflow: visible\"><path id=\"inner\" d=\"M0 0 L1 0\" "
      "marker-end=\"url(#self)\"/></marker>"
      "<linearGradient id=\"g\"/>"
      "<path id=\"outer\" d=\"M10 10 L20 10\" marker-end=\"url(#self)\"/>"
      "<path id=\"wrong\" d=\"M10 10 L20 10\" marker-end=\"url(#g)\"/>");
  CHECK(seen.at("outer").size() == 1);
  // The marker's own path is drawn once, inside the marker: its node places no marker in itself.
  CHECK(seen.at("inner").empty());
  CHECK(seen.at("wrong").empty());
}

TEST_CASE("path_node: a marker reference is read with the node, before the fill's pattern tile is drawn",
          "[svg][render_tree][path][marker]") {
  // The markers are placed when the node is made, with its paints; a pattern's tile is drawn with the
  // fill. So a warning about the marker reference comes before one about the tile's content, whatever
  // the paint order (docs/svg.md, "Where the code is today").
  const RenderedDocument rendered = testing::render(
      testing::svg_document("width=\"100\" height=\"100\"",
                            "<pattern id=\"p\" width=\"10\" height=\"10\" patternUnits=\"userSpaceOnUse\">"
                            "<rect width=\"5\" height=\"5\" transform=\"bogus(1)\"/></pattern>"
                            "<linearGradient id=\"g\"/>"
                            "<rect width=\"50\" height=\"50\" fill=\"url(#p)\" marker-end=\"url(#g)\"/>"));
  REQUIRE(rendered.warnings.size() == 2);
  CHECK(rendered.warnings[0].find("marker refers to '#g', which is not a <marker>") != std::string::npos);
  CHECK(rendered.warnings[1].find("bogus") != std::string::npos);
}
