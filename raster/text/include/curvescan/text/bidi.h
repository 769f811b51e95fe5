// The Unicode Bidirectional Algorithm (UAX #9) for one paragraph of text, through GNU FriBidi: the
// resolved embedding level of every character and the visual order of runs of characters.
//
// UAX #9 in short: every character has a bidi class (strong L, R, AL; weak EN, AN, ...; neutral WS, ON,
// ...); the paragraph direction is given or taken from the first strong character (rules P2-P3); explicit
// embeddings, overrides and isolates (LRE, RLE, LRO, RLO, PDF, LRI, RLI, FSI, PDI) and the implicit rules
// (W1-W7, N0-N2, I1-I2) give each character a level, even = left-to-right, odd = right-to-left; the
// reordering rule L2 then reverses, from the highest level down to the lowest odd one, every maximal
// sequence of characters at that level or higher. Mirroring (L4: "(" drawn as ")" at an odd level) is
// HarfBuzz's, which mirrors the characters of a right-to-left buffer (text_layout.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace curvescan {

/// The base direction of a paragraph (CSS Writing Modes 3 `direction`; UAX #9 P2-P3 for kAuto).
enum class TextDirection {
  kAuto,         ///< from the first strong character (L: left-to-right; R or AL: right-to-left), else LTR
  kLeftToRight,  ///< forced
  kRightToLeft,  ///< forced
};

struct BidiParagraph {
  /// One resolved level per character (0..125, UAX #9 BD2), after rule L1 (trailing white space and
  /// segment separators at the paragraph level).
  std::vector<std::uint8_t> levels;
  bool right_to_left = false;  ///< the paragraph's resolved direction
};

/// The levels of the paragraph `text` (a single line: no paragraph separator is interpreted) with base
/// direction `direction`. With `override_direction` true every character takes the paragraph level of the
/// forced direction (CSS `unicode-bidi: bidi-override`, like enclosing the text in LRO/RLO ... PDF); with
/// kAuto that direction is the first strong character's.
[[nodiscard]] BidiParagraph resolve_bidi(std::u32string_view text, TextDirection direction,
                                         bool override_direction = false);

/// UAX #9 rule L2 over runs: given the level of each run of a line in logical order, the run indices in
/// visual order (left to right). Each run must be at one level; a run's own characters are reversed by
/// whoever draws it (HarfBuzz for an odd-level run). Linear in runs times the number of distinct levels.
[[nodiscard]] std::vector<std::size_t> visual_run_order(std::span<const std::uint8_t> run_levels);

}  // namespace curvescan
