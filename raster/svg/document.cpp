// The SVG document renderer (document.h): pugixml parses, one recursive walk renders.
//
// The walk is bounded: element nesting (DocumentLimits::max_depth), <use> nesting (max_use_depth) and the
// total number of elements rendered (max_elements, counting every <use> expansion again, so a "billion
// laughs" of nested <use> is refused instead of taking hours) -- each a kLimitExceeded error. A <use>
// that refers to itself or to one of its ancestors is an error in SVG 1.1 (5.6): it is skipped with a
// warning.
#include "curvescan/svg/document.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <numbers>
#include <pugixml.hpp>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <variant>
#include <vector>

#include "canvas_background.h"
#include "cascade.h"
#include "computed_style.h"
#include "context_paint.h"
#include "css/style_sheet.h"
#include "css_transform.h"
#include "curve_elements.h"
#include "curvescan/raster/canvas.h"
#include "curvescan/raster/image_pattern.h"
#include "curvescan/raster/limits.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/png_io.h"
#include "curvescan/svg/number.h"
#include "curvescan/svg/path_data.h"
#include "curvescan/svg/transform.h"
#include "curvescan/svg/viewport.h"
#include "document_index.h"
#include "filter/filter_graph.h"
#include "filter/filter_surface.h"
#include "geometry_properties.h"
#include "group_node_probe.h"
#include "image_loading.h"
#include "image_source.h"
#include "marker.h"
#include "mask.h"
#include "output_size.h"
#include "output_size_refusal.h"
#include "paint_server.h"
#include "path_node_probe.h"
#include "pattern.h"
#include "placed_marker.h"
#include "render_group.h"
#include "render_path.h"
#include "resolved_references.h"
#include "shape_paths.h"
#include "source_positions.h"
#include "stroke_style.h"
#include "svg_glyph_document.h"
#include "svg_tree.h"
#include "text_element.h"
#include "transform_origin.h"
#include "xml_names.h"

namespace curvescan::svg {
namespace {

using detail::ComputedStyle;
using detail::Diagnostics;
using detail::PaintSpec;
using detail::stroke_style_of;

using detail::local_name;

// The viewport percentages refer to, in user units of the current coordinate system.
struct Viewport {
  double width = 100.0;
  double height = 100.0;
};

/// Deepest nesting of SVG documents drawn by <image> inside one another.
constexpr int kMaxImageDepth = 4;

/// The offscreen images of one render (mask contents, clip paths of several children, pattern tiles) may
/// add up to this many times the output's pixels, counted as at least kOffscreenBasisPixels and at most
/// DocumentLimits::max_pixels (2^29 pixels up to a 4096 x 4096 output: seconds of work, some 30 masks at
/// 4096 x 4096 or 500 at 1000 x 1000; docs/limits.md). Each offscreen image covers at most the output.
constexpr std::int64_t kOffscreenPixelsPerCanvasPixel = 32;
constexpr std::int64_t kOffscreenBasisPixels = std::int64_t{1} << 24;

Error limit_error(const std::string& what) {
  return Error{ErrorKind::kLimitExceeded, what};
}

class DocumentRenderer {
 public:
  /// `style_sheets`: the document's author sheets (null: none); `image_depth`: how many <image> elements
  /// with SVG content this document is nested in.
  DocumentRenderer(const pugi::xml_node& root, const RenderOptions& options,
                   const css::StyleSheets* style_sheets, Diagnostics& diagnostics, int image_depth = 0)
      : root_(root),
        options_(options),
        diagnostics_(diagnostics),
        style_sheets_(style_sheets),
        image_depth_(image_depth) {}

  /// Memory the parsed document holds, counted against the render's memory budget (Document::parse).
  void set_document_bytes(std::int64_t bytes) noexcept { document_bytes_ = bytes; }

  /// Shows each Group node made to `probe` (null: none), for tests (group_node_probe.h).
  void set_group_probe(const detail::GroupNodeProbe* probe) noexcept { group_probe_ = probe; }
  /// Shows each shape's Path node made to `probe` (null: none), for tests (path_node_probe.h).
  void set_path_probe(const detail::PathNodeProbe* probe) noexcept { path_probe_ = probe; }

  Result<Image> render() {
    CURVESCAN_PROPAGATE(build_index());
    const Result<Size> size = options_.export_id.empty() ? intrinsic_size() : export_size();
    if (!size) return size.error();
    // -w / -h / -z / -x / -y / -a (output_size.h), then the page (--page-width, --left, ...).
    detail::OutputSizeAsked asked;
    asked.request = {size->width,
                     size->height,
                     options_.width,
                     options_.height,
                     options_.zoom * options_.x_zoom,
                     options_.zoom * options_.y_zoom,
                     options_.keep_aspect_ratio};
    asked.zoom = options_.zoom;
    asked.x_zoom = options_.x_zoom;
    asked.y_zoom = options_.y_zoom;
    asked.page_width = options_.page_width;
    asked.page_height = options_.page_height;
    asked.dpi_x = options_.dpi;
    asked.dpi_y = options_.dpi_y.value_or(options_.dpi);
    asked.exported = !options_.export_id.empty();
    asked.max_pixels = options_.limits.max_pixels;
    const std::optional<detail::OutputSize> drawn = detail::output_size(asked.request);
    if (!drawn) return Error{ErrorKind::kInvalidArgument, "the document has no positive width and height"};
    const double scale_x = drawn->width / size->width, scale_y = drawn->height / size->height;
    use_medium(drawn->width, drawn->height, scale_x);
    const Result<detail::OutputPixels> pixels = detail::output_pixels(asked, *drawn);
    if (!pixels) return pixels.error();
    Result<Canvas> canvas = Canvas::create(pixels->width, pixels->height, options_.limits.render);
    if (!canvas) return canvas.error();
    output_pixels_ = std::int64_t{pixels->width} * pixels->height;
    canvas->set_held_memory_bytes(document_bytes_);
    canvas->set_threads(options_.threads);
    if (options_.background) {
      const Color& bg = *options_.background;
      canvas->clear(Paint::solid(bg));
    }
    const Affine placement = Affine::translate(options_.left, options_.top) * Affine::scale(scale_x, scale_y);
    CURVESCAN_PROPAGATE(draw_sized(*canvas, placement, *size));
    return std::move(*canvas).take_image();
  }

  /// Draws the element with id `id` of an SVG-in-OpenType glyph document (OpenType spec, "SVG " table:
  /// "glyphN") into the caller's canvas, `transform` mapping the document's user space (font units, y
  /// down) to the canvas. No viewport is set up and nothing is clipped: the glyph's coordinates are the
  /// font's, above the baseline at negative y. Percentages are of a `units_per_em` square. The root element
  /// is drawn as a group (its transform, opacity, clip and mask applied), any other through its ancestors'
  /// styles. A document without the element draws nothing, with a warning.
  Status draw_glyph_element(Canvas& canvas, const std::string& id, const Affine& transform,
                            double units_per_em) {
    CURVESCAN_PROPAGATE(build_index());
    canvas_ = &canvas;
    const auto found = index_.ids().find(id);
    if (found == index_.ids().end()) {
      diagnostics_.warnings.push_back("an SVG glyph document has no element \"" + id +
                                      "\"; the glyph is not drawn");
      return Status::ok();
    }
    const pugi::xml_node node = found->second;
    const Viewport viewport{units_per_em, units_per_em};
    const ComputedStyle initial;
    if (node == root_) {
      const ComputedStyle style = computed_style(root_, initial, viewport);
      if (!style.display) return Status::ok();
      return draw_group(*group_node(root_, style, viewport, 1), transform, viewport, 1,
                        [&](double folded_opacity, const Affine& content_ctm) {
                          std::optional<ComputedStyle> adjusted;
                          return render_children(root_, content_style(style, folded_opacity, adjusted),
                                                 content_ctm, viewport, 1);
                        });
    }
    std::vector<pugi::xml_node> ancestors;
    for (pugi::xml_node up = node.parent(); up && up.type() == pugi::node_element; up = up.parent())
      ancestors.push_back(up);
    ComputedStyle parent = initial;
    for (auto it = ancestors.rbegin(); it != ancestors.rend(); ++it)
      parent = computed_style(*it, parent, viewport);
    return render_element(node, parent, transform, viewport, 1);
  }

  /// The ink box (fills and strokes, as export_size measures it) of the element with id `id` of an
  /// SVG-in-OpenType glyph document, in the document's user space as draw_glyph_element places it;
  /// nullopt when the element is missing or draws nothing.
  std::optional<Rect> glyph_element_ink_box(const std::string& id, double units_per_em) {
    if (!build_index().is_ok()) return std::nullopt;
    const auto found = index_.ids().find(id);
    if (found == index_.ids().end()) return std::nullopt;
    const pugi::xml_node node = found->second;
    const Viewport viewport{units_per_em, units_per_em};
    ComputedStyle parent;
    std::vector<pugi::xml_node> ancestors;
    if (node != root_) {
      for (pugi::xml_node up = node.parent(); up && up.type() == pugi::node_element; up = up.parent())
        ancestors.push_back(up);
    }
    for (auto it = ancestors.rbegin(); it != ancestors.rend(); ++it)
      parent = computed_style(*it, parent, viewport);
    const ComputedStyle style = computed_style(node, parent, viewport);
    if (!style.display) return std::nullopt;
    measuring_ink_ = true;
    const std::optional<Rect> box = object_bbox(node, style, viewport, 1);
    measuring_ink_ = false;
    std::optional<Rect> ink;
    include_transformed(ink, box, element_transform(node, viewport, style.font_size));
    return ink;
  }

  /// Draws the document into the caller's canvas; `transform` maps the document's CSS pixels (its
  /// width and height, before the viewBox) to the canvas.
  Status draw(Canvas& canvas, const Affine& transform) {
    CURVESCAN_PROPAGATE(build_index());
    const Result<Size> size = intrinsic_size();
    if (!size) return size.error();
    use_medium(size->width, size->height, 1.0);
    return draw_sized(canvas, transform, *size);
  }

 private:
  // The @media queries of the style sheets (css/media_query.h) see a screen of width x height px at
  // `scale` device pixels per px: a copy of the sheets with that medium, made only when some rule
  // depends on one. Before this (while the size is being found), size queries do not match.
  void use_medium(double width, double height, double scale) {
    if (!style_sheets_ || !style_sheets_->has_media_rules()) return;
    media_sheets_ = *style_sheets_;
    media_sheets_.set_medium({true, width, height, 96.0 * scale});
    style_sheets_ = &media_sheets_;
    references_.reset(&index_.ids());  // what was resolved with the other sheets
  }

  struct Size {
    double width, height;
    std::optional<ViewBox> view_box;  // read once, so that a bad viewBox is reported once
  };

  // Intrinsic size, as rsvg-convert 2.54 finds it (librsvg's legacy layer geometry), so that sizes and
  // placements agree with it (SVG 2 8.2 leaves the size of a document without one to the user agent):
  //  - width and height both lengths (not percentages; a missing one is 100%): that size;
  //  - otherwise, with a viewBox: both percentages give the viewBox's size; one length gives that length
  //    and the other in the viewBox's aspect ratio;
  //  - otherwise the drawing's ink box (fills and strokes, not moved to the origin), measured in a
  //    viewport of 1 x 1 px (percentages are of 1 px), as librsvg measures it.
  // Without a viewBox, the root is then drawn as if it had viewBox="0 0 W H", where W x H is its width and
  // height resolved against that size, so that a document of width="80" alone is scaled to fit (librsvg
  // synthesizes the same viewBox for the outermost <svg>).
  Result<Size> intrinsic_size() {
    const detail::ComputedStyle initial;
    const std::optional<ViewBox> view_box = view_box_of(root_);
    // The root's width or height: a length in px, or the fraction of a percentage (missing: 100%).
    struct Dimension {
      double value = 1.0;
      bool percent = true;
      double of(double reference) const { return percent ? value * reference : value; }
    };
    const auto dimension = [&](const char* attribute, double dpi) {
      const pugi::xml_attribute value = root_.attribute(attribute);
      if (!value) return Dimension{};
      const Result<Length> length = parse_length(value.value());
      if (!length) {
        diagnostics_.warnings.push_back("<svg> " + std::string(attribute) + ": " + length.error().message);
        return Dimension{};
      }
      if (length->unit == LengthUnit::kPercent) return Dimension{length->value / 100.0, true};
      return Dimension{length_to_pixels(*length, LengthContext{dpi, initial.font_size, 0.0}), false};
    };
    const Dimension w = dimension("width", options_.dpi);
    const Dimension h = dimension("height", options_.dpi_y.value_or(options_.dpi));
    double width = 0.0, height = 0.0;
    std::optional<ViewBox> drawn_view_box = view_box;
    if (!w.percent && !h.percent) {
      width = w.value;
      height = h.value;
    } else if (view_box) {
      if (view_box->width == 0.0 || view_box->height == 0.0) {
        width = height = 0.0;
      } else if (w.percent && h.percent) {
        width = view_box->width;
        height = view_box->height;
      } else if (!w.percent) {
        width = w.value;
        height = w.value * view_box->height / view_box->width;
      } else {
        width = h.value * view_box->width / view_box->height;
        height = h.value;
      }
    } else {
      const Viewport viewport{1.0, 1.0};
      const ComputedStyle style = computed_style(root_, initial, viewport);
      measuring_ink_ = true;
      const std::optional<Rect> ink = object_bbox(root_, style, viewport, 1);
      measuring_ink_ = false;
      // A drawing with no ink: rsvg-convert refuses it ("has no dimensions"); this reader keeps the size
      // an empty page has in a browser's <img>, 100 x 100 px of the percentages' reference.
      width = w.of(100.0);
      height = h.of(100.0);
      if (ink && ink->width() > 0.0 && ink->height() > 0.0 && std::isfinite(ink->width()) &&
          std::isfinite(ink->height())) {
        width = ink->width();
        height = ink->height();
      }
      if (width > 0.0 && height > 0.0) drawn_view_box = ViewBox{0.0, 0.0, w.of(width), h.of(height)};
    }
    if (!(width > 0.0) || !(height > 0.0) || !std::isfinite(width) || !std::isfinite(height)) {
      return Error{ErrorKind::kInvalidArgument, "the document has no positive width and height"};
    }
    return Size{width, height, drawn_view_box};
  }

  // --export-id: the element's ink box as the natural size (RenderOptions::export_id). The styles it
  // inherits and the viewport its lengths refer to come from its ancestors, as in the whole document.
  Result<Size> export_size() {
    std::string_view id = options_.export_id;
    if (id.front() == '#') id.remove_prefix(1);
    const auto found = index_.ids().find(std::string(id));
    if (found == index_.ids().end()) {
      return Error{ErrorKind::kInvalidArgument, "the document has no element with id \"" + std::string(id) + "\""};
    }
    const Result<Size> document_size = intrinsic_size();
    if (!document_size) return document_size.error();
    export_node_ = found->second;
    export_viewport_ = {document_size->width, document_size->height};
    if (document_size->view_box) export_viewport_ = {document_size->view_box->width, document_size->view_box->height};
    std::vector<pugi::xml_node> ancestors;
    for (pugi::xml_node up = export_node_.parent(); up && up.type() == pugi::node_element; up = up.parent()) {
      ancestors.push_back(up);
    }
    export_parent_style_ = ComputedStyle{};
    for (auto it = ancestors.rbegin(); it != ancestors.rend(); ++it) {
      export_parent_style_ = computed_style(*it, export_parent_style_, export_viewport_);
    }
    const ComputedStyle style = computed_style(export_node_, export_parent_style_, export_viewport_);
    measuring_ink_ = true;
    const std::optional<Rect> box = object_bbox(export_node_, style, export_viewport_, 1);
    measuring_ink_ = false;
    std::optional<Rect> ink;
    if (export_node_ == root_) {
      // The root <svg>: its ink box in the coordinates of the image, through its own transform and viewBox
      // mapping (the size rsvg-convert gives it), and drawn as the whole document is (draw_sized).
      export_root_size_ = *document_size;
      const Viewport outer{document_size->width, document_size->height};
      Affine placed = element_transform(root_, outer, style.font_size);
      if (const std::optional<ViewBox>& view_box = document_size->view_box) {
        placed = placed * view_box_transform(*view_box, aspect_of(root_), 0.0, 0.0, outer.width, outer.height);
      }
      include_transformed(ink, box, placed);
    } else {
      include_transformed(ink, box, element_transform(export_node_, export_viewport_, style.font_size));
    }
    if (!ink || !(ink->width() > 0.0) || !(ink->height() > 0.0) || !std::isfinite(ink->width()) ||
        !std::isfinite(ink->height())) {
      return Error{ErrorKind::kInvalidArgument, "the element with id \"" + std::string(id) + "\" draws nothing"};
    }
    export_origin_ = Point{ink->x0, ink->y0};
    return Size{ink->width(), ink->height(), std::nullopt};
  }

  Status draw_sized(Canvas& canvas, const Affine& transform, const Size& size) {
    canvas_ = &canvas;
    if (export_root_size_) {
      return draw_document(transform * Affine::translate(-export_origin_.x, -export_origin_.y), *export_root_size_);
    }
    if (export_node_) {
      return render_element(export_node_, export_parent_style_,
                            transform * Affine::translate(-export_origin_.x, -export_origin_.y), export_viewport_, 1);
    }
    return draw_document(transform, size);
  }

  // The whole document at `size` (its width, height and viewBox), through `transform`.
  Status draw_document(const Affine& transform, const Size& size) {
    const detail::ComputedStyle initial;
    const std::optional<ViewBox>& view_box = size.view_box;
    // SVG 2 (8.5, 8.6): a transform on the root <svg> applies outside its viewBox mapping.
    const Viewport outer{size.width, size.height};
    Viewport viewport = outer;
    if (view_box) {
      if (view_box->width == 0.0 || view_box->height == 0.0) return Status::ok();  // 7.7: nothing drawn
      viewport = {view_box->width, view_box->height};
    }
    if (!index_.facts(root_).conditions_hold) return Status::ok();  // 5.8.1
    const ComputedStyle style = computed_style(root_, initial, viewport);
    if (!style.display) return Status::ok();
    // The root's opacity, clip-path and mask apply to the whole drawing, as on a group.
    const RootPlacement placement{outer, view_box};
    const std::optional<detail::GroupNode> group = group_node(root_, style, viewport, 1, nullptr, &placement);
    CURVESCAN_PROPAGATE(paint_canvas_background(transform, outer, style));
    return draw_group(*group, transform, viewport, 1, [&](double folded_opacity, const Affine& content_ctm) {
      std::optional<ComputedStyle> adjusted;
      return render_children(root_, content_style(style, folded_opacity, adjusted), content_ctm, viewport, 1);
    });
  }

