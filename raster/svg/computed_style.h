// The cascade of the SVG reader: presentation attributes and the style attribute resolved into one
// ComputedStyle per element (SVG 1.1 section 6.4 "Specifying properties using the presentation
// attributes", 6.7 "Property inheritance").
//
// Order (SVG 1.1 6.4, CSS 2.1 6.4.4): an element starts from its parent's inherited properties (the
// non-inherited ones -- opacity, display, clip-path -- reset to their initial values), then its
// presentation attributes apply, then the declarations of its style attribute, later ones winning. An
// invalid value is ignored (CSS 2.1 4.2: "declarations with invalid values are ignored") and reported as
// a warning naming the property and the value. `inherit` takes the parent's value.
#pragma once

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "css/var_substitution.h"
#include "curvescan/raster/path.h"
#include "curvescan/svg/color.h"
#include "curvescan/svg/length.h"
#include "curvescan/text/text_layout.h"
#include "painting_properties.h"
#include "text_properties.h"

namespace pugi {
class xml_node;
}

namespace curvescan::svg::css {
class StyleSheets;
class CustomProperties;
}

namespace curvescan::svg::detail {

class SourcePositions;  // source_positions.h

/// What the reader tells the user: warnings always (problems with the input, SVG features this reader does
/// not support and element names SVG does not define, once per kind), notes only with --verbose.
/// How the warning about an invalid property value begins ("ignoring invalid value 'x' of property
/// 'fill'"); the renderer puts the element's position in front of it.
inline constexpr std::string_view kInvalidValueWarning = "ignoring invalid value";

struct Diagnostics {
  std::vector<std::string> warnings;
  std::vector<std::string> notes;
  /// Warns once per `feature` (say "<animate>" or "filter") that it is not supported and was ignored: no
  /// silent loss, and no flood from a document that animates every element.
  void unsupported(std::string_view feature);
  /// Warns once per name that an element of the SVG namespace (or of none) that SVG does not define, say
  /// <blink> or a misspelt <rec>, was not drawn, nor its content: the content is lost, so it is said.
  void unknown_element(std::string_view name);
  /// Adds `warning` unless the same line was added before (a rule that applies to every element would
  /// repeat it for each).
  void warn_once(std::string warning);

  /// What var() substitutions may still produce in this document (css/var_substitution.h): the bound that
  /// keeps "billion laughs" through custom properties linear.
  css::SubstitutionBudget substitution_budget;

  /// The document's node positions (null: messages carry none, as for a nested SVG image).
  const SourcePositions* positions = nullptr;
  /// "line L, column C: <name> " for a warning about element `node`, or "<name> " without positions.
  [[nodiscard]] std::string element_prefix(const pugi::xml_node& node) const;

