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
namespace {

// UAX #9 rules P2-P3: the direction of the first strong character (L, R, AL) that is not between an isolate
// initiator (LRI, RLI, FSI) and its matching PDI — or the end of the paragraph when it has none — else
// left-to-right. A PDI with no open isolate is an ordinary neutral (BD9). (pango's pango_find_base_dir
// looks at every character, isolated or not; the standard is followed here, as FriBidi follows it for the
// levels.)
FriBidiParType first_strong_direction(const std::vector<FriBidiCharType>& types) {
  int open_isolates = 0;
  for (const FriBidiCharType type : types) {
    if (FRIBIDI_IS_ISOLATE(type) && type != FRIBIDI_TYPE_PDI) {
      ++open_isolates;
    } else if (type == FRIBIDI_TYPE_PDI) {
      if (open_isolates > 0) --open_isolates;
    } else if (open_isolates == 0 && FRIBIDI_IS_LETTER(type)) {
      return FRIBIDI_IS_RTL(type) ? FRIBIDI_PAR_RTL : FRIBIDI_PAR_LTR;
    }
  }
  return FRIBIDI_PAR_LTR;
}

}  // namespace

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
    if (base == FRIBIDI_PAR_ON) base = first_strong_direction(types);
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