  // The root's background-color under the whole drawing, over the document's area (canvas_background.h).
  Status paint_canvas_background(const Affine& transform, const Viewport& outer, const ComputedStyle& style) {
    const std::optional<Color> color = detail::canvas_background_color(root_, style_sheets_, style.color);
    if (!color) return Status::ok();
    const std::optional<Path> area =
        detail::rect_path(0.0, 0.0, outer.width, outer.height, std::nullopt, std::nullopt);
    if (!area) return Status::ok();
    const Status status = canvas_->fill(*area, Paint::solid(*color), FillRule::kNonZero, transform,
                                        FillOptions{options_.tolerance, options_.antialias});
    if (!status && status.error().kind == ErrorKind::kLimitExceeded) return status;
    if (!status) diagnostics_.warnings.push_back("the background colour was not drawn: " + status.error().message);
    return Status::ok();
  }

  // The resolve pass's per-element decisions (document_index.h): roles, conditions, ids, mask loops.
  Status build_index() {
    Result<detail::DocumentIndex> index = detail::DocumentIndex::build(
        root_, options_.languages, options_.limits.max_elements, style_sheets_, diagnostics_);
    if (!index) return index.error();
    index_ = std::move(*index);
    references_.reset(&index_.ids());
    return Status::ok();
  }

  std::optional<ViewBox> view_box_of(const pugi::xml_node& node) {
    const pugi::xml_attribute attribute = node.attribute("viewBox");
    if (!attribute) return std::nullopt;
    const Result<ViewBox> box = parse_view_box(attribute.value());
    if (!box) {
      diagnostics_.warnings.push_back(box.error().message);
      return std::nullopt;
    }
    return *box;
  }

  PreserveAspectRatio aspect_of(const pugi::xml_node& node) {
    const pugi::xml_attribute attribute = node.attribute("preserveAspectRatio");
    if (!attribute) return {};
    const Result<PreserveAspectRatio> aspect = parse_preserve_aspect_ratio(attribute.value());
    if (!aspect) {
      diagnostics_.warnings.push_back(aspect.error().message);
      return {};
    }
    return *aspect;
  }

  ComputedStyle computed_style(const pugi::xml_node& node, const ComputedStyle& parent,
                               const Viewport& viewport) {
    ComputedStyle style = detail::cascade_style(node, parent, resolve_context(viewport), diagnostics_);
    if (index_.facts(node).mask_loop_dropped) style.painting.mask_id.clear();  // a loop
    return style;
  }

  detail::ResolveContext resolve_context(const Viewport& viewport) const {
    return detail::ResolveContext{viewport.width, viewport.height, resolution(), style_sheets_};
  }

  // The resolution of in, cm, mm, pt and pc across and down (rsvg-convert's -d and -p).
  Resolution resolution() const { return {options_.dpi, options_.dpi_y.value_or(options_.dpi)}; }
  LengthAxis horizontal(const Viewport& viewport) const { return {viewport.width, resolution().x}; }
  LengthAxis vertical(const Viewport& viewport) const { return {viewport.height, resolution().y}; }

  double length(const pugi::xml_node& node, const char* attribute, LengthAxis axis,
                const ComputedStyle& style, double fallback = 0.0) {
    const pugi::xml_attribute value = node.attribute(attribute);
    if (!value) return fallback;
    return detail::resolve_length(attribute, value.value(), axis, style.font_size, diagnostics_)
        .value_or(fallback);
  }

  std::optional<double> optional_length(const pugi::xml_node& node, const char* attribute, LengthAxis axis,
                                        const ComputedStyle& style) {
    const pugi::xml_attribute value = node.attribute(attribute);
    if (!value || std::string_view(value.value()) == "auto") return std::nullopt;
    return detail::resolve_length(attribute, value.value(), axis, style.font_size, diagnostics_);
  }

  // The transform attribute, or the transform property of a style sheet or style attribute, which wins
  // over it (SVG 2 8.5). A CSS value this reader cannot parse (CSS units such as rotate(45deg), which
  // SVG's syntax lacks) is ignored with a warning and the attribute applies, as for an invalid
  // declaration.
  // The element's transform (the CSS property from a sheet or the style attribute, else the attribute),
  // about its transform-origin (CSS Transforms 1, 6.1; transform-box view-box, so percentages and
  // keywords refer to the viewport and the origin is its top-left corner).
  // `font_size`: the element's, in px, for em lengths in the transform and its origin.
  Affine element_transform(const pugi::xml_node& node, const Viewport& viewport, double font_size) {
    const Affine transform = declared_transform(node, {font_size, viewport.width, viewport.height});
    if (transform == Affine::identity()) return transform;
    std::optional<std::string> origin = detail::declared_value(node, "transform-origin", style_sheets_);
    if (!origin) {
      const pugi::xml_attribute attribute = node.attribute("transform-origin");
      if (!attribute) return transform;
      origin = attribute.value();
    }
    const std::optional<Point> point = transform_origin(*origin, viewport, font_size);
    if (!point) {
      diagnostics_.warnings.push_back("<" + std::string(node.name()) + "> ignoring transform-origin \"" + *origin +
                                      "\"");
      return transform;
    }
    return Affine::translate(point->x, point->y) * transform * Affine::translate(-point->x, -point->y);
  }

  Affine declared_transform(const pugi::xml_node& node, const detail::CssTransformContext& context) {
    // none, and initial or unset (the property is not inherited), are the identity. A declaration this
    // reader cannot parse falls back to the next one down, with a warning.
    const auto is_identity = [](std::string_view value) {
      const std::string keyword = css::ascii_lower(trim_whitespace(value));
      return keyword == "none" || keyword == "initial" || keyword == "unset";
    };
    // SVG's syntax first, then CSS's (units, commas: css_transform.h).
    const auto parse_either = [&](std::string_view value) {
      Result<Affine> transform = parse_transform(value);
      if (transform) return transform;
      Result<Affine> css = detail::parse_css_transform(value, context);
      return css ? css : transform;
    };
    const detail::ValueCheck valid = [&](std::string_view value) {
      if (is_identity(value)) return true;
      const Result<Affine> transform = parse_either(value);
      if (!transform)
        diagnostics_.warnings.push_back("<" + std::string(node.name()) +
                                        "> ignoring the transform property: " + transform.error().message);
      return transform.is_ok();
    };
    if (const std::optional<std::string> declared =
            detail::declared_value(node, "transform", style_sheets_, valid)) {
      if (is_identity(*declared)) return Affine::identity();
      return *parse_either(*declared);
    }
    const pugi::xml_attribute attribute = node.attribute("transform");
    if (!attribute) return Affine::identity();
    // The attribute takes the CSS functions too (CSS Transforms 1, 7.1: the SVG grammar extends CSS's).
    const Result<Affine> transform = parse_either(attribute.value());
    if (!transform) {
      diagnostics_.warnings.push_back("<" + std::string(node.name()) + "> ignoring " +
                                      transform.error().message);
      return Affine::identity();
    }
    return *transform;
  }

  // transform-origin (transform_origin.h).
  std::optional<Point> transform_origin(std::string_view text, const Viewport& viewport, double font_size) {
    return detail::transform_origin_point(text, viewport.width, viewport.height, font_size, resolution(),
                                          diagnostics_);
  }

  Status render_children(const pugi::xml_node& node, const ComputedStyle& style, const Affine& ctm,
                         const Viewport& viewport, int depth) {
    for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
      if (child.type() != pugi::node_element) continue;
      CURVESCAN_PROPAGATE(render_element(child, style, ctm, viewport, depth));
    }
    return Status::ok();
  }

  Status render_element(const pugi::xml_node& node, const ComputedStyle& parent, const Affine& parent_ctm,
                        const Viewport& viewport, int depth) {
    if (depth > options_.limits.max_depth) {
      return limit_error("elements are nested more than " + std::to_string(options_.limits.max_depth) +
                         " deep (raise --max-depth)");
    }
    if (++rendered_elements_ > options_.limits.max_elements) {
      return limit_error("rendering needs more than " + std::to_string(options_.limits.max_elements) +
                         " elements, <use> expansions included (raise --max-elements)");
    }
    const detail::ElementFacts& facts = index_.facts(node);
    const std::string_view name = local_name(node);
    const bool is_curve = facts.role == detail::ElementRole::kCurve;
    switch (facts.role) {
      case detail::ElementRole::kCurve:
      case detail::ElementRole::kRendered:
        break;
      case detail::ElementRole::kForeign:       // foreign markup (RDF, Inkscape's) is not rendered
      case detail::ElementRole::kNonRendering:  // drawn only through a reference
      case detail::ElementRole::kUnsupported:   // named once by the index (document_index.h)
        return Status::ok();
      case detail::ElementRole::kUnknown:  // not rendered, nor its children (SVG 2, "Unknown elements")
        diagnostics_.unknown_element(name);
        return Status::ok();
    }
    // Conditional processing attributes that fail skip a graphics element, inside a <switch> or not
    // (SVG 1.1 5.8.1); on referenced elements (defs, clipPath, gradients) they have no effect.
    if (!facts.conditions_hold) return Status::ok();
    ComputedStyle style = computed_style(node, parent, viewport);
    if (!style.display) return Status::ok();
    // A shape's geometry comes with its group: clip paths in objectBoundingBox units refer to its box.
    std::optional<Path> shape;
    const ShapeGeometry geometry{shape, name, is_curve};
    const std::optional<detail::GroupNode> group =
        group_node(node, style, viewport, depth, is_curve || is_basic_shape(name) ? &geometry : nullptr);
    if (!group) return Status::ok();  // a shape without geometry
    return draw_group(
        *group, parent_ctm, viewport, depth, [&](double folded_opacity, const Affine& content_ctm) -> Status {
          std::optional<ComputedStyle> adjusted;
          const ComputedStyle& content = content_style(style, folded_opacity, adjusted);
          if (shape) {
            // draw_group draws its content once: the geometry moves into the node. Markers go on every
            // basic shape and path (SVG 2 11.6: markable elements), not on the curve elements.
            const detail::Markable markable = is_curve         ? detail::Markable::kNo
                                              : name == "path" ? detail::Markable::kPathData
                                                               : detail::Markable::kBasicShape;
            const detail::PathNode drawn = path_node(std::move(*shape), group->box, content, content_ctm,
                                                     viewport, content.aliased_shapes, true, markable);
            if (path_probe_) (*path_probe_)(node, drawn);
            // Fill, stroke and markers in paint-order (SVG 2 13.10).
            for (const detail::PaintLayer layer : drawn.paint_order)
              CURVESCAN_PROPAGATE(draw_path(drawn, layer, content_ctm, viewport, depth));
            return Status::ok();
          }
          if (name == "g" || name == "a")
            return render_children(node, content, content_ctm, viewport, depth + 1);  // 17.1
          if (name == "svg") return render_nested_svg(node, node, content, content_ctm, viewport, depth, {});
          if (name == "switch") return render_switch(node, content, content_ctm, viewport, depth);
          if (name == "image") return render_image(node, content, content_ctm, viewport);
          return name == "text" ? render_text(node, content, content_ctm, viewport, depth)
                                : render_use(node, content, content_ctm, viewport, depth);
        });
  }

  // Grows `box` (none yet: starts it) by the box of `child` mapped through `transform` (its four corners).
  static void include_transformed(std::optional<Rect>& box, const std::optional<Rect>& child,
                                  const Affine& transform) {
    if (!child) return;
    for (const Point corner : {Point{child->x0, child->y0}, Point{child->x1, child->y0},
                               Point{child->x0, child->y1}, Point{child->x1, child->y1}}) {
      const Point mapped = transform.apply(corner);
      if (!box) box = Rect::from_point(mapped);
      box->include(mapped);
    }
  }

  // The box of what painting `path` with `style` covers: its fill's box, and its stroke's outline
  // (stroke.h) when it has a stroke (export_size).
  std::optional<Rect> ink_bounds(const Path& path, const ComputedStyle& style) {
    std::optional<Rect> box = path.tight_bounds();
    if (style.stroke.kind == PaintSpec::Kind::kNone || !(style.stroke_width > 0.0)) return box;
    const Result<Path> outline = stroke_path(path, stroke_style_of(style), options_.tolerance);
    if (!outline) return box;
    const std::optional<Rect> stroke_box = outline->tight_bounds();
    if (!stroke_box) return box;
    if (!box) return stroke_box;
    box->include(Point{stroke_box->x0, stroke_box->y0});
    box->include(Point{stroke_box->x1, stroke_box->y1});
    return box;
  }

  // The Group node of `node` drawn with `style` (render_group.h): its transform, opacity, blend mode and
  // isolation, its clip path, mask and filters read (once per render: resolved_references.h), and its
  // object bounding box when they may refer to it. `root`: the root <svg>'s placement, whose transform
  // refers to the outer viewport and is followed by its viewBox mapping (SVG 2 8.5).
  // `shape`, for a shape element: receives its geometry, which is read after the transform and before
  // the box (the shape's box is its geometry's); nullopt, and no node, when it has none (not drawn).
  // Read in the order the drawing has always met them, so that warnings keep their order: the
  // transform, the geometry, the box, then the clip path, the mask and the filters.
  struct ShapeGeometry {
    std::optional<Path>& path;  // receives the geometry
    std::string_view name;      // the element's local name
    bool is_curve;              // one of curvescan's curve elements (document_index.h)
  };
  struct RootPlacement {
    Viewport outer;                   // the document's width and height
    std::optional<ViewBox> view_box;  // mapped into `outer` with the root's preserveAspectRatio
  };
  std::optional<detail::GroupNode> group_node(
      const pugi::xml_node& node, const ComputedStyle& style, const Viewport& viewport, int depth,
      const ShapeGeometry* shape = nullptr, const RootPlacement* root = nullptr,
      std::optional<std::pair<double, double>> instance_size = std::nullopt) {
    std::optional<detail::GroupNode> made(std::in_place);  // the one object returned, built in place
    detail::GroupNode& group = *made;
    if (root) {
      group.transform = element_transform(node, root->outer, style.font_size);
      if (const std::optional<ViewBox>& box = root->view_box) {
        group.transform = group.transform * view_box_transform(*box, aspect_of(node), 0.0, 0.0,
                                                               root->outer.width, root->outer.height);
      }
    } else {
      group.transform = element_transform(node, viewport, style.font_size);
    }
    if (shape) {
      shape->path = shape_path(node, shape->name, shape->is_curve, style, viewport);
      if (!shape->path) {
        made.reset();
        return made;
      }
    }
    group.opacity = style.opacity;
    group.blend_mode = style.painting.blend_mode;
    group.isolate = style.painting.isolate;
    group.current_color = style.color;
    const bool masked_or_filtered = !style.painting.mask_id.empty() || !style.painting.filters.empty();
    // A <symbol> or <svg> instanced by a <use> that sizes it (`instance_size`) is measured in the viewport
    // that size gives it, which the element alone does not know.
    const auto measured_box = [&] {
      return instance_size ? nested_viewport_bbox(node, style, viewport, depth, instance_size)
                           : object_bbox(node, style, viewport, depth);
    };
    // The clip path is read once, where it is first needed: before the box when its units alone decide
    // whether the box is measured, after the box otherwise (so that warnings keep their order).
    const bool clipped = !style.clip_path_id.empty();
    std::optional<const detail::ResolvedClipPath*> clip_path;
    const auto resolved_clip = [&] {
      if (!clip_path) clip_path = resolved_clip_path(style.clip_path_id, viewport);
      return *clip_path;
    };
    if (shape) {
      // A shape's box is a pass over its curves' extrema, taken only for what may refer to it: a clip
      // path (the clipPath's own clip-path in objectBoundingBox units too), a mask or a filter; a paint
      // server measures it itself (path_node).
      if (clipped || masked_or_filtered) group.box = shape->path->tight_bounds();
    } else if (masked_or_filtered) {
      group.box = measured_box();  // maskUnits default to objectBoundingBox
    } else if (clipped && clip_chain_uses_box(resolved_clip(), viewport)) {
      group.box = measured_box();
    }
    if (clipped) group.clip_path = detail::referenced(resolved_clip(), style.clip_path_id);
    if (!style.painting.mask_id.empty())
      group.mask =
          detail::referenced(resolved_mask(style.painting.mask_id, viewport), style.painting.mask_id);
    for (const detail::filter::FilterFunction& function : style.painting.filters) {
      // The functions' lengths in user units (em and ex are the element's font size); each <filter> of the
      // list read once per render and viewport.
      detail::GroupFilter entry{function.resolved_for(style.font_size), nullptr};
      if (function.kind == detail::filter::FilterFunction::Kind::kUrl) {
        entry.filter = references_.filter(
            function.url_id, resolve_context(viewport), style_sheets_,
            [&](const pugi::xml_node& referenced) { return referenced_style(referenced, viewport); },
            diagnostics_);
      }
      group.filters.push_back(std::move(entry));
    }
    if (group_probe_) (*group_probe_)(node, group);
    return made;
  }

  // Whether applying clip path `clip` needs the element's box: it, or a clipPath its own clip-path leads to
  // (push_clip_path applies that chain in the same element's box), is in objectBoundingBox units. The
  // search ends at a clipPath met before, where push_clip_path ignores the reference that closes the loop.
  bool clip_chain_uses_box(const detail::ResolvedClipPath* clip, const Viewport& viewport) {
    std::vector<pugi::xml_node> seen;
    while (clip && std::find(seen.begin(), seen.end(), clip->element) == seen.end()) {
      if (clip->bounding_box_units) return true;
      seen.push_back(clip->element);
      const std::string& next = clip->style.clip_path_id;
      clip = next.empty() ? nullptr : resolved_clip_path(next, viewport);
    }
    return false;
  }

  // What a group's content inherits from the element: its style, with the opacity the group applied --
  // as a layer, or `folded` into each shape's alpha when layers nest too deep (draw_group). Without an
  // opacity that is the style itself; otherwise the adjusted copy is made in `adjusted`.
  static const ComputedStyle& content_style(const ComputedStyle& style, double folded,
                                            std::optional<ComputedStyle>& adjusted) {
    if (style.opacity == 1.0 && folded == 1.0) return style;
    ComputedStyle& content = adjusted.emplace(style);
    content.group_opacity *= folded;
    content.opacity = 1.0;
    return content;
  }

