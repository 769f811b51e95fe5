// Keys and counters of fontconfig's kept answers (fontconfig_results_p.h).
#include <atomic>
#include <cstdint>
#include <cstring>

#include "fontconfig_results_p.h"

namespace curvescan::detail {
namespace {

std::atomic<int> request_count{0};

void append_number(std::string& key, std::uint64_t value) {
  key += std::to_string(value);
  key += ';';
}

}  // namespace

std::string request_key(char kind, const FontQuery& query, const std::vector<std::string>& families) {
  std::string key(1, kind);
  // Length-prefixed names, so no family name (which may hold any character) can run into the next field.
  for (const std::string& name : families) {
    append_number(key, name.size());
    key += name;
  }
  key += '|';
  append_number(key, static_cast<std::uint32_t>(query.weight));
  key += query.italic ? 'i' : 'r';
  std::uint64_t width_bits = 0;
  static_assert(sizeof(width_bits) == sizeof(query.width));
  std::memcpy(&width_bits, &query.width, sizeof(width_bits));
  append_number(key, width_bits);
  return key;
}

void count_fontconfig_request() noexcept {
  request_count.fetch_add(1, std::memory_order_relaxed);
}

int fontconfig_request_count() noexcept {
  return request_count.load(std::memory_order_relaxed);
}

}  // namespace curvescan::detail
