// Invalid declarations and the CSS-wide keywords in the cascade (svg/cascade.h, svg/computed_style.h).
//
// CSS Syntax 3 5.4.6 and CSS Cascade 4 4.1: a declaration whose value does not match the property's
// grammar is dropped when it is parsed, so it never takes part in the cascade and the next valid
// declaration down (an earlier one in the same block, a less specific rule, the presentation attribute)
// wins. CSS Cascade 4 7.3: inherit, initial and unset (revert acts as unset in an author sheet) work for
// every property.
//
// Colours are checked at pixel centres well inside 10 x 10 squares, where coverage is exactly 1, so a
// solid fill gives its exact sRGB value: no tolerance is needed.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "curvescan/svg/document.h"
#include "svg/computed_style.h"
#include "svg/css_transform.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;

using namespace curvescan::svg::testing;

TEST_CASE("css validity: an invalid declaration falls back to the next valid one down the cascade") {
  const RenderedDocument rendered = render(row_of_squares(
      "<style>.a { fill: #008000 } .a { fill: nonsense }"  // a later rule of equal specificity
      " .b { fill: #008000; fill: 1px }"                   // an earlier declaration of the block
      " #c { fill: 12px } .c { fill: #008000 }"            // a less specific rule
      " .d { fill: #008000 !important } .d { fill: rgb(1 2) !important }</style>" +  // !important over normal
      square(0, "class=\"a\"") +
      square(1, "class=\"b\" style=\"fill: url(\"") + square(2, "id=\"c\" class=\"c\"") +
      square(3, "class=\"d\" style=\"fill: #ff0000\"")));
  for (int i = 0; i < 4; ++i) CHECK(square_colour(rendered.image, i) == "#008000");
  CHECK(contains(rendered.warnings, "ignoring invalid value 'nonsense' of property 'fill'"));
  CHECK(contains(rendered.warnings, "ignoring invalid value '12px' of property 'fill'"));
}

TEST_CASE("css validity: an invalid style attribute or sheet value leaves the presentation attribute") {
  const RenderedDocument rendered = render(row_of_squares(
      "<style>.a { fill: rgb(300, 0) } .b { display: sideways }</style>" +
      square(0, "fill=\"#008000\" style=\"fill: #12345\"") + square(1, "fill=\"#008000\" class=\"a\"") +
      square(2, "fill=\"#008000\" class=\"b\"") +  // not a display keyword: the element stays displayed
      square(3, "fill=\"#008000\" style=\"opacity: half\"")));
  for (int i = 0; i < 4; ++i) CHECK(square_colour(rendered.image, i) == "#008000");
  CHECK(contains(rendered.warnings, "ignoring invalid value 'sideways' of property 'display'"));
}

TEST_CASE("css validity: stop colours and transforms fall back the same way") {
  const RenderedDocument rendered = render(row_of_squares(
      "<style>.s { stop-color: #008000 } .s { stop-color: bogus } .t { transform: translate(10, 0) }"
      " #t { transform: spin(1) }</style>"
      "<linearGradient id=\"g\"><stop class=\"s\" stop-color=\"#ff0000\"/></linearGradient>" +
      square(0, "fill=\"url(#g)\"") +
      "<rect id=\"t\" class=\"t\" width=\"10\" height=\"10\" fill=\"#0000ff\" transform=\"translate(30 "
      "0)\"/>"));
  CHECK(square_colour(rendered.image, 0) == "#008000");
  CHECK(square_colour(rendered.image, 1) == "#0000ff");  // .t's translate(10, 0): #t's transform is invalid
  CHECK(square_colour(rendered.image, 3) == "none");     // the attribute lost to the valid .t declaration
  CHECK(contains(rendered.warnings, "ignoring the transform property"));
}

