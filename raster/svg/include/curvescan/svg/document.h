// Rendering an SVG document (a practical subset of SVG 1.1 / SVG 2, see docs/svg.md) to an Image.
//
// The XML is parsed by pugixml (internal DTD entities expanded first); the reader walks the element tree
// once, resolving the cascade (presentation attributes, <style> sheets, the style attribute,
// inheritance) and drawing each shape through Canvas.
// Failures that make the whole document unusable (malformed XML, a root that is not <svg>, a limit
// exceeded, an image size out of range) are errors; problems local to one element (an invalid attribute
// value, an unknown unit, a broken reference, path data with an error) are warnings and the element is
// handled as the SVG specification prescribes for that error (ignored attribute, path rendered up to the
// error, element not rendered). An unknown element is not drawn, with a warning.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "curvescan/curves/affine.h"
#include "curvescan/curves/flatten.h"
#include "curvescan/raster/canvas.h"
#include "curvescan/raster/path.h"
#include "curvescan/raster/image.h"
#include "curvescan/raster/limits.h"
#include "curvescan/status.h"
#include "curvescan/svg/color.h"

namespace curvescan::svg {

/// Default largest output image, in pixels: 2^26 (8192 x 8192, 256 MiB of RGBA), the most any render may
/// ask for (limits.h's kMaxImagePixels). Documents that draw at their own size ask for more than 4096 x
/// 4096 often enough (flags drawn in a 9600 x 4800 view box, at one pixel a unit) that refusing them by
/// default made `render` fail where rsvg-convert draws; the memory limit (RenderLimits) still bounds
/// what a render holds beside its canvas. A caller may lower it.
inline constexpr std::int64_t kDefaultMaxCanvasPixels = kMaxImagePixels;

/// Bounds on what one document may ask for; each is refused with kLimitExceeded and a message naming it.
struct DocumentLimits {
  std::int64_t max_pixels = kDefaultMaxCanvasPixels;
  std::size_t max_elements = 1'000'000;  ///< elements rendered, counting each <use> expansion again
  int max_depth = 256;                   ///< element nesting, <use> expansions included
  int max_use_depth = 32;                ///< <use> inside <use> inside ...
  RenderLimits render;                   ///< segments, memory and dashes of the render (limits.h)
};

struct RenderOptions {
  /// Output size in pixels, as rsvg-convert's -w and -h: one of them alone, the other follows the aspect
  /// ratio; both, the drawing is stretched to exactly that size unless keep_aspect_ratio. With a zoom,
  /// they cap the zoomed size instead. The full rules are those of rsvg-convert 2.54 (docs/svg.md,
  /// "Output size").
  std::optional<double> width;
  std::optional<double> height;
  double zoom = 1.0;    ///< uniform scale factor (-z)
  double x_zoom = 1.0;  ///< horizontal scale factor, multiplied with zoom (-x)
  double y_zoom = 1.0;  ///< vertical scale factor, multiplied with zoom (-y)
  /// -a: with width and height, scale uniformly to fit inside them; with a zoom, scale it down uniformly.
  bool keep_aspect_ratio = false;
  double dpi = 96.0;  ///< resolution for in, cm, mm, pt, pc of horizontal lengths (x, width...)
  /// Resolution of vertical lengths (y, height...); dpi when not given. Lengths that are neither (r,
  /// stroke-width) take sqrt((dpi² + dpi_y²) / 2).
  std::optional<double> dpi_y;
  /// The image size when it should differ from the drawing's (rsvg-convert's --page-width and
  /// --page-height, px): the drawing is placed at (left, top) on a page of this size.
  std::optional<double> page_width;
  std::optional<double> page_height;
  double left = 0.0;  ///< px from the left edge of the page to the drawing (may be negative)
  double top = 0.0;   ///< px from the top edge of the page to the drawing
  std::optional<Color> background;              ///< painted under the drawing; transparent by default
  double tolerance = kDefaultFlattenTolerance;  ///< flattening tolerance in device pixels
  Antialias antialias = Antialias::kExact;
  DocumentLimits limits;
  /// Extra CSS applied as an author style sheet after the document's own <style> sheets (so it wins over
  /// them at equal specificity; the style attribute still wins over it). Empty: none. Its problems are
  /// reported as warnings like those of the document's sheets (docs/svg.md, "CSS").
  std::string style_sheet;
  /// What messages about `style_sheet` call it, say its file name; empty: "user style sheet".
  std::string style_sheet_name;
  /// Render only the element with this id (a leading '#' is allowed), as rsvg-convert's --export-id does:
  /// the output's natural size is the element's ink box (its fill and stroke, markers and filters not
  /// counted) in its parent's user space -- with its own transform, without its ancestors' transforms or
  /// the viewBox -- and the element is drawn with the styles it inherits, moved so that box starts at
  /// (0, 0). Empty: the whole document. An id that names no element is an error.
  std::string export_id;
  /// The user's languages, most preferred first (BCP 47 tags such as "en" or "fr-CA"), against which
  /// <switch> evaluates systemLanguage (SVG 1.1 5.8.5).
  std::vector<std::string> languages{"en"};
  /// Where <image> may read files: references relative to this directory (the document's own), and
  /// nothing above it. Unset (the default): only data: URIs are read. Nothing is ever read from the
  /// network.
  std::optional<std::filesystem::path> resource_directory;
  /// Threads a large fill may use (Canvas::set_threads): the pixels are the same for any number.
  int threads = 1;
};

struct RenderedDocument {
  Image image;
  /// Problems with the input, and SVG features not supported (each kind named once): the user should see
  /// these.
  std::vector<std::string> warnings;
  std::vector<std::string> notes;  ///< elements outside SVG that were skipped (the CLI's --verbose)
};

/// What drawing a document into a caller's canvas reports (RenderedDocument without the image).
struct DocumentMessages {
  std::vector<std::string> warnings;
  std::vector<std::string> notes;
};

/// A parsed SVG document, kept to be rendered many times — at any size, or into a canvas of the caller's
/// under any transform — without parsing it again. parse() checks that the XML is well-formed with one
/// <svg> root; each render walks the element tree (styles, references, units) for its own options.
class Document {
 public:
  /// Parses the UTF-8 text of a whole SVG file. kCorruptInput for malformed XML, no root, several roots,
  /// text outside the root, or a root other than <svg>; kLimitExceeded when the parsed tree (pugixml's
  /// nodes and its copy of the text, entities expanded) would take more than `max_memory_bytes`.
  [[nodiscard]] static Result<Document> parse(std::string_view xml,
                                              std::int64_t max_memory_bytes = kDefaultMaxRenderMemoryBytes);

