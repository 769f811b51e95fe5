// References resolved into objects (svg/resolved_references.h): each paint server, clip path, marker, mask
// and filter read from the XML once per render and viewport, its href chain followed and its attributes
// settled in the resolved struct.
#include "svg/resolved_references.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <pugixml.hpp>
#include <string>
#include <variant>
#include <vector>

#include "svg/cascade.h"
#include "svg/document_index.h"
#include "svg/filter/filter_region.h"
#include "svg/filter/resolved_filter.h"
#include "svg/shape_paths.h"

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

// The style of a referenced element, for filters whose feImage refers to none.
const ReferencedStyle no_style = [](const pugi::xml_node&) { return ComputedStyle{}; };

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
  // The outlines are built with the clip path: a stand-in path per child (a square as wide as its
  // position in the calls), its rule from its style, and the elements asked for.
  std::vector<pugi::xml_node> outlined;
  reader.outline = [&](const pugi::xml_node& geometry, const ComputedStyle& style, const ComputedStyle&) {
    outlined.push_back(geometry);
    const double side = static_cast<double>(outlined.size());
    return std::optional<ClipOutline>(
        ClipOutline{rect_path(0.0, 0.0, side, side, std::nullopt, std::nullopt).value(), style.clip_rule});
  };
  const ResolvedClipPath* clip = doc.references.clip_path("c", kViewport, reader);
  REQUIRE(clip != nullptr);
  for (int use = 1; use < 100; ++use) CHECK(doc.references.clip_path("c", kViewport, reader) == clip);
  CHECK(styles == 1);
  CHECK(doc.references.resolved_count() == 1);
  CHECK(clip->bounding_box_units);
  CHECK(clip->transform == Affine::scale(2.0));
  // The rect, and the circle through the <use>; the group and the hidden children are left out (14.3.5).
  REQUIRE(clip->children.size() == 2);
  REQUIRE(outlined.size() == 2);  // once each, for the hundred uses
  CHECK(outlined[0] == doc.by_id("c").first_child());
  CHECK(outlined[1] == doc.by_id("dot"));
  REQUIRE(clip->children[0].outline);
  REQUIRE(clip->children[1].outline);
  CHECK(clip->children[0].outline->path.tight_bounds() == Rect{0.0, 0.0, 1.0, 1.0});
  CHECK(clip->children[1].outline->path.tight_bounds() == Rect{0.0, 0.0, 2.0, 2.0});
  CHECK(clip->children[0].outline->rule == FillRule::kEvenOdd);  // inherited from the clipPath
  CHECK(clip->children[1].outline->rule == FillRule::kNonZero);  // the <use>'s, inherited by its target
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