TEST_CASE("css keywords: inherit, initial, unset and revert, in any case") {
  const RenderedDocument rendered = render(row_of_squares(
      "<style>.i { fill: INITIAL } .u { fill: unset } .o { opacity: unset } .r { fill: revert }</style>"
      "<g fill=\"#0000ff\" opacity=\"1\">" +
      square(0, "class=\"i\" fill=\"#ff0000\"") +  // initial: black, not the parent's blue
      square(1, "class=\"u\" fill=\"#ff0000\"") +  // fill is inherited: unset = inherit
      square(2, "fill=\"#008000\" style=\"fill: Inherit; fill: initial; fill: inherit\"") +
      square(3, "class=\"r\" fill=\"#ff0000\"") + "</g>"));
  CHECK(square_colour(rendered.image, 0) == "#000000");
  CHECK(square_colour(rendered.image, 1) == "#0000ff");
  CHECK(square_colour(rendered.image, 2) == "#0000ff");
  CHECK(square_colour(rendered.image, 3) == "#0000ff");
  CHECK(rendered.warnings.empty());
  // opacity is not inherited: unset is its initial 1, not the attribute's 0.25 nor the group's 0.5
  // (which still applies once, to the group): alpha 0.5 -> 128 of 255 (exact coverage inside the square).
  const RenderedDocument opacity =
      render(row_of_squares("<style>.o { opacity: unset }</style><g opacity=\"0.5\">" +
                            square(0, "class=\"o\" opacity=\"0.25\"") + "</g>"));
  CHECK(opacity.image.at(5, 5).a == 128);
}

TEST_CASE("css keywords: initial gives every property of the table its initial value") {
  // Each property set to a value other than its initial one on the parent and on the element, then the
  // element's own `initial`: the result must equal a style where the property was never declared on
  // either (the default ComputedStyle holds the initial values), observed through apply_property's
  // `inherit` from that default.
  using detail::ComputedStyle;
  const std::vector<std::pair<std::string, std::string>> declarations{{"fill", "#00ff00"},
                                                                      {"fill-opacity", "0.5"},
                                                                      {"fill-rule", "evenodd"},
                                                                      {"stroke", "#00ff00"},
                                                                      {"stroke-width", "3"},
                                                                      {"stroke-opacity", "0.5"},
                                                                      {"stroke-linejoin", "round"},
                                                                      {"stroke-linecap", "square"},
                                                                      {"stroke-miterlimit", "9"},
                                                                      {"stroke-dasharray", "1 2"},
                                                                      {"stroke-dashoffset", "3"},
                                                                      {"opacity", "0.5"},
                                                                      {"display", "none"},
                                                                      {"visibility", "hidden"},
                                                                      {"color", "#00ff00"},
                                                                      {"font-size", "30px"},
                                                                      {"clip-rule", "evenodd"},
                                                                      {"clip-path", "url(#c)"},
                                                                      {"font-family", "monospace"},
                                                                      {"font-weight", "bold"},
                                                                      {"font-style", "italic"},
                                                                      {"text-anchor", "middle"},
                                                                      {"mask", "url(#m)"},
                                                                      {"overflow", "hidden"},
                                                                      {"marker-start", "url(#k)"},
                                                                      {"paint-order", "stroke"},
                                                                      {"mix-blend-mode", "multiply"},
                                                                      {"isolation", "isolate"},
                                                                      {"mask-type", "alpha"},
                                                                      {"direction", "rtl"},
                                                                      {"letter-spacing", "3px"},
                                                                      {"text-decoration", "underline"}};
  const detail::ResolveContext context{100.0, 100.0, {96.0, 96.0}, nullptr};
  for (const auto& [name, value] : declarations) {
    INFO(name << ": " << value);
    detail::Diagnostics diagnostics;
    const ComputedStyle initial;
    ComputedStyle parent;
    detail::apply_property(parent, initial, name, value, context, diagnostics);
    ComputedStyle element = detail::inherit_style(parent);
    detail::apply_property(element, parent, name, value, context, diagnostics);
    detail::apply_property(element, parent, name, "initial", context, diagnostics);
    // The same element with `inherit` from the initial style, written out field by field below.
    ComputedStyle expected = detail::inherit_style(parent);
    detail::apply_property(expected, initial, name, "inherit", context, diagnostics);
    CHECK(diagnostics.warnings.empty());
    CHECK(element.fill.kind == expected.fill.kind);
    CHECK(element.fill_opacity == expected.fill_opacity);
    CHECK(element.fill_rule == expected.fill_rule);
    CHECK(element.stroke.kind == expected.stroke.kind);
    CHECK(element.stroke_width == expected.stroke_width);
    CHECK(element.stroke_opacity == expected.stroke_opacity);
    CHECK(element.stroke_linejoin == expected.stroke_linejoin);
    CHECK(element.stroke_linecap == expected.stroke_linecap);
    CHECK(element.stroke_miterlimit == expected.stroke_miterlimit);
    CHECK(element.stroke_dasharray == expected.stroke_dasharray);
    CHECK(element.stroke_dashoffset == expected.stroke_dashoffset);
    CHECK(element.opacity == expected.opacity);
    CHECK(element.display == expected.display);
    CHECK(element.visible == expected.visible);
    CHECK(element.color.g == expected.color.g);
    CHECK(element.font_size == expected.font_size);
    CHECK(element.clip_rule == expected.clip_rule);
    CHECK(element.clip_path_id == expected.clip_path_id);
    CHECK(element.font_family == expected.font_family);
    CHECK(element.font_weight == expected.font_weight);
    CHECK(element.font_italic == expected.font_italic);
    CHECK(element.text_anchor == expected.text_anchor);
    CHECK(element.painting.mask_id == expected.painting.mask_id);
    CHECK(element.painting.overflow == expected.painting.overflow);
    CHECK(element.painting.marker_start == expected.painting.marker_start);
    CHECK(element.painting.paint_order == expected.painting.paint_order);
    CHECK(element.painting.blend_mode == expected.painting.blend_mode);
    CHECK(element.painting.isolate == expected.painting.isolate);
    CHECK(element.painting.mask_type == expected.painting.mask_type);
    CHECK(element.text.right_to_left == expected.text.right_to_left);
    CHECK(element.text.decoration.underline == expected.text.decoration.underline);
    CHECK(element.text.letter_spacing.has_value() == expected.text.letter_spacing.has_value());
    // And it is the initial value: different from the declared one wherever the parent passed it on.
    const ComputedStyle fresh;
    CHECK(element.fill.kind == fresh.fill.kind);
    CHECK(element.stroke_width == fresh.stroke_width);
    CHECK(element.font_size == fresh.font_size);
    CHECK(element.painting.paint_order == fresh.painting.paint_order);
  }
}

