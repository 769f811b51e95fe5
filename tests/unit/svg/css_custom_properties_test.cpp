// Custom properties and var() in rendered documents (svg/cascade.h, CSS Custom Properties for Cascading
// Variables Module Level 1): what design tools and icon sets write -- `:root { --c: ... }` in a <style>,
// `style="--accent: red"` on the root, `fill: var(--icon-color, #333)` -- cascaded, inherited and
// substituted, and the values that become invalid at computed-value time unset (section 3.1).
//
// Colours are read at the centres of 10 x 10 squares, where coverage is exactly 1, so a solid fill gives
// its exact sRGB value: no tolerance is needed. The expected colours follow from the specification: each
// case says which declaration wins and why.
#include <catch2/catch.hpp>
#include <string>

#include "curvescan/svg/document.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

TEST_CASE("var(): the custom properties of design tools and icon sets give their colours") {
  const RenderedDocument rendered = render(row_of_squares(
      "<style>:root { --c: #0000ff } .icon { fill: var(--icon-color, #333333) }</style>" +
          square(0, "fill=\"var(--accent)\"") +    // a presentation attribute, from the root's style
          square(1, "style=\"fill: var(--c)\"") +  // the :root rule, inherited
          square(2, "class=\"icon\"") +            // no --icon-color: the fallback
          "<g style=\"--icon-color: #008000\">" + square(3, "class=\"icon\"") + "</g>",
      "style=\"--accent: #ff0000\""));
  CHECK(square_colour(rendered.image, 0) == "#ff0000");
  CHECK(square_colour(rendered.image, 1) == "#0000ff");
  CHECK(square_colour(rendered.image, 2) == "#333333");
  CHECK(square_colour(rendered.image, 3) == "#008000");
  CHECK(rendered.warnings.empty());
}

TEST_CASE("custom properties cascade like any property: specificity, order, !important, style attribute") {
  const RenderedDocument rendered = render(
      row_of_squares("<style>rect { fill: var(--f) } #s0 { --f: #008000 } rect { --f: #ff0000 }"
                     " .a { --f: #008000 !important } .b { --f: #ff0000 } .b { --f: #008000 }</style>" +
                     square(0, "id=\"s0\"") + square(1, "class=\"a\" style=\"--f: #ff0000\"") +
                     square(2, "class=\"b\"") + square(3, "class=\"b\" style=\"--f: #008000\"")));
  for (int i = 0; i < 4; ++i) CHECK(square_colour(rendered.image, i) == "#008000");
}

TEST_CASE("custom properties are inherited, names are case-sensitive, var() nests in values and fallbacks") {
  const RenderedDocument rendered = render(
      row_of_squares("<style>g { --base: #008000; --Base: #ff0000 } .alias { --alias: var(--base) }</style>"
                     "<g><g class=\"alias\">" +
                     square(0, "fill=\"var(--alias)\"") + square(1, "style=\"fill: var(--base)\"") +
                     square(2, "fill=\"var(--none, var(--other, var(--base)))\"") +
                     square(3, "fill=\"var(--BASE, #008000)\"") + "</g></g>"));
  for (int i = 0; i < 4; ++i) CHECK(square_colour(rendered.image, i) == "#008000");
}

TEST_CASE("var(): an invalid value at computed-value time unsets the property, not the declaration below") {
  // Section 3.1: the declaration was valid when parsed, so it wins the cascade; what it becomes is invalid,
  // so fill is unset: inherited from the <g> (#008000), NOT the rule's #ff0000 or the attribute's.
  const RenderedDocument rendered = render(row_of_squares(
      "<style>.a { fill: #ff0000; fill: var(--missing) } .b { fill: #ff0000 } .b { fill: var(--len) }"
      " :root { --len: 10px }</style>"
      "<g fill=\"#008000\">" +
      square(0, "class=\"a\"") + square(1, "class=\"b\"") +
      square(2, "fill=\"#ff0000\" style=\"fill: var(--x)\"") + "</g>" +
      // A property that is not inherited goes back to its initial value: opacity 1, not the 0 below.
      square(3, "fill=\"#008000\" style=\"opacity: 0; opacity: var(--missing)\"")));
  for (int i = 0; i < 4; ++i) CHECK(square_colour(rendered.image, i) == "#008000");
  // Each is named, with what went wrong.
  CHECK(contains(
      rendered.warnings,
      "ignoring invalid value 'var(--missing)' of property 'fill' (var(--missing) has no value and no "
      "fallback): the property is unset"));
  CHECK(contains(rendered.warnings, "'10px' after var() substitution is not a valid value"));
}