TEST_CASE("resolved references: a filter used by five hundred elements is read once",
          "[svg][resolved_references][filter]") {
  std::string body =
      "<filter id='f' x='oops'><feGaussianBlur stdDeviation='2'/><feOffset dx='3' dy='zz'/>"
      "<feMerge><feMergeNode/><feMergeNode in='SourceGraphic'/></feMerge></filter><g id='not-a-filter'/>";
  // Five hundred: the test document's element limit is 1 000.
  for (int i = 0; i < 500; ++i) body += "<rect width='5' height='5' filter='url(#f)'/>";
  Resolved doc(body);
  const filter::ResolvedFilter* first = nullptr;
  int uses = 0;
  for (pugi::xml_node rect = doc.xml.document_element().child("rect"); rect;
       rect = rect.next_sibling("rect")) {
    std::string_view reference = rect.attribute("filter").value();  // url(#f)
    reference = reference.substr(5, reference.size() - 6);
    const filter::ResolvedFilter* resolved =
        doc.references.filter(std::string(reference), kViewport, nullptr, no_style, doc.diagnostics);
    REQUIRE(resolved != nullptr);
    if (first == nullptr) first = resolved;
    CHECK(resolved == first);
    ++uses;
  }
  CHECK(uses == 500);
  CHECK(doc.references.resolved_count() == 1);
  // Every attribute was read by the one resolution: each warning once, not once per use.
  CHECK(count_containing(doc.diagnostics.warnings, "<filter> x:") == 1);
  CHECK(count_containing(doc.diagnostics.warnings, "<feOffset> dy 'zz' is not a number") == 1);
  // The primitives with their values and their plan.
  REQUIRE(first->primitives.size() == 3);
  const auto* blur = std::get_if<filter::BlurParams>(&first->primitives[0].params);
  REQUIRE(blur != nullptr);
  CHECK(blur->sigma_x == 2.0);
  CHECK(blur->sigma_y == 2.0);
  const auto* offset = std::get_if<filter::OffsetParams>(&first->primitives[1].params);
  REQUIRE(offset != nullptr);
  CHECK(offset->dx == 3.0);
  CHECK(offset->dy == 0.0);  // not a number: as if not given
  CHECK(first->primitives[0].last_use == 1);
  REQUIRE(first->primitives[2].inputs.size() == 2);
  CHECK(first->primitives[2].inputs[0].producer == 1);
  CHECK(first->primitives[2].inputs[1].standard == "SourceGraphic");
  CHECK(first->passes == 5);  // two primitives, and the merge with its two nodes
  // The invalid x is the default: -10 % of each box it is placed on.
  const std::optional<filter::FilterDefinition> placed =
      filter::place_filter(*first, Rect{0.0, 0.0, 10.0, 20.0});
  REQUIRE(placed);
  // Approx: -0.1 and 1.2 are not exact in binary, so 0 + (-0.1 + 1.2) * 20 is 22 to within an ulp or two.
  CHECK(placed->region.x0 == Approx(-1.0));
  CHECK(placed->region.y1 == Approx(22.0));
  // No box: objectBoundingBox filterUnits disable the element's rendering (SVG 1.1 7.11).
  CHECK_FALSE(filter::place_filter(*first, std::nullopt));
  CHECK(doc.references.filter("nothing", kViewport, nullptr, no_style, doc.diagnostics) == nullptr);
  CHECK(doc.references.filter("not-a-filter", kViewport, nullptr, no_style, doc.diagnostics) == nullptr);
}

TEST_CASE("resolved references: a filter's href chain is followed with its loop cut, once",
          "[svg][resolved_references][filter]") {
  Resolved doc(
      "<filter id='a' href='#b' primitiveUnits='objectBoundingBox'/>"
      "<filter id='b' href='#a' x='0' width='2' filterUnits='userSpaceOnUse'><feFlood flood-color='lime'/>"
      "<feComposite k1='nope'/></filter>");
  const filter::ResolvedFilter* a = doc.references.filter("a", kViewport, nullptr, no_style, doc.diagnostics);
  REQUIRE(a != nullptr);
  for (int use = 1; use < 10; ++use)
    CHECK(doc.references.filter("a", kViewport, nullptr, no_style, doc.diagnostics) == a);
  CHECK(doc.references.resolved_count() == 1);
  CHECK(count_containing(doc.diagnostics.warnings, "filter href '#a' is circular") == 1);
  // The primitives come from b, the first of the chain that has any; the units from each nearest.
  CHECK(a->element == doc.by_id("a"));
  REQUIRE(a->primitives.size() == 2);
  CHECK(a->primitives[0].node.parent() == doc.by_id("b"));
  CHECK(a->bounding_box_primitives);
  CHECK_FALSE(a->region_in_box);
  CHECK(a->x == 0.0);
  CHECK(a->width == 2.0);
  const auto* flood = std::get_if<filter::FloodParams>(&a->primitives[0].params);
  REQUIRE(flood != nullptr);
  // lime in linearRGB (the default colour space): 1 stays 1 up to the float rounding of (1 + 0.055) / 1.055.
  CHECK(flood->color.g == Approx(1.0f).margin(1e-6));
  CHECK(flood->color.r == 0.0f);
  CHECK(flood->color.a == 1.0f);
  // An error in an attribute is said once, when the filter is read, and kept for the run.
  CHECK(a->primitives[1].error == "<feComposite> k1 is not a number");
  CHECK(std::holds_alternative<filter::NoParams>(a->primitives[1].params));
  CHECK(count_containing(doc.diagnostics.warnings, "k1 is not a number") == 1);
  // b starting the chain: its own object; primitiveUnits still from a, the next link of b's chain.
  const filter::ResolvedFilter* b = doc.references.filter("b", kViewport, nullptr, no_style, doc.diagnostics);
  REQUIRE(b != nullptr);
  CHECK(b != a);
  CHECK(b->element == doc.by_id("b"));
  CHECK(b->bounding_box_primitives);
  CHECK(count_containing(doc.diagnostics.warnings, "filter href '#b' is circular") == 1);
  CHECK(doc.references.resolved_count() == 2);
}