  // Draws a group's content, given the opacity folded into its shapes (1 when the group has a layer)
  // and the transform to the device of its user space.
  using DrawContent = std::function<Status(double folded_opacity, const Affine& ctm)>;

  // A group's effects around `draw`, its content drawn in `parent_ctm` * its transform. The filter comes
  // first, then clipping, masking and opacity (Filter Effects 1, section 11; CSS Masking 1, section 1): the
  // filtered result is what they apply to. Clip path, then mask, then opacity as a layer are pushed;
  // undone in reverse order, so the group is composited with its opacity through the clip and the mask
  // (SVG 1.1 14.3.5, 14.4 and 14.5).
  Status draw_group(const detail::GroupNode& group, const Affine& parent_ctm, const Viewport& viewport,
                    int depth, const DrawContent& draw) {
    const Affine ctm = parent_ctm * group.transform;
    const std::optional<int> clips =
        group.clip_path.present()
            ? push_clip_path(group.clip_path.resolved, group.clip_path.id(), ctm, group.box, viewport, depth)
            : 0;
    if (budget_error_) return *budget_error_;  // a render limit (limits.h): the whole render fails
    if (!clips) return Status::ok();           // the clip hides the element entirely
    // mask (mask.h): its coverage joins the clip, and the element is drawn as a group through both.
    int masks = 0;
    if (group.mask.present()) {
      const std::optional<int> pushed =
          push_mask(group.mask.resolved, group.mask.id(), ctm, group.box, viewport, depth);
      if (budget_error_) return *budget_error_;
      if (!pushed) {  // the mask hides the element entirely
        for (int i = 0; i < *clips; ++i) CURVESCAN_PROPAGATE(canvas_->pop_clip());
        return Status::ok();
      }
      masks = *pushed;
    }
    double folded = 1.0;
    bool layered = false;
    // A group is drawn into its own layer for opacity, a mask, a blend mode (blended onto what lies
    // under it when the layer is composited) or isolation (its children blend with the group only).
    if (group.opacity < 1.0 || masks > 0 || group.blend_mode != BlendMode::kNormal || group.isolate) {
      CURVESCAN_PROPAGATE(canvas_->reserve_layer());
      const Status pushed = canvas_->push_layer();
      layered = pushed.is_ok();
      if (!layered) {
        // Deeper than kMaxLayerDepth: fold the opacity into each shape's alpha instead (exact for
        // content that does not overlap itself).
        diagnostics_.warnings.push_back("group opacity nested too deep (" + pushed.error().message +
                                        "); applied to each shape separately");
        folded = group.opacity;
      }
    }
    const auto content = [&](const Affine& content_ctm) { return draw(folded, content_ctm); };
    const Status status =
        group.filters.empty() ? content(ctm) : render_filtered(group, ctm, viewport, depth, content);
    if (layered) CURVESCAN_PROPAGATE(canvas_->pop_layer(group.opacity, group.blend_mode));
    for (int i = 0; i < masks + *clips; ++i) CURVESCAN_PROPAGATE(canvas_->pop_clip());
    return status;
  }

  // filter (filter/filter_graph.h): the element drawn into a filter image (filter/filter_surface.h), each
  // filter of the list run in turn, and the result drawn in its place. Per Filter Effects 1: a reference to
  // nothing or to an element that is not a <filter> disables the element's rendering, and so does a filter
  // region without area (objectBoundingBox units on an element without a box among them).
  Status render_filtered(const detail::GroupNode& group, const Affine& ctm, const Viewport& viewport,
                         int depth, const std::function<Status(const Affine&)>& draw) {
    using detail::filter::FilterFunction;
    struct Step {
      const FilterFunction* function;
      std::optional<detail::filter::FilterDefinition> definition;  // url(#id)
      Rect region;
    };
    const std::optional<Rect>& bbox = group.box;
    const bool has_box = bbox && bbox->width() > 0.0 && bbox->height() > 0.0;
    // A url() to nothing, or to an element that is not a <filter>: alone in the list (or with only such
    // others), it disables the element's rendering; next to usable filters it is skipped, as Chrome and
    // resvg do for filter lists.
    const auto unusable = [](const detail::GroupFilter& entry) {
      return entry.function.kind == FilterFunction::Kind::kUrl && entry.filter == nullptr;
    };
    const bool any_usable = std::any_of(group.filters.begin(), group.filters.end(),
                                        [&](const detail::GroupFilter& entry) { return !unusable(entry); });
    // An element drawn by an <feImage> of a filter that is running, and filtered by that same filter: the
    // reference cycle is broken there, and the element is drawn without its filters (as Chrome's cycle
    // breaking and resvg draw it).
    const bool cycle =
        std::any_of(group.filters.begin(), group.filters.end(), [&](const detail::GroupFilter& entry) {
          return entry.function.kind == FilterFunction::Kind::kUrl &&
                 std::find(running_filters_.begin(), running_filters_.end(), entry.function.url_id) !=
                     running_filters_.end();
        });
    if (cycle) {
      diagnostics_.warnings.push_back(
          "a filter draws, through <feImage>, an element it filters; that element is drawn there without "
          "its filters");
      return draw(ctm);
    }
    std::vector<Step> steps;
    std::optional<Rect> all;
    for (const detail::GroupFilter& entry : group.filters) {
      const FilterFunction& function = entry.function;
      Step step{&function, std::nullopt, {}};
      if (unusable(entry)) {
        diagnostics_.warnings.push_back("filter refers to '#" + function.url_id + "', which is not a <filter>; " +
                                        (any_usable ? "skipped" : "the element is not rendered"));
        if (!any_usable) return Status::ok();
        continue;
      }
      if (function.kind == FilterFunction::Kind::kUrl) {
        step.definition = detail::filter::place_filter(*entry.filter, bbox);
        if (!step.definition) return Status::ok();
        step.region = step.definition->region;
      } else {
        // A filter function's region: the bounding box grown by 10 % on each side (the default filter
        // region), and by what a blur or a shadow reaches beyond it (3σ, and the offset).
        if (!has_box) return Status::ok();
        const double reach = 3.0 * function.amount;
        step.region = Rect{bbox->x0 - 0.1 * bbox->width() - reach + std::min(0.0, function.dx),
                           bbox->y0 - 0.1 * bbox->height() - reach + std::min(0.0, function.dy),
                           bbox->x1 + 0.1 * bbox->width() + reach + std::max(0.0, function.dx),
                           bbox->y1 + 0.1 * bbox->height() + reach + std::max(0.0, function.dy)};
      }
      if (!all) all = step.region;
      all->include(Point{step.region.x0, step.region.y0});
      all->include(Point{step.region.x1, step.region.y1});
      steps.push_back(std::move(step));
    }
    if (!all) return Status::ok();
    // Only what can reach the canvas is computed (as resvg and browsers do): with an axis-aligned transform,
    // the region is cut to the canvas grown by how far the primitives carry content (primitive_reach);
    // when a primitive's reach is not known, the whole region is kept.
    if (ctm.b == 0.0 && ctm.c == 0.0 && ctm.a != 0.0 && ctm.d != 0.0) {
      std::optional<std::pair<double, double>> reach = std::pair{0.0, 0.0};
      for (const Step& step : steps) {
        if (!reach) break;
        if (!step.definition) {
          const double spread = step.function->kind == FilterFunction::Kind::kBlur ||
                                        step.function->kind == FilterFunction::Kind::kDropShadow
                                    ? 3.0 * step.function->amount + 1.0
                                    : 0.0;
          reach->first += spread + std::fabs(step.function->dx);
          reach->second += spread + std::fabs(step.function->dy);
          continue;
        }
        detail::filter::FilterSpace units;
        units.bounding_box_units = step.definition->bounding_box_primitives;
        units.bbox = bbox.value_or(Rect{});
        for (const detail::filter::ResolvedPrimitive& primitive : step.definition->filter->primitives) {
          if (!reach) break;
          const std::optional<std::pair<double, double>> own =
              detail::filter::primitive_reach(primitive, units);
          if (!own) {
            reach.reset();
          } else {
            reach->first += own->first;
            reach->second += own->second;
          }
        }
      }
      if (reach) {
        const double margin_x = reach->first * std::fabs(ctm.a) + 2.0,
                     margin_y = reach->second * std::fabs(ctm.d) + 2.0;
        const double ax = (-margin_x - ctm.e) / ctm.a, bx = (canvas_->width() + margin_x - ctm.e) / ctm.a;
        const double ay = (-margin_y - ctm.f) / ctm.d, by = (canvas_->height() + margin_y - ctm.f) / ctm.d;
        const Rect visible{std::max(all->x0, std::min(ax, bx)), std::max(all->y0, std::min(ay, by)),
                           std::min(all->x1, std::max(ax, bx)), std::min(all->y1, std::max(ay, by))};
        if (!(visible.width() > 0.0) || !(visible.height() > 0.0))
          return Status::ok();  // nothing reaches the canvas
        all = visible;
      }
    }
    // Pixels the filter may use: the canvas limit, and the memory budget left for the offscreen canvas (4
    // bytes a pixel) and the primitives' float images (16 bytes each; a result, its conversion to the other
    // colour space, and the inputs of the primitive in progress).
    // Per pixel: the offscreen canvas (4 bytes), the source and the chain's current image (16 each), and the
    // most images one filter of the list holds at once (16 each, filter_graph.h; 4 for a function), plus
    // the blur's two single-channel planes (8).
    std::int64_t peak_images = 4;
    for (const Step& step : steps) {
      if (step.definition)
        peak_images = std::max<std::int64_t>(peak_images, step.definition->filter->peak_images);
    }
    const std::int64_t bytes_per_pixel = 4 + 16 * (2 + peak_images) + 8;
    const std::int64_t memory_left = this->memory_left();
    std::int64_t fitting = std::max<std::int64_t>(0, memory_left / bytes_per_pixel);
    // A float image of kHugeBlockBytes or more is rounded up to whole huge pages (zeroed_memory.h):
    // up to zeroed_block_rounding_bytes() more for each image and plane held at once. Either the images stay
    // below that size, or the rounding is budgeted too.
    const auto huge = static_cast<std::int64_t>(kHugeBlockBytes);
    if (16 * fitting >= huge) {
      const std::int64_t rounding =
          (2 + peak_images + 2) * static_cast<std::int64_t>(curvescan::zeroed_block_rounding_bytes());
      fitting = std::max((memory_left - rounding) / bytes_per_pixel, (huge - 1) / 16);
    }
    // And the work: the pixels times the primitives of the whole list (kFilterWorkPixels).
    std::int64_t primitives = 0;
    for (const Step& step : steps) {
      if (!step.definition) {
        ++primitives;
        continue;
      }
      primitives += step.definition->filter->passes;
    }
    const std::int64_t max_pixels =
        std::min({static_cast<std::int64_t>(options_.limits.max_pixels), fitting,
                  detail::filter::kFilterWorkPixels / std::max<std::int64_t>(1, primitives)});
    std::string warning;
    const std::optional<detail::filter::FilterSurface> surface =
        max_pixels >= 1 ? detail::filter::plan_filter_surface(ctm, *all, max_pixels, warning) : std::nullopt;
    if (!warning.empty()) diagnostics_.warnings.push_back(warning);
    if (!surface) {
      if (max_pixels < 1)
        diagnostics_.warnings.push_back("a filter was not applied: no memory left under the limit");
      return Status::ok();
    }
    // The element itself, into the filter image.
    Canvas offscreen{Image(surface->width, surface->height)};
    offscreen.set_limits(canvas_->limits());
    offscreen.set_held_memory_bytes(canvas_->memory_bytes());
    Canvas* const target = canvas_;
    canvas_ = &offscreen;
    const Status drawn = draw(surface->user_to_pixels);
    canvas_ = target;
    CURVESCAN_PROPAGATE(drawn);
    detail::filter::FilterImage image = detail::filter::to_filter_image(offscreen.image());
    detail::filter::FilterEnvironment environment;
    environment.draw_fe_image = [&](const detail::filter::ImageParams& fe_image,
                                    const detail::filter::FilterSpace& space, const Rect& user_subregion,
                                    detail::filter::PixelRect subregion, detail::filter::FilterImage& out) {
      draw_fe_image(fe_image, space, user_subregion, subregion, viewport, depth, out);
    };
    // The last filter's result may stay in linearRGB: converted to sRGB as it is quantized (to_image).
    detail::filter::ColorSpace result_space = detail::filter::ColorSpace::kSrgb;
    const std::size_t running = running_filters_.size();
    for (const detail::GroupFilter& entry : group.filters)
      if (entry.function.kind == FilterFunction::Kind::kUrl)
        running_filters_.push_back(entry.function.url_id);
    // What each step's result must hold: the last, the pixels that land on the canvas; a function's input,
    // what the function reads to make those (a <filter> step computes only what the canvas needs when it
    // is the last, so the steps before it compute everything).
    detail::filter::FilterSpace function_space = surface->space;
    function_space.bbox = bbox.value_or(Rect{});
    std::vector<detail::filter::PixelRect> needed(steps.size());
    needed.back() = detail::filter::pixels_on_canvas(*surface, canvas_->width(), canvas_->height());
    for (std::size_t i = steps.size() - 1; i > 0; --i) {
      needed[i - 1] =
          steps[i].definition
              ? detail::filter::PixelRect{-(1 << 30), -(1 << 30), 1 << 30, 1 << 30}
              : detail::filter::function_input_needed(*steps[i].function, function_space, needed[i]);
    }
    for (const Step& step : steps) {
      detail::filter::FilterSpace space = surface->space;
      space.bbox = bbox.value_or(Rect{});
      const detail::filter::PixelRect region =
          detail::filter::pixel_rect(space, step.region).intersect(image.bounds());
      if (!step.definition) {
        image = detail::filter::run_filter_function(*step.function, space, region, image, group.current_color,
                                                    needed[static_cast<std::size_t>(&step - steps.data())]);
        continue;
      }
      space.bounding_box_units = step.definition->bounding_box_primitives;
      detail::filter::FilterSources sources;
      sources.source_graphic = &image;
      sources.current_color = group.current_color;
      // The last filter of the list computes only what lands on the canvas.
      const bool last = &step == &steps.back();
      if (last)
        sources.needed = detail::filter::pixels_on_canvas(*surface, canvas_->width(), canvas_->height());
      image = detail::filter::run_filter(*step.definition, space, region, sources, environment, diagnostics_,
                                         last ? &result_space : nullptr);
    }
    running_filters_.resize(running);
    if (budget_error_) return *budget_error_;
    // Placed by a whole-pixel translation (no rotation, skew or reduced resolution), every device pixel
    // centre is an image pixel centre: nearest sampling gives the same pixels as bilinear, faster. The
    // translation is whole by construction, up to the rounding of (e - floor(e)) sums: snapped.
    Affine placed = surface->pixels_to_device;
    const bool whole_pixels = placed.a == 1.0 && placed.b == 0.0 && placed.c == 0.0 && placed.d == 1.0 &&
                              std::fabs(placed.e - std::round(placed.e)) < 1e-6 &&
                              std::fabs(placed.f - std::round(placed.f)) < 1e-6;
    if (whole_pixels) placed = Affine::translate(std::round(placed.e), std::round(placed.f));
    const Paint paint =
        image_pattern_paint(detail::filter::to_image(image, result_space), Affine::identity(),
                            PatternExtend::kNone,
                            whole_pixels ? PatternFilter::kNearest : PatternFilter::kBilinear, 1.0);
    const std::optional<Path> rect =
        detail::rect_path(0.0, 0.0, surface->width, surface->height, std::nullopt, std::nullopt);
    if (!rect || paint.pattern == nullptr) return Status::ok();
    const Status status = canvas_->fill(*rect, paint, FillRule::kNonZero, placed,
                                        FillOptions{options_.tolerance, options_.antialias});
    if (!status && status.error().kind == ErrorKind::kLimitExceeded) return status;
    if (!status)
      diagnostics_.warnings.push_back("a filtered element was not drawn: " + status.error().message);
    return Status::ok();
  }

