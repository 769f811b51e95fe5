// render_svg_document: sizes and options, errors and limits, diagnostics, and the curvescan curve
// elements (each must draw exactly what an SVG path of the same Bézier pieces draws).
#include "curvescan/svg/document.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdio>
#include <string>

#include "curvescan/curves/catmull_rom.h"
#include "curvescan/curves/cubic_spline.h"
#include "curvescan/curves/hermite.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;

using curvescan::svg::testing::contains;
using curvescan::svg::testing::render;

namespace {

std::string svg_document(const std::string& attributes, const std::string& body) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:cs=\"urn:curvescan:curves\" " + attributes + ">" +
         body + "</svg>";
}

Error render_error(const std::string& text, const RenderOptions& options = {}) {
  const Result<RenderedDocument> rendered = render_svg_document(text, options);
  REQUIRE_FALSE(rendered.is_ok());
  return rendered.error();
}

// "C x1 y1 x2 y2 x y ..." for cubic pieces, with %.17g so the path data round-trips exactly.
std::string cubic_path_data(const std::vector<Bezier>& pieces) {
  std::string data;
  char buffer[64];
  const auto point = [&](Point p) {
    std::snprintf(buffer, sizeof buffer, " %.17g %.17g", p.x, p.y);
    data += buffer;
  };
  data += "M";
  point(pieces.front().points()[0]);
  for (const Bezier& piece : pieces) {
    data += " C";
    for (std::size_t i = 1; i < piece.points().size(); ++i) point(piece.points()[i]);
  }
  return data;
}

}  // namespace

TEST_CASE("output size: intrinsic, units at the dpi, -w alone, -w and -h, zoom, rounding up") {
  const std::string text = svg_document("width=\"100.4\" height=\"50\"", "");
  CHECK(render(text).image.width() == 101);  // rounded up, as rsvg-convert does
  RenderOptions zoom;
  zoom.zoom = 2.0;
  CHECK(render(text, zoom).image.height() == 100);
  RenderOptions width_only;
  width_only.width = 50.2;
  CHECK(render(svg_document("width=\"100\" height=\"50\"", ""), width_only).image.height() == 26);
  RenderOptions both;
  both.width = 30;
  both.height = 30;
  const Image stretched = render(svg_document("width=\"100\" height=\"50\"", ""), both).image;
  CHECK(stretched.width() == 30);
  CHECK(stretched.height() == 30);
  RenderOptions dpi;
  dpi.dpi = 300;
  CHECK(render(svg_document("width=\"1in\" height=\"2.54cm\"", ""), dpi).image.width() == 300);
  CHECK(render(svg_document("viewBox=\"0 0 40 24\"", "")).image.width() == 40);
}

TEST_CASE("background colour fills the canvas under the drawing") {
  RenderOptions options;
  options.background = Color{1, 0, 0, 1};
  const Image image = render(svg_document("width=\"4\" height=\"4\"", ""), options).image;
  CHECK(image.at(2, 2).r == 255);
  CHECK(image.at(2, 2).a == 255);
}

TEST_CASE("malformed XML and a non-svg root are errors with a position or a name") {
  const Error broken = render_error("<svg xmlns=\"http://www.w3.org/2000/svg\">\n<rect></svg>");
  CHECK(broken.kind == ErrorKind::kCorruptInput);
  CHECK(broken.message.find("not well-formed XML") != std::string::npos);
  CHECK(broken.message.find("line 2") != std::string::npos);
  const Error root = render_error("<html/>");
  CHECK(root.message == "the root element is <html>, not <svg>");
  CHECK(render_error("").kind == ErrorKind::kCorruptInput);
}