TEST_CASE("css transform: units, commas and the CSS functions, in a sheet and in the attribute") {
  using detail::parse_css_transform;
  const auto near = [](const Affine& a, const Affine& b) {
    // Degrees and turns converted to radians: a few ulps from exact, far below 1e-12 here.
    return std::abs(a.a - b.a) < 1e-12 && std::abs(a.b - b.b) < 1e-12 && std::abs(a.c - b.c) < 1e-12 &&
           std::abs(a.d - b.d) < 1e-12 && std::abs(a.e - b.e) < 1e-12 && std::abs(a.f - b.f) < 1e-12;
  };
  const auto parsed = [](std::string_view text) {
    const Result<Affine> transform = parse_css_transform(text);
    INFO(text);
    REQUIRE(transform.is_ok());
    return *transform;
  };
  CHECK(near(parsed("translate(10px, 5px)"), Affine::translate(10, 5)));
  CHECK(near(parsed("translateX(1in) translateY(72pt)"), Affine::translate(96, 96)));
  CHECK(near(parsed("rotate(90deg)"), Affine{0, 1, -1, 0, 0, 0}));
  CHECK(near(parsed("rotate(0.25turn)"), parsed("rotate(100grad)")));
  CHECK(near(parsed("scale(2) translate(1px)"), Affine{2, 0, 0, 2, 2, 0}));  // rightmost first
  CHECK(near(parsed("skew(45deg, 0)"), Affine::skew_x(std::numbers::pi / 4)));
  CHECK(near(parsed("scaleX(2) scaleY(50%)"), Affine::scale(2, 0.5)));
  CHECK(near(parsed("none"), Affine::identity()));
  CHECK_FALSE(parse_css_transform("translate(10px 5px)"));  // CSS wants the comma
  CHECK_FALSE(parse_css_transform("translate(1rem)"));      // the root's font size: not known here
  CHECK_FALSE(parse_css_transform("rotate(45)"));           // an angle needs its unit
  CHECK_FALSE(parse_css_transform("perspective(100px) rotateY(30deg)"));  // a projective map of the plane
  CHECK_FALSE(parse_css_transform("translate(1px,)"));
  // In a document: the sheet's CSS syntax and the attribute's.
  const RenderedDocument rendered = render(row_of_squares(
      "<style>#a { transform: translateX(10px) }</style>"
      "<rect id=\"a\" width=\"10\" height=\"10\" fill=\"#008000\"/>"
      "<rect width=\"10\" height=\"10\" fill=\"#0000ff\" transform=\"translate(30px, 0) rotate(0.5turn)"
      " translate(-10px, -10px)\"/>"));
  CHECK(square_colour(rendered.image, 1) == "#008000");
  CHECK(square_colour(rendered.image, 0) == "none");
  // [0,10]² moved to [-10,0]², turned half a turn back onto [0,10]², then moved to [30,40] x [0,10].
  CHECK(square_colour(rendered.image, 3) == "#0000ff");
  CHECK(square_colour(rendered.image, 2) == "none");
  CHECK(rendered.warnings.empty());
}