  // feImage (Filter Effects 1, section 9.14): a reference to an element draws that element (as <use>
  // would, in the filtered element's user space moved to the subregion's corner); an image reference (PNG,
  // JPEG, or an SVG document drawn as <image> draws one) draws the image into the primitive's subregion with
  // preserveAspectRatio. Either is clipped to the subregion. What it refers to was read with its filter
  // (detail::filter::ImageParams, resolved once per render); the loops that close while drawing are cut
  // here.
  void draw_fe_image(const detail::filter::ImageParams& fe_image, const detail::filter::FilterSpace& space,
                     const Rect& user_subregion, detail::filter::PixelRect subregion,
                     const Viewport& viewport, int depth, detail::filter::FilterImage& out) {
    const std::string_view reference = fe_image.reference;
    // Nothing to draw: no reference, or one to nothing (said when the filter was read).
    if (reference.empty() || (reference.front() == '#' && !fe_image.target)) return;
    std::optional<Canvas> offscreen;
    if (canvas_->memory_bytes() + image_memory_bytes(out.width, out.height) <=
        canvas_->limits().max_memory_bytes) {
      offscreen.emplace(Image(out.width, out.height));
      offscreen->set_limits(canvas_->limits());
      offscreen->set_held_memory_bytes(canvas_->memory_bytes());
    }
    if (!offscreen) {
      diagnostics_.warnings.push_back("<feImage> not drawn: beyond the memory limit");
      return;
    }
    const Affine to_pixels =
        Affine::translate(-space.scale_x * space.origin_x, -space.scale_y * space.origin_y) *
        Affine::scale(space.scale_x, space.scale_y);
    Canvas* const target = canvas_;
    canvas_ = &*offscreen;
    if (reference.front() == '#') {
      if (std::find(fe_image_stack_.begin(), fe_image_stack_.end(), fe_image.target) !=
          fe_image_stack_.end()) {
        diagnostics_.warnings.push_back("<feImage> of '" + std::string(reference) +
                                        "' refers to itself; not drawn");
      } else if (fe_image_stack_.size() >= kMaxNestedFeImages) {
        diagnostics_.warnings.push_back("<feImage> of '" + std::string(reference) + "' is inside " +
                                        std::to_string(kMaxNestedFeImages) +
                                        " other <feImage>s' content, deeper than curvescan draws; not drawn");
      } else {
        fe_image_stack_.push_back(fe_image.target);
        // Drawn as <use> would, with the subregion's x and y as the use's: its origin is the user-space
        // origin moved to the subregion's corner (Filter Effects 1, 9.14; Chrome and resvg place it so).
        const Affine at_subregion = to_pixels * Affine::translate(user_subregion.x0, user_subregion.y0);
        const Status status =
            render_element(fe_image.target, *fe_image.target_parent_style, at_subregion, viewport, depth + 1);
        if (!status && status.error().kind == ErrorKind::kLimitExceeded) budget_error_ = status.error();
        fe_image_stack_.pop_back();
      }
    } else {
      detail::ImageBytes source = load_image_within_budget(reference);
      const std::string shown = std::string(reference).substr(0, 40);
      const detail::ImageFormat format =
          source.refused.empty() ? detail::sniff_image_format(source.bytes) : detail::ImageFormat::kUnknown;
      Result<Image> decoded = Error{ErrorKind::kInvalidArgument, "not a PNG, JPEG, GIF, WebP or SVG image"};
      if (!source.refused.empty()) {
        decoded = Error{ErrorKind::kInvalidArgument, source.refused};
      } else if (detail::is_raster_format(format)) {
        decoded = decode_within_budget(source.bytes, format, static_cast<std::int64_t>(source.bytes.size()),
                                       "<feImage>", shown);
      }
      if (format == detail::ImageFormat::kSvg && source.refused.empty()) {
        // An SVG document, drawn as <image> draws one: its intrinsic size placed in the subregion with
        // preserveAspectRatio (Filter Effects 1, 9.14).
        NestedSvg nested;
        Status status = load_nested_svg(source.bytes, "<feImage>", shown, nested);
        if (status && nested.renderer) {
          const Affine placed =
              to_pixels * view_box_transform(ViewBox{0.0, 0.0, nested.width, nested.height}, fe_image.aspect,
                                             user_subregion.x0, user_subregion.y0, user_subregion.width(),
                                             user_subregion.height());
          status = draw_nested_svg(nested, placed);
        }
        if (!status && status.error().kind == ErrorKind::kLimitExceeded) budget_error_ = status.error();
        if (!status && status.error().kind != ErrorKind::kLimitExceeded)
          diagnostics_.warnings.push_back("<feImage> '" + shown + "' not drawn: " + status.error().message);
      } else if (!decoded) {
        diagnostics_.warnings.push_back("<feImage> '" + shown + "' not drawn: " + decoded.error().message);
      } else {
        const double w = decoded->width(), h = decoded->height();
        const Affine placed = to_pixels * view_box_transform(ViewBox{0.0, 0.0, w, h}, fe_image.aspect,
                                                             user_subregion.x0, user_subregion.y0,
                                                             user_subregion.width(), user_subregion.height());
        // image-rendering applies to <feImage> as to <image> (inherited along the filter's ancestors).
        const PatternFilter filter = fe_image.pixelated ? PatternFilter::kNearest : PatternFilter::kBilinear;
        const Paint paint = image_pattern_paint(std::move(decoded).value(), Affine::identity(),
                                                PatternExtend::kPad, filter, 1.0);
        const std::optional<Path> bounds = detail::rect_path(0.0, 0.0, w, h, std::nullopt, std::nullopt);
        if (bounds && paint.pattern) {
          const Status status = offscreen->fill(*bounds, paint, FillRule::kNonZero, placed,
                                                FillOptions{options_.tolerance, options_.antialias});
          if (!status && status.error().kind == ErrorKind::kLimitExceeded) budget_error_ = status.error();
        }
      }
    }
    canvas_ = target;
    const detail::filter::FilterImage drawn = detail::filter::to_filter_image(offscreen->image());
    const detail::filter::PixelRect r = subregion.intersect(out.bounds());
    for (int y = r.y0; y < r.y1; ++y) {
      std::copy(drawn.pixel(r.x0, y), drawn.pixel(r.x0, y) + 4 * r.width(), out.pixel(r.x0, y));
    }
  }

  // marker-start, marker-mid and marker-end (marker.h) placed on the vertices of `path` (of a `markable`
  // element with at least one of them) drawn with `style` under `ctm` (placed_marker.h). A reference that is
  // not a <marker> is ignored with a warning; a marker inside its own content (directly or through others) is
  // not placed there, nor any marker deeper than kMaxMarkerDepth: the node is made just before it is drawn,
  // inside the markers being drawn. Null when no marker is placed.
  std::unique_ptr<const detail::PathMarkers> placed_markers(const Path& path, detail::Markable markable,
                                                            const ComputedStyle& style, const Affine& ctm,
                                                            const Viewport& viewport) {
    detail::PathMarkers markers;
    const detail::PaintingProperties& painting = style.painting;
    if (static_cast<int>(marker_stack_.size()) >= detail::kMaxMarkerDepth) return nullptr;
    // Control points this close to a segment's end do not set the direction there, as for the stroke's
    // caps (stroker.cpp: tolerance / 64 in user units), so a marker lines up with the cap it sits on.
    const double coincident_length = stroke_user_tolerance(ctm, options_.tolerance) / 64.0;
    const std::vector<detail::MarkerVertex> vertices =
        detail::marker_vertices(path, markable == detail::Markable::kPathData, coincident_length);
    if (vertices.empty()) return nullptr;
    // A marker (read once per render: resolved_references.h) placed for this stroke width.
    struct Resolved {
      const detail::ResolvedMarker* marker;
      detail::MarkerSetup setup;
    };
    const detail::ResolveContext context{viewport.width, viewport.height, resolution()};
    const auto resolve = [&](const std::string& id) -> std::optional<Resolved> {
      if (id.empty()) return std::nullopt;
      const detail::ResolvedMarker* const marker = references_.marker(
          id, context, [&](const pugi::xml_node& node) { return referenced_style(node, viewport); },
          diagnostics_);
      if (!marker) {
        diagnostics_.warnings.push_back("marker refers to '#" + id + "', which is not a <marker>");
        return std::nullopt;
      }
      if (std::find(marker_stack_.begin(), marker_stack_.end(), marker->element) != marker_stack_.end()) {
        return std::nullopt;
      }
      const std::optional<detail::MarkerSetup> setup = detail::place_marker(*marker, style.stroke_width);
      if (!setup) return std::nullopt;
      // A clip without area (a stroke-width of 0 scales the marker to nothing) shows nothing.
      if (setup->clip && !(setup->clip->width() > 0.0 && setup->clip->height() > 0.0)) return std::nullopt;
      return Resolved{marker, *setup};
    };
    const std::optional<Resolved> start = resolve(painting.marker_start), mid = resolve(painting.marker_mid),
                                  end = resolve(painting.marker_end);
    const auto place = [&](const std::optional<Resolved>& marker, const detail::MarkerVertex& vertex,
                           bool is_start) {
      if (!marker) return;
      double angle = vertex.angle;
      if (marker->marker->fixed_angle)
        angle = *marker->marker->fixed_angle;
      else if (is_start && marker->marker->auto_start_reverse)
        angle += 180.0;
      markers.placed.push_back(
          {marker->marker, vertex.position, angle, marker->setup.content_to_frame, marker->setup.clip});
    };
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      const bool first = i == 0, last = i + 1 == vertices.size();
      if (first) place(start, vertices[i], true);
      if (!first && !last) place(mid, vertices[i], false);
      if (last) place(end, vertices[i], false);
    }
    if (markers.placed.empty()) return nullptr;
    // The marked element's box, for context-fill and -stroke: once per element, not once per marker (a
    // path of n vertices would cost n^2).
    markers.context = context_paint_of(style, {path.tight_bounds(), ctm});
    return std::make_unique<const detail::PathMarkers>(std::move(markers));
  }

  // Draws the markers of `node` under `ctm` (the path's user space to the device), reading nothing but
  // the node: each marker's content, from its element, in its vertex frame and clipped to its overflow
  // clip.
  Status draw_markers(const detail::PathNode& node, const Affine& ctm, const Viewport& viewport, int depth) {
    if (!node.markers) return Status::ok();
    for (const detail::PlacedMarker& placed : node.markers->placed) {
      const Affine frame = placed.frame_under(ctm);
      const FillOptions fill_options{options_.tolerance, options_.antialias};
      bool clipped = false;
      if (const std::optional<Rect>& clip = placed.clip) {
        const std::optional<Path> rect =
            detail::rect_path(clip->x0, clip->y0, clip->width(), clip->height(), std::nullopt, std::nullopt);
        if (!rect) continue;  // not placed without area (placed_markers); NaN is refused here too
        CURVESCAN_PROPAGATE(canvas_->reserve_clip(*rect, frame, fill_options));
        clipped = canvas_->push_clip(*rect, FillRule::kNonZero, frame, fill_options).is_ok();
        if (!clipped) continue;  // a frame that cannot be mapped draws nothing
      }
      marker_stack_.push_back(placed.marker->element);
      context_paint_.push_back(node.markers->context);  // context-fill and -stroke: the marked element's
      // A marker's content is a drawing of its own, not part of the marked element's <use> tree (SVG 2
      // 11.6.2: markers are rendered as if their content were instanced separately), so the <use>s that
      // led to the marked element are not its ancestors there: a <use> in the marker may show that element
      // again. The recursion that can make is cut by marker_stack_ (a marker is not placed inside itself)
      // and kMaxMarkerDepth, as browsers cut it; <use> nesting restarts under each marker level.
      std::vector<pugi::xml_node> outer_uses = std::exchange(use_stack_, {});
      const Status status = render_children(placed.marker->element, placed.marker->style,
                                            frame * placed.content_to_frame, viewport, depth + 1);
      use_stack_ = std::move(outer_uses);
      context_paint_.pop_back();
      marker_stack_.pop_back();
      if (clipped) CURVESCAN_PROPAGATE(canvas_->pop_clip());
      CURVESCAN_PROPAGATE(status);
    }
    return Status::ok();
  }

  // What the render's memory budget has left (limits.h): the limit less what the canvas holds, or the whole
  // limit before there is a canvas (while the document's size is measured).
  std::int64_t memory_left() const {
    return canvas_ != nullptr ? canvas_->limits().max_memory_bytes - canvas_->memory_bytes()
                              : options_.limits.render.max_memory_bytes;
  }

  // The bytes of an image file (<image>, <feImage>), inflated when gzip-compressed, and its pixels, within
  // what the render's memory budget has left (image_loading.h).
  detail::ImageBytes load_image_within_budget(std::string_view href) const {
    return detail::load_image_bytes(href, options_.resource_directory, memory_left());
  }
  // An animated GIF or WebP draws its first frame, as SVG 2 allows a still image ("The image element"),
  // with a warning for `element` ("<image>", "<feImage>") `shown`.
  Result<Image> decode_within_budget(const std::vector<std::uint8_t>& bytes, detail::ImageFormat format,
                                     std::int64_t held, const std::string& element,
                                     const std::string& shown) {
    bool animated = false;
    Result<Image> decoded = detail::decode_image_within_budget(bytes, format, memory_left(), held,
                                                               options_.limits.max_pixels, &animated);
    if (decoded && animated) {
      diagnostics_.warnings.push_back(element + " '" + shown +
                                      "': animation is not supported, first frame drawn");
    }
    return decoded;
  }

  // An SVG document an <image> or <feImage> draws: its tree, its <style> sheets and the renderer over them,
  // which must outlive the renderer (pugi documents do not move: the caller keeps this in place).
  struct NestedSvg {
    detail::SvgTree tree;
    std::unique_ptr<DocumentRenderer> renderer;  // a pointer: the class is incomplete here
    double width = 0.0, height = 0.0;           // the intrinsic size
  };

  // The renderer of a document read into `nested.tree`, one level deeper; the warnings of its reading
  // join this render's.
  void start_nested_renderer(NestedSvg& nested) {
    diagnostics_.warnings.insert(diagnostics_.warnings.end(), nested.tree.warnings.begin(),
                                 nested.tree.warnings.end());
    nested.renderer = std::make_unique<DocumentRenderer>(
        nested.tree.xml.document_element(), nested_options_,
        nested.tree.style_sheets.empty() ? nullptr : &nested.tree.style_sheets, diagnostics_,
        image_depth_ + 1);
  }

  // Parses `bytes` into `nested` for the element `element` ("<image>", "<feImage>"), as every SVG document
  // is read (svg_tree.h: its encoding converted, its entities expanded, its style sheets read). A document
  // nested too deep, one that is not a well-formed SVG document, and one without an intrinsic size are
  // warnings and leave no renderer; a tree beyond the memory left is an error.
  Status load_nested_svg(const std::vector<std::uint8_t>& bytes, const std::string& element,
                         const std::string& shown, NestedSvg& nested) {
    if (image_depth_ >= kMaxImageDepth) {
      diagnostics_.warnings.push_back(element + " SVG documents nested more than " +
                                      std::to_string(kMaxImageDepth) + " deep; the innermost is not drawn");
      return Status::ok();
    }
    // The nested tree counts against what the render has left.
    const Status parsed =
        detail::parse_svg_tree(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
                               memory_left(), nested.tree);
    if (!parsed && parsed.error().kind == ErrorKind::kLimitExceeded) {
      return limit_error("the SVG document of " + element + " '" + shown +
                         "' needs more than the memory left (raise --max-memory)");
    }
    if (!parsed) {
      diagnostics_.warnings.push_back(element + " '" + shown +
                                      "' is not a well-formed SVG document: " + parsed.error().message);
      return Status::ok();
    }
    start_nested_renderer(nested);
    // The nested document's elements have no position in this document's text: its warnings carry none.
    const detail::SourcePositions* outer_positions = std::exchange(diagnostics_.positions, nullptr);
    const Result<Size> size = nested.renderer->intrinsic_size();
    diagnostics_.positions = outer_positions;
    if (!size) {
      nested.renderer.reset();
      return Status::ok();
    }
    nested.width = size->width;
    nested.height = size->height;
    return Status::ok();
  }

  // Draws a loaded nested SVG document on the current canvas under `placed` (its intrinsic size box ->
  // device pixels).
  Status draw_nested_svg(NestedSvg& nested, const Affine& placed) {
    const detail::SourcePositions* outer_positions = std::exchange(diagnostics_.positions, nullptr);
    const Status status = nested.renderer->draw(*canvas_, placed);
    diagnostics_.positions = outer_positions;
    return status;
  }

  // <image> (SVG 1.1 5.7, SVG 2 "The image element"): a PNG, JPEG, GIF or WebP, or an SVG document drawn
  // as a sub-document, from a data: URI or (when RenderOptions::resource_directory allows) a file beside the
  // document (image_source.h). The image's own size (an SVG's intrinsic size) is its viewBox, mapped onto (x,
  // y, width, height) with preserveAspectRatio; a missing or auto width or height takes the image's size, or
  // keeps its aspect ratio when the other is given (SVG 2). What is not loaded is a warning.
  Status render_image(const pugi::xml_node& node, const ComputedStyle& style, const Affine& ctm,
                      const Viewport& viewport) {
    pugi::xml_attribute href = node.attribute("href");
    if (!href) href = node.attribute("xlink:href");
    if (!href || std::string_view(href.value()).empty() || !style.visible) return Status::ok();
    detail::ImageBytes source = load_image_within_budget(href.value());
    const std::string shown = std::string(href.value()).substr(0, 40);
    if (!source.refused.empty()) {
      diagnostics_.warnings.push_back("<image> '" + shown + "' not loaded: " + source.refused);
      return Status::ok();
    }
    const detail::ImageFormat format = detail::sniff_image_format(source.bytes);
    if (format == detail::ImageFormat::kUnknown) {
      diagnostics_.warnings.push_back("<image> '" + shown + "' is not a PNG, JPEG, GIF, WebP or SVG image");
      return Status::ok();
    }
    // The image's own size: its pixels, or the SVG's intrinsic size.
    std::optional<Image> raster;
    NestedSvg sub;
    double own_width = 0.0, own_height = 0.0;
    if (detail::is_raster_format(format)) {
      Result<Image> decoded = decode_within_budget(
          source.bytes, format, static_cast<std::int64_t>(source.bytes.size()), "<image>", shown);
      if (!decoded) {
        diagnostics_.warnings.push_back("<image> '" + shown + "' not drawn: " + decoded.error().message);
        return Status::ok();
      }
      raster = std::move(decoded).value();
      own_width = raster->width();
      own_height = raster->height();
    } else {
      CURVESCAN_PROPAGATE(load_nested_svg(source.bytes, "<image>", shown, sub));
      if (!sub.renderer) return Status::ok();
      own_width = sub.width;
      own_height = sub.height;
    }
    // x, y, width, height are geometry properties (SVG 2 10.2; geometry_properties.h).
    const double x = geometry(node, "x", horizontal(viewport), style).value_or(0.0);
    const double y = geometry(node, "y", vertical(viewport), style).value_or(0.0);
    std::optional<double> width = geometry(node, "width", horizontal(viewport), style);
    std::optional<double> height = geometry(node, "height", vertical(viewport), style);
    if (!width && !height) {
      width = own_width;
      height = own_height;
    } else if (!width) {
      width = *height * own_width / own_height;
    } else if (!height) {
      height = *width * own_height / own_width;
    }
    if (!(*width > 0.0) || !(*height > 0.0)) return Status::ok();  // zero disables rendering
    const PreserveAspectRatio aspect = aspect_of(node);
    const Affine placed =
        ctm * view_box_transform(ViewBox{0.0, 0.0, own_width, own_height}, aspect, x, y, *width, *height);
    // The viewport clips what slice (or an SVG's overflowing content) puts outside it.
    const FillOptions fill_options{options_.tolerance, options_.antialias};
    const std::optional<Path> viewport_rect =
        detail::rect_path(x, y, *width, *height, std::nullopt, std::nullopt);
    const bool clip = viewport_rect && (aspect.slice || sub.renderer != nullptr);
    if (clip) {
      CURVESCAN_PROPAGATE(canvas_->reserve_clip(*viewport_rect, ctm, fill_options));
      if (!canvas_->push_clip(*viewport_rect, FillRule::kNonZero, ctm, fill_options)) return Status::ok();
    }
    Status status = Status::ok();
    if (raster) {
      // image-rendering (SVG 1.1 15.3, computed_style.h): optimizeSpeed, pixelated and crisp-edges keep
      // the pixels sharp.
      const PatternFilter filter =
          style.pixelated_images ? PatternFilter::kNearest : PatternFilter::kBilinear;
      // The decoded pixels stay counted against the memory budget while they are drawn.
      const std::int64_t pixel_bytes = image_memory_bytes(raster->width(), raster->height());
      const Paint paint = image_pattern_paint(std::move(*raster), Affine::identity(), PatternExtend::kPad,
                                              filter, style.group_opacity);
      const std::optional<Path> bounds =
          detail::rect_path(0.0, 0.0, own_width, own_height, std::nullopt, std::nullopt);
      if (bounds && paint.pattern) {
        const std::int64_t held = canvas_->held_memory_bytes();
        canvas_->set_held_memory_bytes(held + pixel_bytes);
        status = canvas_->fill(*bounds, paint, FillRule::kNonZero, placed, fill_options);
        canvas_->set_held_memory_bytes(held);
        if (!status && status.error().kind != ErrorKind::kLimitExceeded) {
          diagnostics_.warnings.push_back("an image was not drawn: " + status.error().message);
          status = Status::ok();
        }
      }
    } else {
      status = draw_nested_svg(sub, placed);
    }
    if (clip) CURVESCAN_PROPAGATE(canvas_->pop_clip());
    return status;
  }