TEST_CASE("resolved references: a filter used from two viewports settles percentages in each",
          "[svg][resolved_references][filter]") {
  Resolved doc(
      "<filter id='f' filterUnits='userSpaceOnUse' x='10%' width='50%' height='20'>"
      "<feOffset x='25%' width='1' dx='1'/></filter>");
  const filter::ResolvedFilter* wide =
      doc.references.filter("f", kViewport, nullptr, no_style, doc.diagnostics);
  const ResolveContext narrow_viewport{50.0, 100.0, svg::Resolution{96.0, 96.0}};
  const filter::ResolvedFilter* narrow =
      doc.references.filter("f", narrow_viewport, nullptr, no_style, doc.diagnostics);
  REQUIRE(wide != nullptr);
  REQUIRE(narrow != nullptr);
  CHECK(wide != narrow);
  CHECK(doc.references.resolved_count() == 2);
  CHECK(doc.references.filter("f", kViewport, nullptr, no_style, doc.diagnostics) == wide);
  CHECK(doc.references.resolved_count() == 2);
  // Percentages of each viewport's width (200 and 50); y's default -10 % of the height (100 in both).
  const std::optional<filter::FilterDefinition> in_wide = filter::place_filter(*wide, std::nullopt);
  const std::optional<filter::FilterDefinition> in_narrow = filter::place_filter(*narrow, std::nullopt);
  REQUIRE(in_wide);
  REQUIRE(in_narrow);
  CHECK(in_wide->region == Rect{20.0, -10.0, 120.0, 10.0});
  CHECK(in_narrow->region == Rect{5.0, -10.0, 30.0, 10.0});
  // The primitive's subregion too: x 25 % of each width, the others not given (NaN: the default).
  CHECK(wide->primitives[0].subregion[0] == 50.0);
  CHECK(narrow->primitives[0].subregion[0] == 12.5);
  CHECK(narrow->primitives[0].subregion[2] == 1.0);
  CHECK(std::isnan(narrow->primitives[0].subregion[1]));
}

TEST_CASE("resolved references: an feImage's element and the style it inherits are read with its filter",
          "[svg][resolved_references][filter]") {
  Resolved doc(
      "<filter id='f'><feImage href='#shape'/><feImage href='#missing'/>"
      "<feImage href='picture.png' preserveAspectRatio='xMinYMin slice'/></filter>"
      "<g id='holder'><rect id='shape' width='4' height='4'/></g>");
  std::vector<pugi::xml_node> styled;
  const ReferencedStyle style_of = [&](const pugi::xml_node& node) {
    styled.push_back(node);
    return ComputedStyle{};
  };
  const filter::ResolvedFilter* resolved =
      doc.references.filter("f", kViewport, nullptr, style_of, doc.diagnostics);
  REQUIRE(resolved != nullptr);
  for (int use = 1; use < 100; ++use)
    CHECK(doc.references.filter("f", kViewport, nullptr, style_of, doc.diagnostics) == resolved);
  REQUIRE(resolved->primitives.size() == 3);
  const auto* element = std::get_if<filter::ImageParams>(&resolved->primitives[0].params);
  REQUIRE(element != nullptr);
  CHECK(element->target == doc.by_id("shape"));
  CHECK(element->target_parent_style != nullptr);
  const auto* missing = std::get_if<filter::ImageParams>(&resolved->primitives[1].params);
  REQUIRE(missing != nullptr);
  CHECK_FALSE(missing->target);
  const auto* picture = std::get_if<filter::ImageParams>(&resolved->primitives[2].params);
  REQUIRE(picture != nullptr);
  CHECK(picture->reference == "picture.png");
  CHECK(picture->aspect.slice);
  // Two styles, once for all the uses: the element's parent (which it inherits from) and the image's
  // feImage (image-rendering).
  REQUIRE(styled.size() == 2);
  CHECK(styled[0] == doc.by_id("holder"));
  CHECK(styled[1] == resolved->primitives[2].node);
  CHECK(count_containing(doc.diagnostics.warnings, "<feImage> refers to '#missing', which does not exist") ==
        1);
}