TEST_CASE("css: the filter primitives' colour properties come from style sheets too (regression: ignored)") {
  const RenderedDocument rendered =
      render(row_of_squares("<style>.f { flood-color: #008000 }</style>"
                            "<filter id=\"a\" x=\"0\" y=\"0\" width=\"1\" height=\"1\"><feFlood class=\"f\" "
                            "flood-color=\"#ff0000\"/></filter>" +
                            square(0, "filter=\"url(#a)\"")));
  CHECK(square_colour(rendered.image, 0) == "#008000");
}

// flood-color is not inherited: `initial`, `unset` and `revert` give its initial value, black, over the
// presentation attribute below them; so does a var() that fails to substitute, which leaves the property
// unset (CSS Variables 1, 3.1) — it was refused as "not a colour" and the attribute's red drawn.
TEST_CASE(
    "css: the CSS-wide keywords and a failed var() in a filter primitive's colour give its initial value") {
  const auto flood = [](const std::string& declaration) {
    return "<filter id=\"f\" x=\"0\" y=\"0\" width=\"1\" height=\"1\"><feFlood style=\"flood-color: " +
           declaration + "\" flood-color=\"#ff0000\"/></filter>";
  };
  for (const std::string declaration : {"initial", "unset", "revert", "var(--missing)", "var(--a)"}) {
    INFO(declaration);
    const RenderedDocument rendered =
        render(row_of_squares("<style>svg { --a: 12px }</style>" + flood(declaration) +
                              square(0, "filter=\"url(#f)\" fill=\"#0000ff\"")));
    CHECK(square_colour(rendered.image, 0) == "#000000");
  }
}

// No silent loss: properties that change a drawing and are not implemented (font-size-adjust, SVG 2's
// text wrapping, CSS animations) were dropped as unknown names without a word. Each is named once, from a
// sheet, the style attribute or a presentation attribute, and only when its value is not the initial one; the
// drawing is unchanged (the declaration is dropped).
TEST_CASE("css: unimplemented properties are named once, initial values are not") {
  const auto count = [](const RenderedDocument& rendered, const std::string& text) {
    return std::count(rendered.warnings.begin(), rendered.warnings.end(), text);
  };
  const RenderedDocument rendered = render(row_of_squares(
      "<style>.a { animation: spin 1s } .b { inline-size: 30px; shape-inside: circle() }</style>" +
      square(0, "class=\"a\" fill=\"#008000\"") + square(1, "class=\"a b\" fill=\"#008000\"") +
      square(2, "fill=\"#008000\" font-size-adjust=\"0.5\"") +
      square(3, "fill=\"#008000\" style=\"font-size-adjust: 0.5\"")));
  for (int i = 0; i < 4; ++i) CHECK(square_colour(rendered.image, i) == "#008000");
  CHECK(count(rendered, "the animation property is not supported, ignored") == 1);
  CHECK(count(rendered, "the inline-size property is not supported, ignored") == 1);
  CHECK(count(rendered, "the shape-inside property is not supported, ignored") == 1);
  CHECK(count(rendered, "the font-size-adjust property is not supported, ignored") == 1);
  const RenderedDocument initial =
      render(row_of_squares("<style>rect { animation: none; white-space: normal; inline-size: auto; "
                            "shape-inside: inherit }</style>" +
                            square(0, "fill=\"#008000\" animation-name=\"none\"")));
  CHECK(initial.warnings.empty());
}