TEST_CASE("custom properties: a cycle has no value, so var() takes its fallback -- initial and inherit") {
  const RenderedDocument rendered = render(row_of_squares(
      "<style>.c { --x: var(--y); --y: var(--x); fill: var(--x, #008000) }"
      " g { --k: #008000 } .i { --k: initial; fill: var(--k, #008000) } .h { --k: inherit; fill: var(--k) }"
      " .u { --k: #ff0000; --k: unset; fill: var(--k) }</style>"
      "<g>" +
      square(0, "class=\"c\"") + square(1, "class=\"i\"") + square(2, "class=\"h\"") +
      square(3, "class=\"u\"") + "</g>"));
  for (int i = 0; i < 4; ++i) CHECK(square_colour(rendered.image, i) == "#008000");
  CHECK(contains(rendered.warnings, "custom property '--x' is part of a var() reference cycle"));
}

TEST_CASE("var(): in font-size before em lengths, in a transform, in a gradient's stops") {
  // font-size from a variable sets the em of stroke-width: a 1em = 10px stroke around a 0-wide line of
  // squares paints the square's centre. The transform moves square 0 to square 1's place. The stops read
  // their colours through the cascade's declared values.
  const RenderedDocument rendered = render(
      row_of_squares("<style>:root { --size: 10px; --move: translate(10px, 0); --stop: #008000 }"
                     " .t { transform: var(--move) } stop { stop-color: var(--stop) }</style>"
                     "<linearGradient id=\"g\"><stop offset=\"0\"/><stop offset=\"1\"/></linearGradient>"
                     "<rect class=\"t\" width=\"10\" height=\"10\" fill=\"#008000\"/>"
                     "<line x1=\"20\" y1=\"5\" x2=\"30\" y2=\"5\" stroke=\"#008000\" style=\"font-size: "
                     "var(--size); stroke-width: 1em\"/>" +
                     square(3, "fill=\"url(#g)\"")));
  CHECK(square_colour(rendered.image, 0) == "none");
  CHECK(square_colour(rendered.image, 1) == "#008000");
  CHECK(square_colour(rendered.image, 2) == "#008000");
  CHECK(square_colour(rendered.image, 3) == "#008000");
}

TEST_CASE("var(): <use> content inherits the custom properties of the <use>") {
  const RenderedDocument rendered = render(row_of_squares(
      "<defs><rect id=\"r\" width=\"10\" height=\"10\" style=\"fill: var(--c, #ff0000)\"/></defs>"
      "<use href=\"#r\" style=\"--c: #008000\"/><use href=\"#r\" x=\"10\" style=\"--c: #0000ff\"/>"));
  CHECK(square_colour(rendered.image, 0) == "#008000");
  CHECK(square_colour(rendered.image, 1) == "#0000ff");
}

TEST_CASE("var() limits: billion laughs through variables renders, refused with one warning") {
  std::string sheet = ":root { --l0: lol;";
  for (int i = 1; i <= 30; ++i) {
    const std::string previous = "var(--l" + std::to_string(i - 1) + ")";
    sheet += " --l" + std::to_string(i) + ": " + previous + " " + previous + ";";
  }
  sheet += "} rect { fill: var(--l30, #008000); stroke-width: var(--l10) }";
  const RenderedDocument rendered =
      render(row_of_squares("<style>" + sheet + "</style>" + square(0, "") + square(1, "") + square(2, "")));
  // --l19 and above are longer than the bound: guaranteed-invalid, so the fallback applies.
  for (int i = 0; i < 3; ++i) CHECK(square_colour(rendered.image, i) == "#008000");
  std::size_t too_long = 0;
  for (const std::string& warning : rendered.warnings)
    too_long += warning.find("longer than") != std::string::npos;
  CHECK(too_long >= 1);
  CHECK(too_long <= 12);  // one per custom property past the bound, named once for the whole document
  // --l10 (4 KiB of "lol") is no stroke width: the warning quotes the start of it only.
  CHECK(contains(rendered.warnings, "'lol lol lol"));
  for (const std::string& warning : rendered.warnings) CHECK(warning.size() < 400);
}
