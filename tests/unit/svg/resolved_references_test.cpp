// References resolved into objects (svg/resolved_references.h): each paint server read from the XML once
// per render and viewport, its href chain followed and its attributes settled in the resolved struct.
#include "svg/resolved_references.h"

#include <catch2/catch.hpp>
#include <pugixml.hpp>
#include <string>

#include "svg/cascade.h"
#include "svg/document_index.h"

using namespace curvescan;
using namespace curvescan::svg::detail;

namespace {

struct Resolved {
  pugi::xml_document xml;
  Diagnostics diagnostics;
  DocumentIndex index;
  ResolvedReferences references;

  explicit Resolved(const std::string& body) {
    const std::string text = "<svg xmlns=\"http://www.w3.org/2000/svg\">" + body + "</svg>";
    REQUIRE(xml.load_string(text.c_str()));
    Result<DocumentIndex> built =
        DocumentIndex::build(xml.document_element(), {"en"}, 1000, nullptr, diagnostics);
    REQUIRE(built.is_ok());
    index = std::move(built).value();
    references.reset(&index.ids());
  }

  pugi::xml_node by_id(const char* id) const {
    const auto found = index.ids().find(id);
    REQUIRE(found != index.ids().end());
    return found->second;
  }
};

const ResolveContext kViewport{200.0, 100.0, svg::Resolution{96.0, 96.0}};

int count_containing(const std::vector<std::string>& messages, const std::string& part) {
  int count = 0;
  for (const std::string& message : messages) count += message.find(part) != std::string::npos ? 1 : 0;
  return count;
}

}  // namespace

TEST_CASE("resolved references: a gradient used a thousand times is read once per viewport",
          "[svg][resolved_references]") {
  Resolved doc(
      "<linearGradient id='g' x1='10%' href='#missing'><stop offset='0' stop-color='red'/>"
      "</linearGradient>");
  const pugi::xml_node gradient = doc.by_id("g");
  const ResolvedGradient* first = &doc.references.gradient(gradient, kViewport, doc.diagnostics);
  for (int use = 1; use < 1000; ++use)
    CHECK(&doc.references.gradient(gradient, kViewport, doc.diagnostics) == first);
  CHECK(doc.references.resolved_count() == 1);
  // The href to nothing is said once, by the one resolution, not by every use.
  CHECK(count_containing(doc.diagnostics.warnings, "gradient href '#missing' does not exist") == 1);
  // Another viewport settles user-space percentages anew: a second object.
  const ResolveContext other{50.0, 100.0, svg::Resolution{96.0, 96.0}};
  CHECK(&doc.references.gradient(gradient, other, doc.diagnostics) != first);
  CHECK(doc.references.resolved_count() == 2);
  doc.references.reset(&doc.index.ids());
  CHECK(doc.references.resolved_count() == 0);
}

TEST_CASE("resolved references: a gradient's attributes come from its href chain, across kinds",
          "[svg][resolved_references]") {
  Resolved doc(
      "<radialGradient id='base' gradientUnits='userSpaceOnUse' spreadMethod='reflect' cx='7' fx='3'>"
      "<stop offset='0.25' stop-color='#ff0000' stop-opacity='0.5'/><stop offset='100%' stop-color='blue'/>"
      "</radialGradient>"
      "<linearGradient id='linear' href='#base' x2='50%'/>"
      "<radialGradient id='radial' href='#linear' r='20'/>"
      "<linearGradient id='a' href='#b'/><linearGradient id='b' href='#a'><stop "
      "offset='0'/></linearGradient>");
  const ResolvedGradient& linear = doc.references.gradient(doc.by_id("linear"), kViewport, doc.diagnostics);
  CHECK_FALSE(linear.radial);
  CHECK_FALSE(linear.bounding_box_units);  // gradientUnits and spreadMethod pass between kinds (13.2.2)
  CHECK(linear.spread == SpreadMethod::kReflect);
  REQUIRE(linear.stops.size() == 2);
  CHECK(linear.stops[0].offset == 0.25);
  CHECK(linear.stops[0].color.r == 1.0);
  CHECK(linear.stops[0].color.a == 0.5);  // stop-opacity folded in; the paint's opacity comes per use
  CHECK(linear.stops[1].color.b == 1.0);
  // User-space percentages of the 200 x 100 viewport; the defaults where nothing in the chain sets one.
  CHECK(linear.linear.end.x == 100.0);
  CHECK(linear.linear.start.x == 0.0);
  // The radial one skips the linear link's geometry but takes the radial base's (cx, fx), fy from cy.
  const ResolvedGradient& radial = doc.references.gradient(doc.by_id("radial"), kViewport, doc.diagnostics);
  CHECK(radial.radial);
  CHECK(radial.circle.center.x == 7.0);
  CHECK(radial.circle.focal.x == 3.0);
  CHECK(radial.circle.focal.y == radial.circle.center.y);
  CHECK(radial.circle.radius == 20.0);
  // A loop is cut where it closes, once, with a warning.
  const ResolvedGradient& looped = doc.references.gradient(doc.by_id("a"), kViewport, doc.diagnostics);
  CHECK(looped.stops.size() == 1);
  CHECK(count_containing(doc.diagnostics.warnings, "gradient href '#a' is circular") == 1);
}