TEST_CASE("a NUL byte anywhere is not well-formed XML (XML 1.0, 2.2), named with its position") {
  using namespace std::string_literals;
  // After the root pugixml would stop at the NUL and accept the document, garbage and all.
  const std::string root = svg_document("width=\"8\" height=\"8\"", "<rect width=\"4\" height=\"4\"/>");
  for (const std::string& xml :
       {root + "\0<junk"s, "<svg xmlns=\"http://www.w3.org/2000/svg\">\n<rect width=\"5\0\"/></svg>"s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\">\n<text>a\0b</text></svg>"s}) {
    const Error nul = render_error(xml);
    INFO(nul.message);
    CHECK(nul.kind == ErrorKind::kCorruptInput);
    CHECK(nul.message.find("not well-formed XML: a NUL byte at line") != std::string::npos);
  }
  CHECK(render_error(root + "\0"s).message.find("a NUL byte at line 1") != std::string::npos);
  // UTF-16 text is all zero bytes between ASCII ones; with or without its byte order mark it still reads.
  std::string utf16le;
  for (const char c : root) utf16le += std::string{c, '\0'};
  CHECK(render(utf16le).image.width() == 8);
  CHECK(render("\xFF\xFE"s + utf16le).image.width() == 8);
}

TEST_CASE("an attribute repeated in a start-tag is not well-formed XML (XML 1.0, 3.1, Unique Att Spec)") {
  const Error twice = render_error(
      svg_document("width=\"8\" height=\"8\"", "<g>\n<rect width=\"1\" height=\"2\" width=\"9\"/></g>"));
  CHECK(twice.kind == ErrorKind::kCorruptInput);
  CHECK(twice.message.find("not well-formed XML: the attribute 'width' appears twice in <rect>") !=
        std::string::npos);
  CHECK(twice.message.find("line 2") != std::string::npos);
  // On the root, and on an element with many attributes (checked by sorting their names): the repeat
  // is found wherever it is; distinct names, however many, are accepted.
  CHECK(render_error("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"8\" width=\"8\"/>").kind ==
        ErrorKind::kCorruptInput);
  std::string many;
  for (int i = 0; i < 40; ++i) many += " data-a" + std::to_string(i) + "=\"1\"";
  CHECK(render(svg_document("width=\"8\" height=\"8\"", "<rect" + many + "/>")).image.width() == 8);
  const Error late =
      render_error(svg_document("width=\"8\" height=\"8\"", "<rect" + many + " data-a7=\"2\"/>"));
  CHECK(late.message.find("the attribute 'data-a7' appears twice in <rect>") != std::string::npos);
  // xlink:href and href are different names.
  CHECK(render(svg_document("width=\"8\" height=\"8\" xmlns:xlink=\"http://www.w3.org/1999/xlink\"",
                            "<use href=\"#a\" xlink:href=\"#a\"/>"))
            .image.width() == 8);
}

