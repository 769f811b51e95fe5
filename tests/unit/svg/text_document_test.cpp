// SVG <text> in whole documents (raster/svg/text_element.cpp), against the exact oracle: the same
// glyph outlines, laid out by the library's own text API (text_layout.h: layout_text / text_path, whose
// advances and kerning are checked against FreeType in tests/unit/font/text_layout_test.cpp) at the
// positions the SVG specification prescribes, filled through Canvas with the same paint and transform.
//
// Tolerance: max |Δ| <= 1/255 per channel. Both sides rasterize the same curves with the same rasterizer;
// the only difference is how glyph origins are summed (the SVG side adds the chunk's anchor shift and
// each run's pen position separately), which moves coordinates by ~1e-13 px and can flip the rounding of
// 255·coverage by one level, never more. Any real error (a wrong size, position, anchor, font) moves
// whole edges and gives differences of ~100/255 and more.
#include <algorithm>
#include <catch2/catch.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/svg/document.h"
#include "curvescan/text/font_lookup.h"
#include "curvescan/text/text_layout.h"
#include "svg_test_support.h"

using namespace curvescan;
using curvescan::svg::testing::inked_pixels;
using curvescan::svg::testing::max_delta;

namespace {

constexpr int kWidth = 240;
constexpr int kHeight = 80;

std::string document(const std::string& body) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(kWidth) + "\" height=\"" +
         std::to_string(kHeight) + "\">" + body + "</svg>";
}

svg::RenderedDocument render(const std::string& body) {
  Result<svg::RenderedDocument> rendered = svg::render_svg_document(document(body), svg::RenderOptions{});
  REQUIRE(rendered.is_ok());
  return std::move(rendered).value();
}

Font font(const std::string& family, int weight = 400, bool italic = false) {
  Result<Font> loaded = load_font(FontQuery{family, weight, italic}, false);
  REQUIRE(loaded.is_ok());
  return std::move(loaded).value();
}

// One string drawn by the library: its outlines at `origin` (the start of the baseline) with `style`.
struct OracleText {
  const Font* font;
  std::string text;
  Point origin;
  TextStyle style;
  Paint paint;
};

Image oracle(const std::vector<OracleText>& texts, const Affine& transform = Affine::identity()) {
  Result<Canvas> canvas = Canvas::create(kWidth, kHeight);
  REQUIRE(canvas.is_ok());
  for (const OracleText& text : texts) {
    const Result<Path> path = text_path(*text.font, text.text, text.origin, text.style);
    REQUIRE(path.is_ok());
    REQUIRE(canvas->fill(*path, text.paint, FillRule::kNonZero, transform).is_ok());
  }
  return std::move(*canvas).take_image();
}


// The text must draw something substantial, or "equal" would prove nothing.
void check_same(const Image& expected, const Image& actual) {
  CHECK(inked_pixels(expected) > 100);
  CHECK(max_delta(expected, actual) <= 1);
}

TextStyle sized(double size, TextAnchor anchor = TextAnchor::kStart) {
  TextStyle style;
  style.size = size;
  style.anchor = anchor;
  return style;
}

const Paint kBlack = Paint::solid({0, 0, 0, 1});

double advance_of(const Font& f, const std::string& text, double size) {
  const Result<Path> unused = text_path(f, text, {0, 0}, sized(size));
  REQUIRE(unused.is_ok());
  std::u32string u32(text.begin(), text.end());  // ASCII only
  const Result<TextLayout> layout = layout_text(f, u32, {0, 0}, sized(size));
  REQUIRE(layout.is_ok());
  return layout->lines.front().advance;
}

}  // namespace

TEST_CASE("svg text: the glyph outlines at x, y and font-size (exact oracle)") {
  const Font sans = font("DejaVu Sans");
  const svg::RenderedDocument rendered =
      render(R"(<text x="12.5" y="40" font-family="DejaVu Sans" font-size="24">Hello, AVA Wy!</text>)");
  CHECK(rendered.warnings.empty());
  check_same(oracle({{&sans, "Hello, AVA Wy!", {12.5, 40}, sized(24), kBlack}}), rendered.image);
}