TEST_CASE("resolved references: a pattern is read once and placed per box", "[svg][resolved_references]") {
  Resolved doc(
      "<pattern id='base' width='0.5' height='25%' patternTransform='scale(2)'><rect width='1' height='1'/>"
      "</pattern><pattern id='p' href='#base' x='0.1'/>");
  int styles = 0;
  const ReferencedStyle style_of = [&](const pugi::xml_node&) {
    ++styles;
    return ComputedStyle{};
  };
  const ResolvedPattern* first =
      &doc.references.pattern(doc.by_id("p"), kViewport, style_of, doc.diagnostics);
  for (int use = 1; use < 100; ++use)
    CHECK(&doc.references.pattern(doc.by_id("p"), kViewport, style_of, doc.diagnostics) == first);
  CHECK(styles == 1);  // the content's cascade, once
  CHECK(first->content == doc.by_id("base"));
  CHECK(first->transform == Affine::scale(2.0));
  // Placed on two boxes: fractions of each.
  const std::optional<PatternSetup> small = place_pattern(*first, Rect{0.0, 0.0, 10.0, 20.0});
  REQUIRE(small);
  CHECK(small->tile == Rect{1.0, 0.0, 6.0, 5.0});
  const std::optional<PatternSetup> large = place_pattern(*first, Rect{10.0, 10.0, 110.0, 210.0});
  REQUIRE(large);
  CHECK(large->tile == Rect{20.0, 10.0, 70.0, 60.0});
  // No box: objectBoundingBox units disable the pattern (SVG 1.1 7.11).
  CHECK_FALSE(place_pattern(*first, Rect{0.0, 0.0, 0.0, 5.0}));
}

TEST_CASE("resolved references: a clip path's units, transform and children are read once",
          "[svg][resolved_references]") {
  Resolved doc(
      "<clipPath id='c' clipPathUnits='objectBoundingBox' transform='scale(2)' clip-rule='evenodd'>"
      "<rect width='1' height='1'/><use href='#dot' x='5' y='6' clip-rule='nonzero'/><g><rect/></g>"
      "<rect display='none'/><circle visibility='hidden' r='1'/></clipPath>"
      "<circle id='dot' r='3'/><rect id='not-a-clip'/>");
  int styles = 0;
  ClipPathReader reader;
  reader.referenced_style = [&](const pugi::xml_node& node) {
    ++styles;
    return cascade_style(node, ComputedStyle{}, kViewport, doc.diagnostics);
  };
  reader.style = [&](const pugi::xml_node& node, const ComputedStyle& parent) {
    return cascade_style(node, parent, kViewport, doc.diagnostics);
  };
  reader.transform = [](const pugi::xml_node& node, double) {
    return std::string_view(node.attribute("transform").value()) == "scale(2)" ? Affine::scale(2.0)
                                                                               : Affine::identity();
  };
  reader.use_offset = [](const pugi::xml_node& use, const ComputedStyle&) {
    return Point{use.attribute("x").as_double(), use.attribute("y").as_double()};
  };
  reader.is_curve = [](const pugi::xml_node&) { return false; };
  const ResolvedClipPath* clip = doc.references.clip_path("c", kViewport, reader);
  REQUIRE(clip != nullptr);
  for (int use = 1; use < 100; ++use) CHECK(doc.references.clip_path("c", kViewport, reader) == clip);
  CHECK(styles == 1);
  CHECK(doc.references.resolved_count() == 1);
  CHECK(clip->bounding_box_units);
  CHECK(clip->transform == Affine::scale(2.0));
  // The rect, and the circle through the <use>; the group and the hidden children are left out (14.3.5).
  REQUIRE(clip->children.size() == 2);
  CHECK(clip->children[0].style.clip_rule == FillRule::kEvenOdd);  // inherited from the clipPath
  CHECK(clip->children[1].geometry == doc.by_id("dot"));
  CHECK(clip->children[1].style.clip_rule == FillRule::kNonZero);  // the <use>'s, inherited by its target
  CHECK(clip->children[1].transform == Affine::translate(5.0, 6.0));
  CHECK(doc.references.clip_path("not-a-clip", kViewport, reader) == nullptr);
  CHECK(doc.references.clip_path("nothing", kViewport, reader) == nullptr);
}

