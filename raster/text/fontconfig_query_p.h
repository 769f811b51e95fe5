// The fontconfig pattern of a FontQuery, shared by font lookup (font_lookup.cpp: FcFontMatch) and
// per-character fallback (font_fallback.cpp: FcFontSort), so both rank faces for the same request.
#pragma once

#include <fontconfig/fontconfig.h>

#include <memory>
#include <string>
#include <vector>

#include "curvescan/text/font_lookup.h"

namespace curvescan::detail {

struct FcPatternDeleter {
  void operator()(FcPattern* pattern) const noexcept { FcPatternDestroy(pattern); }
};
using FcPatternPtr = std::unique_ptr<FcPattern, FcPatternDeleter>;

/// "A, 'B C', \"D\"" -> {A, B C, D}: commas separate, surrounding blanks and one level of quotes go.
[[nodiscard]] std::vector<std::string> split_family_list(std::string_view list);

/// The pattern for `query` (its families in order, weight, slant, width, and with `scalable` scalable
/// faces first) after the configuration's substitutions and the defaults, ready for FcFontMatch or
/// FcFontSort; nullptr when fontconfig is out of memory. fontconfig ranks FC_SCALABLE above the family
/// (fcmatch.c's priorities), so a scalable query passes over a bitmap-only colour font of the family.
[[nodiscard]] FcPatternPtr query_pattern(FcConfig* config, const FontQuery& query,
                                         const std::vector<std::string>& families, bool scalable = true);

/// The face of `matched`'s family, slant and width that CSS Fonts 4 section 5.2 (step 4, font-weight)
/// picks for `desired_weight` (css_weight_match.cpp); nullptr when that is `matched` itself, when the
/// family has a variable face, or when fontconfig cannot say.
[[nodiscard]] FcPatternPtr css_weight_face(FcConfig* config, FcPattern* matched, double desired_weight);

}  // namespace curvescan::detail
