// The weight step of CSS font matching (CSS Fonts 4 section 5.2, step 4, "font-weight"), applied to the
// face fontconfig matched (font_lookup.cpp). fontconfig ranks weights by their distance to the request,
// so 200 (extra-light) in a family of Thin 100, Light 300 and Regular 400 gives Light, and 520 in a
// family of Regular and Bold gives Regular; CSS instead searches in a direction that depends on the
// request, and gives Thin and Bold there, as browsers draw them. Only the weight is re-chosen, among the
// faces of the matched family with the matched face's slant and width (fontconfig's choice of family,
// slant and width stands). A variable face covers a range of weights itself and is left as matched.
#include <fontconfig/fontconfig.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "fontconfig_query_p.h"

namespace curvescan::detail {
namespace {

struct WeightedFace {
  double weight;  // CSS / OpenType weight class
  FcPattern* pattern;
};

// CSS Fonts 4 5.2 step 4: which of `available` weights serves `desired`.
double css_weight(double desired, const std::vector<double>& available) {
  const auto nearest_at_or_above = [&](double from, double to) -> std::optional<double> {
    std::optional<double> best;
    for (const double w : available)
      if (w >= from && w <= to && (!best || w < *best)) best = w;
    return best;
  };
  const auto nearest_below = [&](double limit) -> std::optional<double> {
    std::optional<double> best;
    for (const double w : available)
      if (w < limit && (!best || w > *best)) best = w;
    return best;
  };
  const auto exact = std::find(available.begin(), available.end(), desired);
  if (exact != available.end()) return desired;
  if (desired >= 400.0 && desired <= 500.0) {
    // Weights from the desired one up to 500 ascending, then below it descending, then above 500.
    if (const auto w = nearest_at_or_above(desired, 500.0)) return *w;
    if (const auto w = nearest_below(desired)) return *w;
    return *nearest_at_or_above(500.0, 1e9);
  }
  if (desired < 400.0) {
    // Below the desired weight descending, then above it ascending.
    if (const auto w = nearest_below(desired)) return *w;
    return *nearest_at_or_above(desired, 1e9);
  }
  // Above 500: above the desired weight ascending, then below it descending.
  if (const auto w = nearest_at_or_above(desired, 1e9)) return *w;
  return *nearest_below(desired);
}

}  // namespace

FcPatternPtr css_weight_face(FcConfig* config, FcPattern* matched, double desired_weight) {
  FcChar8* family = nullptr;
  int slant = 0, width = 0;
  FcBool variable = FcFalse;
  if (FcPatternGetString(matched, FC_FAMILY, 0, &family) != FcResultMatch ||
      FcPatternGetInteger(matched, FC_SLANT, 0, &slant) != FcResultMatch ||
      (FcPatternGetBool(matched, FC_VARIABLE, 0, &variable) == FcResultMatch && variable)) {
    return nullptr;
  }
  const FcPatternPtr pattern(FcPatternCreate());
  if (!pattern) return nullptr;
  FcPatternAddString(pattern.get(), FC_FAMILY, family);
  FcPatternAddInteger(pattern.get(), FC_SLANT, slant);
  if (FcPatternGetInteger(matched, FC_WIDTH, 0, &width) == FcResultMatch)
    FcPatternAddInteger(pattern.get(), FC_WIDTH, width);
  FcPatternAddBool(pattern.get(), FC_SCALABLE, FcTrue);
  FcObjectSet* objects = FcObjectSetBuild(FC_FILE, FC_INDEX, FC_WEIGHT, FC_VARIABLE, FC_FAMILY, FC_STYLE,
                                          FC_SLANT, FC_WIDTH, static_cast<char*>(nullptr));
  if (objects == nullptr) return nullptr;
  FcFontSet* faces = FcFontList(config, pattern.get(), objects);
  FcObjectSetDestroy(objects);
  if (faces == nullptr) return nullptr;
  std::vector<WeightedFace> candidates;
  bool any_variable = false;
  for (int i = 0; i < faces->nfont; ++i) {
    FcPattern* face = faces->fonts[i];
    FcBool is_variable = FcFalse;
    double weight = 0.0;
    if (FcPatternGetBool(face, FC_VARIABLE, 0, &is_variable) == FcResultMatch && is_variable)
      any_variable = true;
    // A weight range (a variable font's named instance or the font itself) is not one weight.
    if (FcPatternGetDouble(face, FC_WEIGHT, 0, &weight) != FcResultMatch) {
      any_variable = true;
      continue;
    }
    candidates.push_back({FcWeightToOpenTypeDouble(weight), face});
  }
  FcPatternPtr chosen;
  double matched_weight = 0.0;
  if (!any_variable && !candidates.empty() &&
      FcPatternGetDouble(matched, FC_WEIGHT, 0, &matched_weight) == FcResultMatch) {
    std::vector<double> weights;
    for (const WeightedFace& face : candidates) weights.push_back(face.weight);
    const double wanted = css_weight(std::clamp(desired_weight, 1.0, 1000.0), weights);
    // fontconfig's own face when it already has that weight (it also ranked the files of one weight).
    if (std::fabs(FcWeightToOpenTypeDouble(matched_weight) - wanted) > 0.5) {
      for (const WeightedFace& face : candidates) {
        if (face.weight == wanted) {
          chosen.reset(FcPatternDuplicate(face.pattern));
          break;
        }
      }
    }
  }
  FcFontSetDestroy(faces);
  return chosen;
}

}  // namespace curvescan::detail