TEST_CASE("svg text: text-anchor middle and end shift by half and all of the advance") {
  const Font sans = font("DejaVu Sans");
  // "mmm" has no kerning pair, so its advance is three times the glyph's hmtx advance, scaled.
  const double advance = 3.0 * sans.advance(sans.glyph_for(U'm')) * 20.0 / sans.metrics().units_per_em;
  CHECK(advance_of(sans, "mmm", 20.0) == Approx(advance).epsilon(1e-12));
  for (const auto& [keyword, shift] : {std::pair<std::string, double>{"middle", -advance / 2.0},
                                       std::pair<std::string, double>{"end", -advance}}) {
    INFO("text-anchor " << keyword);
    const svg::RenderedDocument rendered =
        render(R"(<text x="120" y="50" font-family="DejaVu Sans" font-size="20" text-anchor=")" + keyword +
               R"(">mmm</text>)");
    check_same(oracle({{&sans, "mmm", {120.0 + shift, 50}, sized(20), kBlack}}), rendered.image);
  }
}

TEST_CASE("svg text: the anchor applies to the whole chunk across tspans of other sizes and fills") {
  const Font sans = font("DejaVu Sans");
  const double first = advance_of(sans, "ab", 16.0), second = advance_of(sans, "cd", 28.0);
  const svg::RenderedDocument rendered = render(
      R"(<text x="200" y="50" font-family="DejaVu Sans" font-size="16" text-anchor="end">ab<tspan font-size="28" fill="#c00">cd</tspan></text>)");
  const Image expected =
      oracle({{&sans, "ab", {200.0 - first - second, 50}, sized(16), kBlack},
              {&sans, "cd", {200.0 - second, 50}, sized(28), Paint::solid({0.8, 0, 0, 1})}});
  check_same(expected, rendered.image);
}

TEST_CASE("svg text: shaping goes on across tspans that change only the paint (kerning kept)") {
  // "Te" is a kerned pair in DejaVu Sans: shaped in two runs it would lose its kerning.
  const std::string font = R"( x="60" y="50" text-anchor="middle" font-family="DejaVu Sans" font-size="40")";
  const Image whole = render("<text" + font + ">Text</text>").image;
  CHECK(max_delta(whole, render("<text" + font + " style=\"font-kerning: none\">Text</text>").image) > 100);
  CHECK(max_delta(whole, render("<text" + font + ">T<tspan>e</tspan><tspan font-weight=\"400\">x</tspan>t</text>")
                             .image) == 0);
  // A tspan that changes the font still starts a run of its own: bold "e" is not the regular one.
  CHECK(max_delta(whole, render("<text" + font + ">T<tspan font-weight=\"bold\">e</tspan>xt</text>").image) > 100);
}

TEST_CASE("svg text: an absolute x starts a new chunk — x lists place characters one by one") {
  const svg::RenderedDocument lists =
      render(R"(<text x="10 60" y="40" font-family="DejaVu Sans" font-size="30">ABC</text>)");
  const Font sans = font("DejaVu Sans");
  check_same(oracle({{&sans, "A", {10, 40}, sized(30), kBlack}, {&sans, "BC", {60, 40}, sized(30), kBlack}}),
             lists.image);
  // A tspan's own list wins over its parent's for its characters, and the parent's list goes on where
  // the tspan's ends (C keeps x = 140; SVG 1.1 10.5); dy shifts accumulate on the pen.
  const svg::RenderedDocument nested = render(
      R"(<text x="10 40 140" y="40" font-family="DejaVu Sans" font-size="30">A<tspan x="100" dy="-5 10">BCD</tspan></text>)");
  const double c = advance_of(sans, "C", 30.0);
  check_same(oracle({{&sans, "A", {10, 40}, sized(30), kBlack},
                     {&sans, "B", {100, 35}, sized(30), kBlack},
                     {&sans, "C", {140, 45}, sized(30), kBlack},
                     {&sans, "D", {140 + c, 45}, sized(30), kBlack}}),
             nested.image);
}

TEST_CASE("svg text: transforms apply to the outlines") {
  const Font sans = font("DejaVu Sans");
  const svg::RenderedDocument rendered = render(
      R"svg(<g transform="translate(30 10) rotate(15) scale(1.5 1)"><text x="5" y="30" font-family="DejaVu Sans" font-size="18">Turn</text></g>)svg");
  const Affine transform =
      Affine::translate(30, 10) * Affine::rotate(15.0 * std::numbers::pi / 180.0) * Affine::scale(1.5, 1.0);
  check_same(oracle({{&sans, "Turn", {5, 30}, sized(18), kBlack}}, transform), rendered.image);
}

TEST_CASE("svg text: font-weight and font-style select the family's bold and oblique faces") {
  const Font bold = font("DejaVu Sans", 700);
  CHECK(bold.style_name() == "Bold");
  check_same(
      oracle({{&bold, "Bold", {10, 50}, sized(30), kBlack}}),
      render(R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="30" font-weight="bold">Bold</text>)")
          .image);
  const Font oblique = font("DejaVu Sans", 400, true);
  CHECK(oblique.style_name() == "Oblique");
  check_same(
      oracle({{&oblique, "Slant", {10, 50}, sized(30), kBlack}}),
      render(
          R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="30" font-style="italic">Slant</text>)")
          .image);
  // Cantarell is a CFF font: its cubic outlines go the same way.
  const Font cantarell = font("Cantarell");
  check_same(oracle({{&cantarell, "Cubic", {10, 50}, sized(30), kBlack}}),
             render(R"(<text x="10" y="50" font-family="Cantarell" font-size="30">Cubic</text>)").image);
}

TEST_CASE("svg text: font-size in any unit, keywords and the font shorthand resolve to the same pixels") {
  const std::string reference_body =
      R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="24" font-weight="bold" font-style="italic">Size</text>)";
  const Image reference = render(reference_body).image;
  CHECK(inked_pixels(reference) > 100);
  for (const std::string size : {"18pt", "x-large", "1.5em", "150%", "0.25in"}) {
    INFO("font-size " << size);
    const std::string body = R"(<text x="10" y="50" font-family="DejaVu Sans" font-size=")" + size +
                             R"(" font-weight="bold" font-style="italic">Size</text>)";
    CHECK(max_delta(reference, render(body).image) == 0);
  }
  CHECK(
      max_delta(
          reference,
          render(R"(<text x="10" y="50" style="font: italic bold 24px 'DejaVu Sans'">Size</text>)").image) ==
      0);
}

