// The process's fontconfig configuration (fontconfig_config_p.h).
#include <atomic>
#include <cstdlib>
#include <string>

#include "fontconfig_config_p.h"
#include "fontconfig_results_p.h"

namespace curvescan::detail {
namespace {

// The environment that chooses the configuration, as one string to compare.
std::string configuration_environment() {
  std::string key;
  for (const char* name : {"FONTCONFIG_FILE", "FONTCONFIG_PATH", "FONTCONFIG_SYSROOT"}) {
    const char* value = std::getenv(name);
    key += value != nullptr ? "=" + std::string(value) : "-";
    key += '\0';
  }
  return key;
}

struct LoadedConfiguration {
  std::mutex mutex;
  std::string environment;           // what configuration_environment() was when `config` was loaded
  std::shared_ptr<FcConfig> config;  // null until the first lookup
  FontconfigResults results;         // answers under `config`
};

// Constructed at the first lookup and destroyed at exit (a function-local static); a static made earlier that
// still holds a share (a long-lived FontFallback) frees the configuration when it is destroyed in turn.
// LeakSanitizer checks after static destructors have run.
LoadedConfiguration& loaded() {
  static LoadedConfiguration configuration;
  return configuration;
}

std::atomic<int> load_count{0};

}  // namespace

FontconfigLock::FontconfigLock() : lock_(loaded().mutex) {
  LoadedConfiguration& state = loaded();
  std::string environment = configuration_environment();
  if (!state.config || environment != state.environment) {
    state.config.reset();
    state.results = FontconfigResults{};
    if (FcConfig* config = FcInitLoadConfigAndFonts()) {
      state.config = std::shared_ptr<FcConfig>(config, [](FcConfig* c) { FcConfigDestroy(c); });
      state.environment = std::move(environment);
      load_count.fetch_add(1, std::memory_order_relaxed);
    }
  }
  config_ = state.config;
  results_ = &state.results;
}

int fontconfig_load_count() noexcept {
  return load_count.load(std::memory_order_relaxed);
}

}  // namespace curvescan::detail