  // <switch> (SVG 1.1 5.8.2): the first direct child that is an SVG graphics element (or a curvescan
  // curve) and whose conditions hold is rendered, the others are not. Elements outside SVG, comments
  // and non-rendering elements are not candidates. A chosen child with display="none" renders nothing,
  // and the rest stay skipped.
  Status render_switch(const pugi::xml_node& node, const ComputedStyle& style, const Affine& ctm,
                       const Viewport& viewport, int depth) {
    for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
      if (child.type() != pugi::node_element) continue;
      const detail::ElementFacts& facts = index_.facts(child);
      if (!detail::is_switch_candidate(facts.role) || !facts.conditions_hold) continue;
      return render_element(child, style, ctm, viewport, depth + 1);
    }
    return Status::ok();
  }

  // The computed style of a referenced element (a <mask>, <pattern>, <marker>): its own cascade from the
  // root through its ancestors, not the referencing element's (SVG 1.1 6.7: properties inherit along the
  // document tree).
  ComputedStyle referenced_style(const pugi::xml_node& node, const Viewport& viewport) {
    std::vector<pugi::xml_node> chain;
    for (pugi::xml_node scope = node; scope && scope != root_.parent(); scope = scope.parent())
      chain.push_back(scope);
    ComputedStyle style;
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) style = computed_style(*it, style, viewport);
    return style;
  }

  // The object bounding box (SVG 1.1 7.11) of `node` in its own user space (inside its transform): the
  // union of its shapes' geometry, strokes excluded, each child's box mapped by the child's transform
  // (the box of the mapped corners). nullopt when it has no geometry.
  std::optional<Rect> object_bbox(const pugi::xml_node& node, const ComputedStyle& style,
                                  const Viewport& viewport, int depth) {
    if (depth > options_.limits.max_depth) return std::nullopt;
    const bool is_curve = index_.facts(node).role == detail::ElementRole::kCurve;
    const std::string_view name = local_name(node);
    if (is_curve || is_basic_shape(name)) {
      const std::optional<Path> path = shape_path(node, name, is_curve, style, viewport);
      if (!path) return std::nullopt;
      return measuring_ink_ ? ink_bounds(*path, style) : path->tight_bounds();
    }
    std::optional<Rect> box;
    const auto include = [&](const std::optional<Rect>& child, const Affine& transform) {
      include_transformed(box, child, transform);
    };
    if (name == "text") {
      for (const detail::TextPiece& piece : text_pieces(node, style, viewport, depth)) {
        // The glyph cells (SVG 2 8.10) for objectBoundingBox; the ink for what an export draws.
        include(measuring_ink_ ? ink_bounds(piece.path, piece.style) : piece.object_box, Affine::identity());
      }
      return box;
    }
    if (name == "use") {
      pugi::xml_attribute href = node.attribute("href");
      if (!href) href = node.attribute("xlink:href");
      const std::string_view reference = href.value();
      const auto target =
          reference.size() > 1 ? index_.ids().find(std::string(reference.substr(1))) : index_.ids().end();
      if (target == index_.ids().end() ||
          std::find(use_stack_.begin(), use_stack_.end(), target->second) != use_stack_.end())
        return std::nullopt;
      use_stack_.push_back(target->second);
      const ComputedStyle target_style = computed_style(target->second, style, viewport);
      const std::string_view target_name = local_name(target->second);
      const std::optional<Rect> target_box =
          target_name == "symbol" || target_name == "svg"
              ? nested_viewport_bbox(target->second, target_style, viewport, depth + 1,
                                     use_size_override(node, style, target->second, target_style, viewport))
              : object_bbox(target->second, target_style, viewport, depth + 1);
      include(target_box, Affine::translate(geometry(node, "x", horizontal(viewport), style).value_or(0.0),
                                            geometry(node, "y", vertical(viewport), style).value_or(0.0)) *
                              element_transform(target->second, viewport, target_style.font_size));
      use_stack_.pop_back();
      return box;
    }
    if (name == "image") {  // its viewport rectangle (x, y, width, height)
      const double x = length(node, "x", horizontal(viewport), style),
                   y = length(node, "y", vertical(viewport), style);
      const double w = length(node, "width", horizontal(viewport), style),
                   h = length(node, "height", vertical(viewport), style);
      if (!(w > 0.0) || !(h > 0.0)) return std::nullopt;
      return Rect{x, y, x + w, y + h};
    }
    if (name != "g" && name != "a" && name != "svg" && name != "symbol" && name != "switch")
      return std::nullopt;
    // A nested <svg>'s content is in the user space of the viewport it establishes; the root's viewBox
    // mapping is part of the root's own transform (group_node), so its content is measured as a group's.
    if ((name == "svg" && node != root_) || name == "symbol")
      return nested_viewport_bbox(node, style, viewport, depth, std::nullopt);
    return children_bbox(node, style, viewport, depth);
  }

  // The union of the boxes of `node`'s rendered children, each mapped by its transform, in `node`'s
  // user space.
  std::optional<Rect> children_bbox(const pugi::xml_node& node, const ComputedStyle& style,
                                    const Viewport& viewport, int depth) {
    std::optional<Rect> box;
    for (pugi::xml_node child = node.first_child(); child; child = child.next_sibling()) {
      if (child.type() != pugi::node_element) continue;
      const ComputedStyle child_style = computed_style(child, style, viewport);
      if (!child_style.display) continue;
      include_transformed(box, object_bbox(child, child_style, viewport, depth + 1),
                          element_transform(child, viewport, child_style.font_size));
    }
    return box;
  }

  // The box of a nested <svg>'s (or an instanced <symbol>'s) content in the user space the element
  // itself is in: its children measured in the viewport it establishes and mapped out of it (x, y and the
  // viewBox, SVG 1.1 7.9). The viewport's clip does not count: a bounding box ignores clipping (SVG 2 8.10).
  std::optional<Rect> nested_viewport_bbox(const pugi::xml_node& node, const ComputedStyle& style,
                                           const Viewport& viewport, int depth,
                                           std::optional<std::pair<double, double>> size_override) {
    const std::optional<NestedViewport> nested = nested_viewport(node, node, style, viewport, size_override);
    if (!nested) return std::nullopt;
    std::optional<Rect> box;
    include_transformed(box, children_bbox(node, style, nested->content_viewport, depth),
                        nested->content_transform);
    return box;
  }

  // The <mask> `id` names, read once per render and viewport (mask.h); null when it names none.
  const detail::ResolvedMask* resolved_mask(const std::string& id, const Viewport& viewport) {
    const detail::ResolveContext context{viewport.width, viewport.height, resolution()};
    return references_.mask(
        id, context, [&](const pugi::xml_node& node) { return referenced_style(node, viewport); },
        diagnostics_);
  }

  // mask="url(#id)" (mask.h): renders the <mask>'s content offscreen and pushes its coverage as a clip
  // mask. Returns how many clip masks it pushed (a mask on the <mask> element adds one), or nullopt when
  // the element must not be rendered at all. A reference that is not a <mask>, or that closes a loop,
  // counts as none, with a warning.
  // `resolved`: the <mask> `id` names (null: it names none).
  std::optional<int> push_mask(const detail::ResolvedMask* resolved, const std::string& id, const Affine& ctm,
                               const std::optional<Rect>& bbox, const Viewport& viewport, int depth) {
    if (!resolved) {
      diagnostics_.warnings.push_back("mask refers to '#" + id + "', which is not a <mask>; drawn unmasked");
      return 0;
    }
    const pugi::xml_node mask = resolved->element;
    if (std::find(mask_stack_.begin(), mask_stack_.end(), mask) != mask_stack_.end()) {
      diagnostics_.warnings.push_back("a mask reference closes a loop back to mask '#" + id +
                                      "'; that reference is ignored");
      return 0;
    }
    if (static_cast<int>(mask_stack_.size()) >= detail::kMaxMaskDepth) {
      diagnostics_.warnings.push_back("masks nested more than " + std::to_string(detail::kMaxMaskDepth) +
                                      " deep; the innermost is ignored");
      return 0;
    }
    if (!clip_depth_left("masks and clip-paths")) return std::nullopt;
    const ComputedStyle& mask_style = resolved->style;
    const std::optional<detail::MaskSetup> setup = detail::place_mask(*resolved, bbox);
    if (!setup) return std::nullopt;
    const std::optional<Path> region =
        detail::rect_path(setup->region.x0, setup->region.y0, setup->region.width(), setup->region.height(),
                          std::nullopt, std::nullopt);
    if (!region) return std::nullopt;  // a region that underflows to no area hides the element
    // The content is drawn clipped to the mask region, so only the pixels of the region's device box can
    // be non-zero: the offscreen image covers that box within the output, not the whole output (a small
    // masked icon in a large output costs its own size). It is placed at a whole-pixel offset, so every
    // pixel is computed as on an output-sized image: the same coverage, the same pattern tiles, the same
    // filter regions (those reach past the offscreen's edges as they reach past the output's).
    const std::optional<detail::PixelBox> box =
        detail::device_box(setup->region, ctm, canvas_->width(), canvas_->height());
    if (!box) return std::nullopt;  // the region lies outside the output: nothing of the element shows
    // The offscreen image and the output-sized mask made from it count against the memory budget.
    std::optional<Canvas> offscreen = offscreen_canvas(
        box->width(), box->height(), std::int64_t{canvas_->width()} * canvas_->height(), "a mask");
    if (!offscreen) return std::nullopt;
    const Affine shifted = Affine::translate(-box->x0, -box->y0) * ctm;
    Canvas* const target = canvas_;
    canvas_ = &*offscreen;
    mask_stack_.push_back(mask);
    const FillOptions fill_options{options_.tolerance, options_.antialias};
    Status status = offscreen->push_clip(*region, FillRule::kNonZero, shifted, fill_options);
    if (status)
      status = render_children(mask, mask_style, shifted * setup->content_transform, viewport, depth + 1);
    mask_stack_.pop_back();
    canvas_ = target;
    if (!status) {
      if (status.error().kind == ErrorKind::kLimitExceeded) budget_error_ = status.error();
      return std::nullopt;
    }
    if (Status pushed = canvas_->push_clip_mask(detail::mask_coverage(
            offscreen->image(), setup->type, canvas_->width(), canvas_->height(), box->x0, box->y0));
        !pushed) {
      if (pushed.error().kind == ErrorKind::kLimitExceeded) budget_error_ = pushed.error();
      return std::nullopt;
    }
    // A mask on the <mask> element multiplies in (mask.h); a broken one leaves this mask alone.
    int pushed = 1;
    if (!mask_style.painting.mask_id.empty()) {
      mask_stack_.push_back(mask);
      const std::optional<int> inner = push_mask(resolved_mask(mask_style.painting.mask_id, viewport),
                                                 mask_style.painting.mask_id, ctm, bbox, viewport, depth + 1);
      mask_stack_.pop_back();
      if (!inner) {
        if (const Status popped = canvas_->pop_clip(); !popped) budget_error_ = popped.error();
        return std::nullopt;
      }
      pushed += *inner;
    }
    return pushed;
  }

  static bool is_basic_shape(std::string_view name) {
    for (std::string_view known : {"path", "rect", "circle", "ellipse", "line", "polyline", "polygon"}) {
      if (name == known) return true;
    }
    return false;
  }

  // Appends every element of `path` mapped by `transform` to `builder` (exact: control points map, weights
  // stay).
  static void append_transformed(PathBuilder& builder, const Path& path, const Affine& transform) {
    std::vector<Point> points;
    for (const PathElement& element : path) {
      points.clear();
      for (const Point& p : element.points) points.push_back(transform.apply(p));
      switch (element.verb) {
        case PathVerb::kMove:
          builder.move_to(points.front());
          break;
        case PathVerb::kClose:
          builder.close();
          break;
        default:
          if (element.is_rational()) {
            builder.rational_bezier_to(std::span<const Point>(points).subspan(1), element.weights);
          } else {
            builder.bezier_to(std::span<const Point>(points).subspan(1));
          }
      }
    }
  }

  // The <clipPath> `id` names, read once per render and viewport (clip_path.h); null when it names none.
  const detail::ResolvedClipPath* resolved_clip_path(const std::string& id, const Viewport& viewport) {
    detail::ClipPathReader reader;
    reader.referenced_style = [&](const pugi::xml_node& node) { return referenced_style(node, viewport); };
    reader.style = [&](const pugi::xml_node& node, const ComputedStyle& parent) {
      return computed_style(node, parent, viewport);
    };
    reader.transform = [&](const pugi::xml_node& node, double font_size) {
      return element_transform(node, viewport, font_size);
    };
    reader.use_offset = [&](const pugi::xml_node& use, const ComputedStyle& style) {
      return Point{geometry(use, "x", horizontal(viewport), style).value_or(0.0),
                   geometry(use, "y", vertical(viewport), style).value_or(0.0)};
    };
    reader.is_curve = [&](const pugi::xml_node& node) {
      return index_.facts(node).role == detail::ElementRole::kCurve;
    };
    reader.outline = [&](const pugi::xml_node& geometry, const ComputedStyle& style,
                         const ComputedStyle& clip_style) {
      return clip_outline(geometry, style, clip_style, viewport);
    };
    return references_.clip_path(id, resolve_context(viewport), reader);
  }

  // The outline of one clipPath child (`geometry` under `style`) in its own user space, and the rule it is
  // filled with (clip_path.h); nullopt when it has no geometry. A <text> is laid out as at the top of the
  // nesting: it is read once per clip path, wherever the clip path is used.
  std::optional<detail::ClipOutline> clip_outline(const pugi::xml_node& geometry, const ComputedStyle& style,
                                                  const ComputedStyle& clip_style, const Viewport& viewport) {
    const bool is_curve = index_.facts(geometry).role == detail::ElementRole::kCurve;
    const std::string_view name = local_name(geometry);
    if (!is_curve && name == "text") {
      PathBuilder outlines;
      if (append_clip_text(geometry, clip_style, Affine::identity(), viewport, 0, outlines) == 0)
        return std::nullopt;
      Result<Path> built = outlines.build();
      if (!built) return std::nullopt;
      return detail::ClipOutline{std::move(built).value(), FillRule::kNonZero};
    }
    std::optional<Path> path = shape_path(geometry, name, is_curve, style, viewport);
    if (!path) return std::nullopt;
    return detail::ClipOutline{std::move(*path), style.clip_rule};
  }

  // Whether one more clip fits under kMaxClipDepth (limits.h), the most clips a canvas holds at once: every
  // clip-path in force (on the element, its ancestors, and clipPaths clipped in turn) and every mask takes
  // one. No specification sets a depth; an element that would need more is not drawn, with a warning, as
  // hiding what a clip was meant to hide is the safe side (drawing it unclipped would show it).
  bool clip_depth_left(const char* what) {
    if (canvas_->clip_depth() < kMaxClipDepth) return true;
    diagnostics_.warnings.push_back(
        std::string(what) + " nested more than " + std::to_string(kMaxClipDepth) +
        " deep (counting those of the enclosing groups); the element is not drawn");
    return false;
  }

  // A canvas of the output's size for offscreen drawing (a mask's content, a clip made of several
  // children), charged with the enclosing canvas's memory so that nested offscreen canvases are counted
  // together against the render budget (limits.h). `extra` is what the caller keeps beside it (the mask
  // made from it). Sets budget_error_ and gives nullopt when it does not fit.
  std::optional<Canvas> offscreen_canvas(std::int64_t extra, const char* what) {
    return offscreen_canvas(canvas_->width(), canvas_->height(), extra, what);
  }

  // An offscreen canvas of `width` x `height` pixels (a part of the output), counted as above.
  std::optional<Canvas> offscreen_canvas(int width, int height, std::int64_t extra, const char* what) {
    if (!charge_offscreen_pixels(std::int64_t{width} * height, what)) return std::nullopt;
    const std::int64_t bytes = image_memory_bytes(width, height) + extra;
    if (canvas_->memory_bytes() + bytes > canvas_->limits().max_memory_bytes) {
      budget_error_ = limit_error(
          std::string(what) + " needs " + std::to_string(bytes) + " more bytes, beyond the memory limit of " +
          std::to_string(canvas_->limits().max_memory_bytes) + " (raise --max-memory)");
      return std::nullopt;
    }
    Canvas offscreen{Image(width, height)};
    offscreen.set_limits(canvas_->limits());
    offscreen.set_held_memory_bytes(canvas_->memory_bytes() + extra);
    return offscreen;
  }

  // Counts `pixels` more of offscreen image. Each reference level's depth is bounded (masks and patterns 8,
  // markers 4), but not how many references a level holds: a pattern whose tile holds four masked shapes,
  // each mask filled with the next pattern, makes 4^8 output-sized images in 8 levels, hours of work in
  // little memory (each is freed before the next). So their sum is bounded too: past it the render fails
  // with a limit error, as past --max-elements. Sets budget_error_ and gives false then.
  bool charge_offscreen_pixels(std::int64_t pixels, const char* what) {
    offscreen_pixels_ += pixels;
    const std::int64_t basis =
        std::min(options_.limits.max_pixels, std::max(output_pixels_, kOffscreenBasisPixels));
    const std::int64_t bound = kOffscreenPixelsPerCanvasPixel * basis;
    if (offscreen_pixels_ <= bound) return true;
    budget_error_ =
        limit_error(std::string(what) +
                    ": the offscreen images of masks, clip paths and pattern tiles add up to more than " +
                    std::to_string(bound) + " pixels, " + std::to_string(kOffscreenPixelsPerCanvasPixel) +
                    " times the output's pixels (counted as at least 16777216 and at most --max-pixels)");
    return false;
  }

  // clip-path="url(#id)" (SVG 1.1 14.3.5, CSS Masking 1 6.1): pushes the clipPath's region as clip masks.
  // Returns how many it pushed, or nullopt when the element must not be rendered (objectBoundingBox
  // units on an element without a box, or the clipPath's own clip-path hides everything). A reference
  // that is not a <clipPath> is ignored with a warning, and so is one back to a clipPath being applied
  // (that is where a loop closes; resvg breaks loops the same way).
  //
  // One child without a clip-path of its own gives an exact clip path with its clip-rule. Otherwise each
  // child is filled offscreen with its own clip-rule, through its own clip-path, and the union of their
  // coverage becomes the mask: children with different rules, or clipped differently, cannot be one path.
  // A clip-path on the <clipPath> element intersects (a second mask).
  // `resolved`: the <clipPath> `id` names (null: it names none); a clipPath's own clip-path and its
  // children's are still read here by id.
  std::optional<int> push_clip_path(const std::string& id, const Affine& ctm, const std::optional<Rect>& bbox,
                                    const Viewport& viewport, int depth) {
    if (id.empty()) return 0;
    return push_clip_path(resolved_clip_path(id, viewport), id, ctm, bbox, viewport, depth);
  }
  std::optional<int> push_clip_path(const detail::ResolvedClipPath* resolved, const std::string& id,
                                    const Affine& ctm, const std::optional<Rect>& bbox,
                                    const Viewport& viewport, int depth) {
    if (!resolved) {
      diagnostics_.warnings.push_back("clip-path refers to '#" + id +
                                      "', which is not a <clipPath>; drawn unclipped");
      return 0;
    }
    const pugi::xml_node clip = resolved->element;
    if (std::find(clip_stack_.begin(), clip_stack_.end(), clip) != clip_stack_.end()) {
      diagnostics_.warnings.push_back("clip-path '#" + id + "' refers to itself; that reference is ignored");
      return 0;
    }
    if (depth > options_.limits.max_depth) {
      diagnostics_.warnings.push_back("clip-path '#" + id + "' is nested more than " +
                                      std::to_string(options_.limits.max_depth) +
                                      " deep (raise --max-depth); that reference is ignored");
      return 0;
    }
    if (!clip_depth_left("clip-paths")) return std::nullopt;
    const ComputedStyle& clip_style = resolved->style;
    Affine clip_transform = ctm * resolved->transform;
    if (resolved->bounding_box_units) {
      // SVG 1.1 7.11: objectBoundingBox units on an element without area disable the element.
      if (!bbox || !(bbox->width() > 0.0) || !(bbox->height() > 0.0)) return std::nullopt;
      clip_transform = clip_transform * Affine::translate(bbox->x0, bbox->y0) *
                       Affine::scale(bbox->width(), bbox->height());
    }
    clip_stack_.push_back(clip);
    const std::vector<detail::ClipPathChild>& children = resolved->children;
    const FillOptions fill_options{options_.tolerance, options_.antialias};
    const bool exact = children.size() <= 1 && (children.empty() || children.front().clip_path_id.empty());
    Status pushed = Status::ok();
    if (exact) {
      const std::optional<detail::ClipOutline>* outline =
          children.empty() ? nullptr : &children.front().outline;
      // No child, or no geometry: the clip region is empty and nothing under it is drawn (14.3.5).
      static const Path kNothing;
      const Path& path = outline && *outline ? (*outline)->path : kNothing;
      const Affine transform =
          children.empty() ? clip_transform : clip_transform * children.front().transform;
      if (Status room = canvas_->reserve_clip(path, transform, fill_options); !room) {
        budget_error_ = room.error();
      } else {
        pushed = canvas_->push_clip(path, outline && *outline ? (*outline)->rule : FillRule::kNonZero,
                                    transform, fill_options);
      }
    } else if (std::optional<Canvas> offscreen = offscreen_canvas(
                   std::int64_t{canvas_->width()} * canvas_->height(), "a clip path of several children")) {
      Canvas* const target = canvas_;
      canvas_ = &*offscreen;
      const Paint opaque = Paint::solid(Color{1.0, 1.0, 1.0, 1.0});
      for (const detail::ClipPathChild& child : children) {
        if (!child.outline) continue;
        const Affine child_ctm = clip_transform * child.transform;
        const std::optional<int> child_clips = push_clip_path(
            child.clip_path_id, child_ctm, child.outline->path.tight_bounds(), viewport, depth + 1);
        if (budget_error_) break;
        if (!child_clips) continue;
        pushed = offscreen->fill(child.outline->path, opaque, child.outline->rule, child_ctm, fill_options);
        for (int i = 0; i < *child_clips; ++i) {
          if (const Status popped = offscreen->pop_clip(); !popped) pushed = popped;
        }
        if (!pushed) break;
      }
      canvas_ = target;
      if (pushed && !budget_error_) {
        pushed = canvas_->push_clip_mask(detail::mask_coverage(offscreen->image(), detail::MaskType::kAlpha));
      }
    }
    if (budget_error_ || !pushed) {
      clip_stack_.pop_back();
      if (!budget_error_ && pushed.error().kind == ErrorKind::kLimitExceeded) budget_error_ = pushed.error();
      if (!budget_error_)
        diagnostics_.warnings.push_back("clip-path '#" + id + "' ignored: " + pushed.error().message);
      return 0;
    }
    // The clipPath's own clip-path, in the referencing element's user space (CSS Masking 1 6.1).
    const std::optional<int> own = push_clip_path(clip_style.clip_path_id, ctm, bbox, viewport, depth + 1);
    clip_stack_.pop_back();
    if (!own) {
      if (const Status popped = canvas_->pop_clip(); !popped) budget_error_ = popped.error();
      return std::nullopt;
    }
    return 1 + *own;
  }

  // A <text> child of a <clipPath>: appends its glyph outlines (text_element.h, the same pieces
  // render_text paints) mapped by `transform` to `combined`; returns how many pieces it added.
  int append_clip_text(const pugi::xml_node& text, const ComputedStyle& clip_style, const Affine& transform,
                       const Viewport& viewport, int depth, PathBuilder& combined) {
    const ComputedStyle style = computed_style(text, clip_style, viewport);
    if (!style.display || !style.visible) return 0;
    int pieces = 0;
    for (const detail::TextPiece& piece : text_pieces(text, style, viewport, depth)) {
      append_transformed(combined, piece.path, transform);
      ++pieces;
    }
    return pieces;
  }

  // The viewport a nested <svg> (or a <symbol> / <svg> instanced by <use>, whose width and height
  // override) establishes: the rectangle (x, y, width, height) in the parent's user space, and the map
  // from its content's user space into that space, from the viewBox (SVG 1.1 7.9). nullopt when the
  // element is not rendered (a zero width, height or viewBox size).
  struct NestedViewport {
    double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
    Affine content_transform;
    Viewport content_viewport;
  };
  std::optional<NestedViewport> nested_viewport(const pugi::xml_node& node, const pugi::xml_node& sizing,
                                                const ComputedStyle& style, const Viewport& viewport,
                                                std::optional<std::pair<double, double>> size_override) {
    // x, y, width and height are geometry properties (SVG 2 9.1.1 lists them for svg, symbol and use):
    // style sheets may set them; auto and the initial value of width and height are 100%.
    NestedViewport nested;
    nested.x = geometry(sizing, "x", horizontal(viewport), style).value_or(0.0);
    nested.y = geometry(sizing, "y", vertical(viewport), style).value_or(0.0);
    nested.width = geometry(sizing, "width", horizontal(viewport), style).value_or(viewport.width);
    nested.height = geometry(sizing, "height", vertical(viewport), style).value_or(viewport.height);
    if (size_override) std::tie(nested.width, nested.height) = *size_override;
    if (!(nested.width > 0.0) || !(nested.height > 0.0)) return std::nullopt;  // 7.9: zero disables rendering
    nested.content_transform = Affine::translate(nested.x, nested.y);
    nested.content_viewport = {nested.width, nested.height};
    if (const std::optional<ViewBox> box = view_box_of(node)) {
      if (box->width == 0.0 || box->height == 0.0) return std::nullopt;
      nested.content_transform =
          view_box_transform(*box, aspect_of(node), nested.x, nested.y, nested.width, nested.height);
      nested.content_viewport = {box->width, box->height};
    }
    return nested;
  }

  // The size a <use> gives the <symbol> or <svg> it instances: its own width and height where set, the
  // element's where not (SVG 2 5.6); nullopt when the <use> sets neither.
  std::optional<std::pair<double, double>> use_size_override(const pugi::xml_node& use,
                                                             const ComputedStyle& style,
                                                             const pugi::xml_node& element,
                                                             const ComputedStyle& element_style,
                                                             const Viewport& viewport) {
    const std::optional<double> w = geometry(use, "width", horizontal(viewport), style);
    const std::optional<double> h = geometry(use, "height", vertical(viewport), style);
    if (!w && !h) return std::nullopt;
    return std::pair{
        w ? *w : geometry(element, "width", horizontal(viewport), element_style).value_or(viewport.width),
        h ? *h : geometry(element, "height", vertical(viewport), element_style).value_or(viewport.height)};
  }

  // Nested <svg> (or a <symbol> / <svg> instanced by <use>): its content drawn in the viewport it
  // establishes (nested_viewport).
  Status render_nested_svg(const pugi::xml_node& node, const pugi::xml_node& sizing,
                           const ComputedStyle& style, const Affine& ctm, const Viewport& viewport, int depth,
                           std::optional<std::pair<double, double>> size_override) {
    const std::optional<NestedViewport> nested =
        nested_viewport(node, sizing, style, viewport, size_override);
    if (!nested) return Status::ok();
    const double x = nested->x, y = nested->y, width = nested->width, height = nested->height;
    const Affine inner = ctm * nested->content_transform;
    const Viewport inner_viewport = nested->content_viewport;
    // overflow is hidden for nested viewports by default (SVG 1.1 14.3.3): clip to (x, y, width, height);
    // overflow: visible or auto (SVG 2 14.3.3: auto is visible) draws the content outside it too.
    const bool overflow_visible = style.painting.overflow == detail::PaintingProperties::Overflow::kVisible;
    const std::optional<Path> viewport_rect =
        overflow_visible ? std::nullopt : detail::rect_path(x, y, width, height, std::nullopt, std::nullopt);
    if (viewport_rect) {
      CURVESCAN_PROPAGATE(canvas_->reserve_clip(*viewport_rect, ctm, FillOptions{options_.tolerance, options_.antialias}));
    }
    const bool clipped = viewport_rect && canvas_
                                              ->push_clip(*viewport_rect, FillRule::kNonZero, ctm,
                                                          FillOptions{options_.tolerance, options_.antialias})
                                              .is_ok();
    const Status status = render_children(node, style, inner, inner_viewport, depth + 1);
    if (clipped) CURVESCAN_PROPAGATE(canvas_->pop_clip());
    return status;
  }

  Status render_use(const pugi::xml_node& node, const ComputedStyle& style, const Affine& ctm,
                    const Viewport& viewport, int depth) {
    pugi::xml_attribute href = node.attribute("href");
    if (!href) href = node.attribute("xlink:href");
    const std::string_view reference = href ? href.value() : "";
    if (reference.size() < 2 || reference.front() != '#') {
      diagnostics_.warnings.push_back("<use> needs href=\"#id\"; got '" + std::string(reference) + "'");
      return Status::ok();
    }
    const auto target = index_.ids().find(std::string(reference.substr(1)));
    if (target == index_.ids().end()) {
      diagnostics_.warnings.push_back("<use> refers to '" + std::string(reference) +
                                      "', which does not exist");
      return Status::ok();
    }
    const pugi::xml_node element = target->second;
    for (pugi::xml_node scope = node; scope; scope = scope.parent()) {
      if (scope == element) {
        diagnostics_.warnings.push_back("<use> refers to '" + std::string(reference) +
                                        "', which contains it: circular reference skipped");
        return Status::ok();
      }
    }
    if (std::find(use_stack_.begin(), use_stack_.end(), element) != use_stack_.end()) {
      diagnostics_.warnings.push_back("<use> of '" + std::string(reference) + "' is circular; skipped");
      return Status::ok();
    }
    if (static_cast<int>(use_stack_.size()) >= options_.limits.max_use_depth) {
      return limit_error("<use> elements are nested more than " +
                         std::to_string(options_.limits.max_use_depth) + " deep (raise --max-use-depth)");
    }
    // The <use> is the context element of its content (SVG 2 13.4.1); its box only matters (and is only
    // measured, before the target counts as being drawn) when a paint of it is a gradient or pattern.
    detail::PaintSpace use_space{std::nullopt, ctm};
    if (style.fill.kind == PaintSpec::Kind::kUrl || style.stroke.kind == PaintSpec::Kind::kUrl)
      use_space.bbox = object_bbox(node, style, viewport, depth);
    use_stack_.push_back(element);
    push_context_paint(style, use_space);
    // SVG 1.1 5.6: the referenced element is rendered as a child of a group translated by (x, y).
    // x, y, width and height of <use> are geometry properties (SVG 2 9.1.1), from style sheets too.
    const Affine placed =
        ctm * Affine::translate(geometry(node, "x", horizontal(viewport), style).value_or(0.0),
                                geometry(node, "y", vertical(viewport), style).value_or(0.0));
    Status status;
    const std::string_view target_name = local_name(element);
    if (target_name == "symbol" || target_name == "svg") {
      const ComputedStyle symbol_style = computed_style(element, style, viewport);
      const std::optional<std::pair<double, double>> size =
          use_size_override(node, style, element, symbol_style, viewport);
      if (symbol_style.display) {
        // The instance is drawn as a nested <svg> (SVG 2 5.6: a <symbol> in the use's shadow tree becomes
        // one), so the element's own effects -- transform, opacity, blend, clip-path, mask and filter --
        // apply to it as a group, as they do to an <svg> drawn in place.
        const std::optional<detail::GroupNode> instance =
            group_node(element, symbol_style, viewport, depth + 1, nullptr, nullptr, size);
        status = draw_group(*instance, placed, viewport, depth + 1,
                            [&](double folded_opacity, const Affine& content_ctm) {
                              std::optional<ComputedStyle> adjusted;
                              return render_nested_svg(element, element,
                                                       content_style(symbol_style, folded_opacity, adjusted),
                                                       content_ctm, viewport, depth + 1, size);
                            });
      }
    } else {
      status = render_element(element, style, placed, viewport, depth + 1);
    }
    context_paint_.pop_back();
    use_stack_.pop_back();
    return status;
  }

  // context-fill / context-stroke (SVG 2 13.4.1): the paints of the element a marker is drawn for, or of
  // a <use>, for its content. A context paint of the element itself is resolved first (a marker on a
  // path inside a <use>), so the stack never holds one.
  // A gradient or pattern paint is drawn in the context element's user space and with its bounding box
  // (SVG 2 13.4.1: "the paint server is rendered using the coordinate space and bounding box of the
  // context element"), not the box of the shape that uses context-fill: `space`.
  void push_context_paint(const ComputedStyle& style, const detail::PaintSpace& space) {
    context_paint_.push_back(context_paint_of(style, space));
  }
  // The context paint of an element drawn with `style` in `space`, inside the context elements being drawn.
  detail::ContextPaint context_paint_of(const ComputedStyle& style, const detail::PaintSpace& space) const {
    detail::ContextPaint context{style.fill, style.stroke, style.color, space, space};
    if (!context_paint_.empty()) {
      const detail::ContextPaint& outer = context_paint_.back();
      for (auto [spec, spec_space] : {std::pair{&context.fill, &context.fill_space},
                                      std::pair{&context.stroke, &context.stroke_space}}) {
        if (spec->kind == PaintSpec::Kind::kContextFill) {
          *spec = outer.fill;
          *spec_space = outer.fill_space;
        } else if (spec->kind == PaintSpec::Kind::kContextStroke) {
          *spec = outer.stroke;
          *spec_space = outer.stroke_space;
        }
      }
    } else {
      for (PaintSpec* spec : {&context.fill, &context.stroke}) {
        if (spec->kind == PaintSpec::Kind::kContextFill || spec->kind == PaintSpec::Kind::kContextStroke) *spec = {};
      }
    }
    return context;
  }

  // A <text> element laid out (text_element.h): its glyph outlines with the style of each run. Used to
  // paint it, to clip with it and to measure it.
  // `ctm`: where the pieces are drawn (the device), for the strike of a bitmap colour glyph.
  std::vector<detail::TextPiece> text_pieces(const pugi::xml_node& text, const ComputedStyle& style,
                                             const Viewport& viewport, int depth,
                                             const Affine& ctm = Affine::identity()) {
    const detail::ChildStyle child_style = [&](const pugi::xml_node& child, const ComputedStyle& parent) {
      return computed_style(child, parent, viewport);
    };
    detail::TextContext context{viewport.width,
                                viewport.height,
                                resolution(),
                                options_.limits.max_depth - depth,
                                {},
                                {},
                                options_.limits.max_pixels};
    context.conditions_hold = [this](const pugi::xml_node& element) {
      return index_.facts(element).conditions_hold;
    };
    context.user_to_device = ctm;
    // <textPath href="#id">: a basic shape's geometry with its own transform (SVG 1.1 10.13.2).
    context.path_for_id = [&](const std::string& id) -> std::optional<Path> {
      const auto target = index_.ids().find(id);
      if (target == index_.ids().end() || !is_basic_shape(local_name(target->second))) return std::nullopt;
      const ComputedStyle target_style = computed_style(target->second, style, viewport);
      const std::optional<Path> path =
          shape_path(target->second, local_name(target->second), false, target_style, viewport);
      if (!path) return std::nullopt;
      Result<Path> placed = path->transformed(element_transform(target->second, viewport, target_style.font_size));
      return placed ? std::optional<Path>(std::move(placed).value()) : std::nullopt;
    };
    context.element_for_id = [&](const std::string& id) {
      const auto target = index_.ids().find(id);
      return target == index_.ids().end() ? pugi::xml_node() : target->second;
    };
    return detail::text_pieces(text, style, child_style, context, fonts_, diagnostics_);
  }

  // <text> (text_element.h): its glyph outlines, painted run by run like shapes.
  Status render_text(const pugi::xml_node& node, const ComputedStyle& style, const Affine& ctm,
                     const Viewport& viewport, int depth) {
    for (detail::TextPiece& piece : text_pieces(node, style, viewport, depth, ctm)) {
      if (piece.bitmap) {  // a bitmap colour glyph: only a fill to draw
        CURVESCAN_PROPAGATE(paint_glyph_bitmap(piece, ctm));
        continue;
      }
      if (piece.svg_glyph) {  // an SVG-in-OpenType glyph: its document
        CURVESCAN_PROPAGATE(draw_svg_glyph(piece, ctm, viewport, depth));
        continue;
      }
      const detail::PathNode run =
          path_node(std::move(piece.path), piece.object_box, piece.style, ctm, viewport, style.text.aliased);
      // A text run is not markable: its node places no markers, and its markers layer draws nothing.
      for (const detail::PaintLayer layer : run.paint_order)
        CURVESCAN_PROPAGATE(draw_path(run, layer, ctm, viewport, depth));
    }
    return Status::ok();
  }

  // A bitmap colour glyph's piece (text_element.h): its image over its rectangle, sampled as <image> is
  // (bilinear, the edge pixels padded), faded by the fill's own alpha (a colour fill's, as a COLR
  // palette layer is faded by it), fill-opacity and group opacity. The image counts against the memory
  // budget while it is drawn.
  Status paint_glyph_bitmap(const detail::TextPiece& piece, const Affine& ctm) {
    const ComputedStyle& style = piece.style;
    if (!style.visible || style.fill.kind == PaintSpec::Kind::kNone) return Status::ok();
    const double fill_alpha = style.fill.kind == PaintSpec::Kind::kColor          ? style.fill.color.a
                              : style.fill.kind == PaintSpec::Kind::kCurrentColor ? style.color.a
                                                                                  : 1.0;
    const Image& image = piece.bitmap->image;
    const std::int64_t pixel_bytes = image_memory_bytes(image.width(), image.height());
    const Paint paint =
        image_pattern_paint(image, piece.image_to_user, PatternExtend::kPad, PatternFilter::kBilinear,
                            fill_alpha * style.fill_opacity * style.group_opacity);
    if (!paint.pattern) return Status::ok();
    const std::int64_t held = canvas_->held_memory_bytes();
    canvas_->set_held_memory_bytes(held + 2 * pixel_bytes);  // the piece's image and the paint's copy
    Status status = canvas_->fill(piece.path, paint, FillRule::kNonZero, ctm,
                                  FillOptions{options_.tolerance, options_.antialias});
    canvas_->set_held_memory_bytes(held);
    if (!status && status.error().kind != ErrorKind::kLimitExceeded) {
      diagnostics_.warnings.push_back("a colour glyph was not drawn: " + status.error().message);
      status = Status::ok();
    }
    return status;
  }

  // An SVG-in-OpenType glyph's piece (text_element.h): its document parsed (svg_glyph_document.h: inflated
  // first when it is gzip-compressed) once per render, and its element "glyphN" drawn by a renderer of its
  // own, as <image> draws an SVG document, nested no deeper than an <image>'s (a glyph document whose text
  // uses the same font ends there). Faded in a group by the fill's alpha, fill-opacity and group opacity,
  // as a bitmap glyph is. A document that cannot be read (not well formed, not SVG, a gzip error) is one
  // warning, and the plain outline of each of its glyphs is filled instead where it has one.
  Status draw_svg_glyph(const detail::TextPiece& piece, const Affine& ctm, const Viewport& viewport,
                        int depth) {
    const ComputedStyle& style = piece.style;
    if (!style.visible || style.fill.kind == PaintSpec::Kind::kNone) return Status::ok();
    const detail::SvgGlyphDocument& glyph = *piece.svg_glyph;
    const std::string shown = "glyph " + std::to_string(glyph.glyph);
    const auto fill_outline = [&]() -> Status {
      if (!glyph.path_is_outline) return Status::ok();
      const detail::PathNode outline =
          path_node(piece.path, piece.object_box, style, ctm, viewport, /*aliased=*/false, /*stroked=*/false);
      return draw_path(outline, detail::PaintLayer::kFill, ctm, viewport, depth);
    };
    if (image_depth_ >= kMaxImageDepth) {
      diagnostics_.warnings.push_back("SVG glyph documents nested more than " +
                                      std::to_string(kMaxImageDepth) + " deep; the innermost is not drawn");
      return Status::ok();
    }
    // One parse per document and render: the glyphs of a font's document (an emoji font's hundreds) and
    // every occurrence of one glyph share it. A document that cannot be read is remembered as such.
    std::unique_ptr<NestedSvg>& cached = svg_glyph_documents_[{glyph.font, glyph.document.data()}];
    if (!cached) {
      auto nested = std::make_unique<NestedSvg>();
      // The documents kept so far count against what is left.
      const Status parsed = detail::parse_svg_glyph_tree(
          glyph.document, memory_left() - svg_glyph_document_bytes_, nested->tree);
      if (!parsed && parsed.error().kind == ErrorKind::kLimitExceeded)
        return limit_error("the SVG document of " + shown + " needs more than the memory left");
      if (!parsed) {
        diagnostics_.warnings.push_back("the SVG document of " + shown + " " + parsed.error().message +
                                        "; the outlines of its glyphs are drawn");
      } else {
        svg_glyph_document_bytes_ += nested->tree.memory_bytes;
        start_nested_renderer(*nested);
      }
      cached = std::move(nested);
    }
    NestedSvg& nested = *cached;
    if (!nested.renderer) return fill_outline();
    const double fill_alpha = style.fill.kind == PaintSpec::Kind::kColor          ? style.fill.color.a
                              : style.fill.kind == PaintSpec::Kind::kCurrentColor ? style.color.a
                                                                                  : 1.0;
    const double opacity = fill_alpha * style.fill_opacity * style.group_opacity;
    const bool faded = opacity < 1.0;
    if (faded) {
      CURVESCAN_PROPAGATE(canvas_->reserve_layer());
      CURVESCAN_PROPAGATE(canvas_->push_layer());
    }
    const detail::SourcePositions* outer_positions = std::exchange(diagnostics_.positions, nullptr);
    const Status status = nested.renderer->draw_glyph_element(*canvas_, "glyph" + std::to_string(glyph.glyph),
                                                              ctm * piece.svg_to_user, glyph.units_per_em);
    diagnostics_.positions = outer_positions;
    if (faded) CURVESCAN_PROPAGATE(canvas_->pop_layer(opacity));
    return status;
  }

  // The geometry of a basic shape or curvescan curve element, or nullopt when it renders nothing. Path
  // data and point lists with an error give the geometry up to the error, with a warning.
  std::optional<Path> shape_path(const pugi::xml_node& node, std::string_view name, bool is_curve,
                                 const ComputedStyle& style, const Viewport& viewport) {
    const LengthAxis w = horizontal(viewport), h = vertical(viewport),
                     diagonal = resolve_context(viewport).other();
    if (is_curve) {
      const auto attribute = [&](const char* key) { return std::string_view(node.attribute(key).value()); };
      const detail::CurveAttributes attributes{
          attribute("points"),   attribute("degree"), attribute("knots"),
          attribute("weights"),  attribute("closed"), attribute("alpha"),
          attribute("tangents"), attribute("ends"),   attribute("parameterization"),
          attribute("f"),        attribute("x"),      attribute("y"),
          attribute("box"),      attribute("tolerance"),
          attribute("matrix"),   attribute("eye"),    attribute("target"),
          attribute("up"),       attribute("focal"),  attribute("scale"),
          attribute("centre"),   attribute("iso")};
      std::vector<std::string> notes;
      Result<Path> path = name == "explicit" || name == "implicit" || name == "patch"
                              ? detail::curve_family_element_path(name, attributes, notes)
                              : detail::curve_element_path(name, attributes);
      for (std::string& note : notes) diagnostics_.warnings.push_back(std::move(note));
      if (!path) {
        diagnostics_.warnings.push_back(path.error().message + " (element not rendered)");
        return std::nullopt;
      }
      return std::move(path).value();
    }
    if (name == "path") {
      PathBuilder builder;
      const std::string data = detail::geometry_path_data(node, style_sheets_, diagnostics_);
      if (const std::optional<PathDataError> error = append_path_data(data, builder)) {
        diagnostics_.warnings.push_back("<path" + id_suffix(node) + "> " + error->message +
                                        " (rendered up to the error)");
      }
      Result<Path> built = builder.build();
      if (!built || built->empty()) return std::nullopt;
      return std::move(built).value();
    }
    const auto geometry = [&](std::string_view property, LengthAxis axis) {
      return this->geometry(node, property, axis, style);
    };
    if (name == "rect") {
      // width and height auto are 0 for a rect (SVG 2 10.2); rx, ry auto follow rect_path.
      return detail::rect_path(geometry("x", w).value_or(0.0), geometry("y", h).value_or(0.0),
                               geometry("width", w).value_or(0.0), geometry("height", h).value_or(0.0),
                               geometry("rx", w), geometry("ry", h));
    }
    if (name == "circle") {
      const double r = geometry("r", diagonal).value_or(0.0);
      return detail::ellipse_path(geometry("cx", w).value_or(0.0), geometry("cy", h).value_or(0.0), r, r);
    }
    if (name == "ellipse") {
      // SVG 2 10.4: rx or ry auto (the initial value, also where the attribute is missing or invalid)
      // takes the other's value; both auto is 0, which renders nothing.
      const std::optional<double> rx = geometry("rx", w), ry = geometry("ry", h);
      return detail::ellipse_path(geometry("cx", w).value_or(0.0), geometry("cy", h).value_or(0.0),
                                  rx.value_or(ry.value_or(0.0)), ry.value_or(rx.value_or(0.0)));
    }
    if (name == "line") {
      return detail::line_path({length(node, "x1", w, style), length(node, "y1", h, style)},
                               {length(node, "x2", w, style), length(node, "y2", h, style)});
    }
    // polyline, polygon
    NumberList list = parse_number_list(node.attribute("points").value());
    if (!list.complete || list.values.size() % 2 != 0) {
      diagnostics_.warnings.push_back("<" + std::string(name) + id_suffix(node) +
                                      "> points has an error (rendered up to it)");
      if (list.values.size() % 2 != 0) list.values.pop_back();
    }
    return detail::polyline_path(list.values, name == "polygon");
  }

  // A geometry property (geometry_properties.h) in user units: style sheets win over the attributes;
  // nullopt is the initial value or auto.
  std::optional<double> geometry(const pugi::xml_node& node, std::string_view property, LengthAxis axis,
                                 const ComputedStyle& style) {
    const std::optional<Length> value = detail::geometry_length(node, property, style_sheets_, diagnostics_);
    if (!value) return std::nullopt;
    return length_to_pixels(*value, LengthContext{axis.dpi, style.font_size, axis.percent_reference});
  }

  static std::string id_suffix(const pugi::xml_node& node) {
    const pugi::xml_attribute id = node.attribute("id");
    return id ? " id=\"" + std::string(id.value()) + "\"" : std::string();
  }

  // The render tree's node for `path` painted with `style` under `ctm` (render_path.h): its fill resolved,
  // and its stroke when `stroked` and the style draws one. `object_box` replaces the path's own box for
  // objectBoundingBox units (a text run: its <text>'s box). `aliased`: drawn without anti-aliasing (a
  // shape's shape-rendering, ComputedStyle::aliased_shapes). Its markers are placed when `markable`.
  detail::PathNode path_node(Path path, const std::optional<Rect>& object_box, const ComputedStyle& style,
                             const Affine& ctm, const Viewport& viewport, bool aliased, bool stroked = true,
                             detail::Markable markable = detail::Markable::kNo) {
    detail::PathNode node;
    node.fill_rule = style.fill_rule;
    node.non_scaling_stroke = style.painting.non_scaling_stroke;
    node.antialias = aliased ? Antialias::kNone : options_.antialias;
    node.paint_order = style.painting.paint_order;
    if (style.visible) {
      const bool has_stroke =
          stroked && style.stroke.kind != PaintSpec::Kind::kNone && style.stroke_width > 0.0;
      // The box only matters to paint servers (objectBoundingBox units); a plain colour does not measure
      // the path.
      const auto may_need_box = [](const PaintSpec& spec) {
        return spec.kind != PaintSpec::Kind::kNone && spec.kind != PaintSpec::Kind::kColor &&
               spec.kind != PaintSpec::Kind::kCurrentColor;
      };
      const bool needs_box = may_need_box(style.fill) || (has_stroke && may_need_box(style.stroke));
      const Rect box = !needs_box ? Rect{} : object_box ? *object_box : path.tight_bounds();
      node.fill = resolve_paint(style.fill, style.color, style.fill_opacity * style.group_opacity, box, ctm,
                                viewport);
      if (has_stroke) {
        node.stroke = resolve_paint(style.stroke, style.color, style.stroke_opacity * style.group_opacity,
                                    box, ctm, viewport);
        node.stroke_style = stroke_style_of(style);
      }
    }
    // Markers are drawn whatever the element's visibility: their content has its own (the <marker>'s).
    const detail::PaintingProperties& painting = style.painting;
    if (markable != detail::Markable::kNo &&
        !(painting.marker_start.empty() && painting.marker_mid.empty() && painting.marker_end.empty()))
      node.markers = placed_markers(path, markable, style, ctm, viewport);
    node.path = std::move(path);
    return node;
  }

  // Paints the fill, the stroke or the markers (`layer`) of `node` under `ctm`, reading nothing but the
  // node. A render limit exceeded (limits.h) fails the whole render; any other failure skips the fill or
  // stroke with a warning. `viewport` and `depth` are where the walk is, for the tile of a pattern paint
  // and the content of a marker, which are still drawn from their elements.
  Status draw_path(const detail::PathNode& node, detail::PaintLayer layer, const Affine& ctm,
                   const Viewport& viewport, int depth) {
    if (layer == detail::PaintLayer::kMarkers) return draw_markers(node, ctm, viewport, depth);
    const bool is_fill = layer == detail::PaintLayer::kFill;
    const std::optional<detail::ShapePaint>& shape_paint = is_fill ? node.fill : node.stroke;
    if (!shape_paint) return Status::ok();
    const Paint* paint = std::get_if<Paint>(&*shape_paint);
    std::optional<Paint> tile;
    if (paint == nullptr) {
      const detail::PatternPaint& pattern = std::get<detail::PatternPaint>(*shape_paint);
      tile = pattern_tile_paint(pattern, ctm, viewport, depth);
      if (budget_error_) return *budget_error_;  // a pattern tile refused by a render limit
      if (!tile) tile = pattern.fallback;
      if (!tile) return Status::ok();
      paint = &*tile;
    }
    const FillOptions options{options_.tolerance, node.antialias};
    const Status status =
        is_fill ? canvas_->fill(node.path, *paint, node.fill_rule, ctm, options)
        : node.non_scaling_stroke
            ? canvas_->stroke_in_device_space(node.path, *paint, node.stroke_style, ctm, options)
            : canvas_->stroke(node.path, *paint, node.stroke_style, ctm, options);
    if (!status && status.error().kind == ErrorKind::kLimitExceeded) return status;
    if (!status) {
      diagnostics_.warnings.push_back(std::string(is_fill ? "a fill" : "a stroke") +
                                      " was not drawn: " + status.error().message);
    }
    return Status::ok();
  }

  // The solid paint of a `kind` of kColor or kCurrentColor at `opacity`; nullopt for any other kind.
  static std::optional<Paint> solid_paint(PaintSpec::Kind kind, const Color& color,
                                          const Color& current_color, double opacity) {
    if (kind != PaintSpec::Kind::kColor && kind != PaintSpec::Kind::kCurrentColor) return std::nullopt;
    const Color& used = kind == PaintSpec::Kind::kCurrentColor ? current_color : color;
    return Paint::solid(Color{used.r, used.g, used.b, used.a * opacity});
  }

  // What `spec` paints at `opacity` on a shape with box `bbox` drawn under `ctm` (shape_paint.h), or nullopt
  // for none. `current_color` is the shape's `color`. `space` maps the user space `bbox` is in to the
  // shape's (identity but for context paints).
  std::optional<detail::ShapePaint> resolve_paint(const PaintSpec& spec, const Color& current_color,
                                                  double opacity, const Rect& bbox, const Affine& ctm,
                                                  const Viewport& viewport,
                                                  const Affine& space = Affine::identity()) {
    if (spec.kind == PaintSpec::Kind::kContextFill || spec.kind == PaintSpec::Kind::kContextStroke) {
      // The context element's paint (SVG 2 13.4.1); outside a marker or a <use>, none. Its currentColor is
      // the context element's colour.
      if (context_paint_.empty()) return std::nullopt;
      const detail::ContextPaint& context = context_paint_.back();
      const bool fill = spec.kind == PaintSpec::Kind::kContextFill;
      const PaintSpec& paint = fill ? context.fill : context.stroke;
      const detail::PaintSpace& context_space = fill ? context.fill_space : context.stroke_space;
      if (paint.kind == PaintSpec::Kind::kUrl) {
        // An empty box stands for none: objectBoundingBox units then refuse the paint as on any
        // element without area.
        // The context's user space seen from the shape's: shape_ctm^-1 * context_ctm.
        const std::optional<Affine> from_shape = ctm.inverse();
        if (!from_shape) return std::nullopt;  // a shape mapped to nothing draws nothing
        return resolve_paint(paint, context.color, opacity,
                             context_space.bbox.value_or(Rect{0.0, 0.0, 0.0, 0.0}), ctm, viewport,
                             *from_shape * context_space.ctm);
      }
      return resolve_paint(paint, context.color, opacity, bbox, ctm, viewport);
    }
    if (spec.kind != PaintSpec::Kind::kUrl) {
      std::optional<Paint> solid = solid_paint(spec.kind, spec.color, current_color, opacity);
      if (!solid) return std::nullopt;
      return detail::ShapePaint{std::move(*solid)};
    }
    // An empty id is a URL into another document, never read (warned about where it was declared).
    const auto target = spec.url_id.empty() ? index_.ids().end() : index_.ids().find(spec.url_id);
    const std::string_view target_name = target == index_.ids().end() ? "" : local_name(target->second);
    if (target_name == "linearGradient" || target_name == "radialGradient") {
      // objectBoundingBox units on a box without area: the fallback colour, if any (paint_server.h).
      bool refused_for_box = false;
      std::optional<Paint> paint = detail::gradient_paint(
          references_.gradient(target->second, resolve_context(viewport), diagnostics_), bbox, opacity,
          &refused_for_box, space);
      if (!refused_for_box) {
        if (!paint) return std::nullopt;
        return detail::ShapePaint{std::move(*paint)};
      }
    } else if (target_name == "pattern") {
      // A pattern that paints nothing (no tile on a box without area, no content) gives way to the
      // fallback colour when there is one (SVG 2 13.3: the fallback of an invalid paint server); so does
      // one whose tile draws nothing (pattern_tile_paint).
      std::optional<detail::PatternPaint> paint =
          placed_pattern(target->second, opacity, bbox, viewport, space);
      if (paint) {
        paint->fallback = solid_paint(spec.fallback_kind, spec.fallback_color, current_color, opacity);
        return detail::ShapePaint{std::move(*paint)};
      }
    } else if (target == index_.ids().end()) {
      if (!spec.url_id.empty())
        diagnostics_.warnings.push_back("paint refers to '#" + spec.url_id + "', which does not exist");
    } else {
      diagnostics_.unsupported("paint server <" + std::string(target_name) + ">");
    }
    std::optional<Paint> fallback =
        solid_paint(spec.fallback_kind, spec.fallback_color, current_color, opacity);
    if (!fallback) return std::nullopt;
    return detail::ShapePaint{std::move(*fallback)};
  }

  // fill="url(#pattern)" (pattern.h) placed on a shape with box `bbox` (the pattern read once per render),
  // `space` as for resolve_paint; nullopt when the pattern paints nothing there.
  std::optional<detail::PatternPaint> placed_pattern(const pugi::xml_node& pattern, double opacity,
                                                     const Rect& bbox, const Viewport& viewport,
                                                     const Affine& space) {
    // No style sheets for the transform-origin of patternTransform: only its attribute and style attribute.
    const detail::ResolveContext context{viewport.width, viewport.height, resolution()};
    const detail::ResolvedPattern& resolved = references_.pattern(
        pattern, context, [&](const pugi::xml_node& content) { return referenced_style(content, viewport); },
        diagnostics_);
    std::optional<detail::PatternSetup> setup = detail::place_pattern(resolved, bbox);
    if (!setup) return std::nullopt;
    setup->pattern_transform = space * setup->pattern_transform;  // `space`: see resolve_paint
    return detail::PatternPaint{&resolved, *setup, opacity, id_suffix(pattern), std::nullopt};
  }

  // A pattern paint's tile drawn for a shape under `ctm`: the tile's content drawn into an image at the
  // device resolution of the tile, its size rounded to whole pixels, then painted repeated and filtered
  // bilinearly. The period is the rounded size mapped back (as resvg does): within half a device pixel of
  // the tile's width, so a fractional tile size drifts by that much per tile instead of resampling every
  // tile. A pattern drawn inside its own tile (directly or through others) paints nothing there, with a
  // warning: that is where the loop closes, as resvg breaks it. nullopt when the tile paints nothing.
  std::optional<Paint> pattern_tile_paint(const detail::PatternPaint& placed, const Affine& ctm,
                                          const Viewport& viewport, int depth) {
    const detail::ResolvedPattern& resolved = *placed.pattern;
    const detail::PatternSetup& setup = placed.setup;
    if (std::find(pattern_stack_.begin(), pattern_stack_.end(), resolved.content) != pattern_stack_.end()) {
      diagnostics_.warnings.push_back("pattern" + placed.shown +
                                      " is drawn inside itself; painted as none there");
      return std::nullopt;
    }
    if (static_cast<int>(pattern_stack_.size()) >= detail::kMaxPatternDepth) {
      diagnostics_.warnings.push_back("patterns nested more than " +
                                      std::to_string(detail::kMaxPatternDepth) +
                                      " deep; the innermost paints nothing");
      return std::nullopt;
    }
    const Affine to_device = ctm * setup.pattern_transform;
    const double scale_x = std::hypot(to_device.a, to_device.b),
                 scale_y = std::hypot(to_device.c, to_device.d);
    const double tile_w = setup.tile.width(), tile_h = setup.tile.height();
    const double pixels_x = std::round(tile_w * scale_x), pixels_y = std::round(tile_h * scale_y);
    if (!(pixels_x >= 1.0) || !(pixels_y >= 1.0)) return std::nullopt;  // smaller than a pixel, or degenerate
    if (pixels_x > kMaxImageDimension || pixels_y > kMaxImageDimension ||
        canvas_->memory_bytes() +
                image_memory_bytes(static_cast<std::int64_t>(pixels_x), static_cast<std::int64_t>(pixels_y)) >
            canvas_->limits().max_memory_bytes) {
      diagnostics_.warnings.push_back("a pattern tile of " +
                                      std::to_string(static_cast<long long>(pixels_x)) + " x " +
                                      std::to_string(static_cast<long long>(pixels_y)) +
                                      " pixels is beyond the memory limit; painted as none");
      return std::nullopt;
    }
    const int width = static_cast<int>(pixels_x), height = static_cast<int>(pixels_y);
    if (!charge_offscreen_pixels(std::int64_t{width} * height, "a pattern tile")) return std::nullopt;
    Canvas tile{Image(width, height)};
    tile.set_limits(canvas_->limits());
    tile.set_held_memory_bytes(canvas_->memory_bytes());
    Canvas* const target = canvas_;
    canvas_ = &tile;
    pattern_stack_.push_back(resolved.content);
    const Status status =
        render_children(resolved.content, resolved.content_style,
                        Affine::scale(scale_x, scale_y) * setup.content_transform, viewport, depth + 1);
    pattern_stack_.pop_back();
    canvas_ = target;
    if (!status) {
      if (status.error().kind == ErrorKind::kLimitExceeded) budget_error_ = status.error();
      return std::nullopt;
    }
    const Affine image_to_user = setup.pattern_transform * Affine::translate(setup.tile.x0, setup.tile.y0) *
                                 Affine::scale(1.0 / scale_x, 1.0 / scale_y);
    const Paint paint = image_pattern_paint(std::move(tile).take_image(), image_to_user,
                                            PatternExtend::kRepeat, PatternFilter::kBilinear, placed.opacity);
    if (paint.pattern == nullptr) return std::nullopt;
    return paint;
  }

  pugi::xml_node root_;
  const RenderOptions& options_;
  Diagnostics& diagnostics_;
  const css::StyleSheets* style_sheets_;  // the author sheets, null when there are none (cascade.h)
  css::StyleSheets media_sheets_;         // the sheets with the output's medium (use_medium)
  Canvas* canvas_ = nullptr;
  detail::DocumentIndex index_;  // build_index: the per-element decisions of this render
  detail::ResolvedReferences references_;  // paint servers, clip paths, masks, markers: each read once
  std::vector<pugi::xml_node> use_stack_;
  std::size_t rendered_elements_ = 0;
  std::vector<pugi::xml_node> clip_stack_;
  std::vector<pugi::xml_node> mask_stack_;  // the masks being applied, innermost last (recursion check)
  std::vector<pugi::xml_node> pattern_stack_;          // pattern contents being drawn, innermost last
  std::vector<pugi::xml_node> marker_stack_;           // markers being drawn, innermost last
  // How many <feImage>s may draw content that itself holds a filtered <feImage>: each level renders its
  // content once more offscreen, so the cost multiplies with the depth.
  static constexpr std::size_t kMaxNestedFeImages = 4;
  std::vector<pugi::xml_node> fe_image_stack_;         // elements drawn by <feImage>, innermost last
  std::vector<std::string> running_filters_;           // ids of the <filter>s being run, innermost last
  // The context elements being drawn (marked paths, <use>s), innermost last: context_paint.h.
  std::vector<detail::ContextPaint> context_paint_;
  int image_depth_ = 0;                                // <image> SVG documents this one is nested in
  /// The options of SVG documents in <image>: the same, except that they read no files.
  RenderOptions nested_options_ = [this] {
    RenderOptions nested = options_;
    nested.resource_directory.reset();
    return nested;
  }();
  detail::FontCache fonts_;  // <text>: each font looked up and opened once per document
  // SVG-in-OpenType glyph documents parsed in this render, by font and document (draw_svg_glyph); one
  // without a renderer could not be read.
  std::map<std::pair<const Font*, const char*>, std::unique_ptr<NestedSvg>> svg_glyph_documents_;
  std::int64_t svg_glyph_document_bytes_ = 0;  // the memory their trees hold
  const detail::GroupNodeProbe* group_probe_ = nullptr;  // set_group_probe
  const detail::PathNodeProbe* path_probe_ = nullptr;    // set_path_probe
  std::optional<Error> budget_error_;  // set by push_clip_path when a render limit refuses a clip
  std::int64_t offscreen_pixels_ = 0;  // offscreen images made so far (charge_offscreen_pixels)
  std::int64_t output_pixels_ = 0;     // the output canvas's pixels (render; 0 for glyph documents)
  // --export-id (export_size): the element, what it inherits, its viewport and its ink box's corner.
  pugi::xml_node export_node_;
  ComputedStyle export_parent_style_;
  Viewport export_viewport_{0.0, 0.0};
  Point export_origin_;
  std::optional<Size> export_root_size_;  // the document's size when the exported element is the root
  bool measuring_ink_ = false;  // object_bbox measures fills and strokes (export_size)
  std::int64_t document_bytes_ = 0;  // the parsed tree's memory (set_document_bytes)
};

}  // namespace

