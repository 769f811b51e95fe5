// UAX #9 through FriBidi (bidi.h): fribidi_get_bidi_types and fribidi_get_bracket_types classify the
// characters, fribidi_get_par_embedding_levels_ex resolves levels (rules P2-I2 and L1 parts 1-3, with the
// bracket pairs of N0), fribidi_reorder_line applies L1 part 4 (trailing white space) to the levels; the
// visual order of runs is rule L2, done here on runs rather than characters (FriBidi's map is per
// character, and the layout shapes runs).
#include "curvescan/text/bidi.h"

#include <fribidi.h>

#include <algorithm>
#include <limits>

namespace curvescan {

BidiParagraph resolve_bidi(std::u32string_view text, TextDirection direction, bool override_direction) {
  BidiParagraph paragraph;
  const std::size_t length = text.size();
  static_assert(sizeof(FriBidiChar) == sizeof(char32_t));
  const auto* characters = reinterpret_cast<const FriBidiChar*>(text.data());
  std::vector<FriBidiCharType> types(length);
  if (length > 0) fribidi_get_bidi_types(characters, static_cast<FriBidiStrIndex>(length), types.data());

  FriBidiParType base = direction == TextDirection::kLeftToRight   ? FRIBIDI_PAR_LTR
                        : direction == TextDirection::kRightToLeft ? FRIBIDI_PAR_RTL
                                                                   : FRIBIDI_PAR_ON;
  if (override_direction) {
    if (base == FRIBIDI_PAR_ON) {
      // P2-P3: the first strong character, skipping isolates is not needed for a whole-run override.
      const auto strong = std::find_if(types.begin(), types.end(),
                                       [](FriBidiCharType type) { return FRIBIDI_IS_LETTER(type); });
      base = strong != types.end() && FRIBIDI_IS_RTL(*strong) ? FRIBIDI_PAR_RTL : FRIBIDI_PAR_LTR;
    }
    paragraph.right_to_left = base == FRIBIDI_PAR_RTL;
    paragraph.levels.assign(length, paragraph.right_to_left ? 1 : 0);
    return paragraph;
  }
  if (length == 0) {
    paragraph.right_to_left = base == FRIBIDI_PAR_RTL;
    return paragraph;
  }
  std::vector<FriBidiBracketType> brackets(length);
  fribidi_get_bracket_types(characters, static_cast<FriBidiStrIndex>(length), types.data(), brackets.data());
  std::vector<FriBidiLevel> levels(length);
  const FriBidiStrIndex count = static_cast<FriBidiStrIndex>(length);
  if (fribidi_get_par_embedding_levels_ex(types.data(), brackets.data(), count, &base, levels.data()) == 0 ||
      fribidi_reorder_line(0, types.data(), count, 0, base, levels.data(), nullptr, nullptr) == 0) {
    // FriBidi fails only when it cannot allocate: draw the paragraph at its base level, unreordered.
    levels.assign(length, base == FRIBIDI_PAR_RTL ? 1 : 0);
  }
  paragraph.right_to_left = FRIBIDI_DIR_TO_LEVEL(base) == 1;
  paragraph.levels.assign(levels.begin(), levels.end());
  return paragraph;
}

std::vector<std::size_t> visual_run_order(std::span<const std::uint8_t> run_levels) {
  std::vector<std::size_t> order(run_levels.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  if (run_levels.empty()) return order;
  const std::uint8_t highest = *std::max_element(run_levels.begin(), run_levels.end());
  std::uint8_t lowest_odd = std::numeric_limits<std::uint8_t>::max();
  for (const std::uint8_t level : run_levels)
    if (level % 2 == 1) lowest_odd = std::min(lowest_odd, level);
  if (lowest_odd == std::numeric_limits<std::uint8_t>::max()) return order;  // all left-to-right
  // L2: "From the highest level found in the text to the lowest odd level on each line, reverse any
  // contiguous sequence of characters that are at that level or higher." `order` holds run indices in the
  // current visual order; their levels travel with them.
  for (int level = highest; level >= lowest_odd; --level) {
    std::size_t i = 0;
    while (i < order.size()) {
      if (run_levels[order[i]] < level) {
        ++i;
        continue;
      }
      std::size_t end = i;
      while (end < order.size() && run_levels[order[end]] >= level) ++end;
      std::reverse(order.begin() + static_cast<std::ptrdiff_t>(i),
                   order.begin() + static_cast<std::ptrdiff_t>(end));
      i = end;
    }
  }
  return order;
}

}  // namespace curvescan