  /// Parses an SVG-in-OpenType glyph document as the font stores it (color_glyph_svg_document): inflated
  /// first when it is gzip-compressed, as the OpenType specification allows, then read as parse() reads;
  /// draw it with draw_glyph(). The inflated text and the tree each stay within `max_memory_bytes`
  /// (kLimitExceeded beyond). kCorruptInput for a broken gzip stream or a document that is not
  /// well-formed SVG, its message completing "an SVG glyph document ..." ("cannot be inflated (...)", "is
  /// not a well-formed SVG document (...)"), as SVG text words its warning.
  [[nodiscard]] static Result<Document> parse_glyph_document(
      std::string_view stored, std::int64_t max_memory_bytes = kDefaultMaxRenderMemoryBytes);

  /// Bytes the parsed tree holds; render() and draw() count them against the render's memory budget.
  [[nodiscard]] std::int64_t memory_bytes() const noexcept;

  Document(Document&&) noexcept;
  Document& operator=(Document&&) noexcept;
  ~Document();

  /// Renders into a new image sized by `options` (width, height, zoom; document.h's RenderOptions).
  [[nodiscard]] Result<RenderedDocument> render(const RenderOptions& options) const;

  /// Draws into `canvas` over what it holds. `transform` maps the document's CSS pixels (its width and
  /// height at options.dpi, before its viewBox) to the canvas's pixels; options.width, height, zoom and
  /// background are not used. The canvas's own limits (Canvas::create) bound the work.
  [[nodiscard]] Result<DocumentMessages> draw(Canvas& canvas, const Affine& transform,
                                              const RenderOptions& options) const;

  /// Draws glyph `glyph` of an SVG-in-OpenType glyph document (OpenType, "SVG " table: the element with
  /// id "glyphN") into `canvas` over what it holds, as SVG text draws it: `transform` maps the document's
  /// user space — font units, y down, the glyph's origin at (0, 0) — to the canvas; no viewport is set up
  /// and nothing is clipped; percentages are of a `units_per_em` square. A document without the element
  /// draws nothing, with a warning.
  [[nodiscard]] Result<DocumentMessages> draw_glyph(Canvas& canvas, std::uint32_t glyph,
                                                    const Affine& transform, double units_per_em,
                                                    const RenderOptions& options) const;

  /// The ink box of glyph `glyph` of an SVG-in-OpenType glyph document — the box of what draw_glyph paints:
  /// its fills and strokes (not the reach of filters or markers), in the document's user space (font
  /// units, y down, the glyph's origin at (0, 0)) — so that a caller can size a canvas to the glyph as
  /// drawn, which may reach beyond the glyph's outline and its line box. nullopt when the document has no
  /// such element or it draws nothing.
  [[nodiscard]] std::optional<Rect> glyph_ink_box(std::uint32_t glyph, double units_per_em,
                                                  const RenderOptions& options) const;

 private:
  struct Parsed;
  explicit Document(std::unique_ptr<Parsed> parsed);
  std::unique_ptr<Parsed> parsed_;
};

/// Renders the document `xml` (UTF-8 text of a whole SVG file): Document::parse, then render.
[[nodiscard]] Result<RenderedDocument> render_svg_document(std::string_view xml,
                                                           const RenderOptions& options);

}  // namespace curvescan::svg