TEST_CASE(
    "svg text: a missing family falls back through the list, or to fontconfig's choice with a warning") {
  const Image reference =
      render(R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="24">Fallback</text>)").image;
  const svg::RenderedDocument listed = render(
      R"(<text x="10" y="50" font-family="No Such Family Xq, 'DejaVu Sans'" font-size="24">Fallback</text>)");
  CHECK(listed.warnings.empty());
  CHECK(max_delta(reference, listed.image) == 0);

  const svg::RenderedDocument missing =
      render(R"(<text x="10" y="50" font-family="No Such Family Xq" font-size="24">Fallback</text>)");
  REQUIRE(missing.warnings.size() == 1);
  CHECK(missing.warnings.front().find("'No Such Family Xq' is not installed") != std::string::npos);
  CHECK(inked_pixels(missing.image) > 100);  // drawn anyway, in the fallback face
}

TEST_CASE("svg text: white space per xml:space, across tspans and whitespace-only text nodes") {
  const Image reference =
      render(R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="24">a b c</text>)").image;
  for (
      const std::string body :
      {R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="24">   a
       b	  c  </text>)",
       R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="24"><tspan>a</tspan> <tspan>b</tspan> c</text>)",
       R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="24">a <tspan> b </tspan> c</text>)"}) {
    INFO(body);
    CHECK(max_delta(reference, render(body).image) <= 1);
  }
  // preserve keeps the leading spaces: the text starts two space advances later.
  const Font sans = font("DejaVu Sans");
  const double space = advance_of(sans, " ", 24.0);
  check_same(
      oracle({{&sans, "a b", {10 + 2 * space, 50}, sized(24), kBlack}}),
      render(
          R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="24" xml:space="preserve">  a b</text>)")
          .image);
}

TEST_CASE("svg text: display none removes a tspan's text, visibility hidden keeps its advance") {
  const Image joined =
      render(R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="24">ab</text>)").image;
  CHECK(
      max_delta(
          joined,
          render(
              R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="24">a<tspan display="none">XX</tspan>b</text>)")
              .image) <= 1);
  const Image unpainted =
      render(
          R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="24">a<tspan fill="none">XX</tspan>b</text>)")
          .image;
  const Image hidden =
      render(
          R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="24">a<tspan visibility="hidden">XX</tspan>b</text>)")
          .image;
  CHECK(max_delta(unpainted, hidden) == 0);
  CHECK(max_delta(joined, hidden) > 100);  // the b moved
}