 private:
  std::set<std::string, std::less<>> unsupported_seen_;
};

/// A fill or stroke value (SVG 1.1 11.2 "<paint>"): none, a colour, currentColor, or url(#id) with an
/// optional fallback used when the reference is broken.
struct PaintSpec {
  /// kContextFill / kContextStroke: SVG 2 13.4.1, the fill or stroke of the context element (the element
  /// a <marker> is drawn for, or the <use> whose content this is).
  enum class Kind { kNone, kColor, kCurrentColor, kUrl, kContextFill, kContextStroke };
  Kind kind = Kind::kNone;
  Color color;
  std::string url_id;  ///< kUrl: the referenced id, without '#'; empty for a URL into another document
  Kind fallback_kind = Kind::kNone;
  Color fallback_color;
};

enum class LineJoinValue { kMiter, kMiterClip, kRound, kBevel, kArcs };
enum class LineCapValue { kButt, kRound, kSquare };

struct ComputedStyle {
  // Inherited properties (SVG 1.1 property index, "Inherited: yes").
  PaintSpec fill{PaintSpec::Kind::kColor, Color{0, 0, 0, 1}, {}, PaintSpec::Kind::kNone, {}};
  double fill_opacity = 1.0;
  FillRule fill_rule = FillRule::kNonZero;
  FillRule clip_rule = FillRule::kNonZero;
  PaintSpec stroke;
  double stroke_opacity = 1.0;
  double stroke_width = 1.0;  ///< user units, resolved against the viewport when given in % or em
  LineJoinValue stroke_linejoin = LineJoinValue::kMiter;
  LineCapValue stroke_linecap = LineCapValue::kButt;
  double stroke_miterlimit = 4.0;
  std::vector<double> stroke_dasharray;  ///< user units; empty = solid
  double stroke_dashoffset = 0.0;
  Color color{0, 0, 0, 1};
  bool visible = true;
  /// shape-rendering (SVG 1.1 11.7.1) is optimizeSpeed or crispEdges: shapes are drawn without
  /// anti-aliasing, as both values allow and as resvg and Chrome do; auto and geometricPrecision keep
  /// exact coverage. Text has its own text-rendering and is not affected.
  bool aliased_shapes = false;
  /// image-rendering (SVG 1.1 15.3, CSS Images 3 7.5) is optimizeSpeed, pixelated or crisp-edges: the
  /// pixels of <image> and <feImage> are sampled nearest, as Chrome and resvg draw them; else bilinear.
  bool pixelated_images = false;
  double font_size = 16.0;  ///< px, the base of em units
  // Text (SVG 1.1 10.10, 10.9.1; text_font_properties.h). The initial family is the UA's choice (CSS 2.1
  // 15.3): serif, as browsers and rsvg-convert (Times New Roman, which fontconfig maps to a serif face).
  std::string font_family = "serif";
  int font_weight = 400;  ///< 1..1000, 400 normal, 700 bold
  bool font_italic = false;
  TextAnchor text_anchor = TextAnchor::kStart;
  // Not inherited.
  double opacity = 1.0;
  bool display = true;
  std::string clip_path_id;  ///< clip-path="url(#id)", empty = none
  /// mask, markers, overflow and the other properties of masking and painting (painting_properties.h).
  PaintingProperties painting;
  /// direction, unicode-bidi, spacing, baselines and decoration of text (text_properties.h).
  TextProperties text;
  /// The custom properties (CSS Variables 1; css/custom_properties.h), inherited; null when there are none.
  /// Shared: an element that declares none has its parent's set.
  std::shared_ptr<const css::CustomProperties> custom_properties;
  /// Product of the opacities of the enclosing groups, folded into each shape's alpha (no CSS property:
  /// the renderer sets it; see document.cpp).
  double group_opacity = 1.0;
};

/// The viewport a percentage refers to, and the document resolution.
struct ResolveContext {
  double viewport_width = 0.0;
  double viewport_height = 0.0;
  Resolution dpi;
  /// x-like lengths (x, width, cx, rx, dx, refX...): 100% is the viewport's width; physical units at dpi.x.
  [[nodiscard]] LengthAxis horizontal() const noexcept { return {viewport_width, dpi.x}; }
  /// y-like lengths: the viewport's height, dpi.y.
  [[nodiscard]] LengthAxis vertical() const noexcept { return {viewport_height, dpi.y}; }
  /// Other lengths (r, stroke-width...): the viewport's normalized diagonal, dpi.diagonal().
  [[nodiscard]] LengthAxis other() const noexcept;
  /// The document's author style sheets (cascade.h); null when there are none.
  const css::StyleSheets* style_sheets = nullptr;
};

/// `parent` with the non-inherited properties reset to their initial values.
[[nodiscard]] ComputedStyle inherit_style(const ComputedStyle& parent);

/// True when `name` is a property this reader knows (so an attribute of that name is a presentation
/// attribute).
[[nodiscard]] bool is_style_property(std::string_view name) noexcept;

/// Applies `name: value` to `style` (`parent` serves "inherit"). Invalid values leave `style` unchanged,
/// add a warning and return false. Unknown names are ignored (true). `value` holds no var(): the cascade
/// substitutes it first (cascade.h).
bool apply_property(ComputedStyle& style, const ComputedStyle& parent, std::string_view name,
                    std::string_view value, const ResolveContext& context, Diagnostics& diagnostics);

/// A length attribute resolved to user units along `axis`. Unknown units and
/// malformed text give nullopt and a warning naming `attribute`.
[[nodiscard]] std::optional<double> resolve_length(std::string_view attribute, std::string_view text,
                                                   LengthAxis axis, double font_size,
                                                   Diagnostics& diagnostics);

/// The reference length for non-directional percentages: sqrt((w² + h²) / 2) (SVG 1.1 7.10).
[[nodiscard]] double diagonal_reference(double width, double height) noexcept;

/// "url(#id)" -> "id" (whitespace and quotes allowed inside the parentheses); nullopt otherwise.
[[nodiscard]] std::optional<std::string> parse_url_reference(std::string_view text);
/// Whether `text` is url(...) of anything but a fragment of this document ("url(other.svg#id)").
[[nodiscard]] bool is_other_document_url(std::string_view text);

}  // namespace curvescan::svg::detail