TEST_CASE("limits: canvas pixels, element count, nesting depth and <use> nesting are refused") {
  // The default allows 8192 x 8192 (a 9600 x 4800 flag drawn at its own size), not one row more.
  const Error big = render_error(svg_document("width=\"8192\" height=\"8193\"", ""));
  CHECK(big.kind == ErrorKind::kLimitExceeded);
  // The default is the most there is: the message does not offer to raise it.
  CHECK(big.message.find("give a smaller -w, -h or -z") != std::string::npos);
  CHECK(big.message.find("--max-pixels") == std::string::npos);
  CHECK(render(svg_document("width=\"9600\" height=\"4800\"", "")).image.width() == 9600);
  RenderOptions lowered;
  lowered.limits.max_pixels = std::int64_t{100} * 100;
  const Error over_lowered = render_error(svg_document("width=\"101\" height=\"100\"", ""), lowered);
  CHECK(over_lowered.kind == ErrorKind::kLimitExceeded);
  CHECK(over_lowered.message.find("raise it with --max-pixels") != std::string::npos);
  CHECK(render(svg_document("width=\"100\" height=\"100\"", ""), lowered).image.width() == 100);

  RenderOptions few;
  few.limits.max_elements = 3;
  CHECK(render_error(svg_document("width=\"4\" height=\"4\"", "<g/><g/><g/>"), few).kind ==
        ErrorKind::kLimitExceeded);

  std::string nested;
  for (int i = 0; i < 300; ++i) nested += "<g>";
  for (int i = 0; i < 300; ++i) nested += "</g>";
  CHECK(render_error(svg_document("width=\"4\" height=\"4\"", nested)).message.find("--max-depth") !=
        std::string::npos);

  // "Billion laughs" with <use>: each level uses the previous one ten times, 10^9 rectangles in all.
  std::string laughs = "<defs><rect id=\"l0\" width=\"1\" height=\"1\"/>";
  for (int level = 1; level <= 9; ++level) {
    laughs += "<g id=\"l" + std::to_string(level) + "\">";
    for (int i = 0; i < 10; ++i) laughs += "<use href=\"#l" + std::to_string(level - 1) + "\"/>";
    laughs += "</g>";
  }
  laughs += "</defs><use href=\"#l9\"/>";
  const Error laugh = render_error(svg_document("width=\"4\" height=\"4\"", laughs));
  CHECK(laugh.kind == ErrorKind::kLimitExceeded);
  CHECK(laugh.message.find("<use> expansions") != std::string::npos);

  // <use> nesting: three levels (2 223 elements, under the element limit) nested deeper than allowed. (The
  // nine-level document above is refused for its element count before anything is drawn, whatever its
  // nesting: the count is taken first, docs/limits.md.)
  std::string three_levels = "<defs><rect id=\"l0\" width=\"1\" height=\"1\"/>";
  for (int level = 1; level <= 3; ++level) {
    three_levels += "<g id=\"l" + std::to_string(level) + "\">";
    for (int i = 0; i < 10; ++i) three_levels += "<use href=\"#l" + std::to_string(level - 1) + "\"/>";
    three_levels += "</g>";
  }
  three_levels += "</defs><use href=\"#l3\"/>";
  RenderOptions shallow;
  shallow.limits.max_use_depth = 2;
  CHECK(render(svg_document("width=\"4\" height=\"4\"", three_levels)).image.width() == 4);
  const Error use_depth = render_error(svg_document("width=\"4\" height=\"4\"", three_levels), shallow);
  CHECK(use_depth.message.find("--max-use-depth") != std::string::npos);
}

TEST_CASE("diagnostics: broken references, unknown units, path errors and unknown elements warn") {
  const RenderedDocument rendered =
      render(svg_document("width=\"8\" height=\"8\"",
                          "<use href=\"#nope\"/><rect width=\"3km\" height=\"2\"/><path d=\"M0 0 L8 8 X\"/>"
                          "<blink/><rect width=\"2\" height=\"2\" fill=\"url(#nope)\"/>"));
  CHECK(contains(rendered.warnings, "'#nope', which does not exist"));
  CHECK(contains(rendered.warnings, "unknown unit 'km'"));
  CHECK(contains(rendered.warnings, "unexpected character 'X'"));
  // An unknown element's content is lost, so it is a warning (no silent loss), not a --verbose note.
  CHECK(contains(rendered.warnings, "<blink> is not a known SVG element, not drawn (nor its content)"));
  CHECK_FALSE(contains(rendered.notes, "blink"));
}

TEST_CASE("a filled square with an invalid fill keeps the inherited one — display none hides") {
  const Image image =
      render(svg_document("width=\"4\" height=\"4\"",
                          "<g fill=\"#00ff00\"><rect width=\"4\" height=\"2\" fill=\"bogus\"/>"
                          "<rect y=\"2\" width=\"4\" height=\"2\" display=\"none\"/></g>"))
          .image;
  CHECK(image.at(1, 0).g == 255);
  CHECK(image.at(1, 3).a == 0);
}