// The parsed document is an SVG tree as every SVG document is read (svg_tree.h).
struct Document::Parsed : detail::SvgTree {};

Document::Document(std::unique_ptr<Parsed> parsed) : parsed_(std::move(parsed)) {}
Document::Document(Document&&) noexcept = default;
Document& Document::operator=(Document&&) noexcept = default;
Document::~Document() = default;

Result<Document> Document::parse(std::string_view original_xml, std::int64_t max_memory_bytes) {
  auto kept = std::make_unique<Parsed>();
  CURVESCAN_PROPAGATE(detail::parse_svg_tree(original_xml, max_memory_bytes, *kept));
  return Document(std::move(kept));
}

Result<Document> Document::parse_glyph_document(std::string_view stored, std::int64_t max_memory_bytes) {
  auto kept = std::make_unique<Parsed>();
  CURVESCAN_PROPAGATE(detail::parse_svg_glyph_tree(stored, max_memory_bytes, *kept));
  return Document(std::move(kept));
}

namespace {

Status check_render_options(const RenderOptions& options) {
  const auto positive = [](double value) { return value > 0.0 && std::isfinite(value); };
  const auto positive_if_given = [&](const std::optional<double>& value) { return !value || positive(*value); };
  if (!positive(options.zoom) || !positive(options.x_zoom) || !positive(options.y_zoom) ||
      !positive(options.dpi) || !positive_if_given(options.dpi_y) || !positive_if_given(options.width) ||
      !positive_if_given(options.height) || !positive_if_given(options.page_width) ||
      !positive_if_given(options.page_height)) {
    return Error{ErrorKind::kInvalidArgument,
                 "zoom, dpi, width, height and page size must be positive finite numbers"};
  }
  if (!std::isfinite(options.left) || !std::isfinite(options.top)) {
    return Error{ErrorKind::kInvalidArgument, "left and top must be finite numbers"};
  }
  return Status::ok();
}

}  // namespace

