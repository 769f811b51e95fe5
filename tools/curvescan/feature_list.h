// The --features value of `curvescan text`: OpenType features by their four-letter tags, separated by
// commas — "smcp" (on), "-liga" (off), "salt=2" (the second alternate) — the vocabulary of CSS Fonts 4
// font-feature-settings in a shell-friendly spelling. A malformed list is a wrong command line (a usage
// error, exit 64, naming the item), before anything is drawn.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "curvescan/text/text_layout.h"

namespace curvescan::cli {

/// The features of `list` in order (a later item for the same tag wins, as HarfBuzz applies them), or
/// an error message naming the first malformed item. An empty list is no features.
[[nodiscard]] Result<std::vector<FontFeature>> parse_feature_list(std::string_view list);

/// The validator of the option.
inline const CLI::Validator kFeatureList(
    [](std::string& text) -> std::string {
      const Result<std::vector<FontFeature>> features = parse_feature_list(text);
      return features ? std::string() : features.error().message;
    },
    "");

}  // namespace curvescan::cli
