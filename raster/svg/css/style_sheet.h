// The author style sheets of a document, compiled for the cascade (CSS Cascade 4 section 6; SVG 2
// section 6.3 "Styling", 6.4 "Style sheets in SVG content").
//
// Each qualified rule becomes one StyleRule per selector of its list, all sharing one declaration block,
// numbered in source order across every sheet added (document <style> elements in document order, then a
// user-supplied sheet). The rules inside @media blocks (nested ones too, up to kMaxMediaNesting) count
// like the others in that order, and apply while their media queries match the medium set by set_medium
// (media_query.h: a screen of the output size). @import is refused (curvescan reads no file a document
// names); @font-face and the other at-rules are skipped, with one warning per at-rule name; @charset is
// ignored silently, since the text is already decoded.
//
// Rules are indexed by a key of their subject compound (an id, else a class, else a type, else none), so
// an element is tested only against rules that can match it: the ones filed under its id, its classes
// and its local name, and the unkeyed ones.
//
// Bounds (docs/limits.md): kMaxStyleSheetBytes of CSS in all, kMaxStyleRules selectors and
// kMaxStyleDeclarations declarations in all, and the per-list SelectorLimits. What lies beyond is skipped
// with a warning; the render goes on.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <pugixml.hpp>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "matching.h"
#include "media_query.h"
#include "selector.h"
#include "syntax.h"

namespace curvescan::svg::css {

/// Total bytes of CSS text accepted from all sheets of one document (a sheet that would pass it is
/// skipped whole).
inline constexpr std::size_t kMaxStyleSheetBytes = std::size_t{4} << 20;
/// Total selectors (one per entry of each rule's selector list) accepted from all sheets.
inline constexpr std::size_t kMaxStyleRules = 65536;
/// Total declarations kept from all sheets.
inline constexpr std::size_t kMaxStyleDeclarations = 65536;
/// Warnings reported about all sheets; one more line says that the rest are not shown.
inline constexpr std::size_t kMaxStyleWarnings = 32;
/// @media blocks nested deeper than this are skipped with a warning.
inline constexpr int kMaxMediaNesting = 16;
/// @media blocks (and <style media> lists) in all; the ones beyond are skipped with a warning. Each holds
/// its parsed query list, and real sheets have a few dozen.
inline constexpr std::size_t kMaxMediaBlocks = 4096;
/// CSS tokens of one style sheet (about 1.5 MiB of ordinary CSS); the rest of the sheet is skipped with a
/// warning. The tokens of a sheet are held while it is compiled, some 72 bytes each: this bounds that
/// memory whatever the sheet's shape (4 MiB of one-byte tokens would otherwise make 4 million, 300 MB).
inline constexpr std::size_t kMaxStyleSheetTokens = std::size_t{1} << 19;

/// One selector of a rule, with the declarations it brings.
struct StyleRule {
  ComplexSelector selector;
  std::uint32_t block = 0;  ///< index of the rule's declaration block
  std::uint32_t order = 0;  ///< source order across all sheets
  std::uint32_t media = 0;  ///< 0: unconditional; else the 1-based index of the innermost @media block
};

/// A matched declaration block, in cascade order: specificity, then source order.
struct MatchedBlock {
  std::uint32_t specificity;
  std::uint32_t order;
  const std::vector<Declaration>* declarations;
};

class StyleSheets {
 public:
  /// Parses `text` and adds its rules after those already added. `origin` names the sheet in warnings
  /// (e.g. "<style>"). Warnings go to `warnings`. `media` (when not empty) is a media query list the
  /// whole sheet applies under, as <style media="..."> (SVG 2 6.5).
  void add(std::string_view text, std::string_view origin, std::vector<std::string>& warnings,
           std::string_view media = {});

  [[nodiscard]] bool empty() const noexcept { return compiled_->rules.empty(); }
  /// Whether some rules sit inside @media blocks (so that set_medium matters).
  [[nodiscard]] bool has_media_rules() const noexcept { return !compiled_->media_blocks.empty(); }
  /// The medium the @media queries are evaluated for; until it is set, a medium whose size is unknown.
  void set_medium(const MediaFeatures& medium);
  [[nodiscard]] std::size_t rule_count() const noexcept { return compiled_->rules.size(); }

  /// The declaration blocks of the rules `element` matches, in ascending cascade order (later entries
  /// win). `out` is cleared first.
  void match(const pugi::xml_node& element, std::vector<MatchedBlock>& out) const;

 private:
  struct StringHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view text) const noexcept {
      return std::hash<std::string_view>{}(text);
    }
  };
  using Index = std::unordered_map<std::string, std::vector<std::uint32_t>, StringHash, std::equal_to<>>;

  struct MediaBlock {
    MediaQueryList queries;
    std::uint32_t parent = 0;  ///< the enclosing block, 1-based; 0 none
  };

  // The rules, their declarations and indexes: shared between copies until one of them adds a sheet
  // (copy on write), so that a copy for another medium or a user sheet costs no rule copies.
  struct Compiled {
    std::vector<StyleRule> rules;
    std::vector<std::vector<Declaration>> blocks;
    Index by_id, by_class, by_type;
    std::vector<std::uint32_t> unkeyed;
    std::vector<MediaBlock> media_blocks;
  };
  Compiled& writable();

  void add_rules(const TokenList& tokens, const std::vector<Rule>& rules, const std::string& origin,
                 std::uint32_t media, int nesting, std::vector<std::string>& warnings);
  void add_rule(ComplexSelector selector, std::uint32_t block, std::uint32_t media);
  void warn_unsupported_features(const std::set<std::string>& features, const std::string& where,
                                 std::vector<std::string>& warnings);
  void warn(std::vector<std::string>& warnings, std::string message);
  void test(const std::vector<std::uint32_t>& candidates, const pugi::xml_node& element,
            std::vector<MatchedBlock>& out) const;

  std::shared_ptr<Compiled> compiled_ = std::make_shared<Compiled>();
  std::size_t bytes_ = 0;
  std::size_t declarations_ = 0;
  std::size_t warnings_ = 0;
  bool stopped_ = false;            // a limit was reached: the rest of the sheets is skipped
  std::set<std::string> warned_;    // at-rule names and media features already reported
  std::vector<bool> media_active_;  // by media block: do its queries and its parents' match?
  MediaFeatures medium_;
  MatchCache match_cache_;  // sibling positions and `~` outcomes; empty in a copy (matching.h)
};

}  // namespace curvescan::svg::css