// No silent loss: <mesh>, a graphics element of the SVG 2 drafts, and SVG Tiny 1.2's <textArea> were
// skipped as unknown elements (a note under --verbose only). They are named as the other unsupported
// elements are, once each.
TEST_CASE("elements: <mesh> and <textArea> are named as unsupported") {
  const RenderedDocument rendered =
      render(row_of_squares("<mesh/><mesh/><textArea>Hello</textArea>" + square(0, "fill=\"#008000\"")));
  CHECK(std::count(rendered.warnings.begin(), rendered.warnings.end(), "<mesh> is not supported, ignored") ==
        1);
  CHECK(std::count(rendered.warnings.begin(), rendered.warnings.end(),
                   "<textArea> is not supported, ignored") == 1);
}

// Regression: fill="url(other.svg#g)" was an invalid value, dropped for the inherited paint (black here).
// A URL into another document is valid paint syntax (SVG 2 13.2: <url> [none | <color>]); this reader never
// reads it, so it paints the fallback colour, else none, as a reference to nothing does and as Chrome
// (which does not load other documents' paint servers) draws it, with a warning naming the URL. Whole-pixel
// squares: exact.
TEST_CASE("paint: a URL into another document paints its fallback or none, with a warning") {
  const RenderedDocument rendered = render(row_of_squares(
      square(0, "fill=\"url(other.svg#g)\"") + square(1, "fill=\"url('other.svg#g') #008000\"") +
      square(2, "style=\"fill: url(other.svg)\"") + square(3, "fill=\"url(#missing) #008000\"")));
  CHECK(square_colour(rendered.image, 0) == "none");
  CHECK(square_colour(rendered.image, 1) == "#008000");
  CHECK(square_colour(rendered.image, 2) == "none");
  CHECK(square_colour(rendered.image, 3) == "#008000");
  CHECK(contains(rendered.warnings, "fill 'url(other.svg#g)' refers to another document, which is not read"));
  CHECK(contains(rendered.warnings, "fill 'url(other.svg)' refers to another document, which is not read"));
  for (const std::string& warning : rendered.warnings)
    CHECK(warning.find("invalid value") == std::string::npos);
}

TEST_CASE("css validity: keywords match whatever their ASCII case, in attributes and style sheets") {
  // CSS Values 3, 2.1: CSS keywords are ASCII case-insensitive; SVG 2, 4.2 parses presentation attributes
  // with the property's CSS grammar. Square 0 is hidden, 1 has no display, 2 is painted with the even-odd
  // rule over a doubly wound square (an even-odd hole where nonzero would fill), 3 shows.
  const RenderedDocument rendered = render(row_of_squares(
      "<style>.n { DISPLAY: None }</style>" + square(0, "fill=\"#ff0000\" visibility=\"HIDDEN\"") +
      square(1, "fill=\"#ff0000\" class=\"n\"") +
      "<path d=\"M20 0h10v10h-10z M20 0h10v10h-10z\" fill=\"#ff0000\" fill-rule=\"EvenOdd\"/>" +
      square(3, "fill=\"#008000\" visibility=\"Visible\"")));
  for (int i = 0; i < 3; ++i) CHECK(square_colour(rendered.image, i) == "none");
  CHECK(square_colour(rendered.image, 3) == "#008000");
  CHECK(rendered.warnings.empty());
}

TEST_CASE("css validity: paint and reference keywords match whatever their ASCII case") {
  // The same rule for the keywords inside paints and references: none, currentColor (CSS Color 4 writes
  // it `currentcolor`), the url() function name. A gradient of one stop paints that stop's colour.
  const RenderedDocument rendered = render(row_of_squares(
      "<linearGradient id=\"g\"><stop stop-color=\"CurrentColor\" color=\"#0000ff\"/></linearGradient>" +
      square(0, "fill=\"NONE\"") + square(1, "fill=\"currentcolor\" color=\"#008000\"") +
      square(2, "fill=\"URL(#g)\"") +
      square(3, "fill=\"#ff0000\" stroke=\"None\" clip-path=\"NONE\" mask=\"none\" filter=\"NONE\"")));
  CHECK(square_colour(rendered.image, 0) == "none");
  CHECK(square_colour(rendered.image, 1) == "#008000");
  CHECK(square_colour(rendered.image, 2) == "#0000ff");
  CHECK(square_colour(rendered.image, 3) == "#ff0000");
  CHECK(rendered.warnings.empty());
}
