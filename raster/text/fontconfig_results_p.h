// fontconfig's answers kept for the life of the process's configuration (fontconfig_config_p.h).
//
// Every document of a batch render asked fontconfig again for the same requests — FcFontMatch (with the
// FcFontList of the CSS weight step) for each family list, FcFontSort for each fallback: in a batch of
// resvg's 379 text documents, 383 matches and lists for 36 distinct requests (docs/benchmarks.md).
// The answers depend only on the request and the configuration, so they are kept here, keyed by the
// request (family list, weight, slant, width; a match is match_font's whole answer, scalable faces first
// and then bitmap colour ones), beside the configuration they came from, under its lock, and dropped with it
// when the configuration is reloaded. A process that asks for many different requests (a batch of documents
// naming thousands of families) keeps at most kMaxEntries of each kind: past that the table is emptied and
// refilled.
#pragma once

#include <fontconfig/fontconfig.h>

#include <cstddef>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "curvescan/text/font_lookup.h"

namespace curvescan::detail {

struct FcFontSetDeleter {
  void operator()(FcFontSet* set) const noexcept { FcFontSetDestroy(set); }
};
using FcFontSetPtr = std::unique_ptr<FcFontSet, FcFontSetDeleter>;

/// One face of FcFontSort's list: where it is and the characters it covers (its FcCharSet, owned by
/// `SortedFaces::font_set` and read-only: FcCharSetHasChar may be called from any thread).
struct SortedFace {
  std::string file;
  int face_index = 0;
  const FcCharSet* coverage = nullptr;
};

/// FcFontSort's answer for one request. The character sets point into the configuration's memory-mapped
/// caches (fontconfig-devel, "FcCharSetCopy"), so the configuration is held as long as the answer is.
struct SortedFaces {
  std::shared_ptr<FcConfig> config;
  FcFontSetPtr font_set;
  std::vector<SortedFace> faces;
};

/// The answers, per configuration; accessed only while its FontconfigLock is held.
struct FontconfigResults {
  static constexpr std::size_t kMaxEntries = 4096;
  std::unordered_map<std::string, Result<FontMatch>> matches;
  std::unordered_map<std::string, std::shared_ptr<const SortedFaces>> sorts;
};

/// The key of a request: every field of `query` that reaches the pattern (query_pattern, css_weight_face),
/// with the family list as `families` (already split), and `kind` telling match from sort apart.
[[nodiscard]] std::string request_key(char kind, const FontQuery& query,
                                      const std::vector<std::string>& families);

/// Counts a request fontconfig was really asked (not answered from FontconfigResults); for tests.
void count_fontconfig_request() noexcept;
[[nodiscard]] int fontconfig_request_count() noexcept;

}  // namespace curvescan::detail
