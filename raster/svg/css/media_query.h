// Media queries of @media rules (Media Queries Level 4), evaluated for the one medium curvescan renders
// to: a screen whose viewport is the output image.
//
// Grammar (MQ4 section 3, "Syntax"): a comma-separated list of queries, true when any query is; a query
// is a media condition, or [not | only]? <media-type> [and <condition without or>]?; a condition
// combines features in parentheses with not, and, or (one kind of combinator per level); a feature is
// (name), (name: value) or a range such as (width >= 100px) or (100px < width <= 500px). A malformed
// query is false ("not all", section 3.2) without spoiling the others of its list; an empty list is
// true.
//
// The medium (section 2.3 media types, section 4-12 features):
//   type             all and screen match; print, speech and the deprecated types (tv, handheld, ...) do not
//   width, height    the output size in CSS px, with min-/max- and ranges; aspect-ratio and orientation
//                    from them
//   colour           color 8 (bits per component), color-index 0, monochrome 0, color-gamut srgb,
//                    dynamic-range standard
//   preferences      prefers-color-scheme light, prefers-reduced-motion, -transparency, -reduced-data and
//                    prefers-contrast no-preference, forced-colors none, inverted-colors none
//   interaction      hover none, any-hover none, pointer none, any-pointer none (an image has no pointer)
//   output           grid 0, scan progressive, update none (a still image), scripting none,
//                    overflow-block none, overflow-inline none, display-mode browser
//   resolution       the output resolution, 96 dpi per CSS px unless the caller says otherwise
// A feature not listed is "unknown" (section 3.2 "Evaluating Media Queries"), which makes its query
// false; the caller reports its name. Before the output size is known (MediaFeatures::size_known), the
// size features are unknown too.
//
// Lengths in values: px, in, cm, mm, Q, pt, pc, and em, rem at the initial font size (16 px; MQ4 1.3:
// relative units refer to the initial value), ex and ch at half of it.
#pragma once

#include <cstddef>
#include <set>
#include <string>
#include <vector>

#include "token.h"

namespace curvescan::svg::css {

/// What the medium is: the renderer's viewport.
struct MediaFeatures {
  bool size_known = false;
  double width = 0.0;   ///< CSS px
  double height = 0.0;  ///< CSS px
  double dpi = 96.0;    ///< device pixels per CSS inch: resolution is dpi / 96 dppx
};

/// Queries deeper than this many parentheses are malformed (false): the parser's recursion is bounded.
inline constexpr int kMaxMediaConditionDepth = 32;

struct MediaCondition;

/// One parsed media query list.
class MediaQueryList {
 public:
  /// Parses tokens [begin, end) of `list` (an @media prelude). The names of unsupported features go to
  /// `unsupported` (each once).
  static MediaQueryList parse(const TokenList& list, std::size_t begin, std::size_t end,
                              std::set<std::string>& unsupported);

  /// Whether the medium matches.
  [[nodiscard]] bool matches(const MediaFeatures& medium) const;

  MediaQueryList();
  MediaQueryList(const MediaQueryList&);
  MediaQueryList(MediaQueryList&&) noexcept;
  MediaQueryList& operator=(const MediaQueryList&);
  MediaQueryList& operator=(MediaQueryList&&) noexcept;
  ~MediaQueryList();

  /// One query of the list (defined in media_query.cpp).
  struct Query;

 private:
  std::vector<Query> queries_;
};

}  // namespace curvescan::svg::css