namespace {

// The sheets a render uses: the document's, plus the caller's sheet when there is one (added after them,
// so it wins at equal specificity). `own` holds the combined copy in that case.
const css::StyleSheets* style_sheets_for(const css::StyleSheets& document_sheets,
                                         const RenderOptions& options, css::StyleSheets& own,
                                         std::vector<std::string>& warnings) {
  const css::StyleSheets* sheets = &document_sheets;
  if (!options.style_sheet.empty()) {
    own = document_sheets;
    own.add(options.style_sheet, options.style_sheet_name.empty() ? "user style sheet" : options.style_sheet_name,
            warnings);
    sheets = &own;
  }
  return sheets->empty() ? nullptr : sheets;
}

}  // namespace

namespace {

// A document's warnings (and notes) as the user reads them: each text once, in the order first met (a marker
// drawn at every vertex, or a property repeated by every <use>, would otherwise say the same thing many
// times), and at most kMaxWarningsShown of them, then one line with the count left out, so that a generated
// document with an invalid value on each of its 10^5 elements does not bury the output in 10^5 lines.
constexpr std::size_t kMaxWarningsShown = 100;

// Warnings quote the values they reject, and a hostile value may be megabytes long (a 10^6-character
// transform quoted in each of 100 warnings would print 100 MB): a warning longer than this keeps its
// beginning (what was rejected, and how it starts) and its end (whose value it was), with the count of
// characters left out between them.
constexpr std::size_t kMaxWarningBytes = 300;
constexpr std::size_t kWarningHeadBytes = 200;
constexpr std::size_t kWarningTailBytes = 80;

// The first byte of the UTF-8 sequence that byte `at` belongs to (a cut never splits a character).
std::size_t utf8_character_start(std::string_view text, std::size_t at) {
  while (at > 0 && at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) --at;
  return at;
}

std::string shortened_warning(std::string warning) {
  if (warning.size() <= kMaxWarningBytes) return warning;
  const std::size_t head_end = utf8_character_start(warning, kWarningHeadBytes);
  const std::size_t tail_start = utf8_character_start(warning, warning.size() - kWarningTailBytes);
  return warning.substr(0, head_end) + "… (" + std::to_string(tail_start - head_end) + " bytes not shown) …" +
         warning.substr(tail_start);
}

// `noun` names the messages in the line that counts those left out ("warning", "note").
std::vector<std::string> messages_for_the_user(std::vector<std::string> messages, std::string_view noun) {
  std::unordered_set<std::string> seen;
  std::vector<std::string> kept;
  std::size_t left_out = 0;
  for (std::string& message : messages) {
    if (!seen.insert(message).second) continue;
    if (kept.size() == kMaxWarningsShown) {
      ++left_out;
      continue;
    }
    kept.push_back(shortened_warning(std::move(message)));
  }
  if (left_out > 0) {
    kept.push_back(std::to_string(left_out) + " more " + std::string(noun) + (left_out == 1 ? "" : "s") +
                   " not shown");
  }
  return kept;
}

}  // namespace