TEST_CASE("cs:catmull-rom, cs:hermite and cs:spline draw exactly the path of their Bezier pieces") {
  const std::vector<Point> points{{4, 30}, {14, 6}, {30, 26}, {44, 4}, {58, 30}};
  const std::string point_list = "4,30 14,6 30,26 44,4 58,30";
  const auto same_pixels = [&](const std::string& element, const std::vector<Bezier>& pieces) {
    const std::string style = " fill=\"#123456\" stroke=\"#abc\" stroke-width=\"2\"";
    const Image native = render(svg_document("width=\"64\" height=\"36\"", element)).image;
    const Image path = render(svg_document("width=\"64\" height=\"36\"",
                                           "<path d=\"" + cubic_path_data(pieces) + "\"" + style + "/>"))
                           .image;
    INFO(element);
    CHECK(native.pixels() == path.pixels());
    std::size_t painted = 0;
    for (const Rgba8& pixel : native.pixels()) painted += pixel.a != 0;
    CHECK(painted > 200);  // the element really drew something
  };
  const std::string style = " fill=\"#123456\" stroke=\"#abc\" stroke-width=\"2\"";
  same_pixels("<cs:catmull-rom points=\"" + point_list + "\" alpha=\"0.5\"" + style + "/>",
              *catmull_rom(points, 0.5));
  same_pixels("<cs:catmull-rom points=\"" + point_list + "\" alpha=\"0\"" + style + "/>",
              *catmull_rom(points, 0.0));
  const std::vector<Vec2> tangents{{20, -20}, {20, 0}, {20, 10}, {20, 0}, {20, 20}};
  same_pixels(
      "<cs:hermite points=\"" + point_list + "\" tangents=\"20,-20 20,0 20,10 20,0 20,20\"" + style + "/>",
      *hermite_spline(points, tangents));
  same_pixels("<cs:spline points=\"" + point_list + "\"" + style + "/>", *cubic_spline(points));
}

TEST_CASE("cs:nurbs circle covers the same pixels as an SVG circle — cs:bspline draws — bad input warns") {
  const std::string nurbs =
      "<cs:nurbs degree=\"2\" points=\"30 16 30 30 16 30 2 30 2 16 2 2 16 2 30 2 30 16\" "
      "weights=\"1 0.7071067811865476 1 0.7071067811865476 1 0.7071067811865476 1 0.7071067811865476 1\" "
      "knots=\"0 0 0 0.25 0.25 0.5 0.5 0.75 0.75 1 1 1\"/>";
  const Image from_nurbs = render(svg_document("width=\"32\" height=\"32\"", nurbs)).image;
  const Image from_circle =
      render(svg_document("width=\"32\" height=\"32\"", "<circle cx=\"16\" cy=\"16\" r=\"14\"/>")).image;
  // Both are exact conic arcs of the same circle flattened within 0.1 px, so coverage differs by at
  // most ~0.1 px of area per edge pixel: 0.1 · 255 ≈ 26 levels; 32 leaves room for the two flattenings.
  int max_delta = 0;
  for (std::size_t i = 0; i < from_nurbs.pixels().size(); ++i) {
    max_delta = std::max(max_delta, std::abs(from_nurbs.pixels()[i].a - from_circle.pixels()[i].a));
  }
  CHECK(max_delta <= 32);
  CHECK(from_nurbs.at(16, 16).a == 255);

  const Image bspline =
      render(svg_document("width=\"32\" height=\"32\"",
                          "<cs:bspline points=\"2,30 8,2 24,2 30,30\" degree=\"3\" closed=\"true\"/>"))
          .image;
  CHECK(bspline.at(16, 12).a == 255);

  const RenderedDocument bad =
      render(svg_document("width=\"8\" height=\"8\"",
                          "<cs:bspline points=\"1 2 3\"/><cs:nurbs points=\"0 0 1 1\" degree=\"0.5\"/>"
                          "<cs:teapot points=\"0 0\"/>"));
  CHECK(contains(bad.warnings, "<bspline>: attribute 'points' has an odd number of coordinates"));
  CHECK(contains(bad.warnings, "<nurbs>: degree '0.5' is not an integer"));
  CHECK(contains(bad.warnings, "unknown curvescan element <teapot>"));
}

