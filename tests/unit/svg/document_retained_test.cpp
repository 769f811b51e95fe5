// The retained document (svg::Document): parsed once, rendered many times at any size, or drawn into a
// caller's canvas under a transform — each time the same pixels as a fresh parse-and-render.
#include <catch2/catch.hpp>

#include <string>

#include "curvescan/raster/canvas.h"
#include "curvescan/svg/document.h"

namespace curvescan::svg {
namespace {

// A circle and a half-transparent square: curved edges and compositing both take part.
const std::string kDrawing = R"(<svg xmlns="http://www.w3.org/2000/svg" width="20" height="16" viewBox="0 0 40 32">
  <circle cx="16" cy="16" r="12" fill="#3060c0"/>
  <rect x="20" y="4" width="16" height="24" fill="red" fill-opacity="0.5"/>
</svg>)";

TEST_CASE("a document parsed once renders at several sizes as fresh renders do", "[svg][document]") {
  const Result<Document> document = Document::parse(kDrawing);
  REQUIRE(document);
  for (const double width : {20.0, 57.0, 200.0}) {
    RenderOptions options;
    options.width = width;
    const Result<RenderedDocument> retained = document->render(options);
    const Result<RenderedDocument> fresh = render_svg_document(kDrawing, options);
    REQUIRE(retained);
    REQUIRE(fresh);
    CHECK(retained->image.width() == static_cast<int>(width));
    CHECK(retained->image == fresh->image);  // same code path, same arithmetic: bit for bit
  }
}

TEST_CASE("a document drawn into a canvas under a translation lands where the transform says", "[svg][document]") {
  const Result<Document> document = Document::parse(kDrawing);
  REQUIRE(document);
  RenderOptions zoomed;
  zoomed.zoom = 2.0;
  const Result<RenderedDocument> alone = document->render(zoomed);
  REQUIRE(alone);
  Result<Canvas> canvas = Canvas::create(80, 60);
  REQUIRE(canvas);
  // Whole-pixel offsets keep every pixel's coverage exactly what it is in the render of its own.
  const Result<DocumentMessages> drawn =
      document->draw(*canvas, Affine::translate(10, 7) * Affine::scale(2, 2), RenderOptions{});
  REQUIRE(drawn);
  CHECK(drawn->warnings.empty());
  const Image& image = canvas->image();
  int painted = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const bool inside = x >= 10 && x < 10 + alone->image.width() && y >= 7 && y < 7 + alone->image.height();
      const Rgba8 expected = inside ? alone->image.at(x - 10, y - 7) : Rgba8{0, 0, 0, 0};
      if (image.at(x, y) != expected) FAIL("pixel " << x << "," << y << " differs");
      painted += image.at(x, y).a > 0;
    }
  }
  CHECK(painted > 500);  // the drawing is there, not an empty canvas equal to an empty render
}

TEST_CASE("parse refuses what render_svg_document refuses", "[svg][document]") {
  CHECK_FALSE(Document::parse("<svg xmlns='http://www.w3.org/2000/svg'/><svg/>"));
  CHECK_FALSE(Document::parse("text <svg xmlns='http://www.w3.org/2000/svg'/>"));
  CHECK_FALSE(Document::parse("<html/>"));
  CHECK_FALSE(Document::parse("<svg"));
}

}  // namespace
}  // namespace curvescan::svg