TEST_CASE("svg text: missing glyphs, unsupported features and invalid values are diagnostics, not errors") {
  const svg::RenderedDocument missing =
      render("<text x=\"10\" y=\"50\" font-family=\"Cantarell\" font-size=\"24\">a\xe4\xb8\xad</text>");
  REQUIRE(missing.warnings.size() == 1);
  CHECK(missing.warnings.front().find("no glyph for U+4E2D") != std::string::npos);

  const svg::RenderedDocument unsupported = render(
      R"(<text x="10" y="50" font-family="DejaVu Sans" glyph-orientation-horizontal="0" style="writing-mode: sideways-rl">ab<tref href="#p"/>c<tspan style="writing-mode: sideways-rl">d</tspan></text>)");
  // Unsupported features are warnings (shown by default), each named once.
  CHECK(unsupported.warnings.size() == 2);
  const auto noted = [&](const std::string& what) {
    return std::any_of(unsupported.warnings.begin(), unsupported.warnings.end(),
                       [&](const std::string& note) { return note.find(what) != std::string::npos; });
  };
  CHECK(noted("'glyph-orientation-horizontal' is not supported"));
  CHECK(noted("<tref> refers to no element ('#p')"));
  CHECK(inked_pixels(unsupported.image) > 50);

  // SVG 2's wrapping and CSS's font-size-adjust are named once each (attribute or style), on a <text> or a
  // <tspan>, by the cascade; their initial values say nothing. white-space and text-transform are
  // implemented: no warning.
  const svg::RenderedDocument css_text = render(
      R"svg(<text x="10" y="50" font-family="DejaVu Sans" inline-size="100" style="white-space: pre; text-transform: uppercase">a<tspan font-size-adjust="0.5" style="shape-inside: circle(50%)">b</tspan><tspan white-space="pre-wrap" shape-subtract="url(#s)" shape-padding="2" shape-margin="3">c</tspan></text>)svg");
  for (const char* property : {"inline-size", "font-size-adjust", "shape-inside", "shape-subtract",
                               "shape-padding", "shape-margin"}) {
    INFO(property);
    CHECK(std::count(css_text.warnings.begin(), css_text.warnings.end(),
                     std::string("the ") + property + " property is not supported, ignored") == 1);
  }
  CHECK(css_text.warnings.size() == 6);
  CHECK(
      render(
          R"(<text x="10" y="50" font-family="DejaVu Sans" inline-size="auto" style="white-space: normal; text-transform: none; font-size-adjust: none; shape-inside: none; shape-subtract: none; shape-padding: 0; shape-margin: 0">ab</text>)")
          .warnings.empty());

  const svg::RenderedDocument invalid = render(
      R"(<text x="10" y="50" font-family="DejaVu Sans" font-weight="heavy" text-anchor="left">ab</text>)");
  CHECK(invalid.warnings.size() == 2);
  CHECK(inked_pixels(invalid.image) > 50);
  // Empty text, zero size and an element with no characters draw nothing and say nothing.
  const svg::RenderedDocument empty = render(
      R"(<text x="10" y="50"/><text x="10" y="50">   </text><text font-size="0" x="10" y="50">a</text>)");
  CHECK(empty.warnings.empty());
  CHECK(inked_pixels(empty.image) == 0);
}

TEST_CASE("svg text: hostile input is bounded: deep tspan nesting, huge sizes, malformed lists") {
  // 400 nested tspans: beyond the default max_depth of 256 the content is skipped with a warning.
  std::string nested = R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="20">a)";
  for (int i = 0; i < 400; ++i) nested += "<tspan>b";
  for (int i = 0; i < 400; ++i) nested += "</tspan>";
  nested += "</text>";
  const svg::RenderedDocument deep = render(nested);
  REQUIRE_FALSE(deep.warnings.empty());
  CHECK(deep.warnings.front().find("nested more than") != std::string::npos);
  CHECK(inked_pixels(deep.image) > 50);
  // A size beyond kMaxTextSize is a warning and draws nothing.
  const svg::RenderedDocument huge =
      render(R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="1e9">a</text>)");
  REQUIRE(huge.warnings.size() == 1);
  CHECK(inked_pixels(huge.image) == 0);
  // A malformed x list is ignored with a warning; the text still draws, from x = 0.
  const svg::RenderedDocument bad_list =
      render(R"(<text x="10 zz" y="50" font-family="DejaVu Sans" font-size="20">abc</text>)");
  CHECK(bad_list.warnings.size() == 1);
  CHECK(inked_pixels(bad_list.image) > 50);
  // rotate is a list of numbers: with a unit it is ignored, the text drawn unrotated (regression: "5mm"
  // turned every glyph by 5 degrees).
  const svg::RenderedDocument angle_unit =
      render(R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="20" rotate="5mm">abc</text>)");
  CHECK(angle_unit.warnings.size() == 1);
  CHECK(max_delta(angle_unit.image,
                  render(R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="20">abc</text>)").image) == 0);
}

TEST_CASE("svg text: extreme numbers never fail the render (overflowing positions, tiny and huge sizes)") {
  for (const std::string body : {
           R"(<text x="1e308 -1e308" dx="1e308" text-anchor="middle" font-size="20">ab</text>)",
           R"(<text y="20" dx="1e308 1e308 1e308" text-anchor="end">abc</text>)",
           R"(<text x="10" y="20" font-size="1e-300">ab</text>)",
           R"(<text x="nan" y="inf" font-size="20">ab</text>)",
           R"(<text x="10" y="20" font-family="," font-weight="1e400">ab</text>)",
           R"(<text x="10" y="20" style="font: 1e400px serif">ab</text>)",
       }) {
    INFO(body);
    const Result<svg::RenderedDocument> rendered =
        svg::render_svg_document(document(body), svg::RenderOptions{});
    CHECK(rendered.is_ok());
  }
}

TEST_CASE("svg text: tref draws the referenced element's character data, altGlyph draws as a tspan") {
  const std::string font = R"( font-family="DejaVu Sans" font-size="24")";
  const svg::RenderedDocument plain = render("<text x=\"10\" y=\"50\"" + font + ">ab cd</text>");
  REQUIRE(plain.warnings.empty());
  REQUIRE(inked_pixels(plain.image) > 100);
  // All the character data of the target, inside its descendants too, in document order (SVG 1.1 10.6);
  // the tref's own style and the text's white-space rules apply.
  const svg::RenderedDocument tref =
      render("<defs><text id=\"t\">c<tspan>d</tspan></text></defs><text x=\"10\" y=\"50\"" + font +
             ">ab <tref href=\"#t\"/></text>");
  CHECK(tref.warnings.empty());
  CHECK(max_delta(plain.image, tref.image) == 0);
  const svg::RenderedDocument xlink =
      render("<defs><desc id=\"t\">cd</desc></defs><text x=\"10\" y=\"50\"" + font +
             " xmlns:xlink=\"http://www.w3.org/1999/xlink\">ab <tref xlink:href=\"#t\"/></text>");
  CHECK(max_delta(plain.image, xlink.image) == 0);
  // A tref positions its characters like a tspan: dx moves its first character.
  const svg::RenderedDocument moved = render("<defs><desc id=\"t\">cd</desc></defs><text x=\"10\" y=\"50\"" + font +
                                             ">ab <tref dx=\"7\" href=\"#t\"/></text>");
  const svg::RenderedDocument moved_tspan =
      render("<text x=\"10\" y=\"50\"" + font + ">ab <tspan dx=\"7\">cd</tspan></text>");
  CHECK(max_delta(moved_tspan.image, moved.image) == 0);
  CHECK(max_delta(plain.image, moved.image) > 100);

  const svg::RenderedDocument alt = render("<text x=\"10\" y=\"50\"" + font + ">ab <altGlyph>cd</altGlyph></text>");
  REQUIRE(alt.warnings.size() == 1);
  CHECK(alt.warnings.front().find("<altGlyph> glyph substitution is not supported") != std::string::npos);
  CHECK(max_delta(plain.image, alt.image) == 0);
}

TEST_CASE("svg text: a font-weight between the family's faces is matched as CSS Fonts 4 5.2 says") {
  // DejaVu Sans has Book (400) and Bold (700) here. fontconfig alone takes the nearest weight, Book for
  // 520; CSS searches upwards from a weight above 500 and takes Bold, and from one in 400..500 first up
  // to 500, then downwards, taking Book for 450; below 400 it searches downwards, then upwards: Book.
  const Font bold = font("DejaVu Sans", 700);
  const Font book = font("DejaVu Sans", 400);
  REQUIRE(bold.style_name() == "Bold");
  REQUIRE(book.style_name() == "Book");
  const auto weighted = [](const std::string& weight) {
    return render(R"(<text x="10" y="50" font-family="DejaVu Sans" font-size="30" font-weight=")" + weight +
                  R"(">Weight</text>)")
        .image;
  };
  const Image as_bold = oracle({{&bold, "Weight", {10, 50}, sized(30), kBlack}});
  const Image as_book = oracle({{&book, "Weight", {10, 50}, sized(30), kBlack}});
  check_same(as_bold, weighted("520"));
  check_same(as_bold, weighted("600"));
  check_same(as_book, weighted("450"));
  check_same(as_book, weighted("100"));
  // The library's lookup is the same: load_font gives Bold for 520.
  CHECK(font("DejaVu Sans", 520).style_name() == "Bold");
}
