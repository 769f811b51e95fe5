// The process's one fontconfig configuration, shared by font lookup (font_lookup.cpp) and per-character
// fallback (font_fallback.cpp).
//
// Loading a configuration (FcInitLoadConfigAndFonts: the configuration files, then every font cache) takes a
// few milliseconds; when each lookup and each FontFallback loaded its own, a batch render of many small
// documents with text paid it several times per document. Here it is loaded once, at the first lookup,
// and kept for the life of the process — in a function-local static, destroyed at exit before
// LeakSanitizer's final check, rather than fontconfig's implicit global configuration (FcInit), which is
// never freed and which LeakSanitizer reports in every program that looks a font up.
//
// The configuration is reloaded when the environment variables that choose it (FONTCONFIG_FILE,
// FONTCONFIG_PATH, FONTCONFIG_SYSROOT: fontconfig-user, "Environment variables") differ from those it was
// loaded under, so a program — or a test — that points fontconfig at other files gets those. Holders of the
// previous configuration (a FontFallback, whose candidates' character sets live in its caches) keep it
// alive through their shared_ptr.
//
// Queries on the configuration go through FontconfigLock: fontconfig documents itself as thread-safe since
// 2.10.91, but one mutex around the few calls per document costs nothing measurable and does not depend on
// that (batch renders lay out text on several threads).
#pragma once

#include <fontconfig/fontconfig.h>

#include <memory>
#include <mutex>

namespace curvescan::detail {

struct FontconfigResults;  // fontconfig_results_p.h

/// The configuration and the lock that serializes queries on it, held together for one query.
class FontconfigLock {
 public:
  FontconfigLock();
  /// The process's configuration for the current environment; null when fontconfig cannot load one.
  [[nodiscard]] FcConfig* config() const noexcept { return config_.get(); }
  /// A reference that keeps the configuration (and the caches its results point into) alive after the lock
  /// is released.
  [[nodiscard]] std::shared_ptr<FcConfig> share() const noexcept { return config_; }
  /// fontconfig's answers already given under this configuration (fontconfig_results_p.h); emptied when
  /// the configuration is reloaded.
  [[nodiscard]] FontconfigResults& results() const noexcept { return *results_; }

 private:
  std::unique_lock<std::mutex> lock_;
  std::shared_ptr<FcConfig> config_;
  FontconfigResults* results_ = nullptr;
};

/// How many times this process has loaded a configuration (for tests: a second lookup loads none).
[[nodiscard]] int fontconfig_load_count() noexcept;

}  // namespace curvescan::detail