TEST_CASE("resolved references: a marker is read once and placed per stroke width",
          "[svg][resolved_references]") {
  Resolved doc(
      "<marker id='m' markerWidth='10' markerHeight='20' refX='5' refY='10' viewBox='0 0 5 10' "
      "orient='auto-start-reverse'><rect/></marker><marker id='flat' markerWidth='0'/><mask id='k'/>");
  int styles = 0;
  // The cascade's user-agent rule gives a <marker> overflow: hidden.
  const ReferencedStyle style_of = [&](const pugi::xml_node& node) {
    ++styles;
    return cascade_style(node, ComputedStyle{}, kViewport, doc.diagnostics);
  };
  const ResolvedMarker* marker = doc.references.marker("m", kViewport, style_of, doc.diagnostics);
  REQUIRE(marker != nullptr);
  for (int use = 1; use < 100; ++use)
    CHECK(doc.references.marker("m", kViewport, style_of, doc.diagnostics) == marker);
  CHECK(styles == 1);
  CHECK(marker->auto_start_reverse);
  CHECK_FALSE(marker->fixed_angle);
  CHECK(marker->ref == Point{10.0, 20.0});  // (5, 10) of the viewBox, scaled by 2 onto the 10 x 20 viewport
  // Placed for a stroke width of 3: the content scaled by 2 (viewBox) and 3 (markerUnits), the reference
  // point at the origin; overflow hidden clips to the viewport, shifted the same way.
  const std::optional<MarkerSetup> placed = place_marker(*marker, 3.0);
  REQUIRE(placed);
  CHECK(placed->content_to_frame.apply(Point{5.0, 10.0}) == Point{0.0, 0.0});
  CHECK(placed->content_to_frame.apply(Point{0.0, 0.0}) == Point{-30.0, -60.0});
  REQUIRE(placed->clip);
  CHECK(*placed->clip == Rect{-30.0, -60.0, 0.0, 0.0});
  const ResolvedMarker* flat = doc.references.marker("flat", kViewport, style_of, doc.diagnostics);
  REQUIRE(flat != nullptr);
  CHECK_FALSE(place_marker(*flat, 1.0));  // markerWidth 0 draws nothing
  CHECK(doc.references.marker("k", kViewport, style_of, doc.diagnostics) == nullptr);
}

TEST_CASE("resolved references: a mask is read once and placed per box", "[svg][resolved_references]") {
  Resolved doc(
      "<mask id='k' x='0' y='0' width='0.5' height='1' maskContentUnits='objectBoundingBox'/>"
      "<mask id='u' maskUnits='userSpaceOnUse' width='50%'/>");
  int styles = 0;
  const ReferencedStyle style_of = [&](const pugi::xml_node&) {
    ++styles;
    return ComputedStyle{};
  };
  const ResolvedMask* mask = doc.references.mask("k", kViewport, style_of, doc.diagnostics);
  REQUIRE(mask != nullptr);
  for (int use = 1; use < 100; ++use)
    CHECK(doc.references.mask("k", kViewport, style_of, doc.diagnostics) == mask);
  CHECK(styles == 1);
  const std::optional<MaskSetup> placed = place_mask(*mask, Rect{10.0, 20.0, 30.0, 60.0});
  REQUIRE(placed);
  CHECK(placed->region == Rect{10.0, 20.0, 20.0, 60.0});
  CHECK(placed->content_transform.apply(Point{1.0, 1.0}) == Point{30.0, 60.0});
  CHECK_FALSE(place_mask(*mask, Rect{10.0, 20.0, 10.0, 60.0}));  // bounding-box units, no area (7.11)
  // User space: the defaults are of the viewport (-10 % of 100 down), width 50 % of 200 across.
  const ResolvedMask* user = doc.references.mask("u", kViewport, style_of, doc.diagnostics);
  REQUIRE(user != nullptr);
  const std::optional<MaskSetup> user_placed = place_mask(*user, std::nullopt);
  REQUIRE(user_placed);
  CHECK(user_placed->region == Rect{-20.0, -10.0, 80.0, 110.0});
}