TEST_CASE("processing instructions: <?xml-stylesheet?> is named once and ignored, others change nothing") {
  const std::string body = "<rect width=\"4\" height=\"8\" fill=\"#ff0000\"/><text><?pi inside text?></text>";
  const std::string plain = svg_document("width=\"8\" height=\"8\"", body);
  const std::string with_instructions =
      "<?xml version=\"1.0\"?><?xml-stylesheet href=\"a.css\"?><?xml-stylesheet href=\"b.css\"?>" +
      svg_document("width=\"8\" height=\"8\"", "<?other data?>" + body);
  const RenderedDocument expected = render(plain);
  const RenderedDocument rendered = render(with_instructions);
  const auto stylesheet_warnings =
      std::count_if(rendered.warnings.begin(), rendered.warnings.end(), [](const std::string& w) {
        return w.find("<?xml-stylesheet?> is not supported") != std::string::npos;
      });
  CHECK(stylesheet_warnings == 1);
  CHECK(rendered.warnings.size() == expected.warnings.size() + 1);
  // The instructions are dropped before drawing: the pixels are those of the document without them.
  CHECK(expected.image.at(1, 1) == Rgba8{255, 0, 0, 255});
  CHECK(rendered.image == expected.image);
  // Only the prolog links style sheets: one inside a comment there, or after the root, links nothing.
  const RenderedDocument commented =
      render("<!-- <?xml-stylesheet href=\"a.css\"?> -->" + plain + "<?xml-stylesheet href=\"b.css\"?>");
  CHECK(commented.warnings.size() == expected.warnings.size());
  CHECK(commented.image == expected.image);
}

TEST_CASE("warnings: each text once, at most 100, then a count of the ones left out") {
  // A marker that is not a <marker>, drawn at each of three vertices: one warning, not three.
  const RenderedDocument markers =
      render(svg_document("width=\"8\" height=\"8\"",
                          "<rect id=\"m\" width=\"1\" height=\"1\"/>"
                          "<path d=\"M1 1 L4 4 L7 1\" stroke=\"black\" marker-start=\"url(#m)\" "
                          "marker-mid=\"url(#m)\" marker-end=\"url(#m)\"/>"));
  CHECK(std::count_if(markers.warnings.begin(), markers.warnings.end(), [](const std::string& w) {
          return w.find("which is not a <marker>") != std::string::npos;
        }) == 1);

  // 250 elements with distinct invalid values: 100 warnings shown (the first ones), then "150 more".
  std::string body;
  for (int i = 0; i < 250; ++i)
    body += "<rect width=\"1\" height=\"1\" fill=\"bogus" + std::to_string(i) + "\"/>";
  const RenderedDocument many = render(svg_document("width=\"8\" height=\"8\"", body));
  REQUIRE(many.warnings.size() == 101);
  CHECK(many.warnings.front().find("'bogus0'") != std::string::npos);
  CHECK(many.warnings[99].find("'bogus99'") != std::string::npos);
  CHECK(many.warnings.back() == "150 more warnings not shown");
}

TEST_CASE("warnings: a long rejected value is quoted by its beginning and end, not whole") {
  // A 10^5-character fill (multi-byte characters, so that a cut inside one would show as invalid UTF-8).
  std::string value = "bogus";
  for (int i = 0; i < 50000; ++i) value += "\u00e9";  // é: two bytes in UTF-8
  const RenderedDocument rendered = render(
      svg_document("width=\"8\" height=\"8\"", "<rect width=\"1\" height=\"1\" fill=\"" + value + "\"/>"));
  const auto warning =
      std::find_if(rendered.warnings.begin(), rendered.warnings.end(),
                   [](const std::string& w) { return w.find("'bogus") != std::string::npos; });
  REQUIRE(warning != rendered.warnings.end());
  // Its beginning and the property it was for stay; the middle is counted, not printed.
  CHECK(warning->size() <= 400);
  CHECK(warning->find("of property 'fill'") != std::string::npos);
  CHECK(warning->find(" bytes not shown) …") != std::string::npos);
  // Every cut falls between characters: the text is valid UTF-8 (no continuation byte after an ASCII one).
  for (std::size_t i = 1; i < warning->size(); ++i) {
    const auto byte = static_cast<unsigned char>((*warning)[i]);
    const auto before = static_cast<unsigned char>((*warning)[i - 1]);
    if ((byte & 0xC0) == 0x80) CHECK((before & 0x80) != 0);
  }
}
