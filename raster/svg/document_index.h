// The first step of resolving a document for one render (docs/svg.md, "How a document is drawn"): one walk
// over the XML tree that decides, once per element, what the drawing code used to decide again wherever it
// met the element:
//  - its role: SVG element drawn where it stands, drawn only through a reference, unsupported, unknown,
//    a curvescan curve element, or foreign markup (element_support.h, xml_names.h);
//  - whether its conditional processing attributes hold for the user's languages (switch.h, SVG 1.1 5.8);
//  - the id index, the first element of each id winning as in browsers (paint_server.h IdIndex);
//  - which mask references close a loop and count as none (the way resvg breaks them);
// and names each unsupported element once (Diagnostics::unsupported) — the one place that warning comes
// from. The walk counts elements against DocumentLimits::max_elements, and then counts the elements of the
// document with every <use> expanded against the same limit (use_expansion.cpp), so that a "billion laughs"
// of nested <use> is refused before any of it is drawn.
#pragma once

#include <cstddef>
#include <cstdint>
#include <pugixml.hpp>
#include <string>
#include <utility>
#include <vector>

#include "computed_style.h"
#include "css/style_sheet.h"
#include "curvescan/status.h"
#include "paint_server.h"

namespace curvescan::svg::detail {

/// What an element is to the renderer.
enum class ElementRole {
  kForeign,       ///< another namespace (RDF, Inkscape's): not rendered, not named
  kCurve,         ///< a curvescan curve element (curve_elements.h): rendered
  kRendered,      ///< an SVG element drawn where it appears in the tree
  kNonRendering,  ///< an SVG element drawn only through a reference (defs, gradients, clipPath...)
  kUnsupported,   ///< an SVG element this reader does not implement (named once by the index)
  kUnknown,       ///< not an SVG element name (a note when the renderer meets it)
};

/// Whether an element of this role can be the child a <switch> picks (SVG 1.1 5.8.2: an SVG graphics
/// element, or a curve; an unsupported one is picked and named, so that it hides the rest as it would
/// in a renderer that draws it).
[[nodiscard]] constexpr bool is_switch_candidate(ElementRole role) noexcept {
  return role == ElementRole::kCurve || role == ElementRole::kRendered || role == ElementRole::kUnsupported;
}

/// The decisions about one element.
struct ElementFacts {
  ElementRole role = ElementRole::kForeign;
  bool conditions_hold = true;     ///< requiredExtensions / systemLanguage (switch.h)
  bool mask_loop_dropped = false;  ///< its mask reference closes a loop and counts as none
};

class DocumentIndex {
 public:
  /// The walk over `root` and its element descendants. `style_sheets` (null: none) give the cascaded
  /// `mask` property for the loop check and the `display` property for the <use> expansion count.
  /// kLimitExceeded past `max_elements` elements, or past `max_elements` elements with every <use>
  /// expanded (expanded_elements()).
  [[nodiscard]] static Result<DocumentIndex> build(const pugi::xml_node& root,
                                                   const std::vector<std::string>& languages,
                                                   std::size_t max_elements,
                                                   const css::StyleSheets* style_sheets,
                                                   Diagnostics& diagnostics);

  /// The facts of `element`, an element of the indexed tree. An element outside it (never the case for the
  /// renderer's walk) reads as foreign markup: not drawn.
  [[nodiscard]] const ElementFacts& facts(const pugi::xml_node& element) const;

  /// Elements by id, the first of each id in document order.
  [[nodiscard]] const IdIndex& ids() const noexcept { return ids_; }

  /// How many elements the drawing walk meets with every <use> expanded, as use_expansion.cpp counts them
  /// (saturating at the largest std::uint64_t); in a document without a <use>, its element count less the
  /// root, which bounds that.
  [[nodiscard]] std::uint64_t expanded_elements() const noexcept { return expanded_elements_; }

 private:
  void break_mask_loops(const std::vector<pugi::xml_node>& masks, const css::StyleSheets* style_sheets,
                        Diagnostics& diagnostics);

  // use_expansion.cpp: the count behind expanded_elements(); `resources` are the document's <mask>,
  // <pattern> and <marker> elements, whose content counts once each.
  [[nodiscard]] std::uint64_t count_expanded_elements(const pugi::xml_node& root,
                                                      const std::vector<pugi::xml_node>& resources,
                                                      const css::StyleSheets* style_sheets) const;

  // The position of `element` in facts_, or facts_.size() when it is not in the indexed tree.
  [[nodiscard]] std::size_t position(const pugi::xml_node& element) const;

  // The facts of `element`, or null when it is not in the indexed tree.
  [[nodiscard]] ElementFacts* find(const pugi::xml_node& element);

  IdIndex ids_;
  // By pugixml's node object, sorted for a binary search: cheaper to build than a hash map (one allocation
  // for all) and as quick to read for the few hundred lookups of a render.
  std::vector<std::pair<const void*, ElementFacts>> facts_;
  std::uint64_t expanded_elements_ = 0;
};

}  // namespace curvescan::svg::detail