namespace {

// Renders `parsed` for `options` (Document::render); `probe` and `path_probe`, when not null, see each
// Group node and each shape's Path node made.
Result<RenderedDocument> render_parsed(const detail::SvgTree& parsed, const RenderOptions& options,
                                       const detail::GroupNodeProbe* probe,
                                       const detail::PathNodeProbe* path_probe = nullptr) {
  CURVESCAN_PROPAGATE(check_render_options(options));
  RenderedDocument rendered;
  Diagnostics diagnostics;
  diagnostics.warnings = parsed.warnings;
  diagnostics.positions = &parsed.positions;
  css::StyleSheets own;
  const css::StyleSheets* sheets = style_sheets_for(parsed.style_sheets, options, own, diagnostics.warnings);
  DocumentRenderer renderer(parsed.xml.document_element(), options, sheets, diagnostics);
  renderer.set_document_bytes(parsed.memory_bytes);
  renderer.set_group_probe(probe);
  renderer.set_path_probe(path_probe);
  Result<Image> image = renderer.render();
  if (!image) return image.error();
  rendered.image = std::move(image).value();
  rendered.warnings = messages_for_the_user(std::move(diagnostics.warnings), "warning");
  rendered.notes = messages_for_the_user(std::move(diagnostics.notes), "note");
  return rendered;
}

}  // namespace

Result<RenderedDocument> Document::render(const RenderOptions& options) const {
  return render_parsed(*parsed_, options, nullptr);
}

std::int64_t Document::memory_bytes() const noexcept { return parsed_->memory_bytes; }

namespace {

// Draws `parsed` by `draw(renderer)` on a renderer set up for `options` (the document's own warnings, its
// node positions, its style sheets and the options' user sheet), and hands back what it said.
template <typename Draw>
Result<DocumentMessages> draw_parsed(const detail::SvgTree& parsed, const RenderOptions& options, Draw draw) {
  CURVESCAN_PROPAGATE(check_render_options(options));
  Diagnostics diagnostics;
  diagnostics.warnings = parsed.warnings;
  diagnostics.positions = &parsed.positions;
  css::StyleSheets own;
  const css::StyleSheets* sheets = style_sheets_for(parsed.style_sheets, options, own, diagnostics.warnings);
  DocumentRenderer renderer(parsed.xml.document_element(), options, sheets, diagnostics);
  CURVESCAN_PROPAGATE(draw(renderer));
  return DocumentMessages{messages_for_the_user(std::move(diagnostics.warnings), "warning"),
                          messages_for_the_user(std::move(diagnostics.notes), "note")};
}

}  // namespace

Result<DocumentMessages> Document::draw(Canvas& canvas, const Affine& transform,
                                        const RenderOptions& options) const {
  return draw_parsed(*parsed_, options,
                     [&](DocumentRenderer& renderer) { return renderer.draw(canvas, transform); });
}

Result<DocumentMessages> Document::draw_glyph(Canvas& canvas, std::uint32_t glyph, const Affine& transform,
                                              double units_per_em, const RenderOptions& options) const {
  return draw_parsed(*parsed_, options, [&](DocumentRenderer& renderer) {
    return renderer.draw_glyph_element(canvas, "glyph" + std::to_string(glyph), transform, units_per_em);
  });
}

std::optional<Rect> Document::glyph_ink_box(std::uint32_t glyph, double units_per_em,
                                            const RenderOptions& options) const {
  std::optional<Rect> box;
  (void)draw_parsed(*parsed_, options, [&](DocumentRenderer& renderer) {
    box = renderer.glyph_element_ink_box("glyph" + std::to_string(glyph), units_per_em);
    return Status::ok();
  });
  return box;
}

Result<RenderedDocument> render_svg_document(std::string_view xml, const RenderOptions& options) {
  CURVESCAN_PROPAGATE(check_render_options(options));
  const Result<Document> document = Document::parse(xml, options.limits.render.max_memory_bytes);
  if (!document) return document.error();
  return document->render(options);
}

Result<RenderedDocument> detail::render_probing_groups(std::string_view xml, const RenderOptions& options,
                                                       const GroupNodeProbe& probe) {
  CURVESCAN_PROPAGATE(check_render_options(options));
  detail::SvgTree parsed;
  CURVESCAN_PROPAGATE(detail::parse_svg_tree(xml, options.limits.render.max_memory_bytes, parsed));
  return render_parsed(parsed, options, &probe);
}

Result<RenderedDocument> detail::render_probing_paths(std::string_view xml, const RenderOptions& options,
                                                      const PathNodeProbe& probe) {
  CURVESCAN_PROPAGATE(check_render_options(options));
  detail::SvgTree parsed;
  CURVESCAN_PROPAGATE(detail::parse_svg_tree(xml, options.limits.render.max_memory_bytes, parsed));
  return render_parsed(parsed, options, nullptr, &probe);
}

}  // namespace curvescan::svg
